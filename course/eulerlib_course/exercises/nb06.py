"""Answer key of notebook 06, gimbal lock algebraically (Rose eq 4, Baker's poles, the Jacobian)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import NDArray

from eulerlib import euler_to_matrix, matrix_to_euler

from .judges import AnglesJudge, ArrayJudge, Constraint, ExpressionJudge, Mistake
from .key import Example, Exercise

# 06.1: a matrix built at pitch +90°, where only roll − yaw is defined (Rose eq 4b).
_LOCKED_YPR = [25.0, 90.0, -15.0]
_ROLL_MINUS_YAW = _LOCKED_YPR[2] - _LOCKED_YPR[0]


def _wrapped(angle: float) -> float:
    """``angle`` in degrees, brought into (−180°, 180°] by whole turns."""
    return 180.0 - (180.0 - angle) % 360.0


class _Symbolic:
    """An expression in the angles of ``euler_symbols()``, built when SymPy first reads it.

    ``sympy.sympify`` (which the expression judge applies to its reference and mistakes) calls
    ``_sympy_``, so the key can be imported without SymPy, as the course package promises.
    """

    def __init__(self, build: Callable[[Any, Any], Any]) -> None:
        self._build = build

    def _sympy_(self) -> Any:
        from eulerlib.symbolic import euler_symbols

        alpha, _, gamma = euler_symbols()
        return self._build(alpha, gamma)


_DIFFERENCE = (
    "a difference would mean the two turns oppose each other; work out where the turn "
    "R_y(+90°) lays the third axis z, and compare its direction with the first axis"
)


def _some_locked_matrix(rng: np.random.Generator) -> NDArray[np.float64]:
    """A student's matrix at pitch +90°: yaw and roll whole degrees, roll − yaw away from 0°,
    ±90° and 180° (where the typical mistakes would coincide with the answer) and other than in
    the teacher's edition (whose stored outputs show its answer)."""
    while True:
        yaw, roll = (float(a) for a in rng.integers(-80, 81, 2))
        difference = abs(roll - yaw) % 90.0
        if 10.0 <= difference <= 80.0 and roll - yaw != _ROLL_MINUS_YAW:
            return euler_to_matrix([yaw, 90.0, roll], "rose", degrees=True)


def _judge_locked_matrix(R: NDArray[np.float64]) -> AnglesJudge:
    """The judge of 06.1 for a matrix at pitch +90°: roll − yaw from the library."""
    yaw, _, roll = matrix_to_euler(R, "rose", degrees=True, warn=False)
    return _judge_locked(float(roll - yaw))


def _judge_locked(roll_minus_yaw: float) -> AnglesJudge:
    return AnglesJudge(
        [0.0, 90.0, roll_minus_yaw],
        "rose",
        degrees=True,
        what="your yaw, pitch, roll",
        constraints=(
            Constraint(
                lambda a: abs(_wrapped(float(a[0]))) < 1e-9,
                "the question asks for Rose's choice, yaw = 0",
            ),
        ),
        mistakes=(
            Mistake(
                [0.0, 90.0, roll_minus_yaw + 180.0],
                "that roll comes from eq 4a, atan2(−r12, −r13), which belongs to pitch −90° "
                "(r31 = +1); here r31 = −1: use the formula of the other pole",
            ),
            Mistake(
                [0.0, 90.0, -roll_minus_yaw],
                "these angles give roll − yaw with the wrong sign: write out which entries of "
                "the matrix at pitch +90° hold the sine and the cosine of the combination, "
                "with their signs",
            ),
            Mistake(
                [0.0, 90.0, 90.0 - roll_minus_yaw],
                "the arguments of atan2 are swapped: atan2(y, x) takes the sine entry first, "
                "and r12 = sin(roll − yaw)",
            ),
        ),
    )


EXERCISES = [
    Exercise(
        id="06.1",
        level="apply",
        judge=_judge_locked(_ROLL_MINUS_YAW),
        per_student=_some_locked_matrix,
        judged=_judge_locked_matrix,
        given=lambda: euler_to_matrix(_LOCKED_YPR, "rose", degrees=True),
        examples=(
            Example(
                "[0.0, -np.degrees(np.arcsin(W_R_B_ex[2, 0])),"
                " np.degrees(np.arctan2(W_R_B_ex[0, 1], W_R_B_ex[0, 2]))]",
                "correct",
            ),
            Example("[0, 90, 320]", "correct"),
            Example("[360, 90, -40]", "correct"),
            Example("[20, 90, -20]", "off", "yaw = 0"),
            Example(
                "[0, 90, np.degrees(np.arctan2(-W_R_B_ex[0, 1], -W_R_B_ex[0, 2]))]", "off", "eq 4a"
            ),
            Example(
                "[0, 90, np.degrees(np.arctan2(W_R_B_ex[0, 2], W_R_B_ex[0, 1]))]", "off", "swapped"
            ),
            Example("[0, -90, -40]", "off", "pitch has the wrong sign"),
            Example("[0, 90, 40]", "off", "roll − yaw with the wrong sign"),
            Example("[-40, 90, 0]", "off", "roll − yaw with the wrong sign"),
            Example("np.radians([0, 90, -40])", "off", "radians"),
        ),
        forbidden=("-40", "320"),
    ),
    Exercise(
        id="06.2",
        level="predict",
        judge=ExpressionJudge(
            _Symbolic(lambda alpha, gamma: alpha + gamma),
            what="your combination",
            up_to_sign=True,
            mistakes=(
                Mistake(_Symbolic(lambda alpha, gamma: alpha - gamma), _DIFFERENCE),
                Mistake(_Symbolic(lambda alpha, gamma: gamma - alpha), _DIFFERENCE),
            ),
        ),
        examples=(
            Example("gamma + alpha", "correct"),
            Example("-(alpha + gamma)", "correct", "other sign"),
            Example("alpha - gamma", "off", "oppose each other"),
            Example("gamma - alpha", "off", "oppose each other"),
            Example(
                "sp.trigsimp(euler_matrix((alpha, sp.pi / 2, gamma), 'XYZ'))",
                "off",
                "not an expression",
            ),
            Example("'alpha + gamma'", "off", "text"),
        ),
        forbidden=("alpha + gamma", "gamma + alpha"),
    ),
    Exercise(
        id="06.3",
        level="extend",
        judge=ArrayJudge(
            np.array([1.0, 0.0, -1.0]),
            what="your rates",
            tol=1e-9,
            mistakes=(
                Mistake(
                    [-1.0, 0.0, 1.0],
                    "these rates do nothing too, but the question asks for the direction scaled "
                    "so that the heading rate is 1",
                ),
                Mistake(
                    [np.sqrt(0.5), 0.0, -np.sqrt(0.5)],
                    "that is the right direction, with length 1; the question asks for it scaled "
                    "so that the heading rate is 1 (divide by the first component)",
                ),
                Mistake(
                    [-np.sqrt(0.5), 0.0, np.sqrt(0.5)],
                    "that is the right direction, with length 1 and the other sign; the question "
                    "asks for it scaled so that the heading rate is 1 (divide by the first "
                    "component)",
                ),
                Mistake(
                    [1.0, 0.0, 1.0],
                    "these keep heading − bank fixed, the combination of the south pole; at the "
                    "north pole (attitude +90°) the matrix depends on heading + bank",
                ),
                Mistake(
                    [1.0, 0.0, 0.0],
                    "a heading rate alone turns the body about the vertical; only together with "
                    "a bank rate can it cancel",
                ),
            ),
        ),
        examples=(
            Example("np.array([1.0, 0.0, -1.0])", "correct"),
            Example("[1, 0, -1]", "correct"),
            Example("[-1, 0, 1]", "off", "scaled"),
            Example("[1, 0, 1]", "off", "south pole"),
            Example(  # the null direction as numpy's SVD gives it: unit length, either sign
                "np.linalg.svd(np.array(angular_velocity_jacobian((0.2, sp.pi / 2, 0.3), 'baker'),"
                " dtype=float))[2][-1]",
                "off",
                "length 1",
            ),
            Example("[1, 0, 0]", "off", "only together"),
            Example("[1, 1, -1]", "off", "are not it"),
        ),
        forbidden=("[1, 0, -1]", "1.0, 0.0, -1.0"),
    ),
]
