"""Linear maps of huge vectors: the answer when it is a float, a clear refusal when it is not.

Rotating a point, and turning an angular velocity into Euler-angle rates or back, is linear in
one vector. With entries near the largest float (about 1.8e308) a partial sum inside such a map
may overflow although the answer does not: a row of a rotation, ``(0.6, 0.64, 0.48)``, times the
point ``(1.7e308, 1.7e308, -1.7e308)`` passes through ``1.24 · 1.7e308`` on its way to
``0.76 · 1.7e308``. And the answer itself may be beyond the range: the same point turned so
that it lies along an axis has a coordinate ``√3 · 1.7e308``.

So the map runs as usual, with overflow ignored, and one sum of the result tells whether all of
it is finite, which is the usual case and costs nothing more. Only the vectors whose result is
not finite are mapped again, scaled down by :data:`SCALE`, a power of two, which is exact, and
the result scaled back up. What is still infinite then is an answer beyond the range of float64,
and is refused with a ``ValueError`` that names the argument and the index.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from eulerlib._validation import _index_text

Array = NDArray[np.float64]

#: Scale of the second try: room for sums of up to 16 terms of the size of the input.
SCALE = 2.0**-4

_NONE = np.empty(0, dtype=np.intp)


def overflowed(result: Array) -> NDArray[np.intp]:
    """Flat indices of the vectors (along the last axis of ``result``) with an entry that is
    not finite: usually none, found by one sum.
    """
    with np.errstate(over="ignore", invalid="ignore"):
        if math.isfinite(float(np.sum(result))):
            return _NONE
    finite = np.isfinite(result).all(axis=-1).reshape(-1)
    return np.flatnonzero(~finite)


def rescaled(
    compute: Callable[[float], Array],
    rows: NDArray[np.intp],
    name: str,
    what: str,
    shape: tuple[int, ...],
    offset: int = 0,
) -> Array:
    """``compute(SCALE) / SCALE``: the vectors ``rows`` mapped again with their input scaled.

    ``compute(scale)`` maps those vectors, each multiplied by ``scale``, and returns the results
    as rows. If one is still not finite, a ``ValueError`` says that the argument ``name`` is too
    large and that ``what`` (the result, such as "the rotated point") at its index in the result
    of leading shape ``shape`` would be beyond the range of float64; ``offset`` is the flat index
    of the first vector of the caller's block.
    """
    with np.errstate(over="ignore", invalid="ignore"):
        result: Array = compute(SCALE) / SCALE
    still = np.flatnonzero(~np.isfinite(result).all(axis=-1))
    if still.size:
        where = _index_text(shape, offset + int(rows[still[0]]))
        raise ValueError(
            f"{name} is too large: {what}{where} would be above the largest float (about 1.8e308)"
        )
    return result
