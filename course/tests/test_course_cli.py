"""The course package's command line, ``eulerlib-course``: light to start, and one line naming
what to install when a command's tools are missing.

Every probe runs in a fresh interpreter. A package is hidden from it by ``sys.modules[name] =
None``, which makes ``import name`` fail exactly as it does where the package is not installed.
"""

from __future__ import annotations

import json
import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

from eulerlib_course import cli

REPO = Path(__file__).resolve().parents[2]

#: Prints the third-party top-level packages that the statement loads.
PROBE = """\
import json, sys
before = set(sys.modules)
import eulerlib_course, eulerlib_course.cli
loaded = {name.split(".")[0] for name in set(sys.modules) - before}
print(json.dumps(sorted(loaded - set(sys.stdlib_module_names))))
"""


def run_python(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, *args], capture_output=True, text=True, check=False, timeout=120
    )


def test_the_command_line_and_the_checker_load_numpy_and_the_library_only() -> None:
    result = run_python("-c", PROBE)
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout) == ["eulerlib", "eulerlib_course", "numpy"]


def test_python_m_runs_the_course_command_line() -> None:
    result = run_python("-m", "eulerlib_course", "--help")
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("usage: eulerlib-course ")
    for command in ("notebooks", "figures", "site"):
        assert command in result.stdout


def test_the_figures_module_names_the_librarys_plot_extra() -> None:
    code = (
        "import sys\nsys.modules['matplotlib'] = None\n"
        "try:\n    import eulerlib_course.figures\n"
        "except ImportError as error:\n    print(error)\n"
    )
    result = run_python("-c", code)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip().endswith('pip install "eulerlib[plot]"')


def test_the_figures_command_names_what_to_install(
    tmp_path_factory: pytest.TempPathFactory,
) -> None:
    out = tmp_path_factory.mktemp("figures")
    code = (
        "import sys\nsys.modules['matplotlib'] = None\n"
        "from eulerlib_course.cli import main\n"
        f"raise SystemExit(main(['figures', '--out', {str(out)!r}]))\n"
    )
    result = run_python("-c", code)
    assert result.returncode == 1
    assert result.stderr.splitlines() == [
        "eulerlib-course figures: error: eulerlib-course figures needs matplotlib, "
        "a dependency of eulerlib-course: pip install -e ./course"
    ]
    assert list(out.iterdir()) == []


def test_readme_command_lines_are_commands_the_course_cli_takes() -> None:
    readme = (REPO / "README.md").read_text(encoding="utf-8")
    blocks = re.findall(r"```bash\n(.*?)```", readme, flags=re.DOTALL)
    commands = [line for block in blocks for line in block.splitlines()]
    shown = [c.split("#")[0] for c in commands if c.startswith(".venv/bin/eulerlib-course ")]
    assert {shlex.split(c)[1] for c in shown} == set(cli.SUBCOMMANDS)
    parser = cli.build_parser()
    for command in shown:
        try:
            parser.parse_args(shlex.split(command)[1:])
        except SystemExit:
            pytest.fail(f"README shows a command eulerlib-course does not take: {command.strip()}")


# --- the working copy that the README's JupyterLab command opens ------------------------------


def test_the_working_copy_is_the_course_and_keeps_the_learners_work(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """``notebooks copy`` copies every notebook and data file byte for byte; run again, it keeps
    what is there (a notebook emptied by a Run All that stopped, an answer typed in) and copies
    back only what is missing. The committed notebooks are never written."""
    course = REPO / "notebooks"
    committed = {
        path.relative_to(course): path.read_bytes()
        for path in course.rglob("*")
        if path.is_file() and "__pycache__" not in path.parts
    }
    out = tmp_path / "my-course"
    assert cli.main(["notebooks", "copy", "--out", str(out)]) == 0
    copied = {path.relative_to(out): path.read_bytes() for path in out.rglob("*") if path.is_file()}
    assert copied == committed
    assert capsys.readouterr().out == (
        f"copied {len(committed)} files of the course to {out} (0 already there, kept)\n"
    )

    notebook = out / "07_gimbal_lock_seen.ipynb"
    notebook.write_text("my work\n")
    (out / "glossary.ipynb").unlink()
    assert cli.main(["notebooks", "copy", "--out", str(out)]) == 0
    assert capsys.readouterr().out == (
        f"copied 1 files of the course to {out} ({len(committed) - 1} already there, kept)\n"
    )
    assert notebook.read_text() == "my work\n"
    assert (out / "glossary.ipynb").read_bytes() == committed[Path("glossary.ipynb")]
    assert {  # the course itself is untouched
        path.relative_to(course): path.read_bytes()
        for path in course.rglob("*")
        if path.is_file() and "__pycache__" not in path.parts
    } == committed


@pytest.mark.parametrize(
    ("arguments", "message"),
    [
        (["--src", "{course}", "--out", "{course}"], "a folder outside the course notebooks"),
        (["--src", "{course}", "--out", "{course}/mine"], "a folder outside the course notebooks"),
        (["--src", "{empty}", "--out", "{tmp}/mine"], "no course notebooks in"),
    ],
    ids=["the course itself", "inside the course", "no notebooks"],
)
def test_the_working_copy_refuses_the_course_folder_and_an_empty_one(
    arguments: list[str], message: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    course, empty = tmp_path / "course", tmp_path / "empty"
    course.mkdir()
    (course / "01_a.ipynb").write_text("{}")
    empty.mkdir()
    filled = [a.format(course=course, empty=empty, tmp=tmp_path) for a in arguments]
    assert cli.main(["notebooks", "copy", *filled]) == 1
    err = capsys.readouterr().err
    assert len(err.splitlines()) == 1 and message in err, err
    assert sorted(p.name for p in course.iterdir()) == ["01_a.ipynb"]


def test_site_build_refuses_an_empty_out_like_every_course_command(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SystemExit) as exit_:
        cli.main(["site", "build", "--out", ""])
    assert exit_.value.code == 2
    assert "--out: is empty" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []
