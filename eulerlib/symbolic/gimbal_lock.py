"""The matrix at gimbal lock, written with the one combination of outer angles it keeps.

When the middle angle is singular (±90° for a Tait–Bryan sequence, 0° or 180° for a proper
Euler sequence) the first and third rotations turn about the same line, and the matrix depends
on one sum or difference of the outer angles only (Rose 2015, Part 2, eq 4; Baker's two poles).
:func:`gimbal_lock_matrix` finds which one in the algebra and writes the matrix in that form,
as the convention's lock policy does with numbers: the angle it sets to 0 is 0, and the other
carries the combination (see :mod:`eulerlib.conventions`).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import sympy as sp

from eulerlib.conventions import Convention, get_convention
from eulerlib.gimbal_lock import lock_combination
from eulerlib.symbolic._arguments import as_expressions
from eulerlib.symbolic.euler import euler_product, refuse_convention_first

__all__ = ["gimbal_lock_matrix"]

_NUMBERS = (int, float, np.integer, np.floating, sp.Number)


def singular_middle(pole: object, convention: Convention) -> Any:
    """The exact middle angle (radians) of a pole given in degrees, checked for the sequence."""
    if isinstance(pole, (bool, np.bool_)) or not isinstance(pole, _NUMBERS):
        raise TypeError(
            "pole must be a number of degrees, the middle angle at lock (90 or -90 for a "
            f"Tait–Bryan sequence, 0 or 180 for a proper Euler one), got {pole!r} "
            f"({type(pole).__name__})"
        )
    try:
        degrees = float(pole)
    except OverflowError:
        degrees = math.inf
    number = int(degrees) if degrees.is_integer() else degrees
    lock_combination(convention, number)  # which poles the sequence has is checked there
    return sp.pi * sp.Integer(number) / 180


def _same_matrix(A: Any, B: Any) -> bool:
    """Whether two matrices of sines and cosines agree once every sum inside them is expanded."""
    difference = (A - B).applyfunc(lambda entry: sp.expand(sp.expand_trig(entry)))
    return bool(difference.is_zero_matrix)


def _at_lock(convention: Convention, middle: Any, combination: Any) -> tuple[Any, Any, Any]:
    """The three angles in argument order at lock: the zeroed one 0, the carrier ``combination``."""
    values = [0, middle, 0]
    values[convention.carrier_index] = combination
    return values[0], values[1], values[2]


def _combination_sign(convention: Convention, middle: Any) -> int:
    """The sign ``σ`` with which the carrier takes ``carrier + σ·zeroed`` at this pole.

    Found with two fresh symbols for the outer angles, so that it does not depend on what the
    caller's angles are (numbers such as 1 and 2 would hide the identity ``sin 3 = sin(1 + 2)``).
    """
    parsed = convention.parsed
    first, third = sp.Dummy("first", real=True), sp.Dummy("third", real=True)
    outer = (first, middle, third)
    at_pole = euler_product(parsed, outer)
    zeroed, carrier = outer[convention.zeroed_index], outer[convention.carrier_index]
    for sign in (-1, 1):
        values = _at_lock(convention, middle, carrier + sign * zeroed)
        if _same_matrix(euler_product(parsed, values), at_pole):
            return sign
    raise AssertionError(  # pragma: no cover - at a pole one of the two always matches
        f"no sum or difference form found for {parsed.seq!r} at middle angle {middle}"
    )


def gimbal_lock_matrix(angles: Any, seq: str | Convention, *, pole: float) -> Any:
    """The matrix at gimbal lock, written with the one combination of outer angles it depends on.

    Parameters
    ----------
    angles : sequence of 2 SymPy expressions or numbers
        The two **outer** angles, first and third in the order of ``seq``; the middle one is
        the pole. With Rose's yaw ``w``, pitch and roll ``u``: ``(w, u)``.
    seq : str or Convention
        One of the 24 axis sequences, or a preset such as ``"rose"`` or ``"baker"``. Its lock
        policy decides which outer angle the result writes as 0.
    pole : {90, -90, 0, 180}
        The singular middle angle in degrees, as for :func:`eulerlib.lock_combination`:
        90 or −90 for a Tait–Bryan sequence, 0 or 180 for a proper Euler sequence.

    Returns
    -------
    sympy.Matrix, shape (3, 3)
        ``euler_matrix`` at the pole, with the outer angle the convention zeroes at lock set to
        0 and the other replaced by the combination it carries: its entries involve the outer
        angles only through one sum or difference (for example ``sin(u - w)`` for ``"ZYX"``
        at pitch +90°, Rose (2015), Part 2, eq 4).

    Raises
    ------
    TypeError, ValueError
        If ``angles`` is not two expressions or numbers, ``seq`` is neither a sequence nor a
        preset, or ``pole`` is not a singular middle angle of the sequence.

    Notes
    -----
    At the pole the matrix depends on ``third + σ·first`` for one sign ``σ``. Writing it with
    the zeroed angle 0 and the carrier replaced by ``carrier ± zeroed`` gives two candidates;
    for two free symbols, exactly one of them equals the matrix at the pole once every sine and
    cosine of a sum is expanded, and its sign is used for the angles given (numbers too). The
    sign found here is the one :func:`eulerlib.lock_combination` states.

    Examples
    --------
    >>> import sympy as sp
    >>> w, u = sp.symbols("w u", real=True)   # Rose's yaw and roll
    >>> gimbal_lock_matrix((w, u), "rose", pole=90)
    Matrix([
    [ 0, sin(u - w),  cos(u - w)],
    [ 0, cos(u - w), -sin(u - w)],
    [-1,          0,           0]])
    >>> h, b = sp.symbols("h b", real=True)   # Baker's heading and bank; bank is zeroed
    >>> gimbal_lock_matrix((h, b), "baker", pole=90)
    Matrix([
    [0, -cos(b + h), sin(b + h)],
    [1,           0,          0],
    [0,  sin(b + h), cos(b + h)]])
    """
    refuse_convention_first(angles)
    convention = get_convention(seq)
    parsed = convention.parsed
    first, third = as_expressions(angles, "angles", 2, "outer angles (first, third)")
    middle = singular_middle(pole, convention)
    sign = _combination_sign(convention, middle)
    outer = (first, middle, third)
    zeroed, carrier = outer[convention.zeroed_index], outer[convention.carrier_index]
    return euler_product(parsed, _at_lock(convention, middle, carrier + sign * zeroed))
