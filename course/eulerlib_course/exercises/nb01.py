"""Answer key of notebook 01, rotations in the plane and about one axis (Rose eq 1)."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from eulerlib import elementary_rotation, euler_to_matrix

from .judges import ArrayJudge, Mistake, rounded_to
from .key import Example, Exercise

# 01.1: a turn by -90° about x, typed in from where the basis vectors go (x stays, y → -z, z → y)
_QUARTER_BACK_ABOUT_X = [[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]]

# 01.2: the image of e_z under a turn by 30° about y: it tilts towards +x
_HALF_ROOT_3 = math.sqrt(3.0) / 2.0
_E_Z_TURNED = [0.5, 0.0, _HALF_ROOT_3]

# 01.3: a third of a turn about (1, 1, 1)/√3 sends x → y → z → x; the columns are the images
_THIRD_TURN_ABOUT_DIAGONAL = [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]

# 01.4: a turned frame (its columns are its axes) and a point, both in the fixed frame
_FRAME_ANGLES = [60.0, 20.0, -35.0]  # yaw, pitch, roll of the frame, degrees (not shown)
_POINT = [2.0, -1.0, 0.5]  # as the exercise cell writes it


def _frame() -> NDArray[np.float64]:
    return euler_to_matrix(_FRAME_ANGLES, "ZYX", degrees=True)


def _some_frame(rng: np.random.Generator) -> NDArray[np.float64]:
    """A student's turned frame: yaw, pitch, roll in whole degrees, away from lock."""
    yaw, roll = (float(a) for a in rng.integers(-170, 171, 2))
    pitch = float(rng.integers(-60, 61))
    return euler_to_matrix([yaw, pitch, roll], "ZYX", degrees=True)


def _judge_frame(frame: NDArray[np.float64]) -> ArrayJudge:
    return ArrayJudge(
        frame.T @ np.array(_POINT),
        what="your coordinates",
        tol=1e-9,
        mistakes=(
            Mistake(
                frame @ np.array(_POINT),
                "this is the point turned by F_ex (the active reading, F p); the point stays "
                "where it is and the axes are turned, so its coordinates are its components "
                "along the columns of F_ex",
            ),
            Mistake(
                _POINT,
                "these are the coordinates in the fixed frame, where the point was given; "
                "along the turned axes they are other numbers",
            ),
        ),
    )


EXERCISES = [
    Exercise(
        id="01.1",
        level="apply",
        judge=ArrayJudge(
            _QUARTER_BACK_ABOUT_X,
            what="your matrix",
            rotation=True,
            mistakes=(
                Mistake(
                    elementary_rotation("x", -90.0),
                    "this is a turn by -90 radians, not degrees: give the angle in degrees to "
                    "the library (degrees=True), or work out the images by hand",
                ),
            ),
        ),
        examples=(
            Example("np.array([[1, 0, 0], [0, 0, 1], [0, -1, 0]])", "correct"),
            Example("rot_x(270, degrees=True)", "correct"),
            Example(
                "np.column_stack([[1, 0, 0], [0, 0, 1], [0, -1, 0]])",
                "off",
                "transpose of the answer, that is the inverse rotation",
            ),
            Example("np.column_stack([[1, 0, 0], [0, 0, 1], [0, 1, 0]])", "off", "reflection"),
            Example("rot_x(-90)", "off", "radians, not degrees"),
            Example("'[[1, 0, 0], [0, 0, 1], [0, -1, 0]]'", "off", "is text"),
        ),
        forbidden=("rot_x(-90", "rot_x(270", "[0, 0, -1], [0, 1, 0]"),
    ),
    Exercise(
        id="01.2",
        level="predict",
        judge=ArrayJudge(
            _E_Z_TURNED,
            what="your image of e_z",
            tol=rounded_to(3),
            mistakes=(
                Mistake(
                    [-0.5, 0.0, _HALF_ROOT_3],
                    "your e_z tilts towards -x, which is where a turn by -30° takes it (and what "
                    "row 3 of R_y holds, not column 3): with the right thumb along +y, the "
                    "fingers curl from z towards +x",
                ),
                Mistake(
                    [_HALF_ROOT_3, 0.0, 0.5],
                    "sine and cosine are swapped: this is where e_z goes under a turn by 60°",
                ),
                Mistake(
                    [math.sin(30.0), 0.0, math.cos(30.0)],
                    "this is a turn by 30 radians: convert the angle with np.radians first",
                ),
            ),
        ),
        examples=(
            Example("rot_y(30, degrees=True)[:, 2]", "correct"),
            Example("[np.sin(np.pi / 6), 0, np.cos(np.pi / 6)]", "correct"),
            Example("rot_y(30, degrees=True)[2]", "off", "tilts towards -x"),
            Example("rot_y(30) @ [0, 0, 1]", "off", "30 radians"),
            Example(
                "[np.cos(np.radians(30)), 0, np.sin(np.radians(30))]",
                "off",
                "sine and cosine are swapped",
            ),
            Example("[0.5, 0.866]", "off", "shape (2,)"),
            Example("[0.5, 0, 0.87]", "off", "close"),
        ),
        forbidden=("rot_y(30", "0.866", "0.5, 0"),
    ),
    Exercise(
        id="01.3",
        level="extend",
        judge=ArrayJudge(
            _THIRD_TURN_ABOUT_DIAGONAL,
            what="your matrix",
            rotation=True,
            hint="its columns are the images of e_x, e_y and e_z: find where the turn takes each",
            mistakes=(
                Mistake(
                    np.transpose(_THIRD_TURN_ABOUT_DIAGONAL),
                    "your matrix sends e_x to e_z: that is the turn by -120°, the other way round "
                    "the diagonal; with the right thumb along (1, 1, 1) the fingers curl from x "
                    "towards y",
                ),
            ),
        ),
        examples=(
            Example("np.array([[0, 0, 1], [1, 0, 0], [0, 1, 0]])", "correct"),
            Example("np.roll(np.eye(3), 1, axis=0)", "correct"),
            Example("np.array([[0, 1, 0], [0, 0, 1], [1, 0, 0]])", "off", "sends e_x to e_z"),
            Example("np.array([[0, 1, 0], [1, 0, 0], [0, 0, 1]])", "off", "reflection"),
            Example("np.eye(3)", "off", "columns are the images"),
        ),
        forbidden=("[[0, 0, 1], [1, 0, 0], [0, 1, 0]]", "[e2, e3, e1]"),
    ),
    Exercise(
        id="01.4",
        level="extend",
        judge=_judge_frame(_frame()),
        per_student=_some_frame,
        judged=_judge_frame,
        given=_frame,
        examples=(
            Example("F_ex.T @ p_ex", "correct"),
            Example("np.linalg.solve(F_ex, p_ex)", "correct"),
            Example("p_ex @ F_ex", "correct"),
            Example("F_ex @ p_ex", "off", "active reading"),
            Example("p_ex", "off", "fixed frame"),
            Example("(F_ex.T @ p_ex)[:2]", "off", "shape (2,)"),
        ),
        forbidden=("-0.0451", "-2.124", "-0.8578", "F_ex.T @ p_ex"),
    ),
]
