"""Answer key of notebook 09, numerical robustness (Rose eq 3b and eq 4; Baker's poles)."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from eulerlib import matrix_to_euler, rot_x, rot_y, rot_z

from .judges import AnglesJudge, ChoiceJudge, Constraint, Mistake, NumberJudge
from .key import Example, Exercise

_DISTANCE = 1e-9  # 09.1: how far below 90° the pitch of the given matrix is, radians
_HEADING, _BANK = -70.0, 20.0  # 09.3: Baker's north pole, degrees; only heading + bank survives


def _close_to_lock() -> NDArray[np.float64]:
    """09.1: a yaw-pitch-roll matrix whose pitch is π/2 − 1e-9, built from sin d and cos d."""
    s, c = math.sin(_DISTANCE), math.cos(_DISTANCE)  # cos(pitch) and sin(pitch)
    pitch = np.array([[s, 0.0, c], [0.0, 1.0, 0.0], [-c, 0.0, s]])
    matrix: NDArray[np.float64] = rot_z(0.7) @ pitch @ rot_x(-2.1)
    return matrix


def _multiply(A: NDArray[np.float64], B: NDArray[np.float64]) -> NDArray[np.float64]:
    """The matrix product written out entry by entry, so that it rounds the same everywhere."""
    return np.array(
        [
            [A[i, 0] * B[0, j] + A[i, 1] * B[1, j] + A[i, 2] * B[2, j] for j in range(3)]
            for i in range(3)
        ]
    )


def _noisy_north_pole(heading: float = _HEADING, bank: float = _BANK) -> NDArray[np.float64]:
    """09.3: Baker's R = Ry(h) Rz(90°) Rx(b), the 90° made of two steps with exact decimals
    (heading and bank in degrees)."""
    first = np.array([[0.8432, -0.5376, 0.0], [0.5376, 0.8432, 0.0], [0.0, 0.0, 1.0]])
    second = np.array([[0.5376, -0.8432, 0.0], [0.8432, 0.5376, 0.0], [0.0, 0.0, 1.0]])
    attitude_90 = _multiply(first, second)  # about 32.52° + 57.48° about z
    turn = rot_y(heading, degrees=True)
    return _multiply(_multiply(turn, attitude_90), rot_x(bank, degrees=True))


def _general_formulas(m: NDArray[np.float64]) -> list[float]:
    """Baker's general formulas, without the pole test (degrees)."""
    return [
        math.degrees(math.atan2(-m[2, 0], m[0, 0])),
        math.degrees(math.asin(min(1.0, m[1, 0]))),
        math.degrees(math.atan2(-m[1, 2], m[1, 1])),
    ]


_FLAT_SINE = (
    "you used asin: next to 90° the sine is flat, r31 rounds to exactly −1 here and asin returns "
    "exactly π/2; take the pitch from atan2 of its sine and its cosine instead"
)
_NOISE = (
    "heading 0° and bank 0° do not give this matrix: at the north pole it fixes only heading + "
    "bank, which is not 0° here. The general formulas give these zeros (at the pole m20, m00, "
    "m12 and m11 are rounding noise, and atan2 of noise is no angle at all), and so does "
    "setting the heading to 0°, which is Rose's choice, not Baker's; Baker's choice is bank = "
    "0°, and the heading then carries the whole sum: heading = atan2(m02, m22)"
)


def _some_close_to_lock(rng: np.random.Generator) -> NDArray[np.float64]:
    """A student's matrix like 09.1's: pitch π/2 − d with d from 2e-9 to 9e-9, other yaw, roll."""
    d = float(rng.integers(2, 10)) * 1e-9
    s, c = math.sin(d), math.cos(d)
    pitch = np.array([[s, 0.0, c], [0.0, 1.0, 0.0], [-c, 0.0, s]])
    yaw, roll = rng.uniform(-3.0, 3.0, 2)
    matrix: NDArray[np.float64] = rot_z(float(yaw)) @ pitch @ rot_x(float(roll))
    return matrix


def _judge_pitch(pitch: float) -> NumberJudge:
    return NumberJudge(
        pitch,
        what="your pitch",
        tol=1e-15,
        unit="rad",
        mistakes=(
            Mistake(math.pi / 2, _FLAT_SINE),
            Mistake(
                math.pi / 2 - pitch,
                "that is the distance from 90°; the question asks for the pitch itself",
            ),
        ),
    )


def _some_north_pole(rng: np.random.Generator) -> NDArray[np.float64]:
    """A student's noisy north-pole matrix like 09.3's: heading and bank whole degrees, their sum
    at least 10° from 0°, ±90° and 180° and other than in the teacher's edition."""
    while True:
        heading, bank = float(rng.integers(-170, 171)), float(rng.integers(-80, 81))
        total = 180.0 - (180.0 - (heading + bank)) % 360.0  # in (−180°, 180°]
        far = min(abs(total), abs(abs(total) - 90.0), 180.0 - abs(total)) >= 10.0
        if far and total != _HEADING + _BANK:
            return _noisy_north_pole(heading, bank)


def _judge_north_pole(N: NDArray[np.float64]) -> AnglesJudge:
    """The judge of 09.3: at the north pole m02 = sin(h + b) and m22 = cos(h + b)."""
    total = math.degrees(math.atan2(float(N[0, 2]), float(N[2, 2])))
    return AnglesJudge(
        [total, 90.0, 0.0],
        "baker",
        degrees=True,
        what="your heading, attitude, bank",
        constraints=(
            Constraint(
                lambda a: abs((float(a[2]) + 180.0) % 360.0 - 180.0) <= 1e-9,
                "the question asks for Baker's choice at the poles, bank = 0°",
            ),
        ),
        mistakes=(
            Mistake(_general_formulas(N), _NOISE),
            Mistake([0.0, 90.0, 0.0], _NOISE),
        ),
    )


EXERCISES = [
    Exercise(
        id="09.1",
        level="apply",
        judge=_judge_pitch(math.pi / 2 - _DISTANCE),
        per_student=_some_close_to_lock,
        judged=lambda R: _judge_pitch(float(matrix_to_euler(R, "ZYX")[1])),
        given=_close_to_lock,
        examples=(
            Example(
                "np.arctan2(-R_close[2, 0], np.hypot(R_close[0, 0], R_close[1, 0]))", "correct"
            ),
            Example(
                "np.arctan2(-R_close[2, 0], np.hypot(R_close[2, 1], R_close[2, 2]))",
                "correct",
                "is right",
            ),
            Example("matrix_to_euler(R_close, 'ZYX')[1]", "correct", "is right"),
            Example("-np.arcsin(R_close[2, 0])", "off", "asin"),
            Example(
                "np.degrees(np.arctan2(-R_close[2, 0], np.hypot(R_close[0, 0], R_close[1, 0])))",
                "off",
                "degrees",
            ),
            Example(
                "np.arctan2(R_close[2, 0], np.hypot(R_close[0, 0], R_close[1, 0]))",
                "off",
                "wrong sign",
            ),
            Example("1e-9", "off", "distance from 90°"),
        ),
        forbidden=("np.pi / 2 - 1e-9", "1.5707963257948966"),
    ),
    Exercise(
        id="09.2",
        level="predict",
        judge=ChoiceJudge(
            options={"a": "about 1e-20", "b": "about 1e-16", "c": "about 1e-12", "d": "about 1e-8"},
            answer="c",
            computed=NumberJudge(
                float(np.finfo(np.float64).eps) / 1e-4,
                what="your size ε/d",
                tol=0.01 * float(np.finfo(np.float64).eps) / 1e-4,
                hint="divide the spacing of doubles next to 1, np.finfo(float).eps, by d",
            ),
            computed_what="the size ε/d you computed",
            explanations={
                "a": "no formula can be that accurate: the doubles next to π/2 are about 2e-16 "
                "apart, so a pitch near 90° cannot even be stored that closely",
                "b": "that is what atan2 of the sine and the cosine achieves; asin reads the pitch "
                "from r31 alone, where the error is about ε/d",
                "c": "the error of asin is of the order of ε/d: a rounding error of r31 divided "
                "by the slope of the sine there, sin d ≈ d = 1e-4",
                "d": "that is the worst case, near d = 1e-8; further from lock the error of asin "
                "shrinks like 1/d",
            },
        ),
        examples=(
            Example("('c', np.finfo(float).eps / 1e-4)", "correct", "ε/d"),
            Example("('C ', 2.22e-12)", "correct", "1e-4"),
            Example("('c', np.finfo(float).eps * 1e-4)", "off", "size ε/d"),
            Example("('b', np.finfo(float).eps / 1e-4)", "off", "atan2"),
            Example("('d', 1e-8)", "off", "worst case"),
            Example("('a', 1e-20)", "off", "cannot even be stored"),
            Example("1e-12", "off", "give a pair"),
        ),
    ),
    Exercise(
        id="09.3",
        level="extend",
        judge=_judge_north_pole(_noisy_north_pole()),
        per_student=_some_north_pole,
        judged=_judge_north_pole,
        given=_noisy_north_pole,
        examples=(
            Example("[np.degrees(np.arctan2(N_ex[0, 2], N_ex[2, 2])), 90.0, 0.0]", "correct"),
            Example("[310, 90, 360]", "correct", "rotation asked for"),
            Example(
                "np.degrees([np.arctan2(-N_ex[2, 0], N_ex[0, 0]), np.arcsin(N_ex[1, 0]),"
                " np.arctan2(-N_ex[1, 2], N_ex[1, 1])])",
                "off",
                "rounding noise",
            ),
            Example("[0, 90, 0]", "off", "atan2(m02, m22)"),
            Example("[0, 90, -50]", "off", "bank = 0°"),
            Example("[-50, -90, 0]", "off", "attitude has the wrong sign"),
            Example("np.radians([-50, 90, 0])", "off", "radians"),
        ),
        forbidden=("-50",),
    ),
]
