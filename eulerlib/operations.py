"""Using rotation matrices: rotate points, undo a rotation, chain rotations, test a matrix.

These are Rose (2015), Part 2, eq 5–8. A rotation matrix acts on a column vector from the
left (eq 5–6); its inverse is its transpose (eq 7), because its columns are orthonormal; and
rotations combine by matrix product (eq 8). All functions broadcast over leading axes.
"""

from __future__ import annotations

from functools import reduce

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._validation import (
    ROTATION_ATOL,
    as_float_array,
    as_matrices,
    as_vectors,
    determinant,
    matrix_entries,
    orthonormality_error,
)

__all__ = ["compose", "invert", "is_rotation_matrix", "rotate_points"]


def rotate_points(
    R: ArrayLike, points: ArrayLike, *, validate: bool = True, atol: float = ROTATION_ATOL
) -> NDArray[np.float64]:
    """Rotate points: ``p₁ = R p₀`` for each point (Rose 2015, eq 5–6).

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotation matrices.
    points : array_like, shape (..., 3)
        Points as rows. Leading axes broadcast against those of ``R``, so one matrix can turn
        many points and many matrices can turn one point.
    validate : bool, optional
        Check that ``R`` holds rotations (default).
    atol : float, optional
        Tolerance of that check.

    Returns
    -------
    ndarray, shape (broadcast of leading axes, 3)
        The rotated points; a single point ``(3,)`` with a single matrix gives ``(3,)``.

    Raises
    ------
    TypeError
        If an input is not numeric.
    ValueError
        If a shape is wrong, an entry is not finite, ``R`` is not a rotation, or the leading
        axes do not broadcast.

    Notes
    -----
    Eq 6 written out: ``x₁ = r₁₁x₀ + r₁₂y₀ + r₁₃z₀`` and likewise for y and z; that is the
    matrix-vector product, computed here as one ``matmul`` over all points.

    Examples
    --------
    >>> from eulerlib import rot_z
    >>> rotate_points(rot_z(90, degrees=True), [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0]])
    array([[ 0.,  1.,  0.],
           [-2.,  0.,  0.]])
    """
    matrices = as_matrices(R, "R", validate=validate, atol=atol)
    vectors = as_vectors(points, "points")
    try:
        np.broadcast_shapes(matrices.shape[:-2], vectors.shape[:-1])
    except ValueError:
        raise ValueError(
            f"R with shape {matrices.shape} and points with shape {vectors.shape} do not "
            "broadcast: their leading axes (all but the last two of R, all but the last of "
            "points) must be compatible"
        ) from None
    if matrices.ndim == 2:  # one rotation for all points: a single BLAS product, R (3, n)
        columns = vectors.reshape(-1, 3).T
        turned: NDArray[np.float64] = (matrices @ columns).T.reshape(vectors.shape)
        return turned
    rotated: NDArray[np.float64] = (matrices @ vectors[..., np.newaxis])[..., 0]
    return rotated


def invert(
    R: ArrayLike, *, validate: bool = True, atol: float = ROTATION_ATOL
) -> NDArray[np.float64]:
    """Inverse rotation, which is the transpose (Rose 2015, eq 7).

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotation matrices.
    validate : bool, optional
        Check that ``R`` holds rotations (default); the transpose is the inverse only then.
    atol : float, optional
        Tolerance of that check.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        ``Rᵀ`` for each matrix (a new array; the input is untouched).

    Examples
    --------
    >>> import numpy as np
    >>> from eulerlib import euler_to_matrix
    >>> R = euler_to_matrix([0.3, -0.2, 1.1])
    >>> np.allclose(invert(R) @ R, np.eye(3))
    True
    """
    matrices = as_matrices(R, "R", validate=validate, atol=atol)
    transposed: NDArray[np.float64] = np.swapaxes(matrices, -1, -2).copy()
    return transposed


def compose(
    *rotations: ArrayLike, validate: bool = True, atol: float = ROTATION_ATOL
) -> NDArray[np.float64]:
    """Combine rotations into one: the left-to-right product ``compose(A, B) == A @ B``.

    Which rotation happens first depends on how the axes are read (Rose 2015, eq 8):

    * **fixed axes** (extrinsic): ``A @ B`` applies ``B`` first, then ``A``, since
      ``(A @ B) @ v == A @ (B @ v)``;
    * **moving axes** (intrinsic): ``A @ B`` applies ``A`` first, then ``B`` about the axes
      that ``A`` has already turned.

    Parameters
    ----------
    *rotations : array_like, each shape (..., 3, 3)
        At least one stack of rotation matrices; leading axes broadcast.
    validate : bool, optional
        Check that every argument holds rotations (default).
    atol : float, optional
        Tolerance of that check.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        The product, in the order given.

    Raises
    ------
    TypeError
        If no rotation is given or an argument is not numeric.
    ValueError
        If a shape is wrong or an argument is not a rotation.

    Notes
    -----
    Rose's code sample 6 computes ``C = A B`` entry by entry (``c₁₂ = a₁₁b₁₂ + a₁₂b₂₂ +
    a₁₃b₃₂``). The element-wise listing printed under eq 8 in the paper pairs the factors
    the other way round (``c₁₂ = b₁₁a₁₂ + …``), which is the product ``B A``; the notebook on
    combining rotations proves it with SymPy.

    Examples
    --------
    >>> import numpy as np
    >>> from eulerlib import rot_x, rot_y, rot_z, euler_to_matrix
    >>> yaw, pitch, roll = 0.3, 0.2, 0.1
    >>> C = compose(rot_z(yaw), rot_y(pitch), rot_x(roll))
    >>> np.allclose(C, euler_to_matrix([yaw, pitch, roll], "ZYX"))
    True
    """
    if not rotations:
        raise TypeError("compose() needs at least one rotation matrix")
    matrices = [
        as_matrices(R, f"rotation {n + 1}", validate=validate, atol=atol)
        for n, R in enumerate(rotations)
    ]
    try:
        np.broadcast_shapes(*(m.shape for m in matrices))
    except ValueError:
        shapes = ", ".join(str(m.shape) for m in matrices)
        raise ValueError(f"the rotations do not broadcast together: shapes {shapes}") from None
    product: NDArray[np.float64] = reduce(np.matmul, matrices)
    return product.copy() if len(matrices) == 1 else product


def is_rotation_matrix(R: ArrayLike, *, atol: float = ROTATION_ATOL) -> bool | NDArray[np.bool_]:
    """Test whether matrices are rotations: ``R Rᵀ = I`` and ``det R = +1``, within ``atol``.

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Matrices to test.
    atol : float, optional
        Tolerance on ``max |R Rᵀ − I|`` and on ``|det R − 1|``.

    Returns
    -------
    bool or ndarray of bool, shape (...)
        A plain ``bool`` for a single matrix. Matrices with NaN or infinite entries are not
        rotations.

    Raises
    ------
    TypeError
        If ``R`` is not numeric.
    ValueError
        If ``R`` does not have shape ``(..., 3, 3)``.

    Examples
    --------
    >>> import numpy as np
    >>> is_rotation_matrix(np.eye(3))
    True
    >>> is_rotation_matrix(np.diag([1.0, 1.0, -1.0]))   # a mirror
    False
    >>> is_rotation_matrix(np.stack([np.eye(3), 2 * np.eye(3)]))
    array([ True, False])
    """
    if isinstance(R, (str, bytes)):
        raise TypeError(f"R must be numbers, got text {R!r}")
    array = np.asarray(R)
    if array.dtype.kind not in "iuf":
        as_float_array(array, "R")  # raises the TypeError with the usual words
    array = array.astype(np.float64, copy=False)
    if array.ndim < 2 or array.shape[-2:] != (3, 3):
        raise ValueError(f"R must have shape (..., 3, 3), got shape {array.shape}")
    finite = np.all(np.isfinite(array), axis=(-2, -1))
    entries = matrix_entries(np.where(finite[..., np.newaxis, np.newaxis], array, 0.0))
    result = (
        finite
        & (orthonormality_error(entries) <= atol)
        & (np.abs(determinant(entries) - 1.0) <= atol)
    )
    return bool(result) if result.ndim == 0 else result
