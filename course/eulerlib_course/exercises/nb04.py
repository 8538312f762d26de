"""Answer key of notebook 04, rotating points and objects (Rose eq 5–7, undoing a chain)."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from eulerlib import euler_to_matrix

from .judges import ArrayJudge, Mistake
from .key import Example, Exercise
from .seeds import signed_degrees

# 04.1: an aircraft's attitude W_R_B; a light on its wing tip, given in body coordinates, is
# asked for in world coordinates, and a landmark given in world coordinates in body coordinates
_ATTITUDE_04_1 = [35.0, -20.0, 50.0]  # yaw, pitch, roll of the teacher's edition, degrees
_B_LIGHT = np.array([-0.2, 4.5, 0.3])  # as the exercise cell writes it: B-coordinates, metres
_W_LANDMARK = np.array([30.0, -10.0, 5.0])  # W-coordinates, metres from the aircraft


def _attitude_04_1() -> NDArray[np.float64]:
    return euler_to_matrix(_ATTITUDE_04_1, "rose", degrees=True)


def _some_attitude(rng: np.random.Generator) -> NDArray[np.float64]:
    """A student's W_R_B: yaw and roll in whole degrees, at least 10° from 0, pitch within ±60°."""
    yaw, roll = (signed_degrees(rng, 10, 170) for _ in range(2))
    pitch = signed_degrees(rng, 10, 60)
    return euler_to_matrix([yaw, pitch, roll], "rose", degrees=True)


def _judge_there_and_back(W_R_B: NDArray[np.float64]) -> ArrayJudge:
    to_world, to_body = W_R_B @ _B_LIGHT, W_R_B.T @ _W_LANDMARK
    wrong_world, wrong_body = W_R_B.T @ _B_LIGHT, W_R_B @ _W_LANDMARK
    return ArrayJudge(
        np.array([to_world, to_body]),
        what="your two points",
        tol=1e-9,
        mistakes=(
            Mistake(
                np.array([wrong_world, to_body]),
                "the light went the wrong way: ᵂR_B takes B-coordinates to W-coordinates, "
                "ᵂp = ᵂR_B ᴮp; its transpose goes from W to B",
            ),
            Mistake(
                np.array([to_world, wrong_body]),
                "the light is right; the landmark went the wrong way: from W back to B is "
                "ᴮR_W = (ᵂR_B)ᵀ, since the inner frames must cancel",
            ),
            Mistake(
                np.array([wrong_world, wrong_body]),
                "both points went the wrong way: ᵂR_B maps B-coordinates to W-coordinates, and "
                "its transpose W to B; read the frames of ᴬR_B from right to left",
            ),
            Mistake(
                np.array([_B_LIGHT, _W_LANDMARK]),
                "these are the numbers as given; each point must be carried into the other frame",
            ),
            Mistake(
                np.array([to_body, to_world]),
                "the rows are in the other order: first the light in W, then the landmark in B",
            ),
        ),
    )


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


_CameraData = tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]
_PRODUCTS = ("Rt Mt", "R M", "Rt", "M Rt")


def _camera_data() -> _CameraData:
    return (
        euler_to_matrix(_ATTITUDE_YPR, "rose", degrees=True),
        _CAMERA_MOUNT.copy(),
        _BEACON.copy(),
    )


def _some_camera_data(rng: np.random.Generator) -> _CameraData:
    """A student's attitude and beacon (the camera's mounting is the same for everyone).

    Yaw and roll in whole degrees at least 10° from 0, pitch within ±45°, the beacon in whole
    metres, drawn again until the beacon is at least 20 m in front of the lens and every mistake
    of the judge lands at least 5 m from the answer and from each other mistake.
    """
    while True:
        yaw, roll = (signed_degrees(rng, 10, 170) for _ in range(2))
        pitch = signed_degrees(rng, 5, 45)
        R = euler_to_matrix([yaw, pitch, roll], "rose", degrees=True)
        beacon = rng.integers(-150, 151, 3).astype(np.float64)
        data = (R, _CAMERA_MOUNT.copy(), beacon)
        points = [_camera_reference(data), *(_camera_mistake(data, p) for p in _PRODUCTS)]
        if points[0][2] >= 20.0 and all(
            np.linalg.norm(points[i] - points[j]) >= 5.0
            for i in range(len(points))
            for j in range(i + 1, len(points))
        ):
            return data


def _camera_reference(data: _CameraData) -> NDArray[np.float64]:
    # (R M)⁻¹ computed as a general inverse, without using that R and M are rotations
    R, M, b = data
    return np.asarray(np.linalg.solve(R @ M, b), dtype=np.float64)


def _camera_mistake(data: _CameraData, product: str) -> NDArray[np.float64]:
    R, M, b = data
    products = {
        "Rt Mt": R.T @ M.T @ b,
        "R M": R @ M @ b,
        "Rt": R.T @ b,
        "M Rt": M @ R.T @ b,
    }
    return np.asarray(products[product], dtype=np.float64)


def _judge_camera(data: _CameraData) -> ArrayJudge:
    """The judge of 04.3: the beacon of ``data`` in the camera's coordinates."""
    return ArrayJudge(
        _camera_reference(data),
        what="the beacon in camera coordinates",
        tol=1e-9,
        mistakes=(
            Mistake(
                _camera_mistake(data, "Rt Mt"),
                "the two inverses are in the wrong order: camera → world is ᵂR_B ᴮR_C (the "
                "inner frames cancel), so world → camera is its transpose, (ᴮR_C)ᵀ (ᵂR_B)ᵀ: "
                "undo the attitude first, then the mounting",
            ),
            Mistake(
                _camera_mistake(data, "R M"),
                "that goes the other way, from camera coordinates to the world; the "
                "question starts in the world, so both matrices must be undone",
            ),
            Mistake(
                _camera_mistake(data, "Rt"),
                "those are the beacon's body coordinates (nose, left wing, fin); the "
                "camera's axes differ from the body's by the mounting ᴮR_C",
            ),
            Mistake(
                _camera_mistake(data, "M Rt"),
                "the body coordinates are right, but the mounting ᴮR_C turns camera into "
                "body coordinates; body → camera is its transpose",
            ),
        ),
    )


EXERCISES = [
    Exercise(
        id="04.1",
        level="apply",
        judge=_judge_there_and_back(_attitude_04_1()),
        per_student=_some_attitude,
        judged=_judge_there_and_back,
        given=_attitude_04_1,
        examples=(
            Example("np.array([W_R_B @ B_light, W_R_B.T @ W_landmark])", "correct"),
            Example("[B_light @ W_R_B.T, W_landmark @ W_R_B]", "correct"),
            Example("np.vstack([W_R_B @ B_light, np.linalg.solve(W_R_B, W_landmark)])", "correct"),
            Example("[W_R_B.T @ B_light, W_R_B.T @ W_landmark]", "off", "light went the wrong"),
            Example("[W_R_B @ B_light, W_R_B @ W_landmark]", "off", "landmark went the wrong"),
            Example("[W_R_B.T @ B_light, W_R_B @ W_landmark]", "off", "both points"),
            Example("[B_light, W_landmark]", "off", "as given"),
            Example("[W_R_B.T @ W_landmark, W_R_B @ B_light]", "off", "other order"),
            Example("W_R_B @ B_light", "off", "shape (2, 3)"),
        ),
        forbidden=("W_R_B @ B_light, W_R_B.T", "B_R_W @ W_landmark"),
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
        judge=_judge_camera(_camera_data()),
        per_student=_some_camera_data,
        judged=_judge_camera,
        given=_camera_data,
        examples=(
            Example("(W_R_B_ex3 @ B_R_C_ex3).T @ W_beacon", "correct"),
            Example("W_beacon @ W_R_B_ex3 @ B_R_C_ex3", "correct"),
            Example("W_R_B_ex3.T @ B_R_C_ex3.T @ W_beacon", "off", "wrong order"),
            Example("W_R_B_ex3 @ B_R_C_ex3 @ W_beacon", "off", "other way"),
            Example("W_R_B_ex3.T @ W_beacon", "off", "body coordinates"),
            Example("B_R_C_ex3 @ W_R_B_ex3.T @ W_beacon", "off", "its transpose"),
        ),
        forbidden=("B_R_C_ex3.T @ B_beacon", "B_R_C_ex3.T @ W_R_B_ex3.T"),
    ),
]
