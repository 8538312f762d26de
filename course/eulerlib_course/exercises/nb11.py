"""Answer key of notebook 11, quaternions (Hamilton's product, the sandwich, the double cover).

11.1 builds the quaternion of a turn from its axis and angle (half the angle, a unit axis, the
scalar last); 11.2 predicts the quaternion of two quarter turns by multiplying by hand, in the
order of the turns; 11.3 reads, from the components of a quaternion at gimbal lock, the one
combination of Euler angles that is defined there, roll − yaw. ``−q`` is right wherever ``q`` is
(the double cover).
"""

from __future__ import annotations

import math

import numpy as np

from eulerlib import euler_to_quaternion

from .judges import Mistake, NumberJudge, QuaternionJudge
from .key import Example, Exercise

# --- 11.1: 60° about the axis (0, 3, 4) ----------------------------------------------------------

_AXIS = np.array([0.0, 3.0, 4.0])
_UNIT = _AXIS / 5.0
_HALF = math.radians(60.0) / 2


def _scalar_last(angle_half: float, axis: np.ndarray) -> np.ndarray:
    return np.append(math.sin(angle_half) * axis, math.cos(angle_half))


# --- 11.2: first 90° about x, then 90° about y ---------------------------------------------------

_Q2 = np.array([0.5, 0.5, -0.5, 0.5])  # (x, y, z, w) of q_y q_x
_Q2_REVERSED = np.array([0.5, 0.5, 0.5, 0.5])  # q_x q_y: first y, then x
_SUM = np.array([math.sqrt(0.5), math.sqrt(0.5), 0.0, 2 * math.sqrt(0.5)])  # q_x + q_y

# --- 11.3: a quaternion at gimbal lock -----------------------------------------------------------

_LOCKED = [37.0, 90.0, -71.0]  # yaw, pitch, roll of the quaternion the learner is given
_Q_LOCK = euler_to_quaternion(_LOCKED, "rose", degrees=True)
# roll − yaw = 2 atan2(x, w); read scalar first, "w" is x and "x" is y
_ROLL_MINUS_YAW_SCALAR_FIRST = math.degrees(2 * math.atan2(_Q_LOCK[1], _Q_LOCK[0]))


EXERCISES = [
    Exercise(
        id="11.1",
        level="apply",
        judge=QuaternionJudge(
            _scalar_last(_HALF, _UNIT),
            scalar_first=False,
            what="your quaternion",
            mistakes=(
                Mistake(
                    _scalar_last(2 * _HALF, _UNIT),
                    "this quaternion turns by twice the angle: a quaternion holds the half angle, "
                    "(sin(θ/2) k, cos(θ/2))",
                ),
                Mistake(
                    _scalar_last(_HALF, _AXIS),
                    "the axis (0, 3, 4) has length 5: divide it by its length before you scale "
                    "it by sin(θ/2)",
                ),
                Mistake(
                    _scalar_last(30.0, _UNIT),
                    "np.sin and np.cos take radians: 30 is read as 30 radians; convert the "
                    "half angle with np.radians",
                ),
            ),
        ),
        examples=(
            Example(
                "eulerlib.matrix_to_quaternion("
                "eulerlib.axis_angle_to_matrix([0, 3, 4], 60, degrees=True))",
                "correct",
            ),
            Example(
                "Rotation.from_rotvec(np.radians(60) * np.array([0, 0.6, 0.8])).as_quat()",
                "correct",
            ),
            Example(
                "-np.array([0, 0.6 * np.sin(np.pi / 6), 0.8 * np.sin(np.pi / 6),"
                " np.cos(np.pi / 6)])",
                "correct",
                "same rotation",
            ),
            Example(
                "[np.cos(np.pi / 6), 0, 0.6 * np.sin(np.pi / 6), 0.8 * np.sin(np.pi / 6)]",
                "off",
                "wrong order",
            ),
            Example(
                "[0, -0.6 * np.sin(np.pi / 6), -0.8 * np.sin(np.pi / 6), np.cos(np.pi / 6)]",
                "off",
                "conjugate",
            ),
            Example(
                "[0, 0.6 * np.sin(np.pi / 3), 0.8 * np.sin(np.pi / 3), np.cos(np.pi / 3)]",
                "off",
                "half angle",
            ),
            Example(
                "[0, 3 * np.sin(np.pi / 6), 4 * np.sin(np.pi / 6), np.cos(np.pi / 6)]",
                "off",
                "length 5",
            ),
            Example("[0, 0.6 * np.sin(30), 0.8 * np.sin(30), np.cos(30)]", "off", "radians"),
        ),
        forbidden=("0.3, 0.4", "0.866"),
    ),
    Exercise(
        id="11.2",
        level="predict",
        judge=QuaternionJudge(
            _Q2,
            scalar_first=False,
            what="your quaternion",
            mistakes=(
                Mistake(
                    _Q2_REVERSED,
                    "that is q_x q_y, first 90° about y and then about x: quaternions compose "
                    "like matrices, so the first turn stands on the right, q = q_y q_x",
                ),
                Mistake(
                    _SUM / np.linalg.norm(_SUM),
                    "adding quaternions (and normalizing) does not compose the turns: multiply "
                    "them, with the product of section 1",
                ),
            ),
        ),
        examples=(
            Example(
                "eulerlib.matrix_to_quaternion("
                "eulerlib.rot_y(90, degrees=True) @ eulerlib.rot_x(90, degrees=True))",
                "correct",
            ),
            Example("[-0.5, -0.5, 0.5, -0.5]", "correct", "same rotation"),
            Example("[0.5, 0.5, 0.5, 0.5]", "off", "first turn stands on the right"),
            Example("[0.5, 0.5, 0.5, -0.5]", "off", "wrong order"),
            Example("[-0.5, -0.5, 0.5, 0.5]", "off", "conjugate"),
            Example("[np.sqrt(1 / 6), np.sqrt(1 / 6), 0, np.sqrt(2 / 3)]", "off", "adding"),
        ),
        forbidden=(
            "0.5, 0.5, -0.5, 0.5",
            "-0.5, -0.5, 0.5, -0.5",
            "rot_y(90, degrees=True) @",
        ),
    ),
    Exercise(
        id="11.3",
        level="extend",
        judge=NumberJudge(
            _LOCKED[2] - _LOCKED[0],
            what="your roll − yaw",
            tol=1e-6,
            unit="deg",
            modulo=360.0,
            mistakes=(
                Mistake(
                    _ROLL_MINUS_YAW_SCALAR_FIRST,
                    "that comes from q read scalar first, (w, x, y, z); eulerlib and SciPy store "
                    "it scalar last, (x, y, z, w), so w is q_lock[3]",
                ),
                Mistake(
                    _LOCKED[2] + _LOCKED[0],
                    "roll + yaw is what is left at pitch −90°; at +90° the quaternion depends on "
                    "roll − yaw",
                ),
                Mistake(
                    (_LOCKED[2] - _LOCKED[0]) / 2,
                    "that is δ = (roll − yaw)/2, the half angle inside the quaternion: double it",
                ),
            ),
        ),
        given=lambda: _Q_LOCK.copy(),
        examples=(
            Example(
                'eulerlib.quaternion_to_euler(q_lock, "rose", degrees=True, warn=False)[2]',
                "correct",
            ),
            Example("360 + np.degrees(2 * np.arctan2(q_lock[0], q_lock[3]))", "correct"),
            Example("-np.degrees(2 * np.arctan2(q_lock[0], q_lock[3]))", "off", "wrong sign"),
            Example("np.degrees(2 * np.arctan2(q_lock[1], q_lock[0]))", "off", "scalar first"),
            Example("np.degrees(np.arctan2(q_lock[0], q_lock[3]))", "off", "double it"),
            Example("2 * np.arctan2(q_lock[0], q_lock[3])", "off", "radians"),
            Example("-34", "off", "roll + yaw"),
        ),
        forbidden=("37, 90", "-71", "-108", "252"),
    ),
]
