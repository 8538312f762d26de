"""``eulerlib convert``: angles in one convention into a matrix and into angles in another.

Two ways in:

* three angles (``--from`` names their convention): the command prints the rotation matrix
  and, for each ``--to``, the angles of the same rotation in that convention;
* a rotation matrix (``--matrix`` with nine numbers, or ``--matrix-file``): the command prints
  its angles in each ``--to`` convention.

A convention is a preset name (``rose``, ``aerospace``, ``nasa``, ``baker``, ``ros``; any letter
case) or one of SciPy's 24 axis sequences (``ZYX``, ``xyz``, ``ZXZ``, …; uppercase intrinsic,
lowercase extrinsic), see :mod:`eulerlib.conventions`. Gimbal lock is reported in words, with
the angle that was set to 0; it is not an error.
"""

from __future__ import annotations

import argparse
import json
import math
import re
import sys
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from eulerlib._validation import ROTATION_ATOL

__all__ = ["configure_parser", "parse_matrix_text", "parse_numbers", "run"]

DESCRIPTION = """\
Convert Euler angles between conventions, through the rotation matrix.

Angles in one convention (--from) become the rotation matrix and the angles of the
same rotation in each --to convention; or a matrix (--matrix, --matrix-file) becomes
angles. Gimbal lock is reported in words, with the angle that was set to 0."""

EPILOG = f"""\
conventions:
  a preset name (any letter case):
    rose                   ZYX  yaw, pitch, roll         Rose (2015), z up
    aerospace, nasa        ZYX  yaw, pitch, roll         aircraft body frame, z down (NED)
    baker                  YZX  heading, attitude, bank  Baker, y up, bank = 0 at the poles
    ros                    xyz  roll, pitch, yaw         ROS, fixed axes x, y, z, z up
  or an axis sequence as in SciPy: uppercase = intrinsic (moving axes), lowercase =
  extrinsic (fixed axes), angle i about letter i: ZYX, xyz, YZX, ZXZ, ... (24 in all).
  'eulerlib convert --list' prints them all.

negative numbers:
  put '--' before the angles, or give them as one comma-separated value with '=':
    eulerlib convert --from rose --to xyz --degrees -- -30 45 10
    eulerlib convert --from rose --to xyz --degrees --angles=-30,45,10
  the same holds for a matrix: --matrix=0,-1,0,1,0,0,0,0,1

examples:
  # Rose's yaw/pitch/roll to ROS's roll/pitch/yaw (same matrix, reversed order)
  eulerlib convert --from rose --to ros --degrees 30 20 10

  # the same attitude of a body between frames with different up axes (Baker's y up)
  eulerlib convert --from rose --to baker --relabel --degrees 30 20 10

  # one set of angles into several conventions at once
  eulerlib convert --from baker --to rose --to ZXZ --degrees 40 25 -15

  # angles of a matrix given as nine numbers, row by row
  eulerlib convert --to rose --degrees --matrix 0 -1 0 1 0 0 0 0 1

  # angles of a matrix read from a file (3 rows of 3 numbers), or from stdin with '-'
  eulerlib convert --to baker --degrees --matrix-file rotation.txt
  printf '1 0 0\\n0 0 -1\\n0 1 0\\n' | eulerlib convert --to rose --matrix-file -

  # pitch 90°: gimbal lock, reported in words
  eulerlib convert --from rose --to rose --degrees 30 90 10

output:
  angles are in degrees with --degrees, radians otherwise; --json prints one JSON object.
  With --relabel the angles describe the same attitude of a body in each convention's own
  frame (x forward, its up axis up), as convert_angles(..., relabel=True) does; without it,
  the same matrix. A matrix must be a rotation within --atol (default {ROTATION_ATOL:g}; 0
  accepts only exact rotations); --repair uses the nearest rotation instead. Errors end with
  exit status 1 (2 for unknown options).
"""

_SEPARATORS = re.compile(r"[\s,;]+")
_BRACKETS = str.maketrans("", "", "[]()")


def parse_numbers(text: str, what: str) -> list[float]:
    """Numbers from text separated by spaces, commas or semicolons (brackets are ignored).

    Raises
    ------
    ValueError
        Naming the first piece that is not a finite number.

    Examples
    --------
    >>> parse_numbers("-30, 45 10", "angles")
    [-30.0, 45.0, 10.0]
    """
    numbers = []
    for piece in _SEPARATORS.split(text.translate(_BRACKETS).strip()):
        if not piece:
            continue
        try:
            value = float(piece)
        except ValueError:
            raise ValueError(f"{what}: {piece!r} is not a number") from None
        if not np.isfinite(value):
            raise ValueError(f"{what}: {piece!r} is not a finite number")
        numbers.append(value)
    return numbers


def parse_matrix_text(text: str, source: str) -> NDArray[np.float64]:
    """A 3×3 matrix from text: three non-empty lines of three numbers (``#`` starts a comment).

    Brackets are ignored, so a matrix printed by NumPy can be pasted as it is.

    Examples
    --------
    >>> parse_matrix_text("[[1 0 0]\\n [0 0 -1]\\n [0 1 0]]", "example")
    array([[ 1.,  0.,  0.],
           [ 0.,  0., -1.],
           [ 0.,  1.,  0.]])
    """
    rows: list[list[float]] = []
    for line in text.splitlines():
        content = line.split("#", 1)[0].translate(_BRACKETS).strip()
        if content:
            rows.append(parse_numbers(content, f"{source}, row {len(rows) + 1}"))
    if len(rows) != 3 or any(len(row) != 3 for row in rows):
        shape = " + ".join(str(len(row)) for row in rows) or "no numbers"
        raise ValueError(
            f"{source} must hold 3 rows of 3 numbers, got {len(rows)} row(s) ({shape})"
        )
    return np.array(rows, dtype=np.float64)


def _read_matrix_file(path: str) -> NDArray[np.float64]:
    if path == "-":
        return parse_matrix_text(sys.stdin.read(), "matrix on stdin")
    try:
        text = Path(path).read_text(encoding="utf-8-sig")  # Notepad may start the file with a BOM
    except FileNotFoundError:
        raise OSError(f"cannot read the matrix file {path!r}: no such file") from None
    except IsADirectoryError:
        raise OSError(f"cannot read the matrix file {path!r}: it is a folder") from None
    except UnicodeDecodeError:
        raise ValueError(f"the matrix file {path!r} is not text") from None
    except OSError as error:
        raise OSError(f"cannot read the matrix file {path!r}: {error.strerror}") from None
    return parse_matrix_text(text, f"matrix file {path!r}")


def configure_parser(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``eulerlib convert`` to its sub-parser."""
    parser.formatter_class = argparse.RawDescriptionHelpFormatter
    parser.description = DESCRIPTION
    parser.epilog = EPILOG
    parser.add_argument(
        "angles",
        nargs="*",
        metavar="ANGLE",
        help="three angles in the argument order of --from (put '--' before a negative first "
        "angle)",
    )
    parser.add_argument(
        "--angles",
        dest="angles_option",
        metavar="A,B,C",
        help="the three angles as one value, e.g. --angles=-30,45,10",
    )
    parser.add_argument(
        "--from",
        dest="from_",
        metavar="CONVENTION",
        help="convention of the input angles: a preset (rose, baker, ros, ...) or a sequence "
        "(ZYX, xyz, ...)",
    )
    parser.add_argument(
        "--to",
        action="append",
        default=[],
        metavar="CONVENTION",
        help="convention to express the rotation in; repeat for several",
    )
    parser.add_argument(
        "--degrees", action="store_true", help="angles in and out in degrees (default radians)"
    )
    matrix = parser.add_mutually_exclusive_group()
    matrix.add_argument(
        "--matrix",
        nargs="+",
        metavar="X",
        help="a rotation matrix as nine numbers, row by row (spaces or commas)",
    )
    matrix.add_argument(
        "--matrix-file",
        metavar="PATH",
        help="a text file with 3 rows of 3 numbers; '-' reads standard input",
    )
    parser.add_argument(
        "--relabel",
        action="store_true",
        help="keep the attitude, not the matrix: move it between the conventions' frames "
        "(their up axes), as convert_angles(..., relabel=True)",
    )
    parser.add_argument(
        "--repair", action="store_true", help="use the nearest rotation to the given matrix"
    )
    parser.add_argument(
        "--atol",
        type=float,
        default=ROTATION_ATOL,
        metavar="TOL",
        help=f"how far from a rotation an input matrix may be (default {ROTATION_ATOL:g})",
    )
    parser.add_argument(
        "--precision",
        type=int,
        default=6,
        metavar="N",
        help="decimals shown (default 6)",
    )
    parser.add_argument("--json", action="store_true", help="print one JSON object instead")
    parser.add_argument("--list", action="store_true", help="list the conventions and exit")
    parser.set_defaults(run=run)


def _format(value: float, precision: int) -> str:
    text = f"{round(float(value), precision) + 0.0:.{precision}f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


def _angle_list(names: tuple[str, str, str], values: Any, unit: str, precision: int) -> str:
    return ", ".join(
        f"{name} = {_format(value, precision)}{unit}"
        for name, value in zip(names, values, strict=True)
    )


def _lock_words(convention: Any, middle: float) -> str:
    """One sentence about the gimbal lock of one matrix, whose middle angle is ``middle`` (rad)."""
    from eulerlib.gimbal_lock import lock_combination

    first, middle_name, third = convention.angle_names
    pole = convention.pole(middle)
    _, combination = lock_combination(convention, pole)
    return (
        f"gimbal lock: the middle angle ({middle_name}) is {pole}°, so {first} and {third} turn "
        f"about the same axis and only {combination} is defined; {convention.zeroed_name} was "
        f"set to 0 and {convention.carrier_name} carries the whole turn"
    )


def _list_conventions() -> str:
    from eulerlib.conventions import CONVENTIONS, PRESET_ALIASES
    from eulerlib.sequences import ALL_SEQUENCES

    lines = ["presets (any letter case):"]
    for name, convention in CONVENTIONS.items():
        if name in PRESET_ALIASES:
            continue
        aliases = [alias for alias, target in PRESET_ALIASES.items() if target == name]
        label = ", ".join([name, *aliases])
        lines.append(
            f"  {label:<22} {convention.seq}  ({', '.join(convention.angle_names)}); "
            f"{convention.up_axis} up"
        )
        lines.append(f"      {convention.description}")
    lines.append("axis sequences (uppercase intrinsic, lowercase extrinsic):")
    lines.append("  " + " ".join(ALL_SEQUENCES[:12]))
    lines.append("  " + " ".join(ALL_SEQUENCES[12:]))
    return "\n".join(lines)


def _input_matrix(args: argparse.Namespace) -> NDArray[np.float64] | None:
    if args.matrix is not None:
        numbers = parse_numbers(" ".join(args.matrix), "--matrix")
        if len(numbers) != 9:
            raise ValueError(f"--matrix needs 9 numbers (3 rows of 3), got {len(numbers)}")
        return np.array(numbers, dtype=np.float64).reshape(3, 3)
    if args.matrix_file is not None:
        return _read_matrix_file(args.matrix_file)
    return None


def _input_angles(args: argparse.Namespace) -> list[float] | None:
    pieces = list(args.angles)
    if args.angles_option is not None:
        if pieces:
            raise ValueError("give the angles either as ANGLE ... or with --angles, not both")
        pieces = [args.angles_option]
    if not pieces:
        return None
    numbers = parse_numbers(" ".join(pieces), "angles")
    if len(numbers) != 3:
        raise ValueError(f"expected 3 angles, got {len(numbers)}: {' '.join(pieces)}")
    return numbers


def run(args: argparse.Namespace) -> int:
    """Carry out ``eulerlib convert``; bad input raises ValueError/TypeError/OSError."""
    from eulerlib import (
        change_up_axis,
        convert_angles,
        euler_to_matrix,
        gimbal_lock_status,
        matrix_to_euler,
    )
    from eulerlib._validation import RotationCheck, as_rotations, check_tolerance
    from eulerlib.conventions import get_convention

    if args.list:
        print(_list_conventions())
        return 0
    if args.precision < 0 or args.precision > 17:
        raise ValueError(f"--precision must be between 0 and 17, got {args.precision}")
    atol = check_tolerance(args.atol, "--atol")  # the library's rule: a finite number >= 0
    targets = [get_convention(name, "--to") for name in args.to]
    source = get_convention(args.from_, "--from") if args.from_ is not None else None
    given_matrix = _input_matrix(args)
    angles = _input_angles(args)
    unit = "°" if args.degrees else " rad"
    report: dict[str, Any] = {"degrees": bool(args.degrees)}
    lines = []

    if given_matrix is not None:
        if angles is not None:
            raise ValueError("give either angles or a matrix, not both")
        if source is not None:
            raise ValueError("--from names the convention of input angles; a matrix needs none")
        if not targets:
            raise ValueError("a matrix needs at least one --to convention to express it in")
        if args.relabel:
            raise ValueError(
                "--relabel moves angles between the frames of --from and --to; a matrix has "
                "no --from frame"
            )
        advice = "pass --repair to use the nearest rotation instead (or loosen --atol)"
        check = RotationCheck(True, bool(args.repair), atol, advice)
        R = as_rotations(given_matrix, "the matrix", check)
        report["input"] = {"matrix": given_matrix.tolist()}
    else:
        if angles is None:
            raise ValueError(
                "nothing to convert: give three angles (with --from) or a matrix "
                "(--matrix or --matrix-file); see 'eulerlib convert --help'"
            )
        if source is None:
            raise ValueError(
                "the angles need --from: name their convention, a preset such as rose, baker "
                "or ros, or an axis sequence such as ZYX"
            )
        if args.relabel:
            for convention in (source, *targets):
                if convention.up_axis is None:
                    raise ValueError(
                        f"--relabel needs an up axis for every convention, but "
                        f"{convention.name!r} has none; use presets such as rose (z up) or "
                        "baker (y up)"
                    )
        R = euler_to_matrix(angles, source, degrees=args.degrees)
        report["input"] = {
            "convention": source.name,
            "seq": source.seq,
            "angle_names": list(source.angle_names),
            "angles": angles,
        }
        lines.append(
            f"from {source.label}: {_angle_list(source.angle_names, angles, unit, args.precision)}"
        )
    if args.relabel:
        report["relabel"] = True

    report["matrix"] = R.tolist()
    width = args.precision + 4
    lines.append("rotation matrix:")
    for row in R:
        lines.append("  [" + " ".join(f"{_format(x, args.precision):>{width}}" for x in row) + "]")

    results = []
    for target in targets:
        if angles is not None and source is not None:
            shown = convert_angles(
                angles, source, target, degrees=args.degrees, relabel=args.relabel, warn=False
            )
        else:
            shown = matrix_to_euler(R, target, degrees=args.degrees, validate=False, warn=False)
        in_frame = R  # the matrix the target's angles describe, in the target's frame
        if args.relabel and source is not None and source.up_axis and target.up_axis:
            in_frame = change_up_axis(R, source.up_axis, target.up_axis, validate=False)
        status = gimbal_lock_status(in_frame, target, degrees=args.degrees, validate=False)
        locked = bool(status.locked)
        middle = math.radians(shown[1]) if args.degrees else float(shown[1])
        note = _lock_words(target, middle) if locked else None
        results.append(
            {
                "convention": target.name,
                "seq": target.seq,
                "angle_names": list(target.angle_names),
                "angles": [float(x) for x in shown],
                "gimbal_lock": locked,
                "distance_from_lock": float(status.distance),
                "note": note,
            }
        )
        frame = f", {target.up_axis} up" if args.relabel else ""
        lines.append(
            f"to {target.label}{frame}: "
            f"{_angle_list(target.angle_names, shown, unit, args.precision)}"
        )
        if note:
            lines.append(f"  {note}")
        else:
            distance = _format(float(status.distance), args.precision)
            lines.append(f"  distance from gimbal lock: {distance}{unit}")
    report["conversions"] = results

    if args.json:
        print(json.dumps(report, indent=2, ensure_ascii=False))
    else:
        print("\n".join(lines))
    return 0
