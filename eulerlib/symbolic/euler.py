"""Euler-angle matrices as products of three elementary rotations.

For an intrinsic (uppercase) sequence such as ``"ZYX"`` with angles ``(α, β, γ)`` the matrix is
``R_z(α) R_y(β) R_x(γ)``: the product is written in the order in which the rotations about the
*moving* axes happen. An extrinsic (lowercase) sequence turns about *fixed* axes and the product
is reversed: ``"zyx"`` gives ``R_x(γ) R_y(β) R_z(α)``. The ``seq`` strings are those of
:func:`eulerlib.euler_to_matrix` and SciPy's ``Rotation.from_euler``, and the presets
(``"rose"``, ``"baker"``, ``"ros"``) are accepted wherever a ``seq`` is.
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from eulerlib.conventions import Convention, get_convention
from eulerlib.sequences import Sequence
from eulerlib.symbolic._arguments import as_expressions
from eulerlib.symbolic.axis_angle import basis_vector, turn_about

__all__ = ["euler_matrix", "euler_symbols"]


def euler_symbols(seq: str | Convention | None = None) -> tuple[Any, Any, Any]:
    """Default symbols for the three angles of a sequence: ``alpha``, ``beta``, ``gamma``.

    ``alpha`` goes with the first letter of ``seq``, ``beta`` with the middle letter and
    ``gamma`` with the third, whatever the axes are and whether the sequence is intrinsic or
    extrinsic (so ``beta`` is always the angle that decides gimbal lock). The symbols are real,
    which lets SymPy simplify ``sqrt(cos(beta)**2)`` to ``Abs(cos(beta))``.

    Parameters
    ----------
    seq : str or Convention, optional
        An axis sequence or preset; checked when given, but the symbols are the same for all.

    Returns
    -------
    tuple of sympy.Symbol
        ``(alpha, beta, gamma)``.

    Raises
    ------
    TypeError, ValueError
        If ``seq`` is given and is not a valid sequence or preset.

    Examples
    --------
    >>> euler_symbols()
    (alpha, beta, gamma)
    >>> euler_symbols("ZYX")[1].is_real
    True
    """
    if seq is not None:
        get_convention(seq)
    alpha, beta, gamma = sp.symbols("alpha beta gamma", real=True)
    return alpha, beta, gamma


def refuse_convention_first(angles: object) -> None:
    """A clear ``TypeError`` for the 0.1 argument order, where the sequence came first."""
    if isinstance(angles, (str, Convention)):
        try:
            get_convention(angles, "angles")
        except ValueError:
            return
        raise TypeError(
            f"angles must be SymPy expressions or numbers, got the convention {angles!r}: the "
            "angles come first and the convention second, as in euler_matrix(angles, seq)"
        )


def euler_angles(angles: object, seq: object) -> tuple[Sequence, tuple[Any, Any, Any]]:
    """Check ``angles`` (three expressions) and ``seq`` (a sequence or preset) once."""
    refuse_convention_first(angles)
    parsed = get_convention(seq).parsed
    a, b, c = as_expressions(angles, "angles", 3, "angles")
    return parsed, (a, b, c)


def euler_product(parsed: Sequence, values: tuple[Any, Any, Any]) -> Any:
    """The product of the three elementary rotations of a checked sequence, expanded."""
    factors = [
        turn_about(basis_vector(axis), angle)
        for axis, angle in zip(parsed.intrinsic_axes, parsed.intrinsic_order(values), strict=True)
    ]
    product = factors[0] * factors[1] * factors[2]
    return product.applyfunc(sp.expand)


def euler_matrix(angles: Any, seq: str | Convention = "ZYX") -> Any:
    """The rotation matrix of an Euler-angle sequence, as a product of elementary rotations.

    Parameters
    ----------
    angles : sequence of 3 SymPy expressions or numbers
        The angles in radians, in the order of the letters of ``seq``. For symbols, use your
        own (``sp.symbols("w v u", real=True)``) or :func:`euler_symbols`.
    seq : str or Convention, optional
        One of the 24 axis sequences, read as in :func:`eulerlib.euler_to_matrix` and SciPy's
        ``Rotation.from_euler`` (uppercase intrinsic, moving axes; lowercase extrinsic, fixed
        axes; angle ``i`` with letter ``i``), or a preset such as ``"rose"``. Default ``"ZYX"``.

    Returns
    -------
    sympy.Matrix, shape (3, 3)
        For an intrinsic sequence ``"ABC"`` and angles ``(a, b, c)``: ``R_A(a) R_B(b) R_C(c)``;
        for an extrinsic sequence ``"abc"``: ``R_C(c) R_B(b) R_A(a)``. The product is multiplied
        out but not simplified further.

    Raises
    ------
    TypeError, ValueError
        If ``angles`` is not three expressions or numbers (text is refused, not evaluated), or
        ``seq`` is neither a sequence nor a preset.

    Notes
    -----
    ``euler_matrix((w, v, u), "ZYX")`` with yaw ``w``, pitch ``v`` and roll ``u`` is
    Rose (2015), Part 2, eq 2. ``euler_matrix((h, a, b), "YZX")`` with heading, attitude and
    bank is the matrix of Baker, "Matrix to Euler" (y up).

    Examples
    --------
    >>> import sympy as sp
    >>> euler_matrix((sp.pi / 2, 0, 0), "ZYX")   # yaw 90°: x turns into y
    Matrix([
    [0, -1, 0],
    [1,  0, 0],
    [0,  0, 1]])
    >>> w, v, u = sp.symbols("w v u", real=True)   # yaw, pitch, roll
    >>> R = euler_matrix((w, v, u), "rose")
    >>> R[:, 0].T    # where the body's x axis (the nose) points
    Matrix([[cos(v)*cos(w), sin(w)*cos(v), -sin(v)]])
    >>> R == euler_matrix((u, v, w), "xyz")   # the same rotation about fixed axes
    True
    """
    parsed, values = euler_angles(angles, seq)
    return euler_product(parsed, values)
