"""Keeping the course notebooks reproducible, and making student copies of them.

The stored outputs of the notebooks are part of the record: CI re-executes every notebook and
compares its outputs with the stored ones (strict nbval). For that comparison to mean something
the stored notebook must be exactly what a fresh execution writes, in a normal form:

* code cells numbered 1, 2, 3, … in order, as a clean top-to-bottom run numbers them;
* consecutive pieces of printed output joined into one (the kernel may split a print);
* cell metadata reduced to the ``tags`` (no timings, no collapsed/scrolled state);
* notebook metadata reduced to the ``python3`` kernelspec and the language name;
* cell ids derived from the cell's position, so re-running never changes them.

:func:`refresh_notebook` executes a notebook and writes it back in that form;
:func:`is_normalized` tells whether a stored notebook is in it. :func:`student_copy` drops the
cells tagged ``solution`` and all outputs, so that each exercise's check says "not yet" until
the learner fills in the answer.

Command line: ``eulerlib notebooks refresh [NOTEBOOK ...]`` and
``eulerlib notebooks student --out DIR``. Requires the ``notebooks`` extra (nbformat, nbclient).
"""

from __future__ import annotations

import argparse
import copy
import subprocess
from pathlib import Path
from typing import Any

__all__ = [
    "is_normalized",
    "normalize_notebook",
    "refresh_notebook",
    "student_copy",
    "write_student_copies",
]

KERNELSPEC = {"display_name": "Python 3", "language": "python", "name": "python3"}
SOLUTION_TAG = "solution"


def normalize_notebook(notebook: Any) -> Any:
    """Return a normalized deep copy of an ``nbformat`` notebook (see the module docstring)."""
    result = copy.deepcopy(notebook)
    result.metadata = {"kernelspec": dict(KERNELSPEC), "language_info": {"name": "python"}}
    result.nbformat, result.nbformat_minor = 4, 5
    count = 0
    for index, cell in enumerate(result.cells):
        tags = list(cell.get("metadata", {}).get("tags", []))
        cell["metadata"] = {"tags": tags} if tags else {}
        cell["id"] = f"cell-{index:03d}"
        if cell.cell_type == "code":
            count += 1
            cell["execution_count"] = count
            cell["outputs"] = _merge_streams(cell.get("outputs", []))
            for output in cell["outputs"]:
                if output.get("output_type") == "execute_result":
                    output["execution_count"] = count
        else:
            cell.pop("outputs", None)
            cell.pop("execution_count", None)
            if not cell.get("attachments"):
                cell.pop("attachments", None)
    return result


def _text(text: str | list[str]) -> str:
    return "".join(text) if isinstance(text, list) else text


def _merge_streams(outputs: list[Any]) -> list[Any]:
    """Join consecutive stream outputs of the same name (the kernel may split one print)."""
    merged: list[Any] = []
    for output in outputs:
        previous = merged[-1] if merged else None
        if (
            previous is not None
            and output.get("output_type") == "stream"
            and previous.get("output_type") == "stream"
            and previous.get("name") == output.get("name")
        ):
            previous["text"] = _text(previous["text"]) + _text(output["text"])
        else:
            merged.append(output)
    return merged


def is_normalized(path: str | Path) -> bool:
    """True when the notebook at ``path`` is stored exactly in normal form."""
    import nbformat

    notebook = nbformat.read(str(path), as_version=4)
    normal: Any = normalize_notebook(notebook)
    return bool(normal == notebook)


def refresh_notebook(path: str | Path, *, timeout: int = 300) -> None:
    """Execute the notebook at ``path`` top to bottom and write it back normalized.

    The notebook runs with the ``python3`` kernel and its own folder as working directory.
    A cell that raises stops the run unless it is tagged ``raises-exception``.
    """
    import nbformat
    from nbclient import NotebookClient

    path = Path(path)
    notebook = nbformat.read(str(path), as_version=4)
    client = NotebookClient(
        notebook,
        timeout=timeout,
        kernel_name="python3",
        record_timing=False,
        resources={"metadata": {"path": str(path.parent.resolve())}},
    )
    client.execute(stderr=subprocess.DEVNULL)  # the kernel's own log lines are not the notebook's
    normal = normalize_notebook(notebook)
    nbformat.validate(normal)
    with path.open("w", encoding="utf-8", newline="\n") as stream:
        nbformat.write(normal, stream)


def student_copy(notebook: Any) -> Any:
    """A copy without the cells tagged ``solution`` and without any outputs."""
    result = normalize_notebook(notebook)
    result.cells = [
        cell
        for cell in result.cells
        if SOLUTION_TAG not in cell.get("metadata", {}).get("tags", [])
    ]
    for index, cell in enumerate(result.cells):
        cell["id"] = f"cell-{index:03d}"
        if cell.cell_type == "code":
            cell["outputs"] = []
            cell["execution_count"] = None
    return result


def write_student_copies(source: str | Path, out: str | Path) -> list[Path]:
    """Write a student copy of every notebook in ``source`` into ``out``; return the paths."""
    import nbformat

    source, out = Path(source), Path(out)
    if not source.is_dir():
        raise ValueError(f"no notebook folder at {source}")
    if out.resolve() == source.resolve():
        raise ValueError("the student copies must go to another folder than the course notebooks")
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for path in sorted(source.glob("*.ipynb")):
        copy_path = out / path.name
        with copy_path.open("w", encoding="utf-8", newline="\n") as stream:
            nbformat.write(student_copy(nbformat.read(str(path), as_version=4)), stream)
        written.append(copy_path)
    return written


def configure_parser(parser: argparse.ArgumentParser) -> None:
    """Add the ``refresh`` and ``student`` actions to the ``notebooks`` sub-parser."""
    actions = parser.add_subparsers(dest="action", metavar="ACTION", required=True)
    refresh = actions.add_parser(
        "refresh",
        help="re-execute notebooks in place and normalize them (the stored outputs CI compares)",
        description="Re-execute notebooks in place and store them in normal form.",
    )
    refresh.add_argument(
        "notebooks", nargs="*", type=Path, help="notebooks to refresh (default: notebooks/*.ipynb)"
    )
    student = actions.add_parser(
        "student",
        help="write student copies: solutions and outputs removed",
        description="Write student copies of the course notebooks, without solution cells.",
    )
    student.add_argument("--src", type=Path, default=Path("notebooks"), help="course notebooks")
    student.add_argument("--out", type=Path, required=True, help="folder for the student copies")
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    """Carry out ``eulerlib notebooks ...``."""
    if args.action == "refresh":
        from nbclient.exceptions import CellExecutionError

        paths = args.notebooks or sorted(Path("notebooks").glob("*.ipynb"))
        if not paths:
            raise ValueError("no notebooks found: run from the repository root or name them")
        for path in paths:
            if not Path(path).is_file():
                raise ValueError(f"no notebook at {path}")
            try:
                refresh_notebook(path)
            except CellExecutionError as error:  # one line, not the kernel's traceback
                raise ValueError(f"{path}: a cell raised {error.ename}: {error.evalue}") from None
            print(f"refreshed {path}")
        return 0
    written = write_student_copies(args.src, args.out)
    print(f"wrote {len(written)} student copies to {args.out}")
    return 0
