"""Answer key of notebook 08, conventions compared (Rose, Baker, ROS; NED, ENU and the camera)."""

from __future__ import annotations

from typing import Any

import numpy as np

from eulerlib import convert_angles, euler_to_matrix, matrix_to_euler, rot_x, rot_y, rot_z

from .judges import AnglesJudge, ArrayJudge, ChoiceJudge, Mistake, rounded_to
from .key import Example, Exercise

_HAB = (120.0, -30.0, 45.0)  # Baker's heading, attitude, bank of 08.1, degrees
# aerospace yaw, pitch, roll of 08.3: ᴺR_F, an FRD body F in the NED world N
_NED = (30.0, 10.0, 5.0)

# 08.1: Baker's matrix built from its elementary rotations (R = Ry Rz Rx), read as Rose's angles.
_BAKER_MATRIX = (
    rot_y(_HAB[0], degrees=True) @ rot_z(_HAB[1], degrees=True) @ rot_x(_HAB[2], degrees=True)
)
_ROSE_OF_BAKER = matrix_to_euler(_BAKER_MATRIX, "rose", degrees=True)


def _rose_of_baker(hab: Any) -> Any:
    """Rose's angles of Baker's heading, attitude, bank (R = Ry Rz Rx), degrees."""
    h, a, b = (float(x) for x in hab)
    matrix = rot_y(h, degrees=True) @ rot_z(a, degrees=True) @ rot_x(b, degrees=True)
    return matrix_to_euler(matrix, "rose", degrees=True)


def _whole_degrees(rng: np.random.Generator, low: int, high: int) -> float:
    """A whole number of degrees in [low, high], at least 10° from 0° and from ±90°."""
    while True:
        angle = int(rng.integers(low, high + 1))
        if min(abs(angle), abs(abs(angle) - 90)) >= 10:
            return float(angle)


def _some_hab(rng: np.random.Generator) -> Any:
    """A student's heading, attitude, bank (Baker's), away from the poles."""
    return np.array(
        [
            _whole_degrees(rng, -170, 170),
            _whole_degrees(rng, -70, 70),
            _whole_degrees(rng, -170, 170),
        ]
    )


def _some_ned(rng: np.random.Generator) -> Any:
    """A student's aerospace yaw, pitch, roll (FRD body in the NED world): a modest attitude, as
    an aircraft flies."""
    return np.array(
        [_whole_degrees(rng, -170, 170), _whole_degrees(rng, -40, 40), _whole_degrees(rng, -40, 40)]
    )


# 08.3: relabelling the world NED → ENU (T = Rz(90°) Rx(180°)) on the left and the body
# z down → z up (D = Rx(180°)) on the right gives T Rz(w) Ry(v) Rx(u) D = Rz(90° − w) Ry(−v) Rx(u):
# as ROS angles (roll, pitch, yaw) = (u, −v, 90° − w).
_ROS_OF_NED = (_NED[2], -_NED[1], 90.0 - _NED[0])

_SIDEWAYS = (
    "a turn about y keeps the y component of the line of sight, and y is the image's vertical: "
    "the view swings sideways, it does not rise or sink"
)


def _judge_hab(hab: Any) -> AnglesJudge:
    return AnglesJudge(
        _rose_of_baker(hab),
        "rose",
        degrees=True,
        what="your yaw, pitch, roll",
        mistakes=(
            Mistake(
                hab,
                "these are Baker's three numbers read as Rose's: in another convention the "
                "same numbers are another rotation; build Baker's matrix and read Rose's "
                "angles from it",
            ),
            Mistake(
                [hab[0], -hab[1], hab[2]],
                "that is the same aircraft relabelled into z-up coordinates (P R Pᵀ); the "
                "question asks for the same matrix in the same coordinates",
            ),
            Mistake(
                convert_angles(hab, "rose", "baker", degrees=True),
                "that converts the other way, from Rose to Baker: the numbers you have are "
                "Baker's, so the conversion starts from 'baker'",
            ),
        ),
    )


def _judge_ned(ned: Any) -> AnglesJudge:
    return AnglesJudge(
        (ned[2], -ned[1], 90.0 - ned[0]),
        "ros",
        degrees=True,
        what="your roll, pitch, yaw",
        mistakes=(
            Mistake(
                ned[::-1],
                "you put the aerospace angles in ROS order but kept the frames: ENU and a body "
                "with z up are other axes; relabel the world (NED → ENU) and the body "
                "(z down → z up)",
            ),
            Mistake(
                matrix_to_euler(
                    np.diag([1.0, -1.0, -1.0])
                    @ euler_to_matrix(ned, "rose", degrees=True)
                    @ np.diag([1.0, -1.0, -1.0]),
                    "ros",
                    degrees=True,
                ),
                "you relabelled the body and the world alike (z down → z up), but the world "
                "is ENU, not north-west-up: the world needs its own relabelling, NED → ENU",
            ),
            Mistake(
                matrix_to_euler(
                    np.array([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]])
                    @ euler_to_matrix(ned, "rose", degrees=True),
                    "ros",
                    degrees=True,
                ),
                "you relabelled the world (NED → ENU) but not the body: a ROS body has y left "
                "and z up, so the body axes need relabelling too (on the right, transposed)",
            ),
            Mistake(
                [ned[2], -ned[1], 90.0 + ned[0]],
                "the ENU yaw counts from east toward north, counterclockwise seen from above, "
                "while the NED heading counts clockwise from north: it is 90° − heading",
            ),
        ),
    )


EXERCISES = [
    Exercise(
        id="08.1",
        level="apply",
        judge=_judge_hab(_HAB),
        per_student=_some_hab,
        judged=_judge_hab,
        given=lambda: np.array(_HAB),
        examples=(
            Example(
                "matrix_to_euler(heading_attitude_bank_to_matrix(*hab_ex, degrees=True), 'rose',"
                " degrees=True)",
                "correct",
            ),
            Example(  # worked by hand and written to 6 decimals
                "np.round(convert_angles(hab_ex, 'baker', 'rose', degrees=True), 6)",
                "correct",
            ),
            Example(  # to 1 decimal: close, not yet within the tolerance
                "np.round(convert_angles(hab_ex, 'baker', 'rose', degrees=True), 1)",
                "off",
                "close",
            ),
            Example(
                "convert_angles(hab_ex, 'baker', 'rose', degrees=True) + [360, 0, -360]",
                "correct",
                "rotation asked for",
            ),
            Example(  # the other triple: yaw and roll turned by 180°, pitch 180° − pitch
                "convert_angles(hab_ex, 'baker', 'rose', degrees=True) * [1, -1, 1] + 180",
                "correct",
                "rotation asked for",
            ),
            Example("hab_ex", "off", "Baker's three numbers"),
            Example("[120, 30, 45]", "off", "relabelled"),
            Example("convert_angles(hab_ex, 'rose', 'baker', degrees=True)", "off", "other way"),
            Example(
                "convert_angles(hab_ex, 'baker', 'rose', degrees=True)[::-1]", "off", "reverse"
            ),
            Example(
                "np.radians(convert_angles(hab_ex, 'baker', 'rose', degrees=True))",
                "off",
                "radians",
            ),
        ),
        forbidden=("130.89", "48.59", "94.1"),
    ),
    Exercise(
        id="08.2",
        level="predict",
        judge=ChoiceJudge(
            options={
                "a": "further to the right",
                "b": "further to the left",
                "c": "higher",
                "d": "lower",
            },
            answer="a",
            computed=ArrayJudge(
                rot_y(10.0, degrees=True) @ np.array([0.0, 0.0, 1.0]),
                what="your line of sight",
                tol=rounded_to(3),
                rotation=True,
                hint="turn the line of sight (0, 0, 1) of the camera's own axes by its turn",
            ),
            computed_what="the line of sight you computed",
            explanations={
                "a": "the camera's y points down, and a right-handed turn about an axis pointing "
                "down swings the line of sight (z) toward x, the right of the image",
                "b": "a turn to the left is what +10° about an axis pointing up gives (a yaw "
                "with z up); check which way the camera's own y points before you carry it over",
                "c": _SIDEWAYS,
                "d": _SIDEWAYS,
            },
        ),
        examples=(
            Example("('a', rot_y(10, degrees=True) @ [0, 0, 1])", "correct", "points"),
            Example("('A', [0.174, 0, 0.985])", "correct", "right of the image"),
            Example("('a', rot_y(-10, degrees=True) @ [0, 0, 1])", "off", "line of sight"),
            Example("('b', rot_y(10, degrees=True) @ [0, 0, 1])", "off", "camera's own y"),
            Example("('c', [0, 0, 1])", "off", "sideways"),
            Example("('d', [0, 0, 1])", "off", "sideways"),
            Example("'a'", "off", "give a pair"),
        ),
    ),
    Exercise(
        id="08.3",
        level="extend",
        judge=_judge_ned(_NED),
        per_student=_some_ned,
        judged=_judge_ned,
        given=lambda: np.array(_NED),
        examples=(
            Example(
                "matrix_to_euler(np.array([[0, 1, 0], [1, 0, 0], [0, 0, -1]])"
                " @ euler_to_matrix(ned_ex, 'rose', degrees=True) @ np.diag([1, -1, -1]),"
                " 'ros', degrees=True)",
                "correct",
            ),
            Example("[5, -10, 420]", "correct", "rotation asked for"),
            Example("[185, 190, 240]", "correct", "rotation asked for"),
            Example("ned_ex[::-1]", "off", "kept the frames"),
            Example("[5, -10, -30]", "off", "ENU, not north-west-up"),
            Example("[-175, -10, 60]", "off", "not the body"),
            Example("[5, -10, 120]", "off", "90° − heading"),
            Example("[5, 10, 60]", "off", "pitch has the wrong sign"),
            Example("[60, -10, 5]", "off", "reverse order"),
        ),
        forbidden=("-10, 60", "-10.0, 60.0"),
    ),
]
