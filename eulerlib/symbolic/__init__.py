"""Rotations as SymPy expressions: the derivations behind the numeric library.

Every formula that :mod:`eulerlib` evaluates with numbers can be *derived* here with symbols,
so that a notebook can show where it comes from and a test can assert that the numbers agree
with the algebra.

The idea in six steps
---------------------
1. **A turn about an axis is known by where it sends the basis vectors.** Turning a vector
   ``v`` by θ about a unit axis ``k`` (right-hand rule: thumb along ``k``, fingers curl the way
   the turn goes) keeps the part of ``v`` along ``k`` and turns the rest in the plane
   perpendicular to ``k``:

   .. math:: R v = (k \\cdot v)\\,k + \\cos θ\\,(v - (k \\cdot v)\\,k) + \\sin θ\\,(k \\times v).

   Column ``j`` of the matrix is the image of the basis vector ``e_j``.
   :func:`rodrigues_matrix` builds the matrix column by column in exactly this way, and
   :func:`elementary_matrix` gives ``R_x``, ``R_y`` and ``R_z`` as the same construction about
   a coordinate axis, instead of typing the three matrices in. Written with the cross-product
   matrix ``[k]×`` (:func:`skew`) the construction becomes
   ``R = I + sin θ [k]× + (1 − cos θ)[k]×²`` (:func:`axis_angle_matrix`).
2. **A convention is a product of three elementary rotations.** For an intrinsic (uppercase)
   sequence such as ``"ZYX"`` with angles ``(α, β, γ)`` the matrix is ``R_z(α) R_y(β) R_x(γ)``:
   the product is written in the order in which the rotations about the *moving* axes happen.
   An extrinsic (lowercase) sequence turns about *fixed* axes and the product is reversed:
   ``"zyx"`` gives ``R_x(γ) R_y(β) R_z(α)``. :func:`euler_matrix` does this for all 24
   sequences, with the same ``seq`` strings (and presets) as :func:`eulerlib.euler_to_matrix`.
   With Rose's yaw ``w``, pitch ``v`` and roll ``u``, ``euler_matrix((w, v, u), "ZYX")`` is
   Rose (2015), Part 2, eq 2; with Baker's heading, attitude and bank,
   ``euler_matrix((h, a, b), "YZX")`` is the matrix of Baker's "Matrix to Euler" page.
3. **Reading the angles back.** One entry of the matrix depends on the middle angle alone
   (``±sin β`` for Tait–Bryan sequences, ``cos β`` for proper Euler sequences); two entries in
   its row and two in its column are a common factor times the sine and cosine of the first or
   of the third angle. :func:`extraction_relations` finds those entries in the symbolic matrix
   and states the ``atan2`` formulas they give (Rose, eq 3; Baker's three formulas).
4. **Gimbal lock.** When the common factor (``cos β`` or ``sin β``) vanishes the first and
   third axes coincide and the matrix depends on a single combination of the outer angles
   (Rose, eq 4): :func:`gimbal_lock_matrix` writes it in that form.
5. **Angular velocity.** A rotation that changes with time has ``Ṙ Rᵀ = [ω]×``, skew-symmetric
   because ``R Rᵀ = I`` at every instant; :func:`angular_velocity_from_matrix` reads ``ω`` off
   it. For Euler angles ``ω`` is a matrix times the angle rates
   (:func:`angular_velocity_jacobian`), whose determinant (:func:`jacobian_determinant`) is the
   common factor of step 3: at lock one direction of angular velocity cannot be produced by
   any angle rates.
6. **Quaternions do not lock.** A unit quaternion ``q = (cos θ/2, sin θ/2 k)``
   (:func:`quaternion_from_axis_angle`) turns vectors by the sandwich ``v ↦ q v q*``, which
   :func:`quaternion_to_matrix` turns into the matrix of step 1; the Hamilton product
   (:func:`quaternion_product`) composes rotations as the matrix product does. Quaternions
   are written scalar first, ``(w, x, y, z)`` (:class:`Quaternion`).

Arguments
---------
Data first, then the convention, as in the numeric library: ``euler_matrix(angles, seq)``.
Every function reads its arguments once, by the rules of :mod:`eulerlib.symbolic._arguments`:
an angle or component is a SymPy expression or a real number; **text is refused, never
evaluated** (``"x y"`` is a ``TypeError`` that says to build the expression with SymPy, for
example ``sp.Symbol("t")``); an axis name is read by :func:`eulerlib.parse_axis`, a sequence or
preset by :func:`eulerlib.get_convention`. A bad argument raises a ``TypeError`` or
``ValueError`` that names it.

This package imports SymPy, so :mod:`eulerlib` does not import it; use
``from eulerlib import symbolic`` or ``import eulerlib.symbolic``. SymPy comes with the
``symbolic`` extra (``pip install "eulerlib[symbolic]"``); without it the import fails with an
``ImportError`` that says so.

Examples
--------
>>> import sympy as sp
>>> from eulerlib.symbolic import euler_matrix
>>> w, v, u = sp.symbols("w v u", real=True)   # yaw, pitch, roll
>>> R = euler_matrix((w, v, u), "ZYX")
>>> R[:, 0].T    # where the body's x axis (the nose) points
Matrix([[cos(v)*cos(w), sin(w)*cos(v), -sin(v)]])
"""

from eulerlib._extras import MissingExtraError

try:
    import sympy  # noqa: F401  (the modules of this package import it)
except ImportError as error:
    raise MissingExtraError("eulerlib.symbolic", "sympy", "symbolic") from error

from eulerlib.symbolic.angular_velocity import (
    angular_velocity_from_matrix,
    angular_velocity_jacobian,
    jacobian_determinant,
)
from eulerlib.symbolic.axis_angle import (
    axis_angle_matrix,
    elementary_matrix,
    rodrigues_matrix,
    skew,
)
from eulerlib.symbolic.euler import euler_matrix, euler_symbols
from eulerlib.symbolic.extraction import ExtractionRelations, extraction_relations
from eulerlib.symbolic.gimbal_lock import gimbal_lock_matrix
from eulerlib.symbolic.quaternion import (
    Quaternion,
    quaternion_conjugate,
    quaternion_from_axis_angle,
    quaternion_product,
    quaternion_to_matrix,
)

__all__ = [
    "ExtractionRelations",
    "Quaternion",
    "angular_velocity_from_matrix",
    "angular_velocity_jacobian",
    "axis_angle_matrix",
    "elementary_matrix",
    "euler_matrix",
    "euler_symbols",
    "extraction_relations",
    "gimbal_lock_matrix",
    "jacobian_determinant",
    "quaternion_conjugate",
    "quaternion_from_axis_angle",
    "quaternion_product",
    "quaternion_to_matrix",
    "rodrigues_matrix",
    "skew",
]
