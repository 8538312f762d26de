"""``eulerlib convert`` as a user runs it, checked against SciPy.

Most cases run the command line's entry function, :func:`eulerlib.cli.main`, in this process
(:func:`command_line.run_in_process`: its standard streams replaced, its exit status kept, its
warnings written to its standard error). The entry points themselves, ``python -m eulerlib``
and the ``eulerlib`` console script, add nothing but the process around ``main``, so they run
for real in a few representative cases: a conversion, a gimbal lock reported in words, and a
one-line failure.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from command_line import Outcome, Runner, real_process, run_in_process
from numpy.testing import assert_allclose

Rotation = pytest.importorskip("scipy.spatial.transform").Rotation

SCRIPT = Path(sys.executable).with_name("eulerlib")
PYTHON_M = [sys.executable, "-m", "eulerlib"]


#: Every way the command line is started; the representative cases run through each of them.
ENTRY_POINTS = [
    pytest.param(run_in_process, id="in-process"),
    pytest.param(real_process(PYTHON_M), id="python-m"),
]
if SCRIPT.exists():
    ENTRY_POINTS.append(pytest.param(real_process([str(SCRIPT)]), id="console-script"))


def convert(run: Runner, *args: str, stdin: str | None = None) -> Outcome:
    return run("convert", *args, stdin=stdin)


def convert_json(run: Runner, *args: str, stdin: str | None = None) -> Any:
    result = convert(run, "--json", *args, stdin=stdin)
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""
    return json.loads(result.stdout)


def assert_clean_failure(result: Outcome, *words: str) -> None:
    """Non-zero exit, nothing on stdout, no traceback, the message on one line."""
    assert result.returncode != 0
    assert "Traceback" not in result.stderr
    assert result.stdout == ""
    lines = result.stderr.strip().splitlines()
    assert lines, "no error message"
    assert lines[-1].startswith(("eulerlib convert: error:", "eulerlib: error:"))
    if result.returncode == 1:
        assert len(lines) == 1, result.stderr
    for word in words:
        assert word in lines[-1]


@pytest.fixture(params=ENTRY_POINTS)
def entry_point(request: pytest.FixtureRequest) -> Runner:
    """The command line started in each way it can be (a representative case)."""
    value: Runner = request.param
    return value


# --- angles in ----------------------------------------------------------------------------------


def test_rose_to_ros_and_baker_match_scipy(entry_point: Runner) -> None:
    report = convert_json(entry_point, "--from", "rose", "--to", "ros", "--to", "baker",
                          "--degrees", "30", "20", "10")  # fmt: skip
    R = Rotation.from_euler("ZYX", [30, 20, 10], degrees=True)
    assert_allclose(report["matrix"], R.as_matrix(), atol=1e-14)
    ros, baker = report["conversions"]
    assert ros["seq"] == "xyz"
    assert ros["angle_names"] == ["roll", "pitch", "yaw"]
    assert_allclose(ros["angles"], R.as_euler("xyz", degrees=True), atol=1e-10)
    assert_allclose(ros["angles"], [10, 20, 30], atol=1e-10)
    assert_allclose(baker["angles"], R.as_euler("YZX", degrees=True), atol=1e-10)
    assert not baker["gimbal_lock"]
    assert baker["distance_from_lock"] == pytest.approx(90 - abs(baker["angles"][1]))


@pytest.mark.parametrize(
    "angle_args",
    [
        ["--", "-30", "45", "10"],
        ["--angles=-30,45,10"],
        ["--angles", "-30 45 10"],
        ["-30", "45", "10"],
        ["--", "-30,", "45,", "10"],
    ],
    ids=["double-dash", "angles-equals", "angles-quoted", "bare", "commas"],
)
def test_negative_angles(angle_args: list[str]) -> None:
    report = convert_json(run_in_process, "--from", "rose", "--to", "xyz", "--degrees",
                          *angle_args)  # fmt: skip
    expected = Rotation.from_euler("ZYX", [-30, 45, 10], degrees=True)
    assert_allclose(report["matrix"], expected.as_matrix(), atol=1e-14)
    assert_allclose(report["conversions"][0]["angles"], [10, 45, -30], atol=1e-10)


@pytest.mark.parametrize("source", ["ZXZ", "yxy", "XZY", "baker"])
def test_sequences_in_radians_match_scipy(source: str) -> None:
    angles = [0.4, 1.1, -2.3]
    targets = {"zyz": "zyz", "YXZ": "YXZ", "ros": "xyz", "Baker": "YZX"}
    options = [word for name in targets for word in ("--to", name)]
    report = convert_json(run_in_process, "--from", source, *options, "--", *map(str, angles))
    source_seq = "YZX" if source == "baker" else source
    R = Rotation.from_euler(source_seq, angles)
    assert_allclose(report["matrix"], R.as_matrix(), atol=1e-14)
    assert report["degrees"] is False
    for conversion, seq in zip(report["conversions"], targets.values(), strict=True):
        assert conversion["seq"] == seq
        assert_allclose(conversion["angles"], R.as_euler(seq), atol=1e-10)


def test_text_output_names_the_angles() -> None:
    result = convert(run_in_process, "--from", "baker", "--to", "rose", "--degrees",
                     "40", "25", "-15")  # fmt: skip
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert lines[0] == "from baker (YZX): heading = 40°, attitude = 25°, bank = -15°"
    assert lines[1] == "rotation matrix:"
    printed = np.array([[float(x) for x in line.strip(" []").split()] for line in lines[2:5]])
    assert_allclose(printed, Rotation.from_euler("YZX", [40, 25, -15], degrees=True).as_matrix(),
                    atol=5e-7)  # fmt: skip
    assert lines[5].startswith("to rose (ZYX): yaw = ")
    assert lines[6].startswith("  distance from gimbal lock: ")


# --- gimbal lock ---------------------------------------------------------------------------------


def test_gimbal_lock_in_words(entry_point: Runner) -> None:
    result = convert(entry_point, "--from", "rose", "--to", "rose", "--degrees", "30", "90", "10")
    assert result.returncode == 0
    assert "Traceback" not in result.stderr
    assert "Warning" not in result.stderr
    assert "to rose (ZYX): yaw = 0°, pitch = 90°, roll = -20°" in result.stdout
    assert (
        "gimbal lock: the middle angle (pitch) is 90°, so yaw and roll turn about the same "
        "axis and only roll - yaw is defined; yaw was set to 0 and roll carries the whole turn"
    ) in result.stdout


def test_baker_pole_from_a_matrix() -> None:
    # attitude +90° (north pole): Baker keeps heading + bank in heading, bank = 0
    R = Rotation.from_euler("YZX", [40, 90, 10], degrees=True).as_matrix()
    numbers = ",".join(repr(float(x)) for x in R.ravel())
    report = convert_json(run_in_process, "--to", "baker", "--degrees", f"--matrix={numbers}")
    baker = report["conversions"][0]
    assert baker["gimbal_lock"] is True
    assert_allclose(baker["angles"], [50, 90, 0], atol=1e-9)
    assert "bank was set to 0 and heading carries the whole turn" in baker["note"]
    assert "heading + bank is defined" in baker["note"]


# --- matrix in -----------------------------------------------------------------------------------


def test_matrix_numbers() -> None:
    report = convert_json(run_in_process, "--to", "rose", "--to", "XYZ", "--degrees",
                          "--matrix", "0", "-1", "0", "1", "0", "0", "0", "0", "1")  # fmt: skip
    R = np.array([[0, -1, 0], [1, 0, 0], [0, 0, 1]], dtype=float)
    rose, xyz = report["conversions"]
    assert_allclose(rose["angles"], [90, 0, 0], atol=1e-12)
    expected = Rotation.from_matrix(R).as_euler("XYZ", degrees=True)
    assert_allclose(xyz["angles"], expected, atol=1e-10)


def test_matrix_file_and_stdin(tmp_path: Path) -> None:
    R = Rotation.from_euler("ZYX", [-70, 35, 120], degrees=True).as_matrix()
    text = "# a rotation, printed by numpy\n" + np.array2string(R, precision=17) + "\n"
    path = tmp_path / "rotation.txt"
    path.write_text(text, encoding="utf-8")
    from_file = convert_json(run_in_process, "--to", "ros", "--degrees",
                             "--matrix-file", str(path))  # fmt: skip
    from_stdin = convert_json(run_in_process, "--to", "ros", "--degrees", "--matrix-file", "-",
                              stdin=text)  # fmt: skip
    for report in (from_file, from_stdin):
        assert_allclose(report["conversions"][0]["angles"], [120, 35, -70], atol=1e-9)


def rounded_matrix() -> str:
    """A rotation's nine entries rounded to 4 decimals: 1e-5 off, beyond the default atol."""
    R = Rotation.from_euler("ZYX", [10, 20, 30], degrees=True).as_matrix()
    return ",".join(f"{x:.4f}" for x in R.ravel())


def test_a_matrix_that_is_not_a_rotation_is_refused_in_one_line(entry_point: Runner) -> None:
    refused = convert(entry_point, "--to", "rose", f"--matrix={rounded_matrix()}")
    assert refused.returncode == 1
    assert_clean_failure(refused, "not a rotation matrix", "--repair")


def test_repair_accepts_a_rounded_matrix() -> None:
    report = convert_json(run_in_process, "--to", "rose", "--degrees", "--repair",
                          f"--matrix={rounded_matrix()}")  # fmt: skip
    assert_allclose(report["conversions"][0]["angles"], [10, 20, 30], atol=1e-2)


# --- relabel and the tolerance --------------------------------------------------------------------


def test_relabel_keeps_the_attitude_between_frames() -> None:
    """Rose's z-up yaw/pitch/roll as Baker's y-up heading/attitude/bank of the same body.

    Oracles: SciPy, with the frame change written out (y-up coordinates turn into z-up ones by
    R_x(+90°), so Baker's matrix is R_x(90°)ᵀ R R_x(90°)), and the identity
    R_x(90°) R_y(h) R_z(a) R_x(b) R_x(90°)ᵀ = R_z(h) R_y(−a) R_x(b), typed in: heading = yaw,
    attitude = −pitch, bank = roll.
    """
    report = convert_json(run_in_process, "--from", "rose", "--to", "baker", "--relabel",
                          "--degrees", "30", "20", "10")  # fmt: skip
    baker = report["conversions"][0]
    P = Rotation.from_euler("x", 90, degrees=True)
    in_y_up = P.inv() * Rotation.from_euler("ZYX", [30, 20, 10], degrees=True) * P
    assert_allclose(baker["angles"], in_y_up.as_euler("YZX", degrees=True), atol=1e-10)
    assert_allclose(baker["angles"], [30, -20, 10], atol=1e-10)
    assert baker["gimbal_lock"] is False
    assert baker["distance_from_lock"] == pytest.approx(70)
    assert report["relabel"] is True
    # without --relabel the matrix is kept instead, and the angles differ (heading 22.8°)
    kept = convert_json(run_in_process, "--from", "rose", "--to", "baker", "--degrees",
                        "30", "20", "10")  # fmt: skip
    same_matrix = Rotation.from_euler("ZYX", [30, 20, 10], degrees=True).as_euler("YZX", True)
    assert_allclose(kept["conversions"][0]["angles"], same_matrix, atol=1e-10)


def test_relabel_at_lock_is_reported_in_words() -> None:
    # Rose's pitch -90° is Baker's attitude +90°, the pole where Baker sets bank to 0
    result = convert(run_in_process, "--from", "rose", "--to", "baker", "--relabel",
                     "--degrees", "40", "-90", "10")  # fmt: skip
    assert result.returncode == 0, result.stderr
    assert "to baker (YZX), y up: heading = 50°, attitude = 90°, bank = 0°" in result.stdout
    assert "only heading + bank is defined; bank was set to 0" in result.stdout


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["--from", "ZYX", "--to", "baker", "--relabel", "1", "2", "3"], ["--relabel", "'ZYX'"]),
        (["--to", "rose", "--relabel", "--matrix=1,0,0,0,1,0,0,0,1"], ["--relabel"]),
        (["--to", "rose", "--atol", "-1", "--matrix=1,0,0,0,1,0,0,0,1"], ["--atol", "-1"]),
        (["--to", "rose", "--atol", "nan", "--matrix=1,0,0,0,1,0,0,0,1"], ["--atol", "nan"]),
    ],
)
def test_bad_relabel_and_atol_fail_cleanly(args: list[str], words: list[str]) -> None:
    assert_clean_failure(convert(run_in_process, *args), *words)


def test_atol_zero_accepts_exact_rotations_only() -> None:
    """``--atol 0``, which the library accepts too: only an exactly orthogonal matrix passes."""
    exact = convert_json(run_in_process, "--to", "rose", "--degrees", "--atol", "0",
                         "--matrix=0,-1,0,1,0,0,0,0,1")  # fmt: skip
    assert_allclose(exact["conversions"][0]["angles"], [90, 0, 0], atol=1e-12)
    # a matrix whose entries carry one unit of rounding: R Rᵀ − I is not exactly 0
    noisy = np.eye(3)
    noisy[0, 0] = np.nextafter(1.0, 2.0)
    numbers = ",".join(repr(float(x)) for x in noisy.ravel())
    refused = convert(run_in_process, "--to", "rose", "--atol", "0", f"--matrix={numbers}")
    assert_clean_failure(refused, "not a rotation matrix", "--repair", "--atol")


def test_list_and_help() -> None:
    listing = convert(run_in_process, "--list")
    assert listing.returncode == 0
    for word in ("rose", "baker", "ros", "aerospace", "ZYX", "YZX", "xyz", "zyz"):
        assert word in listing.stdout
    helped = convert(run_in_process, "--help")
    assert helped.returncode == 0
    assert "eulerlib convert --from rose --to xyz --degrees -- -30 45 10" in helped.stdout
    assert "--angles=-30,45,10" in helped.stdout
    top = run_in_process("--help")
    assert top.returncode == 0
    assert "convert" in top.stdout


# --- bad arguments -------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (
            ["--from", "ZZX", "--to", "rose", "1", "2", "3"],
            ["--from 'ZZX' is neither a preset", "rose"],
        ),
        (["--from", "rose", "--to", "rsoe", "1", "2", "3"], ["--to 'rsoe' is neither a preset"]),
        (["--from", "rose", "--to", "xyz", "1", "2"], ["expected 3 angles, got 2"]),
        (["--from", "rose", "1", "2", "3", "4"], ["expected 3 angles, got 4"]),
        (["--from", "rose", "--to", "xyz", "1", "two", "3"], ["'two' is not a number"]),
        (["--from", "rose", "--angles=1,2,nan"], ["not a finite number"]),
        (["--to", "rose", "--matrix", "1", "0", "0"], ["9 numbers", "got 3"]),
        (["--to", "rose", "--matrix=1,0,0,0,1,0,0,0,2"], ["not a rotation matrix"]),
        (["--to", "rose", "--matrix=1,0,0,0,1,0,0,0,-1"], ["reflection"]),
        (["--to", "rose", "--matrix=1,0,0,0,1,0,0,x,1"], ["'x' is not a number"]),
        (["--to", "rose", "--matrix-file", "no/such/file.txt"], ["no such file"]),
        (["--from", "rose", "--matrix=1,0,0,0,1,0,0,0,1"], ["--from"]),
        (["--matrix=1,0,0,0,1,0,0,0,1"], ["--to"]),
        (["1", "2", "3"], ["--from"]),
        ([], ["nothing to convert"]),
        (["--from", "rose", "--to", "rose", "--bogus", "1", "2", "3"], ["--bogus"]),
    ],
)
def test_bad_arguments_fail_cleanly(args: list[str], words: list[str]) -> None:
    assert_clean_failure(convert(run_in_process, *args), *words)


def test_bad_matrix_files_fail_cleanly(tmp_path: Path) -> None:
    def from_file(path: str, stdin: str | None = None) -> Outcome:
        return convert(run_in_process, "--to", "rose", "--matrix-file", path, stdin=stdin)

    two_rows = tmp_path / "two_rows.txt"
    two_rows.write_text("1 0 0\n0 1 0\n", encoding="utf-8")
    assert_clean_failure(from_file(str(two_rows)), "3 rows of 3 numbers")
    ragged = tmp_path / "ragged.txt"
    ragged.write_text("1 0 0\n0 1\n0 0 1\n", encoding="utf-8")
    assert_clean_failure(from_file(str(ragged)), "3 + 2 + 3")
    assert_clean_failure(from_file(str(tmp_path)), "folder")
    assert_clean_failure(from_file("-", stdin="1 2\n"), "stdin")
