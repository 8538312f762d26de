"""Helpers of the symbolic tests: numbers from SymPy matrices, and identities decided exactly.

:func:`holds` decides whether an expression vanishes given ``sin² + cos² = 1`` for some angles
and ``|k| = 1`` for some unit vectors, by reducing it modulo those relations with SymPy's
Gröbner-basis machinery (``sp.groebner``, ``sp.reduced``). It shares no code with the library's
own simplification, so a test that uses it does not check the library against itself.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any

import numpy as np
import sympy as sp


def numeric(matrix: Any, symbols: tuple[Any, ...]) -> Callable[..., np.ndarray]:
    """A fast numeric version of a symbolic matrix: ``f(*values) -> float ndarray``."""
    function = sp.lambdify(symbols, matrix, "numpy")
    return lambda *values: np.asarray(function(*values), dtype=float)


def holds(
    expression: Any, *, angles: Iterable[Any] = (), units: Iterable[Iterable[Any]] = ()
) -> bool:
    """Whether ``expression`` (or every entry of a matrix) is 0 given the relations.

    ``angles``: expressions ``x`` with ``sin(x)**2 + cos(x)**2 = 1``; ``units``: vectors whose
    components' squares add up to 1. The relations' leading terms (``sin(x)**2`` and the first
    component squared, in lex order) share no variable, so they are a Gröbner basis and the
    remainder is 0 exactly when the expression lies in the ideal they generate.
    """
    angles = list(angles)
    units = [list(unit) for unit in units]
    sines = [sp.sin(x) for x in angles]
    cosines = [sp.cos(x) for x in angles]
    components = [c for unit in units for c in unit]
    relations = [s**2 + c**2 - 1 for s, c in zip(sines, cosines, strict=True)]
    relations += [sum(c**2 for c in unit) - 1 for unit in units]
    entries = list(expression) if isinstance(expression, sp.MatrixBase) else [expression]
    for entry in entries:
        expanded = sp.expand(entry)
        if expanded == 0:
            continue
        if not relations:
            return False
        _, remainder = sp.reduced(expanded, relations, *sines, *components, *cosines, order="lex")
        if sp.expand(remainder) != 0:
            return False
    return True
