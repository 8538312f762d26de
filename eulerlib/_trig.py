"""Sine and cosine of angles given in radians or degrees, exact for degrees of any size.

For degrees the angle is first reduced modulo 360° with ``fmod``, which is exact in floating
point (the remainder of two floats is always representable), so ``1e20`` degrees is the
280° it really is, rather than whatever ``radians(1e20)`` rounds to. The remainder is then split
into the nearest multiple of 90° and a rest in [-45°, 45°]: ``rot_z(90, degrees=True)`` gets
exact zeros and ones rather than ``6.1e-17``, because the rest of a multiple of 90° is exactly
0, and the quarter turns are applied by swapping and negating sine and cosine, which is exact.
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
    reduced = np.fmod(angle, 360.0)  # exact
    quarter = np.round(reduced / 90.0)
    # reduced − 90·quarter is exact: both are below 360 in size and 90·quarter is exact
    remainder = np.radians(reduced - 90.0 * quarter)
    s, c = np.sin(remainder), np.cos(remainder)
    turn = np.mod(quarter, 4.0)
    # sin(r + k·90°), cos(r + k·90°) for k = 0, 1, 2, 3
    sine = np.select([turn == 0, turn == 1, turn == 2], [s, c, -s], -c)
    cosine = np.select([turn == 0, turn == 1, turn == 2], [c, -s, -c], s)
    return sine + 0.0, cosine + 0.0  # + 0.0 turns -0.0 into 0.0
