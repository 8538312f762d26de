"""Euler-angle matrices as products of three elementary rotations."""

from __future__ import annotations

from collections.abc import Sequence as SequenceABC
from typing import Any

import sympy as sp

from eulerlib.sequences import Sequence, parse_sequence
from eulerlib.symbolic.elementary import elementary_matrix


def euler_symbols(seq: str) -> tuple[Any, Any, Any]:
    """Default symbols for the three angles of a sequence: ``alpha``, ``beta``, ``gamma``.

    ``alpha`` goes with the first letter of ``seq``, ``beta`` with the middle letter and
    ``gamma`` with the third, whatever the axes are and whether the sequence is intrinsic or
    extrinsic (so ``beta`` is always the angle that decides gimbal lock). The symbols are real,
    which lets SymPy simplify ``sqrt(cos(beta)**2)`` to ``Abs(cos(beta))``.

    Parameters
    ----------
    seq : str
        One of the 24 axis sequences (checked).

    Returns
    -------
    tuple of sympy.Symbol
        ``(alpha, beta, gamma)``.

    Raises
    ------
    TypeError, ValueError
        If ``seq`` is not a valid sequence.

    Examples
    --------
    >>> euler_symbols("ZYX")
    (alpha, beta, gamma)
    >>> euler_symbols("ZYX")[1].is_real
    True
    """
    parse_sequence(seq)
    alpha, beta, gamma = sp.symbols("alpha beta gamma", real=True)
    return alpha, beta, gamma


def _angles(seq: str, angles: SequenceABC[Any] | None) -> tuple[Sequence, tuple[Any, Any, Any]]:
    parsed = parse_sequence(seq)
    if angles is None:
        return parsed, euler_symbols(seq)
    if isinstance(angles, (str, bytes)) or not isinstance(angles, SequenceABC):
        raise TypeError(
            f"angles must be a sequence of three SymPy expressions or numbers, got "
            f"{type(angles).__name__}"
        )
    if len(angles) != 3:
        raise ValueError(f"angles must hold exactly 3 angles, got {len(angles)}")
    a, b, c = (sp.sympify(angle) for angle in angles)
    return parsed, (a, b, c)


def euler_matrix(seq: str, angles: SequenceABC[Any] | None = None) -> Any:
    """The rotation matrix of an Euler-angle sequence, as a product of elementary rotations.

    Parameters
    ----------
    seq : str
        One of the 24 axis sequences, read as in :func:`eulerlib.euler_to_matrix` and SciPy's
        ``Rotation.from_euler``: uppercase intrinsic (moving axes), lowercase extrinsic (fixed
        axes), angle ``i`` with letter ``i``.
    angles : sequence of 3 sympy expressions or numbers, optional
        The angles in radians. Default: :func:`euler_symbols` (``alpha``, ``beta``, ``gamma``).

    Returns
    -------
    sympy.Matrix, shape (3, 3)
        For an intrinsic sequence ``"ABC"`` and angles ``(a, b, c)``: ``R_A(a) R_B(b) R_C(c)``;
        for an extrinsic sequence ``"abc"``: ``R_C(c) R_B(b) R_A(a)``. The product is multiplied
        out but not simplified further.

    Raises
    ------
    TypeError, ValueError
        If ``seq`` is invalid, or ``angles`` is not three values.

    Notes
    -----
    ``euler_matrix("ZYX", (w, v, u))`` with yaw ``w``, pitch ``v`` and roll ``u`` is
    Rose (2015), Part 2, eq 2. ``euler_matrix("YZX", (h, a, b))`` with heading, attitude and
    bank is the matrix of Baker, "Matrix to Euler" (y up).

    Examples
    --------
    >>> import sympy as sp
    >>> euler_matrix("ZYX", (sp.pi / 2, 0, 0))   # yaw 90°: x turns into y
    Matrix([
    [0, -1, 0],
    [1,  0, 0],
    [0,  0, 1]])
    >>> a, b, c = euler_symbols("ZYX")
    >>> euler_matrix("ZYX") == euler_matrix("xyz", (c, b, a))   # same rotation, fixed axes
    True
    """
    parsed, values = _angles(seq, angles)
    factors = [
        elementary_matrix(axis, angle) for axis, angle in zip(parsed.axes, values, strict=True)
    ]
    if not parsed.intrinsic:
        factors.reverse()
    product = factors[0] * factors[1] * factors[2]
    return product.applyfunc(sp.expand)
