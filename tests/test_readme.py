"""The README keeps its promises: its example runs as shown, CI runs its test command, and the
commands it shows are commands the CLI takes."""

from __future__ import annotations

import contextlib
import io
import re
import shlex
from pathlib import Path

import pytest

from eulerlib import cli

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


def test_ci_runs_the_nbgrader_tests_that_the_readme_command_skips() -> None:
    # The README's command runs course/tests/test_nbgrader.py without nbgrader's own run (minutes
    # of autograding; skipped unless EULERLIB_NBGRADER=1); CI runs it as a step of its own, with
    # the course's teach extra that installs nbgrader.
    test_file = (ROOT / "course" / "tests" / "test_nbgrader.py").read_text(encoding="utf-8")
    assert 'os.environ.get("EULERLIB_NBGRADER") == "1"' in test_file
    # the script's commands, with lines continued by a backslash joined
    text = (ROOT / ".ci" / "run").read_text(encoding="utf-8").replace("\\\n", " ")
    ci_script = text.splitlines()
    readme_step = next(i for i, line in enumerate(ci_script) if line.endswith("python -m pytest"))
    install = next(i for i, line in enumerate(ci_script) if '"./course[test,teach]"' in line)
    run = next(
        i
        for i, line in enumerate(ci_script)
        if line.startswith("EULERLIB_NBGRADER=1 ")
        and " course/tests/test_nbgrader.py " in f"{line} "
        and " course/tests/test_graded.py " in f"{line} "
    )
    assert readme_step < install < run


def test_readme_opens_the_course_in_jupyterlab() -> None:
    commands = [line for block in _blocks("bash") for line in block.splitlines()]
    assert any(
        c.startswith("python3 -m venv .venv")
        and c.endswith("notebooks copy --out my-course/ && .venv/bin/jupyter lab my-course/")
        for c in commands
    )


def test_readme_command_lines_are_commands_the_cli_takes() -> None:
    # The library's command line; the course's, eulerlib-course, is checked by the course tests.
    commands = [line for block in _blocks("bash") for line in block.splitlines()]
    shown = [c.split("#")[0] for c in commands if c.startswith(".venv/bin/eulerlib ")]
    assert {shlex.split(c)[1] for c in shown} == set(cli.SUBCOMMANDS)
    parser = cli.build_parser()
    for command in shown:
        try:
            parser.parse_args(shlex.split(command)[1:])
        except SystemExit:
            pytest.fail(f"README shows a command the CLI does not take: {command.strip()}")


def test_the_api_table_lists_every_public_name_with_its_keywords() -> None:
    import inspect

    import eulerlib

    section = README.split("### What is in it", 1)[1].split("\n### ", 1)[0]
    rows = [line for line in section.splitlines() if line.startswith("|")]
    for name in eulerlib.__all__:
        mentioned = [row for row in rows if f"`{name}" in row]
        assert mentioned, f"{name} is not in the README's API table"
        value = getattr(eulerlib, name)
        if inspect.isfunction(value):
            keywords = [
                p.name
                for p in inspect.signature(value).parameters.values()
                if p.kind is inspect.Parameter.KEYWORD_ONLY
            ]
            row = next(row for row in mentioned if f"`{name}(" in row)
            for keyword in keywords:
                assert f"`{keyword}`" in row, f"{name}: keyword {keyword} missing from its row"
