"""Unit quaternions: rotations as four numbers, with no gimbal lock and a double cover.

A turn by the angle θ about the unit axis ``n`` is the unit quaternion

.. math::

    q = (w, x, y, z) = \\left(\\cos\\tfrac{θ}{2},\\ \\sin\\tfrac{θ}{2}\\, n\\right),

and its rotation matrix is ``R = I + 2 w [v]× + 2 [v]×²`` with ``v = (x, y, z)`` and ``[v]×`` the
matrix of the cross product ``v × ·`` (Rodrigues' formula, :mod:`eulerlib.axis_angle`, in half
angles). Multiplying quaternions composes rotations as multiplying their matrices does:
``R(p q) = R(p) R(q)``.

The double cover
----------------
``q`` and ``-q`` give the same matrix (every entry of ``R`` is a product of two components),
because a turn by θ about ``n`` and a turn by ``2π − θ`` about ``-n`` are the same rotation.
So each rotation has two quaternions. eulerlib returns the **canonical** one: ``w > 0``; and when
``w = 0`` (a half turn, θ = π), the one whose first nonzero component of ``(x, y, z)`` is
positive. That is SciPy's ``Rotation.as_quat(canonical=True)``.

From a matrix to its quaternion: Shepperd's choice
--------------------------------------------------
Sums and differences of the entries of ``R`` give ``4 q qᵀ``: its diagonal is ``4w² = 1 + r00 +
r11 + r22``, ``4x² = 1 + r00 − r11 − r22``, ``4y²``, ``4z²`` alike, and off the diagonal ``4wx =
r21 − r12``, ``4xy = r01 + r10``, and so on. Taking ``w = sqrt(1 + trace) / 2`` and dividing the
rest by ``4w`` fails for turns near a half turn, where ``w`` is tiny: the division magnifies
rounding without bound. S. W. Shepperd (1978) takes instead the largest of the four diagonal
entries, which add up to 4 and so is at least 1, and divides its row by twice its square root:
never a division by a small number, and every component accurate to a few units in the last
place (F. L. Markley (2008) chooses the same way). SciPy does the same.

Component order
---------------
``scalar_first`` means exactly what it means in SciPy's ``Rotation.from_quat`` and ``as_quat``,
with the same default: ``False`` stores ``(x, y, z, w)``, ``True`` stores ``(w, x, y, z)``. So
arrays pass between the two libraries unchanged.

Examples
--------
>>> import numpy as np
>>> q = matrix_to_quaternion(np.diag([1.0, -1.0, -1.0]))   # half turn about x
>>> q
array([1., 0., 0., 0.])
>>> np.allclose(quaternion_to_matrix(-q), quaternion_to_matrix(q))   # the double cover
True
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib import _compiled, _scalar
from eulerlib._blocks import block_slices
from eulerlib._euler import (
    compiled_quaternion_angles,
    compiled_quaternions,
    entries_to_angles,
    entry_blocks_to_angles,
)
from eulerlib._length_kernels import out_of_range
from eulerlib._quaternion_kernels import (
    entries_to_quaternions,
    euler_to_quaternions,
    normalize,
    quaternions_to_entries,
)
from eulerlib._scalar_kernels import (
    Four,
    Nine,
    entries_to_quaternion,
    normalized,
    quaternion_to_entries,
)
from eulerlib._scalar_kernels import (
    euler_to_quaternion as one_euler_to_quaternion,
)
from eulerlib._unit import scaled_to_unit_size
from eulerlib._validation import (
    ROTATION_ATOL,
    as_float_array,
    as_matrix_stack,
    as_vectors,
    check_flag,
    rotation_check,
    rotation_entry_blocks,
)
from eulerlib.conventions import Convention, get_convention

__all__ = [
    "euler_to_quaternion",
    "matrix_to_quaternion",
    "quaternion_to_euler",
    "quaternion_to_matrix",
]

#: Where w, x, y, z sit in a stored quaternion, by ``scalar_first``.
_ORDER = {False: (3, 0, 1, 2), True: (0, 1, 2, 3)}
#: Where the stored components sit in (w, x, y, z), by ``scalar_first``.
_STORED = {False: (1, 2, 3, 0), True: (0, 1, 2, 3)}


def _as_quaternions(value: ArrayLike, name: str) -> NDArray[np.float64]:
    """``value`` as a float array of shape ``(..., 4)`` with finite entries."""
    array = as_float_array(value, name)
    if array.ndim == 0 or array.shape[-1] != 4:
        raise ValueError(f"{name} must have shape (..., 4), got shape {array.shape}")
    return array


def _quaternion_entry_blocks(
    quaternions: NDArray[np.float64], name: str, scalar_first: bool
) -> Iterator[tuple[slice, NDArray[np.float64]]]:
    """The rotation matrices of checked quaternions ``(..., 4)``, block by block.

    Yields ``(block, entries)`` as :func:`eulerlib._validation.rotation_entry_blocks` does:
    ``entries`` of shape ``(9, n)``, row ``3 i + j`` holding ``R[i, j]``. The few quaternions
    whose squared length leaves the range of float64 are redone after scaling by a power of two;
    a zero quaternion raises while iterating, with its index in the whole of ``quaternions``.
    """
    lead = quaternions.shape[:-1]
    flat = quaternions.reshape(-1, 4)
    order = _ORDER[scalar_first]
    for block in block_slices(flat.shape[0]):
        stored_rows = flat[block].T  # a view: the rows are read where they are
        w, x, y, z = (stored_rows[i] for i in order)
        entries = np.empty((9, stored_rows.shape[1]))
        with np.errstate(all="ignore"):  # zero, tiny or huge quaternions are redone below
            squared = quaternions_to_entries((w, x, y, z), entries)
        redo = out_of_range(squared)
        if redo.size:
            part = np.ascontiguousarray(stored_rows[list(order)][:, redo])
            part, _ = scaled_to_unit_size(part, name, "a quaternion", lead, block.start + redo)
            fixed = np.empty((9, redo.size))
            quaternions_to_entries(part, fixed)
            entries[:, redo] = fixed
        yield block, entries


def _one_quaternion_entries(q: object, scalar_first: bool) -> Nine | None:
    """The matrix entries of a single plain quaternion in Python floats, or None (a zero,
    tiny or huge quaternion, or anything but one plain quaternion: the array path)."""
    single = _scalar.quaternion(q)
    if single is None:
        return None
    w, x, y, z = (single[i] for i in _ORDER[scalar_first])
    return quaternion_to_entries(w, x, y, z)


def _one_stored(q: Four, scalar_first: bool) -> NDArray[np.float64]:
    """One quaternion ``(w, x, y, z)`` of Python floats as a stored quaternion ``(4,)``."""
    return _scalar.as_array(tuple(q[i] for i in _STORED[scalar_first]), (4,))


def _stored(q: NDArray[np.float64], scalar_first: bool) -> NDArray[np.float64]:
    """Rows w, x, y, z of a block ``(4, n)`` as stored quaternions ``(n, 4)``."""
    columns: NDArray[np.float64] = q[list(_STORED[scalar_first])].T
    return columns


def quaternion_to_matrix(q: ArrayLike, *, scalar_first: bool = False) -> NDArray[np.float64]:
    """Rotation matrices of quaternions of any nonzero length.

    Parameters
    ----------
    q : array_like, shape (..., 4)
        Quaternions, ``(x, y, z, w)`` or with ``scalar_first`` ``(w, x, y, z)``; any nonzero
        length. Leading axes are batch axes.
    scalar_first : bool, optional
        Read the scalar part ``w`` first, as SciPy's ``Rotation.from_quat(q,
        scalar_first=True)``. Default ``False``: scalar last, SciPy's default.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        ``R = I + 2 w [v]× + 2 [v]×²`` of the unit quaternion ``q / |q|``; ``q`` and ``-q`` give
        the same matrix.

    Raises
    ------
    TypeError
        If ``q`` is not real numbers or ``scalar_first`` is not a bool.
    ValueError
        If ``q`` does not have shape ``(..., 4)``, has NaN or infinite entries, or a quaternion
        is zero (the message gives its index).

    Notes
    -----
    For a unit quaternion, ``R = [[1 − 2(y² + z²), 2(xy − wz), 2(xz + wy)], [2(xy + wz),
    1 − 2(x² + z²), 2(yz − wx)], [2(xz − wy), 2(yz + wx), 1 − 2(x² + y²)]]``. eulerlib evaluates
    the same matrix in the form that holds for any length, ``R[0, 0] = (w² + x² − y² − z²) /
    |q|²``, ``R[0, 1] = 2(xy − wz) / |q|²`` and so on, so the quaternion is never rounded by a
    separate normalization; a quaternion so small or so large that ``|q|²`` would underflow or
    overflow is first scaled by a power of two, which is exact.

    Examples
    --------
    >>> import numpy as np
    >>> s = np.sqrt(0.5)
    >>> quaternion_to_matrix([0.0, 0.0, s, s])      # (x, y, z, w): 90° about z
    array([[ 0., -1.,  0.],
           [ 1.,  0.,  0.],
           [ 0.,  0.,  1.]])
    >>> quaternion_to_matrix([2.0, 0.0, 0.0, 0.0], scalar_first=True)   # normalized: identity
    array([[1., 0., 0.],
           [0., 1., 0.],
           [0., 0., 1.]])
    """
    first = check_flag(scalar_first, "scalar_first")
    kernels, given = _compiled.rotations, _compiled.batch(q, (4,))
    if kernels is not None and given is not None:  # one pass in C, or the paths below
        out = np.empty((*given.shape[:-1], 3, 3))
        if kernels.quaternions_to_matrices(out, given, first):
            return out
    single = _one_quaternion_entries(q, first)
    if single is not None:
        return _scalar.as_array(single, (3, 3))
    few = _scalar.small_batch(q, (4,))
    if few is not None:  # a few quaternions, one after another in Python floats
        order = _ORDER[first]
        matrices = [quaternion_to_entries(*(row[i] for i in order)) for row in few]
        if all(m is not None for m in matrices):
            return np.array(matrices).reshape(len(few), 3, 3)
    quaternions = _as_quaternions(q, "q")
    lead = quaternions.shape[:-1]
    out = np.empty((math.prod(lead), 9))
    for block, entries in _quaternion_entry_blocks(quaternions, "q", first):
        out[block] = entries.T
    return out.reshape(*lead, 3, 3)


def matrix_to_quaternion(
    R: ArrayLike,
    *,
    scalar_first: bool = False,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
) -> NDArray[np.float64]:
    """Canonical unit quaternions of rotation matrices (Shepperd's method).

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotation matrices. Leading axes are batch axes.
    scalar_first : bool, optional
        Return ``(w, x, y, z)`` instead of the default ``(x, y, z, w)``, as SciPy's
        ``as_quat(scalar_first=True)``.
    validate, repair, atol
        As in :func:`eulerlib.matrix_to_euler`: check that ``R`` holds rotations within
        ``atol`` (default), or use the nearest rotations.

    Returns
    -------
    ndarray, shape (..., 4)
        Unit quaternions with ``w >= 0``; at ``w = 0`` (half turns) the first nonzero of
        ``x, y, z`` is positive. This is SciPy's ``as_quat(canonical=True)``. Their length is
        1 to a unit or two in the last place for every matrix the check accepts, also one
        that is a rotation only within ``atol``.

    Raises
    ------
    TypeError
        If ``R`` is not real numbers or a flag is not a bool.
    ValueError
        If ``R`` has a wrong shape, non-finite entries, is a reflection or not orthogonal
        within ``atol`` (or cannot be repaired), or ``atol`` is not a finite number ≥ 0.

    Notes
    -----
    Of ``4w² = 1 + trace`` and ``4x², 4y², 4z²`` (``1 + 2 r_ii − trace``) the largest is taken
    and its row of ``4 q qᵀ`` divided by twice its square root (S. W. Shepperd, 1978), so the
    result is accurate to a few units in the last place for every rotation, half turns and
    turns near them included. See the module docstring. The quaternion is then divided by its
    length: for a matrix ``R`` with ``R Rᵀ`` off the identity by ``δ``, Shepperd's formula
    gives a length of ``1 ± δ``, and a "unit" quaternion that far from unit would carry the
    matrix's error into every product and conversion that follows.

    Examples
    --------
    >>> import numpy as np
    >>> from eulerlib import rot_z
    >>> matrix_to_quaternion(rot_z(90, degrees=True))           # (x, y, z, w)
    array([0.        , 0.        , 0.70710678, 0.70710678])
    >>> matrix_to_quaternion(np.diag([-1.0, -1.0, 1.0]), scalar_first=True)   # half turn
    array([0., 0., 0., 1.])
    """
    first = check_flag(scalar_first, "scalar_first")
    check = rotation_check(validate, repair, atol)
    kernels, given = _compiled.rotations, _compiled.batch(R, (3, 3))
    if kernels is not None and given is not None and not check.repair:  # one pass in C
        out = np.empty((*given.shape[:-2], 4))
        if kernels.matrices_to_quaternions(out, given, first, check.validate, check.atol):
            return out
    single = _scalar.rotation(R, check)
    unit = None if single is None else normalized(entries_to_quaternion(single))
    if unit is not None:
        return _one_stored(unit, first)
    few = _scalar.rotations(R, check)
    units = [] if few is None else [normalized(entries_to_quaternion(row)) for row in few]
    if units and all(q is not None for q in units):  # a few, one after another in Python floats
        stored = _STORED[first]
        return np.array([[q[i] for i in stored] for q in units if q is not None])
    matrices = as_matrix_stack(R, "R")
    lead = matrices.shape[:-2]
    out = np.empty((math.prod(lead), 4))
    for block, entries in rotation_entry_blocks(matrices, "R", check):
        q = entries_to_quaternions(entries)
        normalize(q)  # a matrix orthogonal only within atol gives |q| = 1 ± atol before this
        out[block] = _stored(q, first)
    return out.reshape(*lead, 4)


def euler_to_quaternion(
    angles: ArrayLike,
    seq: str | Convention = "ZYX",
    *,
    degrees: bool = False,
    scalar_first: bool = False,
) -> NDArray[np.float64]:
    """Canonical unit quaternions of Euler angles, in any of the 24 conventions or a preset.

    Parameters
    ----------
    angles : array_like, shape (..., 3)
        Angle ``i`` goes with letter ``i`` of ``seq``. Leading axes are batch axes.
    seq : str or Convention, optional
        Axis sequence or preset, as in :func:`eulerlib.euler_to_matrix`. Default ``"ZYX"``.
    degrees : bool, optional
        Read ``angles`` in degrees; they are reduced exactly, so angles of any size are exact.
    scalar_first : bool, optional
        Return ``(w, x, y, z)`` instead of the default ``(x, y, z, w)``.

    Returns
    -------
    ndarray, shape (..., 4)
        Canonical unit quaternions, as :func:`matrix_to_quaternion` returns them.

    Raises
    ------
    TypeError
        If ``angles`` is not real numbers, ``seq`` is not a string or a convention, or a flag
        is not a bool.
    ValueError
        If ``angles`` has a wrong shape or non-finite values, or ``seq`` is invalid.

    Notes
    -----
    The product of three elementary quaternions ``(cos(a/2), sin(a/2) e_axis)``, written out
    in closed form; for ``"ZYX"`` it is the quaternion of Rose (2015), eq 2.

    Examples
    --------
    >>> euler_to_quaternion([90, 0, 0], "ZYX", degrees=True)      # yaw 90°
    array([0.        , 0.        , 0.70710678, 0.70710678])
    >>> euler_to_quaternion([0, 0, 180], "rose", degrees=True, scalar_first=True)  # roll 180°
    array([0., 1., 0., 0.])
    """
    convention = get_convention(seq)
    in_degrees = check_flag(degrees, "degrees")
    first = check_flag(scalar_first, "scalar_first")
    compiled = compiled_quaternions(angles, convention, in_degrees, first)
    if compiled is not None:  # compiled kernels, or the paths below
        return compiled
    single = _scalar.vector(angles)
    if single is not None:
        intrinsic = convention.to_intrinsic(single)
        return _one_stored(one_euler_to_quaternion(intrinsic, convention.parsed, in_degrees), first)
    values = as_vectors(angles, "angles")
    parsed = convention.parsed
    flat = convention.to_intrinsic(values.reshape(-1, 3))
    out = np.empty((flat.shape[0], 4))
    for block in block_slices(flat.shape[0]):
        out[block] = _stored(euler_to_quaternions(flat[block], parsed, in_degrees), first)
    return out.reshape(*values.shape[:-1], 4)


def quaternion_to_euler(
    q: ArrayLike,
    seq: str | Convention = "ZYX",
    *,
    degrees: bool = False,
    scalar_first: bool = False,
    warn: bool = True,
) -> NDArray[np.float64]:
    """Euler angles of quaternions, in any of the 24 conventions or a preset.

    Parameters
    ----------
    q : array_like, shape (..., 4)
        Quaternions of any nonzero length (see :func:`quaternion_to_matrix`).
    seq : str or Convention, optional
        Axis sequence or preset, as in :func:`eulerlib.matrix_to_euler`. Default ``"ZYX"``.
    degrees : bool, optional
        Return degrees instead of radians.
    scalar_first : bool, optional
        Read ``(w, x, y, z)`` instead of the default ``(x, y, z, w)``.
    warn : bool, optional
        Emit one :class:`eulerlib.GimbalLockWarning` if any rotation is in gimbal lock.

    Returns
    -------
    ndarray, shape (..., 3)
        The angles, in the ranges and with the lock policy of :func:`eulerlib.matrix_to_euler`;
        ``q`` and ``-q`` give the same angles.

    Raises
    ------
    TypeError
        If ``q`` is not real numbers, ``seq`` is not a string or a convention, or a flag is not
        a bool.
    ValueError
        If ``q`` has a wrong shape, non-finite entries or a zero quaternion, or ``seq`` is
        invalid.

    Warns
    -----
    GimbalLockWarning
        Once per call when some rotation is in gimbal lock (see
        :func:`eulerlib.matrix_to_euler`).

    Notes
    -----
    Each block of quaternions becomes the entries of its rotation matrices, which are then
    read exactly as :func:`eulerlib.matrix_to_euler` reads a matrix: the same ``atan2`` of a
    sine and a cosine for the middle angle, the same test for gimbal lock and the same choice
    of the angle set to 0 there. So the two functions agree at the lock and near it too.

    Examples
    --------
    >>> import numpy as np
    >>> q = euler_to_quaternion([30, 20, 10], "ZYX", degrees=True)
    >>> quaternion_to_euler(q, "ZYX", degrees=True)
    array([30., 20., 10.])
    >>> quaternion_to_euler(-q, "xyz", degrees=True)      # -q is the same rotation
    array([10., 20., 30.])
    """
    convention = get_convention(seq)
    in_degrees = check_flag(degrees, "degrees")
    first = check_flag(scalar_first, "scalar_first")
    warn_lock = check_flag(warn, "warn")
    compiled = compiled_quaternion_angles(q, convention, first, in_degrees)
    if compiled is not None:  # compiled kernels, or the paths below (which warn at lock)
        return compiled
    entries = _one_quaternion_entries(q, first)
    if entries is not None:
        angles = entries_to_angles(entries, convention, in_degrees)
        if angles is not None:  # None at gimbal lock: the array path warns
            return angles
    quaternions = _as_quaternions(q, "q")
    blocks = _quaternion_entry_blocks(quaternions, "q", first)
    return entry_blocks_to_angles(blocks, quaternions.shape[:-1], convention, in_degrees, warn_lock)
