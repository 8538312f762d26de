"""Euler angles ⇄ rotation matrices, for all 24 conventions, exact at gimbal lock.

The convention
--------------
Vectors are columns, the coordinate system is right-handed, positive angles follow the
right-hand rule, and rotations are *active*: ``R @ v`` is the vector ``v`` turned. A sequence
such as ``"ZYX"`` names three elementary rotations (see :mod:`eulerlib.elementary` and
:mod:`eulerlib.sequences`):

* intrinsic (uppercase), angles ``(a, b, c)``: ``R = R_Z(a) @ R_Y(b) @ R_X(c)``: turn by ``a``
  about z, then by ``b`` about the *moved* y, then by ``c`` about the twice-moved x;
* extrinsic (lowercase), angles ``(a, b, c)``: ``R = R_X(c) @ R_Y(b) @ R_Z(a)``
  for ``"zyx"``: turn about the *fixed* z, then the fixed y, then the fixed x.

So ``"ZYX"`` with ``(yaw, pitch, roll)`` is D. Rose's yaw-pitch-roll (2015, Part 2, eq 2), and
``"YZX"`` with ``(heading, attitude, bank)`` is M. Baker's heading-attitude-bank.

From the matrix back to the angles
----------------------------------
Every sequence is reduced to one of two shapes, x-y-z (Tait–Bryan) or x-y-x (proper Euler), by
relabelling the axes with a signed permutation ``P`` that is itself a rotation: ``R = P M Pᵀ``.
Then, for x-y-z,

* the middle angle comes from ``atan2(M[0,2], sqrt(M[0,0]² + M[0,1]²))``: an ``atan2`` of a sine and
  a cosine, accurate to the last bit even next to ±90°, where ``asin(M[0,2])`` loses half the
  digits;
* the first angle comes from ``atan2(-M[1,2], M[2,2])``;
* the third angle is *solved from the first* (the approach of K. Shoemake, Graphics Gems IV):
  rotating rows 1 and 2 back by the first angle leaves ``[sin c, cos c]`` exactly, so the three
  angles always rebuild the matrix they came from, whatever rounding did to the first angle.

Gimbal lock
-----------
When the middle angle is ±90° (Tait–Bryan) or 0°/180° (proper Euler), the first and third axes
line up and only their sum or difference is defined (Rose, eq 4; Baker's two poles). One angle
is then set to 0 and the other carries the whole turn. Which one is the convention's policy
(:mod:`eulerlib.conventions`); for a bare sequence it is **the first angle of the intrinsic
form**, the *last* angle of an extrinsic sequence, so ``matrix_to_euler(R, "ZYX")`` and
``matrix_to_euler(R, "xyz")[..., ::-1]`` are identical, at lock too, and for ``"ZYX"`` the policy
is Rose's choice (yaw = 0). A matrix counts as locked when its middle angle lies within
:data:`eulerlib.GIMBAL_LOCK_TOLERANCE` radians of the singular value; zeroing one angle then
changes the rebuilt matrix by less than that tolerance. A :class:`eulerlib.GimbalLockWarning`
reports it once per call, and :func:`eulerlib.gimbal_lock_status` returns it as data (see
:mod:`eulerlib.gimbal_lock`).

Every function here also takes a preset name (``"rose"``, ``"baker"``, ``"ros"``) wherever it
takes a ``seq``, with the preset's angle order and lock policy.
"""

from __future__ import annotations

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
    as_vectors,
    check_flag,
    rotation_check,
)
from eulerlib.conventions import Convention, get_convention

__all__ = ["euler_to_matrix", "matrix_to_euler"]


def euler_to_matrix(
    angles: ArrayLike, seq: str | Convention = "ZYX", *, degrees: bool = False
) -> NDArray[np.float64]:
    """Rotation matrices from Euler angles in any of the 24 conventions.

    Parameters
    ----------
    angles : array_like, shape (..., 3)
        Angle ``i`` goes with letter ``i`` of ``seq``. Leading axes are batch axes.
    seq : str or Convention, optional
        Axis sequence as in SciPy's ``Rotation.from_euler``: uppercase intrinsic (moving axes),
        lowercase extrinsic (fixed axes); or a preset name such as ``"rose"`` or ``"baker"``.
        Default ``"ZYX"``: yaw, pitch, roll (Rose 2015).
    degrees : bool, optional
        Read ``angles`` in degrees. Degrees are reduced modulo 360° exactly, so angles of any
        size are exact, and multiples of 90° give exact zeros and ones.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        The active rotation matrices.

    Raises
    ------
    TypeError
        If ``angles`` is not real numbers, ``seq`` is not a string, or ``degrees`` not a bool.
    ValueError
        If ``angles`` has a wrong shape or non-finite values, or ``seq`` is invalid.

    Notes
    -----
    For ``"ZYX"`` and angles (w, v, u) = (yaw, pitch, roll) this is Rose (2015), eq 2:
    ``R = R_z(w) R_y(v) R_x(u)``, whose first column is ``(cos v cos w, cos v sin w, -sin v)``.
    The product is evaluated in closed form, not by multiplying three matrices.

    Examples
    --------
    >>> import numpy as np
    >>> R = euler_to_matrix([90, 0, 0], "ZYX", degrees=True)   # yaw 90°: x turns into y
    >>> R @ np.array([1.0, 0.0, 0.0])
    array([0., 1., 0.])
    >>> np.allclose(euler_to_matrix([0.1, 0.2, 0.3], "ZYX"),
    ...             euler_to_matrix([0.3, 0.2, 0.1], "xyz"))
    True
    >>> euler_to_matrix(np.zeros((4, 2, 3))).shape
    (4, 2, 3, 3)
    """
    convention = get_convention(seq)
    in_degrees = check_flag(degrees, "degrees")
    compiled = compiled_matrices(angles, convention, in_degrees)
    if compiled is not None:  # compiled kernels, or the paths below
        return compiled
    single = _scalar.vector(angles)
    if single is not None:  # one rotation: the same formulas in Python floats
        entries = angles_to_entries(convention.to_intrinsic(single), convention.parsed, in_degrees)
        return _scalar.as_array(entries, (3, 3))
    values = as_vectors(angles, "angles")
    return angles_to_matrices(values, convention, in_degrees)


def matrix_to_euler(
    R: ArrayLike,
    seq: str | Convention = "ZYX",
    *,
    degrees: bool = False,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
    warn: bool = True,
) -> NDArray[np.float64]:
    """Euler angles of rotation matrices, in any of the 24 conventions or a preset.

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotation matrices. Leading axes are batch axes.
    seq : str or Convention, optional
        Axis sequence or preset (see :func:`euler_to_matrix`). Default ``"ZYX"``: yaw, pitch,
        roll.
    degrees : bool, optional
        Return degrees instead of radians.
    validate : bool, optional
        Check that every matrix is a rotation within ``atol`` (default). ``False`` skips the
        check for speed; shape and finiteness are still checked.
    repair : bool, optional
        Replace each matrix by the nearest rotation (SVD) before converting, for matrices that
        drifted from orthogonality; a matrix too far from any rotation is refused.
    atol : float, optional
        Tolerance of the rotation check on ``max |R Rᵀ − I|``.
    warn : bool, optional
        Emit one :class:`eulerlib.GimbalLockWarning` if any matrix is in gimbal lock (default).

    Returns
    -------
    ndarray, shape (..., 3)
        Angle ``i`` goes with letter ``i`` of ``seq``. First and third angles lie in (-π, π];
        the middle angle in [-π/2, π/2] (Tait–Bryan) or [0, π] (proper Euler).

    Raises
    ------
    TypeError
        If ``R`` is not real numbers, ``seq`` is not a string, or a flag is not a bool.
    ValueError
        If ``R`` has a wrong shape, non-finite entries, is a reflection or is not orthogonal
        within ``atol``, ``seq`` is invalid, or ``atol`` is not a finite number ≥ 0.

    Warns
    -----
    GimbalLockWarning
        Once per call when some matrix is in gimbal lock; the angle the convention's policy
        names (for a bare sequence, the first angle of the intrinsic form) is then set to 0.

    Notes
    -----
    For ``"ZYX"`` this is Rose (2015), eq 3 (yaw from ``atan2(r21, r11)``, roll from
    ``atan2(r32, r33)``) and eq 4 at lock, but computed so that the result is accurate to a few
    units in the last place everywhere: the pitch by ``atan2`` of a sine and a cosine instead of
    ``asin(r31)``, the roll solved from the yaw, and lock detected by a tolerance instead of an
    exact ``r31 == ±1`` test. See the module docstring.

    Examples
    --------
    >>> import numpy as np
    >>> R = euler_to_matrix([30, 20, 10], "ZYX", degrees=True)
    >>> matrix_to_euler(R, "ZYX", degrees=True)
    array([30., 20., 10.])
    >>> matrix_to_euler(R, "xyz", degrees=True)   # the same rotation, fixed axes
    array([10., 20., 30.])
    >>> import warnings
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     angles = matrix_to_euler(euler_to_matrix([30, 90, 10], degrees=True), degrees=True)
    >>> angles   # locked: yaw set to 0, roll carries roll − yaw = −20°
    array([  0.,  90., -20.])
    >>> caught[0].category.__name__
    'GimbalLockWarning'
    """
    convention = get_convention(seq)
    in_degrees = check_flag(degrees, "degrees")
    check = rotation_check(validate, repair, atol)
    warn_lock = check_flag(warn, "warn")
    compiled = compiled_angles(R, convention, check, in_degrees)
    if compiled is not None:  # compiled kernels, or the paths below (which warn at lock)
        return compiled
    single = one_matrix_to_angles(R, convention, check, in_degrees)
    if single is not None:
        return single
    matrices = as_matrix_stack(R, "R")
    return matrices_to_angles(matrices, convention, check, in_degrees, warn_lock)
