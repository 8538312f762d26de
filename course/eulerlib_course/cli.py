"""The ``eulerlib-course`` command line (also ``python -m eulerlib_course``).

* ``eulerlib-course notebooks``: make student copies of the notebooks or their nbgrader
  edition, or re-execute and normalize them;
* ``eulerlib-course figures``: redraw every figure of the course;
* ``eulerlib-course key remove``: delete the answer key from a students' environment (graded
  mode of the nbgrader edition);
* ``eulerlib-course site``: build the course website from the stored notebooks.

Each subcommand is set up by a function of :mod:`eulerlib_course.commands` that adds the
arguments to its sub-parser and sets ``run`` as a default (``run(args) -> int``); the notebook
tools, matplotlib and Jupyter Book are imported inside ``run``, so ``eulerlib-course --help``
starts quickly. Bad arguments, and a command whose optional dependencies are not installed, end
with a one-line message on standard error and a non-zero exit status, never a traceback. The
library's own command line, ``eulerlib convert``, is :mod:`eulerlib.cli`.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Sequence

from eulerlib_course import commands
from eulerlib_course._extras import MissingExtraError

#: Subcommand name → (function that configures its sub-parser, one-line help).
SUBCOMMANDS: dict[str, tuple[Callable[[argparse.ArgumentParser], None], str]] = {
    "figures": (commands.configure_figures, "redraw every figure of the course"),
    "key": (
        commands.configure_key,
        "remove the answer key from a students' environment (graded mode)",
    ),
    "notebooks": (
        commands.configure_notebooks,
        "student copies or an nbgrader edition of the course notebooks, or refresh them",
    ),
    "site": (commands.configure_site, "build the course website from the notebooks"),
}


def build_parser() -> argparse.ArgumentParser:
    """The argument parser, with one sub-parser per subcommand.

    Examples
    --------
    >>> args = build_parser().parse_args(["notebooks", "student", "--out", "copies"])
    >>> args.command, args.action, args.out.name
    ('notebooks', 'student', 'copies')
    """
    parser = argparse.ArgumentParser(
        prog="eulerlib-course",
        description="The eulerlib course: its notebooks, figures and website.",
    )
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name, (configure, summary) in SUBCOMMANDS.items():
        sub = subparsers.add_parser(
            name, help=summary, description=summary[0].upper() + summary[1:] + "."
        )
        configure(sub)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line and return the exit status."""
    parser = build_parser()
    args = parser.parse_args(argv)
    if args.command is None:
        parser.print_help()
        return 0
    try:
        status: int = args.run(args)
    except (ValueError, TypeError, OSError, MissingExtraError) as error:
        print(f"eulerlib-course {args.command}: error: {error}", file=sys.stderr)
        return 1
    return status


if __name__ == "__main__":
    sys.exit(main())
