"""Reading a learner's answer (numbers, arrays, SymPy expressions), and why one can't be read.

An answer that cannot be read is not an error of the course but a common mistake of the learner,
so it gets feedback, never an exception: text where a number belongs (``"0.5"``), a yes/no
(``True``), a complex number, ``None`` from a function that prints instead of returning, a
SymPy matrix that still holds symbols where numbers are asked for, NaN, a wrong shape.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import NDArray


class Unreadable(Exception):
    """An answer that cannot be judged; the message says why, for the learner."""


def _describe(answer: object) -> str:
    text = repr(answer)
    return text if len(text) <= 40 else text[:37] + "..."


def read_numbers(answer: object, shape: tuple[int, ...], what: str) -> NDArray[np.float64]:
    """``answer`` as a float array of ``shape``, or :class:`Unreadable` saying what is wrong.

    Examples
    --------
    >>> read_numbers([1, 2, 3], (3,), "your point")
    array([1., 2., 3.])
    >>> read_numbers("0.5", (), "your angle")
    Traceback (most recent call last):
    ...
    eulerlib_course.exercises.reading.Unreadable: your angle is text ('0.5'); write the numbers,
    without quotes
    """
    if answer is None:
        raise Unreadable(
            f"{what} is None: the cell assigned the result of a function that returns nothing "
            "(print shows a value but returns None)"
        )
    if isinstance(answer, (str, bytes)):
        raise Unreadable(f"{what} is text ({_describe(answer)}); write the numbers, without quotes")
    if isinstance(answer, (bool, np.bool_)):
        raise Unreadable(f"{what} is {answer}, a yes/no; the question asks for numbers")
    if isinstance(answer, np.ma.MaskedArray):
        raise Unreadable(f"{what} is a masked array; fill or drop the masked entries first")
    if _is_sympy(answer):
        answer = _sympy_to_numbers(answer, what)
    try:
        array = np.asarray(answer)
    except (TypeError, ValueError):
        raise Unreadable(f"{what} could not be read as numbers ({_describe(answer)})") from None
    if array.dtype.kind == "c":
        if np.all(np.imag(array) == 0):
            array = np.real(array)
        else:
            raise Unreadable(f"{what} has an imaginary part; the answer is real")
    if array.dtype.kind == "b":
        raise Unreadable(f"{what} is a yes/no (booleans); the question asks for numbers")
    if array.dtype.kind in "USO":
        try:
            if any(
                isinstance(item, (str, bytes, bool, np.bool_)) or item is None
                for item in array.flat
            ):
                raise TypeError
            array = array.astype(np.float64)
        except (TypeError, ValueError, OverflowError):
            raise Unreadable(
                f"{what} holds something that is not a number ({_describe(answer)})"
            ) from None
    array = array.astype(np.float64)
    if array.shape != shape:
        expected = "a single number" if shape == () else f"shape {shape}"
        raise Unreadable(f"{what} has shape {array.shape}; the question asks for {expected}")
    if not np.all(np.isfinite(array)):
        raise Unreadable(f"{what} contains NaN or infinity")
    return array


def _is_sympy(value: object) -> bool:
    return type(value).__module__.startswith("sympy")


def _sympy_to_numbers(value: Any, what: str) -> Any:
    import sympy as sp

    free = sorted(str(s) for s in getattr(value, "free_symbols", set()))
    if free:
        raise Unreadable(f"{what} still contains the symbol(s) {', '.join(free)}; give numbers")
    if isinstance(value, sp.MatrixBase):
        return np.array(value.evalf(), dtype=np.complex128)
    return complex(value.evalf())


def read_expression(answer: object, what: str) -> Any:
    """``answer`` as a SymPy expression or matrix, or :class:`Unreadable` saying why not.

    Numbers and NumPy arrays are turned into SymPy objects; text is refused (write the
    expression with the notebook's symbols, not a string).
    """
    import sympy as sp

    if answer is None:
        raise Unreadable(f"{what} is None: assign the expression itself")
    if isinstance(answer, (str, bytes)):
        raise Unreadable(
            f"{what} is text ({_describe(answer)}); write it with the notebook's SymPy symbols, "
            "without quotes"
        )
    if isinstance(answer, (bool, np.bool_)):
        raise Unreadable(f"{what} is {answer}, a yes/no; the question asks for an expression")
    if _is_sympy(answer):
        return answer
    if isinstance(answer, np.ndarray) or isinstance(answer, (list, tuple)):
        try:
            return sp.Matrix(np.asarray(answer, dtype=object).tolist())
        except (TypeError, ValueError):
            raise Unreadable(
                f"{what} could not be read as a matrix ({_describe(answer)})"
            ) from None
    if isinstance(answer, (int, float, np.integer, np.floating)):
        return sp.sympify(answer)
    raise Unreadable(f"{what} is a {type(answer).__name__}; give a SymPy expression")
