"""The ``eulerlib`` command line.

Each subcommand is set up by a function of its own module that adds the arguments to its
sub-parser and sets ``run`` as a default (``run(args) -> int``); heavy imports happen inside
``run``, so ``eulerlib --help`` and ``eulerlib convert`` need numpy only:

* ``eulerlib convert``: angles in one convention into a matrix and angles in another
  (:mod:`eulerlib.convert_cli`).

The course's commands (student copies, the nbgrader edition, the figures, the website) belong
to the course package, ``eulerlib-course``, and its own command line of that name.

Bad arguments end with a one-line message on standard error and a non-zero exit status, never a
traceback.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Sequence

from eulerlib import convert_cli
from eulerlib._extras import MissingExtraError

#: Subcommand name → (function that configures its sub-parser, one-line help).
SUBCOMMANDS: dict[str, tuple[Callable[[argparse.ArgumentParser], None], str]] = {
    "convert": (convert_cli.configure_parser, "convert angles and matrices between conventions"),
}


def build_parser() -> argparse.ArgumentParser:
    """The argument parser, with one sub-parser per subcommand."""
    parser = argparse.ArgumentParser(
        prog="eulerlib",
        description="Euler angles and rotation matrices: the command line of eulerlib.",
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
        print(f"eulerlib {args.command}: error: {error}", file=sys.stderr)
        return 1
    return status


if __name__ == "__main__":
    sys.exit(main())
