"""Student copies of the course notebooks: the exercises without their worked solutions.

The committed notebooks are the teacher's edition. Each exercise in them is three tagged code
cells: ``exercise`` (the learner's cell, whose answer starts as ``...``), ``solution`` (the
worked answer, stored folded) and ``check`` (a self-check that reports on the answer). A student
copy is the same notebook with the ``solution`` cells removed and every output cleared, in the
normal form of :mod:`eulerlib_course.notebook_form`; run top to bottom, each check then finds
the ``...`` and says "not yet" until the learner fills in an answer.

The copy is made by nbconvert's ``TagRemovePreprocessor`` (removing the cells tagged
``solution``) and ``ClearOutputPreprocessor``. :func:`student_copy` turns one notebook into its
copy; :func:`write_student_copies` writes a copy of every notebook of a folder into another
folder, refusing to overwrite files unless asked to.

This module needs the ``notebooks`` extra (nbformat, nbconvert).
"""

from __future__ import annotations

import shutil
from pathlib import Path
from typing import Any

from nbconvert.preprocessors import ClearOutputPreprocessor, TagRemovePreprocessor

from eulerlib._validation import check_flag
from eulerlib_course.notebook_form import normalize_notebook, read_notebook, write_notebook

__all__ = ["SOLUTION_TAG", "student_copy", "student_copy_paths", "write_student_copies"]

#: The tag of the cells a student copy leaves out.
SOLUTION_TAG = "solution"
#: The folder of data files next to the notebooks, copied along with the student copies.
DATA_FOLDER = "data"


def student_copy(notebook: Any) -> Any:
    """A copy of ``notebook`` without the cells tagged ``solution`` and without any outputs.

    Parameters
    ----------
    notebook : nbformat.NotebookNode
        A course notebook; it is left unchanged.

    Returns
    -------
    nbformat.NotebookNode
        The student copy, in normal form except that no code cell is numbered (nothing has run).

    Examples
    --------
    >>> import nbformat
    >>> cells = [
    ...     nbformat.v4.new_code_cell("answer = ...", metadata={"tags": ["exercise"]}),
    ...     nbformat.v4.new_code_cell("answer = 42", metadata={"tags": ["solution"]}),
    ... ]
    >>> [cell.source for cell in student_copy(nbformat.v4.new_notebook(cells=cells)).cells]
    ['answer = ...']
    """
    result = normalize_notebook(notebook)  # a copy: the preprocessors below change it in place
    resources: dict[str, Any] = {}
    remove = TagRemovePreprocessor(remove_cell_tags={SOLUTION_TAG})
    for preprocessor in (remove, ClearOutputPreprocessor()):
        result, resources = preprocessor.preprocess(result, resources)
    for index, cell in enumerate(result.cells):  # ids by position, as in the normal form
        cell["id"] = f"cell-{index:03d}"
    return result


def student_copy_paths(source: str | Path, out: str | Path) -> list[tuple[Path, Path]]:
    """Pairs (course notebook, its student copy) for every ``*.ipynb`` in ``source``.

    Raises
    ------
    ValueError
        If ``source`` is not a folder, or ``out`` is the same folder.
    """
    source, out = Path(source), Path(out)
    if not source.is_dir():
        raise ValueError(f"no notebook folder at {source}")
    if out.resolve() == source.resolve():
        raise ValueError("the student copies must go to another folder than the course notebooks")
    return [(path, out / path.name) for path in sorted(source.glob("*.ipynb"))]


def write_student_copies(source: str | Path, out: str | Path, *, force: bool = False) -> list[Path]:
    """Write a student copy of every notebook in ``source`` into ``out``; return the paths.

    Parameters
    ----------
    source : str or Path
        The folder of the course notebooks.
    out : str or Path
        The folder for the copies, created if needed.
    force : bool, optional
        Overwrite copies, and copies of the recorded data, that already exist in ``out``.
        Without it nothing is written when any of them exists.

    The folder ``data/`` next to the notebooks (recorded data that notebooks read) is copied
    into ``out`` as it is, so that the copies run there too.

    Returns
    -------
    list of Path
        The copies written, in the order of the notebooks' names.

    Raises
    ------
    ValueError
        If ``source`` is not a folder or ``out`` is the same folder.
    TypeError
        If ``force`` is not True or False.
    FileExistsError
        If some copies exist already and ``force`` is not set; the message says how many.
    """
    force = check_flag(force, "force")
    pairs = student_copy_paths(source, out)
    data = [
        (path, Path(out) / path.relative_to(source))
        for path in sorted((Path(source) / DATA_FOLDER).rglob("*"))
        if path.is_file()
    ]
    existing = [copy_path for _, copy_path in pairs + data if copy_path.exists()]
    if existing and not force:
        raise FileExistsError(
            f"{len(existing)} of the {len(pairs) + len(data)} files of the student copies "
            f"already exist in {out} (first: {existing[0].relative_to(Path(out)).as_posix()})"
        )
    Path(out).mkdir(parents=True, exist_ok=True)
    for path, copy_path in pairs:
        write_notebook(student_copy(read_notebook(path)), copy_path)
    for path, copy_path in data:  # the recorded data some notebooks read, byte for byte
        copy_path.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(path, copy_path)
    return [copy_path for _, copy_path in pairs]
