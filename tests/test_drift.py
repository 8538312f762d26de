"""Matrices that are rotations only within ``atol``, and products that drift.

The rotation check accepts a matrix whose ``R Rᵀ`` is within ``atol`` (1e-6 by default) of the
identity: one that went through single precision, or a few hundred products. What comes out of
such a matrix must still be exact where the result has a rule of its own: a quaternion has
length 1. And a long chain of products, each accepted, must have a documented way to stay a
rotation. The oracles are SciPy's ``Rotation`` (whose ``from_matrix`` takes the nearest
rotation of a matrix that is not orthogonal) and the definition of orthogonality typed in.
"""

from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.spatial.transform import Rotation

from eulerlib import ROTATION_ATOL, compose, is_rotation_matrix, matrix_to_quaternion

EPS = np.finfo(np.float64).eps


def orthonormality_error(R: np.ndarray) -> np.ndarray:
    return np.abs(R @ np.swapaxes(R, -1, -2) - np.eye(3)).max(axis=(-2, -1))


def at_the_edge(rng: np.random.Generator, count: int, fraction: float) -> np.ndarray:
    """Rotations disturbed until ``max |R Rᵀ − I|`` is about ``fraction`` of the default atol
    (the determinant then differs from 1 by up to about 1.5 times as much)."""
    R = Rotation.random(count, rng=rng).as_matrix()
    noise = rng.normal(size=(count, 3, 3))
    noise /= orthonormality_error(np.eye(3) + noise * 1e-9)[:, None, None] / 1e-9
    M = R + noise * fraction * ROTATION_ATOL @ R  # first order: error ≈ fraction · atol
    assert (orthonormality_error(M) <= ROTATION_ATOL).all()
    assert (np.abs(np.linalg.det(M) - 1.0) <= ROTATION_ATOL).all()
    return M


@pytest.mark.parametrize("fraction", [0.1, 0.4, 0.6])
def test_quaternions_of_matrices_accepted_at_the_edge_are_unit(rng, fraction: float) -> None:
    M = at_the_edge(rng, 2000, fraction)
    for layout in (False, True):
        q = matrix_to_quaternion(M, scalar_first=layout)
        assert np.abs(np.linalg.norm(q, axis=-1) - 1.0).max() <= 4 * EPS
        # the rotation is that of the nearest rotation, to about the tolerance
        nearest = Rotation.from_matrix(M).as_quat(canonical=True, scalar_first=layout)
        assert_allclose(q, nearest, atol=4 * fraction * ROTATION_ATOL)


def test_quaternions_of_exact_rotations_are_unchanged(rng) -> None:
    R = Rotation.random(2000, rng=rng)
    q = matrix_to_quaternion(R.as_matrix())
    assert_allclose(q, R.as_quat(canonical=True), rtol=0, atol=4 * EPS)
    assert np.abs(np.linalg.norm(q, axis=-1) - 1.0).max() <= 2 * EPS


def test_a_long_product_drifts_and_repair_keeps_it_a_rotation(rng) -> None:
    step = at_the_edge(rng, 1, 0.5)[0]
    exact = Rotation.from_matrix(step)  # SciPy's nearest rotation of the step
    C = np.eye(3)
    with pytest.raises(ValueError, match=r"^rotation 1 (is not a rotation|has determinant)"):
        for _ in range(1000):  # each factor is accepted, but the errors add up
            C = compose(C, step)
    C = np.eye(3)
    for _ in range(1000):
        C = compose(C, step, repair=True)
    assert orthonormality_error(C) <= 8 * EPS
    assert bool(is_rotation_matrix(C, atol=8 * EPS))  # the determinant to the same bound
    assert_allclose(C, (exact**1000).as_matrix(), atol=1e-11)
