"""Every bad input a user could pass: the exception type and what its message says.

Also: ``repair=True`` gives the nearest rotation (checked against an SVD projection computed
here and against SciPy), ``validate=False`` skips the rotation check, inputs are never
modified, and nothing is ever printed.
"""

import warnings

import numpy as np
import pytest
from numpy.testing import assert_allclose, assert_array_equal
from scipy.spatial.transform import Rotation

from eulerlib import (
    ALL_SEQUENCES,
    compose,
    euler_to_matrix,
    gimbal_lock_status,
    heading_attitude_bank_to_matrix,
    invert,
    is_rotation_matrix,
    matrix_to_euler,
    matrix_to_heading_attitude_bank,
    matrix_to_yaw_pitch_roll,
    rot_x,
    rot_y,
    rot_z,
    rotate_points,
    yaw_pitch_roll_to_matrix,
)
from eulerlib.sequences import parse_sequence

MATRIX_FUNCTIONS = {
    "matrix_to_euler": matrix_to_euler,
    "matrix_to_yaw_pitch_roll": matrix_to_yaw_pitch_roll,
    "matrix_to_heading_attitude_bank": matrix_to_heading_attitude_bank,
    "gimbal_lock_status": gimbal_lock_status,
    "invert": invert,
    "compose": compose,
    "rotate_points": lambda R: rotate_points(R, [1.0, 2.0, 3.0]),
}
ELEMENTARY = {"rot_x": rot_x, "rot_y": rot_y, "rot_z": rot_z}

REFLECTION = np.diag([1.0, 1.0, -1.0])
SCALED = 2.0 * np.eye(3)
SHEARED = np.array([[1.0, 0.1, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])  # det 1, not orthogonal


# --- angles ------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("angles", "shape"),
    [([0.1, 0.2], r"\(2,\)"), (np.zeros((3, 4)), r"\(3, 4\)"), (0.5, r"\(\)"), ([], r"\(0,\)")],
)
def test_angles_of_wrong_shape(angles, shape):
    with pytest.raises(
        ValueError, match=rf"angles must have shape \(\.\.\., 3\), got shape {shape}"
    ):
        euler_to_matrix(angles)


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_angles_not_finite(bad):
    with pytest.raises(ValueError, match=rf"angles must be finite, got {bad}.* at index \(1,\)"):
        euler_to_matrix([0.0, bad, 0.0])
    with pytest.raises(ValueError, match=r"must be finite.*at index \(1, 2\)"):
        euler_to_matrix([[0.0, 0.0, 0.0], [0.0, 0.0, bad]], "zxz")
    for function in ELEMENTARY.values():
        with pytest.raises(ValueError, match=r"angle must be finite"):
            function(bad)
    with pytest.raises(ValueError, match=r"pitch must be finite"):
        yaw_pitch_roll_to_matrix(0.0, bad, 0.0)
    with pytest.raises(ValueError, match=r"bank must be finite"):
        heading_attitude_bank_to_matrix(0.0, 0.0, [0.0, bad])


@pytest.mark.parametrize(
    ("angles", "words"),
    [
        ("90", r"angles must be numbers, got text '90'"),
        (b"90", r"angles must be numbers, got text b'90'"),
        (["a", "b", "c"], r"angles must be real numbers, got text"),
        ([1 + 2j, 0, 0], r"angles must be real numbers, got complex numbers"),
        (np.array([0.1, 0.2, 0.3]) + 0j, r"got complex numbers"),
        ([True, False, True], r"angles must be real numbers, got booleans"),
        ([1.0, None, 2.0], r"angles must be real numbers; got an array of objects"),
        ([{"x": 1}, 2.0, 3.0], r"objects that are not numbers"),
        (np.array([1.0, "2", 3.0], dtype=object), r"objects that are not numbers"),
        (None, r"objects that are not numbers"),
    ],
)
def test_angles_not_numbers(angles, words):
    with pytest.raises(TypeError, match=words):
        euler_to_matrix(angles)


@pytest.mark.parametrize("angle", ["90", True, 1j, [np.bool_(True)]])
def test_elementary_not_numbers(angle):
    for function in ELEMENTARY.values():
        with pytest.raises(TypeError, match="angle must be"):
            function(angle)


def test_named_angles_not_numbers():
    with pytest.raises(TypeError, match="yaw must be numbers, got text '90'"):
        yaw_pitch_roll_to_matrix("90", 0, 0)
    with pytest.raises(TypeError, match="roll must be real numbers, got complex"):
        yaw_pitch_roll_to_matrix(0, 0, 1j)
    with pytest.raises(TypeError, match="heading must be real numbers, got booleans"):
        heading_attitude_bank_to_matrix(True, 0, 0)
    with pytest.raises(TypeError, match="attitude must be numbers, got text"):
        heading_attitude_bank_to_matrix(0, "up", 0)


def test_named_angles_that_do_not_broadcast():
    with pytest.raises(
        ValueError, match=r"do not broadcast together: shapes yaw \(2,\), pitch \(3,\), roll \(\)"
    ):
        yaw_pitch_roll_to_matrix([0.0, 1.0], [0.0, 1.0, 2.0], 0.0)
    with pytest.raises(ValueError, match=r"heading, attitude and bank do not broadcast"):
        heading_attitude_bank_to_matrix(np.zeros(2), np.zeros(3), 0.0)


def test_ragged_angles():
    with pytest.raises(ValueError, match="angles could not be read as a numeric array"):
        euler_to_matrix([[0.0, 0.0, 0.0], [0.0, 0.0]])


def test_elementary_axis():
    from eulerlib import elementary_rotation

    words = r"axis must be 'x', 'y', 'z' \(either case\) or 0, 1, 2; got"
    for bad in (3, -1, "w", "xy", ""):
        with pytest.raises(ValueError, match=words):
            elementary_rotation(bad, 0.0)
    for bad in (True, 1.0, None, np.bool_(False), [0]):
        with pytest.raises(TypeError, match=words):
            elementary_rotation(bad, 0.5)


# --- sequences ---------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("seq", "reason"),
    [
        ("XYZW", "it has 4 characters, not 3"),
        ("XY", "it has 2 characters, not 3"),
        ("", "it has 0 characters, not 3"),
        ("XXY", "two neighbouring axes are the same, so two rotations would merge"),
        ("xyy", "two neighbouring axes are the same"),
        ("XyZ", r"it mixes uppercase \(intrinsic\) and lowercase \(extrinsic\) letters"),
        ("abc", "it uses letters other than x, y, z"),
        ("XYQ", "it uses letters other than x, y, z"),
    ],
)
def test_invalid_sequence(seq, reason, rng):
    R = Rotation.random(rng=rng).as_matrix()
    for call in (
        lambda: euler_to_matrix([0.1, 0.2, 0.3], seq),
        lambda: matrix_to_euler(R, seq),
        lambda: gimbal_lock_status(R, seq),
    ):
        with pytest.raises(
            ValueError,
            match=rf"seq {seq!r} is neither a preset .* nor a valid axis sequence \({reason}",
        ) as info:
            call()
        for valid in ALL_SEQUENCES:  # the message lists every valid form
            assert valid in str(info.value)


@pytest.mark.parametrize("seq", [123, None, ["Z", "Y", "X"], b"ZYX"])
def test_sequence_not_a_string(seq):
    with pytest.raises(TypeError, match=r"seq must be a convention: a preset name .* got"):
        euler_to_matrix([0.1, 0.2, 0.3], seq)
    with pytest.raises(TypeError, match=r"seq must be a convention"):
        matrix_to_euler(np.eye(3), seq)
    with pytest.raises(TypeError, match=r"seq must be a string"):
        parse_sequence(seq)


# --- matrices ----------------------------------------------------------------------------------


@pytest.mark.parametrize("name", MATRIX_FUNCTIONS)
@pytest.mark.parametrize(
    ("R", "shape"),
    [
        (np.zeros(3), r"\(3,\)"),
        (np.zeros((3, 4)), r"\(3, 4\)"),
        (np.zeros((2, 2)), r"\(2, 2\)"),
        (np.zeros((2, 3, 4)), r"\(2, 3, 4\)"),
        (1.0, r"\(\)"),
    ],
)
def test_matrices_of_wrong_shape(name, R, shape):
    with pytest.raises(ValueError, match=rf"must have shape \(\.\.\., 3, 3\), got shape {shape}"):
        MATRIX_FUNCTIONS[name](R)


@pytest.mark.parametrize("name", MATRIX_FUNCTIONS)
def test_a_stack_of_matrices_is_fine(name, rng):
    MATRIX_FUNCTIONS[name](Rotation.random(2, rng=rng).as_matrix())  # shape (2, 3, 3)


@pytest.mark.parametrize("name", MATRIX_FUNCTIONS)
@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_matrices_not_finite(name, bad, rng):
    R = Rotation.random(3, rng=rng).as_matrix()
    R[2, 1, 0] = bad
    with pytest.raises(ValueError, match=rf"must be finite, got {bad} at index \(2, 1, 0\)"):
        MATRIX_FUNCTIONS[name](R)


@pytest.mark.parametrize("name", MATRIX_FUNCTIONS)
def test_reflections(name, rng):
    with pytest.raises(ValueError, match=r"determinant -1: a reflection, not a rotation"):
        MATRIX_FUNCTIONS[name](REFLECTION)
    R = Rotation.random(4, rng=rng).as_matrix()
    R[3] = -R[3]
    with pytest.raises(ValueError, match=r"at index \(3,\) has determinant -1: a reflection"):
        MATRIX_FUNCTIONS[name](R)


@pytest.mark.parametrize("name", MATRIX_FUNCTIONS)
@pytest.mark.parametrize(
    ("R", "error"), [(SCALED, "3"), (SHEARED, "0.1"), (0.5 * np.eye(3), "0.75")]
)
def test_not_orthogonal(name, R, error):
    words = rf"is not a rotation matrix: max \|R Rᵀ − I\| = {error}.* exceeds the tolerance 1e-06"
    with pytest.raises(ValueError, match=words):
        MATRIX_FUNCTIONS[name](R)


def test_not_orthogonal_message_suggests_repair():
    with pytest.raises(ValueError, match="pass repair=True"):
        matrix_to_euler(SHEARED)


def test_not_orthogonal_within_a_batch(rng):
    R = Rotation.random(5, rng=rng).as_matrix().reshape(5, 1, 3, 3)
    R[4, 0] = SHEARED
    with pytest.raises(ValueError, match=r"R at index \(4, 0\) is not a rotation matrix"):
        matrix_to_euler(R)


def test_tolerance_keyword(rng):
    R = Rotation.random(rng=rng).as_matrix() + 1e-5
    with pytest.raises(ValueError, match="exceeds the tolerance 1e-06"):
        matrix_to_euler(R)
    matrix_to_euler(R, atol=1e-4)
    with pytest.raises(ValueError, match="exceeds the tolerance 1e-08"):
        matrix_to_euler(Rotation.random(rng=rng).as_matrix() + 1e-7, atol=1e-8)


@pytest.mark.parametrize("name", MATRIX_FUNCTIONS)
@pytest.mark.parametrize(
    ("R", "words"),
    [
        ("eye", r"must be numbers, got text 'eye'"),
        ([["a"] * 3] * 3, r"must be real numbers, got text"),
        (np.eye(3) + 0j, r"must be real numbers, got complex numbers"),
        (np.eye(3, dtype=bool), r"must be real numbers, got booleans"),
    ],
)
def test_matrices_not_numbers(name, R, words):
    with pytest.raises(TypeError, match=words):
        MATRIX_FUNCTIONS[name](R)


def test_points_bad_input():
    with pytest.raises(ValueError, match=r"points must have shape \(\.\.\., 3\), got shape \(2,\)"):
        rotate_points(np.eye(3), [1.0, 2.0])
    with pytest.raises(ValueError, match=r"points must be finite"):
        rotate_points(np.eye(3), [1.0, np.nan, 2.0])
    with pytest.raises(TypeError, match=r"points must be real numbers, got text"):
        rotate_points(np.eye(3), ["1", "2", "3"])


# --- repair and validate -------------------------------------------------------------------------


def svd_projection(M: np.ndarray) -> np.ndarray:
    """The rotation nearest to M in the Frobenius norm, computed here from the SVD."""
    U, _, Vt = np.linalg.svd(M)
    D = np.ones(M.shape[:-1])
    D[..., -1] = np.sign(np.linalg.det(U @ Vt))
    return (U * D[..., np.newaxis, :]) @ Vt


@pytest.mark.parametrize("seq", ["ZYX", "xzx", "YZX"])
@pytest.mark.parametrize("noise", [1e-5, 1e-3])
def test_repair_gives_the_nearest_rotation(seq, noise, rng):
    R = Rotation.random(200, rng=rng).as_matrix()
    M = R + noise * rng.normal(size=R.shape)
    with pytest.raises(ValueError, match="not a rotation matrix"):
        matrix_to_euler(M, seq)
    angles = matrix_to_euler(M, seq, repair=True)
    nearest = svd_projection(M)
    assert_allclose(euler_to_matrix(angles, seq), nearest, rtol=0, atol=1e-14)
    assert_allclose(Rotation.from_matrix(M).as_matrix(), nearest, rtol=0, atol=1e-14)
    assert_allclose(matrix_to_euler(nearest, seq), angles, rtol=0, atol=1e-13)


def test_repair_in_the_other_functions(rng):
    R = Rotation.random(50, rng=rng).as_matrix()
    M = R + 1e-4 * rng.normal(size=R.shape)
    nearest = svd_projection(M)
    yaw_pitch_roll = matrix_to_yaw_pitch_roll(M, repair=True)
    assert_allclose(yaw_pitch_roll_to_matrix(*yaw_pitch_roll), nearest, rtol=0, atol=1e-14)
    heading_attitude_bank = matrix_to_heading_attitude_bank(M, repair=True)
    assert_allclose(heading_attitude_bank_to_matrix(*heading_attitude_bank), nearest, atol=1e-14)
    assert_allclose(
        gimbal_lock_status(M, "ZYX", repair=True).distance,
        gimbal_lock_status(nearest, "ZYX").distance,
        rtol=1e-12,
    )


def test_repair_refuses_what_is_closest_to_a_reflection(rng):
    M = REFLECTION + 1e-4 * rng.normal(size=(3, 3))
    with pytest.raises(ValueError, match=r"closest to a reflection.*cannot be repaired"):
        matrix_to_euler(M, repair=True)


@pytest.mark.parametrize("seq", ["ZYX", "YXY", "xzy"])
def test_validate_false_skips_the_rotation_check(seq, rng):
    R = Rotation.random(20, rng=rng).as_matrix()
    angles = matrix_to_euler(R, seq)
    # a uniformly scaled rotation: every ratio the angles come from is unchanged
    assert_allclose(matrix_to_euler(3.0 * R, seq, validate=False), angles, rtol=0, atol=1e-13)
    matrix_to_euler(SHEARED, seq, validate=False, warn=False)  # no error, whatever it returns
    assert invert(SCALED, validate=False)[0, 0] == 2.0
    assert_array_equal(compose(SCALED, SCALED, validate=False), 4.0 * np.eye(3))
    gimbal_lock_status(SHEARED, seq, validate=False)
    # shape and finiteness are still checked
    with pytest.raises(ValueError, match="must be finite"):
        matrix_to_euler(np.full((3, 3), np.nan), seq, validate=False)
    with pytest.raises(ValueError, match="must have shape"):
        matrix_to_euler(np.eye(2), seq, validate=False)


# --- inputs are never modified, nothing is printed ----------------------------------------------


def frozen(array: np.ndarray) -> np.ndarray:
    array = np.array(array)
    array.flags.writeable = False
    return array


def test_inputs_are_never_modified(rng):
    R = Rotation.random(6, rng=rng).as_matrix()
    R[0] = Rotation.from_euler("ZYX", [0.3, np.pi / 2, 0.2]).as_matrix()  # one at lock
    noisy = R + 1e-5
    angles = rng.uniform(-3, 3, (6, 3))
    points = rng.normal(size=(6, 3))
    inputs = {"R": R, "noisy": noisy, "angles": angles, "points": points}
    copies = {name: value.copy() for name, value in inputs.items()}
    # read-only arrays make any attempt to write into them raise
    R_ro, noisy_ro, angles_ro, points_ro = (frozen(v) for v in inputs.values())
    F = np.asfortranarray(R)
    view = R[::-1]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for seq in ALL_SEQUENCES:
            euler_to_matrix(angles, seq)
            euler_to_matrix(angles_ro, seq)
            euler_to_matrix(angles_ro, seq, degrees=True)
            matrix_to_euler(R, seq)
            matrix_to_euler(R_ro, seq)
            matrix_to_euler(F, seq)
            matrix_to_euler(view, seq)
            matrix_to_euler(noisy_ro, seq, repair=True)
            matrix_to_euler(noisy, seq, validate=False)
            gimbal_lock_status(R_ro, seq)
        matrix_to_yaw_pitch_roll(R_ro)
        matrix_to_heading_attitude_bank(R_ro)
        matrix_to_yaw_pitch_roll(noisy_ro, repair=True)
        yaw_pitch_roll_to_matrix(*angles_ro.T)
        heading_attitude_bank_to_matrix(*angles_ro.T)
        rotate_points(R_ro, points_ro)
        invert(R_ro)
        compose(R_ro, R_ro, R_ro)
        is_rotation_matrix(R_ro)
        rot_x(angles_ro[:, 0])
    for name, value in inputs.items():
        assert_array_equal(value, copies[name], err_msg=name)
    assert_array_equal(F, copies["R"])
    assert_array_equal(view, copies["R"][::-1])


def test_outputs_do_not_share_memory_with_inputs(rng):
    R = Rotation.random(3, rng=rng).as_matrix()
    for result in (invert(R), compose(R), matrix_to_euler(R), rotate_points(R, np.eye(3))):
        assert not np.shares_memory(result, R)


def test_nothing_is_printed(capsys, rng):
    R = Rotation.random(20, rng=rng).as_matrix()
    lock = Rotation.from_euler("ZYX", [[0.1, np.pi / 2, 0.3], [0.0, -np.pi / 2, 1.0]]).as_matrix()
    baker_pole = heading_attitude_bank_to_matrix(0.4, np.pi / 2, 0.2)
    with warnings.catch_warnings(record=True):
        warnings.simplefilter("always")
        for seq in ALL_SEQUENCES:
            matrix_to_euler(euler_to_matrix(matrix_to_euler(R, seq), seq), seq)
            matrix_to_euler(lock, seq)
            gimbal_lock_status(lock, seq)
        matrix_to_yaw_pitch_roll(lock)
        matrix_to_heading_attitude_bank(baker_pole)
        matrix_to_euler(lock + 1e-4, repair=True)
        rotate_points(R, np.eye(3)[0])
        compose(R, invert(R))
        is_rotation_matrix(R)
        for bad in (REFLECTION, SCALED, "text", np.zeros(3)):
            with pytest.raises((TypeError, ValueError)):
                matrix_to_euler(bad)
    assert capsys.readouterr() == ("", "")
