"""Tests of eulerlib.plotting: the geometry of what is drawn, read back from the artists.

No baseline images: every test reads coordinates, labels and styles back from the matplotlib
artists and compares them with rotations computed by SciPy's ``Rotation``.
"""

from __future__ import annotations

import inspect
import re
import subprocess
import sys
import warnings
from collections.abc import Iterator
from typing import Any

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
import pytest
from matplotlib.animation import FuncAnimation
from matplotlib.figure import Figure
from mpl_toolkits.mplot3d.art3d import Line3D, Text3D
from scipy.spatial.transform import Rotation

import eulerlib
from eulerlib import plotting
from eulerlib.plotting import (
    aircraft_segments,
    animate_gimbal_lock,
    draw_aircraft,
    draw_axis_path,
    draw_frame,
    gimbal_ring_normals,
    gimbal_ring_points,
    new_3d_axes,
    plot_axis_paths,
    plot_body_rotation,
    plot_frames,
    plot_gimbal,
    plot_sequence_steps,
)

TAIT_BRYAN = [s for s in eulerlib.ALL_SEQUENCES if s[0].lower() != s[2].lower()]
PROPER = [s for s in eulerlib.ALL_SEQUENCES if s[0].lower() == s[2].lower()]
E = np.eye(3)

# Animations built only to inspect their frames are never rendered; matplotlib says so when
# they are garbage collected.
pytestmark = pytest.mark.filterwarnings("ignore:Animation was deleted without rendering")


@pytest.fixture(autouse=True)
def _close_figures() -> Iterator[None]:
    yield
    plt.close("all")


def scipy_matrix(seq: str, angles: Any, degrees: bool = True) -> np.ndarray:
    """SciPy's matrices; one 3×3 matrix for one set of angles.

    (SciPy before 1.17 returns a stack of one for a one-letter sequence with a list of angles.)
    """
    matrices = np.asarray(Rotation.from_euler(seq, angles, degrees=degrees).as_matrix())
    return matrices.reshape(3, 3) if np.ndim(angles) <= 1 else matrices


def shaft_vector(line: Line3D) -> tuple[np.ndarray, np.ndarray]:
    """Start point and end-minus-start of a two-point line."""
    data = np.asarray(line.get_data_3d(), dtype=float)  # (3, 2)
    return data[:, 0], data[:, 1] - data[:, 0]


def shafts(ax: Any) -> dict[str, Line3D]:
    """The frame shafts of an axes, by label (x, y', z'', ...)."""
    found = {}
    for line in ax.get_lines():
        label = line.get_label()
        if label[:1] in "xyz" and len(np.asarray(line.get_data_3d())[0]) == 2:
            found[label] = line
    return found


def frame_matrix(ax: Any, suffix: str) -> np.ndarray:
    """The matrix whose columns are the shafts labelled x+suffix, y+suffix, z+suffix."""
    lines = shafts(ax)
    return np.column_stack([shaft_vector(lines[letter + suffix])[1] for letter in "xyz"])


# --------------------------------------------------------------------------- light import


def test_import_eulerlib_does_not_load_matplotlib() -> None:
    code = "import sys, eulerlib; print('matplotlib' in sys.modules, 'ipywidgets' in sys.modules)"
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout
    assert out.split() == ["False", "False"]


def test_everything_public_is_documented_with_an_example() -> None:
    for name in plotting.__all__:
        value = getattr(plotting, name)
        if inspect.isfunction(value) or inspect.isclass(value):
            doc = inspect.getdoc(value) or ""
            for section in ("Examples", ">>> "):
                assert section in doc, f"{name} has no {section.strip()}"
            if inspect.isfunction(value):
                assert "Parameters" in doc and "Returns" in doc, name


# --------------------------------------------------------------------------- frames


def test_new_3d_axes_is_an_equal_cube() -> None:
    ax = new_3d_axes(limit=1.5, title="t")
    assert ax.get_xlim() == ax.get_ylim() == ax.get_zlim() == (-1.5, 1.5)
    aspect = np.asarray(ax.get_box_aspect())
    assert np.allclose(aspect, aspect[0])
    assert (ax.get_xlabel(), ax.get_ylabel(), ax.get_zlabel()) == ("x", "y", "z")
    assert ax.get_title() == "t"
    ax2 = new_3d_axes(ax.figure, (1, 2, 2))
    assert len(ax.figure.axes) == 2 and ax2.name == "3d"


@pytest.mark.parametrize("seed", range(5))
def test_draw_frame_arrows_follow_the_matrix_columns(seed: int) -> None:
    R = np.asarray(Rotation.random(random_state=seed).as_matrix())
    origin = np.array([0.2, -0.1, 0.3])
    ax = new_3d_axes()
    artists = draw_frame(ax, R, origin=origin, scale=0.7, label_suffix="'")
    assert len(artists) == 9
    for i, letter in enumerate("xyz"):
        shaft, _head, text = artists[3 * i : 3 * i + 3]
        assert isinstance(shaft, Line3D) and isinstance(text, Text3D)
        start, vector = shaft_vector(shaft)
        np.testing.assert_allclose(start, origin, atol=1e-15)
        np.testing.assert_allclose(vector, 0.7 * R[:, i], atol=1e-14)
        assert shaft.get_label() == letter + "'"
        assert text.get_text() == letter + "'"
        # The label sits beyond the tip, on the same line.
        offset = np.asarray(text.get_position_3d()) - origin
        np.testing.assert_allclose(np.cross(offset, R[:, i]), 0.0, atol=1e-12)
        assert offset @ R[:, i] > 0.7


def test_draw_frame_default_is_the_reference_frame_in_okabe_ito_colours() -> None:
    ax = new_3d_axes()
    artists = draw_frame(ax, linestyle="--", alpha=0.5)
    colors = [artists[3 * i].get_color() for i in range(3)]
    # Okabe and Ito's vermillion, bluish green and blue, typed in from their palette
    assert [c.upper() for c in colors] == ["#D55E00", "#009E73", "#0072B2"]
    for i in range(3):
        shaft = artists[3 * i]
        np.testing.assert_array_equal(shaft_vector(shaft)[1], E[:, i])
        assert shaft.get_linestyle() == "--"
        assert shaft.get_alpha() == 0.5


def test_plot_frames_draws_a_dashed_reference_and_solid_rotated_frames() -> None:
    Rs = scipy_matrix("ZYX", [[30, 0, 0], [30, 20, 0], [30, 20, 10]])
    fig = plot_frames(Rs, title="three steps")
    (ax,) = fig.axes
    lines = shafts(ax)
    assert len(lines) == 12  # reference + three frames, three arrows each
    for letter in "xyz":
        assert lines[letter].get_linestyle() == "--"
    for k, suffix in enumerate(["'", "''", "'''"]):
        np.testing.assert_allclose(frame_matrix(ax, suffix), Rs[k], atol=1e-14)
        assert all(lines[letter + suffix].get_linestyle() == "-" for letter in "xyz")
    np.testing.assert_array_equal(frame_matrix(ax, ""), E)


def test_plot_frames_labels_and_no_reference() -> None:
    R = scipy_matrix("xyz", [10, 20, 30])
    fig = plot_frames(R, labels=["_b"], reference=False)
    lines = shafts(fig.axes[0])
    assert sorted(lines) == ["x_b", "y_b", "z_b"]
    np.testing.assert_allclose(frame_matrix(fig.axes[0], "_b"), R, atol=1e-14)


# --------------------------------------------------------------------------- sequence steps


def highlighted_axis(ax: Any) -> np.ndarray:
    (line,) = [line for line in ax.get_lines() if line.get_gid() == "rotation-axis"]
    _, vector = shaft_vector(line)
    return vector / np.linalg.norm(vector)


def assert_parallel(a: np.ndarray, b: np.ndarray) -> None:
    np.testing.assert_allclose(np.cross(a, b), 0.0, atol=1e-12)
    assert a @ b > 0


@pytest.mark.parametrize(
    ("seq", "angles"),
    [("ZYX", [30, 20, 10]), ("XZX", [-40, 70, 25]), ("zxy", [15, -35, 60])],
)
def test_plot_sequence_steps_both_rows_end_in_the_same_frame(seq: str, angles: list[int]) -> None:
    fig = plot_sequence_steps(angles, seq, degrees=True)
    assert len(fig.axes) == 6
    intrinsic = seq if seq.isupper() else seq[::-1].upper()
    values = angles if seq.isupper() else angles[::-1]
    expected = scipy_matrix(seq, angles)
    top, bottom = fig.axes[:3], fig.axes[3:]
    for step in range(3):
        # Top row: frame after k intrinsic steps, turned about the moved axis.
        after = scipy_matrix(intrinsic[: step + 1], values[: step + 1])
        before = E if step == 0 else scipy_matrix(intrinsic[:step], values[:step])
        axis = "xyz".index(intrinsic[step].lower())
        primes = "'" * (step + 1)
        np.testing.assert_allclose(frame_matrix(top[step], primes), after, atol=1e-12)
        np.testing.assert_allclose(frame_matrix(top[step], primes[:-1]), before, atol=1e-12)
        assert_parallel(highlighted_axis(top[step]), before[:, axis])
        # Bottom row: the reversed steps about the fixed axes.
        fixed_seq = intrinsic[::-1].lower()[: step + 1]
        after_fixed = scipy_matrix(fixed_seq, values[::-1][: step + 1])
        fixed_axis = "xyz".index(fixed_seq[-1])
        np.testing.assert_allclose(frame_matrix(bottom[step], primes), after_fixed, atol=1e-12)
        assert_parallel(highlighted_axis(bottom[step]), E[:, fixed_axis])
    np.testing.assert_allclose(frame_matrix(top[2], "'''"), expected, atol=1e-12)
    np.testing.assert_allclose(frame_matrix(bottom[2], "'''"), expected, atol=1e-12)


def test_plot_sequence_steps_in_radians_matches_degrees() -> None:
    fig = plot_sequence_steps(np.radians([30, 20, 10]), "ZYX")
    assert fig.axes[0].get_title() == "1. 30° about z"
    np.testing.assert_allclose(
        frame_matrix(fig.axes[2], "'''"), scipy_matrix("ZYX", [30, 20, 10]), atol=1e-12
    )


# --------------------------------------------------------------------------- aircraft


@pytest.mark.parametrize(("up", "up_axis", "side_axis"), [("z", 2, 1), ("y", 1, 2)])
def test_aircraft_nose_along_x_and_fin_along_up(up: str, up_axis: int, side_axis: int) -> None:
    segments = aircraft_segments(up=up)
    assert segments.ndim == 3 and segments.shape[1:] == (2, 3)
    points = segments.reshape(-1, 3)
    np.testing.assert_array_equal(points[np.argmax(points[:, 0])], [1.0, 0.0, 0.0])
    # Nothing hangs below the wing plane; the fin is the highest point, behind the middle.
    assert points[:, up_axis].min() == 0.0
    top = points[np.argmax(points[:, up_axis])]
    assert top[up_axis] > 0.3 and top[0] < 0
    # Wings: symmetric along the side axis, spanning much wider than the fin is tall.
    mirror = points.copy()
    mirror[:, side_axis] *= -1
    assert {tuple(p) for p in np.round(mirror, 12)} == {tuple(p) for p in np.round(points, 12)}
    assert points[:, side_axis].max() > 2 * points[:, up_axis].max()


@pytest.mark.parametrize("up", ["z", "y"])
def test_draw_aircraft_turns_every_point(up: str) -> None:
    rotation = Rotation.from_euler("ZYX", [40, 25, -15], degrees=True)
    ax = new_3d_axes()
    lines = draw_aircraft(ax, rotation.as_matrix(), up=up, color="k", alpha=0.5, linestyle=":")
    segments = aircraft_segments(up=up)
    assert len(lines) == len(segments)
    for line, segment in zip(lines, segments, strict=True):
        drawn = np.asarray(line.get_data_3d()).T
        np.testing.assert_allclose(drawn, rotation.apply(segment), atol=1e-14)
        assert line.get_linestyle() == ":" and line.get_alpha() == 0.5


def test_yaw_pitch_roll_move_nose_and_fin_as_a_pilot_expects() -> None:
    ax = new_3d_axes()
    yaw = draw_aircraft(ax, eulerlib.yaw_pitch_roll_to_matrix(90, 0, 0, degrees=True))
    nose = np.asarray(yaw[0].get_data_3d())[:, 1]
    np.testing.assert_allclose(nose, [0, 1, 0], atol=1e-15)  # yaw left: nose to +y
    pitch = draw_aircraft(ax, eulerlib.yaw_pitch_roll_to_matrix(0, 90, 0, degrees=True))
    nose = np.asarray(pitch[0].get_data_3d())[:, 1]
    np.testing.assert_allclose(nose, [0, 0, -1], atol=1e-15)  # z up: positive pitch dips x


def test_plot_body_rotation_goes_there_and_back() -> None:
    R = scipy_matrix("ZYX", [30, 20, 10])
    fig = plot_body_rotation(R)
    assert [ax.get_title() for ax in fig.axes] == ["before", "after R", "back with Rᵀ"]
    segments = aircraft_segments()
    fuselage = segments[0]

    def solid_fuselages(ax: Any) -> list[np.ndarray]:
        return [
            np.asarray(line.get_data_3d()).T
            for line in ax.get_lines()
            if line.get_linestyle() == "-" and len(line.get_xdata()) == 2
        ]

    before, after, back = (solid_fuselages(ax) for ax in fig.axes)
    assert any(np.allclose(seg, fuselage) for seg in before)
    assert any(np.allclose(seg, fuselage @ R.T) for seg in after)
    assert not any(np.allclose(seg, fuselage) for seg in after)
    assert any(np.allclose(seg, fuselage, atol=1e-14) for seg in back)
    np.testing.assert_allclose(frame_matrix(fig.axes[1], "'"), R, atol=1e-14)


# --------------------------------------------------------------------------- gimbal


def expected_normals(seq: str, angles: list[float]) -> np.ndarray:
    """Ring normals from SciPy: axis k of the frame each ring moves with."""
    intrinsic = seq if seq.isupper() else seq[::-1].upper()
    values = angles if seq.isupper() else angles[::-1]
    a = ["xyz".index(c) for c in intrinsic.lower()]
    frames = [scipy_matrix(intrinsic[: k + 1], values[: k + 1]) for k in range(3)]
    columns = [3 - a[0] - a[1], 3 - a[1] - a[2], a[1]]
    return np.array([frames[k][:, columns[k]] for k in range(3)])


@pytest.mark.parametrize("seq", eulerlib.ALL_SEQUENCES)
def test_ring_normals_are_the_rotated_axes(seq: str) -> None:
    angles = [35.0, 50.0, -20.0]
    normals = gimbal_ring_normals(angles, seq, degrees=True)
    np.testing.assert_allclose(normals, expected_normals(seq, angles), atol=1e-12)
    rings = gimbal_ring_points(np.radians(angles), seq, n=50)
    for ring, normal, radius in zip(rings, normals, plotting.RING_RADII, strict=True):
        assert ring.shape == (50, 3)
        np.testing.assert_allclose(np.linalg.norm(ring, axis=1), radius, atol=1e-12)
        np.testing.assert_allclose(ring @ normal, 0.0, atol=1e-12)
        np.testing.assert_allclose(ring[0], ring[-1], atol=1e-12)


def test_rings_at_rest_are_mutually_perpendicular() -> None:
    normals = gimbal_ring_normals([0, 0, 0], "ZYX")
    np.testing.assert_allclose(normals @ normals.T, E, atol=1e-15)


@pytest.mark.parametrize("seq", TAIT_BRYAN + PROPER)
@pytest.mark.parametrize("side", [0, 1])
def test_two_rings_coplanar_at_lock_and_not_otherwise(seq: str, side: int) -> None:
    proper = seq in PROPER
    lock = (0.0, 180.0)[side] if proper else (-90.0, 90.0)[side]
    angles = [25.0, lock, 70.0]
    normals = gimbal_ring_normals(angles, seq, degrees=True)
    assert abs(normals[0] @ normals[1]) == pytest.approx(1.0, abs=1e-12)
    # All points of the middle ring lie in the plane of the outer ring.
    rings = gimbal_ring_points(angles, seq, degrees=True, n=40)
    np.testing.assert_allclose(rings[1] @ normals[0], 0.0, atol=1e-12)
    # The locked rotation really is locked, by the library's own test of the matrix.
    assert eulerlib.gimbal_lock_status(scipy_matrix(seq, angles), seq).locked
    for middle in (lock + 20.0, lock - 5.0, lock + 0.5):
        normals = gimbal_ring_normals([25.0, middle, 70.0], seq, degrees=True)
        dots = np.abs(normals @ normals.T)[np.triu_indices(3, 1)]
        assert dots.max() < 1 - 1e-5


def test_plot_gimbal_draws_the_rings_and_reports_lock() -> None:
    fig = plot_gimbal([30, 90, 10], "ZYX", degrees=True)
    ax = fig.axes[0]
    rings = gimbal_ring_points([30, 90, 10], "ZYX", degrees=True)
    drawn = [np.asarray(line.get_data_3d()).T for line in ax.get_lines()]
    for ring in rings:
        assert any(d.shape == ring.shape and np.allclose(d, ring) for d in drawn)
    assert "GIMBAL LOCK" in ax.get_title()
    assert len(ax.get_legend().get_texts()) == 3
    np.testing.assert_allclose(
        frame_matrix(ax, "") * 1 / 0.45, scipy_matrix("ZYX", [30, 90, 10]), atol=1e-12
    )
    fig = plot_gimbal(np.radians([30, 60, 10]), "ZYX")
    assert "30° from lock" in fig.axes[0].get_title()


def test_plot_gimbal_into_an_existing_axes() -> None:
    ax = new_3d_axes(figsize=(3, 3))
    fig = plot_gimbal([0.1, 0.2, 0.3], "xyz", ax=ax)
    assert fig is ax.figure and len(fig.axes) == 1


def test_animation_sweeps_the_middle_angle_into_lock() -> None:
    anim = animate_gimbal_lock(seq="ZYX", frames=24)
    assert isinstance(anim, FuncAnimation)
    values = list(anim.new_frame_seq())
    assert len(values) == 24
    assert values[0] == 0.0 and values[-1] == 90.0
    assert np.all(np.diff(values) > 0)
    proper = list(animate_gimbal_lock(seq="ZXZ", frames=5).new_frame_seq())
    assert proper[0] == 90.0 and proper[-1] == 0.0


def test_animation_renders_every_frame_and_ends_locked() -> None:
    anim = animate_gimbal_lock(frames=3, figsize=(2, 2))
    html = anim.to_jshtml(fps=5)
    assert html.count("data:image/png;base64") == 3
    (ax,) = anim._fig.axes
    assert "GIMBAL LOCK" in ax.get_title()


# --------------------------------------------------------------------------- presets and up axes


@pytest.mark.parametrize(("preset", "seq"), [("rose", "ZYX"), ("Baker", "YZX"), ("ros", "xyz")])
def test_a_preset_is_drawn_with_its_sequence(preset: str, seq: str) -> None:
    angles = [35.0, 50.0, -20.0]
    np.testing.assert_allclose(
        gimbal_ring_normals(angles, preset, degrees=True),
        expected_normals(seq, angles),
        atol=1e-12,
    )
    fig = plot_sequence_steps(angles, preset, degrees=True)
    np.testing.assert_allclose(
        frame_matrix(fig.axes[2], "'''"), scipy_matrix(seq, angles), atol=1e-12
    )
    assert fig.get_suptitle().startswith(f"{preset.lower()} ({seq}) with angles (35°, 50°, -20°)")
    fig = plot_gimbal(angles, preset, degrees=True)
    names = eulerlib.get_convention(preset).angle_names
    assert fig.axes[0].get_title().startswith(f"{preset.lower()} ({seq}): {names[0]} 35°")
    anim = animate_gimbal_lock(seq=preset, frames=2)
    assert list(anim.new_frame_seq())[-1] == 90.0


@pytest.mark.parametrize("up", ["Y", " y", "Z"])
def test_up_is_read_in_any_letter_case(up: str) -> None:
    expected = aircraft_segments(up=up.strip().lower())
    np.testing.assert_array_equal(aircraft_segments(up=up), expected)
    ax = new_3d_axes()
    lines = draw_aircraft(ax, up=up)
    np.testing.assert_array_equal(np.asarray(lines[0].get_data_3d()).T, expected[0])
    fig = plot_body_rotation(np.eye(3), up=up)
    assert len(fig.axes) == 3


def test_rings_of_three_points_are_allowed() -> None:
    rings = gimbal_ring_points([0.1, 0.2, 0.3], n=3)
    assert [ring.shape for ring in rings] == [(3, 3)] * 3
    rings = gimbal_ring_points([0.1, 0.2, 0.3], n=np.int64(5))
    assert rings[0].shape == (5, 3)


def test_matrices_can_be_repaired_or_drawn_unchecked() -> None:
    R = scipy_matrix("ZYX", [30, 20, 10])
    drifted = R + 1e-4 * np.arange(9.0).reshape(3, 3) / 9
    with pytest.raises(ValueError, match="pass repair=True"):
        plot_frames(drifted)
    fig = plot_frames(drifted, repair=True)
    u, _, vt = np.linalg.svd(drifted)
    np.testing.assert_allclose(frame_matrix(fig.axes[0], "'"), u @ vt, atol=1e-14)
    shear = np.array([[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0]])
    ax = new_3d_axes()
    artists = draw_frame(ax, shear, validate=False)
    np.testing.assert_array_equal(shaft_vector(artists[3])[1], shear[:, 1])
    np.testing.assert_array_equal(shaft_vector(artists[6])[1], 0.0)  # a zero column: no arrow
    lines = draw_aircraft(ax, drifted, repair=True)
    np.testing.assert_allclose(np.asarray(lines[0].get_data_3d())[:, 1], (u @ vt)[:, 0])


# --------------------------------------------------------------------------- paths on the sphere


@pytest.mark.parametrize(("axis", "column"), [("x", 0), ("Y", 1), (2, 2)])
def test_draw_axis_path_follows_one_column_of_every_rotation(
    axis: Any, column: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    from eulerlib.plotting import paths

    heads: list[tuple[np.ndarray, np.ndarray]] = []
    draw_head = paths._arrow_head

    def recording_head(ax: Any, tip: Any, direction: Any, size: float, **style: Any) -> Any:
        heads.append((tip, direction))
        return draw_head(ax, tip, direction, size, **style)

    monkeypatch.setattr(paths, "_arrow_head", recording_head)
    R = np.asarray(Rotation.random(7, random_state=3).as_matrix())
    ax = new_3d_axes()
    line, start, head = draw_axis_path(ax, R, axis=axis, color="tab:purple", label="path")
    np.testing.assert_array_equal(np.asarray(line.get_data_3d()).T, R[:, :, column])
    np.testing.assert_array_equal(np.asarray(start.get_data_3d()).T, R[:1, :, column])
    assert line.get_label() == "path" and line.get_color() == "tab:purple"
    assert start.get_marker() == "o" and start.get_linestyle() == "None"
    # the arrowhead points at the last sample, along the last step
    ((tip, direction),) = heads
    np.testing.assert_array_equal(tip, R[-1, :, column])
    np.testing.assert_array_equal(direction, R[-1, :, column] - R[-2, :, column])
    assert head in ax.collections


def test_draw_axis_path_dots_every_kth_sample() -> None:
    R = scipy_matrix("z", np.linspace(0.0, 90.0, 10)[:, None])
    artists = draw_axis_path(new_3d_axes(), R, dot_every=3)
    assert len(artists) == 4
    dots = np.asarray(artists[3].get_data_3d()).T
    np.testing.assert_allclose(dots, R[::3, :, 0], atol=1e-15)
    assert len(dots) == 4  # samples 0, 3, 6, 9
    assert len(draw_axis_path(new_3d_axes(), R)) == 3  # no dots by default


def test_plot_axis_paths_draws_each_path_in_its_colour_with_a_legend_inside() -> None:
    start = np.asarray(Rotation.from_euler("ZYX", [10, 20, 30], degrees=True).as_matrix())
    end = np.asarray(Rotation.from_euler("ZYX", [120, 40, -30], degrees=True).as_matrix())
    t = np.linspace(0.0, 1.0, 9)
    along = np.asarray(
        (
            Rotation.from_matrix(start)
            * Rotation.from_rotvec(
                t[:, None]
                * (Rotation.from_matrix(start).inv() * Rotation.from_matrix(end)).as_rotvec()
            )
        ).as_matrix()
    )
    stepwise = np.asarray(
        Rotation.from_euler(
            "ZYX", np.outer(1 - t, [10, 20, 30]) + np.outer(t, [120, 40, -30]), degrees=True
        ).as_matrix()
    )
    fig = plot_axis_paths(np.stack([along, stepwise]), labels=["a", "b"], axis="y")
    (ax,) = fig.axes
    paths = {line.get_label(): line for line in ax.get_lines() if line.get_label() in ("a", "b")}
    np.testing.assert_allclose(np.asarray(paths["a"].get_data_3d()).T, along[:, :, 1], atol=1e-15)
    np.testing.assert_array_equal(np.asarray(paths["b"].get_data_3d()).T, stepwise[:, :, 1])
    assert [paths["a"].get_color(), paths["b"].get_color()] == ["tab:orange", "tab:purple"]
    assert [text.get_text() for text in ax.get_legend().get_texts()] == ["a", "b"]
    fig.canvas.draw()
    legend = ax.get_legend().get_window_extent(fig.canvas.get_renderer())
    assert ax.bbox.x0 <= legend.x0 and legend.x1 <= ax.bbox.x1
    assert ax.bbox.y0 <= legend.y0 and legend.y1 <= ax.bbox.y1
    # every point of the sphere's wire lies on the unit sphere
    wire = [line for line in ax.get_lines() if line.get_color() == "0.82"]
    assert len(wire) == 11
    for line in wire:
        points = np.asarray(line.get_data_3d())
        np.testing.assert_allclose(np.linalg.norm(points, axis=0), 1.0, atol=1e-15)


def test_plot_axis_paths_one_path_without_labels_has_no_legend() -> None:
    R = scipy_matrix("x", np.linspace(0.0, 60.0, 5)[:, None])
    fig = plot_axis_paths(R, colors=["k"], axis="z", title="one")
    (ax,) = fig.axes
    assert ax.get_legend() is None and ax.get_title() == "one"
    drawn = [line for line in ax.get_lines() if line.get_color() == "k"]
    np.testing.assert_array_equal(np.asarray(drawn[0].get_data_3d()).T, R[:, :, 2])


# --------------------------------------------------------------------------- bad arguments

NAN, INF = float("nan"), float("inf")
REFLECTION = np.diag([1.0, 1.0, -1.0])
NOT_ORTHOGONAL = 2.0 * np.eye(3)

#: Bad values shared by parameters of one kind, with the error each must raise.
POSITIVE = [(0, ValueError), (-1.0, ValueError), (NAN, ValueError), (INF, ValueError),
            (None, TypeError), ("1", TypeError), (True, TypeError), (1j, TypeError)]  # fmt: skip
ALPHA = [(-0.1, ValueError), (1.5, ValueError), (NAN, ValueError), (None, TypeError),
         ("0.5", TypeError), (True, TypeError)]  # fmt: skip
FIGSIZE = [(None, TypeError), ("5x5", TypeError), ((5,), ValueError), ((5, 0), ValueError),
           ((5, -1), ValueError), ((5, NAN), ValueError), ((5, INF), ValueError),
           ((5, "a"), TypeError), ((5, 5, 5), ValueError)]  # fmt: skip
FLAG = [("yes", TypeError), (1, TypeError), (None, TypeError), (np.array(True), TypeError)]
ATOL = [(NAN, ValueError), (-1.0, ValueError), ("1e-6", TypeError), (None, TypeError)]
SEQ = [("ABC", ValueError), ("ZZX", ValueError), ("rosé", ValueError), (3, TypeError),
       (None, TypeError)]  # fmt: skip
UP = [("x", ValueError), ("", ValueError), ("up", ValueError), (None, TypeError), (2, TypeError)]
ANGLES = [([1, 2], ValueError), ([[1, 2, 3]], ValueError), ("abc", TypeError),
          ([1, NAN, 3], ValueError), ([1, INF, 3], ValueError), (None, TypeError),
          ([1, 2, None], TypeError), (np.ma.masked_array([1.0, 2, 3]), TypeError)]  # fmt: skip
ONE_MATRIX = [(REFLECTION, ValueError), (NOT_ORTHOGONAL, ValueError), (np.eye(2), ValueError),
              (np.stack([np.eye(3)] * 2), ValueError), ("R", TypeError),
              (np.full((3, 3), NAN), ValueError)]  # fmt: skip
LINESTYLE = [("x", ValueError), ("--x", ValueError), (None, TypeError), (5, TypeError)]
COLOR = [("bluish", ValueError), (None, TypeError), (5, TypeError), (True, TypeError)]
TITLE = [(1, TypeError), (["t"], TypeError), (b"t", TypeError)]
COUNT_N = [(2, ValueError), (0, ValueError), (4.0, TypeError), (True, TypeError),
           ("4", TypeError), (None, TypeError)]  # fmt: skip
NOT_3D = ["a 2D axes", "text", None]
AXIS = [("w", ValueError), (3, ValueError), (1.0, TypeError), (True, TypeError), (None, TypeError)]
ONE_PATH = [(np.eye(3), ValueError), (np.stack([REFLECTION] * 2), ValueError),
            (np.eye(3)[None, None], ValueError), ("R", TypeError), (None, TypeError),
            (np.full((2, 3, 3), NAN), ValueError)]  # fmt: skip

#: Every parameter of every public plotting function, with its bad values.
BAD: dict[str, dict[str, list[tuple[Any, type[Exception]]]]] = {
    "new_3d_axes": {
        "fig": [("fig", TypeError), ("a 2D axes", TypeError), (1, TypeError)],
        "position": [
            (0, ValueError),
            (1000, ValueError),
            (110, ValueError),
            (124, ValueError),
            ((1, 2), TypeError),
            ((1, 2, 3.0), TypeError),
            (True, TypeError),
            ((0, 1, 1), ValueError),
            ((1, 2, 3), ValueError),
            ("111", TypeError),
            (1.5, TypeError),
        ],
        "limit": POSITIVE,
        "title": TITLE,
        "figsize": FIGSIZE,
    },
    "draw_frame": {
        "ax": [(value, TypeError) for value in NOT_3D],
        "R": ONE_MATRIX,
        "origin": [
            ((0, 0), ValueError),
            ("o", TypeError),
            ((0, NAN, 0), ValueError),
            (None, TypeError),
        ],
        "scale": POSITIVE,
        "alpha": ALPHA,
        "linestyle": LINESTYLE,
        "linewidth": POSITIVE,
        "colors": [
            ("rgb", TypeError),
            (("r", "g"), ValueError),
            (("r", "g", "bluish"), ValueError),
            (("r", "g", None), TypeError),
            (None, TypeError),
        ],
        "labels": [
            (("a", "b"), ValueError),
            ("xyz", TypeError),
            (("a", "b", 1), TypeError),
            (None, TypeError),
        ],
        "label_suffix": [(None, TypeError), (1, TypeError)],
        "validate": FLAG,
        "repair": FLAG,
        "atol": ATOL,
    },
    "plot_frames": {
        "rotations": [
            (REFLECTION, ValueError),
            (np.zeros(3), ValueError),
            ("x", TypeError),
            (np.eye(3)[None, None], ValueError),
            (None, TypeError),
        ],
        "labels": [(["'", "''"], ValueError), ("a", TypeError), ([1], TypeError)],
        "reference": FLAG,
        "figsize": FIGSIZE,
        "title": TITLE,
        "validate": FLAG,
        "repair": FLAG,
        "atol": ATOL,
    },
    "plot_sequence_steps": {
        "angles": ANGLES,
        "seq": SEQ,
        "degrees": FLAG,
        "figsize": FIGSIZE[1:],  # None is the documented default
    },
    "aircraft_segments": {"up": UP},
    "draw_aircraft": {
        "ax": [(value, TypeError) for value in NOT_3D],
        "R": ONE_MATRIX,
        "up": UP,
        "color": COLOR,
        "alpha": ALPHA,
        "linestyle": LINESTYLE,
        "validate": FLAG,
        "repair": FLAG,
        "atol": ATOL,
    },
    "plot_body_rotation": {
        "R": [*ONE_MATRIX, (None, TypeError)],
        "up": UP,
        "figsize": FIGSIZE,
        "validate": FLAG,
        "repair": FLAG,
        "atol": ATOL,
    },
    "gimbal_ring_normals": {"angles": ANGLES, "seq": SEQ, "degrees": FLAG},
    "gimbal_ring_points": {"angles": ANGLES, "seq": SEQ, "degrees": FLAG, "n": COUNT_N},
    "plot_gimbal": {
        "angles": ANGLES,
        "seq": SEQ,
        "degrees": FLAG,
        "ax": [("a 2D axes", TypeError), ("text", TypeError)],
        "figsize": FIGSIZE,
    },
    "animate_gimbal_lock": {
        "seq": SEQ,
        "frames": [
            (1, ValueError),
            (0, ValueError),
            (2.0, TypeError),
            (True, TypeError),
            ("4", TypeError),
            (None, TypeError),
        ],
        "figsize": FIGSIZE,
    },
    "draw_axis_path": {
        "ax": [(value, TypeError) for value in NOT_3D],
        "rotations": ONE_PATH,
        "axis": AXIS,
        "color": COLOR,
        "label": TITLE,
        "linewidth": POSITIVE,
        "linestyle": LINESTYLE,
        "alpha": ALPHA,
        "dot_every": [(-1, ValueError), (2.0, TypeError), (True, TypeError), (None, TypeError)],
        "validate": FLAG,
        "repair": FLAG,
        "atol": ATOL,
    },
    "plot_axis_paths": {
        "paths": [
            (np.eye(3), ValueError),
            (np.stack([np.eye(3)] * 2)[None, None], ValueError),
            (np.stack([REFLECTION] * 2), ValueError),
            ("R", TypeError),
            (None, TypeError),
        ],
        "labels": [(["a", "b"], ValueError), ("a", TypeError), ([1], TypeError)],
        "axis": AXIS,
        "colors": [
            (["r", "g"], ValueError),
            ("r", TypeError),
            (["bluish"], ValueError),
            ([None], TypeError),
        ],
        "dot_every": [(-1, ValueError), (0.5, TypeError), (None, TypeError)],
        "title": TITLE,
        "figsize": FIGSIZE,
        "validate": FLAG,
        "repair": FLAG,
        "atol": ATOL,
    },
}

CALLABLES = {name: value for name in plotting.__all__ if callable(value := getattr(plotting, name))}


def valid_arguments(name: str, ax: Any = None) -> dict[str, Any]:
    """A valid call of each public plotting function, all arguments by keyword.

    The functions that draw into a given axes get ``ax``, or by default a new figure with a 3D
    axes, the most expensive argument here; the others get none.
    """
    if name in ("draw_frame", "draw_aircraft", "draw_axis_path"):
        given = {"ax": new_3d_axes() if ax is None else ax}
        if name == "draw_axis_path":
            given["rotations"] = np.stack([np.eye(3)] * 2)
        return given
    angles = {"angles": [30.0, 20.0, 10.0], "degrees": True}
    return {
        "new_3d_axes": {},
        "plot_frames": {"rotations": np.eye(3)},
        "plot_sequence_steps": angles,
        "aircraft_segments": {},
        "plot_body_rotation": {"R": np.eye(3)},
        "gimbal_ring_normals": angles,
        "gimbal_ring_points": angles,
        "plot_gimbal": angles,
        "animate_gimbal_lock": {"frames": 2},
        "plot_axis_paths": {"paths": np.stack([np.eye(3)] * 2)},
    }[name]


def stand_in(value: Any) -> Any:
    """Axes that a parametrized test cannot hold before the test runs."""
    if isinstance(value, str) and value == "a 2D axes":
        return plt.figure().add_subplot()
    return value


def test_every_parameter_of_every_public_plotting_function_has_bad_values_here() -> None:
    assert set(BAD) == set(CALLABLES)
    for name, function in CALLABLES.items():
        parameters = set(inspect.signature(function).parameters)
        assert set(BAD[name]) == parameters, name
        valid = valid_arguments(name)
        assert set(valid) <= parameters
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            function(**valid)
        plt.close("all")


BAD_CASES = [
    pytest.param(name, parameter, value, error, id=f"{name}-{parameter}-{index}")
    for name, parameters in BAD.items()
    for parameter, values in parameters.items()
    for index, (value, error) in enumerate(values)
]


@pytest.fixture(scope="module")
def blank_axes_store() -> dict[str, Any]:
    return {}


@pytest.fixture
def blank_axes(blank_axes_store: dict[str, Any]) -> Any:
    """A 3D axes as ``new_3d_axes`` makes it, with nothing drawn into it yet.

    The bad-argument cases of the functions that draw into an axes share one: each case checks
    that its call left the axes as it found it. Should a call have drawn into it (that case
    fails), the next case gets a new one. Its figure is not pyplot's, so pyplot's list of
    figures is the same with it as without it.
    """
    ax = blank_axes_store.get("ax")
    if ax is None or len(ax.get_children()) != blank_axes_store["children"]:
        ax = new_3d_axes(Figure(figsize=(5, 5)))
        blank_axes_store.update(ax=ax, children=len(ax.get_children()))
    return ax


@pytest.mark.parametrize(("name", "parameter", "bad", "error"), BAD_CASES)
def test_a_bad_argument_is_named_and_leaves_no_figure_behind(
    name: str,
    parameter: str,
    bad: Any,
    error: type[Exception],
    blank_axes: Any,
    capsys: pytest.CaptureFixture[str],
) -> None:
    arguments = valid_arguments(name, ax=blank_axes)
    arguments[parameter] = stand_in(bad)
    given_ax = arguments.get("ax") if parameter != "ax" else None
    drawn_before = len(given_ax.get_children()) if given_ax is not None else 0
    figures_before = plt.get_fignums()
    with pytest.raises(error) as caught:
        CALLABLES[name](**arguments)
    assert re.match(rf"{re.escape(parameter)}\b", str(caught.value)), str(caught.value)
    assert plt.get_fignums() == figures_before
    if given_ax is not None:  # nothing half drawn either
        assert len(given_ax.get_children()) == drawn_before
    assert capsys.readouterr() == ("", "")


@pytest.mark.parametrize(
    ("call", "module", "inner"),
    [
        (lambda: new_3d_axes(), "eulerlib.plotting._base", "style_axes"),
        (lambda: plot_frames(np.eye(3)), "eulerlib.plotting.frames", "frame_artists"),
        (
            lambda: plot_sequence_steps([1, 2, 3]),
            "eulerlib.plotting.frames",
            "frame_artists",
        ),
        (lambda: plot_body_rotation(np.eye(3)), "eulerlib.plotting.aircraft", "aircraft_lines"),
        (lambda: plot_gimbal([1, 2, 3]), "eulerlib.plotting.gimbal", "_draw_gimbal"),
        (
            lambda: plot_axis_paths(np.stack([np.eye(3)] * 2)),
            "eulerlib.plotting.paths",
            "path_artists",
        ),
    ],
)
def test_a_figure_is_closed_when_drawing_into_it_fails(
    call: Any, module: str, inner: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    def broken(*args: Any, **kwargs: Any) -> None:
        raise RuntimeError("drawing failed")

    monkeypatch.setattr(f"{module}.{inner}", broken)
    before = plt.get_fignums()
    with pytest.raises(RuntimeError, match="drawing failed"):
        call()
    assert plt.get_fignums() == before


def test_nothing_is_printed(capsys: pytest.CaptureFixture[str]) -> None:
    for name, function in CALLABLES.items():
        function(**valid_arguments(name))
        plt.close("all")
    assert capsys.readouterr() == ("", "")


# --------------------------------------------------------------------------- readable figures


def furniture(fig: Any) -> tuple[list[Any], list[Any]]:
    """The figure's own texts (suptitle, row names) and each axes' title, labels and ticks."""
    fig.canvas.draw()
    own = [text for text in fig.texts if text.get_text()]
    if fig._suptitle is not None:
        own.append(fig._suptitle)
    of_axes = []
    for ax in fig.axes:
        axis_list = [ax.xaxis, ax.yaxis] + ([ax.zaxis] if hasattr(ax, "zaxis") else [])
        of_axes.append(ax.title)
        for axis in axis_list:
            of_axes.append(axis.label)
            of_axes.extend(axis.get_ticklabels())
    return own, [text for text in of_axes if text.get_visible() and text.get_text()]


def overlaps(fig: Any) -> list[tuple[str, str]]:
    """Pairs (figure text, axes text) whose boxes on the canvas intersect."""
    renderer = fig.canvas.get_renderer()
    own, of_axes = furniture(fig)
    found = []
    for text in own:
        box = text.get_window_extent(renderer)
        for other in of_axes:
            if box.overlaps(other.get_window_extent(renderer)):
                found.append((text.get_text(), other.get_text()))
    return found


@pytest.mark.parametrize("figsize", [None, (9, 6.2), (11, 7.5)])
@pytest.mark.parametrize("seq", ["ZYX", "xzx"])
def test_row_names_of_the_sequence_steps_clear_the_axis_labels(seq: str, figsize: Any) -> None:
    fig = plot_sequence_steps([40, 30, 20], seq, degrees=True, figsize=figsize)
    assert overlaps(fig) == []
    rows = [text for text in fig.texts if text.get_gid() == "row"]
    assert len(rows) == 2
    renderer = fig.canvas.get_renderer()
    for text in [*rows, fig._suptitle]:  # inside the figure, not cut off
        box = text.get_window_extent(renderer)
        assert fig.bbox.x0 <= box.x0 and box.x1 <= fig.bbox.x1
        assert fig.bbox.y0 <= box.y0 and box.y1 <= fig.bbox.y1


def test_the_gimbal_legend_lies_inside_its_axes() -> None:
    for angles, seq in (([30, 90, 10], "ZYX"), ([30, 20, 10], "baker")):
        fig = plot_gimbal(angles, seq, degrees=True)
        fig.canvas.draw()
        (ax,) = fig.axes
        legend = ax.get_legend().get_window_extent(fig.canvas.get_renderer())
        assert ax.bbox.x0 <= legend.x0 and legend.x1 <= ax.bbox.x1
        assert ax.bbox.y0 <= legend.y0 and legend.y1 <= ax.bbox.y1


def test_every_3d_axes_is_labelled_x_y_z() -> None:
    figures = [
        plot_frames(np.eye(3)),
        plot_sequence_steps([1, 2, 3]),
        plot_body_rotation(np.eye(3)),
        plot_gimbal([1, 2, 3]),
        plot_axis_paths(np.stack([np.eye(3)] * 2)),
    ]
    for fig in figures:
        for ax in fig.axes:
            assert (ax.get_xlabel(), ax.get_ylabel(), ax.get_zlabel()) == ("x", "y", "z")


# --------------------------------------------------------------------------- palette

#: Machado, Oliveira and Fernandes (2009), "A physiologically-based model for simulation of color
#: vision deficiency", their matrices for severity 1.0, acting on linear RGB; typed in.
_DICHROMACY = {
    "protanopia": [
        [0.152286, 1.052583, -0.204868],
        [0.114503, 0.786281, 0.099216],
        [-0.003882, -0.048116, 1.051998],
    ],
    "deuteranopia": [
        [0.367322, 0.860646, -0.227968],
        [0.280085, 0.672501, 0.047413],
        [-0.011820, 0.042940, 0.968881],
    ],
    "tritanopia": [
        [1.255528, -0.076749, -0.178779],
        [-0.078411, 0.930809, 0.147602],
        [0.004733, 0.691367, 0.303900],
    ],
}


def _cielab(color: Any, vision: Any) -> np.ndarray:
    """A matplotlib colour as a reader with ``vision`` (a 3×3 matrix) sees it, in CIELAB (D65)."""
    from matplotlib.colors import to_rgb

    srgb = np.asarray(to_rgb(color))
    linear = np.where(srgb <= 0.04045, srgb / 12.92, ((srgb + 0.055) / 1.055) ** 2.4)
    seen = np.clip(np.asarray(vision) @ linear, 0.0, 1.0)
    xyz = np.array([[0.4124, 0.3576, 0.1805], [0.2126, 0.7152, 0.0722], [0.0193, 0.1192, 0.9505]])
    t = (xyz @ seen) / np.array([0.95047, 1.0, 1.08883])
    f = np.where(t > (6 / 29) ** 3, np.cbrt(t), t / (3 * (6 / 29) ** 2) + 4 / 29)
    return np.array([116 * f[1] - 16, 500 * (f[0] - f[1]), 200 * (f[1] - f[2])])


@pytest.mark.parametrize("vision", sorted(_DICHROMACY))
def test_the_palette_is_told_apart_with_every_kind_of_dichromacy(vision: str) -> None:
    """Axes, rings and the highlighted axis stay apart as a protanope, deuteranope or tritanope
    sees them: every two at least 15 CIELAB units apart (the red and green of matplotlib's
    default cycle come within 8 for a deuteranope)."""
    import itertools

    from eulerlib.plotting import AXIS_COLORS, HIGHLIGHT_COLOR, RING_COLORS

    colours = [*AXIS_COLORS, *RING_COLORS, HIGHLIGHT_COLOR]
    seen = [_cielab(c, _DICHROMACY[vision]) for c in colours]
    closest = min(float(np.linalg.norm(a - b)) for a, b in itertools.combinations(seen, 2))
    assert closest >= 15.0, (vision, closest)
    red, green = (_cielab(c, _DICHROMACY["deuteranopia"]) for c in ("tab:red", "tab:green"))
    assert float(np.linalg.norm(red - green)) < 15.0  # the test can fail
