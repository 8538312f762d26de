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
