"""Turns about an axis in SymPy: elementary matrices, Rodrigues, the cross-product matrix, ``exp``.

Oracles: the three elementary matrices typed in here, the numeric library's
``elementary_rotation``, SciPy's ``Rotation.from_euler`` and ``from_rotvec``, and identities
decided exactly modulo ``sin² + cos² = 1`` and ``|k| = 1`` (``symbolic_oracles.holds``).
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from scipy.spatial.transform import Rotation
from symbolic_oracles import holds, numeric

import eulerlib
from eulerlib.symbolic import axis_angle_matrix, elementary_matrix, rodrigues_matrix, skew

T = sp.Symbol("t", real=True)
K = sp.symbols("k_x k_y k_z", real=True)
PHI, LAM = sp.symbols("phi lambda", real=True)
SPHERICAL = (sp.sin(PHI) * sp.cos(LAM), sp.sin(PHI) * sp.sin(LAM), sp.cos(PHI))  # a unit axis


def typed_in(axis: int, t: sp.Expr) -> sp.Matrix:
    c, s = sp.cos(t), sp.sin(t)
    return [
        sp.Matrix([[1, 0, 0], [0, c, -s], [0, s, c]]),
        sp.Matrix([[c, 0, s], [0, 1, 0], [-s, 0, c]]),
        sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]]),
    ][axis]


def unit_axes_and_angles(rng: np.random.Generator, size: int) -> tuple[np.ndarray, np.ndarray]:
    """Random unit axes, and angles that include the hard places: near 0, near and at π, large."""
    axes = rng.normal(size=(size, 3))
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    angles = rng.uniform(-np.pi, np.pi, size)
    angles[:6] = [0.0, 1e-9, np.pi, np.pi - 1e-9, -np.pi + 1e-7, 40.0]
    return axes, angles


# --- elementary rotations ---------------------------------------------------------------------


def test_elementary_matrices_typed_in() -> None:
    for axis in range(3):
        assert elementary_matrix(axis, T) == typed_in(axis, T)


@pytest.mark.parametrize("axis", ["x", "y", "z"])
def test_elementary_orthogonal_with_unit_determinant(axis: str) -> None:
    R = elementary_matrix(axis, T)
    assert sp.simplify(R.T * R - sp.eye(3)) == sp.zeros(3, 3)
    assert sp.simplify(R * R.T - sp.eye(3)) == sp.zeros(3, 3)
    assert sp.simplify(R.det()) == 1


@pytest.mark.parametrize(
    ("axis", "function"), [(0, eulerlib.rot_x), (1, eulerlib.rot_y), (2, eulerlib.rot_z)]
)
def test_elementary_matches_numeric_and_scipy(
    axis: int, function, rng: np.random.Generator
) -> None:
    letter = "xyz"[axis]
    for spelling in (axis, letter, letter.upper(), np.int64(axis)):
        f = numeric(elementary_matrix(spelling, T), (T,))
        for angle in rng.uniform(-4, 4, 5):
            assert np.allclose(f(angle), function(angle), atol=1e-14)
            assert np.allclose(f(angle), Rotation.from_euler(letter, angle).as_matrix(), atol=1e-14)


def test_elementary_exact_quarter_turns() -> None:
    # x turns into y, y into z, z into x under the three quarter turns
    assert elementary_matrix("z", sp.pi / 2) * sp.Matrix([1, 0, 0]) == sp.Matrix([0, 1, 0])
    assert elementary_matrix("x", sp.pi / 2) * sp.Matrix([0, 1, 0]) == sp.Matrix([0, 0, 1])
    assert elementary_matrix("y", sp.pi / 2) * sp.Matrix([0, 0, 1]) == sp.Matrix([1, 0, 0])


# --- Rodrigues' construction ------------------------------------------------------------------


@pytest.mark.parametrize("axis", [0, 1, 2])
def test_rodrigues_about_a_coordinate_axis_is_the_elementary_rotation(axis: int) -> None:
    e = [1 if i == axis else 0 for i in range(3)]
    assert rodrigues_matrix(e, T) == elementary_matrix(axis, T) == typed_in(axis, T)
    # the opposite axis turns the other way
    minus_e = [-component for component in e]
    assert sp.expand(rodrigues_matrix(minus_e, T) - typed_in(axis, -T)) == sp.zeros(3, 3)


def test_rodrigues_matches_scipy_from_rotvec(rng: np.random.Generator) -> None:
    f = numeric(rodrigues_matrix(K, T), (*K, T))
    axes, angles = unit_axes_and_angles(rng, 40)
    for k, theta in zip(axes, angles, strict=True):
        expected = Rotation.from_rotvec(theta * k).as_matrix()
        assert np.allclose(f(*k, theta), expected, atol=5e-15)
    # numbers in, numbers out
    k, theta = axes[10], angles[10]
    direct = np.array(rodrigues_matrix(tuple(k), theta), dtype=float)
    assert np.allclose(direct, Rotation.from_rotvec(theta * k).as_matrix(), atol=5e-15)


def test_rodrigues_exact_third_of_a_turn_about_the_diagonal() -> None:
    k = sp.Matrix([1, 1, 1]) / sp.sqrt(3)
    cyclic = sp.Matrix([[0, 0, 1], [1, 0, 0], [0, 1, 0]])
    assert sp.simplify(rodrigues_matrix(k, 2 * sp.pi / 3) - cyclic) == sp.zeros(3, 3)


def test_rodrigues_is_a_rotation_about_its_axis_for_a_unit_axis() -> None:
    R = rodrigues_matrix(K, T)
    k = sp.Matrix(K)
    assert holds(R.T * R - sp.eye(3), angles=[T], units=[K])
    assert holds(R.det() - 1, angles=[T], units=[K])
    assert holds(R * k - k, angles=[T], units=[K])  # the axis stays
    # a spherical axis is unit by sin² + cos² = 1 alone
    R_spherical = rodrigues_matrix(SPHERICAL, T)
    assert holds(R_spherical.T * R_spherical - sp.eye(3), angles=[T, PHI, LAM])


def test_rodrigues_takes_the_axis_as_given() -> None:
    # not normalized: an axis of length 2 gives a matrix that is not a rotation
    R = rodrigues_matrix((0, 0, 2), sp.pi / 2)
    assert R.T * R != sp.eye(3)
    assert not holds(rodrigues_matrix(K, T).T * rodrigues_matrix(K, T) - sp.eye(3), angles=[T])


# --- the cross-product matrix and the closed form ---------------------------------------------


def test_skew_is_the_cross_product() -> None:
    v = sp.symbols("v_x v_y v_z", real=True)
    w = sp.Matrix(sp.symbols("w_x w_y w_z", real=True))
    S = skew(v)
    assert sp.expand(S * w - sp.Matrix(v).cross(w)) == sp.zeros(3, 1)
    assert S.T == -S
    # [v]×² = v vᵀ − |v|² I, the fact the closed form rests on
    square = sp.Matrix(v) * sp.Matrix(v).T - sp.Matrix(v).dot(sp.Matrix(v)) * sp.eye(3)
    assert sp.expand(S * S - square) == sp.zeros(3, 3)
    assert skew(sp.Matrix([1, 2, 3])) == skew([1, 2, 3]) == skew(np.array([1, 2, 3]))


def test_closed_form_equals_rodrigues_for_a_unit_axis() -> None:
    difference = axis_angle_matrix(K, T) - rodrigues_matrix(K, T)
    assert holds(difference, angles=[T], units=[K])
    # for an axis that is not unit the two differ by (1 − cos θ)(1 − |k|²) I, as documented
    norm2 = sum(k**2 for k in K)
    assert sp.expand(difference - (1 - sp.cos(T)) * (1 - norm2) * sp.eye(3)) == sp.zeros(3, 3)
    spherical = axis_angle_matrix(SPHERICAL, T) - rodrigues_matrix(SPHERICAL, T)
    assert holds(spherical, angles=[PHI, LAM])


def test_closed_form_matches_scipy(rng: np.random.Generator) -> None:
    f = numeric(axis_angle_matrix(K, T), (*K, T))
    axes, angles = unit_axes_and_angles(rng, 40)
    for k, theta in zip(axes, angles, strict=True):
        assert np.allclose(f(*k, theta), Rotation.from_rotvec(theta * k).as_matrix(), atol=5e-15)
