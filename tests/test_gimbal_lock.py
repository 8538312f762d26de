"""Gimbal lock and the accuracy next to it: the headline claims of the library.

* Round trip ``R → matrix_to_euler → euler_to_matrix`` reproduces ``R`` to 1e-14 in every
  entry, for all 24 conventions: random rotations, exactly at lock, 1e-16 … 1e-3 rad from it,
  and matrices that carry ordinary rounding noise.
* Gimbal lock is reported by one ``GimbalLockWarning`` per call, never away from lock, and not
  at all with ``warn=False``; ``gimbal_lock_status`` gives the distance from lock as data.
* The formulas as printed in the sources (Rose's exact ``r31 == 1`` test with ``asin``, Baker's
  ``0.998`` cut-off), typed in here for comparison only, fail where eulerlib does not.

The test matrices are built by SciPy (``Rotation.from_euler``), not by the code under test.
"""

import re
import warnings

import numpy as np
import pytest
from numpy.testing import assert_allclose, assert_array_equal
from scipy.spatial.transform import Rotation

from eulerlib import (
    ALL_SEQUENCES,
    GIMBAL_LOCK_TOLERANCE,
    GimbalLockWarning,
    euler_to_matrix,
    gimbal_lock_status,
    heading_attitude_bank_to_matrix,
    matrix_to_euler,
    matrix_to_heading_attitude_bank,
    matrix_to_yaw_pitch_roll,
    yaw_pitch_roll_to_matrix,
)

ROUND_TRIP_ATOL = 1e-14
DISTANCES = 10.0 ** np.arange(-16, -2)  # 1e-16, 1e-15, …, 1e-3 rad


def is_proper(seq: str) -> bool:
    return seq[0].lower() == seq[2].lower()


def singular_values(seq: str) -> tuple[float, float]:
    return (0.0, np.pi) if is_proper(seq) else (np.pi / 2, -np.pi / 2)


def round_trip_error(R: np.ndarray, seq: str) -> float:
    """Largest entry of ``|euler_to_matrix(matrix_to_euler(R)) − R|``."""
    angles = matrix_to_euler(R, seq, warn=False)
    return float(np.abs(euler_to_matrix(angles, seq) - R).max())


def scipy_matrices(seq: str, middle: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """SciPy's matrices for the given middle angles and random first and third angles."""
    angles = rng.uniform(-np.pi, np.pi, (middle.size, 3))
    angles[:, 1] = middle
    return Rotation.from_euler(seq, angles).as_matrix()


def near_lock_middles(seq: str, distance: float) -> np.ndarray:
    """Middle angles at ``distance`` from each singular value, on the inner side."""
    if is_proper(seq):
        return np.array([distance, np.pi - distance])
    return np.array([np.pi / 2 - distance, -np.pi / 2 + distance])


def with_rounding_noise(R: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """``Q Qᵀ R`` for random rotations Q: R with a few ulps of ordinary rounding noise."""
    Q = Rotation.random(R.shape[0], rng=rng).as_matrix()
    return Q @ np.swapaxes(Q, -1, -2) @ R


def elementary(axis: str, angle: np.ndarray) -> np.ndarray:
    """Right-handed rotations about one axis, typed in; shape ``(n, 3, 3)``."""
    c, s = np.cos(angle), np.sin(angle)
    zero, one = np.zeros_like(angle), np.ones_like(angle)
    rows = {
        "x": [[one, zero, zero], [zero, c, -s], [zero, s, c]],
        "y": [[c, zero, s], [zero, one, zero], [-s, zero, c]],
        "z": [[c, -s, zero], [s, c, zero], [zero, zero, one]],
    }[axis.lower()]
    return np.stack([np.stack(row, axis=-1) for row in rows], axis=-2)


def as_product(seq: str, angles: np.ndarray) -> np.ndarray:
    """The rotation built as a product of three elementary matrices.

    Thanks to the exact zeros of the elementary matrices, every entry keeps its relative
    accuracy, so a tiny entry such as cos(π/2 − d) is known to a few ulps of itself.
    """
    factors = [elementary(axis, angles[:, n]) for n, axis in enumerate(seq)]
    if seq.isupper():  # intrinsic: R = R1 R2 R3
        return factors[0] @ factors[1] @ factors[2]
    return factors[2] @ factors[1] @ factors[0]  # extrinsic: R = R3 R2 R1


# --- the round trip, 1e-14 in every entry --------------------------------------------------


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_round_trip_random_rotations(seq, rng):
    R = Rotation.random(5000, rng=rng).as_matrix()
    assert round_trip_error(R, seq) <= ROUND_TRIP_ATOL


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_round_trip_exactly_at_lock(seq, rng):
    for singular in singular_values(seq):
        R = scipy_matrices(seq, np.full(500, singular), rng)
        assert round_trip_error(R, seq) <= ROUND_TRIP_ATOL
        assert round_trip_error(with_rounding_noise(R, rng), seq) <= ROUND_TRIP_ATOL
    # lock matrices with exact zeros and ones where a quarter turn puts them
    angles = np.radians(rng.integers(-180, 181, (200, 3)).astype(float))
    angles[:, 1] = rng.choice(singular_values(seq), 200)
    R = np.round(as_product(seq, angles), 15) + 0.0
    intrinsic = seq if seq.isupper() else seq[::-1].upper()
    first, last = ("XYZ".index(intrinsic[0]), "XYZ".index(intrinsic[2]))
    assert_array_equal(np.abs(R[:, first, last]), 1.0)  # the sine or cosine of the middle angle
    assert round_trip_error(R, seq) <= ROUND_TRIP_ATOL


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
@pytest.mark.parametrize("distance", DISTANCES, ids=lambda d: f"{d:.0e}")
def test_round_trip_near_lock(seq, distance, rng):
    middle = np.repeat(near_lock_middles(seq, distance), 100)
    R = scipy_matrices(seq, middle, rng)
    assert round_trip_error(R, seq) <= ROUND_TRIP_ATOL
    assert round_trip_error(with_rounding_noise(R, rng), seq) <= ROUND_TRIP_ATOL


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_round_trip_products_of_rotations(seq, rng):
    n = 600
    angles = rng.uniform(-np.pi, np.pi, (n, 3))
    lock = rng.choice(singular_values(seq), n)
    near = lock + rng.choice([-1, 1], n) * 10.0 ** rng.uniform(-16, -3, n)
    angles[:, 1] = np.where(rng.random(n) < 0.5, lock, near)
    R = as_product(seq, angles)
    # spin about a random axis and back, a few times: more ordinary rounding
    for _ in range(3):
        S = Rotation.random(n, rng=rng).as_matrix()
        R = S @ (np.swapaxes(S, -1, -2) @ R)
    assert round_trip_error(R, seq) <= ROUND_TRIP_ATOL


@pytest.mark.parametrize("pole", [np.pi / 2, -np.pi / 2])
def test_round_trip_named_functions(pole, rng):
    n = 400
    middle = pole - np.sign(pole) * np.concatenate(
        [np.zeros(n // 2), 10.0 ** rng.uniform(-16, -3, n // 2)]
    )
    zyx = with_rounding_noise(scipy_matrices("ZYX", middle, rng), rng)
    yaw, pitch, roll = matrix_to_yaw_pitch_roll(zyx, warn=False)
    assert np.abs(yaw_pitch_roll_to_matrix(yaw, pitch, roll) - zyx).max() <= ROUND_TRIP_ATOL
    yzx = with_rounding_noise(scipy_matrices("YZX", middle, rng), rng)
    heading, attitude, bank = matrix_to_heading_attitude_bank(yzx, warn=False)
    rebuilt = heading_attitude_bank_to_matrix(heading, attitude, bank)
    assert np.abs(rebuilt - yzx).max() <= ROUND_TRIP_ATOL


# --- the warning ----------------------------------------------------------------------------


def lock_batch(seq: str, rng: np.random.Generator) -> np.ndarray:
    """Five rotations, two of them locked (one at each singular value)."""
    middle = np.array([0.7, singular_values(seq)[0], 1.2, singular_values(seq)[1], 2.0])
    if not is_proper(seq):
        middle[[0, 2, 4]] -= 1.5
    return scipy_matrices(seq, middle, rng)


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_one_warning_per_call_at_lock(seq, rng):
    R = lock_batch(seq, rng)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        matrix_to_euler(R, seq)
    assert len(caught) == 1
    assert caught[0].category is GimbalLockWarning
    assert issubclass(GimbalLockWarning, UserWarning)
    message = str(caught[0].message)
    assert "2 of 5" in message
    assert repr(seq) in message
    assert caught[0].filename == __file__  # stacklevel points at the caller


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_warning_at_both_poles_reads_as_one_sentence(seq, rng):
    # Each pole's combination is named once with its pole, and the one semicolon parts what is
    # defined from what was chosen.
    with pytest.warns(GimbalLockWarning) as record:
        matrix_to_euler(lock_batch(seq, rng), seq)
    facts = record[0].message
    message = str(facts)
    assert len(facts.combinations) == 2
    assert "\n" not in message
    assert message.count(";") == 1
    defined = message.split(";")[0]
    for pole, words in facts.combinations.items():
        assert defined.count(f"{words} at {pole}°") == 1


@pytest.mark.parametrize("seq", ["ZYX", "xyz", "ZXZ", "yzy"])
def test_warning_names_the_zeroed_angle(seq, rng):
    with pytest.warns(GimbalLockWarning, match=r"\(angle \d\) was set to 0") as record:
        angles = matrix_to_euler(lock_batch(seq, rng)[1], seq)
    zeroed = int(re.search(r"\(angle (\d)\) was set to 0", str(record[0].message)).group(1))
    assert angles[zeroed - 1] == 0.0
    assert zeroed == (1 if seq.isupper() else 3)
    assert record[0].message.zeroed_position == zeroed - 1


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_no_warning_away_from_lock(seq, rng):
    R = Rotation.random(1000, rng=rng).as_matrix()
    R = np.concatenate([R, scipy_matrices(seq, near_lock_middles(seq, 1e-13), rng)])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        matrix_to_euler(R, seq)


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_warn_false_silences(seq, rng):
    R = lock_batch(seq, rng)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        matrix_to_euler(R, seq, warn=False)
        matrix_to_yaw_pitch_roll(lock_batch("ZYX", rng), warn=False)
        matrix_to_heading_attitude_bank(lock_batch("YZX", rng), warn=False)


def test_named_functions_warn_once(rng):
    for function, seq in (
        (matrix_to_yaw_pitch_roll, "ZYX"),
        (matrix_to_heading_attitude_bank, "YZX"),
    ):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            function(lock_batch(seq, rng))
            function(Rotation.random(10, rng=rng).as_matrix())  # no lock, no warning
        assert [w.category for w in caught] == [GimbalLockWarning]


# --- gimbal lock as data ---------------------------------------------------------------------

# The float nearest π/2 is 6.1e-17 below π/2; the float nearest π is 1.2e-16 below π.
HALF_PI_GAP = 6.123233995736766e-17
PI_GAP = 1.2246467991473532e-16


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
@pytest.mark.parametrize("distance", DISTANCES, ids=lambda d: f"{d:.0e}")
def test_status_distance(seq, distance, rng):
    middle = near_lock_middles(seq, distance)
    if is_proper(seq):
        known = np.array([middle[0], (np.pi - middle[1]) + PI_GAP])
    else:  # π/2 − (π/2 − d) is exact in floating point (Sterbenz), the gap is added
        known = (np.pi / 2 - np.abs(middle)) + HALF_PI_GAP
    angles = rng.uniform(-np.pi, np.pi, (2, 3))
    angles[:, 1] = middle
    R = as_product(seq, angles)
    locked, got = gimbal_lock_status(R, seq)
    assert_allclose(got, known, rtol=1e-12)
    assert_array_equal(locked, known <= GIMBAL_LOCK_TOLERANCE)
    in_degrees = gimbal_lock_status(R, seq, degrees=True)
    assert_allclose(in_degrees.distance, np.degrees(known), rtol=1e-12)


def test_status_locked_flag_and_tolerance(rng):
    R = scipy_matrices("ZYX", np.array([np.pi / 2, -np.pi / 2, np.pi / 2 - 1e-4, 0.0]), rng)
    locked, distance = gimbal_lock_status(R, "ZYX")
    assert_array_equal(locked, [True, True, False, False])
    assert_allclose(distance[3], np.pi / 2, rtol=1e-15)
    assert np.all(distance <= np.pi / 2)
    locked, _ = gimbal_lock_status(R, "ZYX", tolerance=1e-3)
    assert_array_equal(locked, [True, True, True, False])
    locked, _ = gimbal_lock_status(R, "ZYX", degrees=True, tolerance=0.01)
    assert_array_equal(locked, [True, True, True, False])  # 1e-4 rad is 0.0057°


@pytest.mark.parametrize("seq", ["ZYX", "zxz"])
def test_status_tolerance_in_degrees_is_read_in_degrees(seq, rng):
    """Half a degree from lock: locked within 1°, not within 0.1°, whatever 0.1 rad would say."""
    lock = 0.0 if is_proper(seq) else np.pi / 2
    R = scipy_matrices(seq, np.array([lock - np.radians(0.5)]), rng)
    locked, distance = gimbal_lock_status(R, seq, degrees=True, tolerance=1.0)
    assert_allclose(distance, [0.5], rtol=1e-9)
    assert_array_equal(locked, [True])
    locked, _ = gimbal_lock_status(R, seq, degrees=True, tolerance=0.1)
    assert_array_equal(locked, [False])  # 0.5° is 0.0087 rad, under 0.1 rad
    locked, _ = gimbal_lock_status(R, seq, tolerance=0.1)
    assert_array_equal(locked, [True])  # the same number in radians


def test_status_shapes(rng):
    R = Rotation.random(6, rng=rng).as_matrix().reshape(2, 3, 3, 3)
    status = gimbal_lock_status(R, "zxz")
    assert status.locked.shape == status.distance.shape == (2, 3)
    single = gimbal_lock_status(R[0, 0], "zxz")
    assert np.ndim(single.locked) == np.ndim(single.distance) == 0


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_status_agrees_with_the_warning(seq, rng):
    R = lock_batch(seq, rng)
    locked, _ = gimbal_lock_status(R, seq)
    assert_array_equal(locked, [False, True, False, True, False])


# --- the formulas as printed fail where eulerlib does not -------------------------------------


def rose_code_sample_3(R: np.ndarray) -> np.ndarray:
    """Rose's code sample 3 as printed (exact ``== 1`` test, ``asin``), for one matrix."""
    r11, r12, r13 = R[0]
    r21 = R[1, 0]
    r31, r32, r33 = R[2]
    pitch = -np.arcsin(r31) if abs(r31) <= 1 else np.nan
    if r31 == 1:
        return np.array([0.0, pitch, np.arctan2(-r12, -r13)])
    if r31 == -1:
        return np.array([0.0, pitch, np.arctan2(r12, r13)])
    return np.array([np.arctan2(r21, r11), pitch, np.arctan2(r32, r33)])


def baker_code(R: np.ndarray) -> np.ndarray:
    """Baker's code as printed (``0.998`` cut-off, ``asin``), for one matrix."""
    if R[1, 0] > 0.998:
        return np.array([np.arctan2(R[0, 2], R[2, 2]), np.pi / 2, 0.0])
    if R[1, 0] < -0.998:
        return np.array([np.arctan2(R[0, 2], R[2, 2]), -np.pi / 2, 0.0])
    return np.array(
        [np.arctan2(-R[2, 0], R[0, 0]), np.arcsin(R[1, 0]), np.arctan2(-R[1, 2], R[1, 1])]
    )


def test_exact_equality_test_fails_on_rounding_noise(rng):
    """r31 = 0.9999999999999999 is gimbal lock, but ``r31 == 1`` is false."""
    middle = rng.choice([-np.pi / 2, np.pi / 2], 300)
    R = with_rounding_noise(scipy_matrices("ZYX", middle, rng), rng)
    noisy = R[np.abs(R[:, 2, 0]) != 1.0]
    assert len(noisy) > 50
    naive_errors = []
    for matrix in noisy:
        angles = rose_code_sample_3(matrix)
        if np.all(np.isfinite(angles)):
            rebuilt = Rotation.from_euler("ZYX", angles).as_matrix()
            naive_errors.append(np.abs(rebuilt - matrix).max())
        else:  # asin of 1.0000000000000002
            naive_errors.append(np.inf)
    assert max(naive_errors) > 0.5  # a wrong rotation, not a rounding error
    assert round_trip_error(noisy, "ZYX") <= ROUND_TRIP_ATOL


def test_asin_loses_half_the_digits_near_lock(rng):
    pitch = np.pi / 2 - 10.0 ** np.arange(-12, -4)
    R = scipy_matrices("ZYX", pitch, rng)
    naive = np.array([rose_code_sample_3(matrix)[1] for matrix in R])
    assert np.abs(naive - pitch).max() > 1e-9
    _, got, _ = matrix_to_yaw_pitch_roll(R)
    assert np.abs(got - pitch).max() <= 4e-16


def test_baker_cut_off_returns_90_for_86_4_degrees():
    R = heading_attitude_bank_to_matrix(20.0, 86.4, -35.0, degrees=True)
    assert R[1, 0] > 0.998
    naive = np.degrees(baker_code(R))
    assert naive[1] == 90.0
    assert np.abs(Rotation.from_euler("YZX", naive, degrees=True).as_matrix() - R).max() > 0.05
    heading, attitude, bank = matrix_to_heading_attitude_bank(R, degrees=True)
    assert_allclose([heading, attitude, bank], [20.0, 86.4, -35.0], rtol=0, atol=1e-12)


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_outer_angles_lie_in_the_half_open_range(seq, rng):
    """Half turns come back as +180°, never −180°: the range is (−180°, 180°]."""
    grid = np.radians(np.arange(-180.0, 181.0, 15.0))
    angles = np.array(np.meshgrid(grid, grid, grid)).reshape(3, -1).T
    R = Rotation.from_euler(seq, angles).as_matrix()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", GimbalLockWarning)
        got = matrix_to_euler(R, seq)
        named = matrix_to_yaw_pitch_roll(R[:50])
    outer = got[:, [0, 2]]
    assert np.all(outer > -np.pi) and np.all(outer <= np.pi)
    assert np.any(outer == np.pi)  # the half turns are there, as +π
    assert np.all(named.yaw > -np.pi) and np.all(named.roll > -np.pi)
