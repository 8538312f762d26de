"""A fast, sound simplification for the entries of rotation matrices: sin² x = 1 − cos² x.

The entries of products of rotation matrices, and of their derivatives, are polynomials in the
sines and cosines of a few angles (and, for a matrix function of ``t``, in the angles' rates).
Writing every ``sin(x)**n`` with ``n ≥ 2`` as ``sin(x)**(n mod 2) · (1 − cos(x)**2)**(n // 2)``
and multiplying out leaves each sine to the power 0 or 1. That is the remainder of the
polynomial modulo the relations ``sin² x + cos² x − 1`` (which form a Gröbner basis, since their
leading terms ``sin² x`` share no variable), so it is a normal form: a polynomial identity that
follows from those relations reduces to 0. It is tens of times faster than ``sp.trigsimp`` on
such entries. It does not know other identities (``sin 2x = 2 sin x cos x``, or ``sin(θ/2)``
against ``sin θ``); :func:`vanishes` falls back on ``sp.simplify`` for those.
"""

from __future__ import annotations

from typing import Any

import sympy as sp


def _is_sine_power(expression: Any) -> bool:
    return bool(
        expression.is_Pow
        and isinstance(expression.base, sp.sin)
        and expression.exp.is_Integer
        and expression.exp > 1
    )


def _lowered(power: Any) -> Any:
    n = int(power.exp)
    cosine = sp.cos(power.base.args[0])
    return power.base ** (n % 2) * (1 - cosine**2) ** (n // 2)


def pythagorean_form(expression: Any) -> Any:
    """``expression`` multiplied out with every sine to the power 0 or 1.

    Examples
    --------
    >>> import sympy as sp
    >>> x, y = sp.symbols("x y", real=True)
    >>> pythagorean_form(sp.sin(x) ** 2 * sp.cos(y) + sp.cos(x) ** 2 * sp.cos(y))
    cos(y)
    """
    expanded = sp.expand(expression)
    return sp.expand(expanded.replace(_is_sine_power, _lowered))


def vanishes(expression: Any) -> bool:
    """Whether ``expression`` simplifies to 0: by :func:`pythagorean_form`, else ``sp.simplify``."""
    reduced = pythagorean_form(expression)
    return bool(reduced == 0 or sp.simplify(reduced) == 0)
