"""The path of one rotation in Python floats against the array path, on the same inputs.

A single rotation (``(3,)`` angles, a ``(3, 3)`` matrix, a ``(4,)`` quaternion) is computed in
Python floats (:mod:`eulerlib._scalar`); the same rotation with a leading axis of length 1 takes
the array path. Both must give the same numbers to the last bit (the path of one rotation
calls numpy's own sine, cosine, tangent and arctangent, whose vectorized code may differ from
the C library's by a unit in the last place), the same types and shapes, and the same errors
and warnings. The oracle is the array
path, which the other test files hold against SciPy, mpmath and the papers.
"""

from __future__ import annotations

import warnings
from collections.abc import Iterator

import numpy as np
import pytest
from budget import examples
from compiled import numpy_only
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

import eulerlib
from eulerlib import ALL_SEQUENCES, GimbalLockWarning

SEQUENCES = [*ALL_SEQUENCES, "rose", "baker", "ros"]


@pytest.fixture(autouse=True)
def _without_compiled_kernels() -> Iterator[None]:
    """Both paths here are numpy's: the compiled kernels, which would take both the single
    rotation and the batch, are held against them in tests/test_compiled_*.py."""
    with numpy_only():
        yield


def assert_ulp(single: np.ndarray, batch: np.ndarray, ulps: int = 0) -> None:
    """``single`` (one rotation) equals ``batch[0]`` to ``ulps`` units in the last place
    (0: bit for bit)."""
    assert type(single) is np.ndarray and single.dtype == np.float64
    assert single.shape == batch.shape[1:]
    expected = batch[0]
    spacing = np.spacing(np.maximum(np.abs(single), np.abs(expected)))
    worst = np.max(np.abs(single - expected) / spacing)
    assert worst <= ulps, (single, expected, worst)


angle = st.floats(-4.0, 4.0, allow_nan=False)
degree = st.floats(-1e6, 1e6, allow_nan=False)
hard_angle = st.sampled_from(
    [
        0.0,
        -0.0,
        1e-300,
        -1e-17,
        1e-8,
        np.pi / 2,
        -np.pi / 2,
        np.pi,
        -np.pi,
        np.nextafter(np.pi, 0),
        np.pi / 2 + 1e-15,
        1e300,
        -1e20,
        2.0**60,
    ]
)
hard_degree = st.sampled_from(
    [0.0, 90.0, -90.0, 180.0, 270.0, 45.0, 360.0, 1e20, 89.9999999999, -1e300]
)
triple = st.tuples(
    st.one_of(angle, hard_angle), st.one_of(angle, hard_angle), st.one_of(angle, hard_angle)
)
triple_degrees = st.tuples(
    st.one_of(degree, hard_degree), st.one_of(degree, hard_degree), st.one_of(degree, hard_degree)
)


@settings(max_examples=examples(100), deadline=None)
@given(values=triple, seq=st.sampled_from(SEQUENCES))
def test_euler_to_matrix_and_quaternion(values: tuple[float, float, float], seq: str) -> None:
    one, batch = np.array(values), np.array([values])
    assert_ulp(eulerlib.euler_to_matrix(one, seq), eulerlib.euler_to_matrix(batch, seq))
    assert_ulp(eulerlib.euler_to_quaternion(one, seq), eulerlib.euler_to_quaternion(batch, seq))
    assert_ulp(eulerlib.euler_to_matrix(list(values), seq), eulerlib.euler_to_matrix(batch, seq))


@settings(max_examples=examples(100), deadline=None)
@given(values=triple_degrees, seq=st.sampled_from(SEQUENCES), first=st.booleans())
def test_degrees(values: tuple[float, float, float], seq: str, first: bool) -> None:
    one, batch = np.array(values), np.array([values])
    assert_ulp(
        eulerlib.euler_to_matrix(one, seq, degrees=True),
        eulerlib.euler_to_matrix(batch, seq, degrees=True),
    )
    assert_ulp(
        eulerlib.euler_to_quaternion(one, seq, degrees=True, scalar_first=first),
        eulerlib.euler_to_quaternion(batch, seq, degrees=True, scalar_first=first),
    )


def matrices() -> list[np.ndarray]:
    """Random rotations, rotations at and next to gimbal lock, half turns, tiny turns, and
    matrices with rounding noise, for every sequence's poles."""
    rng = np.random.default_rng(7)
    found = list(Rotation.random(200, rng=rng).as_matrix())
    for seq in ALL_SEQUENCES:
        middle = 0.0 if seq[0].lower() == seq[2].lower() else np.pi / 2
        for offset in (0.0, 1e-16, 1e-15, 1e-12, 1e-8, 1e-3):
            for sign in (1.0, -1.0):
                angles = np.array([0.3, middle + sign * offset, -1.2])
                found.append(Rotation.from_euler(seq, angles).as_matrix())
    for axis in np.eye(3):
        for turn in (np.pi, np.nextafter(np.pi, 0), 1e-300, 1e-9, 0.0):
            found.append(Rotation.from_rotvec(axis * turn).as_matrix())
    Q = Rotation.random(50, rng=rng).as_matrix()
    found.extend(Q @ np.swapaxes(Q, -1, -2) @ Rotation.random(50, rng=rng).as_matrix())
    found.extend(np.round(Rotation.random(20, rng=rng).as_matrix(), 7))  # inside atol only
    return found


MATRICES = matrices()


@pytest.mark.parametrize("seq", SEQUENCES)
def test_matrix_to_euler(seq: str) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", GimbalLockWarning)
        for R in MATRICES:
            for degrees in (False, True):
                one = eulerlib.matrix_to_euler(R, seq, degrees=degrees)
                batch = eulerlib.matrix_to_euler(R[np.newaxis], seq, degrees=degrees)
                assert_ulp(one, batch)


@pytest.mark.parametrize("first", [False, True])
def test_matrix_to_quaternion_and_back(first: bool) -> None:
    for R in MATRICES:
        q = eulerlib.matrix_to_quaternion(R, scalar_first=first)
        assert_ulp(q, eulerlib.matrix_to_quaternion(R[np.newaxis], scalar_first=first))
        assert_ulp(
            eulerlib.quaternion_to_matrix(q, scalar_first=first),
            eulerlib.quaternion_to_matrix(q[np.newaxis], scalar_first=first),
            ulps=0,
        )


quaternion_component = st.one_of(
    st.floats(-2.0, 2.0, allow_nan=False),
    st.sampled_from([0.0, -0.0, 1e-300, -1e-200, 1e-17, 1e150, 1e-160, 5e-324]),
)


@settings(max_examples=examples(100), deadline=None)
@given(q=st.tuples(*[quaternion_component] * 4), seq=st.sampled_from(SEQUENCES))
def test_quaternions(q: tuple[float, float, float, float], seq: str) -> None:
    one, batch = np.array(q), np.array([q])
    try:
        expected = eulerlib.quaternion_to_matrix(batch)
    except ValueError as error:  # a zero quaternion: the same refusal on both paths
        with pytest.raises(ValueError) as caught:
            eulerlib.quaternion_to_matrix(one)
        assert str(caught.value).replace(" at index (0,)", "") == str(error).replace(
            " at index (0,)", ""
        )
        return
    assert_ulp(eulerlib.quaternion_to_matrix(one), expected, ulps=0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", GimbalLockWarning)
        assert_ulp(eulerlib.quaternion_to_euler(one, seq), eulerlib.quaternion_to_euler(batch, seq))


def test_the_same_refusals() -> None:
    """A bad single rotation gets the array path's message, word for word."""
    bad = [
        ([1.0, float("nan"), 0.0], "angles must be finite, got nan at index (1,)"),
        ([1.0, 2.0], "angles must have shape (..., 3), got shape (2,)"),
    ]
    for value, message in bad:
        with pytest.raises(ValueError) as caught:
            eulerlib.euler_to_matrix(value)
        assert str(caught.value) == message
    reflection = np.diag([1.0, 1.0, -1.0])
    scaled = 1.001 * np.eye(3)
    for function in (eulerlib.matrix_to_euler, eulerlib.matrix_to_quaternion):
        for R in (reflection, scaled, reflection.tolist()):
            with pytest.raises(ValueError) as single:
                function(R)
            with pytest.raises(ValueError) as batch:
                function(np.asarray(R)[np.newaxis])
            assert str(single.value) == str(batch.value).replace(" at index (0,)", "")
    with pytest.raises(TypeError) as caught:
        eulerlib.euler_to_matrix(["1", 0.0, 0.0])
    assert str(caught.value) == "angles must be real numbers, got text"


def test_the_same_warning_at_lock() -> None:
    R = eulerlib.euler_to_matrix([30, 90, 10], degrees=True)
    with pytest.warns(GimbalLockWarning) as single:
        one = eulerlib.matrix_to_euler(R)
    with pytest.warns(GimbalLockWarning) as batch:
        many = eulerlib.matrix_to_euler(R[np.newaxis])
    assert str(single[0].message) == str(batch[0].message)
    assert_ulp(one, many, ulps=0)


def test_plain_lists_and_tuples() -> None:
    R = eulerlib.euler_to_matrix((0.1, 0.2, 0.3))
    assert_ulp(eulerlib.matrix_to_euler(R.tolist()), eulerlib.matrix_to_euler(R[np.newaxis]))
    assert_ulp(
        eulerlib.matrix_to_euler(tuple(map(tuple, R))), eulerlib.matrix_to_euler(R[np.newaxis])
    )
    assert_ulp(
        eulerlib.euler_to_matrix([30, 20, 10], degrees=True),
        eulerlib.euler_to_matrix([[30.0, 20.0, 10.0]], degrees=True),
        ulps=0,
    )


def test_axis_angle_and_rotation_vectors() -> None:
    rng = np.random.default_rng(3)
    pairs = list(zip(MATRICES, [*MATRICES[1:], MATRICES[0]], strict=True))
    for R, other in pairs:
        for degrees in (False, True):
            batch = eulerlib.matrix_to_axis_angle(R[np.newaxis], degrees=degrees)
            one = eulerlib.matrix_to_axis_angle(R, degrees=degrees)
            assert_ulp(one.axis, batch.axis)
            assert_ulp(np.atleast_1d(one.angle), batch.angle[np.newaxis])
            assert one.angle.shape == ()
            v = eulerlib.matrix_to_rotvec(R, degrees=degrees)
            assert_ulp(v, eulerlib.matrix_to_rotvec(R[np.newaxis], degrees=degrees))
            assert_ulp(
                eulerlib.rotvec_to_matrix(v, degrees=degrees),
                eulerlib.rotvec_to_matrix(v[np.newaxis], degrees=degrees),
            )
            axis = rng.normal(size=3) * 10.0 ** rng.integers(-200, 200)
            assert_ulp(
                eulerlib.axis_angle_to_matrix(axis, float(one.angle), degrees=degrees),
                eulerlib.axis_angle_to_matrix(
                    axis[np.newaxis], [float(one.angle)], degrees=degrees
                ),
            )
            angle = eulerlib.rotation_angle(R, degrees=degrees)
            assert angle.shape == ()
            assert_ulp(
                np.atleast_1d(angle),
                eulerlib.rotation_angle(R[np.newaxis], degrees=degrees)[np.newaxis],
            )
            between = eulerlib.angle_between(R, other, degrees=degrees)
            assert between.shape == ()
            assert_ulp(
                np.atleast_1d(between),
                eulerlib.angle_between(R[np.newaxis], other[np.newaxis], degrees=degrees)[
                    np.newaxis
                ],
            )


def test_matrices_and_points() -> None:
    rng = np.random.default_rng(5)
    for R, other in zip(MATRICES, [*MATRICES[1:], MATRICES[0]], strict=True):
        point = rng.normal(size=3) * 10.0 ** rng.integers(-300, 300)
        assert_ulp(
            eulerlib.rotate_points(R, point),
            eulerlib.rotate_points(R, point[np.newaxis]),
        )
        assert_ulp(eulerlib.invert(R), eulerlib.invert(R[np.newaxis]))
        assert_ulp(eulerlib.compose(R, other), eulerlib.compose(R[np.newaxis], other[np.newaxis]))
    # a point whose turn leaves the range of float64: the array path's refusal, word for word
    huge = np.array([1.7e308, 1.7e308, -1.7e308])
    R = eulerlib.euler_to_matrix([0.3, 0.2, 0.1])
    with pytest.raises(ValueError) as single:
        eulerlib.rotate_points(R, huge)
    with pytest.raises(ValueError) as batch:
        eulerlib.rotate_points(R, huge[np.newaxis])
    assert str(single.value) == str(batch.value).replace(" at index (0,)", "")


@settings(max_examples=examples(100), deadline=None)
@given(values=triple, degrees=st.booleans(), axis=st.sampled_from("xyz"))
def test_named_converted_and_elementary(
    values: tuple[float, float, float], degrees: bool, axis: str
) -> None:
    one, batch = np.array(values), np.array([values])
    for to_matrix, from_matrix in (
        (eulerlib.yaw_pitch_roll_to_matrix, eulerlib.matrix_to_yaw_pitch_roll),
        (eulerlib.heading_attitude_bank_to_matrix, eulerlib.matrix_to_heading_attitude_bank),
    ):
        R = to_matrix(*values, degrees=degrees)
        assert_ulp(R, to_matrix(*batch.T, degrees=degrees))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", GimbalLockWarning)
            named, named_batch = from_matrix(R), from_matrix(R[np.newaxis])
        for single, many in zip(named, named_batch, strict=True):
            assert single.shape == ()
            assert_ulp(np.atleast_1d(single), many[np.newaxis])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", GimbalLockWarning)
        for source, target in (("ZYX", "xyz"), ("rose", "baker"), ("ZXZ", "yzy")):
            assert_ulp(
                eulerlib.convert_angles(one, source, target, degrees=degrees),
                eulerlib.convert_angles(batch, source, target, degrees=degrees),
            )
    assert_ulp(
        eulerlib.elementary_rotation(axis, values[0], degrees=degrees),
        eulerlib.elementary_rotation(axis, [values[0]], degrees=degrees),
    )


@settings(max_examples=examples(100), deadline=None)
@given(
    t=st.one_of(st.floats(-3.0, 3.0), st.sampled_from([0.0, 1.0, 0.5, 1e-300, 1e300])),
    dt=st.one_of(st.floats(-10.0, 10.0), st.sampled_from([0.0, 1e-300, 1e300])),
    pick=st.integers(0, len(MATRICES) - 2),
    degrees=st.booleans(),
    space=st.booleans(),
)
def test_slerp_and_integration(t: float, dt: float, pick: int, degrees: bool, space: bool) -> None:
    R0, R1 = MATRICES[pick], MATRICES[pick + 1]
    omega = np.array([0.3, -2.0, 1.1])
    for single, batch in (
        (lambda: eulerlib.slerp(R0, R1, t), lambda: eulerlib.slerp(R0, R1, [t])),
        (
            lambda: eulerlib.integrate_angular_velocity(
                R0, omega, dt, degrees=degrees, frame="space" if space else "body"
            ),
            lambda: eulerlib.integrate_angular_velocity(
                R0, omega, [dt], degrees=degrees, frame="space" if space else "body"
            ),
        ),
    ):
        try:
            expected = batch()
        except ValueError as error:  # a turn beyond the range of floats: the same refusal
            with pytest.raises(ValueError) as caught:
                single()
            assert str(caught.value) == str(error).replace(" at index (0,)", "")
            continue
        assert_ulp(single(), expected)


@pytest.mark.parametrize("count", [2, 7, 16])
def test_small_batches_of_quaternions_and_matrices(count: int) -> None:
    """Up to ``SMALL_BATCH`` quaternions or matrices take the path in Python floats, one
    after another; a list of arrays takes the array path."""
    for start in range(0, len(MATRICES) - count, count):
        R = np.array(MATRICES[start : start + count])
        for first in (False, True):
            q = eulerlib.matrix_to_quaternion(R, scalar_first=first)
            assert_ulp(q, eulerlib.matrix_to_quaternion(list(R), scalar_first=first)[np.newaxis])
            assert_ulp(
                eulerlib.quaternion_to_matrix(q, scalar_first=first),
                eulerlib.quaternion_to_matrix(list(q), scalar_first=first)[np.newaxis],
            )
    bad = np.array(MATRICES[:count])
    bad[-1] *= 1.001
    with pytest.raises(ValueError) as few:
        eulerlib.matrix_to_quaternion(bad)
    with pytest.raises(ValueError) as many:
        eulerlib.matrix_to_quaternion(list(bad))
    assert str(few.value) == str(many.value)


@pytest.mark.parametrize("scale", [1.7e308, 1e-300, 0.0])
def test_unchecked_matrices_far_from_rotations(scale: float) -> None:
    """With ``validate=False`` a matrix far from any rotation gives a quaternion of zero or
    overflowing length: the path of one rotation leaves it to the array path (it raised
    ZeroDivisionError before) and both give the same result."""
    M = np.diag([scale, 0.0, 0.0])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        single = eulerlib.matrix_to_quaternion(M, validate=False)
        batch = eulerlib.matrix_to_quaternion(M[np.newaxis], validate=False)
        few = eulerlib.matrix_to_quaternion(np.stack([np.eye(3), M]), validate=False)
    np.testing.assert_array_equal(single, batch[0])
    np.testing.assert_array_equal(few[1], batch[0])
