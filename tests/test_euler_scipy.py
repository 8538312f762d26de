"""All 24 conventions against SciPy's ``Rotation``: matrices, angles, ranges, degrees.

SciPy is the independent oracle here: ``seq`` means the same thing in both libraries, so
``euler_to_matrix`` must reproduce ``Rotation.from_euler(seq, angles).as_matrix()`` and, away
from gimbal lock where the angles are unique, ``matrix_to_euler`` must reproduce ``as_euler``.
"""

import warnings

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.spatial.transform import Rotation

from eulerlib import (
    ALL_SEQUENCES,
    PROPER_EULER,
    TAIT_BRYAN,
    GimbalLockWarning,
    euler_to_matrix,
    matrix_to_euler,
)


def is_proper(seq: str) -> bool:
    return seq[0].lower() == seq[2].lower()


def wrapped(difference: np.ndarray) -> np.ndarray:
    """An angle difference brought into [-π, π), so that π and -π count as equal."""
    return (difference + np.pi) % (2 * np.pi) - np.pi


def middle_distance_from_lock(middle: np.ndarray, seq: str) -> np.ndarray:
    """Distance of SciPy's middle angle from the singular values of ``seq``."""
    if is_proper(seq):
        return np.minimum(np.abs(middle), np.abs(np.pi - middle))
    return np.pi / 2 - np.abs(middle)


def test_the_24_sequences():
    assert len(ALL_SEQUENCES) == len(set(ALL_SEQUENCES)) == 24
    assert set(TAIT_BRYAN) | set(PROPER_EULER) == {s for s in ALL_SEQUENCES if s.isupper()}
    assert {s.upper() for s in ALL_SEQUENCES if s.islower()} == set(TAIT_BRYAN + PROPER_EULER)
    for seq in ALL_SEQUENCES:  # SciPy accepts every one of them
        Rotation.from_euler(seq, [0.1, 0.2, 0.3])


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_euler_to_matrix_matches_scipy(seq, rng):
    angles = rng.uniform(-7.0, 7.0, (500, 3))  # any angles, also outside the returned ranges
    expected = Rotation.from_euler(seq, angles).as_matrix()
    assert_allclose(euler_to_matrix(angles, seq), expected, rtol=0, atol=2e-15)


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_euler_to_matrix_degrees_matches_scipy(seq, rng):
    angles = rng.uniform(-360.0, 360.0, (200, 3))
    expected = Rotation.from_euler(seq, angles, degrees=True).as_matrix()
    assert_allclose(euler_to_matrix(angles, seq, degrees=True), expected, rtol=0, atol=2e-15)


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_matrix_to_euler_matches_scipy_away_from_lock(seq, rng):
    R = Rotation.random(2000, rng=rng).as_matrix()
    expected = Rotation.from_matrix(R).as_euler(seq)
    away = middle_distance_from_lock(expected[:, 1], seq) > 1e-2
    assert away.sum() > 1500
    angles = matrix_to_euler(R[away], seq)
    assert_allclose(wrapped(angles - expected[away]), 0.0, rtol=0, atol=1e-12)


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_matrix_to_euler_degrees_matches_scipy(seq, rng):
    R = Rotation.random(300, rng=rng).as_matrix()
    expected = Rotation.from_matrix(R).as_euler(seq, degrees=True)
    away = middle_distance_from_lock(np.radians(expected[:, 1]), seq) > 1e-2
    angles = matrix_to_euler(R[away], seq, degrees=True)
    assert_allclose((angles - expected[away] + 180) % 360 - 180, 0.0, rtol=0, atol=1e-10)


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_degrees_are_radians_converted(seq, rng):
    R = Rotation.random(100, rng=rng).as_matrix()
    assert_allclose(
        matrix_to_euler(R, seq, degrees=True), np.degrees(matrix_to_euler(R, seq)), rtol=1e-15
    )


def lock_matrices(seq: str, rng: np.random.Generator, n: int = 200) -> np.ndarray:
    """Matrices built by SciPy exactly at both singular values of ``seq``."""
    singular = (0.0, np.pi) if is_proper(seq) else (np.pi / 2, -np.pi / 2)
    angles = rng.uniform(-np.pi, np.pi, (n, 3))
    angles[:, 1] = rng.choice(singular, n)
    return Rotation.from_euler(seq, angles).as_matrix()


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_returned_ranges(seq, rng):
    R = np.concatenate(
        [
            Rotation.random(1000, rng=rng).as_matrix(),
            lock_matrices(seq, rng),
            euler_to_matrix(rng.integers(-4, 5, (300, 3)) * 90, seq, degrees=True),
            np.eye(3)[np.newaxis],
        ]
    )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", GimbalLockWarning)
        angles = matrix_to_euler(R, seq)
    first, middle, third = angles[:, 0], angles[:, 1], angles[:, 2]
    assert np.all(np.abs(first) <= np.pi)
    assert np.all(np.abs(third) <= np.pi)
    if is_proper(seq):
        assert np.all((middle >= 0) & (middle <= np.pi))
    else:
        assert np.all(np.abs(middle) <= np.pi / 2)


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_lock_angles_rebuild_the_scipy_matrix(seq, rng):
    """At lock the angles are not unique, but they must describe SciPy's rotation."""
    R = lock_matrices(seq, rng)
    with pytest.warns(GimbalLockWarning):
        angles = matrix_to_euler(R, seq)
    rebuilt = Rotation.from_euler(seq, angles).as_matrix()
    assert_allclose(rebuilt, R, rtol=0, atol=1e-14)


@pytest.mark.parametrize("seq", ["ZYX", "zxz", "YZX", "xyx"])
def test_leading_axes_are_batch_axes(seq, rng):
    angles = rng.uniform(-1.0, 1.0, (4, 5, 3))
    if is_proper(seq):  # keep the middle angle inside [0, π], so the angles come back
        angles[..., 1] = np.abs(angles[..., 1]) + 0.1
    R = euler_to_matrix(angles, seq)
    assert R.shape == (4, 5, 3, 3)
    expected = Rotation.from_euler(seq, angles.reshape(-1, 3)).as_matrix()
    assert_allclose(R.reshape(-1, 3, 3), expected, rtol=0, atol=2e-15)
    back = matrix_to_euler(R, seq)
    assert back.shape == (4, 5, 3)
    assert_allclose(back, angles, rtol=0, atol=1e-14)
    single = euler_to_matrix(angles[1, 2], seq)
    assert single.shape == (3, 3)
    assert matrix_to_euler(single, seq).shape == (3,)


def test_default_sequence_is_intrinsic_zyx(rng):
    angles = rng.uniform(-1.0, 1.0, (10, 3))
    assert_allclose(
        euler_to_matrix(angles), Rotation.from_euler("ZYX", angles).as_matrix(), atol=2e-15
    )
    R = Rotation.random(10, rng=rng).as_matrix()
    assert_allclose(matrix_to_euler(R), Rotation.from_matrix(R).as_euler("ZYX"), atol=1e-12)
