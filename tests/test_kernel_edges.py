"""Edges of the numeric kernels and of the argument checks that other tests pass over.

Each test here pins down a behaviour that a deliberate small change to the library (a mutant,
see ``tests/mutation/README.md``) would alter while every other test still passed: which matrix
a refusal names, which reason it gives, what happens at a scale or a size where two branches
meet. The oracles are typed in (singular values of diagonal matrices, indices counted by hand),
or SciPy's ``Rotation``.
"""

from __future__ import annotations

import warnings
from fractions import Fraction

import numpy as np
import pytest
from numpy.testing import assert_allclose, assert_array_equal
from scipy.spatial.transform import Rotation

from eulerlib import (
    ALL_SEQUENCES,
    GIMBAL_LOCK_TOLERANCE,
    Convention,
    angle_between,
    axis_angle_to_matrix,
    euler_to_matrix,
    euler_to_quaternion,
    get_convention,
    matrix_to_euler,
    matrix_to_rotvec,
    quaternion_to_matrix,
    rot_x,
    rot_y,
    rot_z,
    rotvec_to_matrix,
    slerp,
)
from eulerlib._blocks import BLOCK_SIZE
from eulerlib._euler_kernels import intrinsic_angles, lock_distance
from eulerlib._trig import quarter_turns, sin_cos
from eulerlib._validation import as_float_array, matrix_entries

# --- repairing a matrix that is too far from a rotation ---------------------------------------


def stack_with(bad: np.ndarray, shape: tuple[int, ...], index: tuple[int, ...]) -> np.ndarray:
    """Identity matrices of leading shape ``shape``, with ``bad`` at ``index``."""
    R = np.broadcast_to(np.eye(3), (*shape, 3, 3)).copy()
    R[index] = bad
    return R


def test_one_matrix_too_far_in_its_smallest_singular_value_only() -> None:
    """Singular values (1, 1, 0.5): refused as too far, not as singular, for one matrix."""
    with pytest.raises(ValueError, match="too far") as info:
        matrix_to_euler(np.diag([1.0, 1.0, 0.5]), "ZYX", repair=True)
    assert "singular (" not in str(info.value)
    assert str(info.value).startswith("R ")


@pytest.mark.parametrize(
    ("shape", "index"), [((2, 3), (1, 2)), ((4,), (3,)), ((2, BLOCK_SIZE), (1, 1))]
)
def test_the_refusal_names_the_index_of_the_matrix(shape, index) -> None:
    """The flat index is the block's offset plus the place in the block, as a tuple."""
    R = stack_with(np.diag([1.0, 1.0, 0.5]), shape, index)
    with pytest.raises(ValueError, match=rf"^R at index \({', '.join(map(str, index))},?\) "):
        matrix_to_euler(R, "ZYX", repair=True)
    R = stack_with(np.diag([1.0, 1.0, -1.0]), shape, index)  # nearest to a reflection
    with pytest.raises(ValueError, match=rf"^R at index \({', '.join(map(str, index))},?\) "):
        matrix_to_euler(R, "ZYX", repair=True)


@pytest.mark.parametrize(
    ("singular_values", "rank"),
    [
        ([1.0, 1.0, 0.0], 2),
        ([1.0, 1.0, 1e-12], 2),  # exactly 1e-12 times the largest: still singular
        ([100.0, 1.0, 1e-12], 2),  # 1e-12 ≤ 1e-12 · 100: singular, relative to the largest
        ([100.0, 1.0, 5e-12], 2),  # relative to the largest, not to the middle one
        ([1e-3, 1e-3, 1e-16], 2),  # a small matrix: relative to its own largest value
        ([1.0, 1e-13, 0.0], 1),  # 1e-13 < 1e-12 · 1: counted as zero
        ([0.0, 0.0, 0.0], 0),
    ],
)
def test_singular_matrices_are_refused_with_their_rank(singular_values, rank) -> None:
    with pytest.raises(ValueError, match=rf"singular \(rank {rank}, singular values"):
        matrix_to_euler(np.diag(singular_values), "ZYX", repair=True)


def test_the_refusal_lists_the_singular_values() -> None:
    with pytest.raises(ValueError, match=r"singular values 2, 1, 0\)"):
        matrix_to_euler(np.diag([1.0, 0.0, 2.0]), "ZYX", repair=True)
    with pytest.raises(ValueError, match=r"singular values \(1, 1, 0.5\)"):
        matrix_to_euler(np.diag([1.0, 0.5, 1.0]), "ZYX", repair=True)


@pytest.mark.parametrize(
    "singular_values",
    [[1.0, 1.0, 0.5], [100.0, 1.0, 2e-10], [3.0, 1, 1], [1e-3, 1e-3, 1e-14]],
)
def test_matrices_far_but_not_singular_are_refused_as_too_far(singular_values) -> None:
    with pytest.raises(ValueError, match="too far") as info:
        matrix_to_euler(np.diag(singular_values), "ZYX", repair=True)
    assert "singular (" not in str(info.value)


def test_repair_near_a_rotation_gives_the_rotation(rng) -> None:
    R = Rotation.random(5, rng=rng).as_matrix()
    noisy = R + 1e-9 * rng.normal(size=R.shape)
    assert_allclose(matrix_to_euler(noisy, "ZYX", repair=True), matrix_to_euler(R, "ZYX"),
                    rtol=0, atol=1e-8)  # fmt: skip


# --- lock at the boundary of the tolerance ----------------------------------------------------


@pytest.mark.parametrize("seq", ["zxz", "xyz"])
def test_a_distance_equal_to_the_tolerance_is_locked(seq) -> None:
    """Exactly at lock the distance is exactly 0: locked with a tolerance of 0 as well."""
    parsed = get_convention(seq).parsed
    middle = 0.0 if parsed.proper else 90.0
    entries = matrix_entries(euler_to_matrix([[10.0, middle, 20.0]], seq, degrees=True))
    assert_array_equal(lock_distance(entries, parsed), [0.0])
    for zero_first in (True, False):
        _, locked = intrinsic_angles(entries, parsed, zero_first, 0.0)
        assert_array_equal(locked, [True])


# --- quarter turns in degrees -----------------------------------------------------------------


def test_quarter_turns_leave_a_rest_of_at_most_45_degrees() -> None:
    """``angle = k · 90° + r`` modulo 360° with ``|r| ≤ 45°``, as documented."""
    angles = np.concatenate([np.arange(-720.0, 720.5, 0.5), [44.9, 45.4, 134.6, -45.4, 1e20]])
    quarter, rest = quarter_turns(angles)
    rest_degrees = np.degrees(rest)
    assert np.all(np.abs(rest_degrees) <= 45.0 + 1e-12)
    assert np.all((quarter == np.round(quarter)) & (np.abs(quarter) <= 4))
    for angle, k, r in zip(angles, quarter, rest_degrees, strict=True):
        # the exact remainder modulo 360, as a fraction
        gap = (Fraction(float(angle)) - 90 * int(k) - Fraction(float(r))) % 360
        assert min(gap, 360 - gap) <= 1e-9, angle


# --- which angle gives way at lock, for every sequence ----------------------------------------


def with_lock_zeroes(seq: str, which: str) -> Convention:
    """The bare sequence as a convention whose ``which`` written angle is 0 at lock."""
    return get_convention(seq)._replace(lock_zeroes=which)


@pytest.mark.parametrize("which", ["first", "third"])
@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_either_angle_may_give_way_away_from_lock_the_angles_are_scipys(seq, which, rng) -> None:
    rotation = Rotation.random(200, rng=rng)
    got = matrix_to_euler(rotation.as_matrix(), with_lock_zeroes(seq, which))
    assert_allclose(got, rotation.as_euler(seq), rtol=0, atol=1e-12)


@pytest.mark.parametrize("which", ["first", "third"])
@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_either_angle_may_give_way_at_lock(seq, which, rng) -> None:
    """At lock the chosen written angle is 0 and the three angles rebuild the matrix (SciPy)."""
    proper = seq[0].lower() == seq[2].lower()
    angles = rng.uniform(-3.0, 3.0, (6, 3))
    d = GIMBAL_LOCK_TOLERANCE / 4  # near lock, within the tolerance
    angles[:, 1] = [0.0, np.pi, 0.0, np.pi, d, np.pi - d] if proper else (
        [np.pi / 2, -np.pi / 2, np.pi / 2, -np.pi / 2, np.pi / 2 - d, d - np.pi / 2]
    )  # fmt: skip
    R = Rotation.from_euler(seq, angles).as_matrix()
    got = matrix_to_euler(R, with_lock_zeroes(seq, which), warn=False)
    assert_array_equal(got[:, 0 if which == "first" else 2], 0.0)
    assert_allclose(Rotation.from_euler(seq, got).as_matrix(), R, rtol=0, atol=1e-14)


# --- no negative zeros ------------------------------------------------------------------------

RIGHT_ANGLES = np.array([0.0, 90.0, 180.0, 270.0, 360.0, 450.0, -90.0, -180.0, -270.0, -360.0])


def assert_no_negative_zero(values: np.ndarray) -> None:
    values = np.asarray(values)
    assert not np.signbit(values[values == 0.0]).any()


def test_sines_and_cosines_of_right_angles_have_no_negative_zeros() -> None:
    s, c = sin_cos(RIGHT_ANGLES, degrees=True)
    assert_array_equal(s, [0, 1, 0, -1, 0, 1, -1, 0, 1, 0])  # typed in
    assert_array_equal(c, [1, 0, -1, 0, 1, 0, 0, -1, 0, 1])
    assert_no_negative_zero(s)
    assert_no_negative_zero(c)


@pytest.mark.parametrize("function", [rot_x, rot_y, rot_z])
def test_elementary_rotations_of_right_angles_have_no_negative_zeros(function) -> None:
    assert_no_negative_zero(function(RIGHT_ANGLES, degrees=True))


def test_quaternions_made_canonical_have_no_negative_zeros() -> None:
    """270° about z is (−√½, 0, 0, √½) before the sign is chosen: its zeros stay +0."""
    grid = np.array(np.meshgrid(RIGHT_ANGLES, RIGHT_ANGLES, [0.0, 90.0, 270.0])).reshape(3, -1).T
    for seq in ("ZYX", "zxz", "XYZ"):
        assert_no_negative_zero(euler_to_quaternion(grid, seq, degrees=True))
    q = euler_to_quaternion([270.0, 0.0, 0.0], "ZYX", degrees=True)
    assert_allclose(q, [0.0, 0.0, -np.sqrt(0.5), np.sqrt(0.5)], rtol=0, atol=1e-16)


def test_matrices_of_quaternions_with_zeros_have_no_negative_zeros() -> None:
    """Every quaternion with components in {−1, 0, 1}: a product such as 0 · (−1) is −0.0."""
    grid = np.array(np.meshgrid(*[[-1.0, 0.0, 1.0]] * 4)).reshape(4, -1).T
    grid = grid[np.any(grid != 0.0, axis=1)]
    R = quaternion_to_matrix(grid)
    assert_no_negative_zero(R)
    assert_allclose(R, Rotation.from_quat(grid).as_matrix(), rtol=0, atol=4e-16)


# --- vectors of very different sizes in one block ---------------------------------------------


def test_axes_and_quaternions_of_very_different_sizes_in_one_call() -> None:
    """Each vector is scaled by its own power of two: a huge one next to a tiny one in the same
    block changes neither (SciPy, on the same directions at ordinary size)."""
    scales = np.array([2.0**1000, 1.0, 2.0**-1000, 2.0**-1070])[:, None]  # exact, subnormal last
    axes = np.array([3.0, -1.0, 4.0]) * scales
    angle = 0.75
    expected = Rotation.from_rotvec(np.array([3.0, -1.0, 4.0]) / np.sqrt(26.0) * angle)
    R = axis_angle_to_matrix(axes, angle)
    assert_allclose(R, np.broadcast_to(expected.as_matrix(), R.shape), rtol=0, atol=4e-16)
    q = np.concatenate([np.array([0.5, -0.5, 0.5, 0.5]) * scales[:3], [[0.0, 0.0, 5e-324, 0.0]]])
    R = quaternion_to_matrix(q)
    assert_allclose(R[:3], np.broadcast_to(Rotation.from_quat([0.5, -0.5, 0.5, 0.5])
                    .as_matrix(), (3, 3, 3)), rtol=0, atol=4e-16)  # fmt: skip
    assert_allclose(R[3], np.diag([-1.0, -1.0, 1.0]), rtol=0, atol=0)  # a half turn about z


def test_huge_vectors_give_no_overflow_warning() -> None:
    """The squares of a huge vector overflow on the way; that is handled, not reported."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        R = axis_angle_to_matrix([3e300, 0.0, 4e300], 0.5)
        v = matrix_to_rotvec(rotvec_to_matrix([0.0, 0.0, 1e200], degrees=True), degrees=True)
        q = quaternion_to_matrix([1e300, 1e300, 0.0, 0.0])
    expected = Rotation.from_rotvec(np.array([0.6, 0.0, 0.8]) * 0.5).as_matrix()
    assert_allclose(R, expected, rtol=0, atol=4e-16)
    turn = float(Fraction(1e200) % 360)  # exact, then into (-180, 180]
    assert_allclose(v, [0.0, 0.0, turn - 360.0 if turn > 180.0 else turn], rtol=0, atol=1e-12)
    assert_allclose(q, Rotation.from_quat([1.0, 1.0, 0.0, 0.0]).as_matrix(), rtol=0, atol=4e-16)


# --- broadcasting across several blocks -------------------------------------------------------


def test_broadcast_operands_are_gathered_right_in_every_block(rng) -> None:
    """A (2, 1) operand against an (n,) one, with 2 n results over several blocks."""
    n = BLOCK_SIZE + 7
    axes = rng.normal(size=(2, 1, 3))
    angles = rng.uniform(-3.0, 3.0, n)
    R = axis_angle_to_matrix(axes, angles)
    unit = axes / np.linalg.norm(axes, axis=-1, keepdims=True)
    expected = Rotation.from_rotvec((unit * angles[:, None]).reshape(-1, 3)).as_matrix()
    assert np.abs(R - expected.reshape(2, n, 3, 3)).max() <= 8e-16


# --- repairing stacks of matrices, and what the rotation check looks at -----------------------


def test_repair_of_a_stack_repairs_every_matrix(rng) -> None:
    """Six drifted matrices in a (2, 3) stack: each is replaced by its nearest rotation."""
    A = Rotation.random(6, rng=rng).as_matrix().reshape(2, 3, 3, 3)
    B = Rotation.random(6, rng=rng).as_matrix().reshape(2, 3, 3, 3)
    drift = 1e-7 * rng.normal(size=(2, 2, 3, 3, 3))
    expected = angle_between(A, B)
    assert_allclose(angle_between(A + drift[0], B + drift[1], repair=True), expected, atol=1e-6)
    halfway = slerp(A + drift[0], B + drift[1], 0.5, repair=True)
    assert_allclose(halfway, slerp(A, B, 0.5), rtol=0, atol=1e-6)


def test_repair_of_a_stack_names_the_index_of_a_refused_matrix() -> None:
    B = np.broadcast_to(np.eye(3), (2, 3, 3, 3))
    A = stack_with(np.diag([1.0, 1.0, 0.5]), (2, 3), (1, 2))
    with pytest.raises(ValueError, match=r"^R0 at index \(1, 2\) "):
        angle_between(A, B, repair=True)
    with pytest.raises(ValueError, match=r"^R1 at index \(1, 2\) "):
        slerp(B, A, 0.5, repair=True)


@pytest.mark.parametrize(
    "R",
    [
        np.diag([1.0, 1.001, 1 / 1.001]),  # rows 1 and 2 not unit, determinant 1
        np.diag([1 / 1.001, 1.0, 1.001]),
        # rows 0 and 2 at 89.94° from each other, all rows unit, determinant 1 − 5e-7
        np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [np.sin(1e-3), 0.0, np.cos(1e-3)]]),
        np.array([[1.0, 0.0, 0.0], [np.sin(1e-3), np.cos(1e-3), 0.0], [0.0, 0.0, 1.0]]),
        np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, np.sin(1e-3), np.cos(1e-3)]]),
    ],
)
def test_every_row_and_every_pair_of_rows_is_checked(R) -> None:
    """Not a rotation by 1e-3 in one place only; the determinant alone would pass it."""
    with pytest.raises(ValueError, match=r"^R is not a rotation matrix: max \|R Rᵀ − I\| = 0.00"):
        matrix_to_euler(R, "ZYX", atol=1e-5)


def test_a_singular_matrix_is_not_called_a_reflection() -> None:
    """Determinant exactly 0: refused as not a rotation, not as a reflection (det < 0)."""
    for R in (np.zeros((3, 3)), np.diag([1.0, 1.0, 0.0])):
        with pytest.raises(ValueError, match=r"^R is not a rotation matrix"):
            matrix_to_euler(R, "ZYX")


def test_a_large_tolerance_still_checks_the_determinant() -> None:
    """1.125 I: max |R Rᵀ − I| = 0.265625 and det − 1 = 0.423828125, both exact."""
    R = stack_with(1.125 * np.eye(3), (2, 2), (0, 1))
    R[1, 0] = 1.125 * np.eye(3)
    with pytest.raises(
        ValueError,
        match=r"^R at index \(0, 1\) has determinant 1.42, which differs from 1 by 0.424",
    ):
        matrix_to_euler(R, "ZYX", atol=0.3)
    # a deviation equal to the tolerance is within it, for both checks
    matrix_to_euler(R, "ZYX", atol=0.423828125, warn=False)
    matrix_to_euler(np.diag([1.125, 1.0, 0.875]), "ZYX", atol=0.265625)
    with pytest.raises(ValueError, match=r"^R is not a rotation matrix"):
        matrix_to_euler(np.diag([1.125, 1.0, 0.875]), "ZYX", atol=0.265624)


# --- finiteness of large inputs ---------------------------------------------------------------


@pytest.mark.parametrize("flat_index", [0, 65535, 65536, 65537, 3 * 65536 + 5, 4 * 65536 - 1])
@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_the_first_bad_number_of_a_large_input_is_found(flat_index, bad) -> None:
    """The search runs in blocks of 65536 numbers: a bad one is found in any of them."""
    angles = np.zeros((65536 + 22000, 3))
    angles.reshape(-1)[flat_index] = bad
    later = min(flat_index + 70000, angles.size - 1)
    if later != flat_index:
        angles.reshape(-1)[later] = np.nan  # only the first one is named
    row, column = divmod(flat_index, 3)
    with pytest.raises(ValueError, match=rf"^angles must be finite, got .* at index \({row}, "
                       rf"{column}\)$"):  # fmt: skip
        euler_to_matrix(angles, "ZYX")


def test_finite_numbers_whose_sum_overflows_are_finite() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        R = euler_to_matrix([[1.7e308, 1.7e308, 1.7e308], [-1.7e308, 0.0, 1.7e308]], "ZYX")
    assert np.all(np.isfinite(R))


def test_an_infinity_minus_an_infinity_is_found_without_a_warning() -> None:
    """inf + (−inf) in the quick sum is an invalid operation; the check keeps it quiet."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(ValueError, match=r"^angles must be finite, got inf at index \(0, 1\)$"):
            euler_to_matrix([[0.0, np.inf, -np.inf]], "ZYX")


# --- the reasons given in full -----------------------------------------------------------------


def test_a_reflection_is_refused_with_the_whole_reason() -> None:
    with pytest.raises(
        ValueError,
        match=r"^R is closest to a reflection \(determinant < 0\), so it cannot be repaired into "
        r"a rotation$",
    ):
        matrix_to_euler(np.diag([1.0, 1.0, -1.0]), "ZYX", repair=True)


@pytest.mark.parametrize(
    ("call", "start"),
    [
        (lambda: axis_angle_to_matrix([0.0, 0.0, 0.0], 1.0), "axis is zero: a rotation axis"),
        (lambda: quaternion_to_matrix([0.0, 0.0, 0.0, 0.0]), "q is zero: a quaternion"),
    ],
)
def test_a_zero_vector_is_refused_with_the_whole_reason(call, start) -> None:
    with pytest.raises(ValueError) as caught:
        call()
    reason = " cannot be normalized, since a zero vector has no direction"
    assert str(caught.value) == start + reason


# --- how a number array is read ---------------------------------------------------------------


@pytest.mark.parametrize("lead", [(5,), (2, 4), (2, 1, 3)])
def test_the_entries_of_a_stack_are_laid_out_row_by_row(lead) -> None:
    """Row ``3 i + j`` holds ``R[..., i, j]``, for a stack of any number of leading axes."""
    R = np.arange(9 * int(np.prod(lead)), dtype=np.float64).reshape(*lead, 3, 3)
    entries = matrix_entries(R)
    assert entries.shape == (9, *lead)
    assert entries.flags.c_contiguous
    for i in range(3):
        for j in range(3):
            assert_array_equal(entries[3 * i + j], R[..., i, j])


def test_a_float64_array_is_checked_in_place_not_copied() -> None:
    """The docstring's promise: a copy only when the dtype changes (a million matrices stay one)."""
    angles = np.arange(12.0).reshape(4, 3)
    assert np.shares_memory(as_float_array(angles, "angles"), angles)
    single = angles.astype(np.float32)
    read = as_float_array(single, "angles")
    assert read.dtype == np.float64
    assert not np.shares_memory(read, single)
    assert_array_equal(read, angles)


def test_the_refusal_of_a_masked_array_says_how_to_drop_the_mask() -> None:
    masked = np.ma.masked_array([1.0, 2.0, 3.0], mask=[False, True, False])
    with pytest.raises(TypeError) as caught:
        euler_to_matrix(masked, "ZYX")
    message = str(caught.value)
    for advice in ("angles.filled(...)", "angles.compressed()", "indexing with ~mask"):
        assert advice in message


@pytest.mark.parametrize(
    ("value", "dtype"),
    [
        (np.array(["2026-12-01"] * 3, dtype="datetime64[D]"), "datetime64[D]"),
        (np.array([1, 2, 3], dtype="timedelta64[s]"), "timedelta64[s]"),
        (np.zeros(3, dtype=[("a", np.float64)]), "[('a', '<f8')]"),
    ],
)
def test_an_array_of_times_or_records_is_refused_with_its_dtype(value, dtype) -> None:
    with pytest.raises(TypeError, match=r"^angles must be real numbers, got dtype (.*)$") as caught:
        euler_to_matrix(value, "ZYX")
    assert str(caught.value) == f"angles must be real numbers, got dtype {dtype}"


class _OverflowingArrayLike:
    """An array-like whose conversion overflows, as a list mixing floats and a huge int did in
    older NumPy and may in other array libraries."""

    def __array__(self, dtype: object = None, copy: object = None) -> np.ndarray:
        raise OverflowError("int too large to convert to float")


def test_an_overflow_while_reading_an_array_names_the_argument() -> None:
    with pytest.raises(ValueError, match=r"^angles holds a number too large for a float"):
        euler_to_matrix(_OverflowingArrayLike(), "ZYX")


# --- the keywords of the rotation check are named when wrong ----------------------------------


@pytest.mark.parametrize(
    "call",
    [
        lambda **kw: matrix_to_euler(np.eye(3), "ZYX", **kw),
        lambda **kw: angle_between(np.eye(3), np.eye(3), **kw),
        lambda **kw: slerp(np.eye(3), np.eye(3), 0.5, **kw),
    ],
)
def test_each_keyword_of_the_rotation_check_is_named(call) -> None:
    for keyword in ("validate", "repair"):
        with pytest.raises(
            TypeError, match=rf"^{keyword} must be True or False, got 'yes' \(str\)$"
        ):
            call(**{keyword: "yes"})
    with pytest.raises(TypeError, match=r"^atol must be a real number, got 'small' \(str\)$"):
        call(atol="small")
    with pytest.raises(ValueError, match=r"^atol must be a finite number ≥ 0, got -1e-09$"):
        call(atol=-1e-9)


def test_a_tolerance_may_be_a_0d_array_but_not_a_longer_one() -> None:
    R = np.eye(3)
    for atol in (np.array(1e-6), np.array(0), np.float32(1e-6), np.int64(0)):
        assert_array_equal(matrix_to_euler(R, "ZYX", atol=atol, warn=False), [0.0, 0.0, 0.0])
    for atol in (np.array([1e-6]), np.array([[0.0]])):
        with pytest.raises(TypeError, match=r"^atol must be a real number, got array"):
            matrix_to_euler(R, "ZYX", atol=atol)
