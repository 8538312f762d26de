"""Named conventions and the translator, against SciPy's Rotation and formulas typed in."""

from __future__ import annotations

import warnings
from collections.abc import Iterator
from contextlib import contextmanager

import numpy as np
import pytest
from budget import examples
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from eulerlib import (
    ALL_SEQUENCES,
    CONVENTIONS,
    Convention,
    GimbalLockWarning,
    change_up_axis,
    convert_angles,
    get_convention,
    up_axis_matrix,
)
from eulerlib import euler_to_matrix as angles_to_matrix
from eulerlib import matrix_to_euler as matrix_to_angles

Rotation = pytest.importorskip("scipy.spatial.transform").Rotation

finite_angle = st.floats(-179.0, 179.0, allow_nan=False)
angle_triples = st.tuples(finite_angle, st.floats(-89.0, 89.0), finite_angle)
preset_names = st.sampled_from(sorted(CONVENTIONS))
any_convention = st.sampled_from(sorted(CONVENTIONS) + list(ALL_SEQUENCES))


def scipy_matrix(seq: str, angles: object, degrees: bool = True) -> np.ndarray:
    return np.asarray(Rotation.from_euler(seq, angles, degrees=degrees).as_matrix())


def wrapped_difference(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Difference of angles in degrees, folded into [-180, 180)."""
    return (np.asarray(a) - np.asarray(b) + 180.0) % 360.0 - 180.0


@contextmanager
def quiet_lock() -> Iterator[None]:
    """Silence the gimbal-lock warning (random angles may land on a lock of the target)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", GimbalLockWarning)
        yield


# --- the presets ------------------------------------------------------------------------------


@given(angle_triples)
@settings(max_examples=examples(60), deadline=None)
def test_aerospace_to_rose_relabelled_flips_yaw_and_pitch(
    angles: tuple[float, float, float],
) -> None:
    """NED body axes (x forward, y right, z down) and z-up axes differ by a half turn about x."""
    ned = scipy_matrix("ZYX", list(angles))
    flip = np.diag([1.0, -1.0, -1.0])  # typed in: y and z change sign
    expected = Rotation.from_matrix(flip @ ned @ flip.T).as_euler("ZYX", degrees=True)
    got = convert_angles(list(angles), "aerospace", "rose", degrees=True, relabel=True)
    assert_allclose(
        angles_to_matrix(got, "ZYX", degrees=True), scipy_matrix("ZYX", expected), atol=1e-12
    )
    yaw, pitch, roll = angles
    assert_allclose(got, [-yaw, -pitch, roll], atol=1e-9)


def test_preset_fields() -> None:
    rose, baker, ros = CONVENTIONS["rose"], CONVENTIONS["baker"], CONVENTIONS["ros"]
    assert (rose.seq, rose.angle_names, rose.up_axis) == ("ZYX", ("yaw", "pitch", "roll"), "z")
    assert (baker.seq, baker.angle_names, baker.up_axis) == (
        "YZX",
        ("heading", "attitude", "bank"),
        "y",
    )
    assert (ros.seq, ros.angle_names, ros.up_axis) == ("xyz", ("roll", "pitch", "yaw"), "z")
    aerospace = CONVENTIONS["aerospace"]
    assert CONVENTIONS["nasa"] is aerospace
    assert (aerospace.seq, aerospace.angle_names, aerospace.up_axis) == (
        "ZYX",
        ("yaw", "pitch", "roll"),
        "-z",
    )
    for convention in CONVENTIONS.values():
        assert convention.description


@given(angle_triples)
@settings(max_examples=examples(60), deadline=None)
def test_rose_is_scipy_intrinsic_zyx(angles: tuple[float, float, float]) -> None:
    yaw, pitch, roll = angles
    expected = scipy_matrix("ZYX", [yaw, pitch, roll])
    assert_allclose(
        angles_to_matrix([yaw, pitch, roll], "rose", degrees=True), expected, atol=1e-14
    )
    recovered = matrix_to_angles(expected, "rose", degrees=True)
    assert_allclose(wrapped_difference(recovered, [yaw, pitch, roll]), 0.0, atol=1e-9)


@given(angle_triples)
@settings(max_examples=examples(60), deadline=None)
def test_ros_is_scipy_extrinsic_xyz(angles: tuple[float, float, float]) -> None:
    roll, pitch, yaw = angles[2], angles[1], angles[0]
    expected = scipy_matrix("xyz", [roll, pitch, yaw])
    assert_allclose(angles_to_matrix([roll, pitch, yaw], "ros", degrees=True), expected, atol=1e-14)
    # the same matrix as Rose's with the argument order reversed
    assert_allclose(scipy_matrix("ZYX", [yaw, pitch, roll]), expected, atol=1e-14)
    recovered = matrix_to_angles(expected, "ros", degrees=True)
    assert_allclose(wrapped_difference(recovered, [roll, pitch, yaw]), 0.0, atol=1e-9)


def test_ros_matches_the_rpy_matrix_written_out() -> None:
    """The roll-pitch-yaw matrix as robotics code writes it entry by entry (tf's setRPY)."""
    rng = np.random.default_rng(7)
    for roll, pitch, yaw in rng.uniform(-np.pi, np.pi, size=(20, 3)):
        cr, sr = np.cos(roll), np.sin(roll)
        cp, sp = np.cos(pitch), np.sin(pitch)
        cy, sy = np.cos(yaw), np.sin(yaw)
        written = np.array(
            [
                [cp * cy, sp * sr * cy - cr * sy, sp * cr * cy + sr * sy],
                [cp * sy, sp * sr * sy + cr * cy, sp * cr * sy - sr * cy],
                [-sp, cp * sr, cp * cr],
            ]
        )
        assert_allclose(angles_to_matrix([roll, pitch, yaw], "ros"), written, atol=1e-14)


@given(angle_triples)
@settings(max_examples=examples(60), deadline=None)
def test_baker_is_scipy_intrinsic_yzx(angles: tuple[float, float, float]) -> None:
    expected = scipy_matrix("YZX", angles)
    assert_allclose(angles_to_matrix(angles, "baker", degrees=True), expected, atol=1e-14)
    recovered = matrix_to_angles(expected, "baker", degrees=True)
    assert_allclose(wrapped_difference(recovered, angles), 0.0, atol=1e-9)


def test_baker_matrix_written_out() -> None:
    """Baker's matrix, entry by entry as his page gives it."""
    h, a, b = np.radians([35.0, -20.0, 70.0])
    ch, sh, ca, sa, cb, sb = np.cos(h), np.sin(h), np.cos(a), np.sin(a), np.cos(b), np.sin(b)
    written = np.array(
        [
            [ch * ca, -ch * sa * cb + sh * sb, ch * sa * sb + sh * cb],
            [sa, ca * cb, -ca * sb],
            [-sh * ca, sh * sa * cb + ch * sb, -sh * sa * sb + ch * cb],
        ]
    )
    assert_allclose(angles_to_matrix([h, a, b], "baker"), written, atol=1e-15)


@pytest.mark.parametrize("attitude", [90.0, -90.0])
@pytest.mark.parametrize("heading, bank", [(40.0, 10.0), (-120.0, 75.0), (170.0, 30.0)])
def test_baker_poles_keep_bakers_policy(attitude: float, heading: float, bank: float) -> None:
    R = scipy_matrix("YZX", [heading, attitude, bank])
    with pytest.warns(GimbalLockWarning, match=r"bank \(angle 3\) was set to 0"):
        h, a, b = matrix_to_angles(R, "baker", degrees=True)
    assert b == 0.0
    assert a == pytest.approx(attitude, abs=1e-12)
    # Baker's pole formula: heading = atan2(m02, m22)
    assert wrapped_difference(h, np.degrees(np.arctan2(R[0, 2], R[2, 2]))) == pytest.approx(
        0.0, abs=1e-9
    )
    assert_allclose(scipy_matrix("YZX", [h, a, b]), R, atol=1e-12)


def test_baker_batch_mixes_poles_and_ordinary_attitudes() -> None:
    hab = np.array([[40.0, 90.0, 10.0], [170.0, -90.0, -30.0], [-20.0, 35.0, 60.0]])
    R = scipy_matrix("YZX", hab).reshape(3, 1, 3, 3)
    with pytest.warns(GimbalLockWarning, match="gimbal lock in 2 of 3 rotation"):
        angles = matrix_to_angles(R, "baker", degrees=True)
    assert angles.shape == (3, 1, 3)
    assert_allclose(angles[:, 0, 2], [0.0, 0.0, 60.0], atol=1e-9)
    # Baker's pole rule: heading = atan2(m02, m22); away from the poles the angles come back
    pole_heading = np.degrees(np.arctan2(R[:2, 0, 0, 2], R[:2, 0, 2, 2]))
    assert_allclose(wrapped_difference(angles[:2, 0, 0], pole_heading), 0.0, atol=1e-9)
    assert_allclose(angles[2, 0], hab[2], atol=1e-9)
    assert_allclose(scipy_matrix("YZX", angles.reshape(3, 3)), R.reshape(3, 3, 3), atol=1e-12)


@pytest.mark.parametrize("pitch", [90.0, -90.0])
def test_rose_and_ros_zero_yaw_at_lock(pitch: float) -> None:
    R = scipy_matrix("ZYX", [30.0, pitch, 10.0])
    with pytest.warns(GimbalLockWarning, match=r"yaw \(angle [13]\) was set to 0"):
        yaw, _, roll = matrix_to_angles(R, "rose", degrees=True)
    with pytest.warns(GimbalLockWarning, match=r"yaw \(angle [13]\) was set to 0"):
        ros_roll, _, ros_yaw = matrix_to_angles(R, "ros", degrees=True)
    assert yaw == 0.0
    assert ros_yaw == 0.0
    assert ros_roll == pytest.approx(roll, abs=1e-12)
    assert_allclose(scipy_matrix("ZYX", [yaw, pitch, roll]), R, atol=1e-12)


@given(st.sampled_from(ALL_SEQUENCES), finite_angle, finite_angle, st.booleans())
@settings(max_examples=examples(100), deadline=None)
def test_either_outer_angle_can_be_zeroed_at_lock(
    seq: str, first: float, third: float, high: bool
) -> None:
    proper = seq[0].lower() == seq[2].lower()
    middle = (180.0 if high else 0.0) if proper else (90.0 if high else -90.0)
    R = scipy_matrix(seq, [first, middle, third])
    for zeroed, position in (("first", 0), ("third", 2)):
        convention = Convention("test", seq, ("a", "b", "c"), None, "for the test", zeroed)
        angles = matrix_to_angles(R, convention, degrees=True, warn=False)
        assert angles[position] == 0.0
        assert_allclose(scipy_matrix(seq, angles), R, atol=1e-12)


# --- the translator ---------------------------------------------------------------------------


@given(any_convention, any_convention, angle_triples)
@settings(max_examples=examples(150), deadline=None)
def test_convert_angles_gives_the_same_matrix_as_scipy(
    source: str, target: str, angles: tuple[float, float, float]
) -> None:
    source_seq, target_seq = get_convention(source).seq, get_convention(target).seq
    values = list(angles)
    if source_seq[0].lower() == source_seq[2].lower():  # proper Euler: middle in [0, 180]
        values[1] = abs(values[1]) + 1.0
    with quiet_lock():
        result = convert_angles(values, source, target, degrees=True)
    expected = scipy_matrix(source_seq, values)
    assert_allclose(scipy_matrix(target_seq, result), expected, atol=1e-12)


@given(preset_names, preset_names, angle_triples)
@settings(max_examples=examples(100), deadline=None)
def test_round_trip_returns_the_angles(
    source: str, target: str, angles: tuple[float, float, float]
) -> None:
    with quiet_lock():
        there = convert_angles(angles, source, target, degrees=True)
        back = convert_angles(there, target, source, degrees=True)
    assert_allclose(wrapped_difference(back, angles), 0.0, atol=1e-9)


def test_convert_is_vectorized_over_leading_axes() -> None:
    rng = np.random.default_rng(3)
    angles = rng.uniform(-80.0, 80.0, size=(4, 5, 3))
    result = convert_angles(angles, "baker", "ros", degrees=True)
    assert result.shape == (4, 5, 3)
    expected = Rotation.from_euler("YZX", angles.reshape(-1, 3), degrees=True).as_euler(
        "xyz", degrees=True
    )
    assert_allclose(result.reshape(-1, 3), expected, atol=1e-10)


def test_radians_and_degrees_agree() -> None:
    degrees = convert_angles([50.0, 20.0, -35.0], "rose", "baker", degrees=True)
    radians = convert_angles(np.radians([50.0, 20.0, -35.0]), "rose", "baker")
    assert_allclose(np.radians(degrees), radians, atol=1e-14)


def test_convert_warns_at_lock_and_points_at_the_caller() -> None:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        convert_angles([10.0, 90.0, 0.0], "ros", "rose", degrees=True)
    assert len(caught) == 1
    assert caught[0].category is GimbalLockWarning
    assert "pitch is at 90°" in str(caught[0].message)
    assert caught[0].message.combinations == {90: "roll - yaw"}
    assert caught[0].filename == __file__
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        convert_angles([10.0, 90.0, 0.0], "ros", "rose", degrees=True, warn=False)


def test_same_matrix_different_numbers() -> None:
    """Baker's (h, a, b) read as Rose's would be another rotation; the translator fixes that."""
    hab = [40.0, 25.0, -15.0]
    R = scipy_matrix("YZX", hab)
    assert not np.allclose(scipy_matrix("ZYX", hab), R)
    ypr = convert_angles(hab, "baker", "rose", degrees=True)
    assert_allclose(scipy_matrix("ZYX", ypr), R, atol=1e-13)


# --- up axes ----------------------------------------------------------------------------------


def test_up_axis_matrix_is_a_rotation_that_keeps_the_nose() -> None:
    P = up_axis_matrix("y", "z")
    assert_allclose(P, scipy_matrix("x", 90.0), atol=1e-15)
    assert np.linalg.det(P) == pytest.approx(1.0)
    assert_allclose(P @ [1.0, 0.0, 0.0], [1.0, 0.0, 0.0])  # forward stays forward
    assert_allclose(P @ [0.0, 1.0, 0.0], [0.0, 0.0, 1.0])  # up becomes up
    assert_allclose(up_axis_matrix("z", "y"), P.T)
    assert_allclose(up_axis_matrix("Z", "z"), np.eye(3))


@given(angle_triples, angle_triples)
@settings(max_examples=examples(60), deadline=None)
def test_change_up_axis_properties(
    a: tuple[float, float, float], b: tuple[float, float, float]
) -> None:
    R1, R2 = scipy_matrix("ZYX", a), scipy_matrix("ZYX", b)
    moved = change_up_axis(R1, "y", "z")
    # still a rotation, by the same angle (same trace), about the relabelled axis
    assert_allclose(moved @ moved.T, np.eye(3), atol=1e-14)
    assert np.trace(moved) == pytest.approx(np.trace(R1), abs=1e-13)
    P = scipy_matrix("x", 90.0)
    axis_before = Rotation.from_matrix(R1).as_rotvec()
    axis_after = Rotation.from_matrix(moved).as_rotvec()
    assert_allclose(axis_after, P @ axis_before, atol=1e-9)
    # a change of frame respects products and undoes itself
    assert_allclose(
        change_up_axis(R1 @ R2, "y", "z"), moved @ change_up_axis(R2, "y", "z"), atol=1e-13
    )
    assert_allclose(change_up_axis(moved, "z", "y"), R1, atol=1e-14)
    assert_allclose(change_up_axis(R1, "z", "z"), R1, atol=0.0)


@given(angle_triples)
@settings(max_examples=examples(60), deadline=None)
def test_baker_relabelled_is_rose_with_pitch_negated(angles: tuple[float, float, float]) -> None:
    heading, attitude, bank = angles
    R_baker = scipy_matrix("YZX", [heading, attitude, bank])
    R_z_up = scipy_matrix("x", 90.0) @ R_baker @ scipy_matrix("x", 90.0).T
    assert_allclose(change_up_axis(R_baker, "y", "z"), R_z_up, atol=1e-14)
    assert_allclose(R_z_up, scipy_matrix("ZYX", [heading, -attitude, bank]), atol=1e-14)
    ypr = convert_angles([heading, attitude, bank], "baker", "rose", degrees=True, relabel=True)
    assert_allclose(wrapped_difference(ypr, [heading, -attitude, bank]), 0.0, atol=1e-9)


def test_change_up_axis_is_vectorized() -> None:
    R = scipy_matrix("ZYX", np.random.default_rng(5).uniform(-90, 90, size=(6, 3)))
    stacked = change_up_axis(R.reshape(2, 3, 3, 3), "z", "y")
    assert stacked.shape == (2, 3, 3, 3)
    assert_allclose(stacked.reshape(6, 3, 3)[4], change_up_axis(R[4], "z", "y"))


# --- bad input --------------------------------------------------------------------------------


def test_names_are_case_insensitive_and_sequences_are_not() -> None:
    assert get_convention("ROSE") is CONVENTIONS["rose"]
    assert get_convention(" Baker ") is CONVENTIONS["baker"]
    assert get_convention("ZYX").seq == "ZYX"
    assert get_convention("zyx").seq == "zyx"
    assert get_convention(CONVENTIONS["ros"]) is CONVENTIONS["ros"]


@pytest.mark.parametrize("bad", ["rsoe", "ZYZX", "XyZ", "xxy", "", "abc"])
def test_unknown_names_list_presets_and_sequences(bad: str) -> None:
    with pytest.raises(ValueError, match="is neither a preset") as error:
        get_convention(bad)
    assert "rose" in str(error.value)
    assert "baker" in str(error.value)
    assert "ZYX, " in str(error.value)


@pytest.mark.parametrize("bad", [3, None, ("Z", "Y", "X")])
def test_non_strings_are_a_type_error(bad: object) -> None:
    with pytest.raises(TypeError, match="a preset name such as 'rose' or an axis sequence"):
        get_convention(bad)  # type: ignore[arg-type]


def test_bad_inputs_to_the_translator() -> None:
    with pytest.raises(ValueError, match="shape"):
        convert_angles([1.0, 2.0], "rose", "baker")
    with pytest.raises(TypeError, match="text"):
        convert_angles("30 20 10", "rose", "baker")
    with pytest.raises(ValueError, match="to 'bakr' is neither a preset"):
        convert_angles([1.0, 2.0, 3.0], "rose", "bakr")
    with pytest.raises(ValueError, match="needs an up axis"):
        convert_angles([1.0, 2.0, 3.0], "ZYX", "baker", relabel=True)
    with pytest.raises(ValueError, match="'y' or 'z'"):
        up_axis_matrix("x", "z")
    with pytest.raises(ValueError, match="reflection"):
        change_up_axis(np.diag([1.0, 1.0, -1.0]))
    odd = Convention("odd", "ZYX", ("a", "b", "c"), None, "zeroes the middle", "middle")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="lock_zeroes must be 'first' or 'third'"):
        matrix_to_angles(np.eye(3), odd)
    twice = Convention("twice", "ZYX", ("a", "a", "c"), None, "one name twice", "first")
    with pytest.raises(ValueError, match="angle_names must be three different"):
        angles_to_matrix([0.0, 0.0, 0.0], twice)
