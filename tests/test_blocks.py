"""Work on large inputs runs block by block; the results and the messages must not show it."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import eulerlib
from eulerlib._blocks import BLOCK_SIZE, block_slices

# More rotations than two blocks, in a leading shape of two axes.
SHAPE = (3, BLOCK_SIZE - 5)


@pytest.fixture(scope="module")
def angles() -> np.ndarray:
    rng = np.random.default_rng(11)
    values = rng.uniform(-np.pi, np.pi, (*SHAPE, 3))
    values[..., 1] /= 2
    return values


def test_many_rotations_match_scipy_across_blocks(angles: np.ndarray) -> None:
    R = eulerlib.euler_to_matrix(angles, "ZYX")
    expected = Rotation.from_euler("ZYX", angles.reshape(-1, 3)).as_matrix().reshape(*SHAPE, 3, 3)
    assert R.shape == (*SHAPE, 3, 3)
    assert np.abs(R - expected).max() < 1e-14
    back = eulerlib.matrix_to_euler(R, "ZYX")
    assert back.shape == (*SHAPE, 3)
    assert np.abs(back - angles).max() < 1e-12
    status = eulerlib.gimbal_lock_status(R, "ZYX")
    assert status.distance.shape == SHAPE
    assert np.allclose(status.distance, np.pi / 2 - np.abs(angles[..., 1]), atol=1e-12)


def test_the_error_names_the_index_in_the_whole_input(angles: np.ndarray) -> None:
    R = eulerlib.euler_to_matrix(angles, "ZYX")
    R[2, BLOCK_SIZE - 7] *= 1.01  # in the last block
    with pytest.raises(ValueError, match=rf"R at index \(2, {BLOCK_SIZE - 7}\) is not a rotation"):
        eulerlib.matrix_to_euler(R)
    R[1, 3] = np.diag([1.0, 1.0, -1.0])  # an earlier block: reported first
    with pytest.raises(ValueError, match=r"R at index \(1, 3\) has determinant -1"):
        eulerlib.matrix_to_euler(R)
    with pytest.raises(ValueError, match=r"R at index \(1, 3\) is closest to a reflection"):
        eulerlib.matrix_to_euler(R, repair=True)
    with pytest.raises(ValueError, match=r"R at index \(1, 3\) has determinant -1"):
        eulerlib.rotate_points(R, [1.0, 0.0, 0.0])


def test_one_warning_counts_the_locks_of_every_block(angles: np.ndarray) -> None:
    locked_angles = angles.copy()
    locked_angles[0, 0, 1] = np.pi / 2
    locked_angles[2, -1, 1] = -np.pi / 2
    R = eulerlib.euler_to_matrix(locked_angles, "ZYX")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        eulerlib.matrix_to_euler(R, "ZYX")
    assert len(caught) == 1
    assert f"gimbal lock in 2 of {R[..., 0, 0].size} rotation(s)" in str(caught[0].message)


@pytest.mark.parametrize(("count", "size"), [(0, 3), (1, 3), (5, 2), (6, 3), (7, 16384)])
def test_the_blocks_cut_the_range_into_consecutive_pieces(count: int, size: int) -> None:
    blocks = list(block_slices(count, size))
    covered = [i for block in blocks for i in range(count)[block]]
    assert covered == list(range(count))  # every index once, in order
    assert all(block.stop - block.start == size for block in blocks[:-1])
    assert len(blocks) == -(-count // size)
    assert list(block_slices(5, 2)) == [slice(0, 2), slice(2, 4), slice(4, 5)]
