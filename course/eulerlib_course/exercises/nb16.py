"""Answer key of notebook 16, fusing gyroscope, gravity and field (a Mahony filter).

The filter of the notebook turns its estimate ``M`` (sensor coordinates into earth coordinates)
with the gyroscope's rate plus a correction, ``k Σ v̂ × Mᵀ v``: each measured direction ``v̂``
(a unit vector in sensor axes) crossed with where the estimate expects it, ``Mᵀ v``. With one
direction and a body at rest, the angle θ between the two obeys ``dθ/dt = −k sin θ``, so
``tan(θ/2)`` shrinks like ``e^{−kt}``; a constant gyroscope bias ``b`` about a horizontal axis
leaves a steady tilt with ``k sin θ = b``.
"""

from __future__ import annotations

import math

import numpy as np

from eulerlib import euler_to_matrix

from .judges import ArrayJudge, ChoiceJudge, Mistake, NumberJudge, rounded_to
from .key import Example, Exercise

_UP = np.array([0.0, 0.0, 1.0])

# --- 16.1: one correction ------------------------------------------------------------------------

_ESTIMATE_1 = euler_to_matrix([40.0, 12.0, -20.0], "rose", degrees=True)
_READING_1 = np.array([0.45, -0.18, 1.02])  # g: the accelerometer, not of length 1
_GAIN_1 = 0.5  # 1/s
_UNIT_1 = _READING_1 / np.linalg.norm(_READING_1)
_EXPECTED_1 = _ESTIMATE_1.T @ _UP
_ANSWER_1 = _GAIN_1 * np.cross(_UNIT_1, _EXPECTED_1)

# --- 16.2: how a tilt decays ----------------------------------------------------------------------

_GAIN_2 = 1.5  # 1/s
_FROM_2, _TO_2 = 60.0, 6.0  # degrees


def _half_tan(degrees: float) -> float:
    return math.tan(math.radians(degrees) / 2)


_TIME_2 = math.log(_half_tan(_FROM_2) / _half_tan(_TO_2)) / _GAIN_2
_SMALL_ANGLE_2 = math.log(_FROM_2 / _TO_2) / _GAIN_2

# --- 16.3: a gyroscope bias against a proportional gain -------------------------------------------

_BIAS_3 = 0.8  # °/s, about the sensor's x axis (horizontal)
_GAIN_3 = 0.2  # 1/s
_TILT_3 = math.degrees(math.asin(math.radians(_BIAS_3) / _GAIN_3))


EXERCISES = [
    Exercise(
        id="16.1",
        level="apply",
        judge=ArrayJudge(
            _ANSWER_1,
            what="your correction",
            tol=1e-6,
            hint="cross the measured direction, made a unit vector, with the direction the "
            "estimate expects in the sensor's axes, and scale by the gain",
            mistakes=(
                Mistake(
                    _GAIN_1 * np.cross(_READING_1, _EXPECTED_1),
                    "the reading is not of length 1 (the body accelerates a little); the filter "
                    "crosses unit directions, so that only the angle between them counts",
                ),
                Mistake(
                    _GAIN_1 * np.cross(_UNIT_1, _UP),
                    "this crosses the reading with up in earth axes; the estimate expects up at "
                    "Mᵀ up in the sensor's own axes, where the reading is",
                ),
                Mistake(
                    _GAIN_1 * np.cross(_UNIT_1, _ESTIMATE_1 @ _UP),
                    "M up is the wrong way round: M turns sensor coordinates into earth "
                    "coordinates, so up in the sensor's axes is Mᵀ up",
                ),
                Mistake(
                    np.cross(_UNIT_1, _EXPECTED_1),
                    "the cross product is the direction and size of the error; the gain still "
                    "has to scale it",
                ),
            ),
        ),
        given=lambda: (_ESTIMATE_1.copy(), _READING_1.copy(), np.array(_GAIN_1)),
        examples=(
            Example("k_ex * np.cross(a_ex / np.linalg.norm(a_ex), M_ex.T @ [0, 0, 1])", "correct"),
            Example("-k_ex * np.cross(M_ex[2], a_ex) / np.linalg.norm(a_ex)", "correct"),
            Example(
                "k_ex * np.cross(M_ex.T @ [0, 0, 1], a_ex / np.linalg.norm(a_ex))",
                "off",
                "opposite way",
            ),
            Example("k_ex * np.cross(a_ex, M_ex.T @ [0, 0, 1])", "off", "not of length 1"),
            Example("k_ex * np.cross(a_ex / np.linalg.norm(a_ex), [0, 0, 1])", "off", "earth axes"),
            Example(
                "k_ex * np.cross(a_ex / np.linalg.norm(a_ex), M_ex @ [0, 0, 1])",
                "off",
                "wrong way round",
            ),
            Example("np.cross(a_ex / np.linalg.norm(a_ex), M_ex.T @ [0, 0, 1])", "off", "the gain"),
        ),
        forbidden=tuple(f"{value:.4f}" for value in _ANSWER_1),
    ),
    Exercise(
        id="16.2",
        level="predict",
        judge=ChoiceJudge(
            options={
                "a": "it shrinks by the same factor in every equal stretch of time, once it is "
                "small",
                "b": "it shrinks at a steady rate and reaches zero in a finite time",
                "c": "it stays: the gyroscope reads zero and holds the attitude",
                "d": "it swings past zero and back, as a spring would",
            },
            answer="a",
            computed=NumberJudge(
                _TIME_2,
                what="your time",
                tol=rounded_to(2),
                unit=None,
                hint="solve dθ/dt = −k sin θ from the starting tilt to the final one, or "
                "run the filter's steps and watch the tilt",
                mistakes=(
                    Mistake(
                        _SMALL_ANGLE_2,
                        "this treats the tilt as small all the way (sin θ ≈ θ); at the start sin θ "
                        "is well below θ, and the large tilt shrinks more slowly",
                    ),
                    Mistake(
                        1 / _GAIN_2,
                        "1/k is the time constant of a small tilt, one factor e; the question "
                        "asks for the time from one given tilt to the other",
                    ),
                ),
            ),
            computed_what="the time you computed",
            explanations={
                "a": "yes: the correction is proportional to sin θ, so a small tilt decays like "
                "e^(−kt), with time constant 1/k",
                "b": "a steady rate would need a correction of fixed size; this one is "
                "proportional to sin θ, so it weakens as the tilt shrinks",
                "c": "the gyroscope alone would hold the wrong attitude, but the correction "
                "adds a rate that turns the expected up toward the measured up",
                "d": "a spring has inertia; the correction sets a rate, not an acceleration, so "
                "the tilt has nothing that carries it past zero",
            },
        ),
        given=lambda: (np.array(_GAIN_2), np.array(_FROM_2), np.array(_TO_2)),
        examples=(
            Example("('a', 1.60)", "correct"),
            Example(
                "('A', np.log(np.tan(np.radians(60) / 2) / np.tan(np.radians(6) / 2)) / 1.5)",
                "correct",
            ),
            Example("('b', 1.6)", "off", "steady rate"),
            Example("('c', 0)", "off", "gyroscope alone"),
            Example("('d', 1.6)", "off", "inertia"),
            Example("('a', np.log(10) / 1.5)", "off", "small all the way"),
            Example("('a', 1 / 1.5)", "off", "time constant"),
            Example("'a'", "off", "give a pair"),
        ),
        forbidden=("1.60", "1.599", "answer_2 = 'a'", 'answer_2 = "a"'),
    ),
    Exercise(
        id="16.3",
        level="extend",
        judge=NumberJudge(
            _TILT_3,
            what="your tilt",
            tol=rounded_to(2),
            unit="deg",
            hint="in the steady state the correction's rate cancels the bias exactly",
            mistakes=(
                Mistake(
                    _BIAS_3 * _GAIN_3,
                    "the bias and the gain were multiplied; the tilt grows with the bias and "
                    "shrinks with a larger gain",
                ),
                Mistake(
                    0.0,
                    "a proportional correction needs an error to act on: it cancels the bias "
                    "only while the tilt stays",
                ),
                Mistake(
                    _BIAS_3 / _GAIN_3 * 180 / math.pi,
                    "the bias was already in degrees per second; converting the result again "
                    "counts the degrees twice",
                ),
            ),
        ),
        given=lambda: (np.array(_BIAS_3), np.array(_GAIN_3)),
        examples=(
            Example("np.degrees(np.arcsin(np.radians(bias_ex) / k_ex))", "correct"),
            Example("bias_ex / k_ex", "correct"),
            Example("bias_ex * k_ex", "off", "multiplied"),
            Example("0", "off", "needs an error"),
            Example("np.arcsin(np.radians(bias_ex) / k_ex)", "off", "radians"),
            Example("np.degrees(bias_ex / k_ex)", "off", "twice"),
        ),
        forbidden=("4.00", "4.0 "),
    ),
]
