"""Elementary rotations against SciPy and against the matrices written out by hand."""

import numpy as np
import pytest
from numpy.testing import assert_allclose, assert_array_equal
from scipy.spatial.transform import Rotation

import eulerlib
from eulerlib import rot_x, rot_y, rot_z

ROTATIONS = {"x": rot_x, "y": rot_y, "z": rot_z}


def written_out(axis: str, theta: float) -> np.ndarray:
    """The three right-handed active rotations, typed in entry by entry."""
    c, s = np.cos(theta), np.sin(theta)
    if axis == "x":
        return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    if axis == "y":
        return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


@pytest.mark.parametrize("axis", "xyz")
def test_matches_scipy(axis, rng):
    angles = rng.uniform(-4.0, 4.0, 200)
    expected = Rotation.from_euler(axis, angles[:, np.newaxis]).as_matrix()
    assert_allclose(ROTATIONS[axis](angles), expected, rtol=0, atol=1e-15)


@pytest.mark.parametrize("axis", "xyz")
@pytest.mark.parametrize("theta", [0.0, 0.3, -1.2, 2.9, np.pi])
def test_matches_written_out_matrix(axis, theta):
    assert_allclose(ROTATIONS[axis](theta), written_out(axis, theta), rtol=0, atol=1e-16)


@pytest.mark.parametrize("axis", "xyz")
def test_degrees_match_radians(axis, rng):
    degrees = rng.uniform(-720.0, 720.0, 100)
    assert_allclose(
        ROTATIONS[axis](degrees, degrees=True),
        ROTATIONS[axis](np.radians(degrees)),
        rtol=0,
        atol=4e-15,  # np.radians(700) itself is only known to ulp(12.2) ≈ 1.8e-15
    )


@pytest.mark.parametrize("axis", "xyz")
@pytest.mark.parametrize("quarter", range(-8, 9))
def test_quarter_turns_in_degrees_are_exact(axis, quarter):
    theta = 90.0 * quarter
    c = [1.0, 0.0, -1.0, 0.0][quarter % 4]
    s = [0.0, 1.0, 0.0, -1.0][quarter % 4]
    R = ROTATIONS[axis](theta, degrees=True)
    assert_array_equal(R, _exact(axis, c, s))


def _exact(axis: str, c: float, s: float) -> np.ndarray:
    if axis == "x":
        return np.array([[1, 0, 0], [0, c, -s], [0, s, c]]) + 0.0
    if axis == "y":
        return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]]) + 0.0
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]) + 0.0


def test_right_hand_rule():
    quarter = np.pi / 2
    e_x, e_y, e_z = np.eye(3)
    assert_allclose(rot_x(quarter) @ e_y, e_z, atol=1e-16)
    assert_allclose(rot_y(quarter) @ e_z, e_x, atol=1e-16)
    assert_allclose(rot_z(quarter) @ e_x, e_y, atol=1e-16)


@pytest.mark.parametrize("shape", [(), (1,), (5,), (2, 3), (4, 1, 2)])
def test_shapes(shape, rng):
    angles = rng.uniform(-3, 3, shape)
    R = rot_z(angles)
    assert R.shape == (*shape, 3, 3)
    assert R.dtype == np.float64
    assert_allclose(R, Rotation.from_euler("z", angles.reshape(-1, 1)).as_matrix().reshape(R.shape))


def test_accepts_integers_and_lists():
    assert_array_equal(rot_x([0, 0]), np.stack([np.eye(3), np.eye(3)]))
    assert_array_equal(rot_y(180, degrees=True), np.diag([-1.0, 1.0, -1.0]))


def test_zero_angles_give_no_negative_zeros():
    # a zero sine negated is -0.0, which prints as "-0." in every matrix a learner looks at
    matrices = [rot_x(0.0), rot_y(0.0), rot_z(0.0)]
    matrices += [eulerlib.euler_to_matrix([0.0, 0.0, 0.0], seq) for seq in eulerlib.ALL_SEQUENCES]
    for R in matrices:
        assert not np.any(np.signbit(R)), R
    for seq in eulerlib.ALL_SEQUENCES:
        assert not np.any(np.signbit(eulerlib.matrix_to_euler(np.eye(3), seq, warn=False))), seq
