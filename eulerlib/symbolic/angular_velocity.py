"""From angle rates to angular velocity: the Jacobian and its determinant."""

from __future__ import annotations

from collections.abc import Sequence as SequenceABC
from typing import Any

import sympy as sp

from eulerlib.symbolic.elementary import _basis, elementary_matrix
from eulerlib.symbolic.euler import _angles


def angular_velocity_jacobian(
    seq: str, angles: SequenceABC[Any] | None = None, frame: str = "body"
) -> Any:
    """The matrix that turns angle rates into angular velocity.

    If the angles change at rates ``(α̇, β̇, γ̇)`` (in the order of ``seq``), the rotation
    ``R(t) = euler_matrix(seq, angles(t))`` turns with angular velocity ``ω = J (α̇, β̇, γ̇)``,
    that is ``Ṙ Rᵀ = [ω]×`` in the fixed (space) frame, or ``Rᵀ Ṙ = [ω]×`` in the body frame.

    Parameters
    ----------
    seq : str
        One of the 24 axis sequences.
    angles : sequence of 3 sympy expressions, optional
        Default :func:`euler_symbols`.
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
        If ``seq``, ``angles`` or ``frame`` are invalid.

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
    >>> angular_velocity_jacobian("ZYX", (w, v, u))    # body rates (p, q, r) of an aircraft
    Matrix([
    [       -sin(v),       0, 1],
    [sin(u)*cos(v),  cos(u), 0],
    [cos(u)*cos(v), -sin(u), 0]])
    """
    parsed, values = _angles(seq, angles)
    if frame not in ("body", "space"):
        raise ValueError(f"frame must be 'body' or 'space', got {frame!r}")
    axes = parsed.intrinsic_axes
    intrinsic_values = values if parsed.intrinsic else values[::-1]
    A, B, C = (
        elementary_matrix(axis, angle) for axis, angle in zip(axes, intrinsic_values, strict=True)
    )
    e = [_basis(axis) for axis in axes]
    if frame == "space":
        columns = [e[0], A * e[1], A * B * e[2]]
    else:
        columns = [C.T * B.T * e[0], C.T * e[1], e[2]]
    if not parsed.intrinsic:
        columns.reverse()
    return sp.Matrix.hstack(*columns).applyfunc(sp.expand)


def jacobian_determinant(
    seq: str, angles: SequenceABC[Any] | None = None, frame: str = "body"
) -> Any:
    """Determinant of :func:`angular_velocity_jacobian`, simplified.

    Parameters
    ----------
    seq : str
        One of the 24 axis sequences.
    angles : sequence of 3 sympy expressions, optional
        Default :func:`euler_symbols`.
    frame : {'body', 'space'}, optional
        Either frame gives the same determinant, since the two Jacobians differ by a rotation.

    Returns
    -------
    sympy expression
        ``±cos(middle)`` for a Tait–Bryan sequence, ``±sin(middle)`` for a proper Euler one:
        zero exactly at gimbal lock, where the three rates can no longer produce every angular
        velocity.

    Examples
    --------
    >>> import sympy as sp
    >>> w, v, u = sp.symbols("w v u", real=True)
    >>> jacobian_determinant("ZYX", (w, v, u))
    -cos(v)
    >>> jacobian_determinant("ZXZ")
    -sin(beta)
    """
    J = angular_velocity_jacobian(seq, angles, frame)
    return sp.factor(sp.trigsimp(sp.expand(J.det())))
