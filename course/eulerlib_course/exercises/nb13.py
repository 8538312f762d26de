"""Answer key of notebook 13, angular velocity and Euler rates (ω from Ṙ Rᵀ, 1/cos(pitch), drift,
one step of integration as an exponential).

The references are typed in from the formulas (the aircraft body rates p, q, r of yaw–pitch–roll;
Gram–Schmidt written out; Rodrigues' formula for the exponential of a skew matrix), not taken from
the library functions the notebook teaches; the test table's rows that call those functions must
agree with them.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from eulerlib import euler_to_matrix

from .judges import ArrayJudge, Mistake, NumberJudge
from .key import Example, Exercise
from .seeds import whole_degree_angles

Array = NDArray[np.float64]

# --- 13.1: the gyroscope's reading from angle rates ---------------------------------------------

_ANGLES = (40.0, 25.0, -10.0)  # yaw, pitch, roll, degrees
_RATES = (5.0, -3.0, 8.0)  # their rates, °/s


def _body_rates(angles: tuple[float, ...], rates: tuple[float, ...], to_radians: bool) -> Array:
    """(p, q, r) of yaw–pitch–roll, typed in; ``to_radians=False`` takes sines of degrees."""
    _, v, u = (math.radians(a) for a in angles) if to_radians else angles  # no yaw in (p, q, r)
    dw, dv, du = rates
    return np.array(
        [
            du - dw * math.sin(v),
            dv * math.cos(u) + dw * math.sin(u) * math.cos(v),
            -dv * math.sin(u) + dw * math.cos(u) * math.cos(v),
        ]
    )


_PQR = _body_rates(_ANGLES, _RATES, to_radians=True)
_SPACE = euler_to_matrix(_ANGLES, "rose", degrees=True) @ _PQR

# --- 13.2: how the yaw rate grows near pitch 90° ------------------------------------------------

_FACTOR = math.cos(math.radians(80.0)) / math.cos(math.radians(89.0))

# --- 13.3: Gram–Schmidt that keeps the z column -----------------------------------------------

_TRUE = euler_to_matrix([-35.0, 50.0, 120.0], "rose", degrees=True)
_NOISE = np.array([[0.9e-3, -1.3e-3, 0.4e-3], [-0.7e-3, 1.1e-3, 1.6e-3], [1.2e-3, 0.3e-3, -0.8e-3]])
_DRIFTED = _TRUE + _NOISE  # a rotation matrix after a long, careless computation


def _unit(vector: Array) -> Array:
    result: Array = vector / math.sqrt(float(vector @ vector))
    return result


def _keep_column(M: Array, first: int) -> Array:
    """Gram–Schmidt that keeps column ``first`` (0 or 2), then the x or z column, right-handed."""
    if first == 2:
        z = _unit(M[:, 2])
        x = _unit(M[:, 0] - (z @ M[:, 0]) * z)
        y = np.cross(z, x)
    else:
        x = _unit(M[:, 0])
        y = _unit(M[:, 1] - (x @ M[:, 1]) * x)
        z = np.cross(x, y)
    return np.column_stack([x, y, z])


def _nearest(M: Array) -> Array:
    u, _, vt = np.linalg.svd(M)
    result: Array = u @ vt
    return result


def _some_drifted(rng: np.random.Generator) -> Array:
    """A student's drifted matrix: a rotation of whole-degree Rose angles plus noise of size
    0.3e-3 to 1.6e-3 in every entry, of either sign, to four decimals (as the teacher's)."""
    angles = whole_degree_angles(rng, 80)
    size = rng.integers(3, 17, (3, 3)) * 1e-4
    sign = rng.choice([-1.0, 1.0], (3, 3))
    drifted: Array = euler_to_matrix(angles, "rose", degrees=True) + sign * size
    return drifted


def _judge_repair(M: Array) -> ArrayJudge:
    M = np.asarray(M, dtype=np.float64)
    return ArrayJudge(
        _keep_column(M, 2),
        what="your repaired matrix",
        rotation=True,
        mistakes=(
            Mistake(
                _nearest(M),
                "this is the nearest rotation (the SVD), which moves all three columns a "
                "little; the question keeps the direction of column 3 (z) exactly",
            ),
            Mistake(
                _keep_column(M, 0),
                "this Gram–Schmidt keeps the direction of column 1 (x); the question keeps "
                "column 3 (z) and then as much of column 1 as it can",
            ),
        ),
    )


# --- 13.4: one step of a gyroscope's constant rate, as an exponential ---------------------------

_START_ANGLES = (20.0, -35.0, 60.0)  # Rose's yaw, pitch, roll of the attitude at the start, degrees
_GYRO = (30.0, -45.0, 25.0)  # ᴮω, °/s about the body's x, y and z axes
_STEP = 0.8  # s


def _skew(v: Array) -> Array:
    """[v]x, typed in."""
    x, y, z = (float(c) for c in v)
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])


def _exp_skew(rotvec: Array) -> Array:
    """exp([v]x) by Rodrigues' formula, typed in: I + sin θ K + (1 - cos θ) K², K = [v/θ]x."""
    theta = math.sqrt(float(rotvec @ rotvec))
    K = _skew(rotvec / theta)
    turn: Array = np.eye(3) + math.sin(theta) * K + (1.0 - math.cos(theta)) * (K @ K)
    return turn


def _some_step(rng: np.random.Generator) -> tuple[Array, Array, Array]:
    """A student's start attitude (whole-degree Rose angles), gyroscope rate (every component
    20 to 60 °/s, of either sign) and step (0.5, 1 or 1.5 s): a turn of 17° to 156°."""
    angles = whole_degree_angles(rng, 80)
    rate = rng.integers(20, 61, 3) * rng.choice([-1.0, 1.0], 3)
    step = np.array(rng.choice([0.5, 1.0, 1.5]))  # an array, as all given data: a copy is fresh
    return euler_to_matrix(angles, "rose", degrees=True), rate.astype(float), step


def _judge_step(data: tuple[Array, Array, Array]) -> ArrayJudge:
    start, rate, step = (np.asarray(d, dtype=np.float64) for d in data)
    omega = np.radians(rate)
    turn = _exp_skew(step * omega)
    return ArrayJudge(
        start @ turn,
        what="your attitude",
        rotation=True,
        mistakes=(
            Mistake(
                turn @ start,
                "this turns about the world's axes (the turn multiplies the attitude on the "
                "left); a gyroscope measures the rate about the body's own axes",
            ),
            Mistake(
                start @ (np.eye(3) + step * _skew(omega)),
                "this is the first-order step, which keeps two terms of the series and is not a "
                "rotation; for a constant rate the whole series has a closed form",
            ),
            Mistake(
                start @ _exp_skew(step * np.asarray(rate, dtype=np.float64)),
                "the rate was used in °/s as if it were rad/s",
            ),
            Mistake(
                start @ turn.T,
                "the step turns the body the wrong way: a sign of the rate, or the inverse of "
                "the turn",
            ),
            Mistake(
                start,
                "this is the attitude at the start; during the step the body turns",
            ),
            Mistake(
                turn,
                "this is the turn made during the step alone; the question asks where the body "
                "ends up, starting from its attitude",
            ),
        ),
    )


_GIVEN_STEP = (
    euler_to_matrix(_START_ANGLES, "rose", degrees=True),
    np.array(_GYRO),
    np.array(_STEP),
)
_ANSWER_STEP = _judge_step(_GIVEN_STEP).reference


EXERCISES = [
    Exercise(
        id="13.1",
        level="apply",
        judge=ArrayJudge(
            _PQR,
            what="your (p, q, r)",
            mistakes=(
                Mistake(
                    _SPACE,
                    "this is ω in the fixed axes (the space frame); a gyroscope strapped to the "
                    "body reads it in the body's own axes, Rᵀ times that",
                ),
                Mistake(
                    np.array(_RATES[::-1]),
                    "the angle rates are not the angular velocity: each rate turns the body "
                    "about its own axis as the earlier turns have moved it, so (roll rate, pitch "
                    "rate, yaw rate) is ω only when all three angles are 0",
                ),
                Mistake(
                    np.array(_RATES),
                    "the angle rates are not the angular velocity: each rate turns the body "
                    "about its own axis as the earlier turns have moved it",
                ),
                Mistake(
                    _body_rates(_ANGLES, _RATES, to_radians=False),
                    "the sines and cosines were taken of the angles in degrees as if they were "
                    "radians: convert the angles with np.radians first",
                ),
                Mistake(
                    np.radians(_PQR),
                    "this is the answer in rad/s; the question asks for °/s",
                ),
                Mistake(
                    _PQR[::-1],
                    "the components are in reverse order: p, q, r turn about the body's x, y "
                    "and z axes, in that order",
                ),
            ),
        ),
        given=lambda: (np.array(_ANGLES), np.array(_RATES)),
        examples=(
            Example(
                "[rates_ex[2] - rates_ex[0] * np.sin(np.radians(angles_ex[1])),"
                " rates_ex[1] * np.cos(np.radians(angles_ex[2]))"
                " + rates_ex[0] * np.sin(np.radians(angles_ex[2]))"
                " * np.cos(np.radians(angles_ex[1])),"
                " -rates_ex[1] * np.sin(np.radians(angles_ex[2]))"
                " + rates_ex[0] * np.cos(np.radians(angles_ex[2]))"
                " * np.cos(np.radians(angles_ex[1]))]",
                "correct",
            ),
            Example(
                "euler_rates_to_angular_velocity(angles_ex, rates_ex, 'rose', degrees=True)",
                "correct",
            ),
            Example(
                "np.degrees(euler_rates_to_angular_velocity(np.radians(angles_ex),"
                " np.radians(rates_ex)))",
                "correct",
            ),
            Example(
                "euler_rates_to_angular_velocity(angles_ex, rates_ex, frame='space', degrees=True)",
                "off",
                "fixed axes (the space frame)",
            ),
            Example("rates_ex[::-1]", "off", "the angle rates are not the angular velocity"),
            Example(
                "euler_rates_to_angular_velocity(angles_ex, rates_ex)",
                "off",
                "as if they were radians",
            ),
            Example(
                "euler_rates_to_angular_velocity(np.radians(angles_ex), np.radians(rates_ex))",
                "off",
                "rad/s",
            ),
            Example("'(p, q, r)'", "off", "text"),
        ),
        forbidden=tuple(f"{value:.3f}" for value in _PQR),
    ),
    Exercise(
        id="13.2",
        level="predict",
        judge=NumberJudge(
            _FACTOR,
            what="your factor",
            tol=0.01,
            mistakes=(
                Mistake(
                    1 / _FACTOR,
                    "that is the factor by which the yaw rate would shrink; it grows as the "
                    "pitch nears 90°, like 1 / cos(pitch)",
                ),
                Mistake(
                    89.0 / 80.0,
                    "the yaw rate does not grow in proportion to the pitch angle: it grows like "
                    "1 / cos(pitch)",
                ),
                Mistake(
                    math.tan(math.radians(89.0)) / math.tan(math.radians(80.0)),
                    "tan(pitch) is how the roll rate picks up the yaw rate (u̇ = p + ẇ sin v); "
                    "the yaw rate itself is divided by cos(pitch)",
                ),
                Mistake(
                    math.cos(80.0) / math.cos(89.0),
                    "the cosines were taken of 80 and 89 as if they were radians",
                ),
            ),
        ),
        examples=(
            Example("np.cos(np.radians(80)) / np.cos(np.radians(89))", "correct"),
            Example("9.95", "correct"),
            Example("1 / np.cos(np.radians(89)) * np.cos(np.radians(80))", "correct"),
            Example("0.1", "off", "would shrink"),
            Example("89 / 80", "off", "in proportion to the pitch"),
            Example("np.cos(80) / np.cos(89)", "off", "as if they were radians"),
            Example("np.tan(np.radians(89)) / np.tan(np.radians(80))", "off", "tan(pitch)"),
            Example("'ten'", "off", "text"),
        ),
        forbidden=("9.95", "9.949", "57.29"),
    ),
    Exercise(
        id="13.3",
        level="extend",
        judge=_judge_repair(_DRIFTED),
        per_student=_some_drifted,
        judged=_judge_repair,
        given=lambda: _DRIFTED.copy(),
        examples=(
            # QR is Gram–Schmidt: on the columns (z, x, y), with the signs made positive
            Example(
                "np.linalg.qr(M_ex[:, [2, 0, 1]])[0][:, [1, 2, 0]]"
                " * np.sign(np.diag(np.linalg.qr(M_ex[:, [2, 0, 1]])[1]))[[1, 2, 0]]",
                "correct",
            ),
            Example("nearest_rotation(M_ex)", "off", "nearest rotation (the SVD)"),
            Example(
                "np.linalg.qr(M_ex)[0] * np.sign(np.diag(np.linalg.qr(M_ex)[1]))",
                "off",
                "keeps the direction of column 1",
            ),
            Example("M_ex", "off", "not a rotation"),
            Example(  # the frame built as rows instead of columns
                "(np.linalg.qr(M_ex[:, [2, 0, 1]])[0][:, [1, 2, 0]]"
                " * np.sign(np.diag(np.linalg.qr(M_ex[:, [2, 0, 1]])[1]))[[1, 2, 0]]).T",
                "off",
                "transpose",
            ),
        ),
        forbidden=tuple(f"{value:.4f}" for value in _keep_column(_DRIFTED, 2).ravel()),
    ),
    Exercise(
        id="13.4",
        level="extend",
        judge=_judge_step(_GIVEN_STEP),
        per_student=_some_step,
        judged=_judge_step,
        given=lambda: tuple(part.copy() for part in _GIVEN_STEP),
        examples=(
            Example("W_R_ex @ rotvec_to_matrix(np.radians(B_w_ex) * h_ex)", "correct"),
            Example("integrate_angular_velocity(W_R_ex, B_w_ex, h_ex, degrees=True)", "correct"),
            Example(
                "integrate_angular_velocity(W_R_ex, W_R_ex @ np.radians(B_w_ex), h_ex,"
                " frame='space')",
                "correct",
            ),
            Example("rotvec_to_matrix(np.radians(B_w_ex) * h_ex) @ W_R_ex", "off", "world's axes"),
            Example(
                "W_R_ex @ (np.eye(3) + h_ex * np.cross(np.eye(3), np.radians(B_w_ex)))",
                "off",
                "first-order step",
            ),
            Example("W_R_ex @ rotvec_to_matrix(B_w_ex * h_ex)", "off", "as if it were rad/s"),
            Example("W_R_ex @ rotvec_to_matrix(-np.radians(B_w_ex) * h_ex)", "off", "wrong way"),
            Example("rotvec_to_matrix(np.radians(B_w_ex) * h_ex)", "off", "during the step alone"),
            Example("W_R_ex", "off", "at the start"),
            Example("'the attitude'", "off", "text"),
        ),
        forbidden=tuple(f"{value:.4f}" for value in np.asarray(_ANSWER_STEP).ravel()),
    ),
]
