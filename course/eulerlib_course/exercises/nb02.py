"""Answer key of notebook 02, composing rotations: fixed and moving axes (Rose eq 8)."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from eulerlib import elementary_rotation, euler_to_matrix

from .judges import ArrayJudge, Mistake
from .key import Example, Exercise
from .seeds import signed_degrees


def _turn(axis: str, angle: float, degrees: bool = True) -> NDArray[np.float64]:
    return elementary_rotation(axis, angle, degrees=degrees)


# 02.1: 30° about the fixed x axis, then 45° about the fixed z axis
_FIXED_X_THEN_Z = _turn("z", 45.0) @ _turn("x", 30.0)

# 02.2: a drone turned by a yaw about the world's z, a pitch about the world's fixed y, then a
# roll about its own nose: fixed-axes turns multiply from the left, the own-axis turn from the
# right, so W_R_B = R_y(θ) R_z(ψ) R_x(φ)
_MIXED_ANGLES = [50.0, -30.0, 70.0]  # ψ, θ, φ of the teacher's edition, degrees


def _mixed_angles() -> NDArray[np.float64]:
    return np.array(_MIXED_ANGLES)


def _some_mixed_angles(rng: np.random.Generator) -> NDArray[np.float64]:
    """A student's ψ, θ, φ in whole degrees, each at least 15° from 0 (so that every mistake
    below gives another matrix), the pitch within ±60°."""
    yaw, roll = (signed_degrees(rng, 15, 150) for _ in range(2))
    pitch = signed_degrees(rng, 15, 60)
    return np.array([yaw, pitch, roll])


def _judge_mixed(angles: NDArray[np.float64]) -> ArrayJudge:
    yaw, pitch, roll = (float(a) for a in angles)

    def product(order: str, degrees: bool = True) -> NDArray[np.float64]:
        of = {"z": yaw, "y": pitch, "x": roll}
        result = np.eye(3)
        for axis in order:
            result = result @ _turn(axis, of[axis], degrees)
        return result

    return ArrayJudge(
        product("yzx"),
        what="your matrix",
        rotation=True,
        mistakes=(
            Mistake(
                product("zyx"),
                "this is Rose's product R_z R_y R_x, in which the pitch turns about the drone's "
                "own y axis; here the pitch is about the world's fixed y axis, so it multiplies "
                "the yaw from the left",
            ),
            Mistake(
                product("xyz"),
                "this reads all three turns about the world's fixed axes; the roll is about the "
                "drone's own nose, wherever the first two turns left it, so it multiplies from "
                "the right",
            ),
            Mistake(
                product("xzy"),
                "the pitch and the roll stand on the wrong sides: a turn about a fixed axis "
                "multiplies from the left, a turn about the drone's own axis from the right",
            ),
            Mistake(
                product("yzx", degrees=False),
                "these are turns by radians: pass degrees=True",
            ),
        ),
    )


# 02.3: the nose after a yaw of 90°, then a pitch of 30° about the moved wing axis: the yaw
# turns the nose to +y, the pitch tips it down (in the z-up frame), by 30°
_COS_30, _SIN_30 = math.sqrt(3.0) / 2.0, 0.5
_NOSE = [0.0, _COS_30, -_SIN_30]

# 02.4: an aircraft's attitude (not shown to the learner) and a pitch about its own wing axis
_ATTITUDE_ANGLES = [40.0, -25.0, 65.0]  # yaw, pitch, roll in degrees


def _attitude() -> NDArray[np.float64]:
    return euler_to_matrix(_ATTITUDE_ANGLES, "ZYX", degrees=True)


def _conjugate(outer: NDArray[np.float64], inner: NDArray[np.float64]) -> NDArray[np.float64]:
    conjugate: NDArray[np.float64] = outer @ inner @ outer.T
    return conjugate


def _judge_moved_axis(A: NDArray[np.float64]) -> ArrayJudge:
    """The judge of 02.4: the turn by 30° about the second column of ``A``, in fixed axes."""
    return ArrayJudge(
        _conjugate(A, _turn("y", 30.0)),
        what="your matrix",
        rotation=True,
        mistakes=(
            Mistake(
                _turn("y", 30.0),
                "this turns about the fixed y axis; the wing axis is where the attitude has "
                "moved y, the second column of A_ex: undo A_ex, turn about y, redo A_ex",
            ),
            Mistake(
                A @ _turn("y", 30.0),
                "this is the aircraft's attitude after the pitch (A·B), not the turn itself; "
                "the turn alone, written in the fixed axes, still has to undo A_ex",
            ),
            Mistake(
                _conjugate(A.T, _turn("y", 30.0)),
                "this turns about the second row of A_ex, not about the wing axis (its second "
                "column): undoing A_ex comes first, so the transpose stands on the right",
            ),
            Mistake(
                _conjugate(A, _turn("y", 30.0, False)),
                "this is a turn by 30 radians: pass degrees=True",
            ),
        ),
    )


def _some_attitude(rng: np.random.Generator) -> NDArray[np.float64]:
    """A student's attitude A_ex: yaw, pitch, roll in whole degrees (Z-Y-X, as the teacher's),
    each at least 15° from 0 and the pitch within ±60°, drawn again until the wing axis (second
    column) and the second row are each at least 20° from the fixed y axis and from each other,
    so that every mistake of the judge is another matrix than the answer and than each other."""
    while True:
        yaw, roll = (signed_degrees(rng, 15, 150) for _ in range(2))
        pitch = signed_degrees(rng, 15, 60)
        A = euler_to_matrix([yaw, pitch, roll], "ZYX", degrees=True)
        axes = (A[:, 1], A[1, :], np.array([0.0, 1.0, 0.0]))
        if all(
            float(axes[i] @ axes[j]) < math.cos(math.radians(20.0))
            for i in range(3)
            for j in range(i + 1, 3)
        ):
            return A


EXERCISES = [
    Exercise(
        id="02.1",
        level="apply",
        judge=ArrayJudge(
            _FIXED_X_THEN_Z,
            what="your matrix",
            rotation=True,
            mistakes=(
                Mistake(
                    _turn("x", 30.0) @ _turn("z", 45.0),
                    "your product has the x-turn on the left, as if it came last (or as if the "
                    "turns were about the moving axes): about the fixed axes each later turn "
                    "multiplies from the left",
                ),
                Mistake(
                    _turn("z", 45.0, degrees=False) @ _turn("x", 30.0, degrees=False),
                    "these are turns by 45 and 30 radians: pass degrees=True",
                ),
            ),
        ),
        examples=(
            Example("compose(rot_z(45, degrees=True), rot_x(30, degrees=True))", "correct"),
            Example("euler_to_matrix([30, 0, 45], 'xyz', degrees=True)", "correct"),
            Example(
                "rot_x(30, degrees=True) @ rot_z(45, degrees=True)",
                "off",
                "each later turn multiplies from the left",
            ),
            Example("rot_z(45) @ rot_x(30)", "off", "radians"),
            Example(
                "(rot_z(45, degrees=True) @ rot_x(30, degrees=True)).T",
                "off",
                "transpose of the answer",
            ),
        ),
        forbidden=("rot_z(45, degrees=True) @ rot_x(30", "turn_z @ turn_x"),
    ),
    Exercise(
        id="02.2",
        level="apply",
        judge=_judge_mixed(_mixed_angles()),
        per_student=_some_mixed_angles,
        judged=_judge_mixed,
        given=_mixed_angles,
        examples=(
            Example(
                "rot_y(angles_ex[1], degrees=True) @ rot_z(angles_ex[0], degrees=True)"
                " @ rot_x(angles_ex[2], degrees=True)",
                "correct",
            ),
            Example(
                "euler_to_matrix([angles_ex[1], angles_ex[0], angles_ex[2]], 'YZX', degrees=True)",
                "correct",
            ),
            Example(
                "compose(rot_y(angles_ex[1], degrees=True), rot_z(angles_ex[0], degrees=True),"
                " rot_x(angles_ex[2], degrees=True))",
                "correct",
            ),
            Example("euler_to_matrix(angles_ex, 'ZYX', degrees=True)", "off", "Rose's product"),
            Example(
                "rot_x(angles_ex[2], degrees=True) @ rot_y(angles_ex[1], degrees=True)"
                " @ rot_z(angles_ex[0], degrees=True)",
                "off",
                "own nose",
            ),
            Example(
                "rot_x(angles_ex[2], degrees=True) @ rot_z(angles_ex[0], degrees=True)"
                " @ rot_y(angles_ex[1], degrees=True)",
                "off",
                "wrong sides",
            ),
            Example(
                "rot_y(angles_ex[1]) @ rot_z(angles_ex[0]) @ rot_x(angles_ex[2])",
                "off",
                "radians",
            ),
            Example(
                "(rot_y(angles_ex[1], degrees=True) @ rot_z(angles_ex[0], degrees=True)"
                " @ rot_x(angles_ex[2], degrees=True)).T",
                "off",
                "transpose of the answer",
            ),
        ),
        forbidden=("rot_y(pitch, degrees=True) @ rot_z(yaw", "W_R_2 @ rot_x"),
    ),
    Exercise(
        id="02.3",
        level="predict",
        judge=ArrayJudge(
            _NOSE,
            what="your nose direction",
            mistakes=(
                Mistake(
                    [0.0, 1.0, 0.0],
                    "this is where the yaw alone puts the nose, and where B·A leaves it: a pitch "
                    "about the fixed y axis does not move a nose that lies along y. The pitch is "
                    "about the aircraft's own wing axis, so it multiplies from the right",
                ),
                Mistake(
                    [0.0, _COS_30, _SIN_30],
                    "the nose went up: with the right thumb along the wing (+y), the fingers curl "
                    "from the roof towards the nose, so a positive pitch tips the nose down in "
                    "this frame, where z is up",
                ),
                Mistake(
                    [_COS_30, 0.0, -_SIN_30],
                    "this is the pitch alone: the yaw of 90° that comes first is missing",
                ),
                Mistake(
                    (_turn("z", 90.0, False) @ _turn("y", 30.0, False))[:, 0],
                    "these are turns by 90 and 30 radians: pass degrees=True",
                ),
            ),
        ),
        examples=(
            Example("rot_z(90, degrees=True) @ rot_y(30, degrees=True) @ [1, 0, 0]", "correct"),
            Example("[0, np.cos(np.pi / 6), -np.sin(np.pi / 6)]", "correct"),
            Example("rot_y(30, degrees=True) @ rot_z(90, degrees=True) @ [1, 0, 0]", "off", "B·A"),
            Example(
                "[0, np.cos(np.radians(30)), np.sin(np.radians(30))]",
                "off",
                "tips the nose down",
            ),
            Example("rot_y(30, degrees=True)[:, 0]", "off", "yaw of 90° that comes first"),
            Example("rot_z(90) @ rot_y(30) @ [1, 0, 0]", "off", "radians"),
        ),
        forbidden=("0.866", "rot_z(90, degrees=True) @ rot_y(30"),
    ),
    Exercise(
        id="02.4",
        level="extend",
        judge=_judge_moved_axis(_attitude()),
        per_student=_some_attitude,
        judged=_judge_moved_axis,
        given=_attitude,
        examples=(
            Example("Rotation.from_rotvec(np.radians(30) * A_ex[:, 1]).as_matrix()", "correct"),
            Example("A_ex @ rot_y(30, degrees=True) @ np.linalg.inv(A_ex)", "correct"),
            Example("rot_y(30, degrees=True)", "off", "fixed y axis"),
            Example("A_ex @ rot_y(30, degrees=True)", "off", "attitude after the pitch"),
            Example("A_ex.T @ rot_y(30, degrees=True) @ A_ex", "off", "not about the wing axis"),
            Example("A_ex @ rot_y(30) @ A_ex.T", "off", "radians"),
            Example("A_ex @ rot_y(-30, degrees=True) @ A_ex.T", "off", "transpose of the answer"),
        ),
        forbidden=("A_ex @ pitch_in_body_axes", "A_ex @ rot_y(30"),
    ),
]
