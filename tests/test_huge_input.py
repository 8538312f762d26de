"""Finite input whose arithmetic overflows: the right answer, or a one-line ValueError.

Every number here is finite, so it passes the rule for numbers; but a length, a product or a
sum of such numbers may leave the range of float64 (above about 1.8e308). Each function then
either computes the answer, by scaling by powers of two where the answer itself is in range,
or refuses with a ``ValueError`` that names the argument, and never returns NaN or infinity,
raises an ``IndexError`` or lets a ``RuntimeWarning`` escape: every test here turns warnings
into errors.

The oracles are mpmath (the exact turn by an exactly known angle, reduced modulo 360 with
Python's integers for degrees) and the answers' own definitions typed in.
"""

from __future__ import annotations

from fractions import Fraction

import mp_reference as mp
import mpmath
import numpy as np
import pytest
from numpy.testing import assert_allclose, assert_array_equal
from scipy.spatial.transform import Rotation

from eulerlib import (
    angular_velocity_to_euler_rates,
    euler_rates_to_angular_velocity,
    integrate_angular_velocity,
    is_rotation_matrix,
    rot_z,
    rotate_points,
    rotvec_to_matrix,
    slerp,
)

pytestmark = pytest.mark.filterwarnings("error")

HUGE = 1.7e308
# (3, 4, 0) · 2^1020 has the exact length 5 · 2^1020 ≈ 5.6e307, while its squares overflow
THREE, FOUR = 3.0 * 2.0**1020, 4.0 * 2.0**1020
LENGTH = 5 * 2**1020


def exact_turn_about_3_4_0(angle: mpmath.mpf) -> mp.Matrix:
    return mp.matrix_of_axis_angle(mp.mp_vector([0.6, 0.8, 0.0]), angle)


def test_a_long_rotation_vector_turns_by_its_length() -> None:
    # SciPy's from_rotvec gives NaN here; the length is in range, so is the answer
    with mpmath.workdps(400):  # 1e307 radians reduced modulo 2π keeps 50 digits
        angle = mpmath.mpf(LENGTH) % (2 * mpmath.pi)
        exact = exact_turn_about_3_4_0(+angle)
    assert mp.absolute_ulps(rotvec_to_matrix([THREE, FOUR, 0.0]), exact) <= 3.0


def test_a_long_rotation_vector_in_degrees() -> None:
    reduced = Fraction(LENGTH % 360)  # exact, in Python's integers
    exact = exact_turn_about_3_4_0(mpmath.pi * reduced.numerator / reduced.denominator / 180)
    assert mp.absolute_ulps(rotvec_to_matrix([THREE, FOUR, 0.0], degrees=True), exact) <= 3.0


@pytest.mark.parametrize("degrees", [False, True])
def test_a_rotation_vector_longer_than_any_float_is_refused(degrees: bool) -> None:
    with pytest.raises(ValueError, match=r"^v has a length above") as caught:
        rotvec_to_matrix([HUGE, HUGE, 0.0], degrees=degrees)
    assert "\n" not in str(caught.value)
    with pytest.raises(ValueError, match=r"^v at index \(1,\) has a length above"):
        rotvec_to_matrix([[1.0, 0.0, 0.0], [HUGE, -HUGE, HUGE]], degrees=degrees)


def test_a_step_whose_turn_is_longer_than_any_float_is_refused() -> None:
    with pytest.raises(ValueError, match=r"^omega \* dt at index \(1,\) has a length above"):
        integrate_angular_velocity(np.eye(3), [[0.0, 0.0, 1.0], [HUGE, HUGE, 0.0]], 1.0)
    R = integrate_angular_velocity(np.eye(3), [THREE, FOUR, 0.0], 1.0)
    assert bool(is_rotation_matrix(R, atol=1e-15))


def test_slerp_far_beyond_the_end_turns_by_t_times_the_angle() -> None:
    # R0ᵀ R1 is the quarter turn about z, whose angle slerp finds as the float π/2; t · π/2
    # is then exact in floats for t = 5 · 2^998, and mpmath reduces it modulo 2π
    quarter = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    t = 5.0 * 2.0**998
    with mpmath.workdps(400):
        angle = (mpmath.mpf(t) * mpmath.mpf(float(np.pi / 2))) % (2 * mpmath.pi)
        exact = mp.matrix_of_axis_angle(mp.mp_vector([0.0, 0.0, 1.0]), +angle)
    assert mp.absolute_ulps(slerp(np.eye(3), quarter, t), exact) <= 4.0


def test_slerp_whose_turn_overflows_is_refused() -> None:
    R1 = rot_z(3.0)  # θ = 3: t θ overflows for t = 1.7e308
    with pytest.raises(ValueError, match=r"^t at index \(1,\) times the angle") as caught:
        slerp(np.eye(3), R1, [0.5, HUGE])
    assert "\n" not in str(caught.value)
    assert_array_equal(slerp(R1, R1, HUGE), R1)  # no turn at all: any t stays at R1


def exact_product(R: np.ndarray, p: np.ndarray) -> np.ndarray:
    """``R p`` in exact rationals, rounded once to float (inf where it is beyond the range)."""
    rows = [sum(Fraction(float(a)) * Fraction(float(b)) for a, b in zip(r, p, strict=True))
            for r in R]  # fmt: skip
    return np.array(
        [float(x) if abs(x) < 2**1024 else (np.inf if x > 0 else -np.inf) for x in rows]
    )


def test_rotating_huge_points_whose_turn_is_in_range() -> None:
    # p lies on the axis of R, so R p = p; the first row's partial sums overflow on the way
    p = np.array([HUGE, HUGE, -HUGE])
    R = Rotation.from_rotvec(np.array([1.0, 1.0, -1.0]) / np.sqrt(3) * np.pi / 2).as_matrix()
    exact = exact_product(R, p)
    assert np.isfinite(exact).all()
    cases = [
        (R, p, exact),
        (R, np.stack([p, -p, p / 2]), np.stack([exact, -exact, exact / 2])),
        (np.stack([R, R]), p, np.stack([exact, exact])),
    ]
    for matrices, points, expected in cases:
        assert_allclose(rotate_points(matrices, points), expected, rtol=4e-16, atol=0.0)


def test_rotating_a_point_out_of_the_float_range_is_refused() -> None:
    eighth = rot_z(45.0, degrees=True)  # (h, h, 0) turns to (0, √2 h, 0)
    assert np.isinf(exact_product(eighth, np.array([HUGE, HUGE, 0.0]))).any()
    with pytest.raises(
        ValueError, match=r"^points is too large: the rotated point would"
    ) as caught:
        rotate_points(eighth, [HUGE, HUGE, 0.0])
    assert "\n" not in str(caught.value)
    with pytest.raises(ValueError, match=r"the rotated point at index \(1, 0\) would be above"):
        rotate_points(eighth, [[[1.0, 2.0, 3.0]], [[HUGE, HUGE, 0.0]]])
    with pytest.raises(ValueError, match=r"the rotated point at index \(1,\) would be above"):
        rotate_points(np.stack([np.eye(3), eighth, eighth]), [HUGE, HUGE, 0.0])


def rose_rates(angles: list[float], omega: list[float]) -> list[mpmath.mpf]:
    """Rose's yaw, pitch and roll rates from the body rates (p, q, r), typed in, 50 digits."""
    with mpmath.workdps(50):
        _, v, u = (mpmath.mpf(a) for a in angles)
        p, q, r = (mpmath.mpf(x) for x in omega)
        yaw = (q * mpmath.sin(u) + r * mpmath.cos(u)) / mpmath.cos(v)
        return [yaw, q * mpmath.cos(u) - r * mpmath.sin(u), p + yaw * mpmath.sin(v)]


def rose_omega(angles: list[float], rates: list[float]) -> list[mpmath.mpf]:
    """Rose's body rates (p, q, r) from the yaw, pitch and roll rates, typed in, 50 digits."""
    with mpmath.workdps(50):
        _, v, u = (mpmath.mpf(a) for a in angles)
        dw, dv, du = (mpmath.mpf(x) for x in rates)
        return [
            du - dw * mpmath.sin(v),
            dv * mpmath.cos(u) + dw * mpmath.sin(u) * mpmath.cos(v),
            -dv * mpmath.sin(u) + dw * mpmath.cos(u) * mpmath.cos(v),
        ]


def test_euler_rates_of_a_huge_angular_velocity() -> None:
    angles, omega = [0.3, 0.2, 0.1], [HUGE, -0.5 * HUGE, 0.25 * HUGE]
    exact = np.array(rose_rates(angles, omega), dtype=float)
    assert_allclose(angular_velocity_to_euler_rates(angles, omega), exact, rtol=1e-14)
    rates = [0.25 * HUGE, -0.5 * HUGE, 0.5 * HUGE]
    exact = np.array(rose_omega(angles, rates), dtype=float)
    assert_allclose(euler_rates_to_angular_velocity(angles, rates), exact, rtol=1e-14)


def test_euler_rates_beyond_the_float_range_are_refused() -> None:
    # roll 45°: the yaw rate (q sin u + r cos u) / cos v is √2 · 1.7e308
    angles = [[0.0, 0.0, 0.0], [0.0, 0.0, np.pi / 4]]
    assert float(rose_rates(angles[1], [0, HUGE, HUGE])[0]) == np.inf
    with pytest.raises(ValueError, match=r"^omega is too large: the Euler rates at index \(1,\)"):
        angular_velocity_to_euler_rates(angles, [0.0, HUGE, HUGE])
    # the body rate r = −v̇ sin u + ẇ cos u cos v is √2 · 1.7e308 at roll −45°
    with pytest.raises(
        ValueError, match=r"^rates is too large: the angular velocity at index \(1,\)"
    ) as caught:
        euler_rates_to_angular_velocity([[0.0, 0.0, 0.0], [0, 0, -np.pi / 4]], [HUGE, HUGE, 0])
    assert "\n" not in str(caught.value)
