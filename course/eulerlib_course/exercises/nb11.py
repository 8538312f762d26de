"""Answer key of notebook 11, quaternions (Hamilton's product, the sandwich, the double cover).

11.1 builds the quaternion of a turn from its axis and angle (half the angle, a unit axis, the
scalar last); 11.2 predicts the quaternion of two quarter turns by multiplying by hand, in the
order of the turns; 11.3 reads, from the components of a quaternion at gimbal lock, the one
combination of Euler angles that is defined there, roll − yaw; 11.4 composes a body's attitude
``ᵂq_B`` with a camera's orientation that a paper gives in the JPL convention, ``ᶜq̄_B``, into
``ᵂq_C``, scalar first. ``−q`` is right wherever ``q`` is (the double cover). The references of
11.4 are computed here with Hamilton's product typed in, not with the library's.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

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


def _some_lock(rng: np.random.Generator) -> NDArray[np.float64]:
    """A student's q_lock: pitch +90°, yaw and roll in whole degrees, drawn again until
    roll − yaw is at least 15° from every multiple of 90° (where the answer would meet its own
    negative, its half or the scalar-first reading) and is not the teacher's."""
    teacher = (_LOCKED[2] - _LOCKED[0]) % 360.0
    while True:
        yaw, roll = (float(a) for a in rng.integers(-170, 171, 2))
        difference = (roll - yaw) % 360.0
        if 15.0 <= difference % 90.0 <= 75.0 and difference != teacher:
            return euler_to_quaternion([yaw, 90.0, roll], "rose", degrees=True)


def _judge_lock(q: NDArray[np.float64], roll_plus_yaw: float | None = None) -> NumberJudge:
    """The judge of 11.3: roll − yaw read from q (scalar last) at pitch +90°.

    There q = (sin δ, cos δ, −sin δ, cos δ)/√2 with δ = (roll − yaw)/2, so roll − yaw is
    2 atan2(x, w). ``roll_plus_yaw``, known only for the teacher's data (the angles it is made
    from; a quaternion at the lock keeps no trace of it), adds the diagnosis of that sum.
    """
    x, w = float(q[0]), float(q[3])
    mistakes = [
        Mistake(
            # read scalar first, "w" is x and "x" is y
            math.degrees(2 * math.atan2(float(q[1]), float(q[0]))),
            "that comes from q read scalar first, (w, x, y, z); eulerlib and SciPy store "
            "it scalar last, (x, y, z, w), so w is q_lock[3]",
        ),
        Mistake(
            math.degrees(math.atan2(x, w)),
            "that is δ = (roll − yaw)/2, the half angle inside the quaternion: double it",
        ),
    ]
    if roll_plus_yaw is not None:
        mistakes.insert(
            1,
            Mistake(
                roll_plus_yaw,
                "roll + yaw is what is left at pitch −90°; at +90° the quaternion depends on "
                "roll − yaw",
            ),
        )
    return NumberJudge(
        math.degrees(2 * math.atan2(x, w)),
        what="your roll − yaw",
        tol=1e-6,
        unit="deg",
        modulo=360.0,
        mistakes=tuple(mistakes),
    )


# --- 11.4: a camera's orientation in JPL's convention, composed with the body's attitude ---------


def _hamilton(p: NDArray[np.float64], q: NDArray[np.float64]) -> NDArray[np.float64]:
    """Hamilton's product of two scalar-last quaternions, (p_w q_v + q_w p_v + p_v × q_v, …)."""
    pv, pw, qv, qw = p[:3], p[3], q[:3], q[3]
    return np.append(pw * qv + qw * pv + np.cross(pv, qv), pw * qw - pv @ qv)


def _conjugate(q: NDArray[np.float64]) -> NDArray[np.float64]:
    return np.append(-q[:3], q[3])


def _first(q: NDArray[np.float64]) -> NDArray[np.float64]:
    """Scalar last to scalar first."""
    return np.roll(q, 1)


_W_Q_B = euler_to_quaternion([40.0, -25.0, 70.0], "rose", degrees=True)  # Hamilton, scalar last
# JPL's ᶜq̄_B has the four numbers of Hamilton's ᴮq_C (its matrix C(q̄) is ᶜR_B = ᴮR_Cᵀ)
_C_QBAR_B = euler_to_quaternion([-20.0, 35.0, 60.0], "rose", degrees=True)


def _candidates(
    data: tuple[NDArray[np.float64], NDArray[np.float64]],
) -> tuple[NDArray[np.float64], tuple[Mistake, ...]]:
    """The reference ᵂq_C = ᵂq_B ᴮq_C, scalar first, and the typical mistakes, scalar first."""
    W_q_B, C_qbar_B = (np.asarray(q, dtype=np.float64) for q in data)
    reference = _first(_hamilton(W_q_B, C_qbar_B))
    mistakes = (
        Mistake(
            _first(_hamilton(W_q_B, _conjugate(C_qbar_B))),
            "that reads the paper's quaternion as if it were Hamilton's ᶜq_B and inverts it; in "
            "JPL's convention C(q̄) is the transpose of Hamilton's R(q) for the same four "
            "numbers: ask which frame to which those numbers turn in Hamilton's convention",
        ),
        Mistake(
            _first(_hamilton(_conjugate(W_q_B), C_qbar_B)),
            "that uses the conjugate of W_q_B, which turns W-coordinates into B-coordinates: "
            "ᵂq_B already turns B-coordinates into W, as the answer needs",
        ),
        Mistake(
            _first(_hamilton(C_qbar_B, W_q_B)),
            "the two quaternions are multiplied in the wrong order: with Hamilton's product "
            "the inner frames must stand side by side and cancel, as for matrices",
        ),
        Mistake(
            _first(_hamilton(W_q_B, np.roll(C_qbar_B, -1))),
            "that reads the paper's quaternion scalar first; JPL's papers write it "
            "[q1 q2 q3 q4] with the scalar q4 last, as eulerlib stores it",
        ),
    )
    return reference, mistakes


def _apart(q: NDArray[np.float64], r: NDArray[np.float64]) -> float:
    return float(min(np.abs(q - r).max(), np.abs(q + r).max()))


def _distinct(data: tuple[NDArray[np.float64], NDArray[np.float64]]) -> bool:
    """Every mistake, the reference, its other layout and its conjugate at least 0.05 apart."""
    reference, mistakes = _candidates(data)
    values = [reference, np.roll(reference, -1), _first(_conjugate(np.roll(reference, -1)))]
    values += [np.asarray(m.value, dtype=np.float64) for m in mistakes]
    return all(_apart(a, b) > 0.05 for i, a in enumerate(values) for b in values[i + 1 :])


def _some_camera(rng: np.random.Generator) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """A student's ᵂq_B and ᶜq̄_B: attitudes of whole-degree Rose angles whose mistakes differ."""
    low, high = [-170, -80, -170], [171, 81, 171]
    while True:
        body, camera = (
            euler_to_quaternion(rng.integers(low, high).astype(float), "rose", degrees=True)
            for _ in range(2)
        )
        if _distinct((body, camera)):
            return body, camera


def _judge_camera(data: tuple[NDArray[np.float64], NDArray[np.float64]]) -> QuaternionJudge:
    reference, mistakes = _candidates(data)
    return QuaternionJudge(reference, scalar_first=True, what="your quaternion", mistakes=mistakes)


assert _distinct((_W_Q_B, _C_QBAR_B))


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
        judge=_judge_lock(_Q_LOCK, roll_plus_yaw=_LOCKED[2] + _LOCKED[0]),
        per_student=_some_lock,
        judged=_judge_lock,
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
    Exercise(
        id="11.4",
        level="extend",
        judge=_judge_camera((_W_Q_B, _C_QBAR_B)),
        per_student=_some_camera,
        judged=_judge_camera,
        given=lambda: (_W_Q_B.copy(), _C_QBAR_B.copy()),
        examples=(
            Example("np.roll(eulerlib.quaternion_multiply(W_q_B, C_qbar_B), 1)", "correct"),
            Example(
                "(Rotation.from_quat(W_q_B) * Rotation.from_quat(C_qbar_B)).as_quat("
                "scalar_first=True)",
                "correct",
            ),
            Example(
                "eulerlib.matrix_to_quaternion(eulerlib.quaternion_to_matrix(W_q_B)"
                " @ eulerlib.quaternion_to_matrix(C_qbar_B), scalar_first=True)",
                "correct",
            ),
            Example(
                "-np.roll(eulerlib.quaternion_multiply(W_q_B, C_qbar_B), 1)",
                "correct",
                "same rotation",
            ),
            Example(
                "np.roll(eulerlib.quaternion_multiply(W_q_B,"
                " eulerlib.quaternion_conjugate(C_qbar_B)), 1)",
                "off",
                "as if it were Hamilton's",
            ),
            Example(
                "np.roll(eulerlib.quaternion_multiply("
                "eulerlib.quaternion_conjugate(W_q_B), C_qbar_B), 1)",
                "off",
                "conjugate of W_q_B",
            ),
            Example(
                "np.roll(eulerlib.quaternion_multiply(C_qbar_B, W_q_B), 1)", "off", "wrong order"
            ),
            Example(
                "np.roll(eulerlib.quaternion_multiply(W_q_B, np.roll(C_qbar_B, -1)), 1)",
                "off",
                "scalar first",
            ),
            Example(
                "eulerlib.quaternion_multiply(W_q_B, C_qbar_B)", "off", "scalar-first (w, x, y, z)"
            ),
            Example(
                "np.roll(eulerlib.quaternion_conjugate("
                "eulerlib.quaternion_multiply(W_q_B, C_qbar_B)), 1)",
                "off",
                "inverse rotation",
            ),
        ),
    ),
]
