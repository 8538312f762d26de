"""Graded mode: the visible check sees only the form of an answer; the grade comes from a key
that the students' side never holds.

In graded mode (``eulerlib-course notebooks nbgrader --graded``) an exercise's visible check cell
calls :func:`check_form`, which says whether the answer has the form asked for (a number, three
angles, a 3×3 matrix, an option and a value) and nothing about whether it is right. The hidden
test of the exercise, which nbgrader strips from the release and puts back when it grades,
carries the notebook's answer key as source text and calls :func:`grade` with it.

Nothing here knows a reference: :func:`check_form` gets the form from its arguments (written
into the check cell when the edition is made), :func:`grade` gets the key from the hidden test.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from .feedback import NOT_YET, Feedback, off
from .reading import Unreadable, read_expression, read_numbers
from .seeds import current_student

__all__ = ["check_form", "form_of", "grade"]

RECEIVED = (
    "{what} has the form asked for; it is graded when you hand the notebook in (this check "
    "does not say whether it is right)"
)
NO_STUDENT = (
    "; first type your student id in the cell at the top that calls student_name, so that the "
    "data you work on are the ones you are graded on"
)


def form_of(judge: Any) -> dict[str, Any]:
    """The form of the answers ``judge`` takes, as keyword arguments of :func:`check_form`."""
    from .judges import AnglesJudge, ChoiceJudge, ExpressionJudge, QuaternionJudge

    if isinstance(judge, ChoiceJudge):
        form: dict[str, Any] = {"options": tuple(judge.options)}
        if judge.computed is not None:
            form["value"] = form_of(judge.computed)
        return form
    if isinstance(judge, ExpressionJudge):
        return {"expression": True}
    if isinstance(judge, AnglesJudge):
        return {"shape": (3,)}
    if isinstance(judge, QuaternionJudge):
        return {"shape": (4,)}
    import numpy as np

    return {"shape": tuple(np.shape(judge.reference))}


def _form_verdict(answer: object, form: dict[str, Any], what: str) -> str | None:
    """None when ``answer`` has the form, else what is wrong with it."""
    options: Iterable[str] | None = form.get("options")
    if options is not None:
        labels = ", ".join(repr(o) for o in options)
        value_form = form.get("value")
        label = answer[0] if isinstance(answer, (tuple, list)) and value_form else answer
        if not isinstance(label, str) or label.strip().lower() not in options:
            pair = f"a pair: one of the options {labels}, then the value" if value_form else ""
            return f"give {pair or f'one of the options {labels} (as text, in quotes)'}"
        if value_form:
            if not (isinstance(answer, (tuple, list)) and len(answer) == 2):
                return f"give a pair: one of the options {labels}, then the value"
            return _form_verdict(answer[1], value_form, "the value")
        return None
    try:
        if form.get("expression"):
            read_expression(answer, what)
        else:
            read_numbers(answer, tuple(form.get("shape", ())), what)
    except Unreadable as reason:
        return str(reason)
    return None


def check_form(exercise: str, answer: object, *, prediction: bool = False, **form: Any) -> Feedback:
    """Check only the form of an answer (graded mode's visible check).

    With ``prediction=True`` (a *predict* exercise) an answer of the right form is recorded as
    the prediction, as :func:`~.key.check` records it (see :mod:`.predictions`).

    Examples
    --------
    >>> check_form("05.1", [10, 20, 30], shape=(3,)).status
    'received'
    >>> check_form("05.1", [10, 20], shape=(3,)).message
    'your answer has shape (2,); the question asks for shape (3,)'
    """
    if not isinstance(exercise, str):
        raise TypeError(f"exercise must be an id such as '05.2', got {type(exercise).__name__}")
    hint = NO_STUDENT if current_student() is None else ""
    if answer is Ellipsis or (isinstance(answer, str) and not answer.strip()):
        return Feedback(exercise, "not yet", NOT_YET + hint)
    options = form.get("options")
    if (
        prediction
        and options is not None
        and isinstance(answer, (tuple, list))
        and len(answer) == 2
        and answer[1] is Ellipsis
        and _form_verdict(answer[0], {"options": options}, "your answer") is None
    ):
        from .predictions import record

        record(exercise.strip(), answer)
        return Feedback(
            exercise,
            "not yet",
            f"your prediction {answer[0].strip().lower()!r} is recorded; now compute the value "
            "and put it in place of the ...",
        )
    wrong = _form_verdict(answer, form, "your answer")
    if wrong is not None:
        return Feedback(exercise, "off", wrong)
    if prediction:
        from .predictions import record

        record(exercise.strip(), answer)
    return Feedback(exercise, "received", RECEIVED.format(what="your answer") + hint)


def grade(exercises: Iterable[Any], exercise: str, answer: object) -> Feedback:
    """Grade ``answer`` with the key ``exercises`` (the hidden test's own copy of the key),
    for the current student's data; for a *predict* exercise the answer that counts is the
    prediction recorded before the computation that settles it."""
    key = next((e for e in exercises if e.id == exercise), None)
    if key is None:
        raise ValueError(f"the answer key given has no exercise {exercise!r}")
    if answer is Ellipsis or (isinstance(answer, str) and not answer.strip()):
        return Feedback(key.id, "not yet", NOT_YET)
    if key.level == "predict":
        from .predictions import record

        answer = record(key.id, answer)
    try:
        verdict = key.judge_for().judge(answer)
    except Unreadable as reason:
        verdict = off(str(reason))
    return Feedback(key.id, verdict.status, verdict.message)
