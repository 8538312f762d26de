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
from eulerlib._length_kernels import binary_exponents, squared_lengths
from eulerlib._validation import _index_text

Array = NDArray[np.float64]


def refuse_overlong(length: Array, name: str, lead: tuple[int, ...], selection: Selection) -> None:
    """Raise ``ValueError`` if a length from :func:`eulerlib._length_kernels.lengths` is above
    the largest float.

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
    exponent = binary_exponents(components)
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
