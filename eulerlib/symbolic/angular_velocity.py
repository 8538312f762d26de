"""Angular velocity: read off ``Ṙ Rᵀ``, and produced by angle rates through a Jacobian.

A rotation that changes with time, ``R(t)``, stays a rotation: ``R Rᵀ = I`` for every ``t``.
Differentiating gives ``Ṙ Rᵀ + R Ṙᵀ = 0``, so ``Ṙ Rᵀ`` is skew-symmetric: it is the
cross-product matrix ``[ω]×`` of one vector ``ω``, the angular velocity in the fixed (space)
frame, and ``Ṙ v = ω × (R v)`` for every body-fixed ``v``. Likewise ``Rᵀ Ṙ = [ω_b]×`` gives the
angular velocity in the body's own axes, ``ω_b = Rᵀ ω``.
:func:`angular_velocity_from_matrix` computes either one for any matrix function of ``t``.

For Euler angles the angular velocity is linear in the angle rates: ``ω = J (α̇, β̇, γ̇)``,
where column ``i`` of :func:`angular_velocity_jacobian` is the axis of rotation ``i`` as it
lies when that rotation happens. Its determinant (:func:`jacobian_determinant`) is ``±cos β``
for a Tait–Bryan sequence and ``±sin β`` for a proper Euler one, the same factor that vanishes
at gimbal lock: there one direction of angular velocity cannot be produced by any angle rates.
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from eulerlib._validation import check_choice
from eulerlib.conventions import Convention
from eulerlib.symbolic._arguments import as_matrix, as_symbol
from eulerlib.symbolic._pythagoras import pythagorean_form, vanishes
from eulerlib.symbolic.axis_angle import basis_vector, turn_about
from eulerlib.symbolic.euler import euler_angles

__all__ = ["angular_velocity_from_matrix", "angular_velocity_jacobian", "jacobian_determinant"]

FRAMES = ("body", "space")


def angular_velocity_jacobian(
    angles: Any, seq: str | Convention = "ZYX", *, frame: str = "body"
) -> Any:
    """The matrix that turns angle rates into angular velocity.

    If the angles change at rates ``(α̇, β̇, γ̇)`` (in the order of ``seq``), the rotation
    ``R(t) = euler_matrix(angles(t), seq)`` turns with angular velocity ``ω = J (α̇, β̇, γ̇)``,
    that is ``Ṙ Rᵀ = [ω]×`` in the fixed (space) frame, or ``Rᵀ Ṙ = [ω]×`` in the body frame.

    Parameters
    ----------
    angles : sequence of 3 SymPy expressions or numbers
        The angles, in the order of the letters of ``seq`` (see :func:`euler_symbols`).
    seq : str or Convention, optional
        One of the 24 axis sequences, or a preset. Default ``"ZYX"``.
    frame : {'body', 'space'}, optional
        Express ``ω`` in the rotating body's axes (default) or in the fixed axes.

    Returns
    -------
    sympy.Matrix, shape (3, 3)
        Column ``i`` is the unit axis of rotation ``i`` of ``seq``, as it lies when that
        rotation happens, expressed in the requested frame.

    Raises
    ------
    TypeError, ValueError
        If ``angles``, ``seq`` or ``frame`` are invalid.

    Notes
    -----
    For the intrinsic form ``R = A(a) B(b) C(c)`` (axes ``e_A``, ``e_B``, ``e_C``) the space-frame
    angular velocity is ``ȧ e_A + ḃ A e_B + ċ A B e_C``: each rate turns about its axis as
    moved by the rotations before it. The body-frame one is ``Rᵀ`` times that,
    ``ȧ Cᵀ Bᵀ e_A + ḃ Cᵀ e_B + ċ e_C``. An extrinsic sequence is the intrinsic one with the angles
    reversed, so its columns are the same, in reversed order.

    Examples
    --------
    >>> import sympy as sp
    >>> w, v, u = sp.symbols("w v u", real=True)
    >>> angular_velocity_jacobian((w, v, u), "ZYX")    # body rates (p, q, r) of an aircraft
    Matrix([
    [       -sin(v),       0, 1],
    [sin(u)*cos(v),  cos(u), 0],
    [cos(u)*cos(v), -sin(u), 0]])
    """
    parsed, values = euler_angles(angles, seq)
    in_space = check_choice(frame, "frame", FRAMES) == "space"
    axes = parsed.intrinsic_axes
    intrinsic_values = parsed.intrinsic_order(values)
    A, B, C = (
        turn_about(basis_vector(axis), angle)
        for axis, angle in zip(axes, intrinsic_values, strict=True)
    )
    e = [basis_vector(axis) for axis in axes]
    if in_space:
        columns = [e[0], A * e[1], A * B * e[2]]
    else:
        columns = [C.T * B.T * e[0], C.T * e[1], e[2]]
    written = parsed.intrinsic_order((columns[0], columns[1], columns[2]))
    return sp.Matrix.hstack(*written).applyfunc(sp.expand)


def jacobian_determinant(angles: Any, seq: str | Convention = "ZYX", *, frame: str = "body") -> Any:
    """Determinant of :func:`angular_velocity_jacobian`, simplified.

    Parameters
    ----------
    angles : sequence of 3 SymPy expressions or numbers
        The angles, in the order of the letters of ``seq``.
    seq : str or Convention, optional
        One of the 24 axis sequences, or a preset. Default ``"ZYX"``.
    frame : {'body', 'space'}, optional
        Either frame gives the same determinant, since the two Jacobians differ by a rotation.

    Returns
    -------
    sympy expression
        ``±cos(middle)`` for a Tait–Bryan sequence, ``±sin(middle)`` for a proper Euler one:
        zero exactly at gimbal lock, where the three rates can no longer produce every angular
        velocity.

    Raises
    ------
    TypeError, ValueError
        If ``angles``, ``seq`` or ``frame`` are invalid.

    Examples
    --------
    >>> import sympy as sp
    >>> w, v, u = sp.symbols("w v u", real=True)
    >>> jacobian_determinant((w, v, u), "ZYX")
    -cos(v)
    >>> from eulerlib.symbolic import euler_symbols
    >>> jacobian_determinant(euler_symbols(), "ZXZ")
    -sin(beta)
    """
    J = angular_velocity_jacobian(angles, seq, frame=frame)
    return sp.factor(sp.trigsimp(sp.expand(J.det())))


def _require_zero(matrix: Any, what: str) -> None:
    """Raise ``ValueError`` unless every entry on and above the diagonal simplifies to 0."""
    for i in range(3):
        for j in range(i, 3):
            if not vanishes(matrix[i, j]):
                raise ValueError(f"{what}: entry ({i}, {j}) is {pythagorean_form(matrix[i, j])}")


def angular_velocity_from_matrix(R: Any, t: Any, *, frame: str = "body") -> Any:
    """The angular velocity of a rotation matrix that depends on ``t``, read off ``Ṙ Rᵀ``.

    Parameters
    ----------
    R : sympy.Matrix, shape (3, 3)
        A rotation matrix for every value of ``t``, for example
        ``euler_matrix(angles, seq)`` with angles that are functions of ``t``
        (``sp.Function("alpha", real=True)(t)``).
    t : sympy.Symbol
        The variable ``R`` depends on (time).
    frame : {'body', 'space'}, optional
        ``'body'`` (default): ``ω`` in the body's axes, from ``Rᵀ Ṙ = [ω]×``; ``'space'``: in the
        fixed axes, from ``Ṙ Rᵀ = [ω]×``. The same keyword means the same frame in
        :func:`angular_velocity_jacobian`.

    Returns
    -------
    sympy.Matrix, shape (3, 1)
        ``ω = (S[2, 1], S[0, 2], S[1, 0])`` of the skew-symmetric ``S``, each entry simplified
        with ``sin² x = 1 − cos² x`` and multiplied out.

    Raises
    ------
    TypeError
        If ``R`` is not a 3×3 matrix of expressions (text is refused, not evaluated), ``t`` is
        not a ``sympy.Symbol``, or ``frame`` is not a string.
    ValueError
        If ``frame`` is not ``'body'`` or ``'space'``, or ``R Rᵀ − I`` does not simplify to 0,
        so that ``R`` is not a rotation for every ``t`` (the message shows the first entry that
        is left), or ``S`` cannot be shown to be skew-symmetric.

    Notes
    -----
    ``S`` is skew-symmetric because ``R Rᵀ = I`` for all ``t`` (see the module docstring); the
    function checks both facts in the algebra before it reads ``ω`` off ``S``. The check uses
    ``sin² x + cos² x = 1`` for every angle that occurs, then ``sp.simplify``; an identity that
    SymPy cannot prove is reported as a ``ValueError``, never assumed. The check is exact, so a
    matrix with floating-point entries, which carry rounding, is refused: use exact numbers
    (``sp.Rational``, ``sp.pi``) or symbols.

    Examples
    --------
    >>> import sympy as sp
    >>> from eulerlib.symbolic import elementary_matrix, euler_matrix
    >>> t = sp.Symbol("t", real=True)
    >>> theta = sp.Function("theta", real=True)(t)
    >>> angular_velocity_from_matrix(elementary_matrix("z", theta), t).T
    Matrix([[0, 0, Derivative(theta(t), t)]])
    >>> yaw, pitch, roll = (sp.Function(n, real=True)(t) for n in ("w", "v", "u"))
    >>> omega = angular_velocity_from_matrix(euler_matrix((yaw, pitch, roll), "rose"), t)
    >>> omega[0]    # roll rate p of an aircraft
    -sin(v(t))*Derivative(w(t), t) + Derivative(u(t), t)
    """
    matrix = as_matrix(R, "R")
    variable = as_symbol(t, "t")
    in_space = check_choice(frame, "frame", FRAMES) == "space"
    _require_zero(
        matrix * matrix.T - sp.eye(3),
        "R must be a rotation matrix for every value of t, but R Rᵀ − I does not simplify to 0",
    )
    rate = matrix.diff(variable)
    S = rate * matrix.T if in_space else matrix.T * rate
    _require_zero(
        S + S.T, f"could not show that {'Ṙ Rᵀ' if in_space else 'Rᵀ Ṙ'} is skew-symmetric"
    )
    return sp.Matrix([S[2, 1], S[0, 2], S[1, 0]]).applyfunc(pythagorean_form)
