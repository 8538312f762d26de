"""Gimbal lock: when it happens, how it is reported, and how far a rotation is from it.

When the middle angle of a convention is singular, ±90° for Tait–Bryan sequences and 0° or
180° for proper Euler sequences, the first and third rotations turn about the same axis and
the matrix depends on one combination of the two outer angles only (Rose 2015, eq 4; Baker's
two poles). Which combination follows from relabelling the sequence as x-y-z or x-y-x
(:mod:`eulerlib._euler_kernels`): with the intrinsic angles ``(a, b, c)``,

* x-y-z at ``b = +90°``: ``R_x(a) R_y(90°) = R_y(90°) R_z(a)``, so the matrix depends on
  ``a + σ c`` only, and at ``b = −90°`` on ``σ c − a`` (``σ = ±1`` is the sign with which the
  third axis of the sequence is the relabelled z);
* x-y-x at ``b = 0``: ``R_x(a + c)``; at ``b = 180°``: ``R_y(180°) R_x(c − a)``.

So at lock one outer angle is free. The convention's policy (:attr:`Convention.lock_zeroes`,
see :mod:`eulerlib.conventions`) sets it to 0 and the other carries the turn. A matrix counts
as locked when its middle angle lies within :data:`GIMBAL_LOCK_TOLERANCE` of the singular value.
Each call that meets a locked matrix emits one :class:`GimbalLockWarning`, which carries the
facts as attributes and words them itself; :func:`gimbal_lock_status` returns the same test
as data.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._euler_kernels import lock_distance
from eulerlib._lock import GIMBAL_LOCK_TOLERANCE, GimbalLockWarning, lock_combination
from eulerlib._validation import (
    ROTATION_ATOL,
    as_matrix_stack,
    check_flag,
    check_tolerance,
    rotation_check,
    rotation_entry_blocks,
)
from eulerlib.conventions import Convention, get_convention

__all__ = [
    "GIMBAL_LOCK_TOLERANCE",
    "GimbalLockStatus",
    "GimbalLockWarning",
    "gimbal_lock_status",
    "lock_combination",
]


class GimbalLockStatus(NamedTuple):
    """Gimbal lock as data, one entry per rotation.

    Attributes
    ----------
    locked : ndarray of bool
        True where the middle angle is within the tolerance of its singular value.
    distance : ndarray of float
        How far the middle angle is from the nearest singular value (radians, or degrees if
        requested); 0 at lock, at most π/2.
    """

    locked: NDArray[np.bool_]
    distance: NDArray[np.float64]


def gimbal_lock_status(
    R: ArrayLike,
    seq: str | Convention = "ZYX",
    *,
    degrees: bool = False,
    tolerance: float | None = None,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
) -> GimbalLockStatus:
    """Whether each matrix is in gimbal lock for ``seq``, and how far from it.

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotation matrices.
    seq : str or Convention, optional
        Axis sequence or preset (see :func:`eulerlib.euler_to_matrix`). Default ``"ZYX"``.
    degrees : bool, optional
        Give ``distance`` in degrees, and read ``tolerance`` in degrees.
    tolerance : float, optional
        A matrix is locked when ``distance <= tolerance``. Default:
        :data:`GIMBAL_LOCK_TOLERANCE` radians, the threshold every conversion uses, whatever
        the unit of ``distance``.
    validate, repair, atol
        As in :func:`eulerlib.matrix_to_euler`.

    Returns
    -------
    GimbalLockStatus
        ``(locked, distance)``, arrays of the leading shape of ``R`` (0-d for one matrix): the
        flags, and the distance of the middle angle from the nearest singular value (±90° for
        Tait–Bryan, 0° or 180° for proper Euler).

    Raises
    ------
    TypeError, ValueError
        For bad input, as :func:`eulerlib.matrix_to_euler`, or a tolerance that is not a
        finite number ≥ 0.

    Examples
    --------
    >>> from eulerlib import euler_to_matrix
    >>> R = euler_to_matrix([[0, 89, 0], [0, 90, 0]], "ZYX", degrees=True)
    >>> status = gimbal_lock_status(R, "ZYX", degrees=True)
    >>> status.locked
    array([False,  True])
    >>> status.distance.round(9)
    array([1., 0.])
    """
    convention = get_convention(seq)
    in_degrees = check_flag(degrees, "degrees")
    limit = GIMBAL_LOCK_TOLERANCE if tolerance is None else check_tolerance(tolerance, "tolerance")
    if tolerance is not None and in_degrees:
        limit = math.radians(limit)
    check = rotation_check(validate, repair, atol)
    matrices = as_matrix_stack(R, "R")
    lead = matrices.shape[:-2]
    flat_distance = np.empty(math.prod(lead))
    parsed = convention.parsed
    for block, entries in rotation_entry_blocks(matrices, "R", check):
        flat_distance[block] = lock_distance(entries, parsed)
    distance = flat_distance.reshape(lead)
    locked = np.asarray(distance <= limit)  # 0-d arrays, not NumPy scalars, for one matrix
    if in_degrees:
        np.degrees(distance, out=distance)
    return GimbalLockStatus(locked, distance)
