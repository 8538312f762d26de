"""Answer key of notebook 05, from the matrix back to the angles (Rose eq 3, Baker's formulas).

The course states one range for the angles and uses it everywhere: yaw and roll (the outer
angles) in (−180°, 180°], pitch (the middle angle) in [−90°, 90°]. Answers equal up to whole
turns give the same rotation and pass, unless the question says otherwise.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from eulerlib import euler_to_matrix, matrix_to_euler

from .judges import AnglesJudge, Constraint, Mistake
from .key import Example, Exercise

_YPR = [-100.0, 35.0, 160.0]  # yaw, pitch, roll of the matrix the learner is given
_XYZ = [50.0, -25.0, 110.0]  # α, β, γ of the "XYZ" matrix of 05.3


def _wrapped(angle: float) -> float:
    """``angle`` in degrees, brought into (−180°, 180°] by whole turns."""
    return 180.0 - (180.0 - angle) % 360.0


_ATAN = "atan(y/x) cannot tell (x, y) from (−x, −y); use atan2(y, x), which keeps the quadrant"


def _some_angle(rng: np.random.Generator, low: int, high: int, away_from: tuple[int, ...]) -> float:
    """A whole number of degrees in [low, high], at least 15° from each angle of ``away_from``."""
    while True:
        angle = int(rng.integers(low, high + 1))
        if all(abs(angle - a) >= 15 for a in away_from):
            return float(angle)


def _some_ypr(rng: np.random.Generator) -> list[float]:
    """A student's yaw, pitch, roll: outer angles away from 0° and ±180°, pitch from lock."""
    return [
        _some_angle(rng, -165, 165, (0,)),
        _some_angle(rng, -75, 75, (0,)),
        _some_angle(rng, -165, 165, (0,)),
    ]


def _past_a_quadrant(rng: np.random.Generator) -> float:
    """A whole number of degrees, 105° to 165° either way: outside atan's ±90°, away from ±180°."""
    return float(rng.choice([-1.0, 1.0])) * _some_angle(rng, 105, 165, ())


def _matrix_of_some_ypr(rng: np.random.Generator) -> NDArray[np.float64]:
    """A student's matrix for 05.1 and 05.2: yaw and roll both past a quadrant, as the
    teacher's, so that reading either with atan instead of atan2 is a mistake for everyone."""
    yaw, pitch, roll = _past_a_quadrant(rng), _some_angle(rng, -75, 75, (0,)), _past_a_quadrant(rng)
    return euler_to_matrix([yaw, pitch, roll], "rose", degrees=True)


def _matrix_of_some_xyz(rng: np.random.Generator) -> NDArray[np.float64]:
    return euler_to_matrix(_some_ypr(rng), "XYZ", degrees=True)


def _judge_1(ypr: list[float]) -> AnglesJudge:
    return AnglesJudge(
        ypr,
        "rose",
        degrees=True,
        what="your yaw, pitch, roll",
        mistakes=(
            Mistake(
                [_wrapped(ypr[0] + 180), ypr[1], _wrapped(ypr[2] + 180)],
                f"yaw and roll are both off by 180°: {_ATAN}",
            ),
        ),
    )


def _judge_2(ypr: list[float]) -> AnglesJudge:
    return AnglesJudge(
        [_wrapped(ypr[0] + 180), 180 - ypr[1], _wrapped(ypr[2] + 180)],
        "rose",
        degrees=True,
        what="your second triple",
        mistakes=(
            Mistake(
                [_wrapped(ypr[0] + 180), 180 - ypr[1], ypr[2]],
                "the second triple turns both outer angles by 180°: yaw and roll",
            ),
            Mistake(
                [ypr[0], 180 - ypr[1], _wrapped(ypr[2] + 180)],
                "the second triple turns both outer angles by 180°: yaw and roll",
            ),
            Mistake(
                [ypr[0], 180 - ypr[1], ypr[2]],
                "180° − pitch alone flips the common factor cos(pitch); yaw and roll must "
                "each turn by 180° to flip it back",
            ),
        ),
        constraints=(
            Constraint(
                lambda a: abs(_wrapped(float(a[1]))) > 90.0 + 1e-9,
                "the question asks for the other triple, the one with pitch outside [-90°, 90°]",
            ),
        ),
    )


def _judge_3(xyz: list[float]) -> AnglesJudge:
    return AnglesJudge(
        xyz,
        "XYZ",
        degrees=True,
        what="your angles for 'XYZ'",
        mistakes=(
            Mistake(
                [-xyz[0], xyz[1], -xyz[2]],
                "α and γ both have the wrong sign: the sine entries of 'XYZ' carry a minus "
                "sign (X[1, 2] = −sin α cos β, X[0, 1] = −sin γ cos β)",
            ),
        ),
    )


def _judge_1_of_matrix(R: NDArray[np.float64]) -> AnglesJudge:
    return _judge_1(list(matrix_to_euler(R, "rose", degrees=True)))


def _judge_2_of_matrix(R: NDArray[np.float64]) -> AnglesJudge:
    return _judge_2(list(matrix_to_euler(R, "rose", degrees=True)))


def _judge_3_of_matrix(M: NDArray[np.float64]) -> AnglesJudge:
    return _judge_3(list(matrix_to_euler(M, "XYZ", degrees=True)))


EXERCISES = [
    Exercise(
        id="05.1",
        level="apply",
        judge=_judge_1(_YPR),
        per_student=_matrix_of_some_ypr,
        judged=_judge_1_of_matrix,
        given=lambda: euler_to_matrix(_YPR, "rose", degrees=True),
        examples=(
            Example(
                "np.degrees([np.arctan2(R_ex[1, 0], R_ex[0, 0]), -np.arcsin(R_ex[2, 0]),"
                " np.arctan2(R_ex[2, 1], R_ex[2, 2])])",
                "correct",
            ),
            Example("[260, 35, -200]", "correct", "rotation asked for"),
            Example("matrix_to_euler(R_ex, 'rose', degrees=True)", "correct"),
            Example(
                "np.degrees([np.arctan(R_ex[1, 0] / R_ex[0, 0]), -np.arcsin(R_ex[2, 0]),"
                " np.arctan(R_ex[2, 1] / R_ex[2, 2])])",
                "off",
                "both off by 180°: atan(y/x)",
            ),
            Example(
                "np.degrees([np.arctan(R_ex[1, 0] / R_ex[0, 0]), -np.arcsin(R_ex[2, 0]),"
                " np.arctan2(R_ex[2, 1], R_ex[2, 2])])",
                "off",
                "yaw is off by 180°",
            ),
            Example(
                "[np.arctan2(R_ex[1, 0], R_ex[0, 0]), -np.arcsin(R_ex[2, 0]),"
                " np.arctan2(R_ex[2, 1], R_ex[2, 2])]",
                "off",
                "radians",
            ),
            Example("[160, 35, -100]", "off", "reverse order"),
            Example(
                "np.degrees([np.arctan2(R_ex[1, 0], R_ex[0, 0]), np.arcsin(R_ex[2, 0]),"
                " np.arctan2(R_ex[2, 1], R_ex[2, 2])])",
                "off",
                "pitch has the wrong sign",
            ),
            Example("'-100, 35, 160'", "off", "text"),
        ),
        forbidden=("-100", "160"),
    ),
    Exercise(
        id="05.2",
        level="predict",
        judge=_judge_2(_YPR),
        per_student=_matrix_of_some_ypr,
        judged=_judge_2_of_matrix,
        seed_of="05.1",
        examples=(
            Example("[80, 145, -20]", "correct"),
            Example("[80, 145, 340]", "correct"),
            Example("[-280, -215, -20]", "correct"),
            Example("[-100, 35, 160]", "off", "pitch outside"),
            Example("[80, -145, -20]", "off", "pitch has the wrong sign"),
            Example("[80, 145, 160]", "off", "both outer angles"),
            Example("[260, 145, 340]", "off", "both outer angles"),
            Example("[-100, 145, 160]", "off", "each turn by 180°"),
            # the same two, computed from R_ex, so that they hold for every student's data
            Example(
                "(lambda y, p, r: [y + 180, 180 - p, r + 180])"
                "(*matrix_to_euler(R_ex, 'rose', degrees=True))",
                "correct",
            ),
            Example(
                "(lambda y, p, r: [y, 180 - p, r])(*matrix_to_euler(R_ex, 'rose', degrees=True))",
                "off",
                "each turn by 180°",
            ),
        ),
        forbidden=("80, 145", "145"),
    ),
    Exercise(
        id="05.3",
        level="extend",
        judge=_judge_3(_XYZ),
        per_student=_matrix_of_some_xyz,
        judged=_judge_3_of_matrix,
        given=lambda: euler_to_matrix(_XYZ, "XYZ", degrees=True),
        examples=(
            Example(
                "np.degrees([np.arctan2(-M_ex[1, 2], M_ex[2, 2]), np.arcsin(M_ex[0, 2]),"
                " np.arctan2(-M_ex[0, 1], M_ex[0, 0])])",
                "correct",
            ),
            Example("[50 - 360, -25, 110]", "correct"),
            Example(
                "np.degrees([np.arctan2(M_ex[1, 2], M_ex[2, 2]), np.arcsin(M_ex[0, 2]),"
                " np.arctan2(M_ex[0, 1], M_ex[0, 0])])",
                "off",
                "both have the wrong sign",
            ),
            Example("[50, -25, 110][::-1]", "off", "reverse order"),
            Example("np.degrees(matrix_to_euler(M_ex, 'xyz'))", "off", "fixed axes (extrinsic)"),
        ),
        forbidden=("-25", "110"),
    ),
]
