"""Attacks that see only the checker's text: no exercise may be passed by searching it.

A learner who does not work an exercise could still try to read the answer off the check: try
every option of a choice; bisect a number on the wording of the feedback (60 checks); let a
derivative-free minimizer (SciPy's Nelder–Mead, 500 checks) walk a vector or a matrix towards
the answer, guided by whatever the feedback says — a verdict that changes, a "close", a number
in the text. Each attack sees only the text of :func:`eulerlib_course.exercises.check`, as a
learner does; it must fail on every exercise, for the teacher's data and for two students'.
"""

from __future__ import annotations

import itertools
import re

import numpy as np
import pytest
from scipy.optimize import minimize

from eulerlib_course.exercises import (
    AnglesJudge,
    ArrayJudge,
    ChoiceJudge,
    ExpressionJudge,
    NumberJudge,
    QuaternionJudge,
    check,
    exercises,
)
from eulerlib_course.exercises.seeds import as_student

KEY = exercises()
STUDENTS = (None, "ada", "grace")  # the teacher's data, then two students' data
NUMBER = re.compile(r"[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?")

BISECTION_CHECKS = 60
MINIMIZER_CHECKS = 500


class Found(Exception):
    """The attack reached an answer the check calls correct."""


def text(exercise: str, answer: object) -> str:
    feedback = check(exercise, answer)
    if feedback.status == "correct":
        raise Found(repr(answer))
    return feedback.message


def bisect(exercise: str, low: float, high: float) -> None:
    """Bisection on any change of the wording between the two ends of an interval."""
    said_low = text(exercise, low)
    text(exercise, high)
    for _ in range(BISECTION_CHECKS - 2):
        middle = (low + high) / 2
        if text(exercise, middle) == said_low:
            low = middle
        else:
            high = middle


def score(message: str) -> float:
    """What a minimizer reads off the text: the numbers in it (a distance, if one is given), and
    a step down for "close"."""
    numbers = [abs(float(n)) for n in NUMBER.findall(message)]
    return (0.0 if "close" in message else 1000.0) + sum(numbers)


def walk(exercise: str, shape: tuple[int, ...], start: np.ndarray, checks: int) -> None:
    result = minimize(
        lambda x: score(text(exercise, x.reshape(shape))),
        start.ravel(),
        method="Nelder-Mead",
        options={"maxfev": checks, "xatol": 1e-12, "fatol": 0.0},
    )
    text(exercise, result.x.reshape(shape))


def search(exercise_id: str, judge: object, checks: int, option: str | None = None) -> None:
    """Bisection on a number, the minimizer on anything else, with ``checks`` checks."""
    rng = np.random.default_rng(17)
    ask = exercise_id
    if option is not None:
        global text
        plain = text

        def paired(_: str, answer: object) -> str:
            return plain(exercise_id, (option, answer))

        text = paired  # type: ignore[assignment]
    try:
        if isinstance(judge, NumberJudge):
            spans = {"deg": 360.0, "rad": 2 * np.pi}
            span = spans.get(judge.unit or "", 1000.0)
            bisect(ask, -span, span)
            bisect(ask, 0.0, span)
        elif isinstance(judge, (ArrayJudge, AnglesJudge, QuaternionJudge)):
            shape = {AnglesJudge: (3,), QuaternionJudge: (4,)}.get(
                type(judge), np.shape(judge.reference)
            )
            scale = 90.0 if isinstance(judge, AnglesJudge) and judge.degrees else 1.0
            walk(ask, shape, scale * rng.uniform(-1, 1, shape), checks)
            if len(shape) == 2 and shape[0] == shape[1]:
                walk(ask, shape, np.eye(shape[0]), checks)
        else:  # pragma: no cover - a new kind of judge needs its attack here
            raise AssertionError(f"{exercise_id}: no attack for {type(judge).__name__}")
    finally:
        if option is not None:
            text = plain


def attack(exercise_id: str) -> None:
    judge = KEY[exercise_id].judge_for()
    if isinstance(judge, ChoiceJudge):
        for option in judge.options:  # every option, alone and with a computed part
            text(exercise_id, option)
            text(exercise_id, option.upper())
            text(exercise_id, (option, 0.0))
            if judge.computed is not None:
                search(exercise_id, judge.computed, MINIMIZER_CHECKS // len(judge.options), option)
    elif isinstance(judge, (NumberJudge, ArrayJudge, AnglesJudge, QuaternionJudge)):
        search(exercise_id, judge, MINIMIZER_CHECKS)
    elif isinstance(judge, ExpressionJudge):
        # a symbolic answer has no numbers to search; the attack tries what a guesser would
        import sympy as sp

        for value in (0, 1, -1, sp.eye(3), sp.zeros(3, 3), sp.Matrix([1, 0, 0])):
            text(exercise_id, value)
    else:  # pragma: no cover - a new kind of judge needs its attack here
        raise AssertionError(f"{exercise_id}: no attack for {type(judge).__name__}")


@pytest.mark.slow
@pytest.mark.parametrize(("exercise_id", "student"), list(itertools.product(KEY, STUDENTS)))
def test_an_attack_that_reads_only_the_feedback_fails(
    exercise_id: str, student: str | None
) -> None:
    with as_student(student):
        try:
            attack(exercise_id)
        except Found as found:
            pytest.fail(f"{exercise_id} (student {student}): the attack passed with {found}")
