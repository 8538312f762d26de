"""The README keeps its promises: its example runs as shown, and CI runs its test command."""

from __future__ import annotations

import contextlib
import io
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text(encoding="utf-8")


def _blocks(language: str) -> list[str]:
    return re.findall(rf"```{language}\n(.*?)```", README, flags=re.DOTALL)


def test_library_example_prints_what_the_readme_shows() -> None:
    code, shown = _blocks("python")[0], _blocks("text")[0]
    output = io.StringIO()
    with contextlib.redirect_stdout(output):
        exec(compile(code, "README.md", "exec"), {})
    assert output.getvalue() == shown


def test_ci_runs_the_readme_test_command_verbatim() -> None:
    commands = [line for block in _blocks("bash") for line in block.splitlines()]
    test_command = next(c for c in commands if c.endswith("python -m pytest"))
    ci_script = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    assert test_command in ci_script.splitlines()


def test_readme_opens_the_course_in_jupyterlab() -> None:
    commands = [line for block in _blocks("bash") for line in block.splitlines()]
    assert any(
        c.startswith("python3 -m venv .venv") and "jupyter lab notebooks/" in c for c in commands
    )
