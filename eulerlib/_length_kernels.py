"""Lengths of vectors at every scale, in float64 without overflow or harmful underflow.

The length ``sqrt(x² + y² + z²)`` of a vector is accurate to about one unit in the last place,
unless the squares leave the range of float64: below about 1e-154 they underflow and above
about 1e154 they overflow. Those rare vectors are scaled by a power of two first, which is
exact. A kernel: numpy only, on columns of checked numbers (:mod:`eulerlib._unit` adds the
rule that a zero vector has no direction).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

Array = NDArray[np.float64]

# Squared lengths between these bounds are computed without overflow or harmful underflow.
_SMALL, _LARGE = 2.0**-1000, 2.0**1000

#: The smallest positive float64: ``x / max(length, TINY)`` is ``x / length`` for every
#: nonzero length and 0 for the zero vector, without a division by zero.
TINY = float(np.finfo(np.float64).smallest_subnormal)


def squared_lengths(components: Array) -> Array:
    """``x² + y² + …`` of each column; may overflow or underflow (see :func:`lengths`)."""
    with np.errstate(over="ignore"):  # the squares of huge vectors: redone by the caller
        total: Array = components[0] * components[0]
        for row in components[1:]:
            total += row * row
    return total


def out_of_range(squared: Array) -> NDArray[np.intp]:
    """Columns whose squared length is not safely inside the range of float64 (usually none)."""
    if squared.size and squared.min() >= _SMALL and squared.max() <= _LARGE:
        return np.empty(0, dtype=np.intp)
    return np.flatnonzero(~((squared >= _SMALL) & (squared <= _LARGE)))


def binary_exponents(part: Array) -> NDArray[np.int32]:
    """Binary exponent of the largest component of each column (0 for a zero column)."""
    exponent: NDArray[np.int32] = np.frexp(np.max(np.abs(part), axis=0))[1]
    return exponent


def lengths(components: Array) -> Array:
    """Euclidean length of each column of ``components`` (shape ``(k, n)``), at any scale.

    A length above the largest float (about 1.8e308), which only a vector with entries near it
    can have, comes out as ``inf``, silently: :func:`eulerlib._unit.refuse_overlong` turns it
    into an error where the length must be a number.

    Examples
    --------
    >>> import numpy as np
    >>> lengths(np.array([[3.0, 3e-200, 3e200], [4.0, 4e-200, 4e200]]))
    array([5.e+000, 5.e-200, 5.e+200])
    """
    squared = squared_lengths(components)
    length: Array = np.sqrt(squared)
    redo = out_of_range(squared)
    if redo.size:
        part = components[:, redo]
        exponent = binary_exponents(part)
        unit_size = np.sqrt(squared_lengths(np.ldexp(part, -exponent)))
        with np.errstate(over="ignore"):  # a length above the largest float: inf
            length[redo] = np.ldexp(unit_size, exponent)
    return length
