"""Slerp: the geodesic between two rotations, at constant angular speed.

Oracles: SciPy's ``Slerp``, the 50-digit mpmath reference ``R0 Exp(t log(R0ᵀ R1))`` of
``tests/mp_reference.py`` (near a half turn, for tiny turns, and outside [0, 1]), elementary
rotations about one axis, and hypothesis properties: the endpoints, equal angles for equal steps,
the midpoint halfway from both ends.
"""

from __future__ import annotations

import mp_reference as mp
import mpmath
import numpy as np
import pytest
from budget import examples
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp
from numpy.testing import assert_allclose, assert_array_equal
from scipy.spatial.transform import Rotation, Slerp

from eulerlib import (
    angle_between,
    axis_angle_to_matrix,
    matrix_to_axis_angle,
    rot_x,
    rot_z,
    rotvec_to_matrix,
    slerp,
)

EPS = mp.EPS


def scipy_slerp(R0: np.ndarray, R1: np.ndarray, t: np.ndarray) -> np.ndarray:
    return Slerp([0.0, 1.0], Rotation.from_matrix([R0, R1]))(t).as_matrix()


def test_one_pair_is_scipys_slerp(rng) -> None:
    for _ in range(20):
        R0, R1 = Rotation.random(2, rng=rng).as_matrix()
        t = np.concatenate([[0.0, 1.0], rng.uniform(0.0, 1.0, 50)])
        assert np.abs(slerp(R0, R1, t) - scipy_slerp(R0, R1, t)).max() <= 8 * EPS


def test_many_pairs_are_scipys_slerp(rng) -> None:
    n = 2000
    R0 = Rotation.random(n, rng=rng).as_matrix()
    R1 = Rotation.random(n, rng=rng).as_matrix()
    t = np.round(rng.uniform(0.0, 1.0, n) * 2**20) / 2**20  # so that 2 i + t is exact
    keys = Rotation.from_matrix(np.stack([R0, R1], axis=1).reshape(-1, 3, 3))
    expected = Slerp(np.arange(2 * n), keys)(2 * np.arange(n) + t).as_matrix()
    assert np.abs(slerp(R0, R1, t) - expected).max() <= 8 * EPS


# --- the 50-digit reference --------------------------------------------------------------------


@pytest.mark.parametrize("below_pi", [1e-4, 1e-8, 1e-12, 1e-15])
def test_near_a_half_turn_against_mpmath(below_pi: float, rng) -> None:
    for _ in range(3):
        R0 = Rotation.random(rng=rng).as_matrix()
        axis = mp.random_axis(rng)
        turn = mp.to_float(mp.matrix_of_axis_angle(axis, mpmath.pi - mp.MP(below_pi)))
        R1 = R0 @ turn
        Q0, Q1 = mp.polar(R0), mp.polar(R1)
        for t in (0.25, 0.5, 0.9):
            exact = mp.slerp_of(Q0, Q1, t)
            # near a half turn the path depends on the last bits of R0 and R1 (its axis is
            # ill-conditioned); the exact path of these two float matrices is the reference
            assert mp.absolute_ulps(slerp(R0, R1, t), exact) <= 6.0, (below_pi, t)


@pytest.mark.parametrize("angle", [1e-300, 1e-100, 1e-12, 1e-6, 0.3, 2.0])
def test_tiny_and_ordinary_turns_and_extrapolation_against_mpmath(angle: float, rng) -> None:
    for _ in range(3):
        R0 = Rotation.random(rng=rng).as_matrix()
        direction = rng.normal(size=3)
        R1 = R0 @ rotvec_to_matrix(direction / np.linalg.norm(direction) * angle)
        Q0, Q1 = mp.polar(R0), mp.polar(R1)
        for t in (-1.5, 0.0, 0.3, 0.5, 1.0, 2.5):
            exact = mp.slerp_of(Q0, Q1, t)
            assert mp.absolute_ulps(slerp(R0, R1, t), exact) <= 6.0, (angle, t)


# --- endpoints, exact places and the documented choice -------------------------------------------


def test_endpoints(rng) -> None:
    R0 = Rotation.random(1000, rng=rng).as_matrix()
    R1 = Rotation.random(1000, rng=rng).as_matrix()
    assert_array_equal(slerp(R0, R1, 0.0), R0)  # exactly: R0 times the identity
    assert np.abs(slerp(R0, R1, 1.0) - R1).max() <= 4 * EPS
    assert_array_equal(slerp(R0, R0, rng.uniform(-5, 5, 1000)), R0)


def test_turning_about_one_axis(rng) -> None:
    t = np.array([-1.0, 0.0, 0.25, 0.5, 1.0, 2.0, 3.5])
    path = slerp(rot_z(10, degrees=True), rot_z(50, degrees=True), t)
    assert_allclose(path, rot_z(10 + 40 * t, degrees=True), rtol=0, atol=2 * EPS)
    # the short way round: from 170° to −170° is 20°, not 340°
    path = slerp(rot_z(170, degrees=True), rot_z(-170, degrees=True), t)
    assert_allclose(path, rot_z(170 + 20 * t, degrees=True), rtol=0, atol=4 * EPS)


def test_exactly_half_a_turn_apart_turns_about_the_canonical_axis() -> None:
    """Both ways round are geodesics; slerp turns about the axis with first component > 0."""
    t = np.array([0.25, 0.5, 0.75])
    for axis in ([1.0, 0.0, 0.0], [-1.0, 1.0, 0.0], [0.0, -1.0, -2.0]):
        n = np.array(axis) / np.linalg.norm(axis)
        half_turn = 2.0 * np.outer(n, n) - np.eye(3)
        canonical = matrix_to_axis_angle(half_turn).axis
        assert canonical[np.flatnonzero(canonical)[0]] > 0
        expected = axis_angle_to_matrix(canonical, np.pi * t)
        assert_allclose(slerp(np.eye(3), half_turn, t), expected, rtol=0, atol=4 * EPS)
    assert_allclose(slerp(np.eye(3), np.diag([1.0, -1.0, -1.0]), 0.5), rot_x(90, degrees=True),
                    rtol=0, atol=2 * EPS)  # fmt: skip


# --- shapes ----------------------------------------------------------------------------------


def test_output_shape_is_the_broadcast_of_the_leading_axes(rng) -> None:
    R0 = Rotation.random(4, rng=rng).as_matrix()
    R1 = Rotation.random(4, rng=rng).as_matrix()
    t = rng.uniform(0, 1, 5)
    assert slerp(R0[0], R1[0], t).shape == (5, 3, 3)
    assert slerp(R0, R1, 0.5).shape == (4, 3, 3)
    assert slerp(R0, R1[0], 0.5).shape == (4, 3, 3)
    along = slerp(R0, R1, t[:, None])
    assert along.shape == (5, 4, 3, 3)
    for i in range(5):
        for j in range(4):
            assert_array_equal(along[i, j], slerp(R0[j], R1[j], t[i]))
    assert slerp(R0[0], R1[0], 0.5).shape == (3, 3)
    assert slerp(R0[0], R1[0], np.zeros(0)).shape == (0, 3, 3)
    with pytest.raises(ValueError, match=r"leading shapes of R0 \(4,\), R1 \(4,\) and t \(5,\)"):
        slerp(R0, R1, t)


def test_many_fractions_across_blocks(rng) -> None:
    R0, R1 = Rotation.random(2, rng=rng).as_matrix()
    t = rng.uniform(0, 1, 3 * 16384 + 7)  # SciPy's Slerp does not extrapolate
    path = slerp(R0, R1, t)
    assert_array_equal(path[-5:], slerp(R0, R1, t[-5:]))
    assert np.abs(path - scipy_slerp(R0, R1, t)).max() <= 8 * EPS


# --- properties --------------------------------------------------------------------------------


@st.composite
def rotation_pairs(draw):
    """Two rotations from SciPy, through random quaternions; sometimes a half turn apart or
    nearly equal, on purpose."""
    q = draw(hnp.arrays(np.float64, (2, 4), elements=st.floats(-1, 1, allow_nan=False)))
    q[np.linalg.norm(q, axis=-1) < 1e-3] = [0.0, 0.0, 0.0, 1.0]
    R0, R1 = Rotation.from_quat(q).as_matrix()
    kind = draw(st.sampled_from(["any", "half turn", "close"]))
    if kind == "half turn":
        axis = q[1, :3] if np.linalg.norm(q[1, :3]) > 1e-3 else np.array([1.0, 0.0, 0.0])
        R1 = R0 @ Rotation.from_rotvec(np.pi * axis / np.linalg.norm(axis)).as_matrix()
    elif kind == "close":
        R1 = R0 @ Rotation.from_rotvec(1e-9 * q[1, :3]).as_matrix()
    return R0, R1


checked = settings(max_examples=examples(150), deadline=None)


@checked
@given(rotation_pairs(), st.integers(2, 12))
def test_equal_steps_turn_equal_angles(pair, steps) -> None:
    R0, R1 = pair
    path = slerp(R0, R1, np.linspace(0.0, 1.0, steps + 1))
    step_angles = angle_between(path[:-1], path[1:])
    total = angle_between(R0, R1)
    assert_allclose(step_angles, total / steps, rtol=0, atol=1e-14)


@checked
@given(rotation_pairs())
def test_the_midpoint_is_halfway_from_both_ends(pair) -> None:
    R0, R1 = pair
    middle = slerp(R0, R1, 0.5)
    total = angle_between(R0, R1)
    assert_allclose(angle_between(R0, middle), total / 2, rtol=0, atol=1e-14)
    assert_allclose(angle_between(middle, R1), total / 2, rtol=0, atol=1e-14)


@checked
@given(rotation_pairs(), st.floats(-3.0, 3.0))
def test_the_path_is_made_of_rotations_and_runs_backwards_from_the_other_end(pair, t) -> None:
    R0, R1 = pair
    R = slerp(R0, R1, t)
    assert_allclose(R @ np.swapaxes(R, -1, -2), np.eye(3), rtol=0, atol=1e-14)
    if angle_between(R0, R1) < np.pi - 1e-6:  # a unique geodesic: the same path both ways
        assert_allclose(slerp(R1, R0, 1.0 - t), R, rtol=0, atol=1e-13)


def test_unchecked_ends_far_from_rotations_give_nan_not_an_index_error() -> None:
    """With ``validate=False`` nothing promises a rotation, but ends whose relative quaternion
    overflows gave an IndexError from the search for an infinite ``t θ / 2``: they now give NaN,
    as the other unchecked conversions do, and a ``t`` that overflows is still refused."""
    A = np.eye(3)
    A[0, 0] = 2.0**512
    with np.errstate(all="ignore"):
        result = slerp(A, A.copy(), 0.0, validate=False)
        results = slerp(np.stack([np.eye(3), A]), np.stack([np.eye(3), A]), 0.5, validate=False)
    assert result.shape == (3, 3) and np.isnan(result).any()
    assert_array_equal(results[0], np.eye(3))
    with pytest.raises(ValueError):
        slerp(np.eye(3), rot_z(3.0), 1.7e308, validate=False)
