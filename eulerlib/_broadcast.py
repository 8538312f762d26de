"""Broadcasting in blocks: several inputs of different leading shapes, never expanded in full.

When the leading axes of two inputs broadcast (one axis for many angles, one pair of rotations
for many fractions), the result has the broadcast shape, but the inputs need not be copied to
it. The output is cut into blocks of :data:`eulerlib._blocks.BLOCK_SIZE` as usual, and for each
block every input gives just the elements that block needs: a slice of itself when its shape
is the whole broadcast shape, otherwise the gathered elements, by index. So no temporary is
ever larger than one block, whatever the shapes.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np
from numpy.typing import NDArray

from eulerlib._blocks import BLOCK_SIZE, block_slices

#: What selects one input's elements for one block: a slice, or flat indices into the input.
Selection = slice | NDArray[np.intp]


def broadcast_shape(named: dict[str, tuple[int, ...]]) -> tuple[int, ...]:
    """The broadcast of the given leading shapes, or a ``ValueError`` naming the arguments.

    Examples
    --------
    >>> broadcast_shape({"axis": (4, 1), "angle": (5,)})
    (4, 5)
    >>> broadcast_shape({"R0": (2,), "R1": (3,)})
    Traceback (most recent call last):
    ...
    ValueError: the leading shapes of R0 (2,) and R1 (3,) do not broadcast together
    """
    try:
        return tuple(np.broadcast_shapes(*named.values()))
    except ValueError:
        listed = [f"{name} {shape}" for name, shape in named.items()]
        words = ", ".join(listed[:-1]) + " and " + listed[-1]
        raise ValueError(f"the leading shapes of {words} do not broadcast together") from None


def broadcast_blocks(
    shape: tuple[int, ...], operand_shapes: tuple[tuple[int, ...], ...], size: int = BLOCK_SIZE
) -> Iterator[tuple[slice, tuple[Selection, ...]]]:
    """Blocks of the flattened ``shape``, each with the selection of every operand for it.

    ``operand_shapes`` are the leading shapes of the operands, each broadcasting to ``shape``;
    ``size`` is the number of results per block. Yields ``(block, selections)``:
    ``operand.reshape(-1, ...)[selections[i]]`` holds, in order, the elements of operand ``i``
    that the elements ``block`` of the result combine.

    Examples
    --------
    >>> for block, (a, b) in broadcast_blocks((2, 3), ((2, 1), (3,))):
    ...     print(block, a, b)
    slice(0, 6, None) [0 0 0 1 1 1] [0 1 2 0 1 2]
    """
    padded = [(1,) * (len(shape) - len(s)) + tuple(s) for s in operand_shapes]
    for block in block_slices(math.prod(shape), size):
        yield block, tuple(_selection(block, shape, s) for s in padded)


def _selection(block: slice, shape: tuple[int, ...], padded: tuple[int, ...]) -> Selection:
    if padded == shape:
        return block
    if math.prod(padded) == 1:
        return np.zeros(block.stop - block.start, dtype=np.intp)
    position = np.unravel_index(np.arange(block.start, block.stop), shape)
    index = [p if size != 1 else 0 for p, size in zip(position, padded, strict=True)]
    flat: NDArray[np.intp] = np.ravel_multi_index(index, padded)
    return flat


def selected_index(selection: Selection, position: int) -> int:
    """Flat index in the operand of the element at ``position`` of a block's selection."""
    if isinstance(selection, slice):
        return int(selection.start) + position
    return int(selection[position])


def common_lead(shapes: tuple[tuple[int, ...], ...]) -> tuple[int, ...] | None:
    """The broadcast of leading axes when each operand holds either one item or as many as
    the broadcast (so its items are in the broadcast's order): what the compiled kernels take.
    None for any other broadcast and for shapes that do not broadcast."""
    first = shapes[0]
    if shapes.count(first) == len(shapes):  # the usual cases, at once: all alike,
        return first
    longest = max(shapes, key=len)
    if all(shape == longest or not shape for shape in shapes):  # or a single one with a batch
        return longest
    try:
        lead = np.broadcast_shapes(*shapes)
    except ValueError:
        return None
    size = math.prod(lead)
    return lead if all(math.prod(shape) in (1, size) for shape in shapes) else None


def block_part(items: NDArray[np.float64], block: slice) -> NDArray[np.float64]:
    """The items of one operand for a block of a :func:`common_lead` broadcast: its one item
    for every block, or its slice."""
    return items if len(items) == 1 else items[block]
