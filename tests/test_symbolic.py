"""Tests of eulerlib.symbolic against the numeric library, SciPy and the papers' equations.

The symbolic matrices are evaluated at random angles and compared with
:func:`eulerlib.euler_to_matrix` and SciPy's ``Rotation``; Rose's eq 2 and Baker's matrix are
typed in here term by term; the lock forms, extraction relations and the Jacobian are checked
with numbers (finite differences for the Jacobian).
"""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
import sympy as sp
from scipy.spatial.transform import Rotation

import eulerlib
from eulerlib.symbolic import (
    ExtractionRelations,
    angular_velocity_jacobian,
    elementary_matrix,
    euler_matrix,
    euler_symbols,
    extraction_relations,
    gimbal_lock_matrix,
    jacobian_determinant,
)

ALPHA, BETA, GAMMA = euler_symbols("ZYX")
W, V, U = sp.symbols("w v u", real=True)  # Rose: yaw, pitch, roll
H, A, B = sp.symbols("h a b", real=True)  # Baker: heading, attitude, bank
R_SYMBOL = sp.MatrixSymbol("R", 3, 3)


def evaluate(matrix: sp.Matrix, symbols: tuple[sp.Symbol, ...], values: np.ndarray) -> np.ndarray:
    """A symbolic matrix evaluated at one point, as a float array."""
    return np.array(matrix.subs(dict(zip(symbols, values, strict=True))).evalf(), dtype=float)


def numeric(matrix: sp.Matrix, symbols: tuple[sp.Symbol, ...] = (ALPHA, BETA, GAMMA)):
    """A fast numeric version of a symbolic matrix: ``f(*values) -> ndarray (3, 3)``."""
    function = sp.lambdify(symbols, matrix, "numpy")
    return lambda *values: np.asarray(function(*values), dtype=float)


def middle_range(seq: str, rng: np.random.Generator, size: int) -> np.ndarray:
    """Random angles with the middle one inside the range eulerlib returns, away from lock."""
    angles = rng.uniform(-np.pi, np.pi, (size, 3))
    if seq.upper() in eulerlib.PROPER_EULER:
        angles[:, 1] = rng.uniform(0.05, np.pi - 0.05, size)
    else:
        angles[:, 1] = rng.uniform(-np.pi / 2 + 0.05, np.pi / 2 - 0.05, size)
    return angles


# --- elementary rotations ---------------------------------------------------------------------


def test_elementary_matrices_typed_in() -> None:
    t = sp.Symbol("t", real=True)
    c, s = sp.cos(t), sp.sin(t)
    assert elementary_matrix("x", t) == sp.Matrix([[1, 0, 0], [0, c, -s], [0, s, c]])
    assert elementary_matrix("y", t) == sp.Matrix([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    assert elementary_matrix("z", t) == sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])


@pytest.mark.parametrize("axis", ["x", "y", "z"])
def test_elementary_orthogonal_with_unit_determinant(axis: str) -> None:
    t = sp.Symbol("t", real=True)
    R = elementary_matrix(axis, t)
    assert sp.simplify(R.T * R - sp.eye(3)) == sp.zeros(3, 3)
    assert sp.simplify(R * R.T - sp.eye(3)) == sp.zeros(3, 3)
    assert sp.simplify(R.det()) == 1


@pytest.mark.parametrize(
    ("axis", "function"), [(0, eulerlib.rot_x), (1, eulerlib.rot_y), (2, eulerlib.rot_z)]
)
def test_elementary_matches_numeric_and_scipy(
    axis: int, function, rng: np.random.Generator
) -> None:
    t = sp.Symbol("t", real=True)
    letter = "xyz"[axis]
    for spelling in (axis, letter, letter.upper()):
        f = numeric(elementary_matrix(spelling, t), (t,))
        for angle in rng.uniform(-4, 4, 5):
            assert np.allclose(f(angle), function(angle), atol=1e-14)
            assert np.allclose(f(angle), Rotation.from_euler(letter, angle).as_matrix(), atol=1e-14)


def test_elementary_exact_quarter_turns() -> None:
    # x turns into y, y into z, z into x under the three quarter turns
    assert elementary_matrix("z", sp.pi / 2) * sp.Matrix([1, 0, 0]) == sp.Matrix([0, 1, 0])
    assert elementary_matrix("x", sp.pi / 2) * sp.Matrix([0, 1, 0]) == sp.Matrix([0, 0, 1])
    assert elementary_matrix("y", sp.pi / 2) * sp.Matrix([0, 0, 1]) == sp.Matrix([1, 0, 0])


@pytest.mark.parametrize("axis", ["w", 3, -1, "xy", None, True, 1.0, [0]])
def test_elementary_rejects_bad_axis(axis: object) -> None:
    with pytest.raises(ValueError, match="axis must be"):
        elementary_matrix(axis, 0.1)  # type: ignore[arg-type]


# --- all 24 conventions -----------------------------------------------------------------------


@pytest.mark.parametrize("seq", eulerlib.ALL_SEQUENCES)
def test_euler_matrix_matches_numeric_and_scipy(seq: str, rng: np.random.Generator) -> None:
    f = numeric(euler_matrix(seq))
    for angles in rng.uniform(-np.pi, np.pi, (6, 3)):
        R = f(*angles)
        assert np.allclose(R, eulerlib.euler_to_matrix(angles, seq), atol=1e-13)
        assert np.allclose(R, Rotation.from_euler(seq, angles).as_matrix(), atol=1e-13)


@pytest.mark.parametrize("seq", eulerlib.TAIT_BRYAN + eulerlib.PROPER_EULER)
def test_intrinsic_equals_reversed_extrinsic(seq: str) -> None:
    assert euler_matrix(seq) == euler_matrix(seq.lower()[::-1], (GAMMA, BETA, ALPHA))


def test_rose_equation_2_typed_in() -> None:
    c, s = sp.cos, sp.sin
    rose = sp.Matrix(
        [
            [c(V) * c(W), s(U) * s(V) * c(W) - c(U) * s(W), s(U) * s(W) + c(U) * s(V) * c(W)],
            [c(V) * s(W), c(U) * c(W) + s(U) * s(V) * s(W), c(U) * s(V) * s(W) - s(U) * c(W)],
            [-s(V), s(U) * c(V), c(U) * c(V)],
        ]
    )
    assert sp.expand(euler_matrix("ZYX", (W, V, U)) - rose) == sp.zeros(3, 3)


def test_baker_matrix_typed_in() -> None:
    ch, sh, ca, sa, cb, sb = sp.cos(H), sp.sin(H), sp.cos(A), sp.sin(A), sp.cos(B), sp.sin(B)
    baker = sp.Matrix(
        [
            [ch * ca, -ch * sa * cb + sh * sb, ch * sa * sb + sh * cb],
            [sa, ca * cb, -ca * sb],
            [-sh * ca, sh * sa * cb + ch * sb, -sh * sa * sb + ch * cb],
        ]
    )
    assert sp.expand(euler_matrix("YZX", (H, A, B)) - baker) == sp.zeros(3, 3)


def test_euler_matrix_exact_values_and_default_symbols() -> None:
    assert euler_matrix("ZYX", (sp.pi / 2, 0, 0)) == sp.Matrix([[0, -1, 0], [1, 0, 0], [0, 0, 1]])
    assert euler_matrix("ZYX").free_symbols == {ALPHA, BETA, GAMMA}
    assert euler_symbols("zxz") == (ALPHA, BETA, GAMMA)
    assert all(symbol.is_real for symbol in euler_symbols("XYZ"))


@pytest.mark.parametrize(
    ("seq", "angles", "error", "match"),
    [
        ("ZZX", None, ValueError, "invalid axis sequence"),
        ("ZyX", None, ValueError, "mixes uppercase"),
        (123, None, TypeError, "seq must be a string"),
        ("ZYX", (W, V), ValueError, "exactly 3 angles"),
        ("ZYX", (W, V, U, W), ValueError, "exactly 3 angles"),
        ("ZYX", "wvu", TypeError, "angles must be a sequence"),
        ("ZYX", 0.5, TypeError, "angles must be a sequence"),
    ],
)
def test_euler_matrix_rejects_bad_input(seq, angles, error, match) -> None:
    with pytest.raises(error, match=match):
        euler_matrix(seq, angles)


# --- extraction relations ---------------------------------------------------------------------


@pytest.mark.parametrize("seq", eulerlib.ALL_SEQUENCES)
def test_extraction_relations_numerically(seq: str, rng: np.random.Generator) -> None:
    rel = extraction_relations(seq)
    assert isinstance(rel, ExtractionRelations)
    formulas = [sp.lambdify(R_SYMBOL, formula, "numpy") for formula in rel.formulas]
    values = {
        name: sp.lambdify((ALPHA, BETA, GAMMA), expr, "numpy")
        for name, expr in [
            ("middle", rel.middle_value),
            ("scale", rel.scale),
            ("first_sin", rel.first_values[0]),
            ("first_cos", rel.first_values[1]),
            ("third_sin", rel.third_values[0]),
            ("third_cos", rel.third_values[1]),
        ]
    }
    for angles in middle_range(seq, rng, 6):
        R = eulerlib.euler_to_matrix(angles, seq)
        # the formulas give the angles back, as the numeric library does
        recovered = np.array([formula(R) for formula in formulas])
        assert np.allclose(recovered, angles, atol=1e-10)
        assert np.allclose(recovered, eulerlib.matrix_to_euler(R, seq), atol=1e-10)
        # the named entries hold what the relations say they hold
        a, b, c = angles
        assert np.isclose(R[rel.middle_entry], values["middle"](a, b, c))
        scale = values["scale"](a, b, c)
        assert scale > 0
        for angle, entries, name in [
            (a, rel.first_entries, "first"),
            (c, rel.third_entries, "third"),
        ]:
            sine, cosine = R[entries[0]], R[entries[1]]
            assert np.isclose(sine, values[f"{name}_sin"](a, b, c))
            assert np.isclose(cosine, values[f"{name}_cos"](a, b, c))
            assert np.isclose(abs(sine), scale * abs(np.sin(angle)))
            assert np.isclose(abs(cosine), scale * abs(np.cos(angle)))


def test_extraction_relations_are_rose_equation_3() -> None:
    rel = extraction_relations("ZYX", (W, V, U))
    assert rel.middle_entry == (2, 0)  # r31 = -sin(v)
    assert rel.middle_value == -sp.sin(V)
    assert rel.first_entries == ((1, 0), (0, 0))  # yaw = atan2(r21, r11)
    assert rel.third_entries == ((2, 1), (2, 2))  # roll = atan2(r32, r33)
    assert rel.formulas[0] == sp.atan2(R_SYMBOL[1, 0], R_SYMBOL[0, 0])
    assert rel.formulas[2] == sp.atan2(R_SYMBOL[2, 1], R_SYMBOL[2, 2])


def test_extraction_relations_are_baker_formulas() -> None:
    rel = extraction_relations("YZX", (H, A, B))
    assert rel.middle_entry == (1, 0)  # m10 = sin(attitude)
    assert rel.middle_value == sp.sin(A)
    assert rel.formulas[0] == sp.atan2(-R_SYMBOL[2, 0], R_SYMBOL[0, 0])  # heading
    assert rel.formulas[2] == sp.atan2(-R_SYMBOL[1, 2], R_SYMBOL[1, 1])  # bank


def test_extraction_relations_need_distinct_symbols() -> None:
    with pytest.raises(ValueError, match="three distinct SymPy symbols"):
        extraction_relations("ZYX", (W, W, U))
    with pytest.raises(ValueError, match="three distinct SymPy symbols"):
        extraction_relations("ZYX", (W, sp.pi / 4, U))


# --- gimbal lock ------------------------------------------------------------------------------


def singular_angle(seq: str, middle: int) -> float:
    if seq.upper() in eulerlib.PROPER_EULER:
        return 0.0 if middle == 1 else np.pi
    return middle * np.pi / 2


@pytest.mark.parametrize("middle", [1, -1])
@pytest.mark.parametrize("seq", eulerlib.ALL_SEQUENCES)
def test_gimbal_lock_matrix_numerically(seq: str, middle: int, rng: np.random.Generator) -> None:
    L = gimbal_lock_matrix(seq, middle)
    assert BETA not in L.free_symbols
    f = numeric(L, (ALPHA, GAMMA))
    singular = singular_angle(seq, middle)
    outer = rng.uniform(-np.pi, np.pi, (5, 2))
    for a, c in outer:
        expected = eulerlib.euler_to_matrix([a, singular, c], seq)
        assert np.allclose(f(a, c), expected, atol=1e-13)
    # only one combination c + s·a matters: moving a by d and c by -s·d changes nothing,
    # for exactly one sign s, and the matrix is not constant
    shifts = rng.uniform(-np.pi, np.pi, 5)
    unchanged = [
        all(
            np.allclose(f(a + d, c - s * d), f(a, c), atol=1e-12)
            for (a, c), d in zip(outer, shifts, strict=True)
        )
        for s in (1, -1)
    ]
    assert sorted(unchanged) == [False, True]


def test_gimbal_lock_matrix_is_rose_equation_4() -> None:
    rng = np.random.default_rng(4)
    up, down = gimbal_lock_matrix("ZYX", 1, (W, V, U)), gimbal_lock_matrix("ZYX", -1, (W, V, U))
    for w, u in rng.uniform(-1.5, 1.5, (5, 2)):  # |u ± w| < π so no wrapping
        r_up = evaluate(up, (W, U), (w, u))
        r_down = evaluate(down, (W, U), (w, u))
        assert np.isclose(r_up[2, 0], -1.0) and np.isclose(r_down[2, 0], 1.0)
        assert np.isclose(np.arctan2(r_up[0, 1], r_up[0, 2]), u - w)  # eq 4b
        assert np.isclose(np.arctan2(-r_down[0, 1], -r_down[0, 2]), u + w)  # eq 4a


def test_gimbal_lock_matrix_is_baker_poles() -> None:
    ch_b = sp.cos(H + B)
    north = gimbal_lock_matrix("YZX", 1, (H, A, B))
    south = gimbal_lock_matrix("YZX", -1, (H, A, B))
    baker_north = sp.Matrix([[0, -ch_b, sp.sin(H + B)], [1, 0, 0], [0, sp.sin(H + B), ch_b]])
    baker_south = sp.Matrix(
        [[0, sp.cos(H - B), sp.sin(H - B)], [-1, 0, 0], [0, -sp.sin(H - B), sp.cos(H - B)]]
    )
    assert sp.expand(sp.expand_trig(north - baker_north)) == sp.zeros(3, 3)
    assert sp.expand(sp.expand_trig(south - baker_south)) == sp.zeros(3, 3)


def test_gimbal_lock_matrix_middle_spellings() -> None:
    assert gimbal_lock_matrix("ZYX", sp.pi / 2) == gimbal_lock_matrix("ZYX", 1)
    assert gimbal_lock_matrix("ZYX", -sp.pi / 2) == gimbal_lock_matrix("ZYX", -1)
    assert gimbal_lock_matrix("ZXZ", 0) == gimbal_lock_matrix("ZXZ", 1)
    assert gimbal_lock_matrix("ZXZ", sp.pi) == gimbal_lock_matrix("ZXZ", -1)
    for seq, middle in [("ZYX", 0), ("ZYX", sp.pi), ("ZXZ", sp.pi / 2), ("ZYX", 2)]:
        with pytest.raises(ValueError, match="singular middle angle"):
            gimbal_lock_matrix(seq, middle)


# --- angular velocity -------------------------------------------------------------------------


def vee(skew: np.ndarray) -> np.ndarray:
    """The vector of a skew-symmetric matrix: [ω]× ↦ ω."""
    return np.array([skew[2, 1], skew[0, 2], skew[1, 0]])


@pytest.mark.parametrize("frame", ["body", "space"])
@pytest.mark.parametrize("seq", eulerlib.ALL_SEQUENCES)
def test_jacobian_matches_finite_differences(
    seq: str, frame: str, rng: np.random.Generator
) -> None:
    J = numeric(angular_velocity_jacobian(seq, frame=frame))
    step = 1e-6
    for angles, rates in zip(rng.uniform(-3, 3, (3, 3)), rng.normal(size=(3, 3)), strict=True):
        R = eulerlib.euler_to_matrix(angles, seq)
        R_dot = (
            eulerlib.euler_to_matrix(angles + step * rates, seq)
            - eulerlib.euler_to_matrix(angles - step * rates, seq)
        ) / (2 * step)
        skew = R.T @ R_dot if frame == "body" else R_dot @ R.T
        assert np.allclose(skew, -skew.T, atol=1e-8)
        assert np.allclose(J(*angles) @ rates, vee(skew), atol=1e-8)


@pytest.mark.parametrize("seq", eulerlib.ALL_SEQUENCES)
def test_jacobian_determinant(seq: str, rng: np.random.Generator) -> None:
    det = jacobian_determinant(seq)
    assert det == jacobian_determinant(seq, frame="space")
    assert det.free_symbols <= {BETA}
    for angles in rng.uniform(-3, 3, (3, 3)):
        J = numeric(angular_velocity_jacobian(seq))(*angles)
        assert np.isclose(float(det.subs(BETA, angles[1])), np.linalg.det(J))
    proper = seq.upper() in eulerlib.PROPER_EULER
    singular = (0, sp.pi) if proper else (sp.pi / 2, -sp.pi / 2)
    for value in singular:
        assert det.subs(BETA, value) == 0
    factor = sp.sin(BETA) if proper else sp.cos(BETA)
    assert det in (factor, -factor)


def test_jacobian_rose_body_rates() -> None:
    # aircraft body rates: p = u' - w' sin v, q = v' cos u + w' sin u cos v, ...
    dw, dv, du = sp.symbols("dw dv du", real=True)
    c, s = sp.cos, sp.sin
    expected = sp.Matrix(
        [
            du - dw * s(V),
            dv * c(U) + dw * s(U) * c(V),
            -dv * s(U) + dw * c(U) * c(V),
        ]
    )
    J = angular_velocity_jacobian("ZYX", (W, V, U))
    assert sp.expand(J * sp.Matrix([dw, dv, du]) - expected) == sp.zeros(3, 1)


def test_jacobian_rejects_bad_frame() -> None:
    with pytest.raises(ValueError, match="frame must be 'body' or 'space'"):
        angular_velocity_jacobian("ZYX", frame="world")


# --- light import -----------------------------------------------------------------------------


def test_import_eulerlib_does_not_load_sympy() -> None:
    code = "import sys, eulerlib; sys.exit('sympy' in sys.modules)"
    assert subprocess.run([sys.executable, "-c", code], check=False).returncode == 0
