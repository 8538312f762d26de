"""Uniform random rotations and the chordal mean.

Oracles: the Haar density of the rotation angle, ``(1 − cos θ) / π``, and the uniform
distribution of a turned direction on the sphere, by Kolmogorov–Smirnov tests with fixed seeds;
SciPy's ``Rotation.random`` (the same numbers from the same seed) and ``Rotation.mean``; the
circular mean ``atan2(Σ w sin θ, Σ w cos θ)`` of turns about one axis; a 50-digit mpmath
eigenvector of ``Σ w q qᵀ``; and hypothesis: the mean turns with the rotations.
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
from numpy.testing import assert_allclose, assert_array_equal
from scipy import stats
from scipy.spatial.transform import Rotation

from eulerlib import (
    is_rotation_matrix,
    mean_rotation,
    random_rotations,
    rot_y,
    rot_z,
    rotation_angle,
    slerp,
)

EPS = mp.EPS

# --- random rotations ----------------------------------------------------------------------------


def test_the_angle_has_the_haar_density() -> None:
    angles = rotation_angle(random_rotations(20000, rng=2026))
    # the distribution function of (1 − cos θ) / π on [0, π]
    result = stats.kstest(angles, lambda t: (t - np.sin(t)) / np.pi)
    assert result.pvalue > 0.01, result
    assert abs(angles.mean() - (np.pi / 2 + 2 / np.pi)) < 0.02


def test_uniform_euler_angles_are_not_uniform_rotations() -> None:
    # the same test tells the wrong method apart: it is not a test that always passes
    rng = np.random.default_rng(2026)
    angles = rng.uniform([-np.pi, -np.pi / 2, -np.pi], [np.pi, np.pi / 2, np.pi], (20000, 3))
    wrong = Rotation.from_euler("ZYX", angles).as_matrix()
    result = stats.kstest(rotation_angle(wrong), lambda t: (t - np.sin(t)) / np.pi)
    assert result.pvalue < 1e-6


@pytest.mark.parametrize("column", [0, 1, 2])
def test_a_turned_direction_is_uniform_on_the_sphere(column: int) -> None:
    R = random_rotations(20000, rng=7)
    # each coordinate of a uniform point on the unit sphere is uniform on [−1, 1]
    for row in range(3):
        result = stats.kstest(R[:, row, column], stats.uniform(-1, 2).cdf)
        assert result.pvalue > 0.01, (row, result)


def test_the_same_numbers_as_scipy_from_the_same_seed() -> None:
    ours = random_rotations(1000, rng=np.random.default_rng(11))
    theirs = Rotation.random(1000, rng=np.random.default_rng(11)).as_matrix()
    assert np.abs(ours - theirs).max() <= 4 * EPS


def test_reproducible_and_shaped() -> None:
    assert_array_equal(random_rotations(5, rng=3), random_rotations(5, rng=3))
    generator = np.random.default_rng(3)
    first, second = random_rotations(5, rng=generator), random_rotations(5, rng=generator)
    assert not np.array_equal(first, second)  # a Generator is advanced
    assert_array_equal(first, random_rotations(5, rng=np.random.SeedSequence(3)))
    assert random_rotations((), rng=1).shape == (3, 3)
    assert random_rotations(0, rng=1).shape == (0, 3, 3)
    assert random_rotations((2, 3), rng=1).shape == (2, 3, 3, 3)
    assert random_rotations(np.int64(4)).shape == (4, 3, 3)
    R = random_rotations(40000, rng=5)  # more than one block
    assert bool(np.all(is_rotation_matrix(R, atol=8 * EPS)))
    assert_array_equal(R[:3], random_rotations(3, rng=5))


@pytest.mark.parametrize(
    ("n", "error", "words"),
    [
        (-1, ValueError, "n must be an integer ≥ 0"),
        ((2, -1), ValueError, "n must be an integer ≥ 0"),
        (2.0, TypeError, "n must be an integer ≥ 0 or a tuple of them, got 2.0"),
        (True, TypeError, "n must be an integer"),
        ("3", TypeError, "n must be an integer"),
        (None, TypeError, "n must be an integer"),
        ([2, 3], TypeError, "n must be an integer"),
    ],
)
def test_bad_counts(n: object, error: type[Exception], words: str) -> None:
    with pytest.raises(error, match=rf"^{words}"):
        random_rotations(n)  # type: ignore[arg-type]


@pytest.mark.parametrize(
    ("rng", "error"),
    [(-3, ValueError), (1.5, TypeError), (True, TypeError), ("seed", TypeError)],
)
def test_bad_generators(rng: object, error: type[Exception]) -> None:
    with pytest.raises(error, match=r"^rng must be "):
        random_rotations(2, rng=rng)  # type: ignore[arg-type]


# --- the chordal mean ----------------------------------------------------------------------------


@pytest.mark.parametrize("spread", [0.1, 1.0, 3.0])
def test_scipys_mean(spread: float, rng) -> None:
    for count in (2, 3, 10, 200):
        center = Rotation.random(rng=rng)
        r = center * Rotation.from_rotvec(rng.normal(size=(count, 3)) * spread)
        w = rng.uniform(0.1, 2.0, count)
        found = mean_rotation(r.as_matrix(), w)
        assert np.abs(found - r.mean(w).as_matrix()).max() <= 1e-12
        assert np.abs(mean_rotation(r.as_matrix()) - r.mean().as_matrix()).max() <= 1e-12


def test_turns_about_one_axis_have_the_circular_mean(rng) -> None:
    for _ in range(20):
        angles = rng.uniform(-2.0, 2.0, 6)
        w = rng.uniform(0.1, 2.0, 6)
        expected = np.arctan2(np.sum(w * np.sin(angles)), np.sum(w * np.cos(angles)))
        assert np.abs(mean_rotation(rot_y(angles), w) - rot_y(expected)).max() <= 8 * EPS


def test_two_rotations_average_to_the_midpoint(rng) -> None:
    for _ in range(20):
        R0, R1 = Rotation.random(2, rng=rng).as_matrix()
        midpoint = slerp(R0, R1, 0.5)
        assert np.abs(mean_rotation(np.stack([R0, R1])) - midpoint).max() <= 1e-13


def mp_mean(R: np.ndarray, w: np.ndarray) -> list:
    """The 50-digit chordal mean: the top eigenvector of Σ w q qᵀ of the exact rotations."""
    with mpmath.workdps(mp.DIGITS + 10):
        K = mpmath.matrix(4, 4)
        for matrix, weight in zip(R, w, strict=True):
            q = mp.quaternion_of(mp.polar(matrix))
            for i in range(4):
                for j in range(4):
                    K[i, j] += mp.MP(float(weight)) * q[i] * q[j]
        values, vectors = mpmath.eigsy(K)
        top = max(range(4), key=lambda k: values[k])
        return mp.matrix_of_quaternion([vectors[i, top] for i in range(4)])


@pytest.mark.parametrize("spread", [1e-8, 1e-3, 0.5, 2.0])
def test_against_mpmath(spread: float, rng) -> None:
    worst = 0.0
    for count in (2, 5, 12):
        center = Rotation.random(rng=rng)
        R = (center * Rotation.from_rotvec(rng.normal(size=(count, 3)) * spread)).as_matrix()
        w = rng.uniform(0.5, 2.0, count)
        worst = max(worst, mp.absolute_ulps(mean_rotation(R, w), mp_mean(R, w)))
    assert worst <= 16.0, worst


@settings(max_examples=examples(50), deadline=None)
@given(st.integers(0, 2**32 - 1), st.integers(2, 10))
def test_the_mean_turns_with_the_rotations(seed: int, count: int) -> None:
    rng = np.random.default_rng(seed)
    R = Rotation.random(count, rng=rng).as_matrix()
    P, Q = Rotation.random(2, rng=rng).as_matrix()
    w = rng.uniform(0.1, 2.0, count)
    try:
        M = mean_rotation(R, w)
    except ValueError:  # a spread with no unique mean: so are the turned ones
        return
    assert np.abs(mean_rotation(P @ R @ Q, w) - P @ M @ Q).max() <= 1e-11


def test_many_sets_at_once_and_weights_of_any_size(rng) -> None:
    R = Rotation.random(4 * 5 * 6, rng=rng).as_matrix().reshape(4, 5, 6, 3, 3)
    w = rng.uniform(0.1, 2.0, (5, 6))
    found = mean_rotation(R, w)
    assert found.shape == (4, 5, 3, 3)
    for i in range(4):
        for j in range(5):
            assert_allclose(found[i, j], mean_rotation(R[i, j], w[j]), rtol=0, atol=4 * EPS)
    assert_array_equal(mean_rotation(R[0, 0], w[0] * 2.0**900), mean_rotation(R[0, 0], w[0]))
    assert_allclose(mean_rotation(R[0, 0], w[0] * 1e-300), mean_rotation(R[0, 0], w[0]),
                    rtol=0, atol=4 * EPS)  # fmt: skip
    assert mean_rotation(R[0, 0, :1]).shape == (3, 3)
    assert_allclose(mean_rotation(R[0, 0, :1]), R[0, 0, 0], rtol=0, atol=4 * EPS)


def test_a_mean_that_is_not_unique_is_refused() -> None:
    half = rot_z(np.pi)
    with pytest.raises(ValueError, match=r"^the mean of R is not unique: the rotations are"):
        mean_rotation(np.stack([np.eye(3), half]))
    sets = np.stack([np.stack([np.eye(3), rot_z(0.5)])] * 3)
    sets[1, 1] = half
    with pytest.raises(ValueError, match=r"^the mean of R at index \(1,\) is not unique"):
        mean_rotation(sets)
    with pytest.raises(ValueError, match=r"^R has no rotation with a weight: every weight is"):
        mean_rotation(np.stack([np.eye(3), half]), [0.0, 0.0])
    with pytest.raises(ValueError, match=r"^R has no rotation with a weight"):
        mean_rotation(np.zeros((0, 3, 3)))


@pytest.mark.parametrize(
    ("weights", "error", "words"),
    [
        ([1.0, -1.0], ValueError, r"weights must be ≥ 0, got -1.0 at index \(1,\)"),
        ([1.0, np.inf], ValueError, r"weights must be finite, got inf"),
        ([1.0, 1.0, 1.0], ValueError, r"weights must have shape \(\.\.\., 2\), one per rotation"),
        ("1", TypeError, "weights must be numbers, got text"),
    ],
)
def test_bad_weights(weights, error: type[Exception], words: str) -> None:
    with pytest.raises(error, match=rf"^{words}"):
        mean_rotation(np.stack([np.eye(3), rot_z(0.5)]), weights)


def test_bad_rotations() -> None:
    two = np.stack([np.eye(3), rot_z(0.5)])
    for bad, error, words in bad_values(two):
        with pytest.raises(error, match=rf"^R {words}"):
            mean_rotation(bad)
    with pytest.raises(ValueError, match=r"^R must have shape \(\.\.\., N, 3, 3\), got shape"):
        mean_rotation(np.eye(3))
    reflected = two.copy()
    reflected[1] = np.diag([1.0, 1.0, -1.0])
    with pytest.raises(ValueError, match=r"^R at index \(1,\) has determinant -1"):
        mean_rotation(reflected)
    noisy = two + 1e-5
    with pytest.raises(ValueError, match="pass repair=True"):
        mean_rotation(noisy)
    assert_allclose(mean_rotation(noisy, repair=True), mean_rotation(two), atol=1e-4)
    with pytest.raises(ValueError, match=r"^the leading shapes of R \(2,\) and weights \(3,\)"):
        mean_rotation(np.stack([two, two]), np.ones((3, 2)))


def test_inputs_are_never_modified_and_nothing_is_printed(capsys, rng) -> None:
    R = Rotation.random(5, rng=rng).as_matrix()
    w = rng.uniform(0.1, 1.0, 5)
    before = [x.copy() for x in (R, w)]
    mean_rotation(R, w)
    mean_rotation(R, w, repair=True)
    for original, now in zip(before, (R, w), strict=True):
        assert_array_equal(now, original)
    assert capsys.readouterr() == ("", "")


def test_one_rotation_is_the_first_of_many() -> None:
    # one rotation takes a path of its own, with the same numbers and the same arithmetic
    for seed in range(20):
        assert_array_equal(random_rotations((), rng=seed), random_rotations(1, rng=seed)[0])
        assert_array_equal(
            random_rotations((1, 1), rng=seed)[0, 0], random_rotations(1, rng=seed)[0]
        )


@pytest.mark.parametrize("count", [2, 5, 16, 17])
def test_a_few_matrices_are_checked_as_many_are(count: int) -> None:
    """Up to 16 matrices are checked one by one in Python floats, more as an array: the same
    means, the same refusals, worded alike."""
    R = Rotation.random(count, rng=count).as_matrix()
    assert np.allclose(mean_rotation(R), Rotation.from_matrix(R).mean().as_matrix(), atol=1e-14)
    bad = R.copy()
    bad[count // 2] = bad[count // 2] @ np.diag([1.0, 1.0, -1.0])  # a reflection among them
    with pytest.raises(ValueError, match=rf"^R at index \({count // 2},\) has determinant"):
        mean_rotation(bad)
    noisy = R.copy()
    noisy[-1] = noisy[-1] + 1e-3  # not orthogonal within the default tolerance
    with pytest.raises(ValueError, match=rf"^R at index \({count - 1},\) is not a rotation"):
        mean_rotation(noisy)
    assert np.allclose(mean_rotation(noisy, atol=1e-2), mean_rotation(noisy, validate=False))
