"""Quaternions ⇄ matrices and Euler angles, against oracles nobody here wrote.

Oracles: SciPy's ``Rotation`` (``from_quat``, ``as_quat(canonical=True)``, ``from_euler``,
``as_euler``; its components reordered here rather than through its ``scalar_first`` keyword,
which needs SciPy 1.14), the 50-digit mpmath reference of ``tests/mp_reference.py`` at the hard
places (turns near 0 and near π, quaternions with a tiny scalar part, huge angles in degrees),
Hamilton's product typed in below, and hypothesis properties.
"""

from __future__ import annotations

import warnings

import mp_reference as mp
import numpy as np
import pytest
from budget import examples
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp
from numpy.testing import assert_allclose, assert_array_equal
from scipy.spatial.transform import Rotation

from eulerlib import (
    ALL_SEQUENCES,
    GimbalLockWarning,
    euler_to_matrix,
    euler_to_quaternion,
    get_convention,
    matrix_to_euler,
    matrix_to_quaternion,
    quaternion_to_euler,
    quaternion_to_matrix,
    rot_x,
)

EPS = mp.EPS


def scalar_first(q: np.ndarray) -> np.ndarray:
    """(x, y, z, w) → (w, x, y, z)."""
    return np.roll(q, 1, axis=-1)


def hamilton(p: np.ndarray, q: np.ndarray) -> np.ndarray:
    """Hamilton's product of scalar-first quaternions, from i² = j² = k² = ijk = −1."""
    a, b, c, d = np.moveaxis(p, -1, 0)
    e, f, g, h = np.moveaxis(q, -1, 0)
    return np.stack(
        [
            a * e - b * f - c * g - d * h,
            a * f + b * e + c * h - d * g,
            a * g - b * h + c * e + d * f,
            a * h + b * g - c * f + d * e,
        ],
        axis=-1,
    )


@pytest.fixture(scope="module")
def hard_cases() -> list[tuple[str, np.ndarray]]:
    return mp.hard_rotations(np.random.default_rng(7))


# --- SciPy -----------------------------------------------------------------------------------


def test_matrix_to_quaternion_is_scipys_canonical_quaternion(rng) -> None:
    rotation = Rotation.random(20000, rng=rng)
    R = rotation.as_matrix()
    expected = rotation.as_quat(canonical=True)
    assert np.abs(matrix_to_quaternion(R) - expected).max() <= 2 * EPS
    assert_array_equal(matrix_to_quaternion(R, scalar_first=True), scalar_first(
        matrix_to_quaternion(R)))  # fmt: skip


def test_quaternion_to_matrix_is_scipys(rng) -> None:
    q = rng.normal(size=(20000, 4)) * rng.uniform(0.1, 10.0, (20000, 1))  # any length
    expected = Rotation.from_quat(q).as_matrix()
    assert np.abs(quaternion_to_matrix(q) - expected).max() <= 4 * EPS
    assert_array_equal(quaternion_to_matrix(scalar_first(q), scalar_first=True),
                       quaternion_to_matrix(q))  # fmt: skip


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_euler_to_quaternion_is_scipys_for_every_sequence(seq: str, rng) -> None:
    angles = rng.uniform(-4.0, 4.0, (2000, 3))
    expected = Rotation.from_euler(seq, angles).as_quat(canonical=True)
    assert np.abs(euler_to_quaternion(angles, seq) - expected).max() <= 4 * EPS
    in_degrees = euler_to_quaternion(np.degrees(angles), seq, degrees=True)
    assert np.abs(in_degrees - expected).max() <= 8 * EPS


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_quaternion_to_euler_is_scipys_away_from_lock(seq: str, rng) -> None:
    rotation = Rotation.random(2000, rng=rng)
    expected = rotation.as_euler(seq)
    angles = quaternion_to_euler(rotation.as_quat(), seq, warn=False)
    # both libraries agree on the angles unless a rotation is near lock, where they are
    # ill-conditioned; compare the rotations everywhere and the angles away from lock
    assert_allclose(Rotation.from_euler(seq, angles).as_matrix(), rotation.as_matrix(),
                    rtol=0, atol=1e-14)  # fmt: skip
    proper = seq[0].lower() == seq[2].lower()
    middle = expected[:, 1]
    far = np.abs(np.sin(middle)) > 1e-3 if proper else np.abs(np.cos(middle)) > 1e-3
    assert_allclose(angles[far], expected[far], rtol=0, atol=1e-12)


@pytest.mark.parametrize(
    "axis",
    [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [1, -1, 0], [0, 1, -1], [-1, 0, 1], [1, -2, 3]],
)
def test_half_turns_are_canonical_as_in_scipy(axis: list[int]) -> None:
    """At w = 0 exactly the first nonzero of x, y, z is positive, in both libraries."""
    n = np.array(axis, dtype=float) / np.linalg.norm(axis)
    R = 2.0 * np.outer(n, n) - np.eye(3)  # exactly symmetric: a half turn
    ours = matrix_to_quaternion(R)
    assert ours[3] == 0.0
    first = ours[np.flatnonzero(ours[:3])[0]]
    assert first > 0
    assert_allclose(ours, Rotation.from_matrix(R).as_quat(canonical=True), rtol=0, atol=2 * EPS)
    for sign in (1.0, -1.0):  # either quaternion of the half turn comes back canonical
        q = np.append(sign * n, 0.0)
        assert_allclose(matrix_to_quaternion(quaternion_to_matrix(q)), ours, atol=2 * EPS)


HALF = np.sqrt(0.5)


@pytest.mark.parametrize(
    ("seq", "angles", "expected"),
    [
        # R_z(0) R_y(180°) R_x(180°) = R_z(180°): the product of the elementary quaternions is
        # (0, 0, 0, −1); canonical (0, 0, 0, 1), the first nonzero being z
        ("ZYX", [0.0, 180.0, 180.0], [0.0, 0.0, 0.0, 1.0]),
        ("ZYX", [0.0, -180.0, -180.0], [0.0, 0.0, 0.0, 1.0]),
        # R_z(90°) R_y(180°): (c, 0, 0, s)(0, 0, 1, 0) = (0, −s, c, 0) with c = s = √½, already
        # canonical when flipped: x < 0 before, x > 0 after
        ("ZYX", [90.0, 180.0, 0.0], [0.0, HALF, -HALF, 0.0]),
        # R_y(180°) R_x(−90°): (0, 0, 1, 0)(c, −s, 0, 0) = (0, 0, c, s), and its negative
        # (0, 0, −c, −s) from the angles −180°: x = 0, the first nonzero is y
        ("ZYX", [0.0, 180.0, -90.0], [0.0, 0.0, HALF, HALF]),
        ("ZYX", [0.0, -180.0, -90.0], [0.0, 0.0, HALF, HALF]),
    ],
)
def test_half_turns_from_euler_angles_are_canonical(seq, angles, expected) -> None:
    """At w = 0 the sign of w says nothing: the first nonzero of x, y, z is made positive."""
    ours = euler_to_quaternion(np.array(angles), seq, degrees=True)  # (x, y, z, w)
    assert_allclose(scalar_first(ours), expected, rtol=0, atol=2 * EPS)
    assert ours[3] == 0.0


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_every_half_turn_of_right_angles_is_canonical(seq) -> None:
    """All Euler angles from {0°, ±90°, ±180°} whose rotation is a half turn; the canonical
    quaternion is derived from SciPy's: its w set to 0, the first nonzero of x, y, z made > 0."""
    grid = np.array(np.meshgrid(*[[0.0, 90.0, -90.0, 180.0, -180.0]] * 3)).reshape(3, -1).T
    theirs = Rotation.from_euler(seq, grid, degrees=True).as_quat()  # (x, y, z, w)
    half_turn = np.abs(theirs[:, 3]) < 1e-12
    grid, theirs = grid[half_turn], theirs[half_turn]
    theirs[:, 3] = 0.0
    for row in theirs:
        first = row[np.flatnonzero(np.abs(row[:3]) > 1e-12)[0]]
        row *= np.sign(first)
    ours = euler_to_quaternion(grid, seq, degrees=True)
    assert_allclose(ours, theirs, rtol=0, atol=4 * EPS)
    assert np.all(ours[:, 3] == 0.0)


def test_no_negative_zeros() -> None:
    q = matrix_to_quaternion(np.diag([1.0, -1.0, -1.0]))
    assert not np.signbit(q).any()
    R = quaternion_to_matrix([-0.0, -0.0, -1.0, 0.0])
    assert not np.signbit(R[R == 0]).any()
    assert not np.signbit(euler_to_quaternion([0.0, -0.0, 0.0])).any()


# --- the 50-digit reference at the hard places -------------------------------------------------


def test_matrix_to_quaternion_against_mpmath(hard_cases) -> None:
    for label, R in hard_cases:
        exact = mp.quaternion_of(mp.polar(R))
        q = matrix_to_quaternion(R, scalar_first=True)
        assert mp.quaternion_ulps(q, exact) <= 2.0, label


@pytest.mark.parametrize(
    "w",
    [0.0, 1e-300, 1e-200, 1e-100, 1e-20, 1e-16, 1e-12, 1e-8, 1e-4, 0.5, 1.0],
)
def test_quaternion_to_matrix_against_mpmath(w: float, rng) -> None:
    """Tiny scalar parts, and lengths from 1e-300 to 1e300."""
    for scale in (1e-300, 1e-150, 1.0, 3.0, 1e150, 1e300):
        vector = rng.normal(size=3)
        q = np.concatenate([[w], vector / np.linalg.norm(vector)]) * scale
        exact = mp.matrix_of_quaternion(mp.mp_vector(q))
        R = quaternion_to_matrix(q, scalar_first=True)
        assert mp.absolute_ulps(R, exact) <= 2.0, (w, scale)


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_euler_to_quaternion_against_mpmath(seq: str, rng) -> None:
    for degrees in (False, True):
        for _ in range(10):
            if degrees:
                angles = rng.choice([0.0, 90.0, -90.0, 180.0, 45.0, 1e20, 2.0**60 + 45], 3)
                angles = angles + rng.choice([0.0, 1e-9, 33.3], 3)
            else:
                angles = rng.uniform(-4.0, 4.0, 3)
            exact = mp.quaternion_of_euler(angles, seq, degrees)
            q = euler_to_quaternion(angles, seq, degrees=degrees, scalar_first=True)
            assert mp.quaternion_ulps(q, exact) <= 3.0, (angles, degrees)


def test_quarter_turns_in_degrees_are_exact() -> None:
    s = np.sqrt(0.5)
    assert_array_equal(euler_to_quaternion([180, 0, 0], degrees=True), [0, 0, 1, 0])
    assert_array_equal(euler_to_quaternion([0, -180, 0], degrees=True), [0, 1, 0, 0])
    assert_array_equal(euler_to_quaternion([90, 0, 0], degrees=True), [0, 0, s, s])
    for turns in (45 * 2.0**60, 45 * 2.0**59, -(45 * 2.0**70)):  # 720° · 2⁵⁶, 360° · 2⁵⁶, …
        assert_array_equal(euler_to_quaternion([turns, 0, 0], degrees=True), [0, 0, 0, 1])
    for angles in ([90, 0, 0], [0, 90, 0], [0, 0, -90], [90, 180, 270], [90, 90, 0]):
        q = euler_to_quaternion(angles, degrees=True)
        R = euler_to_matrix(angles, degrees=True)
        assert_array_equal(quaternion_to_matrix(q), R)
        assert_array_equal(matrix_to_quaternion(R), q)


# --- round trips -----------------------------------------------------------------------------


def test_round_trips_everywhere(rng, hard_cases) -> None:
    R = np.concatenate([Rotation.random(100_000, rng=rng).as_matrix(),
                        np.stack([R for _, R in hard_cases])])  # fmt: skip
    q = matrix_to_quaternion(R)
    assert np.abs(quaternion_to_matrix(q) - R).max() <= 1e-14
    again = matrix_to_quaternion(quaternion_to_matrix(q))
    near_half_turn = np.abs(q[:, 3]) < 1e-14  # there q and −q are both canonical within noise
    assert np.abs(again - q)[~near_half_turn].max() <= 1e-15
    assert np.minimum(np.abs(again - q), np.abs(again + q))[near_half_turn].max() <= 1e-15


@pytest.mark.parametrize("seq", ["ZYX", "xyz", "ZXZ", "rose", "baker"])
def test_quaternion_to_euler_reads_the_matrix_as_matrix_to_euler_does(seq: str, rng) -> None:
    """Identical numbers, at lock and near it too, since both read the same entries."""
    q = rng.normal(size=(500, 4))
    convention = get_convention(seq)
    poles = [0.0, np.pi] if convention.parsed.proper else [np.pi / 2, -np.pi / 2]
    lock = rng.uniform(-3, 3, (200, 3))
    lock[:, 1] = rng.choice(poles, 200) + rng.choice([0.0, 1e-15, 1e-9], 200)
    q = np.concatenate([q, euler_to_quaternion(lock, convention.seq), -q])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", GimbalLockWarning)
        angles = quaternion_to_euler(q, seq)
        expected = matrix_to_euler(quaternion_to_matrix(q), seq, validate=False)
    assert_array_equal(angles, expected)


# --- gimbal lock -------------------------------------------------------------------------------


def test_gimbal_lock_gives_the_one_warning_with_the_presets_policy() -> None:
    q = euler_to_quaternion([[40, 90, 10], [0, 0, 0], [5, 20, 5]], "baker", degrees=True)
    with pytest.warns(GimbalLockWarning) as record:
        angles = quaternion_to_euler(q, "baker", degrees=True)
    assert len(record) == 1
    assert record[0].filename == __file__
    facts = record[0].message
    assert isinstance(facts, GimbalLockWarning)
    assert (facts.count, facts.total, facts.zeroed) == (1, 3, "bank")
    assert_allclose(angles[0], [50, 90, 0], atol=1e-12)  # Baker: bank = 0
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        quaternion_to_euler(q, "baker", warn=False)


# --- shapes ----------------------------------------------------------------------------------


def test_leading_axes_and_single_values(rng) -> None:
    q = rng.normal(size=(2, 3, 4))
    assert quaternion_to_matrix(q).shape == (2, 3, 3, 3)
    assert quaternion_to_euler(q).shape == (2, 3, 3)
    R = quaternion_to_matrix(q)
    assert matrix_to_quaternion(R).shape == (2, 3, 4)
    assert euler_to_quaternion(np.zeros((5, 1, 3))).shape == (5, 1, 4)
    assert quaternion_to_matrix([0, 0, 0, 1]).shape == (3, 3)
    assert matrix_to_quaternion(np.eye(3)).shape == (4,)
    assert quaternion_to_matrix(np.zeros((0, 4))).shape == (0, 3, 3)
    assert matrix_to_quaternion(np.zeros((0, 3, 3))).shape == (0, 4)
    assert quaternion_to_euler(np.zeros((0, 4))).shape == (0, 3)


def test_repair_uses_the_nearest_rotation(rng) -> None:
    M = rot_x(0.3) + 1e-4 * rng.normal(size=(3, 3))
    with pytest.raises(ValueError, match="pass repair=True"):
        matrix_to_quaternion(M)
    Q = np.linalg.svd(M)[0] @ np.linalg.svd(M)[2]
    assert_allclose(matrix_to_quaternion(M, repair=True), matrix_to_quaternion(Q), atol=1e-15)


# --- properties --------------------------------------------------------------------------------

quaternions = hnp.arrays(
    np.float64,
    st.tuples(st.integers(1, 6), st.just(4)),
    elements=st.one_of(
        st.floats(-1.0, 1.0, allow_nan=False),
        st.sampled_from([0.0, 1e-300, -1e-200, 1e-16, -1e-8]),
    ),
).filter(lambda q: bool(np.all(np.abs(q).max(axis=-1) > 0)))
# for products and scalings, which would underflow a quaternion made of tiny components to 0
sizable = quaternions.filter(lambda q: bool(np.all(np.abs(q).max(axis=-1) > 1e-3)))
checked = settings(max_examples=examples(150), deadline=None)


@checked
@given(quaternions)
def test_double_cover_q_and_minus_q_give_the_same_matrix(q: np.ndarray) -> None:
    assert_array_equal(quaternion_to_matrix(-q), quaternion_to_matrix(q))


@checked
@given(sizable, st.sampled_from([2.0**-600, 0.5, 3.0, 1e100, 2.0**600]))
def test_any_length_gives_the_same_rotation(q: np.ndarray, scale: float) -> None:
    assert_allclose(quaternion_to_matrix(scale * q), quaternion_to_matrix(q), rtol=0, atol=4 * EPS)


@checked
@given(sizable, sizable)
def test_the_product_of_quaternions_is_the_product_of_matrices(p, q) -> None:
    count = min(len(p), len(q))
    p, q = p[:count], q[:count]
    product = quaternion_to_matrix(hamilton(p, q), scalar_first=True)
    both = quaternion_to_matrix(p, scalar_first=True) @ quaternion_to_matrix(q, scalar_first=True)
    assert_allclose(product, both, rtol=0, atol=1e-14)


@checked
@given(quaternions)
def test_matrix_to_quaternion_is_unit_canonical_and_gives_back_the_rotation(q) -> None:
    R = quaternion_to_matrix(q)
    back = matrix_to_quaternion(R)
    assert_allclose(np.linalg.norm(back, axis=-1), 1.0, rtol=0, atol=2 * EPS)
    assert np.all(back[:, 3] >= 0.0)
    assert_allclose(quaternion_to_matrix(back), R, rtol=0, atol=1e-15)
