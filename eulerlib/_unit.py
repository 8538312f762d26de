"""Lengths and unit vectors, at every scale, and the one rule that a zero vector has no direction.

The length ``sqrt(x² + y² + z²)`` of a vector is accurate to about one unit in the last place,
unless the squares leave the range of float64: below about 1e-154 they underflow (a rotation
vector of length 1e-200 would have length 0) and above about 1e154 they overflow. Those rare
vectors are scaled by a power of two first, which is exact, so every finite vector gets its
length to the same accuracy, at the cost of one comparison for all the others.

A rotation axis and a quaternion are normalized before use. Only the zero vector cannot be;
:func:`in_range` and :func:`unit_components` refuse it with the argument's name and the index of
the vector.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from eulerlib._broadcast import Selection, selected_index
from eulerlib._validation import _index_text

Array = NDArray[np.float64]

# Squared lengths between these bounds are computed without overflow or harmful underflow.
_SMALL, _LARGE = 2.0**-1000, 2.0**1000

#: The smallest positive float64: ``x / max(length, TINY)`` is ``x / length`` for every
#: nonzero length and 0 for the zero vector, without a division by zero.
TINY = float(np.finfo(np.float64).smallest_subnormal)


def squared_lengths(components: Array) -> Array:
    """``x² + y² + …`` of each column; may overflow or underflow (see :func:`in_range`)."""
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


def _exponents(part: Array) -> NDArray[np.int32]:
    """Binary exponent of the largest component of each column (0 for a zero column)."""
    exponent: NDArray[np.int32] = np.frexp(np.max(np.abs(part), axis=0))[1]
    return exponent


def lengths(components: Array) -> Array:
    """Euclidean length of each column of ``components`` (shape ``(k, n)``), at any scale.

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
        exponent = _exponents(part)
        length[redo] = np.ldexp(np.sqrt(squared_lengths(np.ldexp(part, -exponent))), exponent)
    return length


def in_range(
    components: Array, name: str, what: str, lead: tuple[int, ...], selection: Selection
) -> tuple[Array, Array]:
    """Columns of ``components`` scaled where needed, and their squared lengths; no zero column.

    A column whose squared length would underflow or overflow is multiplied by a power of two
    (exactly) so that it does not; the others are returned as they are. A zero column raises
    ``ValueError`` naming ``name`` and the index of that vector in the caller's array of
    leading shape ``lead``, from which ``selection`` took the columns (as
    :func:`eulerlib._broadcast.broadcast_blocks` selects them). ``what`` says what the vector
    is, for the message.
    """
    squared = squared_lengths(components)
    redo = out_of_range(squared)
    if redo.size:
        components = components.copy()
        part = components[:, redo]
        part = np.ldexp(part, -_exponents(part))
        components[:, redo] = part
        squared[redo] = squared_lengths(part)
        zero = np.flatnonzero(squared == 0.0)
        if zero.size:
            where = _index_text(lead, selected_index(selection, int(zero[0])))
            raise ValueError(
                f"{name}{where} is zero: {what} cannot be normalized, since a zero vector has "
                "no direction"
            )
    return components, squared


def unit_components(
    components: Array, name: str, what: str, lead: tuple[int, ...], selection: Selection
) -> Array:
    """Each column of ``components`` (shape ``(k, n)``) divided by its length.

    A zero column raises ``ValueError`` as in :func:`in_range`.
    """
    scaled, squared = in_range(components, name, what, lead, selection)
    unit: Array = scaled / np.sqrt(squared)
    return unit
