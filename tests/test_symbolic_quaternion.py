"""Quaternions in SymPy: Hamilton's product, the conjugate, axis–angle and the sandwich matrix.

Oracles: Hamilton's rules for i, j, k typed in here, SymPy's own ``Quaternion`` class (product
and rotation matrix), SciPy's ``Rotation.from_quat`` and ``as_quat`` (scalar last, reordered) and
``from_rotvec``, and identities decided exactly modulo ``sin² + cos² = 1`` and ``|k| = 1``.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from scipy.spatial.transform import Rotation
from symbolic_oracles import holds, numeric
from sympy.algebras.quaternion import Quaternion as SympyQuaternion

from eulerlib.symbolic import (
    Quaternion,
    quaternion_conjugate,
    quaternion_from_axis_angle,
    quaternion_product,
    quaternion_to_matrix,
    rodrigues_matrix,
)

P = sp.symbols("p_w p_x p_y p_z", real=True)
Q = sp.symbols("q_w q_x q_y q_z", real=True)
K = sp.symbols("k_x k_y k_z", real=True)
T, HALF = sp.symbols("theta h", real=True)

ONE, UNIT_I, UNIT_J, UNIT_K = (tuple(1 if i == n else 0 for i in range(4)) for n in range(4))


def negative(q: tuple) -> tuple:
    return tuple(-part for part in q)


def scalar_last(q: np.ndarray) -> np.ndarray:
    """(w, x, y, z) → (x, y, z, w), SciPy's order (its scalar_first keyword needs SciPy 1.14)."""
    return np.roll(q, -1, axis=-1)


def scalar_first(q: np.ndarray) -> np.ndarray:
    """(x, y, z, w) → (w, x, y, z)."""
    return np.roll(q, 1, axis=-1)


def random_unit_quaternions(rng: np.random.Generator, size: int) -> np.ndarray:
    """Scalar-first unit quaternions, with the hard places: tiny, zero and negative scalar part."""
    q = rng.normal(size=(size, 4))
    q[0, 0] = 0.0
    q[1, 0] = 1e-12
    q[2, 0] = -0.5
    return q / np.linalg.norm(q, axis=1, keepdims=True)


# --- the product ------------------------------------------------------------------------------


def test_hamilton_rules() -> None:
    assert quaternion_product(UNIT_I, UNIT_I) == quaternion_product(UNIT_J, UNIT_J) == negative(ONE)
    assert quaternion_product(UNIT_K, UNIT_K) == negative(ONE)
    assert quaternion_product(UNIT_I, UNIT_J) == UNIT_K and quaternion_product(
        UNIT_J, UNIT_I
    ) == negative(UNIT_K)
    assert quaternion_product(UNIT_J, UNIT_K) == UNIT_I and quaternion_product(
        UNIT_K, UNIT_J
    ) == negative(UNIT_I)
    assert quaternion_product(UNIT_K, UNIT_I) == UNIT_J and quaternion_product(
        UNIT_I, UNIT_K
    ) == negative(UNIT_J)
    assert quaternion_product(quaternion_product(UNIT_I, UNIT_J), UNIT_K) == negative(
        ONE
    )  # ijk = −1


def test_product_equals_sympys_quaternion_product() -> None:
    ours = quaternion_product(P, Q)
    theirs = SympyQuaternion(*P) * SympyQuaternion(*Q)
    expected = (theirs.a, theirs.b, theirs.c, theirs.d)
    assert all(sp.expand(a - b) == 0 for a, b in zip(ours, expected, strict=True))
    # a SymPy Quaternion is accepted as an argument, and the result names its parts
    assert quaternion_product(SympyQuaternion(*P), Q) == ours
    assert isinstance(ours, Quaternion) and ours.w == sp.expand(theirs.a)


def test_product_is_associative_and_not_commutative() -> None:
    R = sp.symbols("r_w r_x r_y r_z", real=True)
    left = quaternion_product(quaternion_product(P, Q), R)
    right = quaternion_product(P, quaternion_product(Q, R))
    assert all(sp.expand(a - b) == 0 for a, b in zip(left, right, strict=True))
    assert quaternion_product(P, Q) != quaternion_product(Q, P)


def test_conjugate_reverses_products_and_gives_the_norm() -> None:
    left = quaternion_conjugate(quaternion_product(P, Q))
    right = quaternion_product(quaternion_conjugate(Q), quaternion_conjugate(P))
    assert all(sp.expand(a - b) == 0 for a, b in zip(left, right, strict=True))
    norm2 = sum(part**2 for part in P)
    assert quaternion_product(P, quaternion_conjugate(P)) == (norm2, 0, 0, 0)


# --- the matrix of the sandwich ---------------------------------------------------------------


def test_matrix_equals_sympys_rotation_matrix() -> None:
    # SymPy divides by |q|²; the sandwich without normalizing is |q|² times that
    ours = quaternion_to_matrix(Q)
    theirs = SympyQuaternion(*Q).to_rotation_matrix()
    norm2 = sum(part**2 for part in Q)
    assert (norm2 * theirs - ours).applyfunc(sp.cancel) == sp.zeros(3, 3)


def test_matrix_matches_scipy(rng: np.random.Generator) -> None:
    f = numeric(quaternion_to_matrix(Q), Q)
    for q in random_unit_quaternions(rng, 30):
        expected = Rotation.from_quat(scalar_last(q)).as_matrix()
        assert np.allclose(f(*q), expected, atol=5e-15)


def test_matrix_is_a_rotation_for_a_unit_quaternion() -> None:
    R = quaternion_to_matrix(Q)
    assert holds(R.T * R - sp.eye(3), units=[Q])
    assert holds(R.det() - 1, units=[Q])


def test_q_and_minus_q_give_the_same_matrix() -> None:
    assert quaternion_to_matrix(negative(Q)) == quaternion_to_matrix(Q)


def test_product_of_quaternions_is_product_of_matrices() -> None:
    # exact for any p, q: both sides are |p|²|q|² times the rotation
    composed = quaternion_to_matrix(quaternion_product(P, Q))
    product = quaternion_to_matrix(P) * quaternion_to_matrix(Q)
    assert sp.expand(composed - product) == sp.zeros(3, 3)


# --- from an axis and an angle ----------------------------------------------------------------


def test_axis_angle_quaternion_gives_the_rodrigues_matrix() -> None:
    # with θ = 2h both sides are polynomials in sin h, cos h and the axis
    q = quaternion_from_axis_angle(K, 2 * HALF)
    difference = quaternion_to_matrix(q) - rodrigues_matrix(K, 2 * HALF)
    assert holds(difference.applyfunc(sp.expand_trig), angles=[HALF], units=[K])
    assert quaternion_from_axis_angle(K, T) == Quaternion(
        sp.cos(T / 2), *(sp.sin(T / 2) * k for k in K)
    )


def test_axis_angle_quaternion_matches_scipy(rng: np.random.Generator) -> None:
    axes = rng.normal(size=(20, 3))
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    angles = rng.uniform(-np.pi + 1e-6, np.pi - 1e-6, 20)  # scalar part cos(θ/2) > 0
    f = numeric(sp.Matrix(quaternion_from_axis_angle(K, T)), (*K, T))
    for k, theta in zip(axes, angles, strict=True):
        expected = scalar_first(Rotation.from_rotvec(theta * k).as_quat(canonical=True))
        assert np.allclose(f(*k, theta).ravel(), expected, atol=5e-16)


def test_exact_quarter_turn() -> None:
    q = quaternion_from_axis_angle((0, 0, 1), sp.pi / 2)
    assert q == Quaternion(sp.sqrt(2) / 2, 0, 0, sp.sqrt(2) / 2)
    assert quaternion_to_matrix(q) == sp.Matrix([[0, -1, 0], [1, 0, 0], [0, 0, 1]])


# --- arguments --------------------------------------------------------------------------------


def test_numpy_arrays_are_refused_because_of_the_order() -> None:
    q = Rotation.from_euler("z", 0.3).as_quat()  # scalar last, as NumPy arrays usually are
    with pytest.raises(TypeError, match=r"^q must be .*scalar first.*scalar last"):
        quaternion_to_matrix(q)
    with pytest.raises(TypeError, match=r"^p must be"):
        quaternion_product(q, Q)
    explicit = Quaternion(q[3], q[0], q[1], q[2])
    expected = Rotation.from_quat(q).as_matrix()
    assert np.allclose(np.array(quaternion_to_matrix(explicit), dtype=float), expected)
