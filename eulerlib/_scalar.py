"""The path of a single rotation: the same checks and the same formulas, in Python floats.

Teaching code converts one rotation at a time (a slider, a frame of an animation, a loop over
samples), and for one rotation the array path's cost is the set-up of dozens of tiny numpy
operations, not arithmetic. So each public function that converts one rotation first offers
its argument to a reader here:

* a reader accepts only the plain forms of one rotation: a float64 array of the exact shape
  (``(3,)``, ``(4,)`` or ``(3, 3)``), or a list or tuple of Python or NumPy numbers (nested
  for a matrix); it returns the numbers as a tuple of floats, or ``None`` for anything else;
* the numbers are checked as the array path checks them, with the same arithmetic: all finite
  (:func:`finite`), and for a matrix ``det R ≥ 0``, ``max |R Rᵀ − I| ≤ atol`` and
  ``|det R − 1| ≤ atol`` (:func:`is_rotation`, the formulas of
  :func:`eulerlib._validation.orthonormality_error` and :func:`eulerlib._validation.determinant`
  evaluated in the same order, so both paths decide alike to the last bit);
* the conversion is then computed by :mod:`eulerlib._scalar_kernels`.

Whenever a reader, a check or a kernel declines, by returning ``None``, the public function
takes the array path with the same argument, which raises the error or the warning. So a
refusal and a gimbal-lock warning are always worded by the one function that words them for
arrays: the two paths cannot drift apart in what they say, only in how fast they are.
"""

from __future__ import annotations

import math
from typing import Any, cast

import numpy as np
from numpy.typing import NDArray

from eulerlib._scalar_kernels import Nine
from eulerlib._validation import RotationCheck

_NUMBER_TYPES = (float, int, np.float64, np.float32, np.int64, np.int32)


def _numbers(value: Any, size: int) -> tuple[float, ...] | None:
    """The ``size`` numbers of a flat list, tuple or float64 array, as floats, or None."""
    kind = type(value)
    if kind is np.ndarray:
        if value.dtype != np.float64 or value.shape != (size,):
            return None
        numbers: tuple[float, ...] = tuple(value.tolist())
    elif kind is list or kind is tuple:
        if len(value) != size:
            return None
        for item in value:
            if type(item) not in _NUMBER_TYPES:  # bool, None, text, complex: the array path
                return None
        try:
            numbers = tuple(float(item) for item in value)
        except OverflowError:  # an integer too large for a float
            return None
    else:
        return None
    return numbers if finite(numbers) else None


def finite(numbers: tuple[float, ...]) -> bool:
    """Whether every number is finite: ``x − x`` is 0 for a finite ``x`` and NaN otherwise."""
    return all(x - x == 0.0 for x in numbers)


def vector(value: Any) -> tuple[float, float, float] | None:
    """One vector of three finite numbers (angles, a point, a rotation vector), or None."""
    return _numbers(value, 3)  # type: ignore[return-value]


def number(value: Any) -> float | None:
    """One finite number (a Python or NumPy number, not a bool), as a float, or None."""
    if type(value) not in _NUMBER_TYPES:
        return None
    try:
        number = float(value)
    except OverflowError:
        return None
    return number if number - number == 0.0 else None


def quaternion(value: Any) -> tuple[float, float, float, float] | None:
    """One quaternion of four finite numbers, or None."""
    return _numbers(value, 4)  # type: ignore[return-value]


def matrix(value: Any) -> Nine | None:
    """The nine entries of one 3×3 matrix of finite numbers, row by row, or None."""
    kind = type(value)
    if kind is np.ndarray:
        if value.dtype != np.float64 or value.shape != (3, 3):
            return None
        entries: tuple[float, ...] = tuple(value.ravel().tolist())
        return entries if finite(entries) else None  # type: ignore[return-value]
    if (kind is not list and kind is not tuple) or len(value) != 3:
        return None
    rows = [_numbers(row, 3) if type(row) in (list, tuple) else None for row in value]
    if rows[0] is None or rows[1] is None or rows[2] is None:
        return None
    return (*rows[0], *rows[1], *rows[2])  # type: ignore[return-value]


#: Largest batch that quaternion ⇄ matrix conversions, which need no sine or arctangent, take
#: one rotation after another in Python floats: measured, that is faster than the array path
#: up to about 20 rotations, where numpy's set-up still outweighs its arithmetic.
SMALL_BATCH = 16


def small_batch(value: Any, shape: tuple[int, ...]) -> list[tuple[float, ...]] | None:
    """The rows of a float64 array of shape ``(k, *shape)`` with ``2 ≤ k ≤ SMALL_BATCH`` and
    finite entries, each as a flat tuple of floats; None for anything else."""
    if type(value) is not np.ndarray or value.dtype != np.float64:
        return None
    if value.ndim != len(shape) + 1 or value.shape[1:] != shape:
        return None
    if not 2 <= value.shape[0] <= SMALL_BATCH:
        return None
    rows = [tuple(row) for row in value.reshape(value.shape[0], -1).tolist()]
    return rows if all(finite(row) for row in rows) else None


def is_rotation(e: Nine, atol: float) -> bool:
    """The rotation test of :func:`eulerlib._validation.as_rotations` for one matrix, in the
    same arithmetic: ``det ≥ 0``, ``max |R Rᵀ − I| ≤ atol``, ``|det − 1| ≤ atol``."""
    a, b, c, d, f, g, h, i, j = e
    det = a * (f * j - g * i) - b * (d * j - g * h) + c * (d * i - f * h)
    if det < 0:
        return False
    worst = abs((a * a + b * b + c * c) - 1.0)
    worst = max(worst, abs((d * d + f * f + g * g) - 1.0), abs((h * h + i * i + j * j) - 1.0))
    worst = max(worst, abs(a * d + b * f + c * g), abs(a * h + b * i + c * j))
    worst = max(worst, abs(d * h + f * i + g * j))
    return worst <= atol and abs(det - 1.0) <= atol


def rotation(value: Any, check: RotationCheck) -> Nine | None:
    """One rotation matrix that passes ``check`` (without repair), or None."""
    if check.repair:
        return None
    entries = matrix(value)
    if entries is None or (check.validate and not is_rotation(entries, check.atol)):
        return None
    return entries


def rotations(value: Any, check: RotationCheck) -> list[Nine] | None:
    """A few rotation matrices (a float64 array of 2 to :data:`SMALL_BATCH`) that all pass
    ``check`` (without repair), each as nine floats; None for anything else, which then takes
    the array path and its wording of any refusal."""
    if check.repair:
        return None
    rows = cast("list[Nine] | None", small_batch(value, (3, 3)))
    if rows is None or (check.validate and not all(is_rotation(e, check.atol) for e in rows)):
        return None
    return rows


def as_array(numbers: tuple[float, ...], shape: tuple[int, ...]) -> NDArray[np.float64]:
    """A new float64 array of ``shape`` holding ``numbers``."""
    return np.array(numbers).reshape(shape)


def degrees_of(angles: tuple[float, ...]) -> tuple[float, ...]:
    """Radians to degrees, as ``np.degrees``."""
    return tuple(math.degrees(angle) for angle in angles)
