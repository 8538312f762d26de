"""The test command catches what it promises to catch, tried on a small course built here.

A scratch repository gets this project's pytest configuration (``pyproject.toml``, the
``conftest.py`` that loads the plugins, the ``tests/conftest.py`` with the checks around the
session, the nbval sanitizer) and one notebook whose cells misbehave on purpose: one prints
something other than its stored output, one writes a file next to the notebook, and together
they take longer than the (lowered) time allowed to a notebook. pytest runs there once, in one
process (the course's own runs use pytest-xdist, where the checks are made in the controller
only: see the last test); the tests below read what it reported.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import nbformat
import pytest

from conftest import SessionChecks, notebook_of, pytest_configure, repository_changes, snapshot

ROOT = Path(__file__).resolve().parents[1]

#: The cells of the misbehaving notebook: (source, the output stored for it).
CELLS = [
    ("import time\ntime.sleep(0.4)\nprint(6 * 7)", "42\n"),
    ("print(6 * 9)", "42\n"),  # prints 54: strict nbval must fail this cell
    ("with open('written_by_a_notebook.txt', 'w') as f:\n    f.write('oops')", None),
]


def misbehaving_notebook() -> nbformat.NotebookNode:
    notebook = nbformat.v4.new_notebook()
    notebook.metadata = {"kernelspec": {"name": "python3", "display_name": "Python 3"}}
    for count, (source, shown) in enumerate(CELLS, start=1):
        cell = nbformat.v4.new_code_cell(source, execution_count=count)
        if shown is not None:
            cell.outputs = [nbformat.v4.new_output("stream", name="stdout", text=shown)]
        notebook.cells.append(cell)
    return notebook


@pytest.fixture(scope="module")
def session(tmp_path_factory: pytest.TempPathFactory) -> subprocess.CompletedProcess[str]:
    root = tmp_path_factory.mktemp("scratch") / "repository"
    (root / "tests").mkdir(parents=True)
    (root / "notebooks").mkdir()
    for name in ("pyproject.toml", "conftest.py"):
        shutil.copy(ROOT / name, root)
    for name in ("conftest.py", "nbval_sanitize.cfg"):
        shutil.copy(ROOT / "tests" / name, root / "tests")
    nbformat.write(misbehaving_notebook(), str(root / "notebooks" / "01_misbehaving.ipynb"))
    return subprocess.run(
        [sys.executable, "-m", "pytest", "-n", "0", "-o", "notebook_max_seconds=0.3"],
        cwd=root,
        capture_output=True,
        text=True,
        timeout=300,
        check=False,
    )


def test_strict_nbval_fails_a_changed_output(session: subprocess.CompletedProcess[str]) -> None:
    assert session.returncode == 1, session.stdout
    assert "1 failed, 2 passed" in session.stdout
    assert "FAILED notebooks/01_misbehaving.ipynb::Cell 1" in session.stdout


def test_a_file_written_into_the_repository_fails_the_session(
    session: subprocess.CompletedProcess[str],
) -> None:
    lines = [line for line in session.stdout.splitlines() if "changed the repository" in line]
    assert len(lines) == 1, session.stdout
    assert "created notebooks/written_by_a_notebook.txt" in lines[0]


def test_a_slow_notebook_fails_the_session(
    session: subprocess.CompletedProcess[str],
) -> None:
    lines = [line for line in session.stdout.splitlines() if "notebook_max_seconds" in line]
    assert len(lines) == 1, session.stdout
    assert lines[0].startswith("FAILED notebooks/01_misbehaving.ipynb: its cells took ")


# --- the pieces of the checks ------------------------------------------------------------------


def test_changes_are_listed_by_kind(tmp_path: Path) -> None:
    (tmp_path / "kept.txt").write_text("same")
    (tmp_path / "edited.txt").write_text("before")
    (tmp_path / "removed.txt").write_text("soon gone")
    (tmp_path / ".hypothesis").mkdir()
    before = snapshot(tmp_path)
    assert repository_changes(before, snapshot(tmp_path)) is None
    (tmp_path / "edited.txt").write_text("after, and longer")
    (tmp_path / "removed.txt").unlink()
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "new.txt").write_text("new")
    (tmp_path / ".hypothesis" / "cache").write_text("a tool's cache is not the repository")
    assert repository_changes(before, snapshot(tmp_path)) == (
        "created sub/new.txt; modified edited.txt; deleted removed.txt"
    )


def test_cells_are_counted_for_their_notebook() -> None:
    assert notebook_of("notebooks/01_x.ipynb::Cell 3") == "notebooks/01_x.ipynb"
    assert notebook_of("tests/test_x.py::test_y[a::b]") is None
    assert notebook_of("eulerlib/euler.py::eulerlib.euler") is None


def test_the_checks_are_made_by_the_controller_only(pytestconfig: pytest.Config) -> None:
    """An xdist worker (its config carries ``workerinput``) registers no checks of its own; the
    process that runs the session registers them once."""
    registered: list[object] = []
    plugins = SimpleNamespace(register=lambda plugin, name: registered.append(plugin))
    getini = pytestconfig.getini
    worker = SimpleNamespace(workerinput={}, pluginmanager=plugins, getini=getini)
    controller = SimpleNamespace(pluginmanager=plugins, getini=getini)
    pytest_configure(worker)  # type: ignore[arg-type]
    assert registered == []
    pytest_configure(controller)  # type: ignore[arg-type]
    assert len(registered) == 1 and isinstance(registered[0], SessionChecks)
    checks = pytestconfig.pluginmanager.get_plugin("eulerlib-session-checks")
    running_in_a_worker = hasattr(pytestconfig, "workerinput")
    assert (checks is None) == running_in_a_worker
