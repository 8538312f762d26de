"""Symbolic Euler-angle matrices, extraction relations and lock forms against independent oracles.

The symbolic matrices are evaluated at random angles and compared with
:func:`eulerlib.euler_to_matrix` and SciPy's ``Rotation``; Rose's eq 2 and Baker's matrix are
typed in here term by term; the lock forms and extraction relations are checked with numbers,
and the lock combination's sign against :func:`eulerlib.lock_combination`.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from budget import sweep
from scipy.spatial.transform import Rotation
from symbolic_oracles import numeric

import eulerlib
from eulerlib.symbolic import (
    ExtractionRelations,
    euler_matrix,
    euler_symbols,
    extraction_relations,
    gimbal_lock_matrix,
)

ALPHA, BETA, GAMMA = euler_symbols()
W, V, U = sp.symbols("w v u", real=True)  # Rose: yaw, pitch, roll
H, A, B = sp.symbols("h a b", real=True)  # Baker: heading, attitude, bank
R_SYMBOL = sp.MatrixSymbol("R", 3, 3)


def evaluate(matrix: sp.Matrix, symbols: tuple[sp.Symbol, ...], values: np.ndarray) -> np.ndarray:
    """A symbolic matrix evaluated at one point, as a float array."""
    return np.array(matrix.subs(dict(zip(symbols, values, strict=True))).evalf(), dtype=float)


def middle_range(seq: str, rng: np.random.Generator, size: int) -> np.ndarray:
    """Random angles with the middle one inside the range eulerlib returns, away from lock."""
    angles = rng.uniform(-np.pi, np.pi, (size, 3))
    if seq.upper() in eulerlib.PROPER_EULER:
        angles[:, 1] = rng.uniform(0.05, np.pi - 0.05, size)
    else:
        angles[:, 1] = rng.uniform(-np.pi / 2 + 0.05, np.pi / 2 - 0.05, size)
    return angles


# --- all 24 conventions -----------------------------------------------------------------------


@pytest.mark.parametrize("seq", sweep(eulerlib.ALL_SEQUENCES))
def test_euler_matrix_matches_numeric_and_scipy(seq: str, rng: np.random.Generator) -> None:
    f = numeric(euler_matrix((ALPHA, BETA, GAMMA), seq), (ALPHA, BETA, GAMMA))
    for angles in rng.uniform(-np.pi, np.pi, (6, 3)):
        R = f(*angles)
        assert np.allclose(R, eulerlib.euler_to_matrix(angles, seq), atol=1e-13)
        assert np.allclose(R, Rotation.from_euler(seq, angles).as_matrix(), atol=1e-13)


@pytest.mark.parametrize("seq", eulerlib.TAIT_BRYAN + eulerlib.PROPER_EULER)
def test_intrinsic_equals_reversed_extrinsic(seq: str) -> None:
    reversed_extrinsic = euler_matrix((GAMMA, BETA, ALPHA), seq.lower()[::-1])
    assert euler_matrix((ALPHA, BETA, GAMMA), seq) == reversed_extrinsic


@pytest.mark.parametrize("preset", ["rose", "baker", "ros", "Aerospace"])
def test_presets_and_conventions_are_their_sequences(preset: str) -> None:
    convention = eulerlib.get_convention(preset)
    expected = euler_matrix((W, V, U), convention.seq)
    assert euler_matrix((W, V, U), preset) == expected
    assert euler_matrix((W, V, U), convention) == expected


def test_rose_equation_2_typed_in() -> None:
    c, s = sp.cos, sp.sin
    rose = sp.Matrix(
        [
            [c(V) * c(W), s(U) * s(V) * c(W) - c(U) * s(W), s(U) * s(W) + c(U) * s(V) * c(W)],
            [c(V) * s(W), c(U) * c(W) + s(U) * s(V) * s(W), c(U) * s(V) * s(W) - s(U) * c(W)],
            [-s(V), s(U) * c(V), c(U) * c(V)],
        ]
    )
    assert sp.expand(euler_matrix((W, V, U), "ZYX") - rose) == sp.zeros(3, 3)
    assert sp.expand(euler_matrix((W, V, U)) - rose) == sp.zeros(3, 3)  # "ZYX" is the default


def test_baker_matrix_typed_in() -> None:
    ch, sh, ca, sa, cb, sb = sp.cos(H), sp.sin(H), sp.cos(A), sp.sin(A), sp.cos(B), sp.sin(B)
    baker = sp.Matrix(
        [
            [ch * ca, -ch * sa * cb + sh * sb, ch * sa * sb + sh * cb],
            [sa, ca * cb, -ca * sb],
            [-sh * ca, sh * sa * cb + ch * sb, -sh * sa * sb + ch * cb],
        ]
    )
    assert sp.expand(euler_matrix((H, A, B), "YZX") - baker) == sp.zeros(3, 3)


def test_euler_matrix_exact_values_and_default_symbols() -> None:
    assert euler_matrix((sp.pi / 2, 0, 0), "ZYX") == sp.Matrix([[0, -1, 0], [1, 0, 0], [0, 0, 1]])
    assert euler_matrix(euler_symbols()).free_symbols == {ALPHA, BETA, GAMMA}
    assert euler_symbols("zxz") == euler_symbols("baker") == (ALPHA, BETA, GAMMA)
    assert all(symbol.is_real for symbol in euler_symbols("XYZ"))


def test_euler_matrix_takes_numbers_of_every_kind() -> None:
    exact = euler_matrix((sp.Rational(1, 2), 0, sp.pi), "ZYX")
    from fractions import Fraction

    assert euler_matrix((Fraction(1, 2), np.int64(0), sp.pi), "ZYX") == exact
    floats = euler_matrix((np.float64(0.5), 0.0, np.float32(0.25)), "ZYX")
    expected = eulerlib.euler_to_matrix([0.5, 0.0, 0.25], "ZYX")
    assert np.allclose(np.array(floats, dtype=float), expected, atol=1e-7)


@pytest.mark.parametrize(
    ("angles", "seq", "error", "match"),
    [
        ((W, V, U), "ZZX", ValueError, "seq 'ZZX' is neither a preset"),
        ((W, V, U), "ZyX", ValueError, "mixes uppercase"),
        ((W, V, U), 123, TypeError, "seq must be a convention"),
        ((W, V), "ZYX", ValueError, "angles must hold exactly 3 angles, got 2"),
        ((W, V, U, W), "ZYX", ValueError, "angles must hold exactly 3 angles, got 4"),
        ("wvu", "ZYX", TypeError, "angles must be 3 angles.*not text"),
        (0.5, "ZYX", TypeError, "angles must be 3 angles.*got float"),
        ("ZYX", (W, V, U), TypeError, "the angles come first and the convention second"),
        ("rose", "ZYX", TypeError, "the angles come first and the convention second"),
    ],
)
def test_euler_matrix_rejects_bad_input(angles, seq, error, match) -> None:
    with pytest.raises(error, match=match):
        euler_matrix(angles, seq)


# --- extraction relations ---------------------------------------------------------------------


@pytest.mark.parametrize("seq", eulerlib.ALL_SEQUENCES)
def test_extraction_relations_numerically(seq: str, rng: np.random.Generator) -> None:
    rel = extraction_relations((ALPHA, BETA, GAMMA), seq)
    assert isinstance(rel, ExtractionRelations)
    assert rel.seq == seq
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
    rel = extraction_relations((W, V, U), "ZYX")
    assert rel.middle_entry == (2, 0)  # r31 = -sin(v)
    assert rel.middle_value == -sp.sin(V)
    assert rel.first_entries == ((1, 0), (0, 0))  # yaw = atan2(r21, r11)
    assert rel.third_entries == ((2, 1), (2, 2))  # roll = atan2(r32, r33)
    assert rel.formulas[0] == sp.atan2(R_SYMBOL[1, 0], R_SYMBOL[0, 0])
    assert rel.formulas[2] == sp.atan2(R_SYMBOL[2, 1], R_SYMBOL[2, 2])
    assert extraction_relations((W, V, U), "rose") == rel


def test_extraction_relations_are_baker_formulas() -> None:
    rel = extraction_relations((H, A, B), "YZX")
    assert rel.middle_entry == (1, 0)  # m10 = sin(attitude)
    assert rel.middle_value == sp.sin(A)
    assert rel.formulas[0] == sp.atan2(-R_SYMBOL[2, 0], R_SYMBOL[0, 0])  # heading
    assert rel.formulas[2] == sp.atan2(-R_SYMBOL[1, 2], R_SYMBOL[1, 1])  # bank
    assert extraction_relations((H, A, B), "baker").seq == "YZX"


def test_extraction_relations_need_distinct_symbols() -> None:
    with pytest.raises(ValueError, match="angles must be 3 distinct SymPy symbols"):
        extraction_relations((W, W, U), "ZYX")
    with pytest.raises(ValueError, match="angles must be 3 distinct SymPy symbols"):
        extraction_relations((W, sp.pi / 4, U), "ZYX")


# --- gimbal lock ------------------------------------------------------------------------------


def poles_of(seq: str) -> tuple[int, int]:
    return (0, 180) if eulerlib.get_convention(seq).parsed.proper else (90, -90)


@pytest.mark.parametrize("which", [0, 1])
@pytest.mark.parametrize("seq", [*sweep(eulerlib.ALL_SEQUENCES), "baker", "ros"])
def test_gimbal_lock_matrix_numerically(seq: str, which: int, rng: np.random.Generator) -> None:
    pole = poles_of(seq)[which]
    L = gimbal_lock_matrix((ALPHA, GAMMA), seq, pole=pole)
    assert L.free_symbols <= {ALPHA, GAMMA}
    f = numeric(L, (ALPHA, GAMMA))
    outer = rng.uniform(-np.pi, np.pi, (5, 2))
    for a, c in outer:
        expected = eulerlib.euler_to_matrix([a, np.radians(pole), c], seq)
        assert np.allclose(f(a, c), expected, atol=1e-13)
    # only one combination c + s·a matters: moving a by d and c by -s·d changes nothing,
    # for exactly one sign s, and it is the sign eulerlib.lock_combination states
    shifts = rng.uniform(-np.pi, np.pi, 5)
    unchanged = {
        s: all(
            np.allclose(f(a + d, c - s * d), f(a, c), atol=1e-12)
            for (a, c), d in zip(outer, shifts, strict=True)
        )
        for s in (1, -1)
    }
    sign, _ = eulerlib.lock_combination(seq, pole)
    assert unchanged == {sign: True, -sign: False}


@pytest.mark.parametrize("seq", ["ZYX", "rose", "baker", "xyz", "zxz", "ros"])
def test_gimbal_lock_matrix_follows_the_lock_policy(seq: str) -> None:
    # the angle the convention zeroes at lock is absent; the other carries the combination
    convention = eulerlib.get_convention(seq)
    for pole in poles_of(seq):
        L = gimbal_lock_matrix((ALPHA, GAMMA), seq, pole=pole)
        sign, _ = eulerlib.lock_combination(convention, pole)
        if convention.lock_zeroes == "first":
            values = (0, sp.pi * pole / 180, GAMMA + sign * ALPHA)
        else:
            values = (ALPHA + sign * GAMMA, sp.pi * pole / 180, 0)
        assert L == euler_matrix(values, seq)


def test_gimbal_lock_matrix_is_rose_equation_4() -> None:
    rng = np.random.default_rng(4)
    up = gimbal_lock_matrix((W, U), "ZYX", pole=90)
    down = gimbal_lock_matrix((W, U), "ZYX", pole=-90)
    for w, u in rng.uniform(-1.5, 1.5, (5, 2)):  # |u ± w| < π so no wrapping
        r_up = evaluate(up, (W, U), (w, u))
        r_down = evaluate(down, (W, U), (w, u))
        assert np.isclose(r_up[2, 0], -1.0) and np.isclose(r_down[2, 0], 1.0)
        assert np.isclose(np.arctan2(r_up[0, 1], r_up[0, 2]), u - w)  # eq 4b
        assert np.isclose(np.arctan2(-r_down[0, 1], -r_down[0, 2]), u + w)  # eq 4a


@pytest.mark.parametrize("seq", ["YZX", "baker"])
def test_gimbal_lock_matrix_is_baker_poles(seq: str) -> None:
    ch_b = sp.cos(H + B)
    north = gimbal_lock_matrix((H, B), seq, pole=90)
    south = gimbal_lock_matrix((H, B), seq, pole=-90)
    baker_north = sp.Matrix([[0, -ch_b, sp.sin(H + B)], [1, 0, 0], [0, sp.sin(H + B), ch_b]])
    baker_south = sp.Matrix(
        [[0, sp.cos(H - B), sp.sin(H - B)], [-1, 0, 0], [0, -sp.sin(H - B), sp.cos(H - B)]]
    )
    assert sp.expand(sp.expand_trig(north - baker_north)) == sp.zeros(3, 3)
    assert sp.expand(sp.expand_trig(south - baker_south)) == sp.zeros(3, 3)


def test_gimbal_lock_matrix_pole_values() -> None:
    expected = gimbal_lock_matrix((W, U), "ZYX", pole=90)
    for spelling in (90.0, np.int64(90), np.float64(90.0), sp.Integer(90), sp.Float(90)):
        assert gimbal_lock_matrix((W, U), "ZYX", pole=spelling) == expected
    bad_values = [("ZYX", 0), ("ZYX", 180), ("ZYX", 1), ("ZXZ", 90), ("ZXZ", -1), ("ZYX", 45.5)]
    bad_values += [
        ("ZYX", 10**400),
        ("ZYX", float("nan")),
        ("ZYX", sp.oo),
        ("ZYX", sp.Rational(1, 2)),
    ]
    for seq, pole in bad_values:
        with pytest.raises(ValueError, match=rf"^pole must be {poles_of(seq)[0]} or .* got"):
            gimbal_lock_matrix((W, U), seq, pole=pole)
    for pole in (True, np.bool_(False), None, "90", sp.pi / 2, [90], sp.zoo, sp.I):
        with pytest.raises(TypeError, match=r"^pole must be a number of degrees"):
            gimbal_lock_matrix((W, U), "ZYX", pole=pole)


@pytest.mark.parametrize("seq", ["ZYX", "baker", "zxz"])
def test_gimbal_lock_matrix_of_numbers(seq: str) -> None:
    # numbers hide the sum identities (sin 3 = sin(1 + 2)), so the form is found with symbols
    for pole in poles_of(seq):
        for first, third in [(1, 2), (0.25, -1.5), (sp.pi / 3, sp.pi / 7)]:
            L = np.array(gimbal_lock_matrix((first, third), seq, pole=pole), dtype=float)
            angles = [float(first), np.radians(pole), float(third)]
            assert np.allclose(L, eulerlib.euler_to_matrix(angles, seq), atol=1e-15)


def test_gimbal_lock_matrix_takes_the_two_outer_angles() -> None:
    with pytest.raises(ValueError, match=r"angles must hold exactly 2 outer angles"):
        gimbal_lock_matrix((W, V, U), "ZYX", pole=90)
    with pytest.raises(TypeError, match=r"pole"):
        gimbal_lock_matrix((W, U), "ZYX")  # type: ignore[call-arg]
