"""Answer key of notebook 10, axis and angle (Euler's rotation theorem, Rodrigues' formula).

10.1 reads the rotation vector of a matrix (the axis from the eigenvector of eigenvalue 1, its
sign from the skew part, the angle by ``atan2``); 10.2 predicts the angle of a product of two
quarter turns, which is not the sum of anything; 10.3 finds the axis of a turn within 1e-7 of a
half turn to full precision, where the skew part alone keeps only about half of the digits.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from eulerlib import matrix_to_rotvec, rotvec_to_matrix

from .judges import ArrayJudge, Mistake, NumberJudge
from .key import Example, Exercise

# --- 10.1: the rotation vector of a matrix -------------------------------------------------------

_ROTVEC = np.array([0.37, -0.86, 0.52])  # radians; the turn the learner's matrix makes
_ANGLE = float(np.linalg.norm(_ROTVEC))
_AXIS = _ROTVEC / _ANGLE


# --- 10.3: the axis of a turn by π − 1e-7 --------------------------------------------------------

_HALF_AXIS = np.array([-3.0, 4.0, 5.5]) / math.hypot(3.0, 4.0, 5.5)  # the unit axis
_SHORT_OF_HALF = 1e-7  # the turn is by π minus this, in radians


def _near_half_turn(k: NDArray[np.float64] = _HALF_AXIS) -> NDArray[np.float64]:
    """R = cos θ I + sin θ [k]× + (1 − cos θ) k kᵀ for θ = π − d, each factor without loss."""
    d = _SHORT_OF_HALF
    cosine, sine, one_minus_cosine = -math.cos(d), math.sin(d), 1.0 + math.cos(d)
    kx, ky, kz = k
    cross = np.array([[0.0, -kz, ky], [kz, 0.0, -kx], [-ky, kx, 0.0]])
    return cosine * np.eye(3) + sine * cross + one_minus_cosine * np.outer(k, k)


def _skew_direction(R: NDArray[np.float64]) -> NDArray[np.float64]:
    """s / |s| with s = (r32 − r23, r13 − r31, r21 − r12): the axis read from the skew part."""
    s: NDArray[np.float64] = np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    return s / float(np.linalg.norm(s))


def _axis_near_half_turn(R: NDArray[np.float64]) -> NDArray[np.float64]:
    """The unit axis of R, a turn close to π: the line from the symmetric part, the sign from s.

    (R + Rᵀ)/2 = cos θ I + (1 − cos θ) k kᵀ with cos θ = (tr R − 1)/2; near a half turn
    1 − cos θ is close to 2, so k kᵀ keeps every digit. Its largest diagonal entry gives the
    column that holds k best; the skew part s = 2 sin θ k is tiny but still has k's sign.
    """
    cosine = (float(np.trace(R)) - 1.0) / 2.0
    outer = ((R + R.T) / 2.0 - cosine * np.eye(3)) / (1.0 - cosine)
    j = int(np.argmax(np.diag(outer)))
    k: NDArray[np.float64] = outer[:, j] / math.sqrt(float(outer[j, j]))
    s = np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    return k if float(s @ k) >= 0.0 else -k


_R_NEAR = _near_half_turn()


def _some_near_half_turn(rng: np.random.Generator) -> NDArray[np.float64]:
    """A student's R_near: a turn by π − 1e-7 about a random unit axis, drawn again while the
    skew part alone happens to give the axis to within 1e-10 (then that mistake would pass)."""
    while True:
        axis = rng.normal(size=3)
        R = _near_half_turn(axis / float(np.linalg.norm(axis)))
        if np.max(np.abs(_skew_direction(R) - _axis_near_half_turn(R))) > 1e-10:
            return R


def _judge_half_turn(R: NDArray[np.float64]) -> ArrayJudge:
    """The judge of 10.3: the unit axis of R, to 12 digits."""
    axis, from_skew = _axis_near_half_turn(R), _skew_direction(R)
    return ArrayJudge(
        axis,
        what="your axis",
        tol=1e-12,
        mistakes=(
            Mistake(
                -axis,
                "that is the right line but the wrong direction: the symmetric part gives k "
                "only up to its sign; choose the sign for which the axis points along "
                "s = (r32 − r23, r13 − r31, r21 − r12)",
            ),
            Mistake(
                from_skew,
                "that is s / |s|, read from the skew part alone: this close to a half turn s "
                "is tiny and the rounding of the entries is a large part of it, so only "
                "about half of the digits are right. Take the line from the symmetric part "
                "(R + Rᵀ)/2 and only the sign from s",
            ),
            Mistake(
                -from_skew,
                "that comes from the skew part alone, with the sign reversed: near a half "
                "turn s keeps only about half of the digits. Take the line from the "
                "symmetric part (R + Rᵀ)/2 and only the sign from s",
            ),
            Mistake(
                matrix_to_rotvec(R),
                "that is the rotation vector, the axis times the angle; the question asks "
                "for the unit axis",
            ),
        ),
    )


def _some_turn(rng: np.random.Generator) -> NDArray[np.float64]:
    """A student's matrix: a turn by 0.5 to 2.5 rad about a random axis, rounded to 2 decimals."""
    axis = rng.normal(size=3)
    rotvec = np.round(rng.uniform(0.5, 2.5) * axis / np.linalg.norm(axis), 2)
    return rotvec_to_matrix(rotvec)


def _judge_rotvec(rotvec: NDArray[np.float64]) -> ArrayJudge:
    angle = float(np.linalg.norm(rotvec))
    axis = rotvec / angle
    return ArrayJudge(
        rotvec,
        what="your rotation vector",
        mistakes=(
            Mistake(
                np.degrees(rotvec),
                "the length of this vector is the angle in degrees; a rotation vector's "
                "length is the angle in radians",
            ),
            Mistake(axis, "that is the axis alone, a unit vector: multiply it by the angle"),
            Mistake(
                -rotvec,
                "that is the rotation vector of the inverse turn, R_exᵀ: an eigenvector fixes "
                "the line of the axis, not its direction; choose the sign for which the axis "
                "points along s = (r32 − r23, r13 − r31, r21 − r12)",
            ),
            Mistake(
                (angle - 2 * math.pi) * axis,
                "that vector gives the same rotation the long way round (2π − θ about −k), "
                "but its length is more than π; the question asks for the angle in [0, π]",
            ),
            Mistake(
                2 * math.sin(angle) * axis,
                "that is s = (r32 − r23, r13 − r31, r21 − r12) = 2 sin θ k: it points along "
                "the axis, but its length is 2 sin θ, not the angle θ",
            ),
        ),
    )


EXERCISES = [
    Exercise(
        id="10.1",
        level="apply",
        judge=_judge_rotvec(_ROTVEC),
        per_student=_some_turn,
        judged=lambda R: _judge_rotvec(matrix_to_rotvec(R)),
        given=lambda: rotvec_to_matrix(_ROTVEC),
        examples=(
            Example("eulerlib.matrix_to_rotvec(R_ex)", "correct"),
            Example("Rotation.from_matrix(R_ex).as_rotvec()", "correct"),
            Example(  # −θ about −k
                "-eulerlib.matrix_to_axis_angle(R_ex).angle"
                " * -eulerlib.matrix_to_axis_angle(R_ex).axis",
                "correct",
            ),
            Example("eulerlib.matrix_to_rotvec(R_ex, degrees=True)", "off", "in degrees"),
            Example("eulerlib.matrix_to_axis_angle(R_ex).axis", "off", "the axis alone"),
            Example("eulerlib.matrix_to_rotvec(R_ex.T)", "off", "inverse turn"),
            Example(
                "(eulerlib.rotation_angle(R_ex) - 2 * np.pi)"
                " * eulerlib.matrix_to_axis_angle(R_ex).axis",
                "off",
                "long way round",
            ),
            Example(
                "np.array([R_ex[2, 1] - R_ex[1, 2], R_ex[0, 2] - R_ex[2, 0],"
                " R_ex[1, 0] - R_ex[0, 1]])",
                "off",
                "2 sin θ",
            ),
            Example("print(eulerlib.matrix_to_rotvec(R_ex))", "off", "None"),
        ),
        forbidden=("0.37", "-0.86", "0.52"),
    ),
    Exercise(
        id="10.2",
        level="predict",
        judge=NumberJudge(
            120.0,
            what="your angle",
            tol=1e-6,
            unit="deg",
            mistakes=(
                Mistake(
                    180.0,
                    "180° = 90° + 90° would be right for two turns about one axis; about different "
                    "axes the angles do not add. Follow where R sends x, y and z instead",
                ),
                Mistake(
                    90.0 * math.sqrt(2.0),
                    "that is 90°·√2, the length of the sum of the two rotation vectors: rotation "
                    "vectors add only for turns about one axis",
                ),
                Mistake(
                    90.0,
                    "90° is the size of each of the two turns, not of their product: follow where "
                    "R sends x, y and z",
                ),
                Mistake(
                    240.0,
                    "that turn gives the right rotation, but the long way round: the question "
                    "asks for the angle in [0°, 180°], so turn about the opposite direction of "
                    "the axis",
                ),
                Mistake(
                    -120.0,
                    "a negative angle is a turn about the opposite direction of the axis; the "
                    "question asks for the angle in [0°, 180°]",
                ),
            ),
        ),
        examples=(
            Example("360 / 3", "correct"),
            Example("np.degrees(2 * np.pi / 3)", "correct"),
            Example("180", "off", "do not add"),
            Example("90 * np.sqrt(2)", "off", "sum of the two rotation vectors"),
            Example("240", "off", "[0°, 180°]"),
            Example("-120", "off", "opposite direction"),
            Example("2 * np.pi / 3", "off", "radians"),
        ),
        forbidden=("120", "2 * np.pi / 3", "360 / 3"),
    ),
    Exercise(
        id="10.3",
        level="extend",
        judge=_judge_half_turn(_R_NEAR),
        per_student=_some_near_half_turn,
        judged=_judge_half_turn,
        given=lambda: _R_NEAR.copy(),
        examples=(
            Example("eulerlib.matrix_to_axis_angle(R_near).axis", "correct"),
            Example(
                "Rotation.from_matrix(R_near).as_rotvec()"
                " / np.linalg.norm(Rotation.from_matrix(R_near).as_rotvec())",
                "correct",
            ),
            Example(
                "np.array([R_near[2, 1] - R_near[1, 2], R_near[0, 2] - R_near[2, 0],"
                " R_near[1, 0] - R_near[0, 1]]) / np.linalg.norm([R_near[2, 1] - R_near[1, 2],"
                " R_near[0, 2] - R_near[2, 0], R_near[1, 0] - R_near[0, 1]])",
                "off",
                "skew part alone",
            ),
            Example("-eulerlib.matrix_to_axis_angle(R_near).axis", "off", "wrong direction"),
            Example("eulerlib.matrix_to_rotvec(R_near)", "off", "unit axis"),
        ),
        forbidden=("-0.403", "0.538", "0.739"),
    ),
]
