"""Baker's convention by name: heading, attitude, bank (y up, ``R = R_y(h) R_z(a) R_x(b)``).

M. J. Baker, "Maths - Conversion Matrix to Euler" (euclideanspace.com), uses a y-up frame: the
aircraft first turns by heading about y, then by attitude about the new z, then by bank about
the newest x. In eulerlib's general terms that is ``seq="YZX"`` with angles
``(heading, attitude, bank)``.

Going back, away from the poles: heading = atan2(−m20, m00), attitude = asin(m10),
bank = atan2(−m12, m11) (rows and columns counted from 0). At the poles, attitude ±90°, Baker
sets bank to 0 and takes heading = atan2(m02, m22); eulerlib keeps that choice (so the lock
policy here differs from :func:`eulerlib.matrix_to_euler`, which zeroes the *first* angle),
but computes attitude with ``atan2`` and detects a pole with a tight tolerance instead of
Baker's ``|m10| > 0.998`` cut-off, which reports an attitude of 86.4° as 90°.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._validation import ROTATION_ATOL, stack_angles
from eulerlib.euler import angles_from_matrix, euler_to_matrix
from eulerlib.sequences import parse_sequence

__all__ = ["heading_attitude_bank_to_matrix", "matrix_to_heading_attitude_bank"]

_YZX = parse_sequence("YZX")


def heading_attitude_bank_to_matrix(
    heading: ArrayLike, attitude: ArrayLike, bank: ArrayLike, *, degrees: bool = False
) -> NDArray[np.float64]:
    """Rotation matrix from heading, attitude and bank (Baker): ``R_y(h) R_z(a) R_x(b)``.

    Parameters
    ----------
    heading, attitude, bank : array_like
        Angles about y, z and x, radians unless ``degrees``. They broadcast together.
    degrees : bool, optional
        Read the angles in degrees.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        The rotation matrices.

    Raises
    ------
    TypeError
        If an angle is not numeric.
    ValueError
        If an angle is NaN or infinite, or the angles do not broadcast.

    Notes
    -----
    With ch = cos(heading), sa = sin(attitude) and so on, Baker's matrix is::

        [ ch·ca   −ch·sa·cb + sh·sb    ch·sa·sb + sh·cb ]
        [ sa       ca·cb              −ca·sb            ]
        [ −sh·ca   sh·sa·cb + ch·sb   −sh·sa·sb + ch·cb ]

    Examples
    --------
    >>> R = heading_attitude_bank_to_matrix(0, 90, 0, degrees=True)
    >>> R @ [1.0, 0.0, 0.0]   # attitude 90°: the nose (x) points straight up (y)
    array([0., 1., 0.])
    """
    stacked = stack_angles({"heading": heading, "attitude": attitude, "bank": bank})
    return euler_to_matrix(stacked, "YZX", degrees=degrees)


def matrix_to_heading_attitude_bank(
    R: ArrayLike,
    *,
    degrees: bool = False,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
    warn: bool = True,
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Heading, attitude and bank of rotation matrices (Baker), with bank = 0 at the poles.

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
    heading, attitude, bank : ndarray, each shape (...)
        Heading and bank in [-π, π], attitude in [-π/2, π/2]. At a pole (attitude ±90°) bank
        is 0 and heading = atan2(m02, m22) carries the whole turn about the vertical.

    Raises
    ------
    TypeError, ValueError
        For bad input, as :func:`eulerlib.matrix_to_euler`.

    Warns
    -----
    GimbalLockWarning
        Once per call when some matrix is at a pole.

    Examples
    --------
    >>> R = heading_attitude_bank_to_matrix(40, 90, 10, degrees=True)   # north pole
    >>> import warnings
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore")
    ...     h, a, b = matrix_to_heading_attitude_bank(R, degrees=True)
    >>> print(h, a, b)   # heading + bank = 50° survives; bank is set to 0
    50.0 90.0 0.0
    """
    angles = angles_from_matrix(
        R,
        _YZX,
        2,
        degrees=degrees,
        validate=validate,
        repair=repair,
        atol=atol,
        warn=warn,
    )
    return angles[..., 0], angles[..., 1], angles[..., 2]
