"""Rose (2015), eq 8: which product is "A, then B"?

Code sample 6 computes ``C = A B`` (tested in ``test_papers.py``). The nine formulas printed
under eq 8 pair the factors the other way round; typed in here term by term, they must equal
``B A``, which is what ``compose(B, A)`` and SciPy's ``Rotation`` give, and must differ from
``A B`` for rotations about different axes. The two readings of "A, then B" are checked
against SciPy: about the moving axes it is ``A B``, about the fixed axes it is ``B A``.
"""

import numpy as np
from numpy.testing import assert_allclose
from scipy.spatial.transform import Rotation

from eulerlib import compose, rot_x, rot_y, rot_z, rotate_points


def listing_under_eq8(A, B):
    """The element-wise expansion printed under eq 8, typed in as printed (1-based keys)."""
    a = {(i + 1, j + 1): A[..., i, j] for i in range(3) for j in range(3)}
    b = {(i + 1, j + 1): B[..., i, j] for i in range(3) for j in range(3)}
    c11 = b[1, 1] * a[1, 1] + b[1, 2] * a[2, 1] + b[1, 3] * a[3, 1]
    c12 = b[1, 1] * a[1, 2] + b[1, 2] * a[2, 2] + b[1, 3] * a[3, 2]
    c13 = b[1, 1] * a[1, 3] + b[1, 2] * a[2, 3] + b[1, 3] * a[3, 3]
    c21 = b[2, 1] * a[1, 1] + b[2, 2] * a[2, 1] + b[2, 3] * a[3, 1]
    c22 = b[2, 1] * a[1, 2] + b[2, 2] * a[2, 2] + b[2, 3] * a[3, 2]
    c23 = b[2, 1] * a[1, 3] + b[2, 2] * a[2, 3] + b[2, 3] * a[3, 3]
    c31 = b[3, 1] * a[1, 1] + b[3, 2] * a[2, 1] + b[3, 3] * a[3, 1]
    c32 = b[3, 1] * a[1, 2] + b[3, 2] * a[2, 2] + b[3, 3] * a[3, 2]
    c33 = b[3, 1] * a[1, 3] + b[3, 2] * a[2, 3] + b[3, 3] * a[3, 3]
    rows = [[c11, c12, c13], [c21, c22, c23], [c31, c32, c33]]
    return np.stack([np.stack(row, axis=-1) for row in rows], axis=-2)


def test_listing_under_eq8_is_b_times_a():
    rA = Rotation.random(200, random_state=8)
    rB = Rotation.random(200, random_state=88)
    A, B = rA.as_matrix(), rB.as_matrix()
    C = listing_under_eq8(A, B)
    assert_allclose(C, (rB * rA).as_matrix(), rtol=0, atol=2e-15)
    assert_allclose(C, compose(B, A), rtol=0, atol=2e-15)
    # ... and not A B: the two orders differ by a lot for general rotations
    assert np.all(np.abs(C - compose(A, B)).max(axis=(-2, -1)) > 1e-3)


def test_listing_and_code_sample_6_agree_only_when_rotations_commute():
    yaw, pitch = rot_z(90, degrees=True), rot_y(30, degrees=True)
    assert np.abs(listing_under_eq8(yaw, pitch) - compose(yaw, pitch)).max() > 0.4
    # rotations about one axis commute, which is why a one-axis test never finds the mix-up
    other_yaw = rot_z(30, degrees=True)
    assert_allclose(listing_under_eq8(yaw, other_yaw), compose(yaw, other_yaw), atol=1e-15)


def test_then_about_moving_axes_is_a_times_b():
    """B about the axes that A has turned is, in world axes, B's angle about A times B's axis."""
    rA = Rotation.random(50, random_state=1)
    rB = Rotation.random(50, random_state=2)
    A = rA.as_matrix()
    moved_axis_rotvec = np.einsum("nij,nj->ni", A, rB.as_rotvec())
    B_in_world = Rotation.from_rotvec(moved_axis_rotvec).as_matrix()
    assert_allclose(B_in_world @ A, compose(A, rB.as_matrix()), atol=1e-14)


def test_then_about_fixed_axes_is_b_times_a():
    A, B = rot_x(40, degrees=True), rot_z(-75, degrees=True)
    points = np.random.default_rng(8).normal(size=(20, 3))
    step_by_step = rotate_points(B, rotate_points(A, points))
    assert_allclose(step_by_step, rotate_points(compose(B, A), points), atol=1e-15)
    assert_allclose(
        step_by_step,
        Rotation.from_matrix(B).apply(Rotation.from_matrix(A).apply(points)),
        atol=1e-15,
    )
    assert np.abs(step_by_step - rotate_points(compose(A, B), points)).max() > 0.1
