"""Quaternion algebra: the Hamilton product, conjugate, inverse, exponential, logarithm, power.

Oracles: Hamilton's multiplication table and the product written as a 4×4 matrix (typed in
here), SciPy's ``Rotation`` (composition, inverse, power), a 50-digit mpmath evaluation of each
textbook formula on the exact value of the float input (tiny and huge lengths, angles near 0
and π), and hypothesis properties: ``p q q⁻¹ = p``, ``exp(log q) = q``, ``q^s q^t = q^(s+t)``.
"""

from __future__ import annotations

import mp_reference as mp
import mpmath
import numpy as np
import pytest
from bad_numbers import bad_values
from budget import examples
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp
from numpy.testing import assert_allclose, assert_array_equal
from scipy.spatial.transform import Rotation

from eulerlib import (
    quaternion_conjugate,
    quaternion_exp,
    quaternion_inverse,
    quaternion_log,
    quaternion_multiply,
    quaternion_power,
    quaternion_to_matrix,
)
from eulerlib._blocks import BLOCK_SIZE

EPS = mp.EPS
MP = mp.MP

# --- the product against typed-in formulas and SciPy -------------------------------------------

UNITS = {"1": [1, 0, 0, 0], "i": [0, 1, 0, 0], "j": [0, 0, 1, 0], "k": [0, 0, 0, 1]}
#: Hamilton's table: row times column, as (sign, unit)
TABLE = {
    ("i", "i"): (-1, "1"), ("i", "j"): (1, "k"), ("i", "k"): (-1, "j"),
    ("j", "i"): (-1, "k"), ("j", "j"): (-1, "1"), ("j", "k"): (1, "i"),
    ("k", "i"): (1, "j"), ("k", "j"): (-1, "i"), ("k", "k"): (-1, "1"),
}  # fmt: skip


@pytest.mark.parametrize(("left", "right"), sorted(TABLE))
def test_hamiltons_table(left: str, right: str) -> None:
    sign, unit = TABLE[left, right]
    product = quaternion_multiply(UNITS[left], UNITS[right], scalar_first=True)
    assert_array_equal(product, sign * np.array(UNITS[unit], dtype=float))


def left_matrix(p: np.ndarray) -> np.ndarray:
    """``L(p)`` with ``p q = L(p) q`` for ``(w, x, y, z)`` column vectors, typed in."""
    w, x, y, z = p
    return np.array([[w, -x, -y, -z], [x, w, -z, y], [y, z, w, -x], [z, -y, x, w]])


def test_product_is_the_left_multiplication_matrix(rng) -> None:
    p, q = rng.normal(size=(2, 50, 4))
    expected = np.stack([left_matrix(a) @ b for a, b in zip(p, q, strict=True)])
    assert_allclose(quaternion_multiply(p, q, scalar_first=True), expected, rtol=0, atol=8 * EPS)


def test_product_composes_rotations_as_scipy_does(rng) -> None:
    r, s = Rotation.random(100, rng=rng), Rotation.random(100, rng=rng)
    pq = quaternion_multiply(r.as_quat(), s.as_quat())
    assert np.abs(pq - (r * s).as_quat()).max() <= 4 * EPS
    R = quaternion_to_matrix(pq)
    assert np.abs(R - r.as_matrix() @ s.as_matrix()).max() <= 8 * EPS
    first = quaternion_multiply(r.as_quat(scalar_first=True), s.as_quat(scalar_first=True),
                                scalar_first=True)  # fmt: skip
    assert_array_equal(first[:, [1, 2, 3, 0]], pq)


def test_product_broadcasts(rng) -> None:
    p = rng.normal(size=(3, 1, 4))
    q = rng.normal(size=(5, 4))
    product = quaternion_multiply(p, q)
    assert product.shape == (3, 5, 4)
    for i in range(3):
        for j in range(5):
            assert_array_equal(product[i, j], quaternion_multiply(p[i, 0], q[j]))
    many = rng.normal(size=(BLOCK_SIZE + 7, 4))
    assert_array_equal(quaternion_multiply(many, q[0])[-3:], quaternion_multiply(many[-3:], q[0]))


def test_conjugate_and_inverse_against_scipy(rng) -> None:
    r = Rotation.random(50, rng=rng)
    assert_array_equal(quaternion_conjugate(r.as_quat()), r.inv().as_quat())
    assert np.abs(quaternion_inverse(r.as_quat()) - r.inv().as_quat()).max() <= 2 * EPS
    q = rng.normal(size=(50, 4))
    assert_allclose(quaternion_inverse(q), quaternion_conjugate(q) / np.sum(q * q, -1)[:, None],
                    rtol=4 * EPS)  # fmt: skip
    assert_array_equal(quaternion_conjugate([0.0, 0.0, 0.0, 1.0]), [0.0, 0.0, 0.0, 1.0])
    assert not np.signbit(quaternion_conjugate([0.0, 0.0, 0.0, 1.0])).any()


# --- the 50-digit reference ----------------------------------------------------------------------


def mp_product(p: list, q: list) -> list:
    pw, px, py, pz = p
    qw, qx, qy, qz = q
    return [
        pw * qw - px * qx - py * qy - pz * qz,
        pw * qx + px * qw + py * qz - pz * qy,
        pw * qy - px * qz + py * qw + pz * qx,
        pw * qz + px * qy - py * qx + pz * qw,
    ]


def mp_polar(q: list) -> tuple:
    norm = mpmath.sqrt(sum(c * c for c in q))
    vector = mpmath.sqrt(sum(c * c for c in q[1:]))
    angle = mpmath.atan2(vector, q[0])
    unit = [c / vector for c in q[1:]] if vector else [MP(1), MP(0), MP(0)]
    return norm, angle, unit


def mp_exp(q: list) -> list:
    a, v = q[0], q[1:]
    length = mpmath.sqrt(sum(c * c for c in v))
    ratio = mpmath.sin(length) / length if length else MP(1)
    scale = mpmath.exp(a)
    return [scale * mpmath.cos(length)] + [scale * ratio * c for c in v]


def mp_log(q: list) -> list:
    norm, angle, unit = mp_polar(q)
    return [mpmath.log(norm)] + [angle * c for c in unit]


def mp_power(q: list, t: float) -> list:
    norm, angle, unit = mp_polar(q)
    scale = norm ** MP(t)
    return [scale * mpmath.cos(t * angle)] + [scale * mpmath.sin(t * angle) * c for c in unit]


def relative_ulps(value: np.ndarray, exact: list) -> float:
    """Largest component error over the exact result's length, in units of 2⁻⁵²."""
    length = mpmath.sqrt(sum(c * c for c in exact))
    worst = max(abs(MP(float(v)) - e) for v, e in zip(value, exact, strict=True))
    return float(worst / length) / EPS


def unit_quaternion_at(angle: float, axis: np.ndarray) -> np.ndarray:
    """``(cos θ, sin θ axis)`` in floats, ``(w, x, y, z)``."""
    return np.concatenate([[np.cos(angle)], np.sin(angle) * axis])


ANGLES = [1e-300, 1e-100, 1e-12, 1e-6, 0.5, 1.5, np.pi / 2, 3.0, np.pi - 1e-6,
          np.pi - 1e-12, np.pi]  # fmt: skip
SCALES = [1e-300, 1e-100, 1e-8, 1.0, 1e8, 1e100, 1e300]


def test_product_and_inverse_against_mpmath(rng) -> None:
    worst_product = worst_inverse = 0.0
    with mpmath.workdps(mp.DIGITS):
        for scale in SCALES:
            for _ in range(20):
                p = rng.normal(size=4) * scale
                q = rng.normal(size=4) / scale
                exact = mp_product(mp.mp_vector(p), mp.mp_vector(q))
                got = quaternion_multiply(p, q, scalar_first=True)
                worst_product = max(worst_product, relative_ulps(got, exact))
                exact_q = mp.mp_vector(p)
                squared = sum(c * c for c in exact_q)
                inverse = [exact_q[0] / squared] + [-c / squared for c in exact_q[1:]]
                got = quaternion_inverse(p, scalar_first=True)
                worst_inverse = max(worst_inverse, relative_ulps(got, inverse))
    assert worst_product <= 4.0
    assert worst_inverse <= 2.0


def test_exp_against_mpmath(rng) -> None:
    with mpmath.workdps(mp.DIGITS):
        for length in [1e-300, 1e-150, 1e-20, 1e-8, 1e-3, 0.5, np.pi / 2, 3.0, np.pi, 10.0]:
            # |v| is rounded to half a unit in its last place before its sine and cosine are
            # taken: an error of up to |v| / 2 units of 2⁻⁵² that no method avoids
            bound = 2.0 + length / 2
            for axis in [np.array([0.0, 0.0, 1.0]), *(mp.random_axis(rng) for _ in range(4))]:
                v = np.asarray(axis, dtype=float) * length
                exact = mp_exp([MP(0), *mp.mp_vector(v)])
                assert relative_ulps(quaternion_exp(v, scalar_first=True), exact) <= bound
                for a in (-3.0, 0.7):
                    q = np.concatenate([[a], v])
                    exact = mp_exp(mp.mp_vector(q))
                    got = quaternion_exp(q, scalar_first=True)
                    assert relative_ulps(got, exact) <= bound + 1.0  # e^a is rounded once more


def test_log_against_mpmath(rng) -> None:
    worst_scalar = worst_vector = 0.0
    with mpmath.workdps(mp.DIGITS):
        for angle in ANGLES:
            axis = np.asarray(mp.random_axis(rng), dtype=float)
            for scale in SCALES:
                q = unit_quaternion_at(angle, axis) * scale
                exact = mp_log(mp.mp_vector(q))
                got = quaternion_log(q, scalar_first=True)
                # ln|q| absolutely (it is near 0 for unit quaternions), θ u relative to θ
                scalar_error = abs(MP(float(got[0])) - exact[0]) / max(abs(exact[0]), 1)
                worst_scalar = max(worst_scalar, float(scalar_error) / EPS)
                if all(c == 0 for c in exact[1:]):  # sin θ · scale underflowed to 0
                    assert_array_equal(got[1:], 0.0)
                else:
                    worst_vector = max(worst_vector, relative_ulps(got[1:], exact[1:]))
    assert worst_scalar <= 1.0
    assert worst_vector <= 3.0


@pytest.mark.parametrize("t", [-2.5, -1.0, 0.3, 0.5, 2.0, 7.0])
def test_power_against_mpmath(t: float, rng) -> None:
    worst = 0.0
    with mpmath.workdps(mp.DIGITS):
        for angle in ANGLES:
            axis = np.asarray(mp.random_axis(rng), dtype=float)
            for scale in SCALES:
                if abs(t * np.log2(scale)) > 1000:
                    continue  # |q|^t beyond float64's range
                q = unit_quaternion_at(angle, axis) * scale
                exact = mp_power(mp.mp_vector(q), t)
                got = quaternion_power(q, t, scalar_first=True)
                worst = max(worst, relative_ulps(got, exact))
    # the angle t θ is rounded once more than θ, and |q|^t has the error of |q| times t
    assert worst <= 4.0 + 2.0 * abs(t)


def test_power_turns_as_scipy_does(rng) -> None:
    r = Rotation.random(200, rng=rng)
    q = r.as_quat(canonical=True)
    for t in (-1.5, 0.25, 0.5, 3.0):
        assert np.abs(quaternion_power(q, t) - (r**t).as_quat()).max() <= 16 * EPS


# --- special values ------------------------------------------------------------------------------


def test_exp_and_log_of_special_values() -> None:
    assert_array_equal(quaternion_exp([0.0, 0.0, 0.0]), [0.0, 0.0, 0.0, 1.0])
    assert_array_equal(quaternion_log([0.0, 0.0, 0.0, 1.0]), [0.0, 0.0, 0.0, 0.0])
    # a negative real number: the vector part is π along x, documented
    assert_array_equal(quaternion_log([0.0, 0.0, 0.0, -2.0]), [np.pi, 0.0, 0.0, np.log(2.0)])
    assert_allclose(quaternion_exp(quaternion_log([0.0, 0.0, 0.0, -2.0])), [0, 0, 0, -2],
                    atol=1e-15)  # fmt: skip
    # the half rotation vector of a unit quaternion, by default in the first three places
    r = Rotation.from_rotvec([0.3, -0.2, 0.1])
    assert_allclose(quaternion_log(r.as_quat())[:3], r.as_rotvec() / 2, rtol=4 * EPS)
    assert_allclose(quaternion_exp(r.as_rotvec() / 2), r.as_quat(), rtol=0, atol=2 * EPS)


def test_powers_of_special_exponents(rng) -> None:
    q = rng.normal(size=(20, 4))
    assert_allclose(quaternion_power(q, 0.0), np.tile([0.0, 0.0, 0.0, 1.0], (20, 1)))
    assert_allclose(quaternion_power(q, 1.0), q, rtol=0, atol=8 * EPS * np.abs(q).max())
    assert_allclose(quaternion_power(q, -1.0), quaternion_inverse(q), rtol=1e-14, atol=1e-15)
    two = quaternion_power(q, 2.0)
    assert_allclose(two, quaternion_multiply(q, q), rtol=1e-13, atol=1e-13)
    broadcast = quaternion_power(q[:3, None], [0.5, 2.0])
    assert broadcast.shape == (3, 2, 4)
    assert_array_equal(broadcast[1, 1], quaternion_power(q[1], 2.0))


# --- properties --------------------------------------------------------------------------------

QUATERNIONS = hnp.arrays(
    np.float64,
    4,
    elements=st.floats(-1e3, 1e3, allow_nan=False, allow_subnormal=False),
).filter(lambda q: np.linalg.norm(q) > 1e-3)


@settings(max_examples=examples(200), deadline=None)
@given(QUATERNIONS, QUATERNIONS)
def test_p_q_times_q_inverse_is_p(p: np.ndarray, q: np.ndarray) -> None:
    back = quaternion_multiply(quaternion_multiply(p, q), quaternion_inverse(q))
    assert np.abs(back - p).max() <= 32 * EPS * np.linalg.norm(p)


@settings(max_examples=examples(200), deadline=None)
@given(QUATERNIONS)
def test_exp_of_log_is_q(q: np.ndarray) -> None:
    assert np.abs(quaternion_exp(quaternion_log(q)) - q).max() <= 16 * EPS * np.linalg.norm(q)


@settings(max_examples=examples(200), deadline=None)
@given(QUATERNIONS, st.floats(-3.0, 3.0), st.floats(-3.0, 3.0))
def test_powers_add_their_exponents(q: np.ndarray, s: float, t: float) -> None:
    unit = q / np.linalg.norm(q)
    # about one axis, q^s q^t = q^(s + t) holds for any real s and t
    product = quaternion_multiply(quaternion_power(unit, s), quaternion_power(unit, t))
    assert np.abs(product - quaternion_power(unit, s + t)).max() <= 64 * EPS


@settings(max_examples=examples(200), deadline=None)
@given(QUATERNIONS, st.floats(0.0, 1.0), st.floats(-2.0, 2.0))
def test_a_power_of_a_power(q: np.ndarray, s: float, t: float) -> None:
    unit = q / np.linalg.norm(q)
    # (q^s)^t = q^(s t) while s θ stays in [0, π], as for s in [0, 1]
    nested = quaternion_power(quaternion_power(unit, s), t)
    assert np.abs(nested - quaternion_power(unit, s * t)).max() <= 64 * EPS


# --- bad input -----------------------------------------------------------------------------------

Q0 = Rotation.from_euler("ZYX", [0.3, 0.2, 0.1]).as_quat()
ARGUMENTS = {
    "quaternion_multiply, p": (lambda x: quaternion_multiply(x, Q0), "p", Q0),
    "quaternion_multiply, q": (lambda x: quaternion_multiply(Q0, x), "q", Q0),
    "quaternion_conjugate": (lambda x: quaternion_conjugate(x), "q", Q0),
    "quaternion_inverse": (lambda x: quaternion_inverse(x), "q", Q0),
    "quaternion_exp, vector": (lambda x: quaternion_exp(x), "v", [0.1, 0.2, 0.3]),
    "quaternion_exp, quaternion": (lambda x: quaternion_exp(x), "v", Q0),
    "quaternion_log": (lambda x: quaternion_log(x), "q", Q0),
    "quaternion_power, q": (lambda x: quaternion_power(x, 0.5), "q", Q0),
    "quaternion_power, t": (lambda x: quaternion_power(Q0, x), "t", [0.5, 2.0]),
}


@pytest.mark.parametrize("key", sorted(ARGUMENTS))
def test_numbers_are_real_and_finite(key: str) -> None:
    call, name, valid = ARGUMENTS[key]
    call(valid)
    for bad, error, words in bad_values(valid):
        with pytest.raises(error, match=rf"^{name} {words}"):
            call(bad)


@pytest.mark.parametrize("key", sorted(k for k in ARGUMENTS if ARGUMENTS[k][1] != "t"))
def test_wrong_shapes_are_named(key: str) -> None:
    call, name, _ = ARGUMENTS[key]
    expected = r"\(\.\.\., 3\) or \(\.\.\., 4\)" if name == "v" else r"\(\.\.\., 4\)"
    for bad in (1.0, [1.0, 2.0], np.zeros((2, 5))):
        with pytest.raises(ValueError, match=rf"^{name} must have shape {expected}, got shape"):
            call(bad)


def test_shapes_that_do_not_broadcast() -> None:
    with pytest.raises(ValueError, match=r"leading shapes of p \(2,\) and q \(3,\) do not"):
        quaternion_multiply(np.ones((2, 4)), np.ones((3, 4)))
    with pytest.raises(ValueError, match=r"leading shapes of q \(2,\) and t \(3,\) do not"):
        quaternion_power(np.ones((2, 4)), np.ones(3))


@pytest.mark.parametrize(
    ("call", "words"),
    [
        (quaternion_inverse, "a zero quaternion has no inverse"),
        (quaternion_log, "the logarithm of 0 is not defined"),
        (lambda q: quaternion_power(q, 0.5), "0 has no power of every exponent"),
    ],
)
def test_a_zero_quaternion_is_refused_with_its_index(call, words: str) -> None:
    with pytest.raises(ValueError, match=rf"^q is zero: {words}$"):
        call([0.0, 0.0, 0.0, 0.0])
    q = np.tile(Q0, (2, BLOCK_SIZE + 3, 1))
    q[1, BLOCK_SIZE + 1] = 0.0
    with pytest.raises(ValueError, match=rf"^q at index \(1, {BLOCK_SIZE + 1}\) is zero"):
        call(q)
    # tiny is not zero
    assert np.all(np.isfinite(call([0.0, 0.0, 0.0, 1e-300])))


def test_inputs_are_never_modified_and_nothing_is_printed(capsys, rng) -> None:
    p, q, t = rng.normal(size=(5, 4)), rng.normal(size=(5, 4)), rng.normal(size=5)
    before = [a.copy() for a in (p, q, t)]
    quaternion_multiply(p, q)
    quaternion_conjugate(q)
    quaternion_inverse(q)
    quaternion_exp(q)
    quaternion_exp(q[:, :3])
    quaternion_log(q)
    quaternion_power(q, t)
    for original, now in zip(before, (p, q, t), strict=True):
        assert_array_equal(now, original)
    assert capsys.readouterr() == ("", "")


def test_one_quaternion_is_computed_as_many_are(rng) -> None:
    """A single quaternion takes a path of its own (Python floats); it agrees with the block
    path to the last bit in the arithmetic, within a unit for sines, cosines and logarithms."""
    q = np.concatenate([rng.normal(size=(50, 4)), rng.normal(size=(10, 4)) * 1e-200,
                        [[0.0, 0.0, 0.0, -2.0], [1e-300, 0.0, 0.0, 1.0]]])  # fmt: skip
    p = rng.normal(size=(len(q), 4))
    t = 0.7
    many = {
        "multiply": quaternion_multiply(p, q),
        "inverse": quaternion_inverse(q),
        "exp": quaternion_exp(q),
        "exp of vectors": quaternion_exp(q[:, :3]),
        "log": quaternion_log(q),
        "power": quaternion_power(q, t),
    }
    for k in range(len(q)):
        one = {
            "multiply": quaternion_multiply(p[k], q[k]),
            "inverse": quaternion_inverse(q[k]),
            "exp": quaternion_exp(q[k]),
            "exp of vectors": quaternion_exp(q[k, :3]),
            "log": quaternion_log(q[k]),
            "power": quaternion_power(q[k], t),
        }
        for name, value in one.items():
            assert value.shape == (4,)
            if name in ("multiply", "inverse"):
                assert_array_equal(value, many[name][k], err_msg=name)
            else:
                scale = np.abs(many[name][k]).max()
                assert_allclose(value, many[name][k], rtol=0, atol=2 * EPS * scale, err_msg=name)
