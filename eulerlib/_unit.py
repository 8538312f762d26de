"""Lengths and unit vectors, at every scale, and the one rule that a zero vector has no direction.

The length ``sqrt(x² + y² + z²)`` of a vector is accurate to about one unit in the last place,
unless the squares leave the range of float64: below about 1e-154 they underflow (a rotation
vector of length 1e-200 would have length 0) and above about 1e154 they overflow. Those rare
vectors are scaled by a power of two first, which is exact, so every finite vector gets its
length to the same accuracy, at the cost of one comparison for all the others.

A rotation axis and a quaternion may have any length, since only their direction matters, and
the formulas that use them divide by their squared length (or length) once.
:func:`scaled_to_unit_size` scales them exactly to a size near 1 where that is needed, and
refuses the zero vector, which has no direction, with the argument's name and the index of the
vector.
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


def _exponents(part: Array) -> NDArray[np.int32]:
    """Binary exponent of the largest component of each column (0 for a zero column)."""
    exponent: NDArray[np.int32] = np.frexp(np.max(np.abs(part), axis=0))[1]
    return exponent


def lengths(components: Array) -> Array:
    """Euclidean length of each column of ``components`` (shape ``(k, n)``), at any scale.

    A length above the largest float (about 1.8e308), which only a vector with entries near it
    can have, comes out as ``inf``, silently: :func:`refuse_overlong` turns it into an error
    where the length must be a number.

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
        unit_size = np.sqrt(squared_lengths(np.ldexp(part, -exponent)))
        with np.errstate(over="ignore"):  # a length above the largest float: inf
            length[redo] = np.ldexp(unit_size, exponent)
    return length


def refuse_overlong(length: Array, name: str, lead: tuple[int, ...], selection: Selection) -> None:
    """Raise ``ValueError`` if a length from :func:`lengths` is above the largest float.

    The message names ``name`` and the index of the first such vector in the caller's array
    of leading shape ``lead``, from which ``selection`` took the columns.
    """
    if not length.size or np.isfinite(length.max()):
        return
    first = int(np.flatnonzero(np.isinf(length))[0])
    where = _index_text(lead, selected_index(selection, first))
    raise ValueError(
        f"{name}{where} has a length above the largest float (about 1.8e308): the angle of "
        "its turn is not a number"
    )


def scaled_to_unit_size(
    components: Array, name: str, what: str, lead: tuple[int, ...], selection: Selection
) -> tuple[Array, Array]:
    """Each column of ``components`` times the power of two that puts its largest entry in
    [0.5, 1), and the squared lengths of the results (between 0.25 and the number of rows).

    Scaling by a power of two is exact, so the direction of every vector is kept to the last
    bit, and whatever is later computed from the scaled vectors can neither overflow nor
    underflow. A zero column raises ``ValueError`` naming ``name`` and the index of that vector
    in the caller's array of leading shape ``lead``, from which ``selection`` took the columns
    (as :func:`eulerlib._broadcast.broadcast_blocks` selects them). ``what`` says what the
    vector is, for the message.
    """
    exponent = _exponents(components)
    scaled = np.ldexp(components, -exponent)
    squared = squared_lengths(scaled)
    zero = np.flatnonzero(squared == 0.0)
    if zero.size:
        where = _index_text(lead, selected_index(selection, int(zero[0])))
        raise ValueError(
            f"{name}{where} is zero: {what} cannot be normalized, since a zero vector has no "
            "direction"
        )
    return scaled, squared
