"""The compiled kernels of quaternions, rotation vectors and axis-angle pairs against the
numpy-only path, on the same inputs: the same bits, the same shapes, the same errors.

The oracle is the numpy-only path, which the other test files hold against SciPy, mpmath and
the papers; these tests show that the optional kernels change nothing but the time.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from budget import examples
from compiled import assert_same_bits, both, needs_compiled
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

import eulerlib

pytestmark = needs_compiled

# numbers of every scale, so that lengths that need rescaling (declined by the kernels) occur
scaled = st.one_of(
    st.floats(-2.0, 2.0),
    st.floats(-1e-160, 1e-160),
    st.floats(-1e160, 1e160),
    st.sampled_from([0.0, -0.0, 1.0, -1.0, 5e-324, 1.7e308]),
)
shapes = st.sampled_from([(), (1,), (3,), (2, 3), (17,)])


def outcome(function, *args, **kwargs):
    """The result of a call, or the type and message of what it raised."""
    try:
        return function(*args, **kwargs)
    except Exception as error:  # any error: both paths must raise the same
        return type(error), str(error)


def assert_same_outcome(function, *args, **kwargs) -> None:
    compiled, pure = both(outcome, function, *args, **kwargs)
    if isinstance(pure, tuple) and isinstance(pure[0], type):
        assert compiled == pure
    else:
        assert_same_bits(compiled, pure)


@settings(max_examples=examples(300))
@given(shape=shapes, data=st.data(), first=st.booleans())
def test_quaternion_to_matrix(shape, data, first) -> None:
    q = data.draw(arrays(np.float64, (*shape, 4), elements=scaled))
    assert_same_outcome(eulerlib.quaternion_to_matrix, q, scalar_first=first)


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_quaternion_to_matrix_refuses_alike(bad) -> None:
    q = np.array([[0.0, 0.0, 0.0, 1.0], [0.5, 0.5, bad, 0.5]])
    assert_same_outcome(eulerlib.quaternion_to_matrix, q)
    assert_same_outcome(eulerlib.quaternion_to_matrix, np.zeros((3, 4)))


# ---- matrices: rotations of every kind, near-rotations, non-rotations, non-finite entries

_TURNS = [0.0, 1e-200, 1e-9, 1e-4, 1.0, np.pi / 2, np.pi - 1e-9, np.pi, 4.0]


def _turn(axis: np.ndarray, angle: float) -> np.ndarray:
    """The matrix of a turn by ``angle`` about the unit ``axis`` (Rodrigues' formula, typed
    in): only an input here, never an expected value."""
    n = axis / np.linalg.norm(axis)
    cross = np.array([[0.0, -n[2], n[1]], [n[2], 0.0, -n[0]], [-n[1], n[0], 0.0]])
    return np.eye(3) + np.sin(angle) * cross + (1.0 - np.cos(angle)) * (cross @ cross)


@st.composite
def one_matrix(draw) -> np.ndarray:
    kind = draw(st.sampled_from(["turn", "turn", "axis", "signs", "noisy", "any", "bad"]))
    if kind == "turn":
        axis = np.array(draw(st.tuples(*[st.floats(-1.0, 1.0)] * 3)))
        if np.max(np.abs(axis)) < 1e-3:
            axis = np.array([0.0, 0.0, 1.0])
        return _turn(axis, draw(st.sampled_from(_TURNS) | st.floats(0.0, np.pi)))
    if kind == "axis":  # about a coordinate axis, where entries are exact zeros and ones
        axis = np.eye(3)[draw(st.integers(0, 2))] * draw(st.sampled_from([1.0, -1.0]))
        return _turn(axis, draw(st.sampled_from(_TURNS)))
    if kind == "signs":  # half turns and the identity, exactly
        signs = draw(st.sampled_from([(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]))
        permuted = np.diag(np.array(signs, dtype=float))
        return permuted
    if kind == "noisy":  # a rotation off by up to about 1e-6, for atol
        base = _turn(np.array([1.0, 2.0, 3.0]), draw(st.floats(0.0, np.pi)))
        noise = draw(arrays(np.float64, (3, 3), elements=st.floats(-1e-6, 1e-6)))
        return base + noise
    if kind == "any":
        return draw(arrays(np.float64, (3, 3), elements=scaled))
    matrix = np.eye(3)
    matrix[draw(st.integers(0, 2)), draw(st.integers(0, 2))] = draw(
        st.sampled_from([np.nan, np.inf, -np.inf])
    )
    return matrix


@st.composite
def matrix_batches(draw, shape) -> np.ndarray:
    count = int(np.prod(shape, dtype=int))
    stack = [draw(one_matrix()) for _ in range(count)]
    return np.array(stack, dtype=float).reshape(*shape, 3, 3)


@st.composite
def rotation_batches(draw, shape) -> np.ndarray:
    """Mostly batches that pass the check, so that the kernels run to the end."""
    if draw(st.booleans()):
        return draw(matrix_batches(shape))
    count = int(np.prod(shape, dtype=int))
    angles = draw(arrays(np.float64, count, elements=st.sampled_from(_TURNS) | st.floats(0, 4)))
    axes = draw(arrays(np.float64, (count, 3), elements=st.floats(-1.0, 1.0)))
    axes[np.max(np.abs(axes), axis=1) < 1e-3] = [1.0, 0.0, 0.0]
    stack = [_turn(axis, angle) for axis, angle in zip(axes, angles, strict=True)]
    return np.array(stack, dtype=float).reshape(*shape, 3, 3)


checks = st.sampled_from(
    [{}, {"validate": False}, {"repair": True}, {"atol": 1e-5}, {"atol": 0.0}, {"atol": 1e-12}]
)
all_shapes = st.sampled_from([(), (1,), (2,), (3,), (2, 3), (17,), (2, 1, 20)])


def assert_same_warned(function, *args, **kwargs) -> None:
    """The same outcome, and the same warnings, with and without the kernels."""

    def recorded(*a, **k):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            result = outcome(function, *a, **k)
        return result, [(w.category, str(w.message)) for w in caught]

    (compiled, compiled_warnings), (pure, pure_warnings) = both(recorded, *args, **kwargs)
    assert compiled_warnings == pure_warnings
    if isinstance(pure, tuple) and len(pure) == 2 and isinstance(pure[0], type):
        assert compiled == pure
    else:
        assert_same_bits(compiled, pure)


@settings(max_examples=examples(300))
@given(shape=all_shapes, data=st.data(), first=st.booleans(), check=checks)
def test_matrix_to_quaternion(shape, data, first, check) -> None:
    R = data.draw(rotation_batches(shape))
    assert_same_warned(eulerlib.matrix_to_quaternion, R, scalar_first=first, **check)


def test_matrix_to_quaternion_hard_places() -> None:
    for angle in _TURNS:
        for axis in [*np.eye(3).tolist(), [1.0, 1.0, 0.0], [1.0, -2.0, 3.0]]:
            R = _turn(np.array(axis), angle)
            for first in (False, True):
                assert_same_warned(eulerlib.matrix_to_quaternion, R, scalar_first=first)
                assert_same_warned(eulerlib.matrix_to_quaternion, np.stack([R] * 20))
    for bad in (np.nan, np.inf):
        R = np.tile(np.eye(3), (20, 1, 1))
        R[7, 1, 2] = bad
        assert_same_warned(eulerlib.matrix_to_quaternion, R)
        assert_same_warned(eulerlib.matrix_to_quaternion, R, validate=False)
    reflection = np.diag([1.0, 1.0, -1.0])
    assert_same_warned(eulerlib.matrix_to_quaternion, reflection)
    assert_same_warned(eulerlib.matrix_to_quaternion, np.full((3, 3, 3), 1e308), validate=False)
    for unchecked in (np.zeros((3, 3)), np.diag([1.7e308, 0.0, 0.0]), np.zeros((20, 3, 3))):
        assert_same_warned(eulerlib.matrix_to_quaternion, unchecked, validate=False)


# ---- rotation vectors and axis-angle pairs

vector_elements = st.one_of(
    scaled,
    st.sampled_from([np.pi, -np.pi, 2 * np.pi, 1e-9, 1e-200, 90.0, 180.0, -270.0, 360.0, 1e17]),
)


@settings(max_examples=examples(300))
@given(shape=all_shapes, data=st.data(), degrees=st.booleans())
def test_rotvec_to_matrix(shape, data, degrees) -> None:
    v = data.draw(arrays(np.float64, (*shape, 3), elements=vector_elements))
    assert_same_warned(eulerlib.rotvec_to_matrix, v, degrees=degrees)


def test_rotvec_to_matrix_hard_places() -> None:
    special = [0.0, 1e-200, 1e-9, np.pi, 180.0, 90.0, -90.0, 270.0, 1e300, 1.7e308, np.nan, np.inf]
    for value in special:
        for degrees in (False, True):
            v = np.array([[value, 0.0, 0.0], [0.0, -value, 0.0], [value, value, 0.0]])
            assert_same_warned(eulerlib.rotvec_to_matrix, v, degrees=degrees)
            assert_same_warned(eulerlib.rotvec_to_matrix, v[2], degrees=degrees)
            assert_same_warned(eulerlib.rotvec_to_matrix, np.tile(v, (7, 1)), degrees=degrees)


angle_elements = st.one_of(
    st.floats(-10.0, 10.0),
    st.floats(-1e300, 1e300),
    st.sampled_from([0.0, -0.0, 1e-9, 1e-200, np.pi, -np.pi, 45.0, 90.0, -90.0, 180.0, 270.0]),
    st.sampled_from([360.0, -360.0, 450.0, 1e17, 1e308, np.nan, np.inf, -np.inf]),
)


# (axis leading shape, angle shape): equal, one of them single, and broadcasts the kernels leave
axis_angle_shapes = [((), ()), ((3,), (3,)), ((3,), ()), ((), (4,)), ((2, 3), (2, 3))]
axis_angle_shapes += [((20,), (20,)), ((20,), ()), ((2,), (3,)), ((1,), (5,)), ((5,), (1,))]


@settings(max_examples=examples(300))
@given(
    shapes=st.sampled_from(axis_angle_shapes),
    data=st.data(),
    degrees=st.booleans(),
    plain=st.booleans(),
)
def test_axis_angle_to_matrix(shapes, data, degrees, plain) -> None:
    axis_shape, angle_shape = shapes
    axis = data.draw(arrays(np.float64, (*axis_shape, 3), elements=vector_elements))
    angle = data.draw(arrays(np.float64, angle_shape, elements=angle_elements))
    if plain and not angle_shape:  # a Python float, or NumPy's
        angle = float(angle) if data.draw(st.booleans()) else np.float64(angle)
    assert_same_warned(eulerlib.axis_angle_to_matrix, axis, angle, degrees=degrees)


def test_axis_angle_to_matrix_hard_places() -> None:
    axes = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -2.0], [1e-310, 0, 0]])
    angles = [0.0, -0.0, 1e-200, 1e-9, 90.0, 180.0, -180.0, 270.0, 1e17, 1e300, np.pi]
    for degrees in (False, True):
        for angle in angles:
            for axis in axes:
                assert_same_warned(eulerlib.axis_angle_to_matrix, axis, angle, degrees=degrees)
            assert_same_warned(eulerlib.axis_angle_to_matrix, axes[1:], angle, degrees=degrees)
            assert_same_warned(eulerlib.axis_angle_to_matrix, axes, angle, degrees=degrees)
        tiny = np.array([[1e-300, 1e-310, 5e-324], [1e300, 1e-300, 0.0], [3e307, 1.7e308, 0]])
        assert_same_warned(eulerlib.axis_angle_to_matrix, tiny, np.array(angles[:3]))
        many = np.array(angles)
        assert_same_warned(eulerlib.axis_angle_to_matrix, tiny[0], many, degrees=degrees)


# ---- angles, axes and rotation vectors of matrices (C, numpy's arctan2, C)


@settings(max_examples=examples(300))
@given(shape=all_shapes, data=st.data(), degrees=st.booleans(), check=checks)
def test_matrix_to_rotvec(shape, data, degrees, check) -> None:
    R = data.draw(rotation_batches(shape))
    assert_same_warned(eulerlib.matrix_to_rotvec, R, degrees=degrees, **check)


@settings(max_examples=examples(300))
@given(shape=all_shapes, data=st.data(), degrees=st.booleans(), check=checks)
def test_matrix_to_axis_angle(shape, data, degrees, check) -> None:
    R = data.draw(rotation_batches(shape))
    assert_same_warned(eulerlib.matrix_to_axis_angle, R, degrees=degrees, **check)


@settings(max_examples=examples(300))
@given(shape=all_shapes, data=st.data(), degrees=st.booleans(), check=checks)
def test_rotation_angle(shape, data, degrees, check) -> None:
    R = data.draw(rotation_batches(shape))
    assert_same_warned(eulerlib.rotation_angle, R, degrees=degrees, **check)


@settings(max_examples=examples(300))
@given(
    shapes=st.sampled_from([((), ()), ((3,), (3,)), ((), (4,)), ((20,), ()), ((2, 3), (2, 3))]),
    data=st.data(),
    degrees=st.booleans(),
    check=checks,
    same=st.booleans(),
)
def test_angle_between(shapes, data, degrees, check, same) -> None:
    R0 = data.draw(rotation_batches(shapes[0]))
    R1 = R0.copy() if same and shapes[0] == shapes[1] else data.draw(rotation_batches(shapes[1]))
    assert_same_warned(eulerlib.angle_between, R0, R1, degrees=degrees, **check)
    assert_same_warned(eulerlib.angle_between, R1, R0, degrees=degrees, **check)


@pytest.mark.parametrize(
    "function",
    [eulerlib.matrix_to_rotvec, eulerlib.matrix_to_axis_angle, eulerlib.rotation_angle],
)
def test_angles_of_matrices_hard_places(function) -> None:
    for angle in _TURNS:
        for axis in [*np.eye(3).tolist(), [0.0, -1.0, 0.0], [1.0, 1.0, 0.0], [1.0, -2.0, 3.0]]:
            R = _turn(np.array(axis), angle)
            for degrees in (False, True):
                assert_same_warned(function, R, degrees=degrees)
                assert_same_warned(function, np.stack([R] * 20), degrees=degrees)
    for bad in (np.nan, np.inf):
        R = np.tile(np.eye(3), (20, 1, 1))
        R[7, 1, 2] = bad
        assert_same_warned(function, R)
        assert_same_warned(function, R, validate=False)
    assert_same_warned(function, np.diag([1.0, 1.0, -1.0]))
    assert_same_warned(function, np.full((3, 3, 3), 1e308), validate=False)
    assert_same_warned(function, np.eye(3) * 2.0, validate=False)
    for unchecked in (np.zeros((3, 3)), np.zeros((20, 3, 3)), np.diag([1.7e308, 0.0, 0.0])):
        assert_same_warned(function, unchecked, validate=False)


def test_angle_between_hard_places() -> None:
    for angle in _TURNS:
        R = _turn(np.array([1.0, 2.0, -3.0]), angle)
        for degrees in (False, True):
            assert_same_warned(eulerlib.angle_between, np.eye(3), R, degrees=degrees)
            assert_same_warned(eulerlib.angle_between, R, R, degrees=degrees)
            assert_same_warned(eulerlib.angle_between, np.stack([R] * 20), R, degrees=degrees)
    bad = np.tile(np.eye(3), (20, 1, 1))
    bad[3, 0, 0] = np.nan
    assert_same_warned(eulerlib.angle_between, bad, np.eye(3))
    assert_same_warned(eulerlib.angle_between, np.eye(3), bad, validate=False)
    assert_same_warned(eulerlib.angle_between, np.eye(3), np.diag([1.0, -1.0, 1.0]))
    assert_same_warned(eulerlib.angle_between, np.zeros((2, 3, 3)), np.eye(3), validate=False)


def test_generic_numbers() -> None:
    """Numbers with all their bits in use, where any change in the order of the arithmetic
    shows in the last bit."""
    from scipy.spatial.transform import Rotation

    rng = np.random.default_rng(16)
    axes = rng.normal(size=(300, 3))
    angles = rng.uniform(-720.0, 720.0, size=300)
    R = Rotation.random(300, random_state=16).as_matrix()
    for degrees in (False, True):
        assert_same_warned(eulerlib.axis_angle_to_matrix, axes, angles, degrees=degrees)
        assert_same_warned(eulerlib.rotvec_to_matrix, axes, degrees=degrees)
        assert_same_warned(eulerlib.matrix_to_rotvec, R, degrees=degrees)
        assert_same_warned(eulerlib.matrix_to_axis_angle, R, degrees=degrees)
        assert_same_warned(eulerlib.rotation_angle, R, degrees=degrees)
        assert_same_warned(eulerlib.angle_between, R, R[::-1].copy(), degrees=degrees)
        assert_same_warned(eulerlib.matrix_to_quaternion, R, scalar_first=degrees)


@settings(max_examples=examples(200))
@given(
    shape=st.sampled_from([(1,), (3,), (2, 3), (17,)]),
    data=st.data(),
    first=st.booleans(),
)
def test_quaternion_exp(shape, data, first) -> None:
    """Pure quaternions (vectors) of every scale: lengths that need rescaling and zero vectors
    leave the kernels, NaN and infinity are refused alike."""
    v = data.draw(arrays(np.float64, (*shape, 3), elements=scaled | st.just(np.inf)))
    assert_same_outcome(eulerlib.quaternion_exp, v, scalar_first=first)


def test_quaternion_exp_of_many_vectors_across_blocks() -> None:
    v = np.random.default_rng(7).normal(size=(40_000, 3)) * np.array([1e-3, 1.0, 30.0])
    assert_same_outcome(eulerlib.quaternion_exp, v)
    assert_same_outcome(eulerlib.quaternion_exp, v, scalar_first=True)
