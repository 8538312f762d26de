"""Using rotation matrices: rotate points, undo a rotation, chain rotations, test and repair.

These are Rose (2015), Part 2, eq 5–8. A rotation matrix acts on a column vector from the
left (eq 5–6); its inverse is its transpose (eq 7), because its columns are orthonormal; and
rotations combine by matrix product (eq 8). A matrix that has drifted from orthogonality (after
thousands of products, or typed with few digits) is brought back to the nearest rotation by the
SVD. All functions broadcast over leading axes, and every function that takes rotation matrices
takes the same ``validate``, ``repair`` and ``atol`` keywords.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib import _compiled, _scalar
from eulerlib._blocks import block_slices
from eulerlib._broadcast import common_lead
from eulerlib._overflow import overflowed, rescaled
from eulerlib._quaternion_kernels import product
from eulerlib._scalar_kernels import Nine
from eulerlib._scalar_kernels import product as product_of_two
from eulerlib._validation import (
    ROTATION_ATOL,
    RotationCheck,
    as_matrix_stack,
    as_rotations,
    as_vectors,
    check_tolerance,
    determinant,
    matrix_entries,
    orthonormality_error,
    rotation_check,
)

__all__ = ["compose", "invert", "is_rotation_matrix", "nearest_rotation", "rotate_points"]


def rotate_points(
    R: ArrayLike,
    points: ArrayLike,
    *,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
) -> NDArray[np.float64]:
    """Rotate points: ``p₁ = R p₀`` for each point (Rose 2015, eq 5–6).

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotation matrices.
    points : array_like, shape (..., 3)
        Points as rows. Leading axes broadcast against those of ``R``, so one matrix can turn
        many points and many matrices can turn one point.
    validate, repair, atol
        As in :func:`eulerlib.matrix_to_euler`: check that ``R`` holds rotations (default),
        or use the nearest rotations, and the tolerance of the check.

    Returns
    -------
    ndarray, shape (broadcast of leading axes, 3)
        The rotated points; a single point ``(3,)`` with a single matrix gives ``(3,)``.

    Raises
    ------
    TypeError
        If an input is not numeric.
    ValueError
        If a shape is wrong, an entry is not finite, ``R`` is not a rotation, the leading
        axes do not broadcast, or a rotated point has a coordinate above the largest float
        (about 1.8e308; the message gives its index).

    Notes
    -----
    Eq 6 written out: ``x₁ = r₁₁x₀ + r₁₂y₀ + r₁₃z₀`` and likewise for y and z; that is the
    matrix-vector product, computed here as one ``matmul`` over all points. A point with
    coordinates near the largest float is rotated again scaled down by a power of two where a
    partial sum overflowed, so its rotated point is found whenever it is a float.

    Examples
    --------
    >>> from eulerlib import rot_z
    >>> rotate_points(rot_z(90, degrees=True), [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0]])
    array([[ 0.,  1.,  0.],
           [-2.,  0.,  0.]])
    """
    check = rotation_check(validate, repair, atol)
    kernels = _compiled.operations
    if kernels is not None and not check.repair:
        given_R, given_points = _compiled.batch(R, (3, 3)), _compiled.batch(points, (3,))
        if given_R is not None and given_points is not None:  # one pass in C, or the paths below
            lead = common_lead((given_R.shape[:-2], given_points.shape[:-1]))
            if lead is not None:
                out = np.empty((*lead, 3))
                if kernels.rotate_points(out, given_R, given_points, check.validate, check.atol):
                    return out
    one_R, one_point = _scalar.rotation(R, check), _scalar.vector(points)
    if one_R is not None and one_point is not None:  # one point: checked in Python floats
        turned = _rotated_point(one_R, one_point)
        if _scalar.finite(turned):  # a huge point: the array path rescales it
            return _scalar.as_array(turned, (3,))
    # Finiteness is read from the result, in the same pass, where that is sound: with IEEE
    # arithmetic a NaN or an infinity among the operands of a product makes it NaN or infinite
    # (0 · ∞ is NaN), so the sum of the result shows it. einsum, over a stack of matrices,
    # multiplies every pair; the BLAS product of a single matrix might skip the zero entries
    # of R, so there each column of R must have a nonzero entry (every rotation's does) for a
    # point to show. Only when the result is not finite are the arguments searched, by the
    # usual checks, which word the message; unchecked stacks of matrices are searched then too.
    unchecked = not (check.validate or check.repair)
    matrices = as_matrix_stack(R, "R", finite=False) if unchecked else as_rotations(R, "R", check)
    if unchecked and matrices.ndim == 2:
        as_matrix_stack(R, "R")  # nine numbers: checked at once
    deferred = unchecked and matrices.ndim > 2

    def check_matrices() -> None:
        if deferred:
            as_matrix_stack(R, "R")  # raises for a NaN or an infinity among the matrices

    shown = matrices.ndim > 2 or bool(np.all(np.any(matrices != 0.0, axis=0)))
    try:
        vectors = as_vectors(points, "points", finite=not shown)
    except (TypeError, ValueError):
        check_matrices()  # the matrices' errors come first, as always
        raise
    try:
        np.broadcast_shapes(matrices.shape[:-2], vectors.shape[:-1])
    except ValueError:
        check_matrices()
        as_vectors(points, "points")  # a NaN or an infinity is reported first, as always
        raise ValueError(
            f"R with shape {matrices.shape} and points with shape {vectors.shape} do not "
            "broadcast: their leading axes (all but the last two of R, all but the last of "
            "points) must be compatible"
        ) from None
    with np.errstate(over="ignore", invalid="ignore"):  # huge points: redone below
        rotated, finite = _rotated(matrices, vectors)
    if finite:
        return rotated
    check_matrices()
    as_vectors(points, "points")  # raises for a NaN or an infinity among the points
    bad = overflowed(rotated)
    if bad.size:
        lead = rotated.shape[:-1]
        if matrices.ndim == 2:
            on_R, on_points = matrices, vectors.reshape(-1, 3)[bad]
        else:  # gather the operands of those points only
            where = np.unravel_index(bad, lead)
            on_R = np.broadcast_to(matrices, (*lead, 3, 3))[where]
            on_points = np.broadcast_to(vectors, (*lead, 3))[where]
        flat = rotated.reshape(-1, 3)  # a view: both layouts of _rotated allow it
        flat[bad] = rescaled(
            lambda scale: _rotated(on_R, on_points * scale)[0],
            bad,
            "points",
            "the rotated point",
            lead,
        )
    return rotated


def _rotated_point(e: Nine, p: tuple[float, float, float]) -> tuple[float, float, float]:
    """``R p`` for one matrix and one point in Python floats, as :func:`_rotated`."""
    x, y, z = p
    turned = [0.0, 0.0, 0.0]
    for i in range(3):
        total = e[3 * i] * x
        total += e[3 * i + 1] * y
        turned[i] = total + e[3 * i + 2] * z
    return turned[0], turned[1], turned[2]


def _rotated(
    matrices: NDArray[np.float64], vectors: NDArray[np.float64]
) -> tuple[NDArray[np.float64], bool]:
    """``R p`` for each point (rows of ``vectors``), broadcast over the leading axes, and
    whether the whole result is finite (one sum, taken while each block is in the cache).

    Each coordinate is ``(r₀ x + r₁ y) + r₂ z`` in that order, element by element, so that one
    point, many points and the compiled kernel give the same bits (a BLAS product may add in
    another order, or fuse a multiply with an add, depending on the machine)."""
    lead = np.broadcast_shapes(matrices.shape[:-2], vectors.shape[:-1])
    out = np.empty((*lead, 3))
    if matrices.ndim == 2:  # one rotation for all points: block by block, in the cache
        flat, flat_out = vectors.reshape(-1, 3), out.reshape(-1, 3)
        total = 0.0
        for block in block_slices(flat.shape[0]):
            _rotate_into(matrices, flat[block], flat_out[block])
            total += float(np.sum(flat_out[block]))
        return out, math.isfinite(total)
    _rotate_into(matrices, vectors, out)
    return out, math.isfinite(float(np.sum(out)))


def _rotate_into(
    matrices: NDArray[np.float64], vectors: NDArray[np.float64], out: NDArray[np.float64]
) -> None:
    """Write ``R p`` into ``out``, broadcast, each coordinate ``(r₀ x + r₁ y) + r₂ z``."""
    x, y, z = vectors[..., 0], vectors[..., 1], vectors[..., 2]
    for i in range(3):
        total = matrices[..., i, 0] * x
        total += matrices[..., i, 1] * y
        np.add(total, matrices[..., i, 2] * z, out=out[..., i])


def invert(
    R: ArrayLike, *, validate: bool = True, repair: bool = False, atol: float = ROTATION_ATOL
) -> NDArray[np.float64]:
    """Inverse rotation, which is the transpose (Rose 2015, eq 7).

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotation matrices.
    validate, repair, atol
        As in :func:`eulerlib.matrix_to_euler`: the transpose is the inverse only of a
        rotation, so ``R`` is checked by default.

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
    check = rotation_check(validate, repair, atol)
    kernels, given = _compiled.operations, _compiled.batch(R, (3, 3))
    if kernels is not None and given is not None and not check.repair:  # one pass in C
        out = np.empty(given.shape)
        if kernels.invert(out, given, check.validate, check.atol):
            return out
    single = _scalar.rotation(R, check)
    if single is not None:
        a, b, c, d, e, f, g, h, i = single
        return _scalar.as_array((a, d, g, b, e, h, c, f, i), (3, 3))
    matrices = as_rotations(R, "R", check)
    transposed: NDArray[np.float64] = np.swapaxes(matrices, -1, -2).copy()
    return transposed


def compose(
    *rotations: ArrayLike,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
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
    validate, repair, atol
        As in :func:`eulerlib.matrix_to_euler`, for every argument. ``repair=True`` replaces
        every factor by its nearest rotation before multiplying, which is how a long chain of
        products stays a rotation (see Notes).

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

    A running product ``C = compose(C, step)`` drifts: the errors of its factors add up, those
    of matrices accepted within ``atol`` as well as rounding, until ``C`` itself is refused.
    With ``repair=True`` each call multiplies the nearest rotations of its factors (an SVD
    each, :func:`eulerlib.nearest_rotation`), so the product is a rotation to rounding, about
    1e-16, however long the chain; it is the product of the nearest rotations of the steps.

    Examples
    --------
    >>> import numpy as np
    >>> from eulerlib import rot_x, rot_y, rot_z, euler_to_matrix
    >>> yaw, pitch, roll = 0.3, 0.2, 0.1
    >>> C = compose(rot_z(yaw), rot_y(pitch), rot_x(roll))
    >>> np.allclose(C, euler_to_matrix([yaw, pitch, roll], "ZYX"))
    True

    A long chain of steps, each a rotation only within ``atol``, kept a rotation:

    >>> step = rot_z(0.001) + 2e-7          # accepted: R Rᵀ is within 4e-7 of I
    >>> C = np.eye(3)
    >>> for _ in range(1000):
    ...     C = compose(C, step, repair=True)
    >>> float(np.abs(C @ C.T - np.eye(3)).max()) < 1e-15
    True
    >>> C = np.eye(3)
    >>> for _ in range(3):                 # without repair the errors add up at once
    ...     C = compose(C, step)
    Traceback (most recent call last):
    ...
    ValueError: rotation 1 has determinant 1.0000012, which differs from 1 by 1.2e-06, more
    than the tolerance 1e-06
    """
    if not rotations:
        raise TypeError("compose() needs at least one rotation matrix")
    check = rotation_check(validate, repair, atol)
    kernels = _compiled.operations
    if kernels is not None and not check.repair:
        given = [_compiled.batch(R, (3, 3)) for R in rotations]
        shapes = tuple(g.shape[:-2] if g is not None else None for g in given)
        if None not in shapes:  # one pass in C, or the paths below
            lead = common_lead(shapes)  # type: ignore[arg-type]
            if lead is not None:
                out = np.empty((*lead, 3, 3))
                if kernels.compose(out, check.validate, check.atol, *given):
                    return out
    singles = [_scalar.rotation(R, check) for R in rotations]
    chosen = [single for single in singles if single is not None]
    if len(chosen) == len(singles):  # single matrices, checked in floats
        running = chosen[0]
        for single in chosen[1:]:
            running = product_of_two(running, single)
        return _scalar.as_array(running, (3, 3))
    matrices = [as_rotations(R, f"rotation {n + 1}", check) for n, R in enumerate(rotations)]
    try:
        lead = np.broadcast_shapes(*(m.shape[:-2] for m in matrices))
        np.broadcast_shapes(*(m.shape for m in matrices))
    except ValueError:
        listed = ", ".join(str(m.shape) for m in matrices)
        raise ValueError(f"the rotations do not broadcast together: shapes {listed}") from None
    if len(matrices) == 1:
        copied: NDArray[np.float64] = matrices[0].copy()
        return copied
    # entry by entry, (a₀ b₀ + a₁ b₃) + a₂ b₆ and without negative zeros, as one pair in Python
    # floats and the compiled kernel (a BLAS product may add in another order, or fuse a
    # multiply with an add, depending on the machine)
    work = lead or (1,)  # at least one axis, so that a row of entries is an array
    result = np.empty((*work, 3, 3))
    # rows of entries (9, ...) with the leading axes aligned on the right, as numpy broadcasts
    entries = [
        matrix_entries(m.reshape((1,) * (len(work) + 2 - m.ndim) + m.shape)) for m in matrices
    ]
    so_far = entries[0]
    for n, factor in enumerate(entries[1:], start=2):
        last = n == len(entries)
        target = np.moveaxis(result.reshape(*work, 9), -1, 0) if last else np.empty((9, *work))
        with np.errstate(over="ignore", invalid="ignore"):  # unchecked huge entries, as matmul
            product(so_far, factor, target)
        target += 0.0
        so_far = target
    return result.reshape(*lead, 3, 3)


def is_rotation_matrix(R: ArrayLike, *, atol: float = ROTATION_ATOL) -> NDArray[np.bool_]:
    """Test whether matrices are rotations: ``R Rᵀ = I`` and ``det R = +1``, within ``atol``.

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Matrices to test.
    atol : float, optional
        Tolerance on ``max |R Rᵀ − I|`` and on ``|det R − 1|``.

    Returns
    -------
    ndarray of bool, shape (...)
        One answer per matrix (a 0-d array for a single matrix, which works in ``if``).
        Matrices with NaN, infinite or huge entries are not rotations; no warning is emitted
        for them.

    Raises
    ------
    TypeError
        If ``R`` is not real numbers, or ``atol`` is not a number.
    ValueError
        If ``R`` does not have shape ``(..., 3, 3)``, or ``atol`` is not finite and ≥ 0.

    Examples
    --------
    >>> import numpy as np
    >>> is_rotation_matrix(np.eye(3))
    array(True)
    >>> bool(is_rotation_matrix(np.diag([1.0, 1.0, -1.0])))   # a mirror
    False
    >>> is_rotation_matrix(np.stack([np.eye(3), 2 * np.eye(3), np.full((3, 3), np.nan)]))
    array([ True, False, False])
    """
    tolerance = check_tolerance(atol, "atol")
    matrices = as_matrix_stack(R, "R", finite=False)
    lead = matrices.shape[:-2]
    flat = matrices.reshape(-1, 3, 3)
    result = np.empty(flat.shape[0], dtype=bool)
    with np.errstate(over="ignore", invalid="ignore"):
        for block in block_slices(flat.shape[0]):
            entries = matrix_entries(flat[block])
            # comparisons with NaN are False, so NaN, infinite and overflowing matrices fail
            result[block] = (orthonormality_error(entries) <= tolerance) & (
                np.abs(determinant(entries) - 1.0) <= tolerance
            )
    return result.reshape(lead)


def nearest_rotation(R: ArrayLike) -> NDArray[np.float64]:
    """The rotation nearest to each matrix, in the Frobenius norm (through the SVD).

    This is what ``repair=True`` does in every function that takes rotation matrices.

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Matrices close to rotations: with rounding noise, typed with few digits, or drifted
        after many products.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        ``U Vᵀ`` from the SVD ``R = U Σ Vᵀ``: the orthogonal matrix nearest to ``R``, which is
        a rotation when ``R`` is close to one.

    Raises
    ------
    TypeError
        If ``R`` is not real numbers.
    ValueError
        If ``R`` has a wrong shape or non-finite entries; if a matrix is singular or its
        singular values differ from 1 by more than ``eulerlib._validation.REPAIR_LIMIT``
        (0.1), so that there is no rotation it is close to; or if its nearest orthogonal
        matrix is a reflection. The message names the matrix and says how far it is.

    Notes
    -----
    For ``R = U Σ Vᵀ`` the orthogonal matrix nearest to ``R`` is ``U Vᵀ`` (the orthogonal
    Procrustes problem). It differs from ``R`` by as much as ``Σ`` differs from the identity,
    which is why the singular values are what decides whether a matrix can be repaired.

    Examples
    --------
    >>> import numpy as np
    >>> from eulerlib import rot_z
    >>> R = np.round(rot_z(30, degrees=True), 3)      # typed with three decimals
    >>> bool(is_rotation_matrix(R))
    False
    >>> Q = nearest_rotation(R)
    >>> bool(is_rotation_matrix(Q, atol=1e-15)), float(np.abs(Q - R).max()) < 1e-3
    (True, True)
    >>> nearest_rotation(np.zeros((3, 3)))
    Traceback (most recent call last):
    ...
    ValueError: R is singular (rank 0, singular values 0, 0, 0); only a matrix close to a rotation
    can be repaired
    """
    check = RotationCheck(validate=False, repair=True, atol=0.0)
    return as_rotations(R, "R", check)
