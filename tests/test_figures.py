"""Tests of ``eulerlib figures``: the committed figures are exactly what the command writes."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import PIL
import pytest
from PIL import Image

from eulerlib import cli
from eulerlib.course import commands, figures

ROOT = Path(__file__).resolve().parents[1]
COMMITTED = ROOT / "figures"


def _pinned(package: str) -> str | None:
    """The version of ``package`` pinned in .ci/constraints.txt (figures/ was made with it)."""
    for line in (ROOT / ".ci" / "constraints.txt").read_text(encoding="utf-8").splitlines():
        requirement = line.split(";")[0].strip()
        if requirement.lower().startswith(f"{package}=="):
            return requirement.split("==")[1]
    return None


SAME_RENDERER = (matplotlib.__version__, PIL.__version__) == (
    _pinned("matplotlib"),
    _pinned("pillow"),
)
NOTEBOOK_TOPICS = [
    "01_conventions_and_elementary_rotations",
    "02_deriving_equation_2",
    "03_matrix_to_angles",
    "04_gimbal_lock_algebra",
    "05_combining_rotations",
    "06_rotating_points_and_objects",
    "07_order_matters",
    "08_gimbal_lock_seen",
    "09_conventions_compared",
    "10_numerical_robustness",
]


@pytest.fixture(scope="module")
def fresh(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The figures written once into a new folder by ``write_figures``."""
    out = tmp_path_factory.mktemp("figures") / "nested" / "out"
    written = figures.write_figures(out)
    assert [path.name for path in written] == list(figures.FIGURE_NAMES)
    assert all(path.parent == out for path in written)
    return out


def listing(folder: Path) -> list[str]:
    return sorted(path.name for path in folder.iterdir())


def test_the_collection_has_one_thumbnail_per_notebook_and_the_key_figures() -> None:
    expected = [f"{topic}.png" for topic in NOTEBOOK_TOPICS] + ["frame_zyx.svg", "gimbal_lock.gif"]
    assert sorted(figures.FIGURE_NAMES) == sorted(expected)


def test_committed_figures_are_the_files_the_command_writes(fresh: Path) -> None:
    assert listing(fresh) == listing(COMMITTED)


@pytest.mark.skipif(
    not SAME_RENDERER,
    reason="figures/ is byte-exact only with the pinned matplotlib and Pillow",
)
def test_committed_figures_are_exactly_what_the_command_writes(fresh: Path) -> None:
    for name in listing(COMMITTED):
        assert (fresh / name).read_bytes() == (COMMITTED / name).read_bytes(), (
            f"figures/{name} differs from a fresh run: regenerate with `eulerlib figures`"
        )


def test_outputs_carry_no_date_or_version(fresh: Path) -> None:
    for name in listing(fresh):
        data = (fresh / name).read_bytes()
        assert matplotlib.__version__.encode() not in data, name
        assert b"Software" not in data and b"<dc:date>" not in data, name
    with Image.open(fresh / "10_numerical_robustness.png") as image:
        assert "Software" not in image.info


def test_gif_is_a_small_24_frame_loop(fresh: Path) -> None:
    path = fresh / "gimbal_lock.gif"
    assert path.stat().st_size <= 300_000
    with Image.open(path) as image:
        assert image.format == "GIF"
        assert image.n_frames == figures.GIF_FRAMES == 24
        assert image.info.get("loop") == 0


def test_thumbnails_are_png_and_svg_is_svg(fresh: Path) -> None:
    for topic in NOTEBOOK_TOPICS:
        with Image.open(fresh / f"{topic}.png") as image:
            assert image.format == "PNG"
            assert max(image.size) <= 800
    svg = (fresh / "frame_zyx.svg").read_text(encoding="utf-8")
    assert svg.lstrip().startswith("<?xml") and "</svg>" in svg


def test_console_command_writes_the_same_files(tmp_path: Path, fresh: Path) -> None:
    out = tmp_path / "cli"
    result = subprocess.run(
        [sys.executable, "-m", "eulerlib", "figures", "--out", str(out)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == f"wrote {len(figures.FIGURE_NAMES)} figures to {out}"
    assert listing(out) == listing(COMMITTED)
    for name in listing(COMMITTED):  # two runs, byte for byte the same
        assert (out / name).read_bytes() == (fresh / name).read_bytes(), name


def test_figures_subcommand_is_registered_without_a_default_folder() -> None:
    args = cli.build_parser().parse_args(["figures"])
    assert args.out is None  # figures/ of the current directory, when it is there
    assert args.run is commands.run_figures


def test_without_a_figures_folder_the_command_fails_in_one_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    assert cli.main(["figures"]) == 1
    lines = capsys.readouterr().err.splitlines()
    assert len(lines) == 1
    assert "no figures/ folder here" in lines[0] and "--out" in lines[0]
    assert list(tmp_path.iterdir()) == []


def test_out_must_not_be_a_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    target = tmp_path / "a_file"
    target.write_text("not a folder")
    assert cli.main(["figures", "--out", str(target)]) == 1
    assert "is a file" in capsys.readouterr().err
