"""A turn about any axis: the Rodrigues construction, the cross-product matrix, the closed form.

Turning a vector ``v`` by θ about a unit axis ``k`` (right-hand rule: thumb along ``k``, fingers
curl the way the turn goes) splits ``v`` into the part along the axis, which stays, and the part
across it, which turns in the plane perpendicular to ``k``:

.. math::

    v_∥ = (k \\cdot v)\\,k, \\qquad v_⊥ = v - v_∥, \\qquad
    R v = v_∥ + \\cos θ\\, v_⊥ + \\sin θ\\, (k \\times v).

``k × v`` is ``v_⊥`` turned a quarter turn about ``k``, so the last two terms are ``v_⊥`` turned
by θ. Column ``j`` of the matrix is the image of the basis vector ``e_j``;
:func:`rodrigues_matrix` builds the matrix column by column in exactly this way, and
:func:`elementary_matrix` is the same construction about a coordinate axis.

The cross product with ``k`` is a linear map, so it has a matrix, ``[k]×`` (:func:`skew`), with
``[k]× v = k × v``. Its square is ``k kᵀ − I`` for a unit ``k`` (it removes the part along
``k`` and reverses the rest), so ``v_⊥ = −[k]×² v`` and the construction collapses to one
formula in ``[k]×`` alone, the rotation-vector form computed by :func:`axis_angle_matrix`:

.. math:: R = I + \\sin θ\\,[k]_× + (1 - \\cos θ)\\,[k]_×^2.

Both forms hold only for a unit axis; the functions take the axis as given and do not
normalize it, so that a symbolic axis stays free of square roots.
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from eulerlib.sequences import parse_axis
from eulerlib.symbolic._arguments import as_axis_angle, as_expression, as_expressions

__all__ = ["axis_angle_matrix", "elementary_matrix", "rodrigues_matrix", "skew"]


def basis_vector(index: int) -> Any:
    """The basis vector ``e_index`` as a SymPy column."""
    return sp.Matrix([1 if i == index else 0 for i in range(3)])


def turn_about(k: Any, theta: Any) -> Any:
    """The Rodrigues construction for a checked axis column ``k`` and angle ``theta``."""
    columns = []
    for j in range(3):
        e = basis_vector(j)
        along = k.dot(e) * k
        image = along + sp.cos(theta) * (e - along) + sp.sin(theta) * k.cross(e)
        columns.append(image.applyfunc(sp.expand))
    return sp.Matrix.hstack(*columns)


def rodrigues_matrix(axis: Any, angle: Any) -> Any:
    """Rotation by ``angle`` about a unit axis, built from the parts along and across the axis.

    Parameters
    ----------
    axis : sequence of 3 SymPy expressions or numbers
        ``(kx, ky, kz)``, a **unit** vector. It is taken as given, not normalized: for an axis
        that is not unit the result is not a rotation. Symbols are fine; the identities that
        make the result a rotation then hold where ``kx² + ky² + kz² = 1``.
    angle : SymPy expression or number
        The angle in radians (right-hand rule about ``axis``).

    Returns
    -------
    sympy.Matrix, shape (3, 3)
        Column ``j`` is the image of ``e_j``:
        ``(k·e_j) k + cos θ (e_j − (k·e_j) k) + sin θ (k × e_j)``, each entry expanded.

    Raises
    ------
    TypeError, ValueError
        If ``axis`` is not three expressions or numbers, or ``angle`` is not one (text is
        refused, not evaluated).

    See Also
    --------
    axis_angle_matrix : the same matrix from the cross-product matrix ``[k]×``.
    elementary_matrix : the same construction about a coordinate axis.

    Notes
    -----
    The construction, ``R v = v∥ + cos θ v⊥ + sin θ (k × v)``, is Rodrigues' rotation formula
    (O. Rodrigues, 1840). For a coordinate axis it gives ``R_x``, ``R_y``, ``R_z`` of Rose (2015),
    Part 2, eq 1.

    Examples
    --------
    >>> import sympy as sp
    >>> t = sp.Symbol("theta", real=True)
    >>> rodrigues_matrix((0, 0, 1), t)
    Matrix([
    [cos(theta), -sin(theta), 0],
    [sin(theta),  cos(theta), 0],
    [         0,           0, 1]])
    >>> k = sp.Matrix([1, 1, 1]) / sp.sqrt(3)
    >>> rodrigues_matrix(k, 2 * sp.pi / 3)   # a third of a turn about the diagonal: x → y → z
    Matrix([
    [0, 0, 1],
    [1, 0, 0],
    [0, 1, 0]])
    """
    k, theta = as_axis_angle(axis, angle)
    return turn_about(k, theta)


def elementary_matrix(axis: str | int, angle: Any) -> Any:
    """Active right-handed rotation by ``angle`` about a coordinate axis, as a SymPy matrix.

    The matrix is derived, not typed in: it is :func:`rodrigues_matrix` about the basis vector
    of the axis.

    Parameters
    ----------
    axis : {'x', 'y', 'z', 'X', 'Y', 'Z', 0, 1, 2}
        The axis to turn about, read by :func:`eulerlib.parse_axis`: exactly what the numeric
        :func:`eulerlib.elementary_rotation` accepts, with the same errors.
    angle : SymPy expression or number
        The angle in radians; a symbol, an expression, or an exact number such as ``sp.pi/2``.

    Returns
    -------
    sympy.Matrix, shape (3, 3)
        ``R`` such that ``R * v`` is the column vector ``v`` turned by ``angle``.

    Raises
    ------
    TypeError
        If ``axis`` is neither a letter nor an integer (a bool, float or None), or ``angle`` is
        not a SymPy expression or a real number (text is refused, not evaluated).
    ValueError
        If ``axis`` names no axis (``'w'``, ``3``), or ``angle`` is not finite.

    Notes
    -----
    These are ``R_x``, ``R_y`` and ``R_z`` of Rose (2015), Part 2, eq 1.

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
    index = parse_axis(axis)
    theta = as_expression(angle, "angle")
    return turn_about(basis_vector(index), theta)


def skew(v: Any) -> Any:
    """The cross-product matrix ``[v]×``: the matrix with ``[v]× w = v × w`` for every ``w``.

    Parameters
    ----------
    v : sequence of 3 SymPy expressions or numbers
        The vector ``(vx, vy, vz)``.

    Returns
    -------
    sympy.Matrix, shape (3, 3)
        Skew-symmetric (``[v]×ᵀ = −[v]×``); column ``j`` is ``v × e_j``.

    Raises
    ------
    TypeError, ValueError
        If ``v`` is not three expressions or numbers.

    Examples
    --------
    >>> import sympy as sp
    >>> vx, vy, vz = sp.symbols("v_x v_y v_z", real=True)
    >>> skew((vx, vy, vz))
    Matrix([
    [   0, -v_z,  v_y],
    [ v_z,    0, -v_x],
    [-v_y,  v_x,    0]])
    """
    vector = sp.Matrix(as_expressions(v, "v", 3, "components"))
    return cross_matrix(vector)


def cross_matrix(vector: Any) -> Any:
    """``[v]×`` of a checked column, built column by column as ``v × e_j``."""
    return sp.Matrix.hstack(*(vector.cross(basis_vector(j)) for j in range(3)))


def axis_angle_matrix(axis: Any, angle: Any) -> Any:
    """Rotation by ``angle`` about a unit axis, in the rotation-vector form ``I + sin θ [k]× + …``.

    Parameters
    ----------
    axis : sequence of 3 SymPy expressions or numbers
        ``(kx, ky, kz)``, a **unit** vector, taken as given (see :func:`rodrigues_matrix`).
    angle : SymPy expression or number
        The angle in radians.

    Returns
    -------
    sympy.Matrix, shape (3, 3)
        ``I + sin θ [k]× + (1 − cos θ) [k]×²``, each entry expanded. For a unit axis this equals
        :func:`rodrigues_matrix`; otherwise this matrix minus that one is
        ``(1 − cos θ)(1 − |k|²) I``.

    Raises
    ------
    TypeError, ValueError
        If ``axis`` or ``angle`` are not expressions or numbers.

    Notes
    -----
    With ``[k]× v = k × v`` and ``[k]×² v = k × (k × v) = (k·v) k − |k|² v``, a unit ``k`` gives
    ``v⊥ = v − (k·v) k = −[k]×² v``, and Rodrigues' construction
    ``R v = v − v⊥ + cos θ v⊥ + sin θ k × v`` becomes ``v + sin θ [k]× v + (1 − cos θ)[k]×² v``.
    It is the closed form of the matrix exponential ``exp(θ [k]×)``, and the form in which
    the rotation vector ``θ k`` is usually turned into a matrix.

    Examples
    --------
    >>> import sympy as sp
    >>> axis_angle_matrix((1, 0, 0), sp.pi / 2)
    Matrix([
    [1, 0,  0],
    [0, 0, -1],
    [0, 1,  0]])
    >>> k = sp.Matrix([0, 3, 4]) / 5
    >>> t = sp.Symbol("theta", real=True)
    >>> sp.simplify(axis_angle_matrix(k, t) - rodrigues_matrix(k, t))
    Matrix([
    [0, 0, 0],
    [0, 0, 0],
    [0, 0, 0]])
    """
    k, theta = as_axis_angle(axis, angle)
    K = cross_matrix(k)
    R = sp.eye(3) + sp.sin(theta) * K + (1 - sp.cos(theta)) * K * K
    return R.applyfunc(sp.expand)
