"""Elementary rotations as SymPy matrices, derived column by column."""

from __future__ import annotations

from typing import Any

import sympy as sp

_AXIS_NAMES = {"x": 0, "y": 1, "z": 2, 0: 0, 1: 1, 2: 2}


def _axis_index(axis: object) -> int:
    key = axis.lower() if isinstance(axis, str) else axis
    if not isinstance(key, (str, int)) or isinstance(key, bool) or key not in _AXIS_NAMES:
        raise ValueError(f"axis must be 'x', 'y', 'z' or 0, 1, 2, got {axis!r}")
    return _AXIS_NAMES[key]


def _basis(index: int) -> Any:
    return sp.Matrix([1 if i == index else 0 for i in range(3)])


def elementary_matrix(axis: str | int, angle: Any) -> Any:
    """Active right-handed rotation by ``angle`` about a coordinate axis, as a SymPy matrix.

    The matrix is derived, not typed in: column ``j`` is the image of the basis vector ``e_j``
    under a right-handed turn about the axis ``k``, namely
    ``(k·e_j) k + cos θ (e_j − (k·e_j) k) + sin θ (k × e_j)``.

    Parameters
    ----------
    axis : {'x', 'y', 'z', 0, 1, 2}
        The axis to turn about (letters in either case).
    angle : sympy expression or number
        The angle in radians; a symbol, an expression, or an exact number such as ``sp.pi/2``.

    Returns
    -------
    sympy.Matrix, shape (3, 3)
        ``R`` such that ``R * v`` is the column vector ``v`` turned by ``angle``.

    Raises
    ------
    ValueError
        If ``axis`` is not one of the accepted values.
    sympy.SympifyError
        If ``angle`` cannot be read by SymPy.

    Examples
    --------
    >>> import sympy as sp
    >>> t = sp.Symbol("theta", real=True)
    >>> elementary_matrix("z", t)
    Matrix([
    [cos(theta), -sin(theta), 0],
    [sin(theta),  cos(theta), 0],
    [         0,           0, 1]])
    >>> elementary_matrix("x", sp.pi / 2) * sp.Matrix([0, 1, 0])   # y turns into z
    Matrix([
    [0],
    [0],
    [1]])
    """
    index = _axis_index(axis)
    theta = sp.sympify(angle)
    k = _basis(index)
    columns = []
    for j in range(3):
        e = _basis(j)
        along = k.dot(e) * k
        image = along + sp.cos(theta) * (e - along) + sp.sin(theta) * k.cross(e)
        columns.append(image.applyfunc(sp.expand))
    return sp.Matrix.hstack(*columns)
