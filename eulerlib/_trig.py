"""Sine and cosine of angles given in radians or degrees, exact for degrees of any size.

For degrees the angle is first reduced modulo 360° with ``fmod``, which is exact in floating
point (the remainder of two floats is always representable), so ``1e20`` degrees is the
280° it really is, rather than whatever ``radians(1e20)`` rounds to. The remainder is then split
into the nearest multiple of 90° and a rest in [-45°, 45°]: ``rot_z(90, degrees=True)`` gets
exact zeros and ones rather than ``6.1e-17``, because the rest of a multiple of 90° is exactly
0, and the quarter turns are applied by swapping and negating sine and cosine, which is exact.

A turn by θ about an axis needs only the direction of ``(cos(θ/2), sin(θ/2))``, which
:func:`half_angle_pair` gives as ``(1, tan(θ/2))``: one tangent instead of a sine and a cosine
(several times faster in numpy, and as accurate). In degrees the same exact reduction applies:
the quarter turns ``k · 90°`` have the exact directions ``(1, 0)``, ``(1, 1)``, ``(0, 1)``,
``(-1, 1)``, and the rest is turned on by the tangent of half the remainder.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray


def sin_cos(
    angle: NDArray[np.float64], degrees: bool
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Return ``(sin(angle), cos(angle))``, with ``angle`` in degrees when ``degrees`` is true.

    Examples
    --------
    >>> import numpy as np
    >>> s, c = sin_cos(np.array([90.0, 1e20]), degrees=True)
    >>> s.round(15), c.round(15)      # 1e20° is 280° exactly
    (array([ 1.        , -0.98480775]), array([0.        , 0.17364818]))
    """
    if not degrees:
        return np.sin(angle), np.cos(angle)
    quarter, remainder = quarter_turns(angle)
    s, c = np.sin(remainder), np.cos(remainder)
    turn = np.mod(quarter, 4.0)
    # sin(r + k·90°), cos(r + k·90°) for k = 0, 1, 2, 3
    sine = np.select([turn == 0, turn == 1, turn == 2], [s, c, -s], -c)
    cosine = np.select([turn == 0, turn == 1, turn == 2], [c, -s, -c], s)
    return sine + 0.0, cosine + 0.0  # + 0.0 turns -0.0 into 0.0


def quarter_turns(angle: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """``angle`` in degrees as ``k · 90° + r`` exactly: the integers ``k`` (as floats, in
    [-4, 4]) and the rests ``r`` in [-45°, 45°], converted to radians.

    Examples
    --------
    >>> import numpy as np
    >>> quarter, rest = quarter_turns(np.array([90.0, 1e20, -100.0]))
    >>> quarter, np.degrees(rest).round(12)   # 1e20° is 280° = 3 · 90° + 10°
    (array([ 1.,  3., -1.]), array([  0.,  10., -10.]))
    """
    reduced = np.fmod(angle, 360.0)  # exact
    quarter = np.round(reduced / 90.0)
    # reduced − 90·quarter is exact: both are below 360 in size and 90·quarter is exact
    return quarter, np.radians(reduced - 90.0 * quarter)


# (cos, sin) of k · 45° times √2 for odd k, by k mod 4: exact directions of the quarter turns
_HALF_QUARTER_COS = np.array([1.0, 1.0, 0.0, -1.0])
_HALF_QUARTER_SIN = np.array([0.0, 1.0, 1.0, 1.0])


def half_angle_pair(
    angle: NDArray[np.float64], degrees: bool
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """``(a, b)``, a positive multiple of ``(cos(θ/2), sin(θ/2))`` for the angles θ.

    ``(1, tan(θ/2))`` in radians: never both 0, and no larger than about 1e18 for any float.
    In degrees, ``θ = k · 90° + r`` exactly and ``(a, b)`` is the exact direction of ``k · 45°``
    turned by ``r / 2``, so that multiples of 90° give exact small integers.

    Examples
    --------
    >>> import numpy as np
    >>> a, b = half_angle_pair(np.array([90.0, 180.0, 1e20]), degrees=True)
    >>> a[:2], b[:2]                       # half of 90° and of 180°: exactly (1, 1) and (0, 1)
    (array([1., 0.]), array([1., 1.]))
    >>> np.degrees(np.arctan2(b, a))       # the directions; 1e20° is 280°, half of it 140°
    array([ 45.,  90., 140.])
    """
    if not degrees:
        return np.ones_like(angle), np.tan(0.5 * angle)
    quarter, remainder = quarter_turns(angle)
    turn = np.mod(quarter, 4.0).astype(np.intp)
    c, s = _HALF_QUARTER_COS[turn], _HALF_QUARTER_SIN[turn]
    t = np.tan(0.5 * remainder)
    # (c + i s)(1 + i t): turn the quarter turn's direction by half the remainder
    return c - s * t + 0.0, s + c * t + 0.0
