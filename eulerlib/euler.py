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

* the middle angle comes from ``atan2(M[0,2], hypot(M[0,0], M[0,1]))``: an ``atan2`` of a sine and
  a cosine, accurate to the last bit even next to ±90°, where ``asin(M[0,2])`` loses half the
  digits;
* the first angle comes from ``atan2(-M[1,2], M[2,2])``;
* the third angle is *solved from the first* (the approach of K. Shoemake, Graphics Gems IV):
  rotating rows 1 and 2 back by the first angle leaves ``[sin c, cos c]`` exactly, so the three
  angles always rebuild the matrix they came from, whatever rounding did to the first angle.

Gimbal lock
-----------
When the middle angle is ±90° (Tait–Bryan) or 0°/180° (proper Euler), the first and third axes
line up and only their sum or difference is defined (Rose, eq 4; Baker's two poles). eulerlib's
policy, the same for every spelling of a convention: **the first angle of the intrinsic form is
set to 0** and the third carries the whole turn. For an extrinsic sequence, whose angles are
the intrinsic ones reversed, that is the *last* angle. So ``matrix_to_euler(R, "ZYX")`` and
``matrix_to_euler(R, "xyz")[..., ::-1]`` are identical, at lock too, and for ``"ZYX"`` the policy
is Rose's choice (yaw = 0). A matrix counts as locked when its middle angle lies within
:data:`GIMBAL_LOCK_TOLERANCE` radians of the singular value; zeroing the first angle then
changes the rebuilt matrix by less than that tolerance. A :class:`GimbalLockWarning` reports it
once per call, and :func:`gimbal_lock_status` returns it as data.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from typing import Literal, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._blocks import block_slices
from eulerlib._trig import sin_cos
from eulerlib._validation import ROTATION_ATOL, as_vectors, matrix_entry_blocks
from eulerlib.sequences import Sequence, parse_sequence

__all__ = [
    "GIMBAL_LOCK_TOLERANCE",
    "GimbalLockStatus",
    "GimbalLockWarning",
    "euler_to_matrix",
    "gimbal_lock_status",
    "matrix_to_euler",
]

#: A matrix is in gimbal lock when its middle angle is within this many radians of the
#: singular value (±π/2 for Tait–Bryan, 0 or π for proper Euler). 2⁻⁴⁹ ≈ 1.8e-15 is eight units
#: in the last place of 1: about four times the distance that ordinary rounding noise puts
#: between a lock matrix and the lock (measured on ``Q @ Q.T @ R``), and small enough that
#: setting the first angle to 0 moves no entry of the rebuilt matrix by more than 2 × 2⁻⁴⁹.
GIMBAL_LOCK_TOLERANCE = 2.0**-49


class GimbalLockWarning(UserWarning):
    """A matrix was in gimbal lock: one Euler angle was set to 0 by the documented policy."""


class GimbalLockStatus(NamedTuple):
    """Gimbal lock as data, one entry per rotation.

    Attributes
    ----------
    locked : bool or ndarray of bool
        True where the middle angle is within the tolerance of its singular value.
    distance : float or ndarray
        How far the middle angle is from the nearest singular value (radians, or degrees if
        requested); 0 at lock, at most π/2.
    """

    locked: NDArray[np.bool_]
    distance: NDArray[np.float64]


def _frame(seq: Sequence) -> tuple[tuple[int, int, int], tuple[float, float, float]]:
    """Signed permutation ``P`` (as index map and column signs) with ``R = P M Pᵀ``.

    ``P`` sends x to the first axis ``i`` and y to the second axis ``j`` of the intrinsic
    sequence, and z to ``eᵢ × eⱼ``, which is ``±`` the remaining axis; so ``P`` is a rotation and
    ``M`` is the same product of rotations about x, y (and z or x) as ``R`` is about ``i``, ``j``.
    """
    i, j, _ = seq.intrinsic_axes
    k = 3 - i - j
    sign = 1.0 if (j - i) % 3 == 1 else -1.0  # eᵢ × eⱼ = +e_k for cyclic order
    return (i, j, k), (1.0, 1.0, sign)


def euler_to_matrix(
    angles: ArrayLike, seq: str = "ZYX", *, degrees: bool = False
) -> NDArray[np.float64]:
    """Rotation matrices from Euler angles in any of the 24 conventions.

    Parameters
    ----------
    angles : array_like, shape (..., 3)
        Angle ``i`` goes with letter ``i`` of ``seq``. Leading axes are batch axes.
    seq : str, optional
        Axis sequence as in SciPy's ``Rotation.from_euler``: uppercase intrinsic (moving axes),
        lowercase extrinsic (fixed axes). Default ``"ZYX"``: yaw, pitch, roll (Rose 2015).
    degrees : bool, optional
        Read ``angles`` in degrees (multiples of 90° then give exact zeros and ones).

    Returns
    -------
    ndarray, shape (..., 3, 3)
        The active rotation matrices.

    Raises
    ------
    TypeError
        If ``angles`` is not numeric or ``seq`` is not a string.
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
    parsed = parse_sequence(seq)
    values = as_vectors(angles, "angles")
    if not parsed.intrinsic:
        values = values[..., ::-1]
    flat = values.reshape(-1, 3)
    R = np.empty((flat.shape[0], 3, 3))
    for block in block_slices(flat.shape[0]):
        _fill_matrices(R[block], flat[block], parsed, degrees)
    return R.reshape(*values.shape[:-1], 3, 3)


def _fill_matrices(
    out: NDArray[np.float64], values: NDArray[np.float64], parsed: Sequence, degrees: bool
) -> None:
    """Write into ``out`` (shape (n, 3, 3)) the matrices of intrinsic angles ``values`` (n, 3)."""
    (i, j, k), sign = _frame(parsed)
    s, c = sin_cos(values, degrees)
    s1, s2, s3 = s[:, 0], s[:, 1], s[:, 2]
    c1, c2, c3 = c[:, 0], c[:, 1], c[:, 2]
    if parsed.proper:  # M = R_x(a) R_y(b) R_x(c)
        M = (
            (c2, s2 * s3, s2 * c3),
            (s1 * s2, c1 * c3 - s1 * c2 * s3, -c1 * s3 - s1 * c2 * c3),
            (-c1 * s2, s1 * c3 + c1 * c2 * s3, c1 * c2 * c3 - s1 * s3),
        )
    else:  # M = R_x(a) R_y(b) R_z(±c): the third axis is ±z
        s3 = s3 * sign[2]
        M = (
            (c2 * c3, -c2 * s3, s2),
            (c1 * s3 + s1 * s2 * c3, c1 * c3 - s1 * s2 * s3, -s1 * c2),
            (s1 * s3 - c1 * s2 * c3, s1 * c3 + c1 * s2 * s3, c1 * c2),
        )
    index = (i, j, k)
    for r in range(3):
        for col in range(3):
            flip = sign[r] * sign[col]
            out[:, index[r], index[col]] = M[r][col] if flip > 0 else -M[r][col]
    out += 0.0  # turns every -0.0 into 0.0, so that a quarter turn prints cleanly


_Entry = Callable[[int, int], NDArray[np.float64]]


def _relabelled(entries: NDArray[np.float64], parsed: Sequence) -> tuple[_Entry, float]:
    """Entry accessor ``m(r, c)`` of ``M = Pᵀ R P`` and the sign of the third axis.

    ``entries`` holds the matrices ``R`` as laid out by ``_validation.matrix_entries``.
    """
    index, sign = _frame(parsed)

    def m(r: int, c: int) -> NDArray[np.float64]:
        entry: NDArray[np.float64] = entries[3 * index[r] + index[c]]
        return entry if sign[r] * sign[c] > 0 else -entry

    return m, sign[2]


def _length(a: NDArray[np.float64], b: NDArray[np.float64]) -> NDArray[np.float64]:
    """``sqrt(a² + b²)`` for entries of a rotation matrix.

    The entries are at most about 1, so the squares cannot overflow, and an entry small enough
    for its square to underflow changes no angle; this is about six times faster than
    ``np.hypot``, which guards against both at every element.
    """
    result: NDArray[np.float64] = np.sqrt(a * a + b * b)
    return result


def _middle(m: _Entry, proper: bool) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Middle angle and its distance from the singular value, both by atan2."""
    if proper:
        sine = _length(m(0, 1), m(0, 2))
        cosine = m(0, 0)
        return np.arctan2(sine, cosine), np.arctan2(sine, np.abs(cosine))
    sine = m(0, 2)
    cosine = _length(m(0, 0), m(0, 1))
    return np.arctan2(sine, cosine), np.arctan2(cosine, np.abs(sine))


def intrinsic_angles(
    entries: NDArray[np.float64],
    parsed: Sequence,
    zero: Literal["first", "third"] = "first",
    tolerance: float = GIMBAL_LOCK_TOLERANCE,
) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """Angles of the *intrinsic* form of ``parsed`` for validated matrices.

    ``entries`` holds the matrices as laid out by ``_validation.matrix_entries``.
    Returns the angles, shape ``(..., 3)`` in intrinsic order, and the lock mask. At lock the
    angle named by ``zero`` is set to 0 and the other is solved from the matrix; away from lock
    the angle named by ``zero`` comes from its own ratio and the other is solved from it.
    """
    m, third_sign = _relabelled(entries, parsed)
    middle, distance = _middle(m, parsed.proper)
    locked = distance <= tolerance
    if parsed.proper:  # M = R_x(a) R_y(b) R_x(c)
        if zero == "first":
            first = np.where(locked, 0.0, np.arctan2(m(1, 0), -m(2, 0)))
            s1, c1 = np.sin(first), np.cos(first)
            third = np.arctan2(-(c1 * m(1, 2) + s1 * m(2, 2)), c1 * m(1, 1) + s1 * m(2, 1))
        else:
            third = np.where(locked, 0.0, np.arctan2(m(0, 1), m(0, 2)))
            s3, c3 = np.sin(third), np.cos(third)
            first = np.arctan2(c3 * m(2, 1) - s3 * m(2, 2), c3 * m(1, 1) - s3 * m(1, 2))
    else:  # M = R_x(a) R_y(b) R_z(c)
        if zero == "first":
            first = np.where(locked, 0.0, np.arctan2(-m(1, 2), m(2, 2)))
            s1, c1 = np.sin(first), np.cos(first)
            third = np.arctan2(c1 * m(1, 0) + s1 * m(2, 0), c1 * m(1, 1) + s1 * m(2, 1))
        else:
            third = np.where(locked, 0.0, np.arctan2(-m(0, 1), m(0, 0)))
            s3, c3 = np.sin(third), np.cos(third)
            first = np.arctan2(s3 * m(2, 0) + c3 * m(2, 1), s3 * m(1, 0) + c3 * m(1, 1))
        third = third * third_sign
    angles = np.stack([first, middle, third], axis=-1)
    angles += 0.0  # turns every -0.0 into 0.0
    return angles, locked


def lock_message(parsed: Sequence, count: int, total: int, zeroed: int) -> str:
    """Words for a :class:`GimbalLockWarning`; ``zeroed`` is the position (0 or 2) set to 0."""
    other = 2 - zeroed
    singular = "0° or 180°" if parsed.proper else "±90°"
    return (
        f"gimbal lock in {count} of {total} rotation(s) for sequence {parsed.seq!r}: the middle "
        f"angle is {singular}, so angles 1 and 3 turn about the same axis and only their "
        f"combination is defined; angle {zeroed + 1} was set to 0 and angle {other + 1} "
        "carries the turn"
    )


def angles_from_matrix(
    R: ArrayLike,
    parsed: Sequence,
    zeroed: int,
    *,
    degrees: bool,
    validate: bool,
    repair: bool,
    atol: float,
    warn: bool,
    describe: Callable[[int, int], str] | None = None,
    stacklevel: int = 3,
) -> NDArray[np.float64]:
    """The one body behind every matrix-to-angles function of eulerlib.

    ``zeroed`` is the position, in the order the angles are written (0 for the first, 2 for the
    third), of the angle set to 0 at gimbal lock: :func:`matrix_to_euler` passes the first angle
    of the intrinsic form, Baker's named function passes bank. ``describe(count, total)`` words
    the warning (default :func:`lock_message`); ``stacklevel`` is counted from here, so 3 points
    at whoever called the public function that calls this one.
    """
    if zeroed not in (0, 2):
        raise ValueError(f"only the first (0) or third (2) angle can be zeroed, got {zeroed!r}")
    lead, blocks = matrix_entry_blocks(R, "R", validate=validate, repair=repair, atol=atol)
    zero: Literal["first", "third"] = "first" if (zeroed == 0) == parsed.intrinsic else "third"
    count = math.prod(lead)
    flat_angles, flat_locked = np.empty((count, 3)), np.empty(count, dtype=bool)
    for block, entries in blocks:
        flat_angles[block], flat_locked[block] = intrinsic_angles(entries, parsed, zero)
    angles, locked = flat_angles.reshape(*lead, 3), flat_locked.reshape(lead)
    if not parsed.intrinsic:
        angles = angles[..., ::-1]
    if warn and np.any(locked):
        count, total = int(np.count_nonzero(locked)), int(locked.size)
        words = describe(count, total) if describe else lock_message(parsed, count, total, zeroed)
        warnings.warn(words, GimbalLockWarning, stacklevel=stacklevel)
    return np.degrees(angles) if degrees else angles


def matrix_to_euler(
    R: ArrayLike,
    seq: str = "ZYX",
    *,
    degrees: bool = False,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
    warn: bool = True,
) -> NDArray[np.float64]:
    """Euler angles of rotation matrices, in any of the 24 conventions.

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotation matrices. Leading axes are batch axes.
    seq : str, optional
        Axis sequence (see :func:`euler_to_matrix`). Default ``"ZYX"``: yaw, pitch, roll.
    degrees : bool, optional
        Return degrees instead of radians.
    validate : bool, optional
        Check that every matrix is a rotation within ``atol`` (default). ``False`` skips the
        check for speed; shape and finiteness are still checked.
    repair : bool, optional
        Replace each matrix by the nearest rotation (SVD) before converting, for matrices that
        drifted from orthogonality.
    atol : float, optional
        Tolerance of the rotation check on ``max |R Rᵀ − I|``.
    warn : bool, optional
        Emit one :class:`GimbalLockWarning` if any matrix is in gimbal lock (default).

    Returns
    -------
    ndarray, shape (..., 3)
        Angle ``i`` goes with letter ``i`` of ``seq``. First and third angles lie in [-π, π];
        the middle angle in [-π/2, π/2] (Tait–Bryan) or [0, π] (proper Euler).

    Raises
    ------
    TypeError
        If ``R`` is not numeric or ``seq`` is not a string.
    ValueError
        If ``R`` has a wrong shape, non-finite entries, is a reflection or is not orthogonal
        within ``atol``, or ``seq`` is invalid.

    Warns
    -----
    GimbalLockWarning
        Once per call when some matrix is in gimbal lock; the first angle of the intrinsic form
        (the last angle of an extrinsic sequence) is then set to 0.

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
    parsed = parse_sequence(seq)
    return angles_from_matrix(
        R,
        parsed,
        0 if parsed.intrinsic else 2,
        degrees=degrees,
        validate=validate,
        repair=repair,
        atol=atol,
        warn=warn,
    )


def gimbal_lock_status(
    R: ArrayLike,
    seq: str = "ZYX",
    *,
    degrees: bool = False,
    tolerance: float = GIMBAL_LOCK_TOLERANCE,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
) -> GimbalLockStatus:
    """Whether each matrix is in gimbal lock for ``seq``, and how far from it.

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotation matrices.
    seq : str, optional
        Axis sequence (see :func:`euler_to_matrix`). Default ``"ZYX"``.
    degrees : bool, optional
        Give ``distance`` in degrees (and read ``tolerance`` in degrees).
    tolerance : float, optional
        A matrix is locked when ``distance <= tolerance``. Default
        :data:`GIMBAL_LOCK_TOLERANCE` radians, the threshold :func:`matrix_to_euler` uses.
    validate, repair, atol
        As in :func:`matrix_to_euler`.

    Returns
    -------
    GimbalLockStatus
        ``(locked, distance)``: boolean(s), and the distance of the middle angle from the
        nearest singular value (±90° for Tait–Bryan, 0° or 180° for proper Euler).

    Notes
    -----
    The distance is computed as ``atan2(cos, |sin|)`` of the middle angle (Tait–Bryan) or
    ``atan2(|sin|, |cos|)`` (proper Euler), which stays accurate when it is tiny, where
    ``π/2 − |asin(r31)|`` would be swamped by rounding.

    Examples
    --------
    >>> R = euler_to_matrix([[0, 89, 0], [0, 90, 0]], "ZYX", degrees=True)
    >>> status = gimbal_lock_status(R, "ZYX", degrees=True)
    >>> status.locked
    array([False,  True])
    >>> status.distance.round(9)
    array([1., 0.])
    """
    parsed = parse_sequence(seq)
    lead, blocks = matrix_entry_blocks(R, "R", validate=validate, repair=repair, atol=atol)
    flat_distance = np.empty(math.prod(lead))
    for block, entries in blocks:
        m, _ = _relabelled(entries, parsed)
        _, flat_distance[block] = _middle(m, parsed.proper)
    distance: NDArray[np.float64] = flat_distance.reshape(lead)
    if degrees:
        distance = np.degrees(distance)
    return GimbalLockStatus(distance <= tolerance, distance)
