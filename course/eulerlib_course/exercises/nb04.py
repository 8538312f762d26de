"""Answer key of notebook 04, rotating points and objects (Rose eq 5–7, undoing a chain)."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from eulerlib import euler_to_matrix

from .judges import ArrayJudge, Mistake
from .key import Example, Exercise

# 04.1: a sensor turned by yaw, pitch, roll; the point before the turn is asked for.
_SENSOR_YPR = [30.0, -15.0, 60.0]
_POINT_BEFORE = np.array([1.5, -0.5, 2.0])


def _sensor() -> NDArray[np.float64]:
    return euler_to_matrix(_SENSOR_YPR, "rose", degrees=True)


def _sensor_data() -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    R = _sensor()
    return R, R @ _POINT_BEFORE


# 04.2: yaw 90°, then roll 90° about the moved nose; where the left wing (body y) points.
_WING_AFTER = np.array([0.0, 0.0, 1.0])  # Rz(90) Rx(90) e_y: the roll lifts y to z, yaw keeps z

# 04.3: the camera frame (x right, y down, z forward) bolted to the body (x nose, y left, z up):
# its columns are where the camera's axes point in body coordinates.
_CAMERA_MOUNT = np.array(
    [
        [0.0, 0.0, 1.0],  # camera z (forward) is the nose
        [-1.0, 0.0, 0.0],  # camera x (right) is body -y
        [0.0, -1.0, 0.0],  # camera y (down) is body -z
    ]
)
_ATTITUDE_YPR = [40.0, 10.0, -20.0]
_BEACON = np.array([120.0, 60.0, -25.0])


def _camera_data() -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    return (
        euler_to_matrix(_ATTITUDE_YPR, "rose", degrees=True),
        _CAMERA_MOUNT.copy(),
        _BEACON.copy(),
    )


def _camera_reference() -> NDArray[np.float64]:
    # (R M)⁻¹ computed as a general inverse, without using that R and M are rotations
    R, M, b = _camera_data()
    return np.asarray(np.linalg.solve(R @ M, b), dtype=np.float64)


def _camera_mistake(product: str) -> NDArray[np.float64]:
    R, M, b = _camera_data()
    products = {
        "Rt Mt": R.T @ M.T @ b,
        "R M": R @ M @ b,
        "Rt": R.T @ b,
        "M Rt": M @ R.T @ b,
    }
    return np.asarray(products[product], dtype=np.float64)


EXERCISES = [
    Exercise(
        id="04.1",
        level="apply",
        judge=ArrayJudge(
            _POINT_BEFORE,
            what="your point",
            mistakes=(
                Mistake(
                    _sensor() @ _sensor() @ _POINT_BEFORE,
                    "that turns the point a second time; to undo the rotation use its "
                    "transpose (eq 7)",
                ),
                Mistake(
                    euler_to_matrix([-a for a in _SENSOR_YPR], "rose", degrees=True)
                    @ _sensor()
                    @ _POINT_BEFORE,
                    "negating yaw, pitch and roll but keeping Rose's order is not the inverse: "
                    "the last turn (the roll) must be undone first, which the transpose does",
                ),
            ),
        ),
        given=_sensor_data,
        examples=(
            Example("q_ex @ R_ex", "correct"),
            Example("np.linalg.solve(R_ex, q_ex)", "correct"),
            Example("R_ex @ q_ex", "off", "second time"),
            Example(
                "euler_to_matrix([-30, 15, -60], 'rose', degrees=True) @ q_ex",
                "off",
                "last turn",
            ),
            Example("-(R_ex.T @ q_ex)", "off", "opposite way"),
            Example("R_ex.T", "off", "shape (3, 3)"),
        ),
        forbidden=("1.5, -0.5", "-0.5, 2"),
    ),
    Exercise(
        id="04.2",
        level="predict",
        judge=ArrayJudge(
            _WING_AFTER,
            what="your direction",
            tol=1e-6,
            rotation=True,
            mistakes=(
                Mistake(
                    [-1.0, 0.0, 0.0],
                    "that is the two turns about the fixed axes: the yaw takes the wing to −x, "
                    "then a roll about the world's x leaves it there. In Rose's convention the "
                    "roll turns about the aircraft's own nose, wherever the yaw has put it",
                ),
                Mistake(
                    [1.0, 0.0, 0.0],
                    "the yaw went the wrong way round: a positive yaw turns x towards y, and so "
                    "y towards −x (right-hand rule about z); your direction is where the inverse "
                    "rotation sends the wing",
                ),
                Mistake(
                    [0.0, 0.0, -1.0],
                    "the roll went the wrong way round: a positive roll about the nose lifts "
                    "the left wing (y turns towards z, right-hand rule about x)",
                ),
                Mistake([0.0, 1.0, 0.0], "that is where the wing started; both turns move it"),
            ),
        ),
        examples=(
            Example("[0, 0, 1]", "correct"),
            Example(
                "euler_to_matrix([90, 0, 90], 'rose', degrees=True) @ np.array([0.0, 1.0, 0.0])",
                "correct",
            ),
            Example("[-1, 0, 0]", "off", "fixed axes"),
            Example("[1, 0, 0]", "off", "wrong way round"),
            Example("[0, 0, -1]", "off", "lifts"),
            Example("[0, 1, 0]", "off", "started"),
            Example("[0, 0, 2]", "off", "length"),
        ),
        forbidden=("[90, 0, 90]", "(90, 0, 90)"),
    ),
    Exercise(
        id="04.3",
        level="extend",
        judge=ArrayJudge(
            _camera_reference(),
            what="the beacon in camera coordinates",
            tol=1e-9,
            mistakes=(
                Mistake(
                    _camera_mistake("Rt Mt"),
                    "the two inverses are in the wrong order: camera → world is R M (the "
                    "mounting first), so world → camera is (R M)ᵀ = Mᵀ Rᵀ: undo the attitude "
                    "first, then the mounting",
                ),
                Mistake(
                    _camera_mistake("R M"),
                    "that goes the other way, from camera coordinates to the world; the "
                    "question starts in the world, so both matrices must be undone",
                ),
                Mistake(
                    _camera_mistake("Rt"),
                    "those are the beacon's body coordinates (nose, left wing, fin); the "
                    "camera's axes differ from the body's by the mounting M",
                ),
                Mistake(
                    _camera_mistake("M Rt"),
                    "the body coordinates are right, but the mounting turns camera into body "
                    "coordinates; body → camera is its transpose",
                ),
            ),
        ),
        given=_camera_data,
        examples=(
            Example("(R_ex3 @ M_ex3).T @ b_world", "correct"),
            Example("b_world @ R_ex3 @ M_ex3", "correct"),
            Example("R_ex3.T @ M_ex3.T @ b_world", "off", "wrong order"),
            Example("R_ex3 @ M_ex3 @ b_world", "off", "other way"),
            Example("R_ex3.T @ b_world", "off", "body coordinates"),
            Example("M_ex3 @ R_ex3.T @ b_world", "off", "its transpose"),
        ),
        forbidden=("M_ex3.T @ b_body", "M_ex3.T @ R_ex3.T"),
    ),
]
