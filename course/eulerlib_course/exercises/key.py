"""The answer key: every exercise of the course, with its reference, its judge and its test table.

Each notebook ``NN`` has a module ``nbNN`` here whose ``EXERCISES`` list holds its exercises,
``"NN.1"``, ``"NN.2"``, … in order. An :class:`Exercise` keeps together what a teacher needs to
trust it:

* the **judge** (:mod:`.judges`) with the reference and the tolerance, which the learner's check
  cell never shows;
* the data the question gives (``given``), handed to the notebook by :func:`given` so that the
  exercise cell shows the question's data but not how it was made;
* the **test table** (``examples``): the answers a learner might type, each with the verdict and
  the words of the feedback it must get — at least one answer that is right in another form than
  the worked solution, and the typical wrong answers. The course's tests run every example
  through the student copy of the notebook;
* ``forbidden``: text that would give the answer away, which no visible cell of a student copy may
  contain;
* ``per_student`` (optional): how to make the question's data from a random generator, and
  ``judged``: the judge for given data. With them each student gets data of their own
  (:mod:`.seeds`), judged against the reference computed from that student's data; ``given``
  and ``judge`` stay the teacher's fixed data and judge, which the worked solutions and the
  stored outputs use;
* ``level``: where it stands in the notebook's climb: ``apply`` (use the idea), ``predict`` (say
  what will happen before computing it), ``extend`` (carry the idea to a new case).
"""

from __future__ import annotations

import importlib
import pkgutil
import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np

from .feedback import NOT_YET, Feedback, Status, off
from .judges import Judge
from .reading import Unreadable
from .seeds import current_student, rng_for

Level = Literal["apply", "predict", "extend"]
_ID = re.compile(r"\d\d\.\d")


@dataclass(frozen=True)
class Example:
    """One row of an exercise's test table.

    ``code`` is what a learner might write in place of the ``...`` of the exercise cell (it is run
    in the notebook, after the exercise cell's own lines); ``status`` the verdict it must get;
    ``says`` words the feedback must contain (for a wrong answer: the diagnosis).
    """

    code: str
    status: Status
    says: str = ""


@dataclass(frozen=True)
class Exercise:
    """One exercise of the course (see the module docstring)."""

    id: str
    level: Level
    judge: Judge
    examples: tuple[Example, ...]
    given: Callable[[], Any] | None = None
    forbidden: tuple[str, ...] = ()
    per_student: Callable[[np.random.Generator], Any] | None = None
    judged: Callable[[Any], Judge] | None = None
    seed_of: str = ""  # the exercise whose data this one reuses ("" for its own)

    def __post_init__(self) -> None:
        if not _ID.fullmatch(self.id):
            raise ValueError(f"an exercise id is 'NN.k' (notebook, number), got {self.id!r}")
        if self.level not in ("apply", "predict", "extend"):
            raise ValueError(f"{self.id}: level must be apply, predict or extend")
        if (self.per_student is None) != (self.judged is None):
            raise ValueError(f"{self.id}: per_student and judged go together")

    def data_for(self, name: str | None) -> Any:
        """The question's data for student ``name`` (None: the teacher's fixed data)."""
        if name is not None and self.per_student is not None:
            return self.per_student(rng_for(self.seed_of or self.id, name))
        if self.given is None:
            raise ValueError(f"exercise {self.id} gives no data")
        return self.given()

    def judge_for(self, name: str | None = None) -> Judge:
        """The judge of student ``name``'s answer (None: the current student, see
        :func:`.seeds.current_student`; the teacher's judge when nobody is named)."""
        name = current_student() if name is None else name
        if self.judged is not None and name is not None:
            return self.judged(self.data_for(name))
        return self.judge


def _modules() -> list[str]:
    package = __name__.rsplit(".", 1)[0]
    path = importlib.import_module(package).__path__
    return sorted(
        f"{package}.{m.name}" for m in pkgutil.iter_modules(path) if m.name.startswith("nb")
    )


_EXERCISES: dict[str, Exercise] | None = None


def exercises() -> dict[str, Exercise]:
    """Every exercise of the course by id, in course order (the key modules load on first use)."""
    global _EXERCISES
    if _EXERCISES is None:
        found: dict[str, Exercise] = {}
        for name in _modules():
            for exercise in importlib.import_module(name).EXERCISES:
                if exercise.id in found:
                    raise ValueError(f"exercise {exercise.id} is defined twice")
                found[exercise.id] = exercise
        _EXERCISES = found
    return _EXERCISES


def _lookup(exercise: object) -> Exercise:
    if not isinstance(exercise, str):
        raise TypeError(f"exercise must be an id such as '05.2', got {type(exercise).__name__}")
    if not exercises():
        raise ValueError(
            "the answer key is not installed here (graded mode): your answers are checked for "
            "their form, and graded when you hand them in"
        )
    key = exercises().get(exercise.strip())
    if key is None:
        raise ValueError(f"there is no exercise {exercise!r} in the course")
    return key


def _blank(answer: object) -> bool:
    """Whether an answer is still blank: the ``...`` of the exercise cell, or empty text."""
    return answer is Ellipsis or (isinstance(answer, str) and not answer.strip())


def check(exercise: str, answer: object) -> Feedback:
    """Judge a learner's answer to an exercise of the course.

    Parameters
    ----------
    exercise : str
        The exercise, ``"NN.k"``: notebook ``NN``, exercise ``k``.
    answer : object
        The learner's answer; ``...`` (the placeholder of the exercise cell) means not yet
        attempted.

    Returns
    -------
    Feedback
        ``correct``, ``off`` with the likely reason, or ``not yet``. Shown by Jupyter as the
        cell's output; nothing is printed.

    Raises
    ------
    TypeError, ValueError
        If ``exercise`` is not the id of an exercise of the course (a mistake in the notebook,
        not in the answer). An answer never raises: whatever it is, it gets feedback.

    Examples
    --------
    >>> check("05.1", ...)
    Exercise 05.1 — not yet: there is no answer yet; replace the ... with your answer and run the
    cell again
    """
    key = _lookup(exercise)
    if key.level == "predict":
        from .predictions import record

        counted = record(key.id, answer)
        if not _blank(answer) and not _same_answer(counted, answer):
            feedback = check_recorded(key, counted)
            return Feedback(
                key.id,
                feedback.status,
                f"{feedback.message} (the prediction that counts is the one made before the "
                "computation)",
            )
    return check_recorded(key, answer)


def _same_answer(a: object, b: object) -> bool:
    if a is b:
        return True
    if isinstance(a, tuple) and isinstance(b, (tuple, list)) and len(a) == len(b) == 2:
        return a[0] == b[0] and a[1] is b[1]
    return False


def check_recorded(key: Exercise, answer: object) -> Feedback:
    """Judge ``answer`` to the exercise ``key`` (no prediction is recorded)."""
    if _blank(answer):
        return Feedback(key.id, "not yet", NOT_YET)
    try:
        verdict = key.judge_for().judge(answer)
    except Unreadable as reason:
        verdict = off(str(reason))
    return Feedback(key.id, verdict.status, verdict.message)


def given(exercise: str) -> Any:
    """The data an exercise's question gives (a fresh copy each call).

    The current student's own data when the exercise makes data per student (see
    :mod:`.seeds`), otherwise the teacher's.

    Examples
    --------
    >>> R = given("05.1")
    >>> R.shape
    (3, 3)
    """
    key = _lookup(exercise)
    return key.data_for(current_student())
