"""Running the ``eulerlib`` command line from the tests: in this process, or as its own process.

:func:`run_in_process` calls :func:`eulerlib.cli.main` with its standard input, output and
error replaced and its exit status kept (argparse's exits included); any warning it raises is
written to its standard error, as a fresh interpreter would show it. :func:`real_process` runs a
real command (``python -m eulerlib`` or the console script) in a process of its own. Both give
back an :class:`Outcome`.
"""

from __future__ import annotations

import contextlib
import gc
import io
import subprocess
import sys
import warnings
from collections.abc import Callable
from typing import Any, NamedTuple

from eulerlib import cli


class Outcome(NamedTuple):
    """What a run of the command line left behind: its exit status and what it wrote."""

    returncode: int
    stdout: str
    stderr: str


#: Runs ``eulerlib ARGS...`` with an optional standard input.
Runner = Callable[..., Outcome]


def run_in_process(*args: str, stdin: str | None = None) -> Outcome:
    """``eulerlib ARGS...`` through :func:`eulerlib.cli.main`, in this process.

    Garbage left by earlier tests is collected first, so that a warning from its finalizer (an
    animation never rendered, say) is not taken for one of the command's.
    """
    gc.collect()
    out, err = io.StringIO(), io.StringIO()
    given_stdin = sys.stdin
    sys.stdin = io.StringIO(stdin or "")
    try:
        with (
            contextlib.redirect_stdout(out),
            contextlib.redirect_stderr(err),
            warnings.catch_warnings(record=True) as caught,
        ):
            warnings.simplefilter("always")
            try:
                status: Any = cli.main(list(args))
            except SystemExit as stop:  # argparse: --help, or a bad option
                status = stop.code
    finally:
        sys.stdin = given_stdin
    for warning in caught:
        err.write(warnings.formatwarning(
            warning.message, warning.category, warning.filename, warning.lineno
        ))  # fmt: skip
    if status is None:
        status = 0
    elif not isinstance(status, int):  # sys.exit("message") prints it and exits with 1
        err.write(f"{status}\n")
        status = 1
    return Outcome(status, out.getvalue(), err.getvalue())


def real_process(command: list[str]) -> Runner:
    """``eulerlib ARGS...`` run as its own process by ``command``."""

    def run(*args: str, stdin: str | None = None) -> Outcome:
        result = subprocess.run(
            [*command, *args],
            input=stdin,
            capture_output=True,
            text=True,
            encoding="utf-8",
            timeout=120,
            check=False,
        )
        return Outcome(result.returncode, result.stdout, result.stderr)

    return run
