"""Checks at the boundary: turn user input into float arrays, or say clearly why not.

Every public function of eulerlib passes its inputs through these helpers, so that a wrong
shape, a NaN, text where numbers belong, or a matrix that is not a rotation is reported once,
in the same words, with what was received and what was expected.
"""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._blocks import block_slices

#: Default tolerance on ``max |R Rᵀ − I|`` and ``|det R − 1|`` for a matrix to count as a
#: rotation. Loose enough for matrices that went through single precision or a few hundred
#: products, tight enough to reject a scaled or sheared matrix.
ROTATION_ATOL = 1e-6


def as_float_array(value: ArrayLike, name: str) -> NDArray[np.float64]:
    """Return ``value`` as a float64 array, refusing text, complex numbers and non-finite values.

    The input is never modified; a copy is made only when the dtype changes.
    """
    if isinstance(value, (str, bytes)):
        raise TypeError(f"{name} must be numbers, got text {value!r}")
    try:
        array = np.asarray(value)
    except (ValueError, TypeError) as error:  # ragged nested lists and the like
        raise ValueError(f"{name} could not be read as a numeric array: {error}") from None
    if array.dtype.kind not in "iuf":
        if array.dtype.kind == "O":
            try:
                # astype would turn None into NaN and the text "2" into 2.0: refuse both
                if any(item is None or isinstance(item, (str, bytes)) for item in array.flat):
                    raise TypeError
                array = array.astype(np.float64)
            except (TypeError, ValueError):
                raise TypeError(
                    f"{name} must be real numbers; got an array of objects that are not numbers"
                ) from None
        else:
            kinds = {"U": "text", "S": "bytes", "c": "complex numbers", "b": "booleans"}
            what = kinds.get(array.dtype.kind, f"dtype {array.dtype}")
            raise TypeError(f"{name} must be real numbers, got {what}")
    array = array.astype(np.float64, copy=False)
    if not np.all(np.isfinite(array)):
        bad = np.argwhere(~np.isfinite(array))[0]
        where = f" at index {tuple(int(i) for i in bad)}" if array.ndim else ""
        raise ValueError(f"{name} must be finite, got {array[tuple(bad)]}{where}")
    return array


def as_vectors(value: ArrayLike, name: str) -> NDArray[np.float64]:
    """Return ``value`` as a float array of shape ``(..., 3)``."""
    array = as_float_array(value, name)
    if array.ndim == 0 or array.shape[-1] != 3:
        raise ValueError(f"{name} must have shape (..., 3), got shape {array.shape}")
    return array


def stack_angles(named: dict[str, ArrayLike]) -> NDArray[np.float64]:
    """Check three separately given angles and stack them, broadcast, into shape ``(..., 3)``.

    ``named`` maps each angle's name (used in messages) to its value, in sequence order.
    """
    values = [as_float_array(value, name) for name, value in named.items()]
    try:
        return np.stack(np.broadcast_arrays(*values), axis=-1)
    except ValueError:
        shapes = ", ".join(
            f"{name} {value.shape}" for name, value in zip(named, values, strict=True)
        )
        raise ValueError(
            f"{', '.join(list(named)[:-1])} and {list(named)[-1]} do not broadcast together: "
            f"shapes {shapes}"
        ) from None


def _matrix_array(value: ArrayLike, name: str) -> NDArray[np.float64]:
    array = as_float_array(value, name)
    if array.ndim < 2 or array.shape[-2:] != (3, 3):
        raise ValueError(f"{name} must have shape (..., 3, 3), got shape {array.shape}")
    return array


def as_matrices(
    value: ArrayLike,
    name: str = "R",
    *,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
) -> NDArray[np.float64]:
    """Return ``value`` as a float array of rotation matrices, shape ``(..., 3, 3)``.

    With ``repair=True`` each matrix is replaced by the nearest rotation (in the Frobenius
    norm, through the SVD); a matrix whose nearest orthogonal matrix is a reflection is still
    refused. With ``validate=False`` only the shape and finiteness are checked.
    """
    array = _matrix_array(value, name)
    if repair:
        return nearest_rotation(array, name)
    if validate:
        for _ in _entry_blocks(array, name, validate=True, repair=False, atol=atol):
            pass
    return array


def matrix_entry_blocks(
    value: ArrayLike,
    name: str = "R",
    *,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
) -> tuple[tuple[int, ...], Iterator[tuple[slice, NDArray[np.float64]]]]:
    """Check matrices block by block, for conversions that work entry by entry.

    Returns the leading shape of ``value`` and an iterator over ``(block, entries)``: ``block``
    slices the flattened leading axes, and ``entries`` holds that block's matrices as
    :func:`matrix_entries` lays them out, already checked (or repaired) as in
    :func:`as_matrices`. Type, shape and finiteness are checked before this returns; a matrix
    that is not a rotation raises while iterating, with its index in the whole of ``value``.
    """
    array = _matrix_array(value, name)
    return array.shape[:-2], _entry_blocks(array, name, validate, repair, atol)


def _entry_blocks(
    array: NDArray[np.float64], name: str, validate: bool, repair: bool, atol: float
) -> Iterator[tuple[slice, NDArray[np.float64]]]:
    flat = array.reshape(-1, 3, 3)
    for block in block_slices(flat.shape[0]):
        try:
            part = nearest_rotation(flat[block], name) if repair else flat[block]
            entries = matrix_entries(part)
            if validate and not repair:
                check_rotation(entries, name, atol)
        except ValueError:
            # Say it again about the whole input, so that the index in the message is the
            # caller's; earlier blocks passed, so the first bad matrix is in this block.
            if repair:
                nearest_rotation(array, name)
            else:
                check_rotation(matrix_entries(array), name, atol)
            raise
        yield block, entries


def matrix_entries(R: NDArray[np.float64]) -> NDArray[np.float64]:
    """The nine entries of each matrix as contiguous rows: shape ``(9, ...)``, row ``3 i + j``.

    Element-wise arithmetic on these rows is several times faster than ``matmul`` on a stack
    of 3×3 matrices, whose inner loops are too short to pay off.
    """
    flat = R.reshape(*R.shape[:-2], 9)
    return np.ascontiguousarray(np.moveaxis(flat, -1, 0))


def orthonormality_error(entries: NDArray[np.float64]) -> NDArray[np.float64]:
    """Largest entry of ``|R Rᵀ − I|`` for each matrix, from :func:`matrix_entries` rows."""
    e = entries

    def dot(r: int, s: int) -> NDArray[np.float64]:
        result: NDArray[np.float64] = (
            e[3 * r] * e[3 * s] + e[3 * r + 1] * e[3 * s + 1] + e[3 * r + 2] * e[3 * s + 2]
        )
        return result

    worst = np.abs(dot(0, 0) - 1.0)
    for r, s in ((1, 1), (2, 2)):
        worst = np.maximum(worst, np.abs(dot(r, s) - 1.0))
    for r, s in ((0, 1), (0, 2), (1, 2)):
        worst = np.maximum(worst, np.abs(dot(r, s)))
    return worst


def determinant(entries: NDArray[np.float64]) -> NDArray[np.float64]:
    """Determinant of each 3×3 matrix from :func:`matrix_entries` rows (rule of Sarrus)."""
    a, b, c, d, e, f, g, h, i = entries
    result: NDArray[np.float64] = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    return result


def _index_of_first(mask: NDArray[np.bool_]) -> str:
    if mask.ndim == 0:
        return ""
    index = tuple(int(i) for i in np.argwhere(mask)[0])
    return f" at index {index}"


def check_rotation(entries: NDArray[np.float64], name: str, atol: float) -> None:
    """Raise ``ValueError`` unless every matrix is a rotation within ``atol``.

    ``entries`` are the matrices laid out by :func:`matrix_entries`.
    """
    det = determinant(entries)
    reflected = det < 0
    if np.any(reflected):
        first = det[tuple(np.argwhere(reflected)[0])] if det.ndim else det
        raise ValueError(
            f"{name}{_index_of_first(reflected)} has determinant {float(first):.6g}: "
            "a reflection, not a rotation"
        )
    error = orthonormality_error(entries)
    bad = error > atol
    if np.any(bad):
        worst = float(error[tuple(np.argwhere(bad)[0])] if error.ndim else error)
        raise ValueError(
            f"{name}{_index_of_first(bad)} is not a rotation matrix: max |R Rᵀ − I| = "
            f"{worst:.3g} exceeds the tolerance {atol:g}; pass repair=True to use the "
            "nearest rotation instead"
        )
    off = np.abs(det - 1.0) > atol
    if np.any(off):  # only reachable for a singular-looking matrix that passed the Gram test
        raise ValueError(f"{name}{_index_of_first(off)} has a determinant far from 1")


def nearest_rotation(R: NDArray[np.float64], name: str = "R") -> NDArray[np.float64]:
    """Nearest rotation matrix to each matrix of ``R`` in the Frobenius norm (via the SVD)."""
    u, _, vt = np.linalg.svd(R)
    det = np.linalg.det(u @ vt)
    reflected = det < 0
    if np.any(reflected):
        raise ValueError(
            f"{name}{_index_of_first(reflected)} is closest to a reflection (determinant < 0), "
            "so it cannot be repaired into a rotation"
        )
    result: NDArray[np.float64] = u @ vt
    return result
