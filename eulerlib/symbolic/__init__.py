"""Rotation matrices as SymPy expressions: the derivations behind the numeric library.

Every formula that :mod:`eulerlib` evaluates with numbers can be *derived* here with symbols,
so that a notebook can show where it comes from and a test can assert that the numbers agree
with the algebra.

The idea in four steps
----------------------
1. **An elementary rotation is known by where it sends the basis vectors.** Turning a vector
   ``v`` by θ about a unit axis ``k`` (right-hand rule: thumb along ``k``, fingers curl the way
   the turn goes) keeps the part of ``v`` along ``k`` and turns the rest in the plane
   perpendicular to ``k``:

   .. math:: R v = (k \\cdot v)\\,k + \\cos θ\\,(v - (k \\cdot v)\\,k) + \\sin θ\\,(k \\times v).

   Column ``j`` of the matrix is the image of the basis vector ``e_j``.
   :func:`elementary_matrix` builds ``R_x``, ``R_y`` and ``R_z`` column by column in exactly
   this way, instead of typing the three matrices in.
2. **A convention is a product of three elementary rotations.** For an intrinsic (uppercase)
   sequence such as ``"ZYX"`` with angles ``(α, β, γ)`` the matrix is ``R_z(α) R_y(β) R_x(γ)``:
   the product is written in the order in which the rotations about the *moving* axes happen.
   An extrinsic (lowercase) sequence turns about *fixed* axes and the product is reversed:
   ``"zyx"`` gives ``R_x(γ) R_y(β) R_z(α)``. :func:`euler_matrix` does this for all 24
   sequences, with the same ``seq`` strings as :func:`eulerlib.euler_to_matrix` and SciPy's
   ``Rotation.from_euler``. With Rose's yaw ``w``, pitch ``v`` and roll ``u``,
   ``euler_matrix("ZYX", (w, v, u))`` is Rose (2015), Part 2, eq 2; with Baker's heading,
   attitude and bank, ``euler_matrix("YZX", (h, a, b))`` is the matrix of Baker's
   "Matrix to Euler" page.
3. **Reading the angles back.** One entry of the matrix depends on the middle angle alone
   (``±sin β`` for Tait–Bryan sequences, ``cos β`` for proper Euler sequences); two entries in
   its row and two in its column are a common factor times the sine and cosine of the first or
   of the third angle. :func:`extraction_relations` finds those entries in the symbolic matrix
   and states the ``atan2`` formulas they give (Rose, eq 3; Baker's three formulas).
4. **Gimbal lock.** When the common factor (``cos β`` or ``sin β``) vanishes the first and
   third axes coincide and the matrix depends on a single combination of the outer angles
   (Rose, eq 4): :func:`gimbal_lock_matrix` writes it in that form. The same factor is the
   determinant of the map from angle rates to angular velocity,
   :func:`angular_velocity_jacobian` and :func:`jacobian_determinant`: at lock one direction of
   angular velocity cannot be produced by any angle rates.

This module imports SymPy, so :mod:`eulerlib` does not import it; use
``from eulerlib import symbolic`` or ``import eulerlib.symbolic``.

Examples
--------
>>> import sympy as sp
>>> from eulerlib.symbolic import euler_matrix
>>> w, v, u = sp.symbols("w v u", real=True)   # yaw, pitch, roll
>>> R = euler_matrix("ZYX", (w, v, u))
>>> R[:, 0].T    # where the body's x axis (the nose) points
Matrix([[cos(v)*cos(w), sin(w)*cos(v), -sin(v)]])
"""

from eulerlib.symbolic.angular_velocity import angular_velocity_jacobian, jacobian_determinant
from eulerlib.symbolic.elementary import elementary_matrix
from eulerlib.symbolic.euler import euler_matrix, euler_symbols
from eulerlib.symbolic.extraction import ExtractionRelations, extraction_relations
from eulerlib.symbolic.gimbal_lock import gimbal_lock_matrix

__all__ = [
    "ExtractionRelations",
    "angular_velocity_jacobian",
    "elementary_matrix",
    "euler_matrix",
    "euler_symbols",
    "extraction_relations",
    "gimbal_lock_matrix",
    "jacobian_determinant",
]
