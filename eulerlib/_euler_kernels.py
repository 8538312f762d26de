"""The arithmetic of Euler angles, on one block of checked values (see :mod:`eulerlib.euler`).

Nothing here checks its input: the public functions did that once. Every function works on a
block of a few thousand rotations laid out for element-wise arithmetic, and the loops of the
public functions run over blocks, never over rotations.

Every sequence is reduced to one of two shapes, x-y-z (Tait–Bryan) or x-y-x (proper Euler), by
relabelling the axes with a signed permutation ``P`` that is itself a rotation: ``R = P M Pᵀ``.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from eulerlib._sequences import Sequence
from eulerlib._trig import sin_cos

Entry = Callable[[int, int], NDArray[np.float64]]


def frame(parsed: Sequence) -> tuple[tuple[int, int, int], tuple[float, float, float]]:
    """Signed permutation ``P`` (as index map and column signs) with ``R = P M Pᵀ``.

    ``P`` sends x to the first axis ``i`` and y to the second axis ``j`` of the intrinsic
    sequence, and z to ``eᵢ × eⱼ``, which is ``±`` the remaining axis; so ``P`` is a rotation and
    ``M`` is the same product of rotations about x, y (and z or x) as ``R`` is about ``i``, ``j``.
    """
    i, j, _ = parsed.intrinsic_axes
    k = 3 - i - j
    sign = 1.0 if (j - i) % 3 == 1 else -1.0  # eᵢ × eⱼ = +e_k for cyclic order
    return (i, j, k), (1.0, 1.0, sign)


def fill_matrices(
    out: NDArray[np.float64], values: NDArray[np.float64], parsed: Sequence, degrees: bool
) -> None:
    """Write into ``out`` (shape (n, 3, 3)) the matrices of intrinsic angles ``values`` (n, 3)."""
    (i, j, k), sign = frame(parsed)
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


def relabelled(entries: NDArray[np.float64], parsed: Sequence) -> tuple[Entry, float]:
    """Entry accessor ``m(r, c)`` of ``M = Pᵀ R P`` and the sign of the third axis.

    ``entries`` holds the matrices ``R`` as laid out by ``_validation.matrix_entries``.
    """
    index, sign = frame(parsed)

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


def middle_angle(m: Entry, proper: bool) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Middle angle and its distance from the nearest singular value, both by ``atan2``.

    The distance is ``atan2(cos, |sin|)`` of the middle angle (Tait–Bryan) or
    ``atan2(|sin|, |cos|)`` (proper Euler), which stays accurate when it is tiny, where
    ``π/2 − |asin(r31)|`` would be swamped by rounding.
    """
    if proper:
        sine = _length(m(0, 1), m(0, 2))
        cosine = m(0, 0)
        return np.arctan2(sine, cosine), np.arctan2(sine, np.abs(cosine))
    sine = m(0, 2)
    cosine = _length(m(0, 0), m(0, 1))
    return np.arctan2(sine, cosine), np.arctan2(cosine, np.abs(sine))


def lock_distance(entries: NDArray[np.float64], parsed: Sequence) -> NDArray[np.float64]:
    """Distance (radians) of each matrix's middle angle from the nearest singular value."""
    m, _ = relabelled(entries, parsed)
    return middle_angle(m, parsed.proper)[1]


def direction(
    y: NDArray[np.float64], x: NDArray[np.float64], locked: NDArray[np.bool_]
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """``(sin, cos)`` of ``atan2(y, x)`` as ``(y, x) / sqrt(x² + y²)``, and ``(0, 1)`` where
    ``locked`` (the angle set to 0) or where ``x = y = 0``.

    The same numbers as the sine and cosine of the angle to a unit in the last place, for a
    square root and two divisions instead of a sine and a cosine, which cost about ten times
    as much in numpy (its float64 ``sin`` and ``cos`` are not vectorized).
    """
    length = _length(y, x)
    empty = locked | (length == 0.0)
    length[empty] = 1.0
    sine = y / length
    cosine = x / length
    sine[empty] = 0.0
    cosine[empty] = 1.0
    return sine, cosine


def intrinsic_angles(
    entries: NDArray[np.float64], parsed: Sequence, zero_first: bool, tolerance: float
) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """Angles of the *intrinsic* form of ``parsed``, and the lock mask, for checked matrices.

    ``entries`` holds the matrices as laid out by ``_validation.matrix_entries``. Returns the
    angles, shape ``(n, 3)`` in intrinsic order, and where the matrices are locked. At lock the
    first angle (``zero_first``) or the third is set to 0 and the other is solved from the
    matrix; away from lock that angle comes from its own ratio and the other is solved from it,
    so that the three angles always rebuild the matrix (K. Shoemake, Graphics Gems IV).
    """
    m, third_sign = relabelled(entries, parsed)
    middle, distance = middle_angle(m, parsed.proper)
    locked = distance <= tolerance
    # the outer angle read from its own ratio (y, x), 0 at lock
    if parsed.proper:
        y, x = (m(1, 0), -m(2, 0)) if zero_first else (m(0, 1), m(0, 2))
    else:
        y, x = (-m(1, 2), m(2, 2)) if zero_first else (-m(0, 1), m(0, 0))
    read = np.where(locked, 0.0, np.arctan2(y, x))
    sine, cosine = direction(y, x, locked)
    if parsed.proper:  # M = R_x(a) R_y(b) R_x(c)
        if zero_first:
            first, s1, c1 = read, sine, cosine
            third = np.arctan2(-(c1 * m(1, 2) + s1 * m(2, 2)), c1 * m(1, 1) + s1 * m(2, 1))
        else:
            third, s3, c3 = read, sine, cosine
            first = np.arctan2(c3 * m(2, 1) - s3 * m(2, 2), c3 * m(1, 1) - s3 * m(1, 2))
    else:  # M = R_x(a) R_y(b) R_z(c)
        if zero_first:
            first, s1, c1 = read, sine, cosine
            third = np.arctan2(c1 * m(1, 0) + s1 * m(2, 0), c1 * m(1, 1) + s1 * m(2, 1))
        else:
            third, s3, c3 = read, sine, cosine
            first = np.arctan2(s3 * m(2, 0) + c3 * m(2, 1), s3 * m(1, 0) + c3 * m(1, 1))
        third = third * third_sign
    angles = np.stack([first, middle, third], axis=-1)
    angles += 0.0  # turns every -0.0 into 0.0
    # atan2 gives −π where a sine came out as −0.0; a half turn is +π, so that the outer angles
    # lie in (−π, π] as documented
    angles[angles == -np.pi] = np.pi
    return angles, locked


def relabel_into(
    out: NDArray[np.float64], matrices: NDArray[np.float64], P: NDArray[np.float64]
) -> None:
    """Write ``P R Pᵀ`` for each ``R`` of ``matrices`` (n, 3, 3) into ``out``; ``P`` a signed
    permutation."""
    perm = np.argmax(np.abs(P), axis=1)
    signs = P[np.arange(3), perm]
    np.multiply(matrices[:, perm][:, :, perm], np.outer(signs, signs), out=out)
    out += 0.0  # no negative zeros
