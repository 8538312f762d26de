"""Angular velocity in SymPy: the Euler-rate Jacobian, its determinant, and ω read off ``Ṙ Rᵀ``.

Oracles: finite differences of the numeric library's matrices, the aircraft body rates typed in
here, and identities decided exactly modulo ``sin² + cos² = 1``; the two symbolic routes (the
Jacobian built from the moved axes, and ``Ṙ Rᵀ`` differentiated) are compared with each other
only after each has met an independent oracle.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from budget import sweep
from symbolic_oracles import holds, numeric

import eulerlib
from eulerlib.symbolic import (
    angular_velocity_from_matrix,
    angular_velocity_jacobian,
    elementary_matrix,
    euler_matrix,
    euler_symbols,
    jacobian_determinant,
    quaternion_from_axis_angle,
    quaternion_to_matrix,
    rodrigues_matrix,
)

ALPHA, BETA, GAMMA = euler_symbols()
W, V, U = sp.symbols("w v u", real=True)  # Rose: yaw, pitch, roll
T = sp.Symbol("t", real=True)
FUNCTIONS = tuple(sp.Function(name, real=True)(T) for name in ("alpha", "beta", "gamma"))
RATES = sp.Matrix([f.diff(T) for f in FUNCTIONS])


def vee(skew: np.ndarray) -> np.ndarray:
    """The vector of a skew-symmetric matrix: [ω]× ↦ ω."""
    return np.array([skew[2, 1], skew[0, 2], skew[1, 0]])


def finite_difference_omega(R_of_t, t: float, frame: str, step: float = 1e-6) -> np.ndarray:
    R = R_of_t(t)
    R_dot = (R_of_t(t + step) - R_of_t(t - step)) / (2 * step)
    skew = R.T @ R_dot if frame == "body" else R_dot @ R.T
    assert np.allclose(skew, -skew.T, atol=1e-8)
    return vee(skew)


# --- the Jacobian -----------------------------------------------------------------------------


@pytest.mark.parametrize("frame", ["body", "space"])
@pytest.mark.parametrize("seq", eulerlib.ALL_SEQUENCES)
def test_jacobian_matches_finite_differences(
    seq: str, frame: str, rng: np.random.Generator
) -> None:
    J = numeric(
        angular_velocity_jacobian((ALPHA, BETA, GAMMA), seq, frame=frame), (ALPHA, BETA, GAMMA)
    )
    for angles, rates in zip(rng.uniform(-3, 3, (3, 3)), rng.normal(size=(3, 3)), strict=True):

        def R_of_t(t: float, angles=angles, rates=rates) -> np.ndarray:
            return eulerlib.euler_to_matrix(angles + t * rates, seq)

        assert np.allclose(
            J(*angles) @ rates, finite_difference_omega(R_of_t, 0.0, frame), atol=1e-8
        )


@pytest.mark.parametrize("seq", sweep(eulerlib.ALL_SEQUENCES))
def test_jacobian_determinant(seq: str, rng: np.random.Generator) -> None:
    det = jacobian_determinant((ALPHA, BETA, GAMMA), seq)
    assert det == jacobian_determinant((ALPHA, BETA, GAMMA), seq, frame="space")
    assert det.free_symbols <= {BETA}
    J = numeric(angular_velocity_jacobian((ALPHA, BETA, GAMMA), seq), (ALPHA, BETA, GAMMA))
    for angles in rng.uniform(-3, 3, (3, 3)):
        assert np.isclose(float(det.subs(BETA, angles[1])), np.linalg.det(J(*angles)))
    proper = seq.upper() in eulerlib.PROPER_EULER
    singular = (0, sp.pi) if proper else (sp.pi / 2, -sp.pi / 2)
    for value in singular:
        assert det.subs(BETA, value) == 0
    factor = sp.sin(BETA) if proper else sp.cos(BETA)
    assert det in (factor, -factor)


def test_jacobian_rose_body_rates() -> None:
    # aircraft body rates: p = u' - w' sin v, q = v' cos u + w' sin u cos v, ...
    dw, dv, du = sp.symbols("dw dv du", real=True)
    c, s = sp.cos, sp.sin
    expected = sp.Matrix(
        [
            du - dw * s(V),
            dv * c(U) + dw * s(U) * c(V),
            -dv * s(U) + dw * c(U) * c(V),
        ]
    )
    J = angular_velocity_jacobian((W, V, U), "ZYX")
    assert sp.expand(J * sp.Matrix([dw, dv, du]) - expected) == sp.zeros(3, 1)
    assert angular_velocity_jacobian((W, V, U), "rose") == J
    assert angular_velocity_jacobian((W, V, U)) == J  # "ZYX" and the body frame by default


def test_jacobian_frame_is_a_choice() -> None:
    body = angular_velocity_jacobian((W, V, U), "ZYX", frame="body")
    assert angular_velocity_jacobian((W, V, U), "ZYX", frame="BODY") == body
    with pytest.raises(ValueError, match=r"^frame must be 'body' or 'space', got 'world'"):
        angular_velocity_jacobian((W, V, U), "ZYX", frame="world")
    with pytest.raises(TypeError, match=r"^frame must be 'body' or 'space'"):
        jacobian_determinant((W, V, U), "ZYX", frame=None)


# --- ω read off Ṙ Rᵀ --------------------------------------------------------------------------


@pytest.mark.parametrize("frame", ["body", "space"])
@pytest.mark.parametrize("seq", ["ZYX", "xyz", "YZX", "ZXZ", "zyz", "baker"])
def test_omega_from_the_matrix_is_the_jacobian_times_the_rates(seq: str, frame: str) -> None:
    omega = angular_velocity_from_matrix(euler_matrix(FUNCTIONS, seq), T, frame=frame)
    J = angular_velocity_jacobian(FUNCTIONS, seq, frame=frame)
    assert holds(omega - J * RATES, angles=FUNCTIONS)


def test_omega_about_a_coordinate_axis_is_the_angle_rate() -> None:
    theta = FUNCTIONS[0]
    for frame in ("body", "space"):
        omega = angular_velocity_from_matrix(elementary_matrix("y", theta), T, frame=frame)
        assert omega == sp.Matrix([0, theta.diff(T), 0])
    constant = angular_velocity_from_matrix(euler_matrix((W, V, U)), T)
    assert constant == sp.zeros(3, 1)


def test_omega_of_a_turn_about_a_moving_axis_matches_finite_differences() -> None:
    # the axis (cos t, sin t, 0) turns while the body turns about it by t²: not an Euler matrix
    axis = (sp.cos(T), sp.sin(T), 0)
    R = rodrigues_matrix(axis, T**2)
    R_numeric = numeric(R, (T,))
    for frame in ("body", "space"):
        omega = numeric(angular_velocity_from_matrix(R, T, frame=frame), (T,))
        for t in (-1.3, 0.2, 0.9, 2.5):
            expected = finite_difference_omega(R_numeric, t, frame)
            assert np.allclose(omega(t).ravel(), expected, atol=1e-8)


def test_omega_of_a_quaternion_turn_about_a_fixed_axis() -> None:
    k = (sp.Rational(2, 3), sp.Rational(1, 3), sp.Rational(-2, 3))  # a unit axis
    theta = FUNCTIONS[1]
    R = quaternion_to_matrix(quaternion_from_axis_angle(k, theta))
    for frame in ("body", "space"):
        omega = angular_velocity_from_matrix(R, T, frame=frame)
        assert sp.simplify(omega - theta.diff(T) * sp.Matrix(k)) == sp.zeros(3, 1)


def test_omega_refuses_a_matrix_that_is_not_a_rotation() -> None:
    theta = FUNCTIONS[0]
    with pytest.raises(ValueError, match=r"^R must be a rotation matrix for every value of t"):
        angular_velocity_from_matrix(2 * elementary_matrix("z", theta), T)
    with pytest.raises(ValueError, match=r"^R must be a rotation matrix"):
        angular_velocity_from_matrix(rodrigues_matrix((theta, 0, 0), theta), T)
    with pytest.raises(TypeError, match=r"^t must be a SymPy Symbol"):
        angular_velocity_from_matrix(elementary_matrix("z", theta), theta)
