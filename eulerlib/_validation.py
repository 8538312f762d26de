"""The argument rules of eulerlib: every public function checks its input here, once.

A public function converts and checks each argument at its boundary, with the helpers below,
and hands checked values to the inner layers, which never check again. So one rule holds for
every function and every message reads the same:

* **numbers** (angles, points, matrices) become float64 arrays; text, ``None``, complex numbers,
  booleans, objects that are not numbers, masked arrays and values too large for a float are
  refused with a ``TypeError`` or ``ValueError`` that names the argument; NaN and infinity are
  refused with the index of the first one in the caller's array;
* **flags** (``degrees``, ``validate``, ``repair``, ``warn``, …) are ``True`` or ``False``
  (``bool`` or ``numpy.bool_``), nothing else: ``degrees="no"`` is a ``TypeError``, not a
  silent yes;
* **tolerances** (``atol``, ``tolerance``, …) are finite real numbers ≥ 0;
* **choices** (an up axis, a frame) are one of a few words, in any letter case;
* **rotation matrices** are checked for ``R Rᵀ = I`` and ``det R = +1`` within ``atol``, block
  by block, so that no check allocates a temporary as large as the input; ``repair=True``
  replaces each matrix by the nearest rotation instead, and refuses a matrix that has none
  worth the name (see :func:`eulerlib.nearest_rotation`).
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._blocks import block_slices

#: Default tolerance on ``max |R Rᵀ − I|`` and ``|det R − 1|`` for a matrix to count as a
#: rotation. Loose enough for matrices that went through single precision or a few hundred
#: products, tight enough to reject a scaled or sheared matrix.
ROTATION_ATOL = 1e-6

#: ``repair=True`` refuses a matrix whose singular values differ from 1 by more than this: such
#: a matrix is singular, or scaled or sheared far beyond rounding and drift, and the "nearest
#: rotation" would be an arbitrary answer rather than a repair.
REPAIR_LIMIT = 0.1

_KINDS = {"U": "text", "S": "bytes", "c": "complex numbers", "b": "booleans"}


# --- flags, tolerances, choices -----------------------------------------------------------------


def check_flag(value: object, name: str) -> bool:
    """``value`` as a ``bool``, when it is ``True`` or ``False`` (Python or NumPy).

    Examples
    --------
    >>> check_flag(True, "degrees")
    True
    >>> check_flag("no", "degrees")
    Traceback (most recent call last):
    ...
    TypeError: degrees must be True or False, got 'no' (str)
    """
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise TypeError(f"{name} must be True or False, got {value!r} ({type(value).__name__})")


def real_number(value: object, name: str) -> float:
    """``value`` as a float, when it is a real number (a 0-d array of one counts); a number too
    large for a float becomes infinity. What range is allowed is for the caller to decide.

    Examples
    --------
    >>> real_number(-2, "scale"), real_number(10**400, "scale")
    (-2.0, inf)
    """
    if isinstance(value, np.ndarray) and value.ndim == 0 and value.dtype.kind in "iuf":
        value = value[()]
    if isinstance(value, (bool, np.bool_)) or not isinstance(
        value, (int, float, np.integer, np.floating)
    ):
        raise TypeError(f"{name} must be a real number, got {value!r} ({type(value).__name__})")
    try:
        return float(value)
    except OverflowError:
        return math.inf if value > 0 else -math.inf


def check_tolerance(value: object, name: str) -> float:
    """``value`` as a float, when it is a finite real number ≥ 0.

    Examples
    --------
    >>> check_tolerance(1e-6, "atol")
    1e-06
    >>> check_tolerance(float("nan"), "atol")
    Traceback (most recent call last):
    ...
    ValueError: atol must be a finite number ≥ 0, got nan
    """
    number = real_number(value, name)
    if not (math.isfinite(number) and number >= 0.0):
        raise ValueError(f"{name} must be a finite number ≥ 0, got {value!r}")
    return number


def check_choice(value: object, name: str, choices: tuple[str, ...]) -> str:
    """``value`` in lowercase, when it is one of ``choices`` (lowercase words), in any case.

    Examples
    --------
    >>> check_choice("Y", "up", ("y", "z"))
    'y'
    >>> check_choice("w", "up", ("y", "z"))
    Traceback (most recent call last):
    ...
    ValueError: up must be 'y' or 'z', got 'w'
    """
    listed = " or ".join(repr(choice) for choice in choices)
    if not isinstance(value, str):
        raise TypeError(f"{name} must be {listed} (a string), got {type(value).__name__}")
    key = value.strip().lower()
    if key not in choices:
        raise ValueError(f"{name} must be {listed}, got {value!r}")
    return key


# --- numbers --------------------------------------------------------------------------------------


def _index_text(shape: tuple[int, ...], flat_index: int) -> str:
    if not shape:
        return ""
    index = tuple(int(i) for i in np.unravel_index(flat_index, shape))
    return f" at index {index}"


def _first_nonfinite(array: NDArray[np.float64]) -> int | None:
    """Flat index of the first NaN or infinity in ``array``, or None when all are finite.

    The common case costs one sum and no temporary: a sum of finite numbers is finite unless
    it overflows, and any NaN or infinity makes the sum NaN or infinite. Only then is the array
    searched, block by block.
    """
    with np.errstate(over="ignore", invalid="ignore"):
        if math.isfinite(float(np.sum(array))):
            return None
    flat = array.reshape(-1)  # a view for the contiguous arrays that reach here in practice
    for block in block_slices(flat.size, 1 << 16):
        bad = np.flatnonzero(~np.isfinite(flat[block]))
        if bad.size:
            return int(block.start + bad[0])
    return None


def as_float_array(value: ArrayLike, name: str, finite: bool = True) -> NDArray[np.float64]:
    """``value`` as a float64 array of finite numbers, or a clear error naming ``name``.

    The input is never modified; a copy is made only when the dtype changes. With
    ``finite=False`` NaN and infinities are let through (for a predicate that answers False
    for them instead of refusing them).

    Examples
    --------
    >>> as_float_array([1, 2, 3], "angles")
    array([1., 2., 3.])
    >>> as_float_array([1.0, None, 2.0], "angles")
    Traceback (most recent call last):
    ...
    TypeError: angles must be real numbers; got an array of objects that are not numbers
    """
    if isinstance(value, (str, bytes)):
        raise TypeError(f"{name} must be numbers, got text {value!r}")
    if isinstance(value, np.ma.MaskedArray):
        raise TypeError(
            f"{name} is a masked array, whose mask eulerlib would ignore: fill the masked "
            f"entries ({name}.filled(...)) or leave them out ({name}.compressed() or indexing "
            "with ~mask) first"
        )
    try:
        array = np.asarray(value)
    except (ValueError, TypeError) as error:  # ragged nested lists and the like
        raise ValueError(f"{name} could not be read as a numeric array: {error}") from None
    except OverflowError:
        raise ValueError(f"{name} holds a number too large for a float (above 1.8e308)") from None
    if array.dtype.kind not in "iuf":
        if array.dtype.kind != "O":
            what = _KINDS.get(array.dtype.kind, f"dtype {array.dtype}")
            raise TypeError(f"{name} must be real numbers, got {what}")
        # astype would turn None into NaN, the text "2" into 2.0 and True into 1.0: refuse them
        if any(
            item is None or isinstance(item, (str, bytes, bool, np.bool_, complex))
            for item in array.flat
        ):
            raise TypeError(
                f"{name} must be real numbers; got an array of objects that are not numbers"
            )
        try:
            array = array.astype(np.float64)
        except OverflowError:
            raise ValueError(
                f"{name} holds a number too large for a float (above 1.8e308)"
            ) from None
        except (TypeError, ValueError):
            raise TypeError(
                f"{name} must be real numbers; got an array of objects that are not numbers"
            ) from None
    array = array.astype(np.float64, copy=False)
    bad = _first_nonfinite(array) if finite else None
    if bad is not None:
        raise ValueError(
            f"{name} must be finite, got {array.reshape(-1)[bad]}{_index_text(array.shape, bad)}"
        )
    return array


def as_vectors(value: ArrayLike, name: str, finite: bool = True) -> NDArray[np.float64]:
    """``value`` as a float array of shape ``(..., 3)``; ``finite`` as in :func:`as_float_array`."""
    array = as_float_array(value, name) if finite else as_float_array(value, name, finite=False)
    if array.ndim == 0 or array.shape[-1] != 3:
        raise ValueError(f"{name} must have shape (..., 3), got shape {array.shape}")
    return array


def stack_angles(named: dict[str, ArrayLike]) -> NDArray[np.float64]:
    """Check three separately given angles and stack them, broadcast, into shape ``(..., 3)``.

    ``named`` maps each angle's name (used in messages) to its value, in argument order.
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


def as_matrix_stack(value: ArrayLike, name: str, finite: bool = True) -> NDArray[np.float64]:
    """``value`` as a float array of shape ``(..., 3, 3)`` with finite entries (no other check).

    ``finite=False`` lets NaN and infinities through, as in :func:`as_float_array`.
    """
    array = as_float_array(value, name, finite)
    if array.ndim < 2 or array.shape[-2:] != (3, 3):
        raise ValueError(f"{name} must have shape (..., 3, 3), got shape {array.shape}")
    return array


# --- rotation matrices ----------------------------------------------------------------------------


class RotationCheck(NamedTuple):
    """The three keywords every function that takes rotation matrices shares, checked.

    ``validate``: check ``R Rᵀ = I`` and ``det R = +1`` within ``atol``; ``repair``: use the
    nearest rotation instead (then nothing is checked against ``atol``).
    """

    validate: bool
    repair: bool
    atol: float
    #: What the refusal of a matrix that is not orthogonal within ``atol`` advises; a command
    #: line names its own options here.
    advice: str = "pass repair=True to use the nearest rotation instead"


#: The keywords' defaults, checked (what :func:`rotation_check` gives for them).
_DEFAULT_CHECK = RotationCheck(True, False, ROTATION_ATOL)


def rotation_check(validate: object, repair: object, atol: object) -> RotationCheck:
    """Check the ``validate``, ``repair`` and ``atol`` keywords of a public function."""
    if validate is True and repair is False and atol == ROTATION_ATOL and type(atol) is float:
        return _DEFAULT_CHECK  # the defaults: what most calls pass, without the checks' cost
    return RotationCheck(
        check_flag(validate, "validate"),
        check_flag(repair, "repair"),
        check_tolerance(atol, "atol"),
    )


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
        np.maximum(worst, np.abs(dot(r, s) - 1.0), out=worst)
    for r, s in ((0, 1), (0, 2), (1, 2)):
        np.maximum(worst, np.abs(dot(r, s)), out=worst)
    return worst


def determinant(entries: NDArray[np.float64]) -> NDArray[np.float64]:
    """Determinant of each 3×3 matrix from :func:`matrix_entries` rows (rule of Sarrus)."""
    a, b, c, d, e, f, g, h, i = entries
    result: NDArray[np.float64] = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    return result


def shown(value: float, *, beyond: float, around: float = 0.0) -> str:
    """``value`` as text for a message that compares it with a limit: with three significant
    digits, or, when ``value`` lies farther than ``beyond`` from ``around``, as many more as it
    takes for the decimal number the text shows to lie that far from the decimals of ``around``
    and ``beyond`` too. Print the limit with ``repr``, which shows the same decimals.

    Examples
    --------
    >>> shown(0.0123456, beyond=1e-6)
    '0.0123'
    >>> shown(1.0000000001e-6, beyond=1e-6)     # not "1e-06 exceeds the tolerance 1e-06"
    '1.0000000001e-06'
    >>> shown(1.0000004, beyond=3e-7, around=1.0), shown(1.0000001, beyond=3e-7, around=1.0)
    ('1.0000004', '1')
    """
    if not abs(value - around) > beyond:
        return f"{value:.3g}"
    from decimal import Decimal  # only for messages: the arithmetic a reader does on the text

    center, limit = Decimal(repr(float(around))), Decimal(repr(float(beyond)))
    for digits in range(3, 18):
        text = f"{value:.{digits}g}"
        if abs(Decimal(text) - center) > limit:
            return text
    return repr(float(value))


def _raise_unless_rotations(
    entries: NDArray[np.float64],
    name: str,
    check: RotationCheck,
    lead: tuple[int, ...],
    offset: int,
) -> None:
    """Raise ``ValueError`` unless every matrix of a block is a rotation within ``check.atol``.

    ``entries`` holds a block of matrices laid out by :func:`matrix_entries`, shape ``(9, n)``;
    ``offset`` is the flat index of its first matrix in the caller's array of leading shape
    ``lead``, so that the message names the caller's index.
    """
    det = determinant(entries)
    reflected = np.flatnonzero(det < 0)
    if reflected.size:
        first = int(reflected[0])
        raise ValueError(
            f"{name}{_index_text(lead, offset + first)} has determinant {float(det[first]):.6g}: "
            "a reflection, not a rotation"
        )
    atol = check.atol
    error = orthonormality_error(entries)
    bad = np.flatnonzero(~(error <= atol))
    if bad.size:
        first = int(bad[0])
        measured = shown(float(error[first]), beyond=atol)
        raise ValueError(
            f"{name}{_index_text(lead, offset + first)} is not a rotation matrix: "
            f"max |R Rᵀ − I| = {measured} exceeds the tolerance {atol!r}; {check.advice}"
        )
    off = np.flatnonzero(~(np.abs(det - 1.0) <= atol))
    if off.size:  # |det − 1| can be up to 1.5 times max |R Rᵀ − I|, or more with a large atol
        first = int(off[0])
        value = float(det[first])
        raise ValueError(
            f"{name}{_index_text(lead, offset + first)} has determinant "
            f"{shown(value, beyond=atol, around=1.0)}, which differs from 1 by "
            f"{shown(abs(value - 1.0), beyond=atol)}, more than the tolerance {atol!r}"
        )


def nearest_rotations(
    flat: NDArray[np.float64], name: str, lead: tuple[int, ...], offset: int
) -> NDArray[np.float64]:
    """Nearest rotation to each matrix of ``flat`` (shape ``(n, 3, 3)``), or a clear refusal.

    ``lead`` and ``offset`` place the block in the caller's array for the messages, as in
    :func:`_raise_unless_rotations`.
    """
    u, sigma, vt = np.linalg.svd(flat)
    deviation = np.max(np.abs(sigma - 1.0), axis=-1)
    far = np.flatnonzero(~(deviation <= REPAIR_LIMIT))
    if far.size:
        first = int(far[0])
        values = ", ".join(shown(float(s), beyond=REPAIR_LIMIT, around=1.0) for s in sigma[first])
        where = f"{name}{_index_text(lead, offset + first)}"
        if sigma[first, -1] <= 1e-12 * max(float(sigma[first, 0]), 1e-300):
            rank = int(np.count_nonzero(sigma[first] > 1e-12 * sigma[first, 0]))
            reason = f"is singular (rank {rank}, singular values {values})"
        else:
            reason = (
                f"is too far from a rotation to repair: its singular values ({values}) differ "
                f"from 1 by up to {shown(float(deviation[first]), beyond=REPAIR_LIMIT)}, more "
                f"than {REPAIR_LIMIT!r}"
            )
        raise ValueError(f"{where} {reason}; only a matrix close to a rotation can be repaired")
    Q = u @ vt
    det = np.linalg.det(Q)
    reflected = np.flatnonzero(det < 0)
    if reflected.size:
        first = int(reflected[0])
        raise ValueError(
            f"{name}{_index_text(lead, offset + first)} is closest to a reflection "
            "(determinant < 0), so it cannot be repaired into a rotation"
        )
    result: NDArray[np.float64] = Q
    return result


def rotation_entry_blocks(
    matrices: NDArray[np.float64], name: str, check: RotationCheck
) -> Iterator[tuple[slice, NDArray[np.float64]]]:
    """Checked (or repaired) blocks of matrices, laid out for entry-by-entry arithmetic.

    ``matrices`` has passed :func:`as_matrix_stack`. Yields ``(block, entries)``: ``block``
    slices the flattened leading axes, ``entries`` holds that block's matrices as
    :func:`matrix_entries` lays them out. A matrix that is not a rotation raises while
    iterating, with its index in the whole of ``matrices``.
    """
    lead = matrices.shape[:-2]
    flat = matrices.reshape(-1, 3, 3)
    for block in block_slices(flat.shape[0]):
        part = flat[block]
        if check.repair:
            part = nearest_rotations(part, name, lead, block.start)
        entries = matrix_entries(part)
        if check.validate and not check.repair:
            _raise_unless_rotations(entries, name, check, lead, block.start)
        yield block, entries


def as_rotations(value: ArrayLike, name: str, check: RotationCheck) -> NDArray[np.float64]:
    """``value`` as rotation matrices ``(..., 3, 3)``: checked, or repaired into a new array."""
    matrices = as_matrix_stack(value, name)
    if check.repair:
        repaired = np.empty(matrices.shape)
        flat = repaired.reshape(-1, 3, 3)
        source = matrices.reshape(-1, 3, 3)
        for block in block_slices(flat.shape[0]):
            flat[block] = nearest_rotations(source[block], name, matrices.shape[:-2], block.start)
        return repaired
    if check.validate:
        for _ in rotation_entry_blocks(matrices, name, check):
            pass
    return matrices
