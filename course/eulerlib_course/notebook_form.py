"""The normal form of a course notebook, and refreshing a notebook into it.

The stored outputs of the notebooks are part of the record: CI re-executes every notebook and
compares its outputs with the stored ones (strict nbval). For that comparison to mean something
the stored notebook must be exactly what a fresh execution writes, in a normal form:

* code cells numbered 1, 2, 3, … in order, as a clean top-to-bottom run numbers them, and each
  result carrying the number of its cell;
* consecutive pieces of printed output joined into one (the kernel may split a print);
* cell metadata reduced to the ``tags``, to JupyterLab's folding state,
  ``jupyter.source_hidden`` and ``jupyter.outputs_hidden`` (worked solutions are stored folded),
  and to ``alt``, the text alternatives of the cell's figures (nbconvert's cell metadata of that
  name; one string per figure, in order, see :func:`eulerlib_course.site.figure_alts`);
  no timings, no ``collapsed``/``scrolled`` state, no empty entries;
* notebook metadata reduced to the ``python3`` kernelspec, the language name and, when a cell
  shows a widget, the widgets' saved state (``widgets``), which lets JupyterLab draw a widget's
  first state — an explorable's picture and controls — when no kernel is running;
* cell ids derived from the cell's position (``cell-000``, ``cell-001``, …), so re-running
  never changes them.

The form is produced by nbconvert's own preprocessors: ``ClearMetadataPreprocessor`` (applied to
every cell, see :class:`KeepCellMetadata`) and ``CoalesceStreamsPreprocessor``, followed by
:class:`NumberCells` for the numbering and the ids. :func:`normalize_notebook` applies them,
:func:`is_normalized` tells whether a stored notebook is in the form, and
:func:`refresh_notebook` executes a notebook with nbclient and stores it in the form.

This module needs the ``notebooks`` extra (nbformat, nbclient, nbconvert).
"""

from __future__ import annotations

import copy
import subprocess
from pathlib import Path
from typing import Any

import nbformat
from nbclient import NotebookClient
from nbconvert.preprocessors import (
    ClearMetadataPreprocessor,
    CoalesceStreamsPreprocessor,
    Preprocessor,
)

__all__ = [
    "CELL_METADATA_KEPT",
    "KERNELSPEC",
    "KeepCellMetadata",
    "NumberCells",
    "is_normalized",
    "normalize_notebook",
    "read_notebook",
    "refresh_notebook",
    "write_notebook",
]

KERNELSPEC = {"display_name": "Python 3", "language": "python", "name": "python3"}
_WIDGET_STATE = "application/vnd.jupyter.widget-state+json"

#: The cell metadata the normal form keeps, as key paths (nbconvert's mask notation).
CELL_METADATA_KEPT = frozenset(
    {"tags", "alt", ("jupyter", "source_hidden"), ("jupyter", "outputs_hidden")}
)


class KeepCellMetadata(ClearMetadataPreprocessor):
    """nbconvert's ``ClearMetadataPreprocessor``, keeping :data:`CELL_METADATA_KEPT` in every cell.

    Two adjustments to the parent class. It filters code cells only; here markdown and raw cells
    are filtered too (an editor leaves state on them as well). And it keeps one nested path per
    top-level key, so ``("jupyter", "source_hidden")`` and ``("jupyter", "outputs_hidden")``
    would drop each other; here the nested paths under one key are kept together. Entries left
    empty by the filter (``tags: []``, ``jupyter: {}``) are dropped. Notebook metadata is left to
    :func:`normalize_notebook`.
    """

    def __init__(self, **kwargs: Any) -> None:
        super().__init__(
            preserve_cell_metadata_mask=set(CELL_METADATA_KEPT),
            clear_notebook_metadata=False,
            **kwargs,
        )

    def nested_masks(self, mask: Any) -> dict[str, set[tuple[str, ...]]]:
        nested: dict[str, set[tuple[str, ...]]] = {}
        for key in mask:
            if not isinstance(key, str) and len(key) > 1:
                nested.setdefault(self.current_key(key), set()).add(tuple(key[1:]))
        return nested

    def preprocess_cell(self, cell: Any, resources: Any, index: int) -> tuple[Any, Any]:
        metadata = cell.get("metadata", {}).items()
        kept = self.nested_filter(metadata, self.preserve_cell_metadata_mask)
        cell.metadata = {key: value for key, value in kept if value not in ([], {})}
        return cell, resources


class NumberCells(Preprocessor):
    """Number the code cells 1, 2, 3, … and give every cell the id ``cell-NNN`` of its position.

    Results (``execute_result`` outputs) carry their cell's number; markdown and raw cells carry
    neither a number nor outputs, nor an empty ``attachments`` entry.
    """

    def preprocess(self, nb: Any, resources: Any) -> tuple[Any, Any]:
        count = 0
        for index, cell in enumerate(nb.cells):
            cell["id"] = f"cell-{index:03d}"
            if cell.cell_type == "code":
                count += 1
                cell["execution_count"] = count
                for output in cell.get("outputs", []):
                    if output.get("output_type") == "execute_result":
                        output["execution_count"] = count
            else:
                cell.pop("outputs", None)
                cell.pop("execution_count", None)
                if not cell.get("attachments"):
                    cell.pop("attachments", None)
        return nb, resources


def normalize_notebook(notebook: Any) -> Any:
    """Return a copy of an ``nbformat`` notebook in normal form (see the module docstring).

    Parameters
    ----------
    notebook : nbformat.NotebookNode
        A version-4 notebook; it is left unchanged.

    Returns
    -------
    nbformat.NotebookNode
        The normalized copy.

    Examples
    --------
    >>> import nbformat
    >>> cell = nbformat.v4.new_code_cell("1 + 1", execution_count=7)
    >>> cell.metadata = {"scrolled": True, "tags": ["check"]}
    >>> normal = normalize_notebook(nbformat.v4.new_notebook(cells=[cell]))
    >>> normal.cells[0].id, normal.cells[0].execution_count, normal.cells[0].metadata
    ('cell-000', 1, {'tags': ['check']})
    """
    result = copy.deepcopy(notebook)
    resources: dict[str, Any] = {}
    for preprocessor in (KeepCellMetadata(), CoalesceStreamsPreprocessor(), NumberCells()):
        result, resources = preprocessor.preprocess(result, resources)
    saved = result.metadata.get("widgets", {}).get(_WIDGET_STATE, {})
    result.metadata = {"kernelspec": dict(KERNELSPEC), "language_info": {"name": "python"}}
    if saved.get("state"):  # what nbclient stores after a cell displayed a widget
        result.metadata["widgets"] = {_WIDGET_STATE: saved}
    result.nbformat, result.nbformat_minor = 4, 5
    return result


def read_notebook(path: str | Path) -> Any:
    """Read the notebook at ``path`` as an nbformat version-4 notebook."""
    return nbformat.read(str(path), as_version=4)


def write_notebook(notebook: Any, path: str | Path) -> None:
    """Write ``notebook`` to ``path`` as UTF-8 with ``\\n`` line ends, on every platform."""
    with Path(path).open("w", encoding="utf-8", newline="\n") as stream:
        nbformat.write(notebook, stream)


def is_normalized(path: str | Path) -> bool:
    """True when the notebook at ``path`` is stored exactly in normal form."""
    notebook = read_notebook(path)
    return bool(normalize_notebook(notebook) == notebook)


def refresh_notebook(path: str | Path, *, timeout: int = 300) -> None:
    """Execute the notebook at ``path`` top to bottom and write it back normalized.

    The notebook runs with the ``python3`` kernel and its own folder as working directory, as
    nbval runs it. A cell that raises stops the run (nbclient's ``CellExecutionError``) unless it
    is tagged ``raises-exception``; the file is then left as it was.
    """
    path = Path(path)
    notebook = read_notebook(path)
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
    write_notebook(normal, path)
