"""Answer key of notebook 14, a real IMU recording (the device's conventions, lock, the gyroscope).

The questions use data in the device's conventions, as the notebook works them out from the
recording: quaternions stored scalar first that give the earth frame in sensor coordinates,
``M = R(q)ᵀ`` turning sensor coordinates into earth coordinates, yaw–pitch–roll z-y-x of ``M``,
attitude samples at 128 Hz and the gyroscope in °/s about the sensor's axes. The data are made
here from stated attitudes and rates, not taken from the recording, so that the key needs no file.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from eulerlib import euler_to_matrix, matrix_to_quaternion, quaternion_to_matrix, rotvec_to_matrix

from .judges import ArrayJudge, ChoiceJudge, Mistake, NumberJudge, rounded_to
from .key import Example, Exercise
from .seeds import whole_degree_angles

ATTITUDE_RATE = 128.0  # Hz, the device's quaternion, matrix and Euler-angle samples
_DOWN_YPR = (40.0, -90.0, 10.0)  # 14.2: yaw, pitch, roll of an attitude at pitch −90°, degrees

# --- 14.1: the device's quaternion to its attitude matrix ---------------------------------------

_M1 = euler_to_matrix([-150.0, 20.0, 35.0], "rose", degrees=True)  # sensor → earth
_Q1 = matrix_to_quaternion(_M1.T, scalar_first=True)  # as the device stores it: R(q) = Mᵀ


def _judge_device_quaternion(q: NDArray[np.float64]) -> ArrayJudge:
    """The judge of 14.1: M = R(q)ᵀ, q read scalar first as the device writes it."""
    q = np.asarray(q, dtype=np.float64)
    seen = quaternion_to_matrix(q, scalar_first=True)  # R(q): the earth's axes in sensor axes
    misread = quaternion_to_matrix(q)  # the same four numbers read scalar last
    return ArrayJudge(
        seen.T,
        what="your attitude matrix",
        rotation=True,
        mistakes=(
            Mistake(
                seen,
                "this is R(q): the earth's axes in sensor coordinates. The device's "
                "attitude, which turns sensor coordinates into earth coordinates, is its "
                "transpose",
            ),
            Mistake(
                misread,
                "you read the quaternion as scalar last (x, y, z, w); this device writes the "
                "scalar first (w, x, y, z)",
            ),
            Mistake(
                misread.T,
                "you read the quaternion as scalar last (x, y, z, w); this device writes the "
                "scalar first (w, x, y, z)",
            ),
        ),
    )


def _some_device_quaternion(rng: np.random.Generator) -> NDArray[np.float64]:
    """A student's q_ex: the device's quaternion of an attitude of whole-degree Rose angles
    (pitch within ±60°), drawn again until the answer and every diagnosed mistake are at least
    0.05 apart (largest entry), so that each is told from the others."""
    while True:
        angles = whole_degree_angles(rng, 60)
        M = euler_to_matrix(angles, "rose", degrees=True)
        q = matrix_to_quaternion(M.T, scalar_first=True)
        judge = _judge_device_quaternion(q)
        points = [np.asarray(judge.reference), *(np.asarray(m.value) for m in judge.mistakes)]
        if all(
            np.max(np.abs(points[i] - points[j])) >= 0.05
            for i in range(len(points))
            for j in range(i + 1, len(points))
        ):
            return q


# --- 14.3: from two consecutive attitudes back to the gyroscope's reading -----------------------

_OMEGA = np.array([120.0, -45.0, 300.0])  # °/s about the sensor's axes
_M0 = euler_to_matrix([35.0, 60.0, -110.0], "rose", degrees=True)
_M0_NEXT = _M0 @ rotvec_to_matrix(_OMEGA / ATTITUDE_RATE, degrees=True)


_SPACE_OMEGA = _M0 @ _OMEGA  # the same turn, in earth axes

EXERCISES = [
    Exercise(
        id="14.1",
        level="apply",
        judge=_judge_device_quaternion(_Q1),
        per_student=_some_device_quaternion,
        judged=_judge_device_quaternion,
        given=lambda: _Q1.copy(),
        examples=(
            Example("quaternion_to_matrix(q_ex, scalar_first=True).T", "correct"),
            Example("quaternion_to_matrix(-q_ex, scalar_first=True).T", "correct"),
            Example("quaternion_to_matrix(q_ex * [1, -1, -1, -1], scalar_first=True)", "correct"),
            Example("quaternion_to_matrix(q_ex, scalar_first=True)", "off", "transpose"),
            Example("quaternion_to_matrix(q_ex).T", "off", "scalar last"),
            Example("quaternion_to_matrix(q_ex)", "off", "scalar last"),
            Example("q_ex", "off", "shape (4,)"),
        ),
        forbidden=tuple(f"{value:.4f}" for value in _M1.ravel()),
    ),
    Exercise(
        id="14.2",
        level="predict",
        judge=ChoiceJudge(
            options={
                "a": "roll + yaw",
                "b": "roll − yaw",
                "c": "yaw alone",
                "d": "roll alone",
            },
            answer="a",
            computed=NumberJudge(
                _DOWN_YPR[2] + _DOWN_YPR[0],
                what="your value",
                tol=rounded_to(2),
                unit="deg",
                modulo=360.0,
                hint="compute the quantity you chose from the two angles of the question",
            ),
            computed_what="the value you computed",
            explanations={
                "a": "yes: at pitch −90° the first and third axes line up the other way round, "
                "so the matrix depends on roll + yaw only (Rose, eq 4a), and that sum stays "
                "smooth while yaw and roll swing in opposite directions",
                "b": "roll − yaw is what stays defined at pitch +90°, the pole this recording "
                "visits (eq 4b); at −90° the middle turn lays the first axis the other way round: "
                "write the product out there before carrying eq 4b over",
                "c": "alone, yaw is defined at neither pole: near one it swings by large "
                "amounts from one sample to the next, and only a combination with roll is "
                "pinned down by the matrix",
                "d": "alone, roll is defined at neither pole: near one it swings by large "
                "amounts from one sample to the next, and only a combination with yaw is "
                "pinned down by the matrix",
            },
        ),
        examples=(
            Example("('a', 50)", "correct"),
            Example("(' A ', 410.0)", "correct"),
            Example("('a', -30)", "off", "your value"),
            Example("('b', -30)", "off", "pitch +90°"),
            Example("('c', 40)", "off", "alone, yaw"),
            Example("('d', 10)", "off", "alone, roll"),
            Example("'a'", "off", "give a pair"),
        ),
        forbidden=("answer_2 = 'a'", 'answer_2 = "a"'),
    ),
    Exercise(
        id="14.3",
        level="extend",
        judge=ArrayJudge(
            _OMEGA,
            what="your angular velocity",
            tol=1e-6,
            hint="the turn between the two samples is M₀ᵀ M₁; its rotation vector, divided by "
            "the time between the samples, is the rate",
            mistakes=(
                Mistake(
                    _SPACE_OMEGA,
                    "this is ω in the earth's axes (from M₁ M₀ᵀ); the gyroscope measures it in "
                    "the sensor's own axes, from M₀ᵀ M₁",
                ),
                Mistake(
                    np.radians(_OMEGA),
                    "this is in rad/s; the question asks for °/s",
                ),
                Mistake(
                    2 * _OMEGA,
                    "the attitude samples are 1/128 s apart (128 Hz); 1/256 s is the interval "
                    "of the gyroscope's samples",
                ),
                Mistake(
                    -_OMEGA,
                    "M₁ᵀ M₀ is the turn from the later attitude back to the earlier one: the "
                    "rate has the right size and the wrong direction",
                ),
            ),
        ),
        given=lambda: (_M0.copy(), _M0_NEXT.copy()),
        examples=(
            Example("np.degrees(matrix_to_rotvec(M0_ex.T @ M1_ex)) * 128", "correct"),
            Example("matrix_to_rotvec(M0_ex.T @ M1_ex, degrees=True) / (1 / 128)", "correct"),
            Example(
                "matrix_to_rotvec(M1_ex @ M0_ex.T, degrees=True) * 128",
                "off",
                "earth's axes",
            ),
            Example("matrix_to_rotvec(M0_ex.T @ M1_ex) * 128", "off", "rad/s"),
            Example("matrix_to_rotvec(M0_ex.T @ M1_ex, degrees=True) * 256", "off", "1/128 s"),
            Example(
                "matrix_to_rotvec(M1_ex.T @ M0_ex, degrees=True) * 128",
                "off",
                "wrong direction",
            ),
        ),
        forbidden=("120.0", "300.0", "[120"),
    ),
]
