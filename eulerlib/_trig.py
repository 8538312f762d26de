"""Sine and cosine of angles given in radians or degrees.

For degrees the angle is first reduced exactly to the nearest multiple of 90° plus a remainder
in [-45°, 45°], so that ``rot_z(90, degrees=True)`` has exact zeros and ones rather than
``6.1e-17``: the remainder of a multiple of 90° is exactly 0, and the quarter turns are
applied by swapping and negating sine and cosine, which is exact.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray


def sin_cos(
    angle: NDArray[np.float64], degrees: bool
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Return ``(sin(angle), cos(angle))``, with ``angle`` in degrees when ``degrees`` is true."""
    if not degrees:
        return np.sin(angle), np.cos(angle)
    quarter = np.round(angle / 90.0)
    # angle − 90·quarter is exact: both are floats of similar size and 90·quarter is exact
    remainder = np.radians(angle - 90.0 * quarter)
    s, c = np.sin(remainder), np.cos(remainder)
    turn = np.mod(quarter, 4.0)
    # sin(r + k·90°), cos(r + k·90°) for k = 0, 1, 2, 3
    sine = np.select([turn == 0, turn == 1, turn == 2], [s, c, -s], -c)
    cosine = np.select([turn == 0, turn == 1, turn == 2], [c, -s, -c], s)
    return sine + 0.0, cosine + 0.0  # + 0.0 turns -0.0 into 0.0
