"""Properties that must hold for every input: hypothesis looks for a counterexample.

Angles are drawn from the whole circle and, on purpose, from the singular values (0, ±π/2, ±π)
and from 1e-16 … 1e-1 rad around them, where gimbal lock lives.
"""

import numpy as np
from budget import examples
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp
from numpy.testing import assert_allclose, assert_array_equal
from scipy.spatial.transform import Rotation

from eulerlib import (
    ALL_SEQUENCES,
    compose,
    euler_to_matrix,
    invert,
    matrix_to_euler,
    rotate_points,
)

SINGULAR = (0.0, np.pi / 2, -np.pi / 2, np.pi, -np.pi)

near_singular = st.builds(
    lambda base, sign, exponent: base + sign * 10.0**exponent,
    st.sampled_from(SINGULAR),
    st.sampled_from([-1.0, 1.0]),
    st.integers(-16, -1),
)
angle = st.one_of(
    st.floats(-np.pi, np.pi, allow_nan=False),
    st.sampled_from(SINGULAR),
    near_singular,
)
angle_batches = hnp.arrays(np.float64, st.tuples(st.integers(1, 6), st.just(3)), elements=angle)
sequences = st.sampled_from(ALL_SEQUENCES)
intrinsic_sequences = st.sampled_from([s for s in ALL_SEQUENCES if s.isupper()])


@st.composite
def rotations(draw, count=None):
    """Rotation matrices from SciPy, through random quaternions (an independent path)."""
    count = draw(st.integers(1, 5)) if count is None else count
    quaternions = draw(
        hnp.arrays(np.float64, (count, 4), elements=st.floats(-1, 1, allow_nan=False))
    )
    quaternions[np.linalg.norm(quaternions, axis=-1) < 1e-3] = [0.0, 0.0, 0.0, 1.0]
    return Rotation.from_quat(quaternions).as_matrix()


checked = settings(max_examples=examples(150), deadline=None)


@checked
@given(angle_batches, sequences)
def test_round_trip_angles_matrix_angles_matrix(angles, seq):
    R = euler_to_matrix(angles, seq)
    back = matrix_to_euler(R, seq, warn=False)
    assert_allclose(euler_to_matrix(back, seq), R, rtol=0, atol=1e-14)
    # the angles come back themselves when they are in range and well away from lock
    proper = seq[0].lower() == seq[2].lower()
    middle = angles[:, 1]
    if proper:
        unique = (middle > 1e-3) & (middle < np.pi - 1e-3)
    else:
        unique = np.abs(middle) < np.pi / 2 - 1e-3
    difference = (back - angles + np.pi) % (2 * np.pi) - np.pi
    assert_allclose(difference[unique], 0.0, rtol=0, atol=1e-11)


@checked
@given(rotations(), sequences)
def test_round_trip_matrix_angles_matrix(R, seq):
    angles = matrix_to_euler(R, seq, warn=False)
    assert_allclose(euler_to_matrix(angles, seq), R, rtol=0, atol=1e-14)


@checked
@given(angle_batches, intrinsic_sequences)
def test_intrinsic_is_extrinsic_reversed_bitwise(angles, seq):
    extrinsic = seq[::-1].lower()
    R = euler_to_matrix(angles, seq)
    assert_array_equal(R, euler_to_matrix(angles[:, ::-1], extrinsic))
    assert_array_equal(
        matrix_to_euler(R, seq, warn=False), matrix_to_euler(R, extrinsic, warn=False)[:, ::-1]
    )


@checked
@given(rotations(), intrinsic_sequences)
def test_intrinsic_is_extrinsic_reversed_for_any_matrix(R, seq):
    extrinsic = seq[::-1].lower()
    assert_array_equal(
        matrix_to_euler(R, seq, warn=False), matrix_to_euler(R, extrinsic, warn=False)[:, ::-1]
    )


@checked
@given(rotations())
def test_inverse(R):
    identity = np.broadcast_to(np.eye(3), R.shape)
    # SciPy's matrices are orthogonal to a few ulps, so I is reached to a few ulps
    assert_allclose(invert(R) @ R, identity, rtol=0, atol=5e-15)
    assert_allclose(R @ invert(R), identity, rtol=0, atol=5e-15)
    assert_array_equal(invert(R), np.swapaxes(R, -1, -2))
    assert_allclose(invert(R), Rotation.from_matrix(R).inv().as_matrix(), rtol=0, atol=1e-15)


def typed_product(A, B):
    """``A B`` entry by entry, ``(a_i0 b_0j + a_i1 b_1j) + a_i2 b_2j`` with no negative zeros:
    the order compose promises on every machine (a BLAS ``@`` may add in another order)."""
    C = np.empty(np.broadcast_shapes(A.shape, B.shape))
    for i in range(3):
        for j in range(3):
            total = A[..., i, 0] * B[..., 0, j] + A[..., i, 1] * B[..., 1, j]
            C[..., i, j] = (total + A[..., i, 2] * B[..., 2, j]) + 0.0
    return C


@checked
@given(rotations(3), rotations(3), rotations(3))
def test_composition(A, B, C):
    assert_array_equal(compose(A, B), typed_product(A, B))
    assert_allclose(compose(A, B), A @ B, rtol=0, atol=1e-15)
    assert_allclose(compose(compose(A, B), C), compose(A, compose(B, C)), rtol=0, atol=2e-15)
    assert_allclose(compose(A, B, C), A @ B @ C, rtol=0, atol=2e-15)
    scipy_product = (Rotation.from_matrix(A) * Rotation.from_matrix(B)).as_matrix()
    assert_allclose(compose(A, B), scipy_product, rtol=0, atol=1e-14)


@checked
@given(angle_batches, angle_batches, intrinsic_sequences)
def test_composition_of_euler_rotations(a, b, seq):
    """Moving axes: A then B about the moved axes is A @ B; fixed axes: B then A is A @ B."""
    n = min(len(a), len(b))
    A, B = euler_to_matrix(a[:n], seq), euler_to_matrix(b[:n], seq)
    moving = Rotation.from_euler(seq, a[:n]) * Rotation.from_euler(seq, b[:n])
    assert_allclose(compose(A, B), moving.as_matrix(), rtol=0, atol=1e-14)


@checked
@given(
    rotations(),
    hnp.arrays(np.float64, (5, 3), elements=st.floats(-1e3, 1e3, allow_nan=False)),
)
def test_rotate_points_is_rose_eq6(R, points):
    for matrix in R:
        x0, y0, z0 = points[:, 0], points[:, 1], points[:, 2]
        (r11, r12, r13), (r21, r22, r23), (r31, r32, r33) = matrix
        x1 = r11 * x0 + r12 * y0 + r13 * z0
        y1 = r21 * x0 + r22 * y0 + r23 * z0
        z1 = r31 * x0 + r32 * y0 + r33 * z0
        expected = np.stack([x1, y1, z1], axis=-1)
        assert_allclose(rotate_points(matrix, points), expected, rtol=0, atol=1e-12)
    assert_allclose(
        rotate_points(R[:, np.newaxis], points),
        Rotation.from_matrix(R[:, np.newaxis].repeat(5, 1).reshape(-1, 3, 3))
        .apply(np.tile(points, (len(R), 1)))
        .reshape(len(R), 5, 3),
        rtol=0,
        atol=1e-11,
    )


@checked
@given(rotations(), hnp.arrays(np.float64, 3, elements=st.floats(-10, 10, allow_nan=False)))
def test_rotation_keeps_lengths_and_angles(R, point):
    rotated = rotate_points(R, point)
    assert_allclose(np.linalg.norm(rotated, axis=-1), np.linalg.norm(point), rtol=1e-14, atol=1e-14)
    assert_allclose(
        rotate_points(invert(R), rotated), np.broadcast_to(point, (len(R), 3)), atol=1e-13
    )


@checked
@given(
    hnp.arrays(np.float64, (4, 3), elements=st.floats(-360, 360, allow_nan=False)),
    sequences,
)
def test_degrees_and_radians_agree(degrees, seq):
    assert_allclose(
        euler_to_matrix(degrees, seq, degrees=True),
        euler_to_matrix(np.radians(degrees), seq),
        rtol=0,
        atol=4e-15,
    )
    R = euler_to_matrix(degrees, seq, degrees=True)
    assert_allclose(
        matrix_to_euler(R, seq, degrees=True, warn=False),
        np.degrees(matrix_to_euler(R, seq, warn=False)),
        rtol=1e-15,
        atol=0,
    )
