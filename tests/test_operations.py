"""Rotating points, inverting, composing and testing matrices (Rose 2015, eq 5–8)."""

import numpy as np
import pytest
from numpy.testing import assert_allclose, assert_array_equal
from scipy.spatial.transform import Rotation

from eulerlib import (
    compose,
    euler_to_matrix,
    invert,
    is_rotation_matrix,
    rot_x,
    rot_y,
    rot_z,
    rotate_points,
)


def typed_product(A, B):
    """``A B`` typed in entry by entry, ``c_ij = (a_i0 b_0j + a_i1 b_1j) + a_i2 b_2j``, with no
    negative zeros: the order of additions compose promises on every machine (a BLAS ``@``
    may add in another order or fuse a multiply with an add)."""
    A, B = np.broadcast_arrays(np.asarray(A), np.asarray(B))
    C = np.empty(A.shape)
    for i in range(3):
        for j in range(3):
            C[..., i, j] = (
                (A[..., i, 0] * B[..., 0, j] + A[..., i, 1] * B[..., 1, j])
                + A[..., i, 2] * B[..., 2, j]
                + 0.0
            )
    return C


@pytest.fixture
def matrices(rng):
    return Rotation.random(4, rng=rng).as_matrix()


# --- rotate_points ---------------------------------------------------------------------------


def test_rotate_points_against_scipy_apply(rng, matrices):
    points = rng.normal(size=(4, 3))
    expected = Rotation.from_matrix(matrices).apply(points)
    assert_allclose(rotate_points(matrices, points), expected, rtol=0, atol=1e-15)


@pytest.mark.parametrize(
    ("matrix_shape", "point_shape", "result_shape"),
    [
        ((3, 3), (3,), (3,)),  # one matrix, one point
        ((3, 3), (7, 3), (7, 3)),  # one matrix, many points
        ((4, 3, 3), (3,), (4, 3)),  # many matrices, one point
        ((4, 3, 3), (4, 3), (4, 3)),  # one point per matrix
        ((4, 1, 3, 3), (5, 3), (4, 5, 3)),  # every matrix on every point
        ((2, 3, 3), (6, 1, 3), (6, 2, 3)),
    ],
)
def test_rotate_points_broadcasting(rng, matrix_shape, point_shape, result_shape):
    R = Rotation.random(int(np.prod(matrix_shape[:-2])), rng=rng).as_matrix()
    R = R.reshape(matrix_shape)
    points = rng.normal(size=point_shape)
    rotated = rotate_points(R, points)
    assert rotated.shape == result_shape
    # one by one, with the matrix-vector product written as a sum
    R_b = np.broadcast_to(R, (*result_shape[:-1], 3, 3))
    p_b = np.broadcast_to(points, result_shape)
    expected = np.einsum("...ij,...j->...i", R_b, p_b)
    assert_allclose(rotated, expected, rtol=0, atol=1e-15)


def test_rotate_points_quarter_turns():
    points = np.eye(3)
    assert_allclose(
        rotate_points(rot_z(np.pi / 2), points), [[0, 1, 0], [-1, 0, 0], [0, 0, 1]], atol=1e-16
    )
    assert_array_equal(rotate_points(rot_x(90, degrees=True), [0, 1, 0]), [0.0, 0.0, 1.0])


def test_rotate_points_does_not_broadcast(matrices):
    with pytest.raises(ValueError, match=r"shape \(4, 3, 3\).*shape \(5, 3\) do not broadcast"):
        rotate_points(matrices, np.zeros((5, 3)))


def test_rotate_points_checks_the_matrix():
    with pytest.raises(ValueError, match="not a rotation matrix"):
        rotate_points(2 * np.eye(3), [1.0, 0.0, 0.0])
    assert_array_equal(rotate_points(2 * np.eye(3), [1.0, 0.0, 0.0], validate=False), [2.0, 0, 0])


# --- invert ----------------------------------------------------------------------------------


def test_invert(matrices):
    inverse = invert(matrices)
    assert_array_equal(inverse, np.swapaxes(matrices, -1, -2))
    assert_allclose(inverse, Rotation.from_matrix(matrices).inv().as_matrix(), atol=1e-15)
    assert not np.shares_memory(inverse, matrices)
    assert invert(matrices[0]).shape == (3, 3)


def test_invert_undoes_a_rotation(rng, matrices):
    points = rng.normal(size=(4, 3))
    back = rotate_points(invert(matrices), rotate_points(matrices, points))
    assert_allclose(back, points, rtol=0, atol=1e-14)


# --- compose ---------------------------------------------------------------------------------


def test_compose_is_the_left_to_right_product(matrices):
    A, B, C, D = matrices
    assert_array_equal(compose(A, B), typed_product(A, B))
    assert_array_equal(compose(matrices, B), typed_product(matrices, B))
    assert_array_equal(compose(A, B, C, D), typed_product(typed_product(typed_product(A, B), C), D))
    assert_allclose(compose(A, B, C, D), A @ B @ C @ D, rtol=0, atol=1e-15)
    assert_allclose(
        compose(A, B), (Rotation.from_matrix(A) * Rotation.from_matrix(B)).as_matrix(), atol=2e-15
    )


def test_compose_order_for_moving_and_fixed_axes():
    yaw, pitch, roll = 0.3, -1.1, 2.0
    # moving axes: yaw first, then pitch about the new y, then roll about the newest x
    moving = compose(rot_z(yaw), rot_y(pitch), rot_x(roll))
    assert_allclose(moving, Rotation.from_euler("ZYX", [yaw, pitch, roll]).as_matrix(), atol=1e-15)
    # fixed axes: the rightmost factor acts first
    fixed = compose(rot_z(yaw), rot_y(pitch), rot_x(roll))
    assert_allclose(fixed, Rotation.from_euler("xyz", [roll, pitch, yaw]).as_matrix(), atol=1e-15)
    v = np.array([0.2, -0.5, 0.9])
    assert_allclose(fixed @ v, rot_z(yaw) @ (rot_y(pitch) @ (rot_x(roll) @ v)), atol=1e-15)
    # and it is not commutative
    assert np.abs(compose(rot_x(roll), rot_z(yaw)) - compose(rot_z(yaw), rot_x(roll))).max() > 0.1


def test_compose_broadcasts(matrices):
    stack = matrices.reshape(2, 2, 3, 3)
    product = compose(stack, matrices[0])
    assert product.shape == (2, 2, 3, 3)
    assert_array_equal(product, typed_product(stack, matrices[0]))
    assert compose(stack[:, :1], matrices[:2]).shape == (2, 2, 3, 3)
    assert_array_equal(
        compose(stack[:, :1], matrices[:2]), typed_product(stack[:, :1], matrices[:2])
    )
    with pytest.raises(ValueError, match=r"do not broadcast.*\(4, 3, 3\).*\(3, 3, 3\)"):
        compose(matrices, matrices[:3])


def test_compose_of_one_is_a_copy(matrices):
    single = compose(matrices)
    assert_array_equal(single, matrices)
    assert not np.shares_memory(single, matrices)


def test_compose_needs_a_rotation():
    with pytest.raises(TypeError, match="at least one rotation"):
        compose()


def test_compose_names_the_bad_argument():
    with pytest.raises(ValueError, match="rotation 2"):
        compose(np.eye(3), np.diag([1.0, 1.0, -1.0]))


def test_compose_matches_euler_angles(rng):
    angles = rng.uniform(-np.pi, np.pi, (10, 3))
    product = compose(rot_z(angles[:, 0]), rot_x(angles[:, 1]), rot_z(angles[:, 2]))
    assert_allclose(product, euler_to_matrix(angles, "ZXZ"), rtol=0, atol=2e-15)


# --- is_rotation_matrix ----------------------------------------------------------------------


def test_is_rotation_matrix_single_is_a_0d_array(matrices):
    def answer(R):
        result = is_rotation_matrix(R)
        assert isinstance(result, np.ndarray) and result.shape == () and result.dtype == bool
        return bool(result)

    assert answer(matrices[0]) is True
    assert answer(-np.eye(3)) is False  # a point reflection, det −1
    assert answer(np.diag([1.0, -1.0, 1.0])) is False
    assert answer(2 * np.eye(3)) is False
    assert answer(np.eye(3).tolist()) is True
    assert answer(np.eye(3, dtype=int)) is True


def test_is_rotation_matrix_batch(matrices):
    bad = matrices.copy()
    bad[1, 0, 0] += 1e-3  # not orthogonal
    bad[2] = -bad[2]  # a reflection
    bad[3, 1, 2] = np.nan
    assert_array_equal(is_rotation_matrix(bad), [True, False, False, False])
    assert is_rotation_matrix(matrices.reshape(2, 2, 3, 3)).shape == (2, 2)


def test_is_rotation_matrix_tolerance(matrices):
    noisy = matrices[0] + 1e-9
    assert bool(is_rotation_matrix(noisy)) is True
    assert bool(is_rotation_matrix(noisy, atol=1e-12)) is False
    assert bool(is_rotation_matrix(np.full((3, 3), np.inf))) is False


def test_is_rotation_matrix_bad_shape_and_type():
    with pytest.raises(ValueError, match=r"shape \(\.\.\., 3, 3\), got shape \(3, 4\)"):
        is_rotation_matrix(np.zeros((3, 4)))
    with pytest.raises(TypeError, match="text"):
        is_rotation_matrix("identity")
    with pytest.raises(TypeError, match="complex"):
        is_rotation_matrix(np.eye(3) + 0j)
