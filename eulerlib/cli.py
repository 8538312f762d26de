"""The ``eulerlib`` command line.

Subcommands live in their own modules, each with ``configure_parser(parser)`` (which sets
``run`` as a default) and ``run(args) -> int``; heavy imports happen inside ``run``:

* ``eulerlib convert``: angles in one convention into a matrix and angles in another;
* ``eulerlib figures``: regenerate every figure of the course into ``figures/``;
* ``eulerlib notebooks``: re-execute and normalize the notebooks, or make student copies.

Bad arguments end with a one-line message on standard error and a non-zero exit status, never
a traceback.
"""

from __future__ import annotations

import argparse
import importlib
import sys
from collections.abc import Sequence

#: Subcommand name → (module, one-line help).
SUBCOMMANDS = {
    "convert": ("eulerlib.convert_cli", "convert angles and matrices between conventions"),
    "figures": ("eulerlib.figures", "regenerate every figure of the course"),
    "notebooks": ("eulerlib.course", "refresh the course notebooks or make student copies"),
}


def build_parser() -> argparse.ArgumentParser:
    """The argument parser, with one sub-parser per available subcommand."""
    parser = argparse.ArgumentParser(
        prog="eulerlib",
        description="Euler angles and rotation matrices: the command line of the eulerlib course.",
    )
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name, (module_name, summary) in SUBCOMMANDS.items():
        try:
            module = importlib.import_module(module_name)
        except ModuleNotFoundError as error:
            if error.name != module_name:
                raise
            continue  # subcommand not part of this version
        sub = subparsers.add_parser(
            name, help=summary, description=summary[0].upper() + summary[1:] + "."
        )
        module.configure_parser(sub)
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
    except (ValueError, TypeError, OSError) as error:
        print(f"eulerlib {args.command}: error: {error}", file=sys.stderr)
        return 1
    return status


if __name__ == "__main__":
    sys.exit(main())
