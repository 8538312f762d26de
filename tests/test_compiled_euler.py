"""The compiled kernels of Euler angles against the numpy-only path, on the same inputs: the
same bits, the same shapes, the same errors and the same warnings.

The oracle is the numpy-only path, which the other test files hold against SciPy, mpmath and
the papers; these tests show that the optional kernels change nothing but the time, for all 24
sequences and the presets, in radians and degrees, at gimbal lock, next to it and far from it.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from budget import examples
from compiled import assert_same_bits, both, needs_compiled, numpy_only
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

import eulerlib
from eulerlib._lock import GIMBAL_LOCK_TOLERANCE
from eulerlib.sequences import ALL_SEQUENCES

pytestmark = needs_compiled

# the 24 sequences, the presets, and conventions that zero the third angle at lock (for
# intrinsic sequences; the first written angle for extrinsic ones), which no bare sequence does
SEQUENCES = [
    *ALL_SEQUENCES,
    "rose",
    "baker",
    "ros",
    *(
        eulerlib.Convention(
            f"third-{seq}", seq, ("a", "b", "c"), None, "zeroes the other angle", "third"
        )
        for seq in ("ZXZ", "YXY", "XYZ", "ZXY", "yzy", "xzx", "zyx", "yxz")
    ),
]
sequences = st.sampled_from(SEQUENCES)
shapes = st.sampled_from([(), (1,), (3,), (2, 3), (17,)])

# angles of every scale: ordinary, tiny, huge, whole multiples of 45° and 90° (in degrees),
# and the values next to 0 and ±π
angle_values = st.one_of(
    st.floats(-4.0, 4.0),
    st.floats(-1e-160, 1e-160),
    st.floats(-1e300, 1e300),
    st.integers(-40, 40).map(lambda k: 45.0 * k),
    st.integers(-8, 8).map(lambda k: 90.0 * k),
    st.sampled_from([0.0, -0.0, np.pi, -np.pi, np.nextafter(np.pi, 0), 0.5 * np.pi, 5e-324]),
)


def outcome(function, *args, **kwargs):
    """The result (or the type and message of the error) and the warnings of a call."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            result = function(*args, **kwargs)
        except (ValueError, TypeError) as error:
            result = (type(error), str(error))
    return result, [(w.category, str(w.message)) for w in caught]


def assert_same_outcome(function, *args, **kwargs) -> None:
    (compiled, said), (pure, said_pure) = both(outcome, function, *args, **kwargs)
    assert said == said_pure
    if isinstance(pure, tuple) and isinstance(pure[0], type):
        assert compiled == pure
    else:
        assert_same_bits(compiled, pure)


def matrices_near_lock(data, shape, seq) -> np.ndarray:
    """Rotation matrices (numpy-only) whose middle angle is at lock, a few tolerances from it,
    or anywhere, for the sequence ``seq``; with noise of several sizes on some of them."""
    convention = eulerlib.get_convention(seq)
    proper = convention.parsed.proper
    angles = data.draw(arrays(np.float64, (*shape, 3), elements=st.floats(-np.pi, np.pi)))
    singular = st.sampled_from([0.0, np.pi] if proper else [0.5 * np.pi, -0.5 * np.pi])
    offset = st.sampled_from([0.0, 0.25, 0.5, 0.99, 1.0, 1.01, 2.0, 4.0, 1e3, 1e8])
    middles = data.draw(
        arrays(
            np.float64,
            shape,
            elements=st.one_of(
                st.tuples(singular, offset, st.sampled_from([1.0, -1.0])).map(
                    lambda t: t[0] + t[2] * t[1] * GIMBAL_LOCK_TOLERANCE
                ),
                st.floats(-np.pi, np.pi),
            ),
        )
    )
    angles[..., 1] = middles
    with numpy_only():
        R = eulerlib.euler_to_matrix(angles, seq)
    noise = data.draw(st.sampled_from([0.0, 0.0, 1e-15, 1e-9, 1e-3]))
    if noise:
        R = R + noise * data.draw(arrays(np.float64, R.shape, elements=st.floats(-1, 1)))
    return R


@settings(max_examples=examples(400), deadline=None)
@given(shape=shapes, data=st.data(), seq=sequences, degrees=st.booleans())
def test_euler_to_matrix(shape, data, seq, degrees) -> None:
    angles = data.draw(arrays(np.float64, (*shape, 3), elements=angle_values))
    assert_same_outcome(eulerlib.euler_to_matrix, angles, seq, degrees=degrees)


@settings(max_examples=examples(400), deadline=None)
@given(
    shape=shapes,
    data=st.data(),
    seq=sequences,
    degrees=st.booleans(),
    validate=st.booleans(),
    repair=st.booleans(),
    atol=st.sampled_from([1e-9, 1e-6, 0.0, 0.1]),
    warn=st.booleans(),
)
def test_matrix_to_euler(shape, data, seq, degrees, validate, repair, atol, warn) -> None:
    R = matrices_near_lock(data, shape, seq)
    assert_same_outcome(
        eulerlib.matrix_to_euler,
        R,
        seq,
        degrees=degrees,
        validate=validate,
        repair=repair,
        atol=atol,
        warn=warn,
    )


@settings(max_examples=examples(200), deadline=None)
@given(shape=shapes, data=st.data(), seq=sequences, degrees=st.booleans())
def test_matrix_to_euler_of_any_numbers(shape, data, seq, degrees) -> None:
    """Not rotations, without the check: entries of every scale, up to where squares
    overflow."""
    scaled = st.one_of(
        st.floats(-2.0, 2.0), st.floats(-1e200, 1e200), st.sampled_from([0.0, -0.0, 1e155])
    )
    R = data.draw(arrays(np.float64, (*shape, 3, 3), elements=scaled))
    assert_same_outcome(eulerlib.matrix_to_euler, R, seq, degrees=degrees, validate=False)


@pytest.mark.parametrize("seq", SEQUENCES)
@pytest.mark.parametrize("degrees", [False, True])
def test_every_sequence_at_and_near_lock(seq, degrees) -> None:
    convention = eulerlib.get_convention(seq)
    middle = 0.0 if convention.parsed.proper else 90.0
    steps = np.array([0.0, 0.5, 1.0, 2.0, 1e6]) * np.degrees(GIMBAL_LOCK_TOLERANCE)
    angles = np.array([[30.0, middle + step, -70.0] for step in [*steps, *(-steps)]])
    angles = angles if degrees else np.radians(angles)
    assert_same_outcome(eulerlib.euler_to_matrix, angles, seq, degrees=degrees)
    with numpy_only():
        R = eulerlib.euler_to_matrix(angles, seq, degrees=degrees)
    for warn in (True, False):
        for matrices in (R, R[1:2], R[-1], R[2:]):
            assert_same_outcome(eulerlib.matrix_to_euler, matrices, seq, degrees=degrees, warn=warn)
        assert_same_outcome(eulerlib.convert_angles, angles, seq, "ZYX", degrees=degrees)
        assert_same_outcome(eulerlib.convert_angles, angles, "XYZ", seq, degrees=degrees, warn=warn)


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_refuses_alike(bad) -> None:
    angles = np.array([[0.1, 0.2, 0.3], [0.5, bad, 0.5]])
    for degrees in (False, True):
        assert_same_outcome(eulerlib.euler_to_matrix, angles, "zxz", degrees=degrees)
        assert_same_outcome(eulerlib.convert_angles, angles, "zxz", "rose", degrees=degrees)
        assert_same_outcome(eulerlib.euler_to_quaternion, angles, "YZX", degrees=degrees)
    R = np.stack([np.eye(3), np.eye(3)])
    R[1, 2, 0] = bad
    assert_same_outcome(eulerlib.matrix_to_euler, R)
    assert_same_outcome(eulerlib.matrix_to_euler, R, validate=False)
    q = np.array([[0.0, 0.0, 0.0, 1.0], [0.5, bad, 0.5, 0.5]])
    assert_same_outcome(eulerlib.quaternion_to_euler, q, "xyx")
    assert_same_outcome(eulerlib.quaternion_to_euler, np.zeros((2, 4)), "xyx")


def test_other_forms_and_wrong_arguments_take_the_same_paths() -> None:
    R = eulerlib.euler_to_matrix([0.1, 0.2, 0.3])
    for arguments in [
        ((R,), {"seq": "nope"}),
        ((R,), {"degrees": 1}),
        ((R,), {"atol": -1.0}),
        ((R,), {"repair": True}),
        ((R.astype(np.float32),), {}),
        ((np.asfortranarray(np.stack([R, R]).T),), {}),
        ((R.tolist(),), {}),
        ((np.diag([1.0, 1.0, -1.0]),), {}),
        ((np.zeros((0, 3, 3)),), {}),
    ]:
        args, kwargs = arguments
        assert_same_outcome(eulerlib.matrix_to_euler, *args, **kwargs)
    read_only = np.array([0.1, 0.2, 0.3])
    read_only.flags.writeable = False
    for angles in ([1, 2, 3], read_only, np.zeros((0, 3)), np.zeros((2, 4))):
        assert_same_outcome(eulerlib.euler_to_matrix, angles, "xyz", degrees=True)
        assert_same_outcome(eulerlib.euler_to_quaternion, angles, "xyz", degrees=True)


@settings(max_examples=examples(300), deadline=None)
@given(
    shape=shapes,
    data=st.data(),
    source=sequences,
    target=sequences,
    degrees=st.booleans(),
    warn=st.booleans(),
    relabel=st.booleans(),
)
def test_convert_angles(shape, data, source, target, degrees, warn, relabel) -> None:
    angles = data.draw(arrays(np.float64, (*shape, 3), elements=angle_values))
    if data.draw(st.booleans()):  # the middle angle at a singular value of the target
        angles[..., 1] = data.draw(st.sampled_from([0.0, 90.0, -90.0, 180.0]))
    assert_same_outcome(
        eulerlib.convert_angles,
        angles,
        source,
        target,
        degrees=degrees,
        warn=warn,
        relabel=relabel,
    )


@settings(max_examples=examples(300), deadline=None)
@given(shape=shapes, data=st.data(), seq=sequences, degrees=st.booleans(), first=st.booleans())
def test_euler_to_quaternion(shape, data, seq, degrees, first) -> None:
    angles = data.draw(arrays(np.float64, (*shape, 3), elements=angle_values))
    assert_same_outcome(
        eulerlib.euler_to_quaternion, angles, seq, degrees=degrees, scalar_first=first
    )


@settings(max_examples=examples(300), deadline=None)
@given(
    shape=shapes,
    data=st.data(),
    seq=sequences,
    degrees=st.booleans(),
    first=st.booleans(),
    warn=st.booleans(),
)
def test_quaternion_to_euler(shape, data, seq, degrees, first, warn) -> None:
    if data.draw(st.booleans()):  # quaternions of rotations at, near and away from lock
        R = matrices_near_lock(data, shape, seq)
        with numpy_only():
            q = eulerlib.matrix_to_quaternion(R, repair=True) if R.size else np.zeros((0, 4))
        q = q * data.draw(st.sampled_from([1.0, -1.0, 1e-200, 1e200, 3.0]))
    else:
        scaled = st.one_of(
            st.floats(-2.0, 2.0),
            st.floats(-1e-160, 1e-160),
            st.floats(-1e160, 1e160),
            st.sampled_from([0.0, -0.0, 1.0, -1.0, 5e-324, 1.7e308]),
        )
        q = data.draw(arrays(np.float64, (*shape, 4), elements=scaled))
    assert_same_outcome(
        eulerlib.quaternion_to_euler, q, seq, degrees=degrees, scalar_first=first, warn=warn
    )


@pytest.mark.parametrize("seq", SEQUENCES)
def test_many_random_rotations(seq) -> None:
    """A thousand rotations at once, so that a change of rounding anywhere shows."""
    rng = np.random.default_rng(sum(map(ord, str(seq))))
    radians = rng.uniform(-4.0, 4.0, (1000, 3))
    degrees = rng.uniform(-720.0, 720.0, (1000, 3))
    assert_same_outcome(eulerlib.euler_to_matrix, radians, seq)
    assert_same_outcome(eulerlib.euler_to_matrix, degrees, seq, degrees=True)
    assert_same_outcome(eulerlib.euler_to_quaternion, degrees, seq, degrees=True)
    assert_same_outcome(eulerlib.convert_angles, radians, seq, "zxz")
    assert_same_outcome(eulerlib.convert_angles, degrees, "baker", seq, degrees=True)
    with numpy_only():
        R = eulerlib.euler_to_matrix(radians, seq)
        q = eulerlib.euler_to_quaternion(radians, seq)
    assert_same_outcome(eulerlib.matrix_to_euler, R, seq)
    assert_same_outcome(eulerlib.matrix_to_euler, R, seq, degrees=True, validate=False)
    assert_same_outcome(eulerlib.quaternion_to_euler, 3.0 * q, seq, degrees=True)


def named_angles(function, *args, **kwargs):
    """The named tuple of a function of named angles as a tuple of arrays, for comparing."""
    return tuple(function(*args, **kwargs))


@settings(max_examples=examples(200), deadline=None)
@given(shape=shapes, data=st.data(), degrees=st.booleans(), warn=st.booleans())
def test_named_angles(shape, data, degrees, warn) -> None:
    angles = data.draw(arrays(np.float64, (*shape, 3), elements=angle_values))
    a, b, c = angles[..., 0], angles[..., 1], angles[..., 2]
    for to_matrix, to_angles, seq in [
        (eulerlib.yaw_pitch_roll_to_matrix, eulerlib.matrix_to_yaw_pitch_roll, "rose"),
        (
            eulerlib.heading_attitude_bank_to_matrix,
            eulerlib.matrix_to_heading_attitude_bank,
            "baker",
        ),
    ]:
        assert_same_outcome(to_matrix, a, b, c, degrees=degrees)
        assert_same_outcome(to_matrix, a, 0.5, c, degrees=degrees)
        R = matrices_near_lock(data, shape, seq)
        assert_same_outcome(named_angles, to_angles, R, degrees=degrees, warn=warn)


@pytest.mark.parametrize("trouble", ["none", "lock", "nan"])
def test_batches_of_several_blocks(trouble) -> None:
    """More rotations than one block of the array path (16384), with a lock or a NaN in the
    last block, which sends the whole call to the array path."""
    rng = np.random.default_rng(7)
    angles = rng.uniform(-3.0, 3.0, (2, 10000, 3))
    with numpy_only():
        R = eulerlib.euler_to_matrix(angles, "zyx")
        q = eulerlib.euler_to_quaternion(angles, "zyx")
    if trouble == "lock":
        angles[1, -1, 1] = 0.5 * np.pi
        R[1, -1] = np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]])
        q[1, -1] = [0.0, np.sqrt(0.5), 0.0, np.sqrt(0.5)]
    elif trouble == "nan":
        angles[1, -1, 2] = R[1, -1, 2, 2] = q[1, -1, 0] = np.nan
    assert_same_outcome(eulerlib.euler_to_matrix, angles, "zyx")
    assert_same_outcome(eulerlib.euler_to_quaternion, angles, "zyx", degrees=True)
    assert_same_outcome(eulerlib.convert_angles, angles, "xyz", "rose")
    assert_same_outcome(eulerlib.matrix_to_euler, R, "zyx")
    assert_same_outcome(eulerlib.quaternion_to_euler, q, "zyx")


@settings(max_examples=examples(300), deadline=None)
@given(
    shape=st.sampled_from([(), (1,), (3,), (2, 3), (17,)]),
    data=st.data(),
    axis=st.sampled_from(["x", "y", "z", 0, 1, 2]),
    degrees=st.booleans(),
)
def test_elementary_rotations(shape, data, axis, degrees) -> None:
    angle = data.draw(arrays(np.float64, shape, elements=angle_values))
    assert_same_outcome(eulerlib.elementary_rotation, axis, angle, degrees=degrees)
    for function in (eulerlib.rot_x, eulerlib.rot_y, eulerlib.rot_z):
        assert_same_outcome(function, angle, degrees=degrees)


def test_elementary_rotations_of_many_angles_and_bad_ones() -> None:
    rng = np.random.default_rng(3)
    angles = np.concatenate([rng.uniform(-720.0, 720.0, 20000), np.arange(-720.0, 721.0, 45)])
    for degrees in (False, True):
        assert_same_outcome(eulerlib.rot_y, angles, degrees=degrees)
        assert_same_outcome(eulerlib.rot_z, np.array([0.0, np.nan]), degrees=degrees)
        assert_same_outcome(eulerlib.rot_x, np.array(np.inf), degrees=degrees)


def test_named_angles_refused_alike() -> None:
    good, bad = np.array([0.1, 0.2]), np.array([0.3, np.nan])
    for to_matrix in (eulerlib.yaw_pitch_roll_to_matrix, eulerlib.heading_attitude_bank_to_matrix):
        assert_same_outcome(to_matrix, good, bad, good)
        assert_same_outcome(to_matrix, good, good, np.array([0.1, 0.2, 0.3]))
        assert_same_outcome(to_matrix, good, good.astype(np.float32), good, degrees=True)
        assert_same_outcome(to_matrix, good, good, good, degrees=1)
