"""Every bad input of quaternions, axis–angle, rotation vectors and slerp: type and message.

The same rules as for Euler angles (``tests/test_bad_input.py``): numbers are real and finite,
shapes are named, rotation matrices are rotations (or ``repair=True`` is asked for), and a
quaternion or an axis must not be zero. Flags and tolerances are held to the rules by
``tests/test_api.py`` for every public function. Inputs are never modified, nothing is printed.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
import pytest
from bad_numbers import bad_values
from numpy.testing import assert_array_equal
from scipy.spatial.transform import Rotation

from eulerlib import (
    angle_between,
    axis_angle_to_matrix,
    euler_to_quaternion,
    matrix_to_axis_angle,
    matrix_to_quaternion,
    matrix_to_rotvec,
    quaternion_to_euler,
    quaternion_to_matrix,
    rotation_angle,
    rotvec_to_matrix,
    slerp,
)
from eulerlib._blocks import BLOCK_SIZE

R0 = Rotation.from_euler("ZYX", [0.3, 0.2, 0.1]).as_matrix()
Q0 = Rotation.from_euler("ZYX", [0.3, 0.2, 0.1]).as_quat()

#: name → (call with one argument replaced, the argument's name, a valid value of it)
ARGUMENTS: dict[str, tuple[Callable[[Any], object], str, Any]] = {
    "quaternion_to_matrix": (lambda x: quaternion_to_matrix(x), "q", Q0),
    "quaternion_to_euler": (lambda x: quaternion_to_euler(x), "q", Q0),
    "euler_to_quaternion": (lambda x: euler_to_quaternion(x), "angles", [0.1, 0.2, 0.3]),
    "axis_angle_to_matrix, axis": (lambda x: axis_angle_to_matrix(x, 0.5), "axis", [0, 0, 1.0]),
    "axis_angle_to_matrix, angle": (lambda x: axis_angle_to_matrix([0, 0, 1.0], x), "angle", 0.5),
    "rotvec_to_matrix": (lambda x: rotvec_to_matrix(x), "v", [0.1, 0.2, 0.3]),
    "matrix_to_quaternion": (lambda x: matrix_to_quaternion(x), "R", R0),
    "matrix_to_axis_angle": (lambda x: matrix_to_axis_angle(x), "R", R0),
    "matrix_to_rotvec": (lambda x: matrix_to_rotvec(x), "R", R0),
    "rotation_angle": (lambda x: rotation_angle(x), "R", R0),
    "angle_between, R0": (lambda x: angle_between(x, R0), "R0", R0),
    "angle_between, R1": (lambda x: angle_between(R0, x), "R1", R0),
    "slerp, R0": (lambda x: slerp(x, R0, 0.5), "R0", R0),
    "slerp, R1": (lambda x: slerp(R0, x, 0.5), "R1", R0),
    "slerp, t": (lambda x: slerp(R0, R0.T, x), "t", 0.5),
}
MATRIX_ARGUMENTS = {key: value for key, value in ARGUMENTS.items() if value[1] in ("R", "R0", "R1")}


@pytest.mark.parametrize("key", sorted(ARGUMENTS))
def test_numbers_are_real_and_finite(key: str) -> None:
    call, name, valid = ARGUMENTS[key]
    call(valid)
    for bad, error, words in bad_values(valid):
        with pytest.raises(error, match=rf"^{name} {words}"):
            call(bad)


SHAPES = {
    "q": ([0.0, 0.0, 1.0], r"q must have shape \(\.\.\., 4\), got shape \(3,\)"),
    "angles": ([0.1, 0.2], r"angles must have shape \(\.\.\., 3\), got shape \(2,\)"),
    "axis": (1.0, r"axis must have shape \(\.\.\., 3\), got shape \(\)"),
    "v": (np.zeros((2, 4)), r"v must have shape \(\.\.\., 3\), got shape \(2, 4\)"),
    "R": (np.eye(4), r"R must have shape \(\.\.\., 3, 3\), got shape \(4, 4\)"),
    "R0": (np.eye(3)[0], r"R0 must have shape \(\.\.\., 3, 3\), got shape \(3,\)"),
    "R1": (np.ones((2, 3, 2)), r"R1 must have shape \(\.\.\., 3, 3\), got shape \(2, 3, 2\)"),
}


@pytest.mark.parametrize("key", sorted(ARGUMENTS))
def test_wrong_shapes_are_named(key: str) -> None:
    call, name, _ = ARGUMENTS[key]
    if name not in SHAPES:
        return  # angle and t are any shape that broadcasts
    bad, words = SHAPES[name]
    with pytest.raises(ValueError, match=rf"^{words}$"):
        call(bad)


def test_shapes_that_do_not_broadcast() -> None:
    with pytest.raises(ValueError, match=r"leading shapes of axis \(2,\) and angle \(3,\) do not"):
        axis_angle_to_matrix(np.ones((2, 3)), np.ones(3))
    with pytest.raises(ValueError, match=r"leading shapes of R0 \(2,\) and R1 \(3,\) do not"):
        angle_between(np.stack([R0] * 2), np.stack([R0] * 3))
    with pytest.raises(ValueError, match=r"leading shapes of R0 \(\), R1 \(2,\) and t \(3,\)"):
        slerp(R0, np.stack([R0] * 2), np.zeros(3))


# --- zero quaternions and axes ------------------------------------------------------------------


def test_a_zero_quaternion_is_refused_with_its_index() -> None:
    for call in (quaternion_to_matrix, quaternion_to_euler):
        with pytest.raises(ValueError, match=r"^q is zero: a quaternion cannot be normalized"):
            call([0.0, 0.0, 0.0, 0.0])
        q = np.tile(Q0, (2, BLOCK_SIZE + 3, 1))
        q[1, BLOCK_SIZE + 1] = 0.0  # in the last block
        with pytest.raises(ValueError, match=rf"^q at index \(1, {BLOCK_SIZE + 1}\) is zero"):
            call(q)
    # tiny is not zero: a quaternion of any nonzero length is a rotation
    assert_array_equal(quaternion_to_matrix([0.0, 0.0, 0.0, 5e-324]), np.eye(3))


def test_a_zero_axis_is_refused_with_its_index() -> None:
    with pytest.raises(ValueError, match=r"^axis is zero: a rotation axis cannot be normalized"):
        axis_angle_to_matrix([0.0, 0.0, 0.0], 0.0)
    axes = np.ones((3, 4, 3))
    axes[2, 1] = 0.0
    with pytest.raises(ValueError, match=r"^axis at index \(2, 1\) is zero"):
        axis_angle_to_matrix(axes, 0.5)
    # broadcast against many angles, the index is still the axis' own
    with pytest.raises(ValueError, match=r"^axis at index \(2, 1, 0\) is zero"):
        axis_angle_to_matrix(axes[:, :, None], np.zeros(5))
    with pytest.raises(ValueError, match=r"^axis at index \(1,\) is zero"):
        axis_angle_to_matrix([[1.0, 0.0, 0.0], [0.0, 0.0, 0.0]], np.zeros((BLOCK_SIZE + 9, 1)))
    assert_array_equal(axis_angle_to_matrix([0.0, 0.0, 1e-320], 0.0), np.eye(3))


def test_the_zero_rotation_vector_is_the_identity() -> None:
    assert_array_equal(rotvec_to_matrix([0.0, 0.0, 0.0]), np.eye(3))
    assert_array_equal(rotvec_to_matrix([0.0, -0.0, 0.0], degrees=True), np.eye(3))


# --- matrices that are not rotations --------------------------------------------------------------

REFLECTION = np.diag([1.0, 1.0, -1.0])
SHEARED = np.array([[1.0, 0.1, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])


@pytest.mark.parametrize("key", sorted(MATRIX_ARGUMENTS))
def test_matrices_must_be_rotations(key: str) -> None:
    call, name, _ = MATRIX_ARGUMENTS[key]
    with pytest.raises(ValueError, match=rf"^{name} has determinant -1: a reflection"):
        call(REFLECTION)
    with pytest.raises(ValueError, match=rf"^{name} is not a rotation matrix: .*pass repair=True"):
        call(SHEARED)
    stack = np.stack([R0, R0, 1.01 * R0])
    with pytest.raises(ValueError, match=rf"^{name} at index \(2,\) is not a rotation matrix"):
        call(stack)


def test_repair_and_its_refusals() -> None:
    noisy = R0 + 1e-5
    for call in (
        lambda **k: matrix_to_quaternion(noisy, **k),
        lambda **k: matrix_to_axis_angle(noisy, **k),
        lambda **k: matrix_to_rotvec(noisy, **k),
        lambda **k: rotation_angle(noisy, **k),
        lambda **k: angle_between(noisy, R0, **k),
        lambda **k: slerp(R0, noisy, 0.5, **k),
    ):
        with pytest.raises(ValueError, match="pass repair=True"):
            call()
        call(repair=True)
        call(validate=False)
    with pytest.raises(ValueError, match=r"^R is singular \(rank 0"):
        matrix_to_quaternion(np.zeros((3, 3)), repair=True)
    with pytest.raises(ValueError, match=r"^R1 is closest to a reflection"):
        slerp(R0, REFLECTION + 1e-9, 0.5, repair=True)


# --- inputs untouched, nothing printed ---------------------------------------------------------


def test_inputs_are_never_modified_and_nothing_is_printed(capsys, rng) -> None:
    R = Rotation.random(5, rng=rng).as_matrix()
    q = rng.normal(size=(5, 4))
    v = rng.normal(size=(5, 3))
    t = rng.uniform(0, 1, 5)
    before = [a.copy() for a in (R, q, v, t)]
    matrix_to_quaternion(R)
    matrix_to_axis_angle(R)
    matrix_to_rotvec(R, degrees=True)
    rotation_angle(R)
    angle_between(R, R[::-1])
    slerp(R, R[::-1], t)
    slerp(R, R[::-1], t, repair=True)
    quaternion_to_matrix(q)
    quaternion_to_euler(q, warn=False)
    rotvec_to_matrix(v, degrees=True)
    axis_angle_to_matrix(v, t)
    euler_to_quaternion(v, degrees=True)
    for original, now in zip(before, (R, q, v, t), strict=True):
        assert_array_equal(now, original)
    assert capsys.readouterr() == ("", "")
