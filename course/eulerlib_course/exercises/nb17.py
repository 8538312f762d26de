"""Answer key of notebook 17, random and average rotations.

Euler angles are Rose's yaw, pitch, roll (``"rose"``, z-y-x intrinsic, degrees). Uniform
(Haar) rotations in those angles have yaw and roll uniform and ``sin(pitch)`` uniform on
[−1, 1]; the nose, the sensor's x axis, is ``(cos y cos p, sin y cos p, −sin p)`` in earth axes.
The chordal mean is the rotation nearest to the average of the matrices.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from eulerlib import euler_to_matrix, matrix_to_euler, mean_rotation

from .judges import AnglesJudge, ChoiceJudge, Mistake, NumberJudge, rounded_to
from .key import Example, Exercise

# --- 17.1: three uniform numbers into a uniform rotation's angles ---------------------------------

_U_1 = np.array([0.8125, 0.15, 0.375])


def _some_u(rng: np.random.Generator) -> NDArray[np.float64]:
    """Three uniform numbers, kept away from the ends so that no angle sits on a seam."""
    return np.round(rng.uniform(0.05, 0.95, size=3), 4)


def _haar_angles(u: NDArray[np.float64]) -> list[float]:
    return [360.0 * u[0] - 180.0, math.degrees(math.asin(2.0 * u[1] - 1.0)), 360.0 * u[2] - 180.0]


def _judge_1(u: NDArray[np.float64]) -> AnglesJudge:
    yaw, pitch, roll = _haar_angles(u)
    return AnglesJudge(
        [yaw, pitch, roll],
        "rose",
        degrees=True,
        what="your yaw, pitch, roll",
        hint="yaw and roll are spread evenly over a turn; for pitch, it is sin(pitch) that is "
        "spread evenly over [−1, 1]",
        mistakes=(
            Mistake(
                [yaw, 180.0 * u[1] - 90.0, roll],
                "this pitch is spread evenly over [−90°, 90°]: that piles the noses up at the "
                "poles; spread sin(pitch) evenly instead",
            ),
            Mistake(
                [yaw, math.degrees(math.acos(2.0 * u[1] - 1.0)), roll],
                "arccos gives an angle in [0°, 180°], measured from the pole; pitch is measured "
                "from the horizon, in [−90°, 90°]",
            ),
        ),
    )


# --- 17.2: noses near the zenith ------------------------------------------------------------------

_CAP_2 = 30.0  # degrees from straight up
_EULER_SHARE_2 = _CAP_2 / 180.0  # pitch spread evenly over 180°: the nose's elevation likewise
_AREA_SHARE_2 = (1.0 - math.cos(math.radians(_CAP_2))) / 2.0

# --- 17.3: the mean of attitudes across the ±180° seam -------------------------------------------

_YPR_3 = np.array(
    [[172.0, 8.0, -4.0], [-168.0, 12.0, 3.0], [178.0, 5.0, 6.0], [-175.0, 14.0, -2.0]]
)
_R_3 = euler_to_matrix(_YPR_3, "rose", degrees=True)
_MEAN_3 = matrix_to_euler(mean_rotation(_R_3), "rose", degrees=True)


EXERCISES = [
    Exercise(
        id="17.1",
        level="apply",
        judge=_judge_1(_U_1),
        per_student=_some_u,
        judged=_judge_1,
        given=lambda: _U_1.copy(),
        examples=(
            Example(
                "[360 * u_ex[0] - 180, "
                "np.degrees(np.arcsin(2 * u_ex[1] - 1)), 360 * u_ex[2] - 180]",
                "correct",
            ),
            Example(
                "[360 * u_ex[0] + 180, "
                "-np.degrees(np.arcsin(1 - 2 * u_ex[1])), 360 * u_ex[2] - 540]",
                "correct",
            ),
            Example(
                "[360 * u_ex[0] - 180, 180 * u_ex[1] - 90, 360 * u_ex[2] - 180]", "off", "poles"
            ),
            Example(
                "[360 * u_ex[0] - 180, "
                "np.degrees(np.arccos(2 * u_ex[1] - 1)), 360 * u_ex[2] - 180]",
                "off",
                "from the pole",
            ),
            Example(
                "[2 * np.pi * u_ex[0] - np.pi, "
                "np.arcsin(2 * u_ex[1] - 1), 2 * np.pi * u_ex[2] - np.pi]",
                "off",
                "radians",
            ),
        ),
        forbidden=("-44.4", "-44.42"),
    ),
    Exercise(
        id="17.2",
        level="predict",
        judge=ChoiceJudge(
            options={
                "a": "the cap's share of the sphere's area, as for uniform rotations",
                "b": "more than the cap's share of the area",
                "c": "less than the cap's share of the area",
            },
            answer="b",
            computed=NumberJudge(
                _EULER_SHARE_2,
                what="your fraction",
                tol=rounded_to(3),
                hint="the nose's elevation is minus the pitch; ask which share of the pitch's "
                "range puts the nose within the cap",
                mistakes=(
                    Mistake(
                        _AREA_SHARE_2,
                        "this is the cap's share of the sphere's area, what uniform rotations "
                        "give; the question draws the pitch evenly instead",
                    ),
                    Mistake(
                        2 * _EULER_SHARE_2,
                        "this counts the noses near straight down as well; the question asks for "
                        "the cap around straight up only",
                    ),
                ),
            ),
            computed_what="the fraction you computed",
            explanations={
                "b": "yes: every band of pitch gets the same share of samples, but the bands "
                "near the poles are small circles, so the noses crowd there",
                "a": "that holds when sin(pitch) is spread evenly; here the pitch itself is, and "
                "the bands of equal pitch are not bands of equal area",
                "c": "the cap near the pole is where bands of equal pitch have the least area, so "
                "an even spread of pitch puts relatively more noses there, not fewer",
            },
        ),
        examples=(
            Example("('b', 1 / 6)", "correct"),
            Example("('B', 0.1667)", "correct"),
            Example("('a', 0.067)", "off", "sin(pitch) is spread evenly"),
            Example("('c', 0.05)", "off", "not fewer"),
            Example("('b', (1 - np.cos(np.radians(30))) / 2)", "off", "sphere's area"),
            Example("('b', 1 / 3)", "off", "straight down"),
            Example("'b'", "off", "give a pair"),
        ),
        forbidden=("1 / 6", "1/6", "answer_2 = 'b'", 'answer_2 = "b"'),
    ),
    Exercise(
        id="17.3",
        level="extend",
        judge=AnglesJudge(
            _MEAN_3,
            "rose",
            degrees=True,
            what="your yaw, pitch, roll",
            hint="average the rotations, not their angles: the chordal mean, then its angles",
            mistakes=(
                Mistake(
                    _YPR_3.mean(axis=0),
                    "this averages the angles: the yaws straddle the ±180° seam, and their "
                    "plain average points the other way",
                ),
            ),
        ),
        given=lambda: _R_3.copy(),
        examples=(
            Example("matrix_to_euler(mean_rotation(R_ex), 'rose', degrees=True)", "correct"),
            Example(
                "matrix_to_euler(mean_rotation(R_ex[::-1]), 'ZYX', degrees=True) + [360, 0, 0]",
                "correct",
            ),
            Example("matrix_to_euler(R_ex, 'rose', degrees=True).mean(axis=0)", "off", "seam"),
            Example(
                "matrix_to_euler(mean_rotation(R_ex), 'rose', degrees=True)[::-1]",
                "off",
                "reverse order",
            ),
            Example("matrix_to_euler(mean_rotation(R_ex), 'rose')", "off", "radians"),
        ),
        forbidden=tuple(f"{value:.2f}" for value in _MEAN_3),
    ),
]
