"""Answer key of notebook 12, interpolating orientations (Euler angles against slerp).

12.1 finds the attitude 30 % of the way along the geodesic; 12.2 predicts the angle between two
samples of slerp from the constant angular speed alone; 12.3 interpolates two quaternions whose
dot product is negative, where the short way needs ``−q1`` (the double cover); 12.4 builds
squad's control attitude at a key from its two neighbours. The references are computed here with
Shoemake's quaternion formulas (slerp's arc; squad's ``s = q exp(−(log(q⁻¹ q₊) + log(q⁻¹ q₋)) / 4)``
with the quaternion exp and log), not with :func:`eulerlib.slerp` or the rotation vectors the
notebook uses.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib import (
    axis_angle_to_matrix,
    euler_to_matrix,
    euler_to_quaternion,
    matrix_to_axis_angle,
    matrix_to_euler,
    matrix_to_quaternion,
    quaternion_conjugate,
    quaternion_exp,
    quaternion_log,
    quaternion_multiply,
    quaternion_to_matrix,
)

from .judges import ArrayJudge, Mistake, NumberJudge, QuaternionJudge
from .key import Example, Exercise
from .seeds import whole_degree_angles


def _shoemake(q0: NDArray[np.float64], q1: NDArray[np.float64], t: float) -> NDArray[np.float64]:
    """(sin((1 − t) Ω) q0 + sin(t Ω) q1) / sin Ω, cos Ω = q0 · q1, for q0 · q1 > 0 (short way)."""
    omega = math.acos(float(q0 @ q1))
    return (math.sin((1 - t) * omega) * q0 + math.sin(t * omega) * q1) / math.sin(omega)


# --- 12.1: 30 % of the way -----------------------------------------------------------------------

_START = [-35.0, 20.0, 15.0]  # yaw, pitch, roll of R0 (Rose's ZYX, degrees)
_END = [70.0, -25.0, 110.0]  # ... and of R1
_Q_START = euler_to_quaternion(_START, "rose", degrees=True)
_Q_END = euler_to_quaternion(_END, "rose", degrees=True)
_R_START = quaternion_to_matrix(_Q_START)
_R_END = quaternion_to_matrix(_Q_END)
_FRACTION = 0.3
_MatrixPair = tuple[NDArray[np.float64], NDArray[np.float64]]


def _short_way(pair: _MatrixPair) -> _MatrixPair:
    """The quaternions of R0 and R1, the sign of q1 chosen so that q0 · q1 ≥ 0 (the short way)."""
    q0, q1 = (matrix_to_quaternion(np.asarray(R, dtype=np.float64)) for R in pair)
    return q0, (q1 if float(q0 @ q1) >= 0.0 else -q1)


def _judge_fraction(pair: _MatrixPair) -> ArrayJudge:
    """The judge of 12.1: the attitude 30 % of the way along slerp from R0 to R1."""
    R0, R1 = (np.asarray(R, dtype=np.float64) for R in pair)
    q0, q1 = _short_way((R0, R1))
    t = _FRACTION
    # what the learner's Euler-angle interpolation starts from: the angles the library reads
    angles0, angles1 = (matrix_to_euler(R, "rose", degrees=True) for R in (R0, R1))
    axis, angle = matrix_to_axis_angle(R0.T @ R1)
    return ArrayJudge(
        quaternion_to_matrix(_shoemake(q0, q1, t)),
        what="your matrix",
        rotation=True,
        mistakes=(
            Mistake(
                quaternion_to_matrix(_shoemake(q0, q1, 1 - t)),
                "that is 70 % of the way from R0, or 30 % from R1's end: slerp(R0, R1, t) "
                "starts at R0 when t = 0",
            ),
            Mistake(
                euler_to_matrix((1 - t) * angles0 + t * angles1, "rose", degrees=True),
                "that is 30 % of the way from R0's yaw, pitch and roll to R1's: interpolating "
                "Euler angles follows another path; the question asks for slerp",
            ),
            Mistake(
                (1 - t) * R0 + t * R1,
                "interpolating the entries of the matrices leaves the rotations: that matrix "
                "is not orthogonal. Turn from R0 toward R1 about the axis of R0ᵀ R1 instead",
            ),
            Mistake(
                # the body-frame turn applied about the fixed axes
                axis_angle_to_matrix(axis, t * angle) @ R0,
                "the turn R0ᵀ R1 is about an axis of the body, so it multiplies R0 on the "
                "right: R0 Rot(n, t θ), not Rot(n, t θ) R0",
            ),
        ),
    )


def _some_two_attitudes(rng: np.random.Generator) -> _MatrixPair:
    """A student's R0 and R1: whole-degree Rose angles, pitch within ±60° (away from the lock),
    40° to 150° apart, drawn again until the answer and every diagnosed mistake are at least
    0.05 apart (largest entry), so that each mistake is told from the answer and the others."""
    while True:
        low, high = [-170, -60, -170], [171, 61, 171]
        R0, R1 = (
            euler_to_matrix(rng.integers(low, high).astype(float), "rose", degrees=True)
            for _ in range(2)
        )
        cosine = (float(np.trace(R0.T @ R1)) - 1.0) / 2.0
        if not math.cos(math.radians(150.0)) <= cosine <= math.cos(math.radians(40.0)):
            continue
        judge = _judge_fraction((R0, R1))
        points = [np.asarray(judge.reference), *(np.asarray(m.value) for m in judge.mistakes)]
        points.append(points[0].T)
        if all(
            np.max(np.abs(points[i] - points[j])) >= 0.05
            for i in range(len(points))
            for j in range(i + 1, len(points))
        ):
            return R0, R1


# --- 12.3: the short way between q0 and q1 -------------------------------------------------------

_Q0 = euler_to_quaternion([20.0, 10.0, -30.0], "rose", degrees=True)
_Q1 = -euler_to_quaternion([75.0, -15.0, 20.0], "rose", degrees=True)  # q0 · q1 < 0
assert _Q0 @ _Q1 < 0


def _some_far_pair(rng: np.random.Generator) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """A student's q0 and q1: two attitudes of whole-degree Rose angles, 30° to 150° apart, with
    q1's sign chosen so that q0 · q1 < 0 (the short way needs −q1)."""
    while True:
        low, high = [-170, -80, -170], [171, 81, 171]
        q0, q1 = (
            euler_to_quaternion(rng.integers(low, high).astype(float), "rose", degrees=True)
            for _ in range(2)
        )
        if q0 @ q1 > 0:
            q1 = -q1
        if math.cos(math.radians(75.0)) <= -float(q0 @ q1) <= math.cos(math.radians(15.0)):
            return q0, q1


def _judge_halfway(pair: tuple[NDArray[np.float64], NDArray[np.float64]]) -> QuaternionJudge:
    q0, q1 = (np.asarray(q, dtype=np.float64) for q in pair)
    long_way = (q0 + q1) / np.linalg.norm(q0 + q1)
    return QuaternionJudge(
        _shoemake(q0, -q1, 0.5),
        scalar_first=False,
        what="your quaternion",
        mistakes=(
            Mistake(
                long_way,
                "that is the middle of the long way round: q0 · q1 < 0, so q1 lies on the "
                "far side of the sphere; −q1 is the same rotation on the near side. Flip q1 "
                "first",
            ),
        ),
    )


# --- 12.4: squad's control attitude at a key -----------------------------------------------------

_KEYS = (  # yaw, pitch, roll (Rose's ZYX, degrees) of the keys k − 1, k, k + 1
    [15.0, -5.0, 25.0],
    [65.0, 30.0, -15.0],
    [145.0, 5.0, 35.0],
)
_KeyTriple = tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]


def _key_matrices(angles: Sequence[ArrayLike]) -> _KeyTriple:
    previous, key, following = (euler_to_matrix(a, "rose", degrees=True) for a in angles)
    return previous, key, following


def _half_logs(keys: _KeyTriple) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The vector parts of log(q⁻¹ q₊) and log(q⁻¹ q₋), each neighbour on the key's side."""
    previous, key, following = (matrix_to_quaternion(m) for m in keys)
    inverse = quaternion_conjugate(key)
    logs = []
    for neighbour in (following, previous):
        if neighbour @ key < 0:  # the same rotation, on the near side: the short turn
            neighbour = -neighbour
        logs.append(quaternion_log(quaternion_multiply(inverse, neighbour))[:3])
    return logs[0], logs[1]


def _control(
    keys: _KeyTriple, sign: float, share: float, *, left: bool = False, only_next: bool = False
) -> NDArray[np.float64]:
    """``q exp(sign · share · (log(q⁻¹ q₊) + log(q⁻¹ q₋)))`` as a matrix (Shoemake: −, 1/4);
    ``left`` puts the turn before ``q``, ``only_next`` drops the previous key's log."""
    to_next, to_previous = _half_logs(keys)
    total = to_next if only_next else to_next + to_previous
    turn = quaternion_exp(sign * share * total)
    key = matrix_to_quaternion(keys[1])
    product = quaternion_multiply(turn, key) if left else quaternion_multiply(key, turn)
    return quaternion_to_matrix(product)


def _some_keys(rng: np.random.Generator) -> _KeyTriple:
    """A student's three keys: whole-degree Rose angles, 40° to 120° from key to key, with the
    control attitude at least 10° from the middle key, so that every mistake is told apart."""
    while True:
        middle = whole_degree_angles(rng, 60)
        neighbours = [middle + rng.integers(-50, 51, size=3) for _ in range(2)]
        neighbours[0][1] = np.clip(neighbours[0][1], -80, 80)
        neighbours[1][1] = np.clip(neighbours[1][1], -80, 80)
        keys = _key_matrices([neighbours[0], middle, neighbours[1]])
        apart = [_angle(keys[0], keys[1]), _angle(keys[1], keys[2])]
        if not all(40.0 <= a <= 120.0 for a in apart):
            continue
        if _angle(_control(keys, -1.0, 0.25), keys[1]) >= 10.0:
            return keys


def _angle(first: NDArray[np.float64], second: NDArray[np.float64]) -> float:
    cosine = (np.trace(first.T @ second) - 1.0) / 2.0
    return math.degrees(math.acos(max(-1.0, min(1.0, float(cosine)))))


def _judge_control(keys: _KeyTriple) -> ArrayJudge:
    return ArrayJudge(
        _control(keys, -1.0, 0.25),
        what="your matrix",
        rotation=True,
        mistakes=(
            Mistake(
                _control(keys, 1.0, 0.25),
                "that control attitude leans toward the two neighbours; squad's leans away from "
                "them, by minus a quarter of the sum of the two logarithms",
            ),
            Mistake(
                _control(keys, -1.0, 0.5),
                "that turns by half the sum of the two logarithms; Shoemake's control attitude "
                "turns by a quarter of it",
            ),
            Mistake(
                _control(keys, -1.0, 0.25, left=True),
                "the logarithms of R_kᵀ R_k±1 are turns in the key's own body axes, so their "
                "exponential multiplies R_k on the right, not on the left",
            ),
            Mistake(
                _control(keys, -1.0, 0.25, only_next=True),
                "that uses only the turn to the next key; the control attitude takes the turns "
                "to both neighbours, the previous key's too",
            ),
        ),
    )


_LOG_NEXT = "eulerlib.matrix_to_rotvec(R_key_ex.T @ R_next_ex)"
_LOG_PREVIOUS = "eulerlib.matrix_to_rotvec(R_key_ex.T @ R_prev_ex)"

EXERCISES = [
    Exercise(
        id="12.1",
        level="apply",
        judge=_judge_fraction((_R_START, _R_END)),
        per_student=_some_two_attitudes,
        judged=_judge_fraction,
        given=lambda: (_R_START.copy(), _R_END.copy()),
        examples=(
            Example("eulerlib.slerp(R0_ex, R1_ex, 0.3)", "correct"),
            Example(
                "Slerp([0, 1], Rotation.from_matrix([R0_ex, R1_ex]))(0.3).as_matrix()", "correct"
            ),
            Example("eulerlib.slerp(R1_ex, R0_ex, 0.7)", "correct"),
            Example("eulerlib.slerp(R0_ex, R1_ex, 0.7)", "off", "70 %"),
            Example(
                "eulerlib.euler_to_matrix(0.7 * eulerlib.matrix_to_euler(R0_ex, 'rose')"
                " + 0.3 * eulerlib.matrix_to_euler(R1_ex, 'rose'), 'rose')",
                "off",
                "Euler angles",
            ),
            Example("0.7 * R0_ex + 0.3 * R1_ex", "off", "not orthogonal"),
            Example(
                "eulerlib.axis_angle_to_matrix(eulerlib.matrix_to_axis_angle(R0_ex.T @ R1_ex).axis,"
                " 0.3 * eulerlib.matrix_to_axis_angle(R0_ex.T @ R1_ex).angle) @ R0_ex",
                "off",
                "on the right",
            ),
            Example("eulerlib.slerp(R0_ex, R1_ex, 0.3).T", "off", "transpose"),
        ),
        forbidden=("-35", "70.0, -25", "110"),
    ),
    Exercise(
        id="12.2",
        level="predict",
        judge=NumberJudge(
            36.0,
            what="your angle",
            tol=1e-6,
            unit="deg",
            mistakes=(
                Mistake(
                    48.0,
                    "48° = 0.6 × 80° is the angle from R0 to the sample at t = 0.6, not from the "
                    "sample at t = 0.15",
                ),
                Mistake(12.0, "12° = 0.15 × 80° is the angle from R0 to the sample at t = 0.15"),
                Mistake(
                    0.45,
                    "0.45 is the difference of the fractions; the angle is that fraction of the "
                    "whole turn between R0 and R1",
                ),
                Mistake(
                    60.0,
                    "60° = (0.15 + 0.6) × 80° adds the two fractions: the angle between the two "
                    "samples is their difference times the whole turn",
                ),
            ),
        ),
        examples=(
            Example("(0.6 - 0.15) * 80", "correct"),
            Example("np.degrees(0.45 * np.radians(80))", "correct"),
            Example("0.6 * 80", "off", "t = 0.6"),
            Example("0.6 - 0.15", "off", "difference of the fractions"),
            Example("(0.6 + 0.15) * 80", "off", "adds the two fractions"),
            Example("0.45 * np.radians(80)", "off", "radians"),
        ),
        forbidden=("36", "0.45"),
    ),
    Exercise(
        id="12.3",
        level="extend",
        judge=_judge_halfway((_Q0, _Q1)),
        per_student=_some_far_pair,
        judged=_judge_halfway,
        given=lambda: (_Q0.copy(), _Q1.copy()),
        examples=(
            Example(
                "eulerlib.matrix_to_quaternion(eulerlib.slerp(eulerlib.quaternion_to_matrix(q0_ex),"
                " eulerlib.quaternion_to_matrix(q1_ex), 0.5))",
                "correct",
            ),
            Example("(q1_ex - q0_ex) / np.linalg.norm(q1_ex - q0_ex)", "correct", "same rotation"),
            Example("Slerp([0, 1], Rotation.from_quat([q0_ex, q1_ex]))(0.5).as_quat()", "correct"),
            Example("(q0_ex + q1_ex) / np.linalg.norm(q0_ex + q1_ex)", "off", "long way round"),
            Example("(q0_ex - q1_ex) / 2", "off", "length"),
            Example("np.roll((q0_ex - q1_ex) / np.linalg.norm(q0_ex - q1_ex), 1)", "off", "order"),
        ),
    ),
    Exercise(
        id="12.4",
        level="extend",
        judge=_judge_control(_key_matrices(_KEYS)),
        per_student=_some_keys,
        judged=_judge_control,
        given=lambda: _key_matrices(_KEYS),
        examples=(
            Example(
                f"R_key_ex @ eulerlib.rotvec_to_matrix(-({_LOG_NEXT} + {_LOG_PREVIOUS}) / 4)",
                "correct",
            ),
            Example(
                "R_key_ex @ expm(-(logm(R_key_ex.T @ R_next_ex) + logm(R_key_ex.T @ R_prev_ex))"
                ".real / 4)",
                "correct",
            ),
            Example(
                "R_key_ex @ eulerlib.rotvec_to_matrix(-("
                + _LOG_NEXT
                + " - eulerlib.matrix_to_rotvec(R_prev_ex.T @ R_key_ex)) / 4)",
                "correct",
            ),
            Example(
                f"R_key_ex @ eulerlib.rotvec_to_matrix(({_LOG_NEXT} + {_LOG_PREVIOUS}) / 4)",
                "off",
                "leans toward",
            ),
            Example(
                f"R_key_ex @ eulerlib.rotvec_to_matrix(-({_LOG_NEXT} + {_LOG_PREVIOUS}) / 2)",
                "off",
                "a quarter",
            ),
            Example(
                f"eulerlib.rotvec_to_matrix(-({_LOG_NEXT} + {_LOG_PREVIOUS}) / 4) @ R_key_ex",
                "off",
                "on the right",
            ),
            Example(
                f"R_key_ex @ eulerlib.rotvec_to_matrix(-{_LOG_NEXT} / 4)",
                "off",
                "both neighbours",
            ),
            Example(
                f"(R_key_ex @ eulerlib.rotvec_to_matrix(-({_LOG_NEXT} + {_LOG_PREVIOUS}) / 4)).T",
                "off",
                "transpose",
            ),
        ),
        forbidden=("65.0, 30.0", "145.0", "-15.0]"),
    ),
]
