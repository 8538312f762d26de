"""The papers' two conventions by name: yaw-pitch-roll (Rose), heading-attitude-bank (Baker).

D. Rose, "Rotations in Three-Dimensions: Euler Angles and Rotation Matrices, Part 2" (2015)
turns a body first by yaw ``w`` about z, then by pitch ``v`` about the new y, then by roll
``u`` about the newest x: ``R = R_z(w) R_y(v) R_x(u)`` (eq 2), ``seq="ZYX"``. Going back (eq 3):
yaw = atan2(r21, r11), pitch = −asin(r31), roll = atan2(r32, r33); at pitch ±90° the paper sets
yaw to 0 and solves roll from eq 4.

M. J. Baker, "Maths - Conversion Matrix to Euler" (euclideanspace.com), uses a y-up frame: the
aircraft turns by heading about y, then by attitude about the new z, then by bank about the
newest x: ``R = R_y(h) R_z(a) R_x(b)``, ``seq="YZX"``. Going back, away from the poles:
heading = atan2(−m20, m00), attitude = asin(m10), bank = atan2(−m12, m11) (rows and columns
from 0); at the poles, attitude ±90°, Baker sets bank to 0 and takes heading = atan2(m02, m22).

The functions here are the general conversions of :mod:`eulerlib.euler` with the presets
``"rose"`` and ``"baker"`` (:mod:`eulerlib.conventions`), so they keep each paper's lock choice
(yaw = 0, bank = 0) while computing the middle angle with ``atan2`` and detecting lock with a
tight tolerance instead of the papers' ``r31 == ±1`` test and ``|m10| > 0.998`` cut-off. They
take the three angles separately and return them as a named tuple of arrays.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib import _scalar
from eulerlib._euler import (
    angles_to_matrices,
    compiled_angles,
    compiled_matrices,
    matrices_to_angles,
    one_matrix_to_angles,
)
from eulerlib._scalar_kernels import angles_to_entries
from eulerlib._validation import (
    ROTATION_ATOL,
    as_matrix_stack,
    check_flag,
    rotation_check,
    stack_angles,
)
from eulerlib.conventions import CONVENTIONS, Convention

__all__ = [
    "HeadingAttitudeBank",
    "YawPitchRoll",
    "heading_attitude_bank_to_matrix",
    "matrix_to_heading_attitude_bank",
    "matrix_to_yaw_pitch_roll",
    "yaw_pitch_roll_to_matrix",
]


class YawPitchRoll(NamedTuple):
    """Rose's three angles, each an array of the leading shape of the matrices (0-d for one)."""

    yaw: NDArray[np.float64]
    pitch: NDArray[np.float64]
    roll: NDArray[np.float64]


class HeadingAttitudeBank(NamedTuple):
    """Baker's three angles, each an array of the leading shape of the matrices (0-d for one)."""

    heading: NDArray[np.float64]
    attitude: NDArray[np.float64]
    bank: NDArray[np.float64]


def _named_to_matrix(
    convention: Convention, values: tuple[ArrayLike, ArrayLike, ArrayLike], degrees: object
) -> NDArray[np.float64]:
    """The matrices of three separately given angles in a named convention."""
    in_degrees = check_flag(degrees, "degrees")
    a, b, c = (_scalar.number(value) for value in values)
    if a is not None and b is not None and c is not None:  # one rotation, in Python floats
        intrinsic = convention.to_intrinsic((a, b, c))
        entries = angles_to_entries(intrinsic, convention.parsed, in_degrees)
        return _scalar.as_array(entries, (3, 3))
    same = _same_shape_floats(values)
    compiled = None if same is None else compiled_matrices(same, convention, in_degrees)
    if compiled is not None:  # compiled kernels, which check the angles themselves
        return compiled
    stacked = stack_angles(dict(zip(convention.angle_names, values, strict=True)))
    compiled = compiled_matrices(stacked, convention, in_degrees)
    return angles_to_matrices(stacked, convention, in_degrees) if compiled is None else compiled


def _same_shape_floats(
    values: tuple[ArrayLike, ArrayLike, ArrayLike],
) -> NDArray[np.float64] | None:
    """Three float64 arrays of one shape stacked into ``(..., 3)`` with no check, for the
    compiled kernels (which check them and decline anything the full path must word); None
    for anything else."""
    a, b, c = values
    if type(a) is not np.ndarray or type(b) is not np.ndarray or type(c) is not np.ndarray:
        return None
    if not (a.dtype == b.dtype == c.dtype == np.float64 and a.shape == b.shape == c.shape):
        return None
    stacked = np.empty((*a.shape, 3))
    stacked[..., 0], stacked[..., 1], stacked[..., 2] = a, b, c
    return stacked


def _matrix_to_named(
    convention: Convention,
    R: ArrayLike,
    degrees: object,
    validate: object,
    repair: object,
    atol: object,
    warn: object,
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """The three angles, as separate arrays, of matrices in a named convention."""
    in_degrees = check_flag(degrees, "degrees")
    check = rotation_check(validate, repair, atol)
    warn_lock = check_flag(warn, "warn")
    single = compiled_angles(R, convention, check, in_degrees)
    if single is None:
        single = one_matrix_to_angles(R, convention, check, in_degrees)
    if single is not None:
        angles = single
    else:
        matrices = as_matrix_stack(R, "R")
        angles = matrices_to_angles(matrices, convention, check, in_degrees, warn_lock)
    first, middle, third = (np.array(angles[..., i]) for i in range(3))  # 0-d for one matrix
    return first, middle, third


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
        If an angle is not real numbers or ``degrees`` is not a bool.
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
    return _named_to_matrix(CONVENTIONS["rose"], (yaw, pitch, roll), degrees)


def matrix_to_yaw_pitch_roll(
    R: ArrayLike,
    *,
    degrees: bool = False,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
    warn: bool = True,
) -> YawPitchRoll:
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
    YawPitchRoll
        ``(yaw, pitch, roll)``, arrays of the leading shape of ``R``. Yaw and roll in (-π, π],
        pitch in [-π/2, π/2]. At gimbal lock (pitch ±90°) yaw is 0 and roll carries the whole
        turn about the vertical, as Rose chooses: roll = atan2(−r12, −r13) at pitch −90° and
        roll = atan2(r12, r13) at pitch +90° (eq 4a, 4b).

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
    >>> angles = matrix_to_yaw_pitch_roll(R, degrees=True)
    >>> print(angles.yaw, angles.pitch, angles.roll)
    30.0 20.0 10.0
    """
    return YawPitchRoll(
        *_matrix_to_named(CONVENTIONS["rose"], R, degrees, validate, repair, atol, warn)
    )


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
        If an angle is not real numbers or ``degrees`` is not a bool.
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
    return _named_to_matrix(CONVENTIONS["baker"], (heading, attitude, bank), degrees)


def matrix_to_heading_attitude_bank(
    R: ArrayLike,
    *,
    degrees: bool = False,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
    warn: bool = True,
) -> HeadingAttitudeBank:
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
    HeadingAttitudeBank
        ``(heading, attitude, bank)``, arrays of the leading shape of ``R``. Heading and bank in
        (-π, π], attitude in [-π/2, π/2]. At a pole (attitude ±90°) bank is 0 and
        heading = atan2(m02, m22) carries the whole turn about the vertical.

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
    return HeadingAttitudeBank(
        *_matrix_to_named(CONVENTIONS["baker"], R, degrees, validate, repair, atol, warn)
    )
