"""The argument rules of :mod:`eulerlib.symbolic`: every public function reads its input here, once.

The symbolic functions take SymPy expressions where the numeric library takes arrays, so they
need rules of their own, written once:

* **an expression** (an angle, an axis component, a quaternion component, a matrix entry) is a
  SymPy expression, or a Python or NumPy integer or float, or a ``fractions.Fraction``; it must
  be finite, and not known to be non-real. **Text is refused, never evaluated**: reading
  ``"x y"`` or ``"import os"`` with ``sympify`` would run SymPy's parser (and Python's ``eval``)
  on it, and would turn a typing mistake into a silently different expression. Build the
  expression with SymPy instead (``sp.Symbol("t")``, ``sp.pi / 2``). ``None``, booleans, complex
  numbers, lists and matrices are refused too;
* **a fixed number of expressions** (three angles, an axis, the four parts of a quaternion) is a
  tuple, list, ``sympy.Tuple``, 1-D NumPy array or SymPy column or row vector of that length;
* **a 3×3 matrix** is a SymPy matrix or nested sequences of that shape;
* **a variable** (the ``t`` a matrix depends on) is a ``sympy.Symbol``;
* the axis, sequence and choice arguments use the numeric library's rules unchanged:
  :func:`eulerlib.parse_axis`, :func:`eulerlib.get_convention` and the ``check_choice`` helper
  of :mod:`eulerlib._validation`.

Every message names the argument, with an index for one item of a sequence (``angles[1]``),
and says what was received.
"""

from __future__ import annotations

import fractions
from collections.abc import Sequence as SequenceABC
from typing import Any

import numpy as np
import sympy as sp

_WANTED = "a SymPy expression or a real number"
_NOT_FINITE = (sp.nan, sp.oo, -sp.oo, sp.zoo)


def _text_refusal(value: str | bytes, name: str) -> TypeError:
    return TypeError(
        f"{name} must be {_WANTED}, not text ({value!r}): text is never evaluated; build the "
        "expression with SymPy, for example sp.Symbol('t') or sp.pi / 2"
    )


def as_expression(value: object, name: str) -> Any:
    """``value`` as one finite SymPy expression.

    Examples
    --------
    >>> as_expression(0.5, "angle")
    0.500000000000000
    >>> as_expression("x y", "angle")
    Traceback (most recent call last):
    ...
    TypeError: angle must be a SymPy expression or a real number, not text ('x y'): text is never
    evaluated; build the expression with SymPy, for example sp.Symbol('t') or sp.pi / 2
    """
    if isinstance(value, (str, bytes)):
        raise _text_refusal(value, name)
    if value is None or isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be {_WANTED}, got {value!r}")
    if isinstance(value, (sp.MatrixBase, np.ndarray, list, tuple, dict, set, sp.Tuple)):
        raise TypeError(f"{name} must be one expression ({_WANTED}), got a {type(value).__name__}")
    if isinstance(value, complex):
        raise TypeError(f"{name} must be real, got the complex number {value!r}")
    if isinstance(value, np.integer):
        value = int(value)
    elif isinstance(value, np.floating):
        value = float(value)
    if isinstance(value, sp.Basic):
        expression = value
    elif isinstance(value, (int, float, fractions.Fraction)):
        expression = sp.sympify(value, strict=True)
    else:
        try:
            expression = sp.sympify(value, strict=True)
        except sp.SympifyError:
            raise TypeError(f"{name} must be {_WANTED}, got {type(value).__name__}") from None
    if not isinstance(expression, sp.Expr) or expression.is_Matrix:
        raise TypeError(f"{name} must be {_WANTED}, got {type(expression).__name__} {expression}")
    if expression.has(*_NOT_FINITE):
        raise ValueError(f"{name} must be finite, got {expression}")
    if expression.is_extended_real is False:
        raise ValueError(f"{name} must be real, got {expression}")
    return expression


def as_expressions(value: object, name: str, count: int, what: str) -> tuple[Any, ...]:
    """``value`` as exactly ``count`` expressions; ``what`` names them in messages ("angles").

    Examples
    --------
    >>> as_expressions([0, 1, 2], "angles", 3, "angles")
    (0, 1, 2)
    >>> as_expressions([0, 1], "angles", 3, "angles")
    Traceback (most recent call last):
    ...
    ValueError: angles must hold exactly 3 angles, got 2
    """
    wanted = f"{count} {what}, each {_WANTED}"
    if isinstance(value, (str, bytes)):
        raise TypeError(f"{name} must be {wanted}, not text ({value!r}); text is never evaluated")
    if isinstance(value, sp.MatrixBase):
        if 1 not in value.shape:
            rows, columns = value.shape
            raise ValueError(f"{name} must be {wanted}, got a {rows}×{columns} matrix")
        items = list(value)
    elif isinstance(value, np.ndarray):
        if value.ndim != 1:
            raise ValueError(f"{name} must be {wanted}, got an array of shape {value.shape}")
        items = list(value)
    elif isinstance(value, (SequenceABC, sp.Tuple)):
        items = list(value)
    else:
        raise TypeError(f"{name} must be {wanted} (a tuple or list), got {type(value).__name__}")
    if len(items) != count:
        raise ValueError(f"{name} must hold exactly {count} {what}, got {len(items)}")
    return tuple(as_expression(item, f"{name}[{i}]") for i, item in enumerate(items))


def as_axis_angle(axis: object, angle: object) -> tuple[Any, Any]:
    """``axis`` as a SymPy column of three expressions (taken as given) and ``angle``."""
    k = sp.Matrix(as_expressions(axis, "axis", 3, "components"))
    return k, as_expression(angle, "angle")


def as_distinct_symbols(value: object, name: str, count: int) -> tuple[Any, ...]:
    """``value`` as ``count`` distinct ``sympy.Symbol`` objects."""
    symbols = as_expressions(value, name, count, "symbols")
    if not all(isinstance(symbol, sp.Symbol) for symbol in symbols) or len(set(symbols)) != count:
        raise ValueError(f"{name} must be {count} distinct SymPy symbols, got {symbols}")
    return symbols


def as_symbol(value: object, name: str) -> Any:
    """``value`` when it is a ``sympy.Symbol``."""
    if isinstance(value, (str, bytes)):
        raise TypeError(
            f"{name} must be a SymPy Symbol, not text ({value!r}); for example sp.Symbol('t')"
        )
    if not isinstance(value, sp.Symbol):
        raise TypeError(f"{name} must be a SymPy Symbol, got {type(value).__name__} {value!r}")
    return value


def as_matrix(value: object, name: str) -> Any:
    """``value`` as a 3×3 ``sympy.Matrix`` of finite expressions."""
    if isinstance(value, (str, bytes)):
        raise TypeError(f"{name} must be a 3×3 SymPy matrix, not text ({value!r})")
    if isinstance(value, (sp.MatrixBase, np.ndarray)):
        shape = value.shape
        rows = value.tolist()
    elif isinstance(value, SequenceABC) and all(
        isinstance(row, SequenceABC) and not isinstance(row, (str, bytes)) for row in value
    ):
        rows = [list(row) for row in value]
        lengths = {len(row) for row in rows}
        if len(lengths) > 1:
            raise ValueError(f"{name} must be a 3×3 matrix, got rows of lengths {sorted(lengths)}")
        shape = (len(rows), *(lengths or {0}))
    else:
        raise TypeError(f"{name} must be a 3×3 SymPy matrix, got {type(value).__name__}")
    if tuple(shape) != (3, 3):
        raise ValueError(f"{name} must be a 3×3 matrix, got shape {tuple(shape)}")
    return sp.Matrix(
        [[as_expression(rows[i][j], f"{name}[{i}, {j}]") for j in range(3)] for i in range(3)]
    )
