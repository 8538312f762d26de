"""Axis and angle, rotation vectors, rotation angles and geodesic distances.

Oracles: SciPy's ``Rotation`` (``from_rotvec``, ``as_rotvec``, ``magnitude``, with and without
degrees), the 50-digit mpmath reference of ``tests/mp_reference.py`` (Rodrigues' formula typed
in, the exact answer for the float64 input) at the hard places, the elementary rotations, and
hypothesis properties (round trips, ``angle_between`` a metric).
"""

from __future__ import annotations

import math

import mp_reference as mp
import mpmath
import numpy as np
import pytest
from budget import examples
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp
from numpy.testing import assert_allclose, assert_array_equal
from scipy.spatial.transform import Rotation

from eulerlib import (
    AxisAngle,
    angle_between,
    axis_angle_to_matrix,
    elementary_rotation,
    matrix_to_axis_angle,
    matrix_to_rotvec,
    rotation_angle,
    rotvec_to_matrix,
)

EPS = mp.EPS


@pytest.fixture(scope="module")
def hard_cases() -> list[tuple[str, np.ndarray]]:
    return mp.hard_rotations(np.random.default_rng(11))


# --- SciPy -----------------------------------------------------------------------------------


def test_rotation_vectors_are_scipys(rng) -> None:
    rotation = Rotation.random(20000, rng=rng)
    R = rotation.as_matrix()
    assert np.abs(matrix_to_rotvec(R) - rotation.as_rotvec()).max() <= 8 * EPS
    in_degrees = matrix_to_rotvec(R, degrees=True)
    assert np.abs(in_degrees - rotation.as_rotvec(degrees=True)).max() <= 1e-12
    v = rng.normal(size=(20000, 3)) * rng.choice([1e-9, 1.0, 3.0, 50.0], (20000, 1))
    assert np.abs(rotvec_to_matrix(v) - Rotation.from_rotvec(v).as_matrix()).max() <= 4 * EPS
    assert (
        np.abs(rotvec_to_matrix(v, degrees=True) - Rotation.from_rotvec(v, degrees=True)
               .as_matrix()).max() <= 4 * EPS
    )  # fmt: skip


def test_rotation_angle_is_scipys_magnitude(rng) -> None:
    rotation = Rotation.random(20000, rng=rng)
    R = rotation.as_matrix()
    assert np.abs(rotation_angle(R) - rotation.magnitude()).max() <= 4 * EPS
    assert_allclose(rotation_angle(R, degrees=True), np.degrees(rotation.magnitude()), atol=1e-12)
    other = Rotation.random(20000, rng=rng)
    expected = (rotation.inv() * other).magnitude()
    assert np.abs(angle_between(R, other.as_matrix()) - expected).max() <= 8 * EPS


def test_axis_angle_to_matrix_is_scipys_from_rotvec(rng) -> None:
    axis = rng.normal(size=(5000, 3)) * rng.uniform(0.01, 100.0, (5000, 1))  # any length
    angle = rng.uniform(-10.0, 10.0, 5000)
    unit = axis / np.linalg.norm(axis, axis=-1, keepdims=True)
    expected = Rotation.from_rotvec(unit * angle[:, None]).as_matrix()
    # SciPy rounds the rotation vector and its length, which moves the angle by up to about
    # |angle| ε: the bound grows with the angle (the mpmath tests below are exact)
    bound = 4 * EPS * np.maximum(1.0, np.abs(angle))[:, None, None]
    assert np.all(np.abs(axis_angle_to_matrix(axis, angle) - expected) <= bound)
    in_degrees = axis_angle_to_matrix(axis, np.degrees(angle), degrees=True)
    assert np.all(np.abs(in_degrees - expected) <= 2 * bound)


# --- the 50-digit reference at the hard places ---------------------------------------------


def test_angle_axis_and_rotvec_against_mpmath(hard_cases) -> None:
    for label, R in hard_cases:
        axis_exact, angle_exact = mp.axis_angle_of(mp.polar(R))
        axis, angle = matrix_to_axis_angle(R)
        assert mp.ulps(angle, angle_exact) <= 2.0, label
        assert mp.ulps(rotation_angle(R), angle_exact) <= 2.0, label
        half_turn = angle_exact > mpmath.pi - 8 * EPS  # either axis may be the canonical one
        error = mp.absolute_ulps(axis, axis_exact)
        if half_turn:
            error = min(error, mp.absolute_ulps(-axis, axis_exact))
        assert error <= 2.0, label
        v = matrix_to_rotvec(R)
        exact_v = [angle_exact * c for c in axis_exact]
        spacing = np.spacing(float(angle_exact))
        error = float(max(abs(mp.MP(float(a)) - b) for a, b in zip(v, exact_v, strict=True)))
        if half_turn:
            error = min(error, float(max(abs(mp.MP(float(-a)) - b)
                                         for a, b in zip(v, exact_v, strict=True))))  # fmt: skip
        assert error <= 3.0 * spacing, label


@pytest.mark.parametrize("length", [float(a) for a in mp.SMALL_ANGLES] + [0.5, 3.0, 3.14159, 1e3])
def test_rotvec_to_matrix_against_mpmath(length: float, rng) -> None:
    for _ in range(5):
        direction = rng.normal(size=3)
        v = direction / np.linalg.norm(direction) * length
        exact = mp.matrix_of_rotvec(v, degrees=False)
        R = rotvec_to_matrix(v)
        # the length |v| is rounded, by up to |v| ε, before any trigonometry: the bound grows
        # with the length, as it does for any float64 computation of the length
        assert mp.absolute_ulps(R, exact) <= 2.0 * max(1.0, length), length
        if length <= 1e-4:  # the small entries of small turns, relative to their size too
            for i, j in [(0, 1), (0, 2), (1, 0), (1, 2), (2, 0), (2, 1)]:
                assert mp.ulps(R[i, j], exact[i][j]) <= 4.0, (length, i, j)


@pytest.mark.parametrize("length", [1e-300, 1e-100, 1e-10, 1e-4])
def test_tiny_rotation_vectors_come_back_to_the_last_digit(length: float, rng) -> None:
    for _ in range(20):
        direction = rng.normal(size=3)
        v = direction / np.linalg.norm(direction) * length
        back = matrix_to_rotvec(rotvec_to_matrix(v))
        assert np.abs(back - v).max() <= 4 * np.spacing(length)
        assert mp.ulps(rotation_angle(rotvec_to_matrix(v)), mp.MP(float(np.linalg.norm(v)))) <= 4


@pytest.mark.parametrize(
    ("angle", "degrees"),
    [(1e20, True), (-(10.0**17), True), (2.0**60 + 45, True), (1e300, True), (123456.789, True),
     (1e5, False), (-7.5, False)],
)  # fmt: skip
def test_huge_angles(angle: float, degrees: bool, rng) -> None:
    for _ in range(5):
        axis = rng.normal(size=3)
        exact = mp.matrix_of_axis_angle(mp.mp_vector(axis), mp.radians_of(angle, degrees))
        R = axis_angle_to_matrix(axis, angle, degrees=degrees)
        assert mp.absolute_ulps(R, exact) <= 3.0
        # the rotation vector of the turn, typed in: the angle reduced to [-π, π] times the
        # unit axis (a negative reduced angle turns the axis around)
        with mpmath.workdps(mp.DIGITS):
            turn = mp.radians_of(angle, degrees)
            reduced = turn - 2 * mpmath.pi * mpmath.nint(turn / (2 * mpmath.pi))
            exact_v = [reduced * c for c in mp.unit(mp.mp_vector(axis))]
            exact_degrees = [c / mpmath.pi for c in exact_v]
        assert mp.absolute_ulps(matrix_to_rotvec(R), exact_v) <= 16.0
        in_degrees = matrix_to_rotvec(R, degrees=True)
        assert mp.absolute_ulps(in_degrees / 180.0, exact_degrees) <= 16.0
    along = np.array([0.0, abs(angle), 0.0])
    exact = mp.matrix_of_axis_angle(mp.mp_vector([0, 1, 0]), mp.radians_of(abs(angle), degrees))
    assert mp.absolute_ulps(rotvec_to_matrix(along, degrees=degrees), exact) <= 3.0


@pytest.mark.parametrize("scale", [5e-324, 1e-300, 1e-150, 1.0, 1e150, 1e300])
def test_axes_of_any_length(scale: float, rng) -> None:
    """Only the direction of the axis counts, at any scale, tiny and half turns included."""
    for angle in (np.pi, 3.0, 1.0, 1e-8, 1e-300):
        direction = rng.normal(size=3)
        axis = direction * scale if scale > 1e-320 else np.array([0.0, scale, 0.0])
        exact = mp.matrix_of_axis_angle(mp.mp_vector(axis), mp.MP(angle))
        R = axis_angle_to_matrix(axis, angle)
        assert mp.absolute_ulps(R, exact) <= 2.0, (scale, angle)
        if angle < 1e-4:  # the small entries carry the whole turn: relative accuracy
            for i, j in [(0, 1), (0, 2), (1, 0), (1, 2), (2, 0), (2, 1)]:
                if exact[i][j] != 0:
                    assert mp.ulps(R[i, j], exact[i][j]) <= 4.0, (scale, angle, i, j)


def test_angle_between_against_mpmath(rng, hard_cases) -> None:
    matrices = [R for _, R in hard_cases]
    for index in range(0, len(matrices) - 1, 3):
        A, B = matrices[index], matrices[(7 * index + 5) % len(matrices)]
        exact = mp.rotation_angle_of(mp.transpose_product(mp.polar(A), mp.polar(B)))
        # absolute: two matrices each orthogonal only to rounding fix the angle to about that
        assert float(abs(mp.MP(float(angle_between(A, B))) - exact)) <= 4 * EPS
    R = Rotation.random(rng=rng).as_matrix()
    for small in (1e-12, 1e-8, 1e-4):
        B = R @ rotvec_to_matrix([small, 0.0, 0.0])
        exact = mp.rotation_angle_of(mp.transpose_product(mp.polar(R), mp.polar(B)))
        assert float(abs(mp.MP(float(angle_between(R, B))) - exact)) <= 4 * EPS


# --- exact places and documented choices -----------------------------------------------------


@pytest.mark.parametrize("axis", ["x", "y", "z"])
def test_quarter_turns_about_coordinate_axes_are_the_elementary_rotations(axis: str) -> None:
    direction = np.eye(3)["xyz".index(axis)]
    angles = np.array([0.0, 90.0, 180.0, 270.0, -90.0, 360.0, 450.0, 45 * 2.0**60, -45 * 2.0**70])
    expected = elementary_rotation(axis, angles, degrees=True)
    assert_array_equal(axis_angle_to_matrix(direction, angles, degrees=True), expected)
    assert_array_equal(axis_angle_to_matrix(3.0 * direction, angles, degrees=True), expected)
    rotvecs = direction * angles[:, None]
    assert_array_equal(rotvec_to_matrix(rotvecs, degrees=True), expected)


def test_the_axis_at_angle_zero_and_at_a_half_turn() -> None:
    axis, angle = matrix_to_axis_angle(np.eye(3))
    assert_array_equal(axis, [1.0, 0.0, 0.0])
    assert angle == 0.0
    assert_array_equal(matrix_to_rotvec(np.eye(3)), [0.0, 0.0, 0.0])
    for direction in ([0, 1, 0], [-1, 1, 0], [0, -1, -1], [-1, -2, 2]):
        n = np.array(direction, dtype=float) / np.linalg.norm(direction)
        half_turn = 2.0 * np.outer(n, n) - np.eye(3)
        axis, angle = matrix_to_axis_angle(half_turn)
        assert angle == np.pi
        first = n[np.flatnonzero(n)[0]]
        assert_allclose(axis, n * np.sign(first), rtol=0, atol=2 * EPS)  # first nonzero > 0
        assert_allclose(matrix_to_rotvec(half_turn), np.pi * axis, rtol=0, atol=4 * EPS)


def test_angles_agree_across_functions(rng, hard_cases) -> None:
    R = np.concatenate([Rotation.random(2000, rng=rng).as_matrix(),
                        np.stack([R for _, R in hard_cases])])  # fmt: skip
    angle = rotation_angle(R)
    assert_array_equal(matrix_to_axis_angle(R).angle, angle)
    assert_array_equal(angle_between(np.eye(3), R), angle)
    assert np.all((angle >= 0.0) & (angle <= np.pi))
    v = matrix_to_rotvec(R)
    length = np.array([math.hypot(*row) for row in v])  # np.linalg.norm underflows at 1e-300
    assert_allclose(length, angle, rtol=2 * EPS, atol=0)
    assert_allclose(matrix_to_rotvec(R, degrees=True), np.degrees(v), rtol=2 * EPS, atol=0)


def test_round_trips_everywhere(rng, hard_cases) -> None:
    R = np.concatenate([Rotation.random(100_000, rng=rng).as_matrix(),
                        np.stack([R for _, R in hard_cases])])  # fmt: skip
    axis, angle = matrix_to_axis_angle(R)
    assert np.abs(axis_angle_to_matrix(axis, angle) - R).max() <= 1e-14
    assert np.abs(rotvec_to_matrix(matrix_to_rotvec(R)) - R).max() <= 1e-14
    in_degrees = matrix_to_axis_angle(R, degrees=True)
    assert np.abs(axis_angle_to_matrix(*in_degrees, degrees=True) - R).max() <= 1e-14
    assert_allclose(np.linalg.norm(axis, axis=-1), 1.0, rtol=0, atol=2 * EPS)


# --- shapes and broadcasting -------------------------------------------------------------------


def test_one_matrix_gives_0d_arrays() -> None:
    result = matrix_to_axis_angle(np.eye(3))
    assert isinstance(result, AxisAngle)
    assert result.axis.shape == (3,)
    assert isinstance(result.angle, np.ndarray) and result.angle.shape == ()
    for value in (rotation_angle(np.eye(3)), angle_between(np.eye(3), np.eye(3))):
        assert isinstance(value, np.ndarray) and value.shape == ()


def test_axis_and_angle_broadcast(rng) -> None:
    axis = rng.normal(size=(4, 1, 3))
    angle = rng.uniform(-3, 3, 5)
    R = axis_angle_to_matrix(axis, angle)
    assert R.shape == (4, 5, 3, 3)
    unit = axis / np.linalg.norm(axis, axis=-1, keepdims=True)
    expected = Rotation.from_rotvec((unit * angle[:, None]).reshape(-1, 3)).as_matrix()
    assert np.abs(R - expected.reshape(4, 5, 3, 3)).max() <= 4 * EPS
    assert axis_angle_to_matrix([0, 0, 1], angle).shape == (5, 3, 3)
    assert axis_angle_to_matrix(axis[:, 0], 0.3).shape == (4, 3, 3)
    assert axis_angle_to_matrix([0, 0, 1], 0.3).shape == (3, 3)
    assert axis_angle_to_matrix(np.zeros((0, 3)), 0.3).shape == (0, 3, 3)


def test_angle_between_broadcasts(rng) -> None:
    A = Rotation.random(3, rng=rng).as_matrix()
    B = Rotation.random((2 * 3), rng=rng).as_matrix().reshape(2, 3, 3, 3)
    expected = np.array([[angle_between(A[j], B[i, j]) for j in range(3)] for i in range(2)])
    assert_array_equal(angle_between(A, B), expected)
    assert angle_between(A[0], B).shape == (2, 3)


def test_many_rotations_across_blocks(rng) -> None:
    rotation = Rotation.random(3 * (16384 + 5), rng=rng)
    R = rotation.as_matrix().reshape(3, -1, 3, 3)
    assert_allclose(matrix_to_rotvec(R).reshape(-1, 3), rotation.as_rotvec(), rtol=0, atol=1e-14)
    axis = rng.normal(size=3)
    angles = rng.uniform(-3, 3, 3 * 16384 + 5)
    R = axis_angle_to_matrix(axis, angles)
    expected = axis_angle_to_matrix(np.broadcast_to(axis, (angles.size, 3)), angles)
    assert_array_equal(R, expected)


# --- properties --------------------------------------------------------------------------------


@st.composite
def rotations(draw, count=None):
    """Rotation matrices from SciPy, through random quaternions (an independent path)."""
    count = draw(st.integers(1, 5)) if count is None else count
    q = draw(hnp.arrays(np.float64, (count, 4), elements=st.floats(-1, 1, allow_nan=False)))
    q[np.linalg.norm(q, axis=-1) < 1e-3] = [0.0, 0.0, 0.0, 1.0]
    return Rotation.from_quat(q).as_matrix()


small_or_any_angle = st.one_of(
    st.floats(-10.0, 10.0, allow_nan=False),
    st.floats(1e-300, 1e-4),
    st.builds(lambda d: math.pi - d, st.floats(0.0, 1e-4)),
)
checked = settings(max_examples=examples(150), deadline=None)


@checked
@given(rotations(), rotations(), rotations())
def test_angle_between_is_a_metric(A, B, C) -> None:
    count = min(len(A), len(B), len(C))
    A, B, C = A[:count], B[:count], C[:count]
    assert_array_equal(angle_between(A, B), angle_between(B, A))
    assert_array_equal(angle_between(A, A), 0.0)
    assert np.all(angle_between(A, C) <= angle_between(A, B) + angle_between(B, C) + 8 * EPS)


@checked
@given(hnp.arrays(np.float64, 3, elements=st.floats(-1.0, 1.0)), small_or_any_angle)
def test_axis_angle_round_trip(axis, angle) -> None:
    if not np.any(axis):
        axis = np.array([0.0, 0.0, 1.0])
    R = axis_angle_to_matrix(axis, angle)
    back_axis, back_angle = matrix_to_axis_angle(R)
    assert_allclose(axis_angle_to_matrix(back_axis, back_angle), R, rtol=0, atol=1e-15)
    assert_allclose(rotation_angle(R), abs(math.remainder(angle, 2 * math.pi)), rtol=0,
                    atol=1e-14)  # fmt: skip
