"""One exact step of a constant angular velocity: against SciPy, the closed form and 50 digits.

Oracles: SciPy's ``Rotation.from_rotvec`` composed with ``Rotation.from_matrix``; the closed form
of a constant rate, ``R(t) = R(0) exp([ω t]×)``; a 50-digit product of ``R`` and Rodrigues'
matrix typed in with mpmath; and the identity ``R exp([ω]×) = exp([R ω]×) R`` that ties the two
frames together (hypothesis).
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from budget import examples
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp
from mp_reference import EPS, matrix_of_rotvec, mp_matrix, to_float
from numpy.testing import assert_allclose, assert_array_equal
from scipy.spatial.transform import Rotation

from eulerlib import (
    euler_rates_to_angular_velocity,
    euler_to_matrix,
    integrate_angular_velocity,
    is_rotation_matrix,
    nearest_rotation,
    rotvec_to_matrix,
)
from eulerlib._blocks import BLOCK_SIZE

FRAMES = ("body", "space")


def scipy_step(R: np.ndarray, omega: np.ndarray, dt: np.ndarray, frame: str) -> np.ndarray:
    turn = Rotation.from_rotvec(np.asarray(omega) * np.asarray(dt)[..., None])
    start = Rotation.from_matrix(R)
    return (start * turn if frame == "body" else turn * start).as_matrix()


@pytest.mark.parametrize("frame", FRAMES)
def test_one_step_is_scipys_composition(frame: str, rng) -> None:
    n = 200
    R = Rotation.random(n, rng=rng).as_matrix()
    omega = rng.normal(size=(n, 3)) * rng.choice([1e-9, 1e-3, 1.0, 30.0], size=(n, 1))
    dt = rng.uniform(-0.5, 0.5, n)
    got = integrate_angular_velocity(R, omega, dt, frame=frame)
    assert_allclose(got, scipy_step(R, omega, dt, frame), rtol=0, atol=2e-15)


@pytest.mark.parametrize("frame", FRAMES)
def test_a_constant_rate_is_integrated_without_error_of_the_method(frame: str, rng) -> None:
    """n steps of ω dt are one step of ω n dt: the closed form, up to rounding only."""
    R0 = Rotation.random(rng=rng).as_matrix()
    omega, dt, n = rng.normal(size=3) * 2.0, 1 / 256, 1024
    R = R0
    for _ in range(n):
        R = integrate_angular_velocity(R, omega, dt, frame=frame)
    turn = Rotation.from_rotvec(omega * n * dt).as_matrix()  # SciPy's closed form
    closed = R0 @ turn if frame == "body" else turn @ R0
    # rounding only: every step multiplies by the same rounded turn, so its few ulp of error
    # add up n times
    assert np.abs(R - closed).max() <= n * EPS


def test_a_tumbling_body_passes_gimbal_lock_untroubled() -> None:
    """A turn about the body's y axis takes the pitch through 90° and on; no step notices."""
    R = np.eye(3)
    steps, rate = 200, math.radians(1.0)  # 1° per step about y: pitch 0° → 200°
    for _ in range(steps):
        R = integrate_angular_velocity(R, [0.0, rate, 0.0], 1.0)
    assert_allclose(R, euler_to_matrix([0.0, 200.0, 0.0], degrees=True), rtol=0, atol=1e-13)


@pytest.mark.parametrize("frame", FRAMES)
@pytest.mark.parametrize("degrees", [False, True])
def test_one_step_against_fifty_digits_at_the_hard_places(frame: str, degrees: bool, rng) -> None:
    unit = 180 / math.pi if degrees else 1.0
    R = Rotation.random(rng=rng).as_matrix()
    exact_R = mp_matrix(R)
    turns = [1e-300, 1e-20, 1e-8, 1e-3, 1.0, math.pi - 1e-9, math.pi, 7.0, 1e6]
    for length in turns:
        axis = rng.normal(size=3)
        omega = axis / np.linalg.norm(axis) * length * unit / 0.25
        with mpmath.workdps(60):
            step = matrix_of_rotvec(omega * 0.25, degrees)  # ω dt is exact: dt = 1/4
            A, B = (exact_R, step) if frame == "body" else (step, exact_R)
            exact = [[sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
        got = integrate_angular_velocity(R, omega, 0.25, frame=frame, degrees=degrees)
        error = np.abs(got - to_float(exact)).max()
        # the exact product of the float R and the exact turn, to a few ulp; a turn of many
        # radians is known only to a few ulp of its length, since ω's components are rounded
        assert error <= 4 * EPS * max(1.0, length), (length, error / EPS)


rotations = st.builds(
    lambda q: Rotation.from_quat(q if np.linalg.norm(q) > 1e-3 else [0, 0, 0, 1]).as_matrix(),
    hnp.arrays(np.float64, (4,), elements=st.floats(-1, 1, allow_nan=False)),
)
vectors = hnp.arrays(np.float64, (3,), elements=st.floats(-50.0, 50.0, allow_nan=False))


@settings(max_examples=examples(200), deadline=None)
@given(rotations, vectors, st.floats(-1.0, 1.0, allow_nan=False))
def test_body_and_space_frames_agree(R, omega, dt) -> None:
    """``R exp([ω dt]×) = exp([R ω dt]×) R``: the body rate ω is the space rate R ω."""
    body = integrate_angular_velocity(R, omega, dt, frame="body")
    space = integrate_angular_velocity(R, R @ omega, dt, frame="space")
    assert_allclose(body, space, rtol=0, atol=1e-13)
    assert bool(is_rotation_matrix(body, atol=1e-14))


def test_euler_rates_and_the_matrix_step_agree_for_a_short_step(rng) -> None:
    """Angles moving at constant rates for a tiny time, against one step of their ω."""
    angles, rates, dt = np.array([0.4, -0.3, 1.2]), rng.normal(size=3), 1e-6
    R0 = euler_to_matrix(angles, "ZYX")
    for frame in FRAMES:
        omega = euler_rates_to_angular_velocity(angles + rates * dt / 2, rates, frame=frame)
        stepped = integrate_angular_velocity(R0, omega, dt, frame=frame)
        # the midpoint rule: second order in dt, so 1e-12 in the step's 1e-6 turn
        assert_allclose(stepped, euler_to_matrix(angles + rates * dt), rtol=0, atol=1e-15)


def test_degrees_read_omega_in_degrees(rng) -> None:
    R = Rotation.random(4, rng=rng).as_matrix()
    omega, dt = rng.normal(size=(4, 3)) * 100, 0.01
    assert_allclose(
        integrate_angular_velocity(R, omega, dt, degrees=True),
        integrate_angular_velocity(R, np.radians(omega), dt),
        rtol=0,
        atol=2e-16 * 8,
    )
    # a quarter turn in degrees is exact
    assert_array_equal(
        integrate_angular_velocity(np.eye(3), [0, 0, 90], 1.0, degrees=True),
        rotvec_to_matrix([0, 0, 90], degrees=True),
    )


def test_shapes_broadcast(rng) -> None:
    R = Rotation.random(4, rng=rng).as_matrix()[:, None]  # (4, 1, 3, 3)
    omega = rng.normal(size=(5, 3))
    dt = np.array(0.1)
    out = integrate_angular_velocity(R, omega, dt)
    assert out.shape == (4, 5, 3, 3)
    assert_array_equal(out[2, 3], integrate_angular_velocity(R[2, 0], omega[3], 0.1))
    assert integrate_angular_velocity(R[0, 0], omega[0], [0.1, 0.2, 0.3]).shape == (3, 3, 3)
    assert integrate_angular_velocity(np.eye(3), [0, 0, 1], 1.0).shape == (3, 3)
    many = np.broadcast_to(np.eye(3), (BLOCK_SIZE + 5, 3, 3))
    out = integrate_angular_velocity(many, omega[:1], np.linspace(0, 1, BLOCK_SIZE + 5))
    assert_array_equal(out[-1], integrate_angular_velocity(np.eye(3), omega[0], 1.0))


def test_repair_starts_from_the_nearest_rotation(rng) -> None:
    R = Rotation.random(rng=rng).as_matrix() + 1e-5 * rng.normal(size=(3, 3))
    omega = [0.3, -0.1, 0.2]
    with pytest.raises(ValueError, match="pass repair=True"):
        integrate_angular_velocity(R, omega, 0.1)
    assert_array_equal(
        integrate_angular_velocity(R, omega, 0.1, repair=True),
        integrate_angular_velocity(nearest_rotation(R), omega, 0.1),
    )
    integrate_angular_velocity(R, omega, 0.1, validate=False)  # trusted as given


def test_a_step_whose_turn_overflows_is_refused() -> None:
    with pytest.raises(ValueError, match=r"^omega \* dt overflows at index \(1,\)"):
        integrate_angular_velocity(np.eye(3), [[0, 0, 1.0], [1e300, 0, 0]], 1e10)
    # huge but finite turns are fine: 1e300 radians is some angle
    assert bool(is_rotation_matrix(integrate_angular_velocity(np.eye(3), [1e300, 0, 0], 1.0)))
