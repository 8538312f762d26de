"""Predictions: a "predict first" answer recorded before the computation that settles it.

A *predict* exercise asks for an answer before the notebook computes it. Its check cell (or
:func:`predict`) records the learner's prediction and judges it. A cell that settles the
question calls :func:`settle` with the computation; it runs the computation only once a
prediction is recorded, and otherwise asks for one. From then on the prediction is fixed: a
changed answer is still judged, but the one that counts is the prediction made before the
computation. Nothing depends on timing or randomness, so stored outputs stay the same.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from .feedback import Feedback
from .key import _ID, _blank, _lookup, check, exercises

__all__ = ["predict", "prediction", "settle"]

_PREDICTIONS: dict[str, Any] = {}
_SETTLED: set[str] = set()


def _option_and_value(answer: object) -> tuple[object, object] | None:
    if isinstance(answer, (tuple, list)) and len(answer) == 2:
        return answer[0], answer[1]
    return None


def record(exercise: str, answer: object) -> object:
    """Record ``answer`` as the prediction of ``exercise`` unless the question is settled;
    return the answer that counts.

    For a choice with a computed part, ``(option, value)``, only the option is the prediction:
    after the settling computation the option stays the one recorded, and the computed value
    may still be corrected.
    """
    pair = _option_and_value(answer)
    if not _blank(answer) and exercise not in _SETTLED:
        _PREDICTIONS[exercise] = answer
    recorded = _PREDICTIONS.get(exercise, answer)
    if exercise in _SETTLED and pair is not None:
        before = _option_and_value(recorded)
        return (before[0] if before is not None else recorded, pair[1])
    return recorded


def predict(exercise: str, answer: object) -> Feedback:
    """Record a prediction for ``exercise`` (the first one stays) and judge it.

    The check cell of a *predict* exercise records its answer the same way.

    Examples
    --------
    >>> forget()
    >>> predict("07.2", ...).status
    'not yet'
    >>> prediction("07.2") is None
    True
    """
    key = _lookup(exercise)
    if key.level != "predict":
        raise ValueError(f"exercise {key.id} is not a prediction; check it with check()")
    return check(key.id, answer)


def prediction(exercise: str) -> Any:
    """The prediction recorded for ``exercise``, or None."""
    return _PREDICTIONS.get(_lookup(exercise).id)


def settle(exercise: str, computation: Callable[[], Any]) -> Any:
    """The result of ``computation`` once a prediction of ``exercise`` is recorded.

    Until then the computation does not run and a line asks for the prediction; once it has
    run, the prediction is fixed.

    Examples
    --------
    >>> forget()
    >>> settle("07.2", lambda: 180.0)
    'predict first: give your answer to exercise 07.2 and run its check cell'
    """
    exercise_id = _settled_id(exercise)
    if exercise_id not in _PREDICTIONS:
        return f"predict first: give your answer to exercise {exercise_id} and run its check cell"
    _SETTLED.add(exercise_id)
    return computation()


def _settled_id(exercise: object) -> str:
    """The id of ``exercise``; without the answer key (graded mode) any id of the form 'NN.k'."""
    if isinstance(exercise, str) and not exercises() and _ID.fullmatch(exercise.strip()):
        return exercise.strip()
    return _lookup(exercise).id


def forget() -> None:
    """Forget every recorded prediction (a fresh kernel; for tests)."""
    _PREDICTIONS.clear()
    _SETTLED.clear()
