"""The rules every public function follows: one set of argument checks, one meaning per keyword.

The functions are found by introspecting ``eulerlib.__all__``, so a function added later is held
to the same rules without touching this file. Each bug the 0.2 release fixed has a test here
that failed before the fix.
"""

from __future__ import annotations

import inspect
import json
import math
import tracemalloc
import warnings
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest
from command_line import run_in_process
from compiled import numpy_only
from numpy.testing import assert_allclose
from scipy.spatial.transform import Rotation

import eulerlib
from conftest import SEED
from eulerlib import (
    ALL_SEQUENCES,
    GIMBAL_LOCK_TOLERANCE,
    GimbalLockWarning,
    change_up_axis,
    convert_angles,
    euler_to_matrix,
    gimbal_lock_status,
    is_rotation_matrix,
    lock_combination,
    matrix_to_euler,
    nearest_rotation,
    rot_x,
    rot_y,
    rot_z,
)

PUBLIC = {name: getattr(eulerlib, name) for name in eulerlib.__all__}
FUNCTIONS = {name: f for name, f in PUBLIC.items() if inspect.isfunction(f)}

#: One valid call of every public function, as (positional arguments, keyword arguments).
R0 = Rotation.from_euler("ZYX", [0.3, 0.2, 0.1]).as_matrix()
Q0 = Rotation.from_euler("ZYX", [0.3, 0.2, 0.1]).as_quat()
VALID_CALLS: dict[str, tuple[tuple[Any, ...], dict[str, Any]]] = {
    "align_vectors": (([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], [[0.0, 1.0, 0.0], [1.0, 0.0, 0.0]]), {}),
    "angle_between": ((R0, R0.T), {}),
    "angular_velocity_to_euler_rates": (([0.1, 0.2, 0.3], [1.0, 2.0, 3.0]), {}),
    "axis_angle_to_matrix": (([0.0, 0.0, 1.0], 0.5), {}),
    "change_up_axis": ((R0,), {}),
    "compose": ((R0, R0), {}),
    "convert_angles": (([0.1, 0.2, 0.3], "rose", "baker"), {}),
    "elementary_rotation": (("x", 0.5), {}),
    "euler_rates_to_angular_velocity": (([0.1, 0.2, 0.3], [1.0, 2.0, 3.0]), {}),
    "euler_to_matrix": (([0.1, 0.2, 0.3],), {}),
    "euler_to_quaternion": (([0.1, 0.2, 0.3],), {}),
    "get_convention": (("rose",), {}),
    "gimbal_lock_status": ((R0,), {}),
    "heading_attitude_bank_to_matrix": ((0.1, 0.2, 0.3), {}),
    "integrate_angular_velocity": ((R0, [1.0, 2.0, 3.0], 0.01), {}),
    "invert": ((R0,), {}),
    "is_rotation_matrix": ((R0,), {}),
    "lock_combination": (("rose", 90), {}),
    "matrix_to_axis_angle": ((R0,), {}),
    "matrix_to_euler": ((R0,), {}),
    "matrix_to_quaternion": ((R0,), {}),
    "matrix_to_rotvec": ((R0,), {}),
    "matrix_to_heading_attitude_bank": ((R0,), {}),
    "matrix_to_yaw_pitch_roll": ((R0,), {}),
    "mean_rotation": ((np.stack([R0, R0.T]),), {}),
    "nearest_rotation": ((R0,), {}),
    "parse_axis": (("x",), {}),
    "parse_sequence": (("ZYX",), {}),
    "quaternion_conjugate": ((Q0,), {}),
    "quaternion_exp": (([0.1, 0.2, 0.3],), {}),
    "quaternion_inverse": ((Q0,), {}),
    "quaternion_log": ((Q0,), {}),
    "quaternion_multiply": ((Q0, Q0), {}),
    "quaternion_power": ((Q0, 0.5), {}),
    "quaternion_to_euler": ((Q0,), {}),
    "quaternion_to_matrix": ((Q0,), {}),
    "random_rotations": ((3,), {"rng": 1}),
    "rot_x": ((0.5,), {}),
    "rot_y": ((0.5,), {}),
    "rot_z": ((0.5,), {}),
    "rotate_points": ((R0, [1.0, 2.0, 3.0]), {}),
    "rotation_angle": ((R0,), {}),
    "rotvec_to_matrix": (([0.1, 0.2, 0.3],), {}),
    "slerp": ((R0, R0.T, [0.0, 0.5, 1.0]), {}),
    "up_axis_matrix": (("y", "z"), {}),
    "yaw_pitch_roll_to_matrix": ((0.1, 0.2, 0.3), {}),
}

FLAGS = ("degrees", "validate", "repair", "warn", "relabel", "scalar_first")
TOLERANCES = ("atol", "tolerance")
MATRIX_KEYWORDS = ("validate", "repair", "atol")


def keywords_of(function: Callable[..., Any]) -> set[str]:
    return {
        name
        for name, parameter in inspect.signature(function).parameters.items()
        if parameter.kind is inspect.Parameter.KEYWORD_ONLY
    }


def test_every_public_function_has_a_valid_call_here() -> None:
    assert set(VALID_CALLS) == set(FUNCTIONS)
    for name, (args, kwargs) in VALID_CALLS.items():
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            FUNCTIONS[name](*args, **kwargs)


def test_everything_public_is_documented_with_an_example() -> None:
    for name, value in PUBLIC.items():
        if inspect.isfunction(value) or inspect.isclass(value):
            doc = inspect.getdoc(value) or ""
            assert doc, f"{name} has no docstring"
        if inspect.isfunction(value):
            assert "Examples" in doc, f"{name} has no Examples section"


# --- flags and tolerances ----------------------------------------------------------------------


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
@pytest.mark.parametrize("bad", ["no", "", 1, 0, None, 1.0, np.array(True), [True]])
def test_flags_accept_bools_only(name: str, bad: object) -> None:
    function = FUNCTIONS[name]
    args, kwargs = VALID_CALLS[name]
    for flag in keywords_of(function) & set(FLAGS):
        with pytest.raises(TypeError, match=rf"^{flag} must be True or False, got "):
            function(*args, **kwargs, **{flag: bad})
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", GimbalLockWarning)
            function(*args, **kwargs, **{flag: np.False_})  # NumPy's bools are fine


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
@pytest.mark.parametrize(
    ("bad", "error", "words"),
    [
        (float("nan"), ValueError, "must be a finite number ≥ 0, got nan"),
        (float("inf"), ValueError, "must be a finite number ≥ 0, got inf"),
        (-1.0, ValueError, "must be a finite number ≥ 0, got -1.0"),
        (10**400, ValueError, "must be a finite number ≥ 0"),
        (None, TypeError, "must be a real number, got None"),
        ("1e-6", TypeError, "must be a real number, got '1e-6'"),
        (True, TypeError, "must be a real number, got True"),
        (1j, TypeError, "must be a real number"),
    ],
)
def test_tolerances_are_finite_numbers_at_least_zero(
    name: str, bad: object, error: type[Exception], words: str
) -> None:
    function = FUNCTIONS[name]
    args, kwargs = VALID_CALLS[name]
    for keyword in keywords_of(function) & set(TOLERANCES):
        if bad is None and inspect.signature(function).parameters[keyword].default is None:
            continue  # None is this keyword's documented default
        with pytest.raises(error, match=rf"^{keyword} {words}"):
            function(*args, **kwargs, **{keyword: bad})


def test_nan_tolerance_no_longer_accepts_the_zero_matrix() -> None:
    with pytest.raises(ValueError, match="atol must be a finite number"):
        is_rotation_matrix(np.zeros((3, 3)), atol=float("nan"))
    assert not is_rotation_matrix(np.zeros((3, 3)))


# --- the same keywords everywhere ----------------------------------------------------------------


def test_every_function_that_takes_matrices_takes_validate_repair_atol() -> None:
    for name, function in FUNCTIONS.items():
        first = next(iter(inspect.signature(function).parameters))
        if first in ("R", "rotations") and name not in ("is_rotation_matrix", "nearest_rotation"):
            assert set(MATRIX_KEYWORDS) <= keywords_of(function), name


def test_every_function_that_takes_or_returns_angles_takes_degrees() -> None:
    with_angles = {
        "angle_between",
        "angular_velocity_to_euler_rates",
        "axis_angle_to_matrix",
        "convert_angles",
        "elementary_rotation",
        "euler_rates_to_angular_velocity",
        "euler_to_matrix",
        "gimbal_lock_status",
        "heading_attitude_bank_to_matrix",
        "euler_to_quaternion",
        "integrate_angular_velocity",
        "matrix_to_axis_angle",
        "matrix_to_euler",
        "matrix_to_heading_attitude_bank",
        "matrix_to_rotvec",
        "matrix_to_yaw_pitch_roll",
        "quaternion_to_euler",
        "rot_x",
        "rot_y",
        "rot_z",
        "rotation_angle",
        "rotvec_to_matrix",
        "yaw_pitch_roll_to_matrix",
    }
    for name in with_angles:
        assert "degrees" in keywords_of(FUNCTIONS[name]), name


def test_repair_works_in_invert_compose_rotate_and_change_up_axis(rng) -> None:
    M = Rotation.random(5, rng=rng).as_matrix() + 1e-4 * rng.normal(size=(5, 3, 3))
    Q = nearest_rotation(M)
    assert_allclose(eulerlib.invert(M, repair=True), np.swapaxes(Q, -1, -2), atol=1e-15)
    assert_allclose(eulerlib.compose(M, M, repair=True), Q @ Q, atol=1e-14)
    assert_allclose(eulerlib.rotate_points(M, [1.0, 0.0, 0.0], repair=True), Q[..., 0], atol=1e-15)
    assert_allclose(change_up_axis(M, "y", "z", repair=True), change_up_axis(Q), atol=1e-15)
    with pytest.raises(ValueError, match="pass repair=True"):
        change_up_axis(M)


@pytest.mark.parametrize("preset", ["rose", "Baker", "ros", "aerospace"])
def test_a_preset_is_accepted_wherever_a_seq_is(preset: str, rng) -> None:
    convention = eulerlib.get_convention(preset)
    angles = rng.uniform(-1.0, 1.0, (4, 3))
    R = euler_to_matrix(angles, preset)
    assert_allclose(R, Rotation.from_euler(convention.seq, angles).as_matrix(), atol=1e-15)
    assert_allclose(matrix_to_euler(R, preset), angles, atol=1e-14)
    status = gimbal_lock_status(R, preset)
    assert status.locked.shape == (4,)
    assert_allclose(convert_angles(angles, preset, convention.seq), angles, atol=1e-14)


def test_baker_by_name_keeps_bakers_lock_policy() -> None:
    R = Rotation.from_euler("YZX", [40, 90, 10], degrees=True).as_matrix()
    with pytest.warns(GimbalLockWarning, match="bank"):
        by_preset = matrix_to_euler(R, "baker", degrees=True)
    with pytest.warns(GimbalLockWarning):
        by_seq = matrix_to_euler(R, "YZX", degrees=True)
    assert_allclose(by_preset, [50, 90, 0], atol=1e-12)  # Baker: bank = 0
    assert_allclose(by_seq, [0, 90, 50], atol=1e-12)  # eulerlib's rule: the first angle


# --- return types --------------------------------------------------------------------------------


def test_named_functions_return_named_tuples_of_arrays() -> None:
    ypr = eulerlib.matrix_to_yaw_pitch_roll(R0)
    assert isinstance(ypr, eulerlib.YawPitchRoll)
    assert ypr._fields == ("yaw", "pitch", "roll")
    assert all(isinstance(v, np.ndarray) and v.shape == () for v in ypr)
    hab = eulerlib.matrix_to_heading_attitude_bank(np.stack([R0, R0]))
    assert isinstance(hab, eulerlib.HeadingAttitudeBank)
    assert all(isinstance(v, np.ndarray) and v.shape == (2,) for v in hab)
    assert_allclose(eulerlib.yaw_pitch_roll_to_matrix(*ypr), R0, atol=1e-15)


def test_one_matrix_in_gives_0d_arrays_out() -> None:
    for degrees in (False, True):
        status = gimbal_lock_status(R0, degrees=degrees)
        assert isinstance(status, eulerlib.GimbalLockStatus)
        for value in status:
            assert isinstance(value, np.ndarray) and value.shape == ()
    result = is_rotation_matrix(R0)
    assert isinstance(result, np.ndarray) and result.shape == ()


# --- bugs of 0.1, each with the test that failed before the fix ----------------------------------


def test_lock_flag_does_not_depend_on_the_unit() -> None:
    R = euler_to_matrix([0.0, math.pi / 2 - 1e-15, 0.0])
    in_radians = gimbal_lock_status(R)
    in_degrees = gimbal_lock_status(R, degrees=True)
    assert bool(in_radians.locked) and bool(in_degrees.locked)
    assert_allclose(in_degrees.distance, np.degrees(in_radians.distance), rtol=1e-15)
    with pytest.warns(GimbalLockWarning):
        matrix_to_euler(R)
    # a tolerance given by the caller is read in the unit of the distance
    assert bool(gimbal_lock_status(euler_to_matrix([0, 89.5, 0], degrees=True), degrees=True,
                                   tolerance=0.6).locked)  # fmt: skip
    assert not gimbal_lock_status(euler_to_matrix([0, 89.5, 0], degrees=True), tolerance=0.0).locked


@pytest.mark.parametrize("turns", [10**17, 10**20, 10**300, -(10**19) + 7, 2**60 + 45])
def test_huge_angles_in_degrees_keep_the_rotation(turns: int) -> None:
    # the oracle: Python's exact integer arithmetic on the value the float holds, then SciPy on
    # an angle below 360°
    reduced = math.radians(int(float(turns)) % 360)
    expected = Rotation.from_euler("z", reduced).as_matrix()
    assert_allclose(euler_to_matrix([turns, 0, 0], "ZYX", degrees=True), expected, atol=1e-15)
    assert_allclose(euler_to_matrix([float(turns), 0, 0], degrees=True), expected, atol=1e-15)
    assert_allclose(rot_z(float(turns), degrees=True), expected, atol=1e-15)
    assert_allclose(
        rot_x(turns, degrees=True), Rotation.from_euler("x", reduced).as_matrix(), atol=1e-15
    )
    assert_allclose(
        rot_y(turns, degrees=True), Rotation.from_euler("y", reduced).as_matrix(), atol=1e-15
    )


def test_the_command_line_reduces_huge_degrees_too() -> None:
    result = run_in_process("convert", "--from", "rose", "--to", "rose", "--degrees", "--json",
                            "1e20", "0", "0")  # fmt: skip
    assert result.returncode == 0, result.stderr
    report = json.loads(result.stdout)
    assert_allclose(report["conversions"][0]["angles"], [-80, 0, 0], atol=1e-12)  # 280° = −80°


@pytest.mark.parametrize("huge", [10**400, [0, 10**400, 0], -(10**309)])
def test_numbers_too_large_for_a_float_are_a_value_error(huge: object) -> None:
    with pytest.raises(ValueError, match="too large for a float"):
        euler_to_matrix(huge if isinstance(huge, list) else [huge, 0, 0], degrees=True)
    with pytest.raises(ValueError, match="too large for a float"):
        rot_x(huge)


@pytest.mark.parametrize(
    ("matrix", "words"),
    [
        (np.zeros((3, 3)), r"is singular \(rank 0, singular values 0, 0, 0\)"),
        (np.outer([1.0, 0, 0], [0, 1.0, 0]), r"is singular \(rank 1"),
        (np.diag([1.0, 1.0, 0.0]), r"is singular \(rank 2"),
        (2 * np.eye(3), r"is too far from a rotation to repair: .*by up to 1, more than 0.1"),
        (np.diag([1.0, 1.0, 0.5]), r"is too far .* by up to 0.5"),
    ],
)
def test_repair_refuses_matrices_with_no_nearest_rotation(matrix: np.ndarray, words: str) -> None:
    for call in (
        lambda: nearest_rotation(matrix),
        lambda: matrix_to_euler(matrix, repair=True),
        lambda: eulerlib.invert(matrix, repair=True),
        lambda: gimbal_lock_status(matrix, repair=True),
    ):
        with pytest.raises(ValueError, match=words):
            call()
    stack = np.stack([np.eye(3), np.eye(3), matrix])
    with pytest.raises(ValueError, match=rf"R at index \(2,\) {words}"):
        matrix_to_euler(stack, repair=True)


def test_the_command_line_refuses_an_unrepairable_matrix() -> None:
    result = run_in_process("convert", "--to", "rose", "--repair",
                            "--matrix", "0", "0", "0", "0", "0", "0", "0", "0", "0")  # fmt: skip
    assert result.returncode == 1
    assert "singular" in result.stderr and "Traceback" not in result.stderr


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda m: matrix_to_euler(m), "R"),
        (lambda m: is_rotation_matrix(m), "R"),
        (lambda m: eulerlib.rotate_points(np.eye(3), m[0]), "points"),
        (lambda m: euler_to_matrix(m[0]), "angles"),
        (lambda m: rot_x(m[0, 0]), "angle"),
        (lambda m: eulerlib.yaw_pitch_roll_to_matrix(m[0, 0], 0, 0), "yaw"),
    ],
)
def test_masked_arrays_are_refused(call: Callable[[Any], Any], name: str) -> None:
    masked = np.ma.masked_array(np.eye(3), mask=np.eye(3, dtype=bool))
    with pytest.raises(TypeError, match=rf"^{name} is a masked array.*fill .*first"):
        call(masked)


def test_is_rotation_matrix_of_huge_entries_says_false_without_a_warning() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert not is_rotation_matrix(1e200 * np.eye(3))
        assert not is_rotation_matrix(np.full((3, 3), np.nan))
        assert list(is_rotation_matrix(np.stack([np.eye(3), 1e300 * np.eye(3)]))) == [True, False]


# --- the lock policy in one place ------------------------------------------------------------


@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_lock_combination_is_what_the_matrix_keeps(seq: str) -> None:
    """At each pole, moving the first angle by d and the third by −sign·d keeps SciPy's matrix."""
    proper = seq[0].lower() == seq[2].lower()
    for pole in (0, 180) if proper else (90, -90):
        sign, words = lock_combination(seq, pole)
        a, c, d = 25.0, -40.0, 17.0
        before = Rotation.from_euler(seq, [a, pole, c], degrees=True).as_matrix()
        after = Rotation.from_euler(seq, [a + d, pole, c - sign * d], degrees=True).as_matrix()
        assert_allclose(after, before, atol=1e-14)
        moved = Rotation.from_euler(seq, [a + d, pole, c + sign * d], degrees=True).as_matrix()
        assert not np.allclose(moved, before, atol=1e-6)
        names = eulerlib.get_convention(seq).angle_names
        assert names[0] in words and names[2] in words


def test_the_warning_carries_its_facts() -> None:
    R = euler_to_matrix([[30, 90, 10], [0, 0, 0], [5, -90, 5]], "rose", degrees=True)
    with pytest.warns(GimbalLockWarning) as record:
        matrix_to_euler(R, "rose")
    facts = record[0].message
    assert isinstance(facts, GimbalLockWarning)
    assert (facts.seq, facts.count, facts.total) == ("ZYX", 2, 3)
    assert (facts.zeroed, facts.carrier, facts.zeroed_position) == ("yaw", "roll", 0)
    assert facts.combinations == {90: "roll - yaw", -90: "yaw + roll"}
    assert "2 of 3" in str(facts)
    assert record[0].filename == __file__
    import pickle

    assert str(pickle.loads(pickle.dumps(facts))) == str(facts)


@pytest.mark.parametrize(
    ("pole", "error"),
    [(True, TypeError), ("90", TypeError), (None, TypeError), (45, ValueError), (0, ValueError)],
)
def test_lock_combination_checks_its_pole(pole: object, error: type[Exception]) -> None:
    with pytest.raises(error, match=r"^pole must be"):
        lock_combination("rose", pole)  # type: ignore[arg-type]


def test_lock_tolerance_is_the_documented_constant() -> None:
    assert GIMBAL_LOCK_TOLERANCE == 2.0**-49


# --- checked once, and no temporary as large as the input ----------------------------------


def test_convert_angles_checks_its_angles_once(monkeypatch: pytest.MonkeyPatch) -> None:
    from eulerlib import _validation

    calls: list[str] = []
    original = _validation.as_float_array

    def counting(value: Any, name: str) -> Any:
        calls.append(name)
        return original(value, name)

    monkeypatch.setattr(_validation, "as_float_array", counting)
    with numpy_only():  # the compiled kernels check the angles in C instead
        convert_angles(np.zeros((10, 3)), "rose", "baker")
    assert calls == ["angles"]


@pytest.fixture(scope="module")
def large_inputs() -> tuple[np.ndarray, ...]:
    """400 000 angles, their matrices and quaternions, made once and shared read-only.

    The values are those the seeded ``rng`` fixture draws, the same for every case; read-only,
    so no call can change what the next case is given.
    """
    rng = np.random.default_rng(SEED)
    n = 400_000
    angles = rng.uniform(-3.0, 3.0, (n, 3))
    R = euler_to_matrix(angles)
    q = rng.normal(size=(n, 4))
    for array in (angles, R, q):
        array.flags.writeable = False
    return angles, R, q


def peak_bytes(call: Callable[[], object]) -> int:
    """Peak of the memory NumPy allocates during ``call`` (NumPy reports to tracemalloc)."""
    tracemalloc.start()
    try:
        tracemalloc.reset_peak()
        call()
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


@pytest.mark.parametrize(
    ("name", "call", "output_bytes"),
    [
        ("convert_angles", lambda a, R, q: convert_angles(a, "rose", "baker"), 24),
        ("change_up_axis", lambda a, R, q: change_up_axis(R), 72),
        ("is_rotation_matrix", lambda a, R, q: is_rotation_matrix(R), 1),
        ("matrix_to_euler", lambda a, R, q: matrix_to_euler(R), 24),
        ("matrix_to_euler, extrinsic", lambda a, R, q: matrix_to_euler(R, "xyz"), 24),
        ("matrix_to_euler, degrees", lambda a, R, q: matrix_to_euler(R, "ros", degrees=True), 24),
        ("convert_angles, extrinsic", lambda a, R, q: convert_angles(a, "rose", "ros"), 24),
        (
            "quaternion_to_euler, extrinsic",
            lambda a, R, q: eulerlib.quaternion_to_euler(q, "xyz", degrees=True),
            24,
        ),
        ("euler_to_matrix", lambda a, R, q: euler_to_matrix(a), 72),
        ("gimbal_lock_status", lambda a, R, q: gimbal_lock_status(R), 9),
        ("matrix_to_quaternion", lambda a, R, q: eulerlib.matrix_to_quaternion(R), 32),
        ("quaternion_to_matrix", lambda a, R, q: eulerlib.quaternion_to_matrix(q), 72),
        ("quaternion_to_euler", lambda a, R, q: eulerlib.quaternion_to_euler(q), 24),
        ("euler_to_quaternion", lambda a, R, q: eulerlib.euler_to_quaternion(a), 32),
        ("matrix_to_rotvec", lambda a, R, q: eulerlib.matrix_to_rotvec(R), 24),
        ("rotvec_to_matrix", lambda a, R, q: eulerlib.rotvec_to_matrix(a), 72),
        ("matrix_to_axis_angle", lambda a, R, q: eulerlib.matrix_to_axis_angle(R), 32),
        ("axis_angle_to_matrix", lambda a, R, q: eulerlib.axis_angle_to_matrix(a, a[:, 0]), 72),
        ("rotation_angle", lambda a, R, q: eulerlib.rotation_angle(R), 8),
        ("angle_between", lambda a, R, q: eulerlib.angle_between(R, R[::-1]), 8),
        ("slerp", lambda a, R, q: eulerlib.slerp(R, R[::-1], a[:, 0]), 72),
        ("slerp, one pair", lambda a, R, q: eulerlib.slerp(R[0], R[1], a[:, 0]), 72),
        (
            "euler_rates_to_angular_velocity",
            lambda a, R, q: eulerlib.euler_rates_to_angular_velocity(a, q[:, :3]),
            24,
        ),
        (
            "angular_velocity_to_euler_rates",
            lambda a, R, q: eulerlib.angular_velocity_to_euler_rates(a, q[:, :3]),
            24,
        ),
        (
            "integrate_angular_velocity",
            lambda a, R, q: eulerlib.integrate_angular_velocity(R, a, a[:, 0]),
            72,
        ),
        ("quaternion_multiply", lambda a, R, q: eulerlib.quaternion_multiply(q, q[::-1]), 32),
        ("quaternion_conjugate", lambda a, R, q: eulerlib.quaternion_conjugate(q), 32),
        ("quaternion_inverse", lambda a, R, q: eulerlib.quaternion_inverse(q), 32),
        ("quaternion_exp", lambda a, R, q: eulerlib.quaternion_exp(a), 32),
        ("quaternion_log", lambda a, R, q: eulerlib.quaternion_log(q), 32),
        ("quaternion_power", lambda a, R, q: eulerlib.quaternion_power(q, a[:, 0]), 32),
        ("random_rotations", lambda a, R, q: eulerlib.random_rotations(len(a), rng=1), 72),
        ("mean_rotation", lambda a, R, q: eulerlib.mean_rotation(R), 0),
    ],
)
def test_no_temporary_as_large_as_the_input(
    name: str, call: Any, output_bytes: int, large_inputs: tuple[np.ndarray, ...]
) -> None:
    angles, R, q = large_inputs
    n = len(angles)
    peak = peak_bytes(lambda: call(angles, R, q))
    # the output, plus the temporaries of one block (16384 rotations): a few MB at most
    assert peak <= n * output_bytes + 6_000_000, f"{name}: peak {peak / 1e6:.1f} MB"


@pytest.mark.parametrize(
    "call",
    [
        lambda a, omega: eulerlib.angular_velocity_to_euler_rates(a, omega),
        lambda a, omega: eulerlib.angular_velocity_to_euler_rates(a, omega, "xyz", degrees=True),
    ],
)
def test_euler_rates_keep_nothing_per_rotation_beyond_the_output(
    call: Any, large_inputs: tuple[np.ndarray, ...]
) -> None:
    """Twice the rotations cost the output's 24 bytes per rotation more, and nothing else:
    the gimbal-lock warning is worded from a few numbers per block, not a mask of the batch."""
    angles, _, q = large_inputs
    half = len(angles) // 2
    smaller = peak_bytes(lambda: call(angles[:half], q[:half, :3]))
    larger = peak_bytes(lambda: call(angles, q[:, :3]))
    assert larger - smaller <= (len(angles) - half) * 24 + 1_000_000, larger - smaller
