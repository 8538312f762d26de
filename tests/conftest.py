"""Shared fixtures of the unit tests, and two checks that look at the test session as a whole.

The course notebooks are executed once per session, by nbval (strict: every stored output is
compared). Two properties of that execution are checked around the session instead of by
running the notebooks a second time:

* **Nothing writes into the repository.** The repository's files (tool caches and the
  environment left out) are listed with their sizes and modification times when the session
  starts and again when it ends; a file created, changed or deleted in between fails the
  session, and the summary names it. Notebooks run with their own folder as working directory,
  so a notebook that saves a file shows up here, and so does a test that writes next to itself
  instead of into ``tmp_path``.
* **Each notebook runs in a few seconds.** nbval reports every cell as a test; the durations of
  their calls are summed per notebook (kernel start-up not included). A notebook whose cells
  take more than ``notebook_max_seconds`` in total fails the session. The course rule is "well
  under 10 s" on an ordinary laptop; shared CI runners can be two or three times slower, so
  the default bound sits at twice the rule. It catches a notebook that does heavy work (a big
  SymPy simplify, hundreds of animation frames) without turning into a benchmark.

With pytest-xdist both checks run once, in the controller process: the workers send it every
test report, durations included. A failed check turns the exit status into "tests failed".
"""

from __future__ import annotations

import os
from collections import defaultdict
from pathlib import Path

import numpy as np
import pytest
from hypothesis import Phase, settings

ROOT = Path(__file__).resolve().parents[1]

#: Folders that tools write into during a session; never part of the course or the library.
IGNORED_DIRS = frozenset(
    {
        ".git",
        ".venv",
        "__pycache__",
        ".ipynb_checkpoints",
        ".pytest_cache",
        ".mypy_cache",
        ".ruff_cache",
        ".hypothesis",
        "mutants",  # the working copy of mutation testing (tests/mutation/README.md)
    }
)

#: Default of the ``notebook_max_seconds`` setting (see the module docstring).
NOTEBOOK_MAX_SECONDS = 20.0

# Mutation testing (tests/mutation/README.md) runs the tests once per mutant with
# ``--hypothesis-profile=mutation``: the same examples every time, and a failing test stops at
# its first failing example instead of shrinking it, which can take seconds.
settings.register_profile(
    "mutation",
    derandomize=True,
    database=None,
    phases=(Phase.explicit, Phase.generate),
    deadline=None,
)

# The README's test command draws a quarter of each property test's examples (the ``quick``
# profile, tests/budget.py); CI draws them all again with
# ``--hypothesis-profile=thorough``, Hypothesis' usual settings.
settings.register_profile("thorough")
settings.register_profile("quick", max_examples=25)
settings.load_profile("quick")

#: Seed of the ``rng`` fixture, for tests that draw the same numbers once for many cases.
SEED = 20150214


@pytest.fixture
def rng() -> np.random.Generator:
    """A seeded generator, so every failure can be replayed."""
    return np.random.default_rng(SEED)


# --- checks around the session ------------------------------------------------------------------


def snapshot(root: Path) -> dict[str, tuple[int, int]]:
    """Every file under ``root`` (tool caches left out) with its size and modification time."""
    files = {}
    for folder, dirs, names in os.walk(root):
        dirs[:] = [d for d in dirs if d not in IGNORED_DIRS and not d.endswith(".egg-info")]
        for name in names:
            path = Path(folder, name)
            stat = path.stat()
            files[path.relative_to(root).as_posix()] = (stat.st_size, stat.st_mtime_ns)
    return files


def repository_changes(
    before: dict[str, tuple[int, int]], after: dict[str, tuple[int, int]]
) -> str | None:
    """What changed between two snapshots, in words; None when nothing did."""
    changes = {
        "created": sorted(set(after) - set(before)),
        "modified": sorted(p for p in set(before) & set(after) if before[p] != after[p]),
        "deleted": sorted(set(before) - set(after)),
    }
    listed = [f"{what} {', '.join(paths)}" for what, paths in changes.items() if paths]
    return "; ".join(listed) or None


def notebook_of(nodeid: str) -> str | None:
    """The notebook a test id belongs to (``notebooks/01_x.ipynb::Cell 3``), else None."""
    path = nodeid.split("::", 1)[0]
    return path if path.endswith(".ipynb") else None


class SessionChecks:
    """The two checks of the module docstring, as a pytest plugin of the controller process."""

    def __init__(self, root: Path, max_seconds: float) -> None:
        self.root = root
        self.max_seconds = max_seconds
        self.before: dict[str, tuple[int, int]] = {}
        self.seconds: defaultdict[str, float] = defaultdict(float)
        self.problems: list[str] = []

    def pytest_sessionstart(self) -> None:
        self.before = snapshot(self.root)

    def pytest_runtest_logreport(self, report: pytest.TestReport) -> None:
        notebook = notebook_of(report.nodeid)
        if notebook is not None and report.when == "call":
            self.seconds[notebook] += report.duration

    def pytest_sessionfinish(self, session: pytest.Session) -> None:
        changes = repository_changes(self.before, snapshot(self.root))
        if changes:
            self.problems.append(
                f"the test session changed the repository ({changes}): notebooks and tests "
                "must write into a temporary folder"
            )
        for notebook, seconds in sorted(self.seconds.items()):
            if seconds > self.max_seconds:
                self.problems.append(
                    f"{notebook}: its cells took {seconds:.1f} s, more than the "
                    f"{self.max_seconds:g} s a notebook may take (notebook_max_seconds)"
                )
        if self.problems and session.exitstatus == pytest.ExitCode.OK:
            session.exitstatus = pytest.ExitCode.TESTS_FAILED

    def pytest_terminal_summary(self, terminalreporter: pytest.TerminalReporter) -> None:
        if self.problems:
            terminalreporter.section("checks around the session", sep="=", red=True, bold=True)
            for problem in self.problems:
                terminalreporter.line(f"FAILED {problem}", red=True)


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addini(
        "notebook_max_seconds",
        "longest time, in seconds, that the cells of one notebook may take in total",
        default=str(NOTEBOOK_MAX_SECONDS),
    )


def pytest_configure(config: pytest.Config) -> None:
    if hasattr(config, "workerinput"):
        return  # an xdist worker: the controller checks the session
    max_seconds = float(config.getini("notebook_max_seconds"))
    config.pluginmanager.register(SessionChecks(ROOT, max_seconds), "eulerlib-session-checks")
