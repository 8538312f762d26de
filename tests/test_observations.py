"""Attitude from vector observations: Wahba's problem and TRIAD.

Oracles: SciPy's ``Rotation.align_vectors`` (with and without an infinite weight), the TRIAD
method written out here with cross products (H. D. Black, 1964), a 50-digit mpmath solution by
the SVD of ``B = Σ w a bᵀ``, and hypothesis: noiseless vectors give back the rotation that made
them, and turning ``a`` turns the answer.
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
from scipy.spatial.transform import Rotation

from eulerlib import Alignment, align_vectors, rot_x, rot_z

EPS = mp.EPS


@pytest.mark.parametrize("count", [2, 3, 10, 100])
def test_scipys_align_vectors(count: int, rng) -> None:
    for _ in range(10):
        a = rng.normal(size=(count, 3))
        b = rng.normal(size=(count, 3))
        w = rng.uniform(0.1, 3.0, count)
        expected, rssd = Rotation.align_vectors(a, b, w)
        found = align_vectors(a, b, w)
        assert isinstance(found, Alignment)
        assert found.matrix.shape == (3, 3) and found.rssd.shape == ()
        assert np.abs(found.matrix - expected.as_matrix()).max() <= 64 * EPS
        assert_allclose(found.rssd, rssd, rtol=1e-13)
        unweighted, rssd = Rotation.align_vectors(a, b)
        assert np.abs(align_vectors(a, b).matrix - unweighted.as_matrix()).max() <= 64 * EPS


@pytest.mark.parametrize("count", [2, 3, 10])
def test_scipys_align_vectors_with_an_infinite_weight(count: int, rng) -> None:
    for _ in range(10):
        a = rng.normal(size=(count, 3))
        b = rng.normal(size=(count, 3))
        w = rng.uniform(0.1, 3.0, count)
        w[count // 2] = np.inf
        expected, rssd = Rotation.align_vectors(a, b, w)
        found = align_vectors(a, b, w)
        assert np.abs(found.matrix - expected.as_matrix()).max() <= 64 * EPS
        assert_allclose(found.rssd, rssd, rtol=1e-12)
        primary = count // 2
        turned = found.matrix @ b[primary]
        assert_allclose(turned / np.linalg.norm(turned), a[primary] / np.linalg.norm(a[primary]),
                        atol=4 * EPS)  # fmt: skip


def triad(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """TRIAD, typed in: the frames (t1, t2, t3) of each pair, C = [t_a][t_b]ᵀ."""

    def frame(first: np.ndarray, second: np.ndarray) -> np.ndarray:
        t1 = first / np.linalg.norm(first)
        t2 = np.cross(first, second)
        t2 /= np.linalg.norm(t2)
        return np.column_stack([t1, t2, np.cross(t1, t2)])

    return frame(a[0], a[1]) @ frame(b[0], b[1]).T


def test_an_infinite_first_weight_is_triad(rng) -> None:
    for _ in range(50):
        a, b = rng.normal(size=(2, 2, 3))
        found = align_vectors(a, b, [np.inf, 1.0])
        assert np.abs(found.matrix - triad(a, b)).max() <= 32 * EPS


def test_two_vectors_without_an_infinite_weight_split_the_error(rng) -> None:
    # noise on both: the least-squares answer lies between the two TRIAD answers
    C = rot_z(30, degrees=True) @ rot_x(20, degrees=True)
    b = np.array([[0.0, 0.0, -1.0], [0.4, 0.0, 0.9]])
    a = b @ C.T + [[0.0, 0.02, 0.0], [0.0, 0.0, 0.02]]
    both = align_vectors(a, b).matrix
    first, second = align_vectors(a, b, [np.inf, 1]).matrix, align_vectors(a, b, [1, np.inf]).matrix

    def angle(P: np.ndarray, Q: np.ndarray) -> float:
        return float(np.arccos(np.clip((np.trace(P.T @ Q) - 1) / 2, -1, 1)))

    assert angle(both, C) < max(angle(first, C), angle(second, C))
    assert angle(first, both) > 0 and angle(second, both) > 0


def mp_wahba(a: np.ndarray, b: np.ndarray, w: np.ndarray) -> list:
    """The 50-digit solution: SVD of B = Σ w a bᵀ, computed on the exact float inputs."""
    with mpmath.workdps(mp.DIGITS + 10):
        B = mpmath.matrix(3, 3)
        for weight, x, y in zip(w, a, b, strict=True):
            for i in range(3):
                for j in range(3):
                    B[i, j] += mp.MP(float(weight)) * mp.MP(float(x[i])) * mp.MP(float(y[j]))
        U, _, V = mpmath.svd_r(B)  # B = U diag(S) V, V already transposed
        d = mpmath.sign(mpmath.det(U) * mpmath.det(V))
        D = mpmath.diag([1, 1, d])
        C = U * D * V
        return [[C[i, j] for j in range(3)] for i in range(3)]


@pytest.mark.parametrize("scale", [1e-200, 1e-50, 1.0, 1e50, 1e200])
def test_against_mpmath_at_every_scale(scale: float, rng) -> None:
    worst = 0.0
    for count in (2, 3, 8):
        for _ in range(4):
            a = rng.normal(size=(count, 3))
            C = Rotation.random(rng=rng).as_matrix()
            b = (a + 0.05 * rng.normal(size=(count, 3))) @ C  # a ≈ C b, a little noise
            w = rng.uniform(0.5, 2.0, count)
            exact = mp_wahba(a, b, w)
            found = align_vectors(a * scale, b / scale, w * scale).matrix
            worst = max(worst, mp.absolute_ulps(found, exact))
    assert worst <= 32.0, worst


@settings(max_examples=examples(100), deadline=None)
@given(st.integers(0, 2**32 - 1), st.integers(2, 12))
def test_noiseless_vectors_give_back_their_rotation(seed: int, count: int) -> None:
    rng = np.random.default_rng(seed)
    C = Rotation.random(rng=rng).as_matrix()
    b = rng.normal(size=(count, 3))
    a = b @ C.T
    found = align_vectors(a, b, rng.uniform(0.1, 2.0, count))
    # conditioned by how far the vectors are from all lying on one line
    spread = np.linalg.svd(b, compute_uv=False)
    if spread[1] < 1e-3 * spread[0]:
        return
    assert np.abs(found.matrix - C).max() <= 64 * EPS * (spread[0] / spread[1]) ** 2
    assert found.rssd <= 1e-13 * np.sqrt(np.sum(b * b))


@settings(max_examples=examples(50), deadline=None)
@given(st.integers(0, 2**32 - 1))
def test_turning_the_observations_turns_the_answer(seed: int) -> None:
    rng = np.random.default_rng(seed)
    a, b = rng.normal(size=(2, 5, 3))
    Q = Rotation.random(rng=rng).as_matrix()
    plain, turned = align_vectors(a, b), align_vectors(a @ Q.T, b)
    assert np.abs(turned.matrix - Q @ plain.matrix).max() <= 1e-13
    assert_allclose(turned.rssd, plain.rssd, rtol=1e-12)


def test_many_problems_at_once(rng) -> None:
    a = rng.normal(size=(4, 5, 3, 3))
    b = rng.normal(size=(3, 3))  # one reference for all twenty problems
    w = rng.uniform(0.5, 2.0, (5, 3))
    w[2, 0] = np.inf
    found = align_vectors(a, b, w)
    assert found.matrix.shape == (4, 5, 3, 3) and found.rssd.shape == (4, 5)
    for i in range(4):
        for j in range(5):
            one = align_vectors(a[i, j], b, w[j])
            assert_allclose(found.matrix[i, j], one.matrix, rtol=0, atol=4 * EPS)
            assert_allclose(found.rssd[i, j], one.rssd, rtol=4 * EPS)


def test_the_readme_case_gravity_and_field() -> None:
    C = rot_z(-50, degrees=True) @ rot_x(12, degrees=True)
    world = np.array([[0.0, 0.0, -9.81], [20.0, 0.0, -45.0]])  # gravity, field (µT)
    seen = world @ C.T
    assert np.abs(align_vectors(seen, world).matrix - C).max() <= 32 * EPS
    assert np.abs(align_vectors(seen, world, [np.inf, 1.0]).matrix - C).max() <= 32 * EPS


# --- degenerate and bad input ---------------------------------------------------------------

A0 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
B0 = [[0.0, 1.0, 0.0], [1.0, 0.0, 0.0]]
NOT_ONE = "a and b do not determine one rotation"


@pytest.mark.parametrize(
    ("a", "b", "w", "words"),
    [
        ([[1.0, 0, 0], [2.0, 0, 0]], [[0, 1.0, 0], [0, 3.0, 0]], None, "all parallel"),
        ([[1.0, 0, 0], [-2.0, 0, 0]], [[0, 1.0, 0], [0, -3.0, 0]], None, "all parallel"),
        ([[1.0, 0, 0]], [[0, 1.0, 0]], None, "all parallel"),
        (A0, B0, [1.0, 0.0], "all parallel"),
        (A0, B0, [0.0, 0.0], "every weight is zero"),
        (np.eye(3), -np.eye(3), None, "two rotations fit equally well"),
        (A0, B0, [np.inf, 0.0], "parallel to the one with the infinite weight"),
        ([[1.0, 0, 0]], [[0, 1.0, 0]], [np.inf], "parallel to the one with the infinite weight"),
        ([[1.0, 0, 0], [3.0, 0, 0]], [[0, 1.0, 0], [0, 3.0, 0]], [np.inf, 1.0], "parallel to"),
    ],
)
def test_degenerate_problems_are_refused(a, b, w, words: str) -> None:
    with pytest.raises(ValueError, match=rf"^{NOT_ONE}: .*{words}"):
        align_vectors(a, b, w)


def test_nearly_parallel_is_ill_conditioned_until_it_is_degenerate(rng) -> None:
    C = Rotation.random(rng=rng).as_matrix()
    for angle in (1e-2, 1e-4, 1e-5):  # rounding turns the answer by about eps / (angle² / 4)
        b = np.array([[1.0, 0.0, 0.0], [np.cos(angle), np.sin(angle), 0.0]])
        for w in ([1.0, 1.0], [np.inf, 1.0]):
            error = np.abs(align_vectors(b @ C.T, b, w).matrix - C).max()
            assert error <= 16 * EPS / (angle**2 / 4)
    b = np.array([[1.0, 0.0, 0.0], [1.0, 1e-7, 0.0]])
    for w in ([1.0, 1.0], [np.inf, 1.0]):
        with pytest.raises(ValueError, match=NOT_ONE):
            align_vectors(b @ C.T, b, w)


def test_the_index_of_a_degenerate_problem() -> None:
    a = np.tile(A0, (3, 4, 1, 1))
    a[2, 1, 1] = a[2, 1, 0]
    with pytest.raises(ValueError, match=rf"^{NOT_ONE} at index \(2, 1\): .*all parallel"):
        align_vectors(a, np.tile(A0, (3, 4, 1, 1)))
    w = np.ones((3, 2))
    w[1] = np.inf
    with pytest.raises(ValueError, match=r"^weights at index \(1,\) has 2 infinite weights"):
        align_vectors(A0, B0, w)


def test_zero_vectors_are_refused() -> None:
    with pytest.raises(ValueError, match=r"^a at index \(1,\) is zero: a vector with no direct"):
        align_vectors([[1.0, 0, 0], [0.0, 0, 0]], B0)
    b = np.tile(B0, (2, 1, 1))
    b[1, 0] = 0.0
    with pytest.raises(ValueError, match=r"^b at index \(1, 0\) is zero"):
        align_vectors(A0, b)


@pytest.mark.parametrize(
    ("weights", "error", "words"),
    [
        ([1.0, -1.0], ValueError, r"weights must be ≥ 0 .*got -1.0 at index \(1,\)"),
        ([1.0, np.nan], ValueError, r"weights must be ≥ 0 .*got nan at index \(1,\)"),
        ([-np.inf, 1.0], ValueError, r"weights must be ≥ 0 .*got -inf at index \(0,\)"),
        ([1.0, 1.0, 1.0], ValueError, r"weights must have shape \(\.\.\., 2\), one per vector"),
        (1.0, ValueError, r"weights must have shape \(\.\.\., 2\)"),
        ("1", TypeError, "weights must be numbers, got text"),
        ([True, False], TypeError, "weights must be real numbers, got booleans"),
    ],
)
def test_bad_weights(weights, error: type[Exception], words: str) -> None:
    with pytest.raises(error, match=rf"^{words}"):
        align_vectors(A0, B0, weights)


@pytest.mark.parametrize("name", ["a", "b"])
def test_numbers_are_real_and_finite(name: str) -> None:
    for bad, error, words in bad_values(A0):
        arguments = {"a": A0, "b": B0, name: bad}
        with pytest.raises(error, match=rf"^{name} {words}"):
            align_vectors(arguments["a"], arguments["b"])


def test_wrong_shapes_are_named() -> None:
    with pytest.raises(ValueError, match=r"^a must have shape \(\.\.\., N, 3\), got shape \(3,\)"):
        align_vectors([1.0, 0.0, 0.0], B0)
    with pytest.raises(ValueError, match=r"^b must have shape .*, got shape \(2, 2\)"):
        align_vectors(A0, np.ones((2, 2)))
    with pytest.raises(ValueError, match=r"^a and b must hold as many vectors each, got 2 and 3"):
        align_vectors(A0, np.ones((3, 3)))
    with pytest.raises(ValueError, match=r"^the leading shapes of a \(2,\), b \(3,\) and weights"):
        align_vectors(np.ones((2, 2, 3)), np.ones((3, 2, 3)))


def test_inputs_are_never_modified_and_nothing_is_printed(capsys, rng) -> None:
    a, b = rng.normal(size=(2, 4, 3))
    w = np.array([np.inf, 1.0, 2.0, 0.5])
    before = [x.copy() for x in (a, b, w)]
    align_vectors(a, b, w)
    align_vectors(a, b)
    for original, now in zip(before, (a, b, w), strict=True):
        assert_array_equal(now, original)
    assert capsys.readouterr() == ("", "")
