"""Rose's convention by name: yaw, pitch, roll (z-y-x, intrinsic, active, right-handed).

D. Rose, "Rotations in Three-Dimensions: Euler Angles and Rotation Matrices, Part 2" (2015)
turns a body first by yaw ``w`` about z, then by pitch ``v`` about the new y, then by roll
``u`` about the newest x: ``R = R_z(w) R_y(v) R_x(u)`` (eq 2). In eulerlib's general terms that
is ``seq="ZYX"`` with angles ``(yaw, pitch, roll)``; these functions are the same conversions
with the paper's names, taking and returning the three angles separately.

Going back (eq 3): yaw = atan2(r21, r11), pitch = −asin(r31), roll = atan2(r32, r33). At pitch
±90° the paper sets yaw to 0 and solves roll from eq 4; eulerlib keeps that choice, but
computes pitch with ``atan2`` and detects the lock with a tolerance rather than ``r31 == ±1``
(see :mod:`eulerlib.euler`), so a lock matrix with rounding noise is still handled.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._validation import ROTATION_ATOL, stack_angles
from eulerlib.euler import angles_from_matrix, euler_to_matrix
from eulerlib.sequences import parse_sequence

__all__ = ["matrix_to_yaw_pitch_roll", "yaw_pitch_roll_to_matrix"]

_ZYX = parse_sequence("ZYX")


def yaw_pitch_roll_to_matrix(
    yaw: ArrayLike, pitch: ArrayLike, roll: ArrayLike, *, degrees: bool = False
) -> NDArray[np.float64]:
    """Rotation matrix from yaw, pitch and roll (Rose 2015, eq 2).

    Parameters
    ----------
    yaw, pitch, roll : array_like
        Angles about z, y and x (w, v, u in the paper), radians unless ``degrees``. They
        broadcast against each other.
    degrees : bool, optional
        Read the angles in degrees.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        ``R_z(yaw) @ R_y(pitch) @ R_x(roll)``.

    Raises
    ------
    TypeError
        If an angle is not numeric.
    ValueError
        If an angle is NaN or infinite, or the angles do not broadcast.

    Notes
    -----
    Eq 2, with c and s for cosine and sine::

        [ c(v)c(w)   s(u)s(v)c(w) − c(u)s(w)   s(u)s(w) + c(u)s(v)c(w) ]
        [ c(v)s(w)   c(u)c(w) + s(u)s(v)s(w)   c(u)s(v)s(w) − s(u)c(w) ]
        [ −s(v)      s(u)c(v)                  c(u)c(v)                ]

    Examples
    --------
    >>> R = yaw_pitch_roll_to_matrix(90, 0, 0, degrees=True)
    >>> R @ [1.0, 0.0, 0.0]   # yawing 90° turns the nose from x to y
    array([0., 1., 0.])
    >>> yaw_pitch_roll_to_matrix([0.0, 0.1, 0.2], 0.3, 0.0).shape
    (3, 3, 3)
    """
    stacked = stack_angles({"yaw": yaw, "pitch": pitch, "roll": roll})
    return euler_to_matrix(stacked, "ZYX", degrees=degrees)


def matrix_to_yaw_pitch_roll(
    R: ArrayLike,
    *,
    degrees: bool = False,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
    warn: bool = True,
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Yaw, pitch and roll of rotation matrices (Rose 2015, eq 3, and eq 4 at gimbal lock).

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotation matrices.
    degrees : bool, optional
        Return degrees instead of radians.
    validate, repair, atol, warn
        As in :func:`eulerlib.matrix_to_euler`.

    Returns
    -------
    yaw, pitch, roll : ndarray, each shape (...)
        Yaw and roll in [-π, π], pitch in [-π/2, π/2]. At gimbal lock (pitch ±90°) yaw is 0
        and roll carries the whole turn about the vertical, as Rose chooses: roll = atan2(−r12,
        −r13) at pitch −90° and roll = atan2(r12, r13) at pitch +90° (eq 4a, 4b).

    Raises
    ------
    TypeError, ValueError
        For bad input, as :func:`eulerlib.matrix_to_euler`.

    Warns
    -----
    GimbalLockWarning
        Once per call when some matrix is in gimbal lock.

    Examples
    --------
    >>> R = yaw_pitch_roll_to_matrix(30, 20, 10, degrees=True)
    >>> yaw, pitch, roll = matrix_to_yaw_pitch_roll(R, degrees=True)
    >>> print(yaw, pitch, roll)
    30.0 20.0 10.0
    """
    angles = angles_from_matrix(
        R,
        _ZYX,
        0,
        degrees=degrees,
        validate=validate,
        repair=repair,
        atol=atol,
        warn=warn,
    )
    return angles[..., 0], angles[..., 1], angles[..., 2]
