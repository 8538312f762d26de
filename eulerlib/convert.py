"""Translating angles from one convention to another, through the rotation matrix.

Angles in one convention become the rotation matrix, and the matrix becomes the angles of the
same rotation in the other convention, with that convention's angle order and lock policy
(:mod:`eulerlib.conventions`). With ``relabel=True`` the matrix is also moved between the
conventions' up axes (:mod:`eulerlib.up_axis`), so that Baker's heading/attitude/bank (y up)
and Rose's yaw/pitch/roll (z up) describe the same physical attitude of a body whose nose is x.

The work runs block by block: a block of angles becomes a block of matrices, which becomes a
block of angles, so no matrix array as large as the input is ever allocated.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib import _scalar
from eulerlib._blocks import block_slices
from eulerlib._euler import compiled_conversion, entries_to_angles
from eulerlib._euler_kernels import fill_matrices, intrinsic_angles, relabel_into
from eulerlib._lock import GIMBAL_LOCK_TOLERANCE, warn_if_locked
from eulerlib._scalar_kernels import angles_to_entries
from eulerlib._validation import as_vectors, check_flag, matrix_entries
from eulerlib.conventions import Convention, get_convention
from eulerlib.up_axis import up_axis_matrix

__all__ = ["convert_angles"]


def convert_angles(
    angles: ArrayLike,
    from_: str | Convention,
    to: str | Convention,
    *,
    degrees: bool = False,
    warn: bool = True,
    relabel: bool = False,
) -> NDArray[np.float64]:
    """Angles in one convention → the angles of the same rotation in another, via the matrix.

    Parameters
    ----------
    angles : array_like, shape (..., 3)
        Angles in the argument order of ``from_``. Leading axes are batch axes.
    from_, to : str or Convention
        Preset names or axis sequences (see :func:`eulerlib.get_convention`).
    degrees : bool, optional
        Angles in and out in degrees.
    warn : bool, optional
        Emit a :class:`eulerlib.GimbalLockWarning` when a rotation is in gimbal lock for
        ``to`` (default).
    relabel : bool, optional
        False (default): the matrix is shared, so both sets of angles give the same matrix in
        the same coordinates. True: also move between the presets' up axes with
        :func:`eulerlib.change_up_axis`, so both sets describe the same physical attitude of a
        body whose nose is x (for example Baker's heading/attitude/bank, y up, into Rose's
        yaw/pitch/roll, z up). Both conventions then need an up axis.

    Returns
    -------
    ndarray, shape (..., 3)
        Angles in the argument order of ``to``, with ``to``'s lock policy.

    Raises
    ------
    TypeError, ValueError
        For unknown conventions, bad angles or flags, or ``relabel=True`` without up axes.

    Warns
    -----
    GimbalLockWarning
        When some rotation is in gimbal lock for ``to``.

    Examples
    --------
    >>> convert_angles([30, 20, 10], "rose", "ros", degrees=True)   # same matrix, reversed order
    array([10., 20., 30.])
    >>> convert_angles([[30, 20, 10], [0, 0, 45]], "rose", "XYZ", degrees=True).round(4)
    array([[-1.1161, 22.2422, 28.4518],
           [45.    ,  0.    ,  0.    ]])
    >>> hab = [40, 25, -15]                            # heading, attitude, bank (y up)
    >>> convert_angles(hab, "baker", "rose", degrees=True, relabel=True).round(9)
    array([ 40., -25., -15.])
    """
    source, target = get_convention(from_, "from_"), get_convention(to, "to")
    in_degrees = check_flag(degrees, "degrees")
    warn_lock = check_flag(warn, "warn")
    move = check_flag(relabel, "relabel")
    compiled = None if move else compiled_conversion(angles, source, target, in_degrees)
    if compiled is not None:  # compiled kernels, or the paths below (which warn at lock)
        return compiled
    single = None if move else _scalar.vector(angles)
    if single is not None:  # one rotation, in Python floats; None at lock (the array path warns)
        entries = angles_to_entries(source.to_intrinsic(single), source.parsed, in_degrees)
        converted = entries_to_angles(entries, target, in_degrees)
        if converted is not None:
            return converted
    values = as_vectors(angles, "angles")
    P = None
    if move:
        if source.up_axis is None or target.up_axis is None:
            missing = source if source.up_axis is None else target
            raise ValueError(
                f"relabel=True needs an up axis for both conventions, but {missing.name!r} has "
                "none; use presets such as 'rose' (z up) or 'baker' (y up)"
            )
        P = up_axis_matrix(source.up_axis, target.up_axis)

    parsed_in, parsed_out = source.parsed, target.parsed
    lead = values.shape[:-1]
    flat = source.to_intrinsic(values.reshape(-1, 3))
    count = math.prod(lead)
    result, locked = np.empty((count, 3)), np.empty(count, dtype=bool)
    # the kernels give the intrinsic order; write it through a view of the result in that
    # order (reversed for an extrinsic sequence), so the result is in argument order in place
    intrinsic = target.to_intrinsic(result)
    zero_first = target.zeroes_intrinsic_first
    for block in block_slices(count):
        matrices = np.empty((block.stop - block.start, 3, 3))
        fill_matrices(matrices, flat[block], parsed_in, in_degrees)
        if P is not None:
            relabel_into(matrices, matrices.copy(), P)
        intrinsic[block], locked[block] = intrinsic_angles(
            matrix_entries(matrices), parsed_out, zero_first, GIMBAL_LOCK_TOLERANCE
        )
    if warn_lock:
        warn_if_locked(target, locked, result[:, 1])  # the middle angle either way
    if in_degrees:
        np.degrees(result, out=result)
    return result.reshape(*lead, 3)
