"""The papers' own equations, typed in term by term, as oracles.

Rose (2015), Part 2: eq 2 (yaw-pitch-roll to matrix), eq 3 (matrix to angles), eq 4a/4b (gimbal
lock), eq 6a–c (rotating a point), eq 7b (the inverse is the transpose), eq 8 / code sample 6
(combining rotations). Baker, "Matrix to Euler": the heading-attitude-bank matrix, the three
formulas away from the poles and the choice bank = 0 at both poles.

Rows and columns follow each paper: Rose counts from 1 (``r11`` … ``r33``), Baker from 0
(``m00`` … ``m22``). The helpers below read the entries by those names before using them, so
each formula reads as in the paper.
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose, assert_array_equal

from eulerlib import (
    GimbalLockWarning,
    compose,
    euler_to_matrix,
    heading_attitude_bank_to_matrix,
    invert,
    matrix_to_euler,
    matrix_to_heading_attitude_bank,
    matrix_to_yaw_pitch_roll,
    rotate_points,
    yaw_pitch_roll_to_matrix,
)


def wrapped(difference):
    return (np.asarray(difference) + np.pi) % (2 * np.pi) - np.pi


def rose_entries(R):
    """``r11, r12, …, r33`` of Rose's eq 1, each of shape ``R.shape[:-2]``."""
    return {f"r{i + 1}{j + 1}": R[..., i, j] for i in range(3) for j in range(3)}


def rose_eq2(w, v, u):
    """Rose (2015), eq 2: yaw w about z, pitch v about y, roll u about x."""
    c, s = np.cos, np.sin
    r11 = c(v) * c(w)
    r12 = s(u) * s(v) * c(w) - c(u) * s(w)
    r13 = s(u) * s(w) + c(u) * s(v) * c(w)
    r21 = c(v) * s(w)
    r22 = c(u) * c(w) + s(u) * s(v) * s(w)
    r23 = c(u) * s(v) * s(w) - s(u) * c(w)
    r31 = -s(v)
    r32 = s(u) * c(v)
    r33 = c(u) * c(v)
    rows = [[r11, r12, r13], [r21, r22, r23], [r31, r32, r33]]
    return np.stack([np.stack(row, axis=-1) for row in rows], axis=-2)


def baker_matrix(heading, attitude, bank):
    """Baker's heading-attitude-bank matrix, typed in entry by entry."""
    ch, sh = np.cos(heading), np.sin(heading)
    ca, sa = np.cos(attitude), np.sin(attitude)
    cb, sb = np.cos(bank), np.sin(bank)
    m00 = ch * ca
    m01 = -ch * sa * cb + sh * sb
    m02 = ch * sa * sb + sh * cb
    m10 = sa
    m11 = ca * cb
    m12 = -ca * sb
    m20 = -sh * ca
    m21 = sh * sa * cb + ch * sb
    m22 = -sh * sa * sb + ch * cb
    rows = [[m00, m01, m02], [m10, m11, m12], [m20, m21, m22]]
    return np.stack([np.stack(row, axis=-1) for row in rows], axis=-2)


def baker_entries(R):
    return {f"m{i}{j}": R[..., i, j] for i in range(3) for j in range(3)}


@pytest.fixture
def yaw_pitch_roll(rng):
    """Random angles with |pitch| ≤ 89°, so eq 3 applies."""
    n = 1000
    yaw = rng.uniform(-np.pi, np.pi, n)
    pitch = rng.uniform(-1.0, 1.0, n) * np.radians(89)
    roll = rng.uniform(-np.pi, np.pi, n)
    return yaw, pitch, roll


# --- Rose, eq 2 ---------------------------------------------------------------------------


def test_rose_eq2(yaw_pitch_roll):
    w, v, u = yaw_pitch_roll
    expected = rose_eq2(w, v, u)
    assert_allclose(yaw_pitch_roll_to_matrix(w, v, u), expected, rtol=0, atol=2e-15)
    assert_allclose(euler_to_matrix(np.stack([w, v, u], -1), "ZYX"), expected, atol=2e-15)
    assert_allclose(euler_to_matrix(np.stack([u, v, w], -1), "xyz"), expected, atol=2e-15)


def test_rose_eq2_degrees_and_broadcasting():
    yaw = np.array([[10.0], [-135.0]])  # (2, 1) against (3,) pitch and a scalar roll
    pitch = np.array([-60.0, 0.0, 45.0])
    roll = 30.0
    R = yaw_pitch_roll_to_matrix(yaw, pitch, roll, degrees=True)
    assert R.shape == (2, 3, 3, 3)
    w, v = np.broadcast_arrays(np.radians(yaw), np.radians(pitch))
    assert_allclose(R, rose_eq2(w, v, np.full(w.shape, np.radians(roll))), atol=2e-15)


# --- Rose, eq 3 (away from lock) ----------------------------------------------------------


def test_rose_eq3(yaw_pitch_roll):
    R = rose_eq2(*yaw_pitch_roll)
    r = rose_entries(R)
    yaw = np.arctan2(r["r21"], r["r11"])  # eq 3a
    pitch = -np.arcsin(r["r31"])  # eq 3b
    roll = np.arctan2(r["r32"], r["r33"])  # eq 3c
    got_yaw, got_pitch, got_roll = matrix_to_yaw_pitch_roll(R)
    assert_allclose(wrapped(got_yaw - yaw), 0, atol=1e-13)
    assert_allclose(got_pitch, pitch, rtol=0, atol=1e-13)
    assert_allclose(wrapped(got_roll - roll), 0, atol=1e-13)
    # and the generic function agrees with the named one for "ZYX"
    assert_array_equal(matrix_to_euler(R, "ZYX"), np.stack([got_yaw, got_pitch, got_roll], -1))


def test_rose_eq3_recovers_the_angles(yaw_pitch_roll):
    R = rose_eq2(*yaw_pitch_roll)
    for got, original in zip(matrix_to_yaw_pitch_roll(R), yaw_pitch_roll, strict=True):
        assert_allclose(got, original, rtol=0, atol=1e-13)
    in_degrees = matrix_to_yaw_pitch_roll(R, degrees=True)
    for got, original in zip(in_degrees, yaw_pitch_roll, strict=True):
        assert_allclose(got, np.degrees(original), rtol=0, atol=1e-11)


# --- Rose, eq 4a and 4b (gimbal lock) -----------------------------------------------------


def lock_angles(rng, n=300):
    return rng.uniform(-np.pi, np.pi, n), rng.uniform(-np.pi, np.pi, n)


def test_rose_eq4a_pitch_minus_90(rng):
    w, u = lock_angles(rng)
    R = rose_eq2(w, np.full_like(w, -np.pi / 2), u)
    r = rose_entries(R)
    assert_array_equal(r["r31"], 1.0)  # as the paper says
    with pytest.warns(GimbalLockWarning):
        yaw, pitch, roll = matrix_to_yaw_pitch_roll(R)
    assert_array_equal(yaw, 0.0)  # Rose's choice
    assert_allclose(pitch, -np.pi / 2, rtol=0, atol=1e-15)
    # eq 4a: u + w = atan2(-r12, -r13), solved with w = 0
    assert_allclose(wrapped(roll + yaw - np.arctan2(-r["r12"], -r["r13"])), 0, atol=1e-14)
    assert_allclose(wrapped(roll - (u + w)), 0, atol=1e-14)


def test_rose_eq4b_pitch_plus_90(rng):
    w, u = lock_angles(rng)
    R = rose_eq2(w, np.full_like(w, np.pi / 2), u)
    r = rose_entries(R)
    assert_array_equal(r["r31"], -1.0)
    with pytest.warns(GimbalLockWarning):
        yaw, pitch, roll = matrix_to_yaw_pitch_roll(R)
    assert_array_equal(yaw, 0.0)
    assert_allclose(pitch, np.pi / 2, rtol=0, atol=1e-15)
    # eq 4b: u − w = atan2(r12, r13), solved with w = 0
    assert_allclose(wrapped(roll - yaw - np.arctan2(r["r12"], r["r13"])), 0, atol=1e-14)
    assert_allclose(wrapped(roll - (u - w)), 0, atol=1e-14)


def test_rose_lock_angles_rebuild_the_matrix(rng):
    w, u = lock_angles(rng)
    v = rng.choice([-np.pi / 2, np.pi / 2], w.shape)
    R = rose_eq2(w, v, u)
    yaw, pitch, roll = matrix_to_yaw_pitch_roll(R, warn=False)
    assert_allclose(rose_eq2(yaw, pitch, roll), R, rtol=0, atol=1e-15)


# --- Rose, eq 6, 7 and 8 ------------------------------------------------------------------


def test_rose_eq6_rotating_points(yaw_pitch_roll, rng):
    R = rose_eq2(*yaw_pitch_roll)
    x0, y0, z0 = rng.normal(size=(3, R.shape[0]))
    r = rose_entries(R)
    x1 = r["r11"] * x0 + r["r12"] * y0 + r["r13"] * z0  # eq 6a
    y1 = r["r21"] * x0 + r["r22"] * y0 + r["r23"] * z0  # eq 6b
    z1 = r["r31"] * x0 + r["r32"] * y0 + r["r33"] * z0  # eq 6c
    rotated = rotate_points(R, np.stack([x0, y0, z0], axis=-1))
    assert_allclose(rotated, np.stack([x1, y1, z1], axis=-1), rtol=0, atol=1e-14)


def test_rose_eq7b_inverse_is_transpose(yaw_pitch_roll):
    R = rose_eq2(*yaw_pitch_roll)
    r = rose_entries(R)
    rows = [
        [r["r11"], r["r21"], r["r31"]],
        [r["r12"], r["r22"], r["r32"]],
        [r["r13"], r["r23"], r["r33"]],
    ]
    expected = np.stack([np.stack(row, axis=-1) for row in rows], axis=-2)
    assert_array_equal(invert(R), expected)


def test_rose_code_sample_6_product(rng):
    """C = A B with c_ij = a_i1 b_1j + a_i2 b_2j + a_i3 b_3j, A the first rotation."""
    A = rose_eq2(*rng.uniform(-np.pi, np.pi, (3, 50)))
    B = rose_eq2(*rng.uniform(-np.pi, np.pi, (3, 50)))
    C = np.zeros_like(A)
    for i in range(3):
        for j in range(3):
            C[:, i, j] = A[:, i, 0] * B[:, 0, j] + A[:, i, 1] * B[:, 1, j] + A[:, i, 2] * B[:, 2, j]
    assert_allclose(compose(A, B), C, rtol=0, atol=2e-15)


# --- Baker --------------------------------------------------------------------------------


@pytest.fixture
def heading_attitude_bank(rng):
    """Random angles with |attitude| ≤ 89°, away from Baker's poles."""
    n = 1000
    heading = rng.uniform(-np.pi, np.pi, n)
    attitude = rng.uniform(-1.0, 1.0, n) * np.radians(89)
    bank = rng.uniform(-np.pi, np.pi, n)
    return heading, attitude, bank


def test_baker_matrix(heading_attitude_bank):
    h, a, b = heading_attitude_bank
    expected = baker_matrix(h, a, b)
    assert_allclose(heading_attitude_bank_to_matrix(h, a, b), expected, rtol=0, atol=2e-15)
    assert_allclose(euler_to_matrix(np.stack([h, a, b], -1), "YZX"), expected, atol=2e-15)
    assert_allclose(euler_to_matrix(np.stack([b, a, h], -1), "xzy"), expected, atol=2e-15)
    assert_allclose(
        heading_attitude_bank_to_matrix(*np.degrees([h, a, b]), degrees=True),
        expected,
        rtol=0,
        atol=2e-15,
    )


def test_baker_formulas_away_from_the_poles(heading_attitude_bank):
    R = baker_matrix(*heading_attitude_bank)
    m = baker_entries(R)
    heading = np.arctan2(-m["m20"], m["m00"])
    attitude = np.arcsin(m["m10"])
    bank = np.arctan2(-m["m12"], m["m11"])
    got = matrix_to_heading_attitude_bank(R)
    assert_allclose(wrapped(got[0] - heading), 0, atol=1e-13)
    assert_allclose(got[1], attitude, rtol=0, atol=1e-13)
    assert_allclose(wrapped(got[2] - bank), 0, atol=1e-13)
    for value, original in zip(got, heading_attitude_bank, strict=True):
        assert_allclose(value, original, rtol=0, atol=1e-13)


@pytest.mark.parametrize("pole", [+1, -1], ids=["north", "south"])
def test_baker_poles(pole, rng):
    h, b = lock_angles(rng)
    R = baker_matrix(h, np.full_like(h, pole * np.pi / 2), b)
    m = baker_entries(R)
    assert_array_equal(m["m10"], pole)
    with pytest.warns(GimbalLockWarning):
        heading, attitude, bank = matrix_to_heading_attitude_bank(R)
    assert_array_equal(bank, 0.0)  # Baker's choice
    assert_allclose(attitude, pole * np.pi / 2, rtol=0, atol=1e-15)
    assert_allclose(wrapped(heading - np.arctan2(m["m02"], m["m22"])), 0, atol=1e-14)
    # north pole: h + b is what survives; south pole: h − b
    assert_allclose(wrapped(heading - (h + pole * b)), 0, atol=1e-14)
    assert_allclose(baker_matrix(heading, attitude, bank), R, rtol=0, atol=1e-15)


def test_baker_worked_example():
    """Baker's example: a quarter turn about x is heading 0, attitude 0, bank 90°."""
    R = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
    heading, attitude, bank = matrix_to_heading_attitude_bank(R, degrees=True)
    assert (float(heading), float(attitude), float(bank)) == (0.0, 0.0, 90.0)


def test_named_functions_keep_their_papers_lock_choice(rng):
    """At a Baker pole, the generic "YZX" zeroes heading, the named function zeroes bank."""
    h, b = lock_angles(rng, 50)
    R = baker_matrix(h, np.full_like(h, np.pi / 2), b)
    generic = matrix_to_euler(R, "YZX", warn=False)
    named = np.stack(matrix_to_heading_attitude_bank(R, warn=False), axis=-1)
    assert_array_equal(generic[:, 0], 0.0)
    assert_array_equal(named[:, 2], 0.0)
    for angles in (generic, named):
        assert_allclose(baker_matrix(*angles.T), R, rtol=0, atol=1e-15)
    # for Rose's "ZYX" both choices are the same: yaw = 0
    w, u = lock_angles(rng, 50)
    R = rose_eq2(w, np.full_like(w, -np.pi / 2), u)
    assert_array_equal(
        matrix_to_euler(R, "ZYX", warn=False),
        np.stack(matrix_to_yaw_pitch_roll(R, warn=False), axis=-1),
    )
