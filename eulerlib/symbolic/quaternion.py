"""Quaternions: the product, the sandwich ``q v q*``, and the rotation matrix it defines.

A quaternion ``q = w + x i + y j + z k`` is a scalar part ``w`` and a vector part
``(x, y, z)``. **Here a quaternion is always written scalar first, ``(w, x, y, z)``** (the
:class:`Quaternion` tuple names its parts), as Hamilton wrote it and as SciPy does with
``scalar_first=True``. The numeric library follows SciPy's default instead, scalar last
``(x, y, z, w)``; NumPy arrays are therefore refused here, so that one order is never read as
the other.

Hamilton's rules ``i² = j² = k² = ijk = −1`` give ``ij = k = −ji``, ``jk = i = −kj``,
``ki = j = −ik``: for two pure (vector) quaternions, ``u v = −u·v + u × v``. Multiplying out
``(p_w + p_v)(q_w + q_v)`` term by term then gives the product (:func:`quaternion_product`):

.. math:: p q = (p_w q_w - p_v \\cdot q_v,\\; p_w q_v + q_w p_v + p_v \\times q_v).

The conjugate ``q* = (w, −x, −y, −z)`` (:func:`quaternion_conjugate`) reverses products,
``(p q)* = q* p*``, and ``q q* = |q|²``. For a unit ``q`` the **sandwich** ``v ↦ q v q*``
maps pure quaternions to pure quaternions, keeps lengths, and fixes the vector part of ``q``:
it is a rotation. :func:`quaternion_to_matrix` derives its matrix from the sandwich itself,
column ``j`` being the image of ``e_j``. With ``q = (cos(θ/2), sin(θ/2) k)``
(:func:`quaternion_from_axis_angle`) the rotation is the turn by θ about ``k``, so ``q`` and
``−q`` (the turn by θ + 2π) give the same matrix, and the product of quaternions is the
product of their rotations: ``(p q) v (p q)* = p (q v q*) p*``.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np
import sympy as sp
from sympy.algebras.quaternion import Quaternion as SympyQuaternion

from eulerlib.symbolic._arguments import as_axis_angle, as_expressions
from eulerlib.symbolic.axis_angle import basis_vector

__all__ = [
    "Quaternion",
    "quaternion_conjugate",
    "quaternion_from_axis_angle",
    "quaternion_product",
    "quaternion_to_matrix",
]


class Quaternion(NamedTuple):
    """A quaternion as four SymPy expressions, **scalar first**: ``w + x i + y j + z k``.

    Every quaternion function of :mod:`eulerlib.symbolic` returns one; as an argument it also
    takes any four expressions in the order ``(w, x, y, z)``, or a SymPy
    ``sympy.algebras.quaternion.Quaternion``.

    Attributes
    ----------
    w : sympy expression
        The scalar part.
    x, y, z : sympy expression
        The vector part.

    Examples
    --------
    >>> import sympy as sp
    >>> q = Quaternion(sp.cos(sp.pi / 4), 0, 0, sp.sin(sp.pi / 4))
    >>> q.w, q.z
    (sqrt(2)/2, sqrt(2)/2)
    """

    w: Any
    x: Any
    y: Any
    z: Any


def as_quaternion(value: object, name: str) -> Quaternion:
    """``value`` as a :class:`Quaternion` of four checked expressions, scalar first."""
    if isinstance(value, SympyQuaternion):
        value = (value.a, value.b, value.c, value.d)
    elif isinstance(value, np.ndarray):
        raise TypeError(
            f"{name} must be a Quaternion(w, x, y, z) or four SymPy expressions, scalar first; "
            "got a NumPy array, refused because eulerlib's numeric quaternions are scalar last "
            "(x, y, z, w) by default: write Quaternion(q[3], q[0], q[1], q[2]) for one of those"
        )
    w, x, y, z = as_expressions(value, name, 4, "parts (w, x, y, z), scalar first")
    return Quaternion(w, x, y, z)


def _scalar_vector(q: Quaternion) -> tuple[Any, Any]:
    return q.w, sp.Matrix([q.x, q.y, q.z])


def _product(p: Quaternion, q: Quaternion) -> Quaternion:
    """Hamilton product of two checked quaternions, each part expanded."""
    pw, pv = _scalar_vector(p)
    qw, qv = _scalar_vector(q)
    # (pw + pv)(qw + qv) = pw qw + pw qv + qw pv + pv qv, and pv qv = -pv·qv + pv × qv
    scalar = pw * qw - pv.dot(qv)
    vector = pw * qv + qw * pv + pv.cross(qv)
    return Quaternion(*(sp.expand(part) for part in (scalar, *vector)))


def _conjugate(q: Quaternion) -> Quaternion:
    return Quaternion(q.w, -q.x, -q.y, -q.z)


def quaternion_product(p: Any, q: Any) -> Quaternion:
    """The Hamilton product ``p q`` of two quaternions, scalar first.

    Parameters
    ----------
    p, q : Quaternion or sequence of 4 SymPy expressions or numbers
        ``(w, x, y, z)``, **scalar first**; a SymPy ``Quaternion`` is accepted too. NumPy
        arrays are refused (the numeric library's quaternions are scalar last).

    Returns
    -------
    Quaternion
        ``(p_w q_w − p_v·q_v, p_w q_v + q_w p_v + p_v × q_v)``, each part expanded. Not
        commutative: ``p q`` and ``q p`` differ in the sign of ``p_v × q_v``.

    Raises
    ------
    TypeError, ValueError
        If ``p`` or ``q`` is not four expressions or numbers.

    Notes
    -----
    Derived from Hamilton's rules ``i² = j² = k² = ijk = −1`` (W. R. Hamilton, 1843), which
    give ``u v = −u·v + u × v`` for pure quaternions ``u`` and ``v``; see the module docstring.
    If ``p`` and ``q`` are the quaternions of rotations ``P`` and ``Q``, ``p q`` is the quaternion
    of ``P Q`` (first ``Q``, then ``P``), as with matrices.

    Examples
    --------
    >>> quaternion_product((0, 1, 0, 0), (0, 0, 1, 0))   # i j = k
    Quaternion(w=0, x=0, y=0, z=1)
    >>> quaternion_product((0, 0, 1, 0), (0, 1, 0, 0))   # j i = -k
    Quaternion(w=0, x=0, y=0, z=-1)
    """
    return _product(as_quaternion(p, "p"), as_quaternion(q, "q"))


def quaternion_conjugate(q: Any) -> Quaternion:
    """The conjugate ``q* = (w, −x, −y, −z)``.

    Parameters
    ----------
    q : Quaternion or sequence of 4 SymPy expressions or numbers
        ``(w, x, y, z)``, **scalar first**.

    Returns
    -------
    Quaternion
        ``q`` with its vector part negated. For a unit quaternion it is the inverse, the
        quaternion of the inverse rotation.

    Raises
    ------
    TypeError, ValueError
        If ``q`` is not four expressions or numbers.

    Examples
    --------
    >>> import sympy as sp
    >>> w, x, y, z = sp.symbols("w x y z", real=True)
    >>> quaternion_conjugate((w, x, y, z))
    Quaternion(w=w, x=-x, y=-y, z=-z)
    >>> quaternion_product((w, x, y, z), quaternion_conjugate((w, x, y, z)))   # |q|²
    Quaternion(w=w**2 + x**2 + y**2 + z**2, x=0, y=0, z=0)
    """
    return _conjugate(as_quaternion(q, "q"))


def quaternion_from_axis_angle(axis: Any, angle: Any) -> Quaternion:
    """The unit quaternion of the rotation by ``angle`` about a unit axis: ``(cos θ/2, sin θ/2 k)``.

    Parameters
    ----------
    axis : sequence of 3 SymPy expressions or numbers
        ``(kx, ky, kz)``, a **unit** vector, taken as given (not normalized), as in
        :func:`rodrigues_matrix`.
    angle : SymPy expression or number
        The angle θ in radians (right-hand rule about ``axis``).

    Returns
    -------
    Quaternion
        ``(cos(θ/2), sin(θ/2) kx, sin(θ/2) ky, sin(θ/2) kz)``, scalar first.

    Raises
    ------
    TypeError, ValueError
        If ``axis`` or ``angle`` are not expressions or numbers.

    Notes
    -----
    For a unit pure quaternion ``k``, ``k² = −k·k = −1``, so the exponential series of
    ``(θ/2) k`` splits into ``cos(θ/2) + sin(θ/2) k``, as ``e^{iφ} = cos φ + i sin φ``. The half
    angle is there because the sandwich ``q v q*`` applies ``q`` twice; the tests check that
    :func:`quaternion_to_matrix` of this quaternion is :func:`rodrigues_matrix` for the same
    axis and angle.

    Examples
    --------
    >>> import sympy as sp
    >>> quaternion_from_axis_angle((0, 0, 1), sp.pi / 2)   # a quarter turn about z
    Quaternion(w=sqrt(2)/2, x=0, y=0, z=sqrt(2)/2)
    """
    k, theta = as_axis_angle(axis, angle)
    half = theta / 2
    return Quaternion(sp.cos(half), *(sp.sin(half) * component for component in k))


def quaternion_to_matrix(q: Any) -> Any:
    """The rotation matrix of a unit quaternion, derived from the sandwich ``v ↦ q v q*``.

    Parameters
    ----------
    q : Quaternion or sequence of 4 SymPy expressions or numbers
        ``(w, x, y, z)``, **scalar first**, a unit quaternion (taken as given, not
        normalized); a SymPy ``Quaternion`` is accepted too. NumPy arrays are refused.

    Returns
    -------
    sympy.Matrix, shape (3, 3)
        Column ``j`` is the vector part of ``q (0, e_j) q*``, expanded. Its entries are
        quadratic in the parts of ``q`` (for example ``w² + x² − y² − z²``), which needs no
        square root and is exact for symbols; for a ``q`` that is not unit it is ``|q|²`` times
        the rotation of ``q / |q|``.

    Raises
    ------
    TypeError, ValueError
        If ``q`` is not four expressions or numbers.

    Examples
    --------
    >>> import sympy as sp
    >>> w, x, y, z = sp.symbols("w x y z", real=True)
    >>> quaternion_to_matrix((w, x, y, z))[:, 0]   # where the x axis goes
    Matrix([
    [w**2 + x**2 - y**2 - z**2],
    [            2*w*z + 2*x*y],
    [           -2*w*y + 2*x*z]])
    >>> quaternion_to_matrix(quaternion_from_axis_angle((0, 0, 1), sp.pi / 2))
    Matrix([
    [0, -1, 0],
    [1,  0, 0],
    [0,  0, 1]])
    """
    quaternion = as_quaternion(q, "q")
    conjugate = _conjugate(quaternion)
    columns = []
    for j in range(3):
        pure = Quaternion(0, *basis_vector(j))
        image = _product(_product(quaternion, pure), conjugate)
        columns.append(sp.Matrix([image.x, image.y, image.z]))
    return sp.Matrix.hstack(*columns)
