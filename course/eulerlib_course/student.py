"""Student copies of the course notebooks: the exercises without their worked solutions.

The committed notebooks are the teacher's edition. Each exercise in them is three tagged code
cells: ``exercise`` (the learner's cell, whose answer starts as ``...``), ``solution`` (the
worked answer, stored folded) and ``check`` (a self-check that reports on the answer). A student
copy is the same notebook with the ``solution`` cells removed and every output cleared, in the
normal form of :mod:`eulerlib_course.notebook_form`; run top to bottom, each check then finds
the ``...`` and says "not yet" until the learner fills in an answer.

Each copy of a notebook that uses the exercises gets, after its first cell that imports from
``eulerlib_course``, a cell that says whose data the exercises give (:mod:`.exercises.seeds`):
``student_name("NAME")`` in a copy made for a named student, ``student_name(...)`` otherwise,
for the student to type their name in. Exercises that make data per student then give that student
data of their own, and check answers against the reference of those data.

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

__all__ = [
    "SOLUTION_TAG",
    "name_cell_source",
    "student_copy",
    "student_copy_paths",
    "write_student_copies",
]

#: The tag of the cells a student copy leaves out.
SOLUTION_TAG = "solution"
#: The folder of data files next to the notebooks, copied along with the student copies.
DATA_FOLDER = "data"


def name_cell_source(student: str | None) -> str:
    """The source of the cell that names the student whose data the exercises give.

    Examples
    --------
    >>> print(name_cell_source("ada"))
    # whose data the exercises give: this copy is ada's
    from eulerlib_course import student_name
    <BLANKLINE>
    student_name('ada')
    """
    if student is None:
        head = (
            "# whose data the exercises give: type your name in place of the ..., then run the\n"
            "# notebook from the top (leave the ... for the data of the teacher's edition)"
        )
        call = "student_name(...)"
    else:
        head = f"# whose data the exercises give: this copy is {student}'s"
        call = f"student_name({student!r})"
    return f"{head}\nfrom eulerlib_course import student_name\n\n{call}"


def _check_student(student: object) -> str | None:
    if student is None:
        return None
    if not isinstance(student, str) or not student.strip() or not student.isprintable():
        raise ValueError(f"student must be a name such as 'ada', got {student!r}")
    return student.strip()


def _imports_course(cell: Any) -> bool:
    return cell.cell_type == "code" and "from eulerlib_course import" in cell.source


def student_copy(notebook: Any, student: str | None = None) -> Any:
    """A copy of ``notebook`` without the cells tagged ``solution`` and without any outputs.

    Parameters
    ----------
    notebook : nbformat.NotebookNode
        A course notebook; it is left unchanged.
    student : str, optional
        The student the copy is for; their name goes in the copy's name cell (see the module
        docstring). Without it the name cell holds ``student_name(...)``.

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
    student = _check_student(student)
    first = next((i for i, cell in enumerate(result.cells) if _imports_course(cell)), None)
    if first is not None:
        import nbformat

        result.cells.insert(first + 1, nbformat.v4.new_code_cell(name_cell_source(student)))
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


def write_student_copies(
    source: str | Path, out: str | Path, *, force: bool = False, student: str | None = None
) -> list[Path]:
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
    student : str, optional
        The student the copies are for (their own data in every exercise that has some).

    The folder ``data/`` next to the notebooks (recorded data that notebooks read) is copied
    into ``out`` as it is, so that the copies run there too.

    Returns
    -------
    list of Path
        The copies written, in the order of the notebooks' names.

    Raises
    ------
    ValueError
        If ``source`` is not a folder or ``out`` is the same folder, or ``student`` is not a
        name.
    TypeError
        If ``force`` is not True or False.
    FileExistsError
        If some copies exist already and ``force`` is not set; the message says how many.
    """
    force = check_flag(force, "force")
    student = _check_student(student)
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
        write_notebook(student_copy(read_notebook(path), student), copy_path)
    for path, copy_path in data:  # the recorded data some notebooks read, byte for byte
        copy_path.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(path, copy_path)
    return [copy_path for _, copy_path in pairs]
