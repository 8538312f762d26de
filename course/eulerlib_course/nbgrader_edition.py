"""The nbgrader edition of the course: every exercise graded by the answer key that checks it.

A teacher who grades with `nbgrader <https://nbgrader.readthedocs.io>`_ needs the course as an
nbgrader *source* tree: one folder per assignment under ``source/``, holding notebooks whose
cells carry nbgrader's metadata. This module writes that tree from the teacher's edition (the
committed notebooks), one assignment per numbered notebook::

    DIR/nbgrader_config.py
    DIR/source/05_matrix_to_angles/05_matrix_to_angles.ipynb
    DIR/source/05_matrix_to_angles/glossary.md         (when the notebook links to it)
    DIR/source/05_matrix_to_angles/data/...            (when the notebook reads from it)

Each exercise of the course is four cells: the question (markdown), the ``exercise`` cell (the
question's data and ``answer_k = ...``), the ``solution`` cell (the worked answer) and the
``check`` cell (``check("NN.k", answer_k)``). In the edition they become two graded cells:

* an **autograded answer** cell (nbgrader's ``solution`` cell): the exercise cell's code, followed
  by the worked solution between ``### BEGIN SOLUTION`` and ``### END SOLUTION``. nbgrader's
  ``generate_assignment`` replaces that region by the short note of :data:`CODE_STUB` (set in the
  ``nbgrader_config.py`` written next to ``source/``), so a student finds the cell exactly as
  in a student copy of the course: the data, then ``answer_k = ...`` to fill in;
* an **autograder test** cell worth :data:`POINTS` ``[level]`` points: the check cell as it is,
  which the student runs for feedback, followed by a hidden test, between ``### BEGIN HIDDEN
  TESTS`` and ``### END HIDDEN TESTS``, that asks the answer key itself
  (:func:`eulerlib_course.exercises.check`, imported afresh) and fails unless the verdict is
  ``correct``. Its output is the feedback: a right answer prints the key's verdict, an answer
  left at ``...`` fails saying that no answer was handed in, and a wrong one fails with the key's
  diagnosis, so a student's graded notebook says why an answer lost its points. The reference
  and the tolerance stay in the key: the same judge decides the self-check and the grade, and
  accepts every answer that is equally right.

The glossary goes with each assignment whose notebook links to it, as ``glossary.md`` (its
text, which JupyterLab shows rendered when a link is followed), and the links point there: a
notebook would be a second notebook of every assignment, listed and graded by nbgrader.

After the first cell that imports from ``eulerlib_course`` comes the **name cell** of the
student copies (:func:`eulerlib_course.student.name_cell_source`), as an ungraded answer cell:
the student types their student id in it, so that while they work the exercises give the data
that nbgrader grades them on (at grading time the student id comes from the submission folder,
see :mod:`eulerlib_course.exercises.seeds`).

**Two modes.** In *practice mode* (the default) the visible check is the course's check, with its
full diagnosis, and the hidden test asks the installed answer key. In *graded mode*
(``graded=True``, ``--graded``) nothing on the students' side can give a graded reference away:

* the visible check cell calls :func:`~eulerlib_course.exercises.graded.check_form` with the form
  of the answer written into it (a number, a shape, the options): it says whether the answer has
  that form, never whether it is right;
* the hidden test carries the notebook's answer key as source text (the key module ``nbNN``) and
  grades with it (:func:`~eulerlib_course.exercises.graded.grade`), for the data of the student
  whose submission it runs in; nbgrader strips it from the release and puts it back when it
  grades;
* the students' environment has the course without its answer key
  (``eulerlib-course key remove`` in it, see the README): a key installed next to the release
  would compute any student's reference from their data.

Every other cell — the explanations, the demonstrations, the question — is read-only (nbgrader's
``locked`` cells, which ``autograde`` restores from the source before it runs a submission).
Outputs are cleared; nbgrader's metadata follows schema version :data:`SCHEMA_VERSION`, the one
nbgrader 0.9 reads.

An exercise that is not in the course's form (the check cell is not exactly
``check("NN.k", answer_k)``, the three cells are not consecutive, the exercise cell has no
``answer_k = ...`` line, the key has no such exercise) stops the edition with a message naming
the notebook and the exercise, before anything is written.

This module needs nbformat and nbconvert (the ``notebooks`` extra); using the edition needs
nbgrader (the ``teach`` extra).
"""

from __future__ import annotations

import copy
import inspect
import re
import shutil
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import nbformat
from nbconvert.preprocessors import ClearOutputPreprocessor

from eulerlib._validation import check_flag
from eulerlib_course.exercises import exercises
from eulerlib_course.exercises.graded import form_of
from eulerlib_course.notebook_form import normalize_notebook, read_notebook, write_notebook
from eulerlib_course.student import name_cell_source

__all__ = [
    "CODE_STUB",
    "CONFIG_NAME",
    "COURSE_ID",
    "POINTS",
    "SCHEMA_VERSION",
    "Edition",
    "nbgrader_config",
    "nbgrader_edition",
    "nbgrader_notebook",
    "write_nbgrader_edition",
]

#: Points of an exercise by its level in the notebook's climb (apply, predict, extend).
POINTS = {"apply": 1, "predict": 2, "extend": 3}
#: The version of nbgrader's cell metadata that nbgrader 0.9 reads and writes.
SCHEMA_VERSION = 3
#: What ``generate_assignment`` puts in place of a worked solution (see :func:`nbgrader_config`).
CODE_STUB = "# your answer goes in place of the ... above"
#: The name of the configuration file written next to ``source/``.
CONFIG_NAME = "nbgrader_config.py"
#: The course's name in nbgrader's exchange (``release_assignment``, ``collect``, ``fetch``).
COURSE_ID = "eulerlib"

BEGIN_SOLUTION, END_SOLUTION = "### BEGIN SOLUTION", "### END SOLUTION"
BEGIN_HIDDEN_TESTS, END_HIDDEN_TESTS = "### BEGIN HIDDEN TESTS", "### END HIDDEN TESTS"

_NOTEBOOK_NAME = re.compile(r"(\d\d)_\w+\.ipynb")
_CHECK = re.compile(r'check\("(\d\d\.\d)", (answer_\d)\)')
_TAGS = ("exercise", "solution", "check")
_COURSE_TAGS = frozenset({*_TAGS, "hide-input"})
_GLOSSARY = "glossary.ipynb"
_GLOSSARY_PAGE = "glossary.md"
_DATA = "data"


def _tags(cell: Any) -> list[str]:
    return list(cell.get("metadata", {}).get("tags", []))


def _kind(cell: Any) -> str | None:
    """``exercise``, ``solution``, ``check`` or None, from the cell's tags."""
    kinds = [tag for tag in _tags(cell) if tag in _TAGS]
    return kinds[0] if kinds else None


def _nbgrader(grade_id: str, *, grade: bool, solution: bool, locked: bool) -> dict[str, Any]:
    """nbgrader's metadata of a cell (schema version 3)."""
    return {
        "grade": grade,
        "grade_id": grade_id,
        "locked": locked,
        "schema_version": SCHEMA_VERSION,
        "solution": solution,
    }


def _without_course_tags(cell: Any) -> dict[str, Any]:
    """The cell's metadata without the exercise tags and JupyterLab's folding state."""
    metadata = {key: value for key, value in cell.metadata.items() if key != "jupyter"}
    tags = [tag for tag in _tags(cell) if tag not in _COURSE_TAGS]
    metadata.pop("tags", None)
    if tags:
        metadata["tags"] = tags
    return metadata


def _answer_cell(exercise: Any, solution: Any, exercise_id: str) -> Any:
    grade_id = "answer-" + exercise_id.replace(".", "-")
    source = "\n".join(
        [exercise.source.rstrip(), BEGIN_SOLUTION, solution.source.rstrip(), END_SOLUTION]
    )
    cell = nbformat.v4.new_code_cell(source, metadata=_without_course_tags(exercise))
    cell.metadata["nbgrader"] = _nbgrader(grade_id, grade=False, solution=True, locked=False)
    return cell


def _key_source(exercise_id: str) -> str:
    """The source of the key module of ``exercise_id``'s notebook, importing absolutely."""
    import importlib

    package = "eulerlib_course.exercises"
    module = importlib.import_module(f"{package}.nb{exercise_id[:2]}")
    return re.sub(
        r"^from \.(\w+) import",
        rf"from {package}.\1 import",
        inspect.getsource(module),
        flags=re.MULTILINE,
    )


def _form_call(exercise_id: str, answer: str) -> str:
    key = exercises()[exercise_id]
    form = form_of(key.judge)
    if key.level == "predict":
        form["prediction"] = True  # recorded, for the cell that settles it
    arguments = "".join(f", {name}={value!r}" for name, value in form.items())
    return (
        "from eulerlib_course.exercises.graded import check_form\n\n"
        f'check_form("{exercise_id}", {answer}{arguments})'
    )


def _test_cell(
    check: Any, exercise_id: str, answer: str, points: int, *, graded: bool = False
) -> Any:
    grade_id = "test-" + exercise_id.replace(".", "-")
    if graded:
        visible = _form_call(exercise_id, answer)
        hidden = [
            BEGIN_HIDDEN_TESTS,
            "# graded by the answer key of this notebook, carried here: the release has none",
            "from eulerlib_course.exercises.graded import grade as _grade",
            "",
            f"_KEY_SOURCE = {_key_source(exercise_id)!r}",
            '_key = {"__name__": "answer_key"}',
            f'exec(compile(_KEY_SOURCE, "answer key {exercise_id[:2]}", "exec"), _key)',
            f'_feedback = _grade(_key["EXERCISES"], "{exercise_id}", {answer})',
            *_verdict_lines(exercise_id, answer),
            END_HIDDEN_TESTS,
        ]
    else:
        visible = check.source.strip()
        hidden = [
            BEGIN_HIDDEN_TESTS,
            "# graded by the answer key itself, whatever the notebook may have redefined",
            "import eulerlib_course.exercises as _answer_key",
            "",
            f'_feedback = _answer_key.check("{exercise_id}", {answer})',
            *_verdict_lines(exercise_id, answer),
            END_HIDDEN_TESTS,
        ]
    cell = nbformat.v4.new_code_cell(
        "\n".join([visible, *hidden]), metadata=_without_course_tags(check)
    )
    cell.metadata["nbgrader"] = _nbgrader(grade_id, grade=True, solution=False, locked=True)
    cell.metadata["nbgrader"]["points"] = points
    return cell


def _verdict_lines(exercise_id: str, answer: str) -> list[str]:
    """The hidden test's last lines: a right answer prints the key's verdict, so the graded
    notebook shows it; an answer left at ``...`` fails saying that no answer was handed in (not
    the self-check's "replace the ... and run the cell again"); a wrong one fails with the key's
    diagnosis."""
    blank = f"Exercise {exercise_id} — no answer: {answer} was handed in as ..."
    return [
        'if _feedback.status == "correct":',
        "    print(_feedback)",
        'elif _feedback.status == "not yet":',
        f"    raise AssertionError({blank!r})",
        "else:",
        "    raise AssertionError(str(_feedback))",
    ]


def _lock(cell: Any, grade_id: str) -> Any:
    locked = copy.deepcopy(cell)
    locked.metadata["nbgrader"] = _nbgrader(grade_id, grade=False, solution=False, locked=True)
    return locked


def _cleared(notebook: Any) -> Any:
    """A copy of ``notebook`` in normal form, without outputs and without saved widget state."""
    result = normalize_notebook(notebook)
    result, _ = ClearOutputPreprocessor().preprocess(result, {})
    result.metadata.pop("widgets", None)
    return result


def _name_cell() -> Any:
    source = "\n".join([name_cell_source(None), BEGIN_SOLUTION, END_SOLUTION])
    cell = nbformat.v4.new_code_cell(source)
    cell.metadata["nbgrader"] = _nbgrader("student-name", grade=False, solution=True, locked=False)
    return cell


def nbgrader_notebook(notebook: Any, name: str, *, graded: bool = False) -> Any:
    """The nbgrader source version of one course notebook (see the module docstring).

    Parameters
    ----------
    notebook : nbformat.NotebookNode
        A course notebook (teacher's edition); it is left unchanged.
    name : str
        Its file name, ``NN_name.ipynb``: the exercises in it must be ``NN.1``, ``NN.2``, …
    graded : bool, optional
        Graded mode (see the module docstring): the visible checks check the form only and the
        hidden tests carry the answer key.

    Returns
    -------
    nbformat.NotebookNode
        The notebook with an autograded answer cell and an autograder test cell per exercise,
        every other cell read-only, outputs cleared.

    Raises
    ------
    ValueError
        If ``name`` is not ``NN_name.ipynb``, or an exercise is not in the course's form or not
        in the answer key; the message names the notebook and the exercise.

    Examples
    --------
    >>> import nbformat
    >>> new = nbformat.v4.new_code_cell
    >>> course = nbformat.v4.new_notebook(cells=[
    ...     new("from eulerlib_course import check, given"),
    ...     new('R_ex = given("05.1")\\nanswer_1 = ...', metadata={"tags": ["exercise"]}),
    ...     new("answer_1 = [-100, 35, 160]", metadata={"tags": ["solution"]}),
    ...     new('check("05.1", answer_1)', metadata={"tags": ["check"]}),
    ... ])
    >>> edition = nbgrader_notebook(course, "05_matrix_to_angles.ipynb")
    >>> [cell.metadata["nbgrader"]["grade_id"] for cell in edition.cells]
    ['cell-000', 'student-name', 'answer-05-1', 'test-05-1']
    >>> print(edition.cells[2].source)
    R_ex = given("05.1")
    answer_1 = ...
    ### BEGIN SOLUTION
    answer_1 = [-100, 35, 160]
    ### END SOLUTION
    >>> edition.cells[3].metadata["nbgrader"]["points"]
    1
    """
    match = _NOTEBOOK_NAME.fullmatch(name)
    if match is None:
        raise ValueError(f"{name}: a course notebook is named NN_name.ipynb")
    number = match.group(1)
    key = exercises()
    edition = _cleared(notebook)
    cells = edition.cells
    result: list[Any] = []
    count = 0
    index = 0
    while index < len(cells):
        cell = cells[index]
        kind = _kind(cell)
        if kind is None:
            result.append(_lock(cell, f"cell-{len(result):03d}"))
            if cell.cell_type == "code" and "from eulerlib_course import" in cell.source:
                if not any(c.metadata["nbgrader"]["grade_id"] == "student-name" for c in result):
                    result.append(_name_cell())
            index += 1
            continue
        count += 1
        exercise_id = f"{number}.{count}"
        where = f"{name}, exercise {exercise_id}"
        three = cells[index : index + 3]
        if [_kind(c) for c in three] != list(_TAGS):
            raise ValueError(
                f"{where}: expected an exercise cell, its solution cell and its check cell, "
                "in this order and next to each other"
            )
        exercise, solution, check = three
        found = _CHECK.fullmatch(check.source.strip())
        if found is None:
            raise ValueError(f'{where}: the check cell must be exactly check("NN.k", answer_k)')
        if found.group(1) != exercise_id:
            raise ValueError(f"{where}: the check cell names exercise {found.group(1)}")
        answer = found.group(2)
        if not re.search(rf"^{answer} = \.\.\.\s*$", exercise.source, flags=re.MULTILINE):
            raise ValueError(f"{where}: the exercise cell has no `{answer} = ...` line")
        if exercise_id not in key:
            raise ValueError(f"{where}: the answer key has no exercise {exercise_id}")
        points = POINTS[key[exercise_id].level]
        result.append(_answer_cell(exercise, solution, exercise_id))
        result.append(_test_cell(check, exercise_id, answer, points, graded=graded))
        index += 3
    edition.cells = result
    for position, cell in enumerate(edition.cells):
        cell["id"] = f"cell-{position:03d}"
    return edition


def _glossary_page(notebook: Any) -> str:
    """The glossary's text as one Markdown file (its cells are Markdown).

    An assignment's folder holds its own notebook only, so the glossary's links to the course's
    notebooks (``[[05](05_matrix_to_angles.ipynb)]``) become their plain numbers (``[05]``).
    """
    parts = [cell.source.strip() for cell in notebook.cells if cell.cell_type == "markdown"]
    text = "\n\n".join(parts) + "\n"
    return re.sub(r"\[(\d\d)\]\(\d\d_[^)\s]*\.ipynb\)", r"\1", text)


def _linking_glossary_page(notebook: Any) -> Any:
    """``notebook`` with its links to the glossary notebook pointing at the glossary page."""
    for cell in notebook.cells:
        if cell.cell_type == "markdown":
            cell.source = cell.source.replace(_GLOSSARY, _GLOSSARY_PAGE)
    return notebook


def nbgrader_config() -> str:
    """The text of the ``nbgrader_config.py`` of the edition.

    It sets nbgrader's ``ClearSolutions.code_stub`` to :data:`CODE_STUB`. nbgrader's own stub
    (``raise NotImplementedError()``) would make every answer cell fail even after the student
    has filled in the ``...`` kept above the solution. And it puts the folder of the Python
    that runs nbgrader first on ``PATH``: nbgrader starts the ``alembic`` command from ``PATH``
    when it creates the gradebook, and a teacher who runs ``../.venv/bin/nbgrader`` without
    activating the environment would otherwise meet ``FileNotFoundError: 'alembic'``.
    Then come the settings of :func:`_grading_settings`: autograde without the false "checksum
    has changed" of hidden tests, feedback pages and formgrader views with MathJax in them, no
    SQLAlchemy session
    warnings from nbgrader, and the course's name in the exchange (:data:`COURSE_ID`).
    """
    return (
        "# nbgrader settings of the eulerlib course, as written by\n"
        "# `eulerlib-course notebooks nbgrader`.\n"
        "# Run nbgrader's commands in this folder, or copy these settings into the\n"
        "# nbgrader_config.py of your course.\n"
        "import os\n"
        "import sys\n"
        "\n"
        "c = get_config()  # noqa: F821 (defined by nbgrader when it reads this file)\n"
        "\n"
        "# nbgrader runs the `alembic` command from PATH when it creates gradebook.db; with\n"
        "# `../.venv/bin/nbgrader` and the environment not activated, that command is not on\n"
        "# PATH. The folder of the Python that runs nbgrader holds it: look there first.\n"
        "os.environ['PATH'] = os.pathsep.join(\n"
        "    [os.path.dirname(sys.executable), os.environ.get('PATH', '')]\n"
        ")\n"
        "\n"
        "# Each answer cell keeps the course's `answer_k = ...` line above the worked solution,\n"
        "# so the released copy needs only a note where the solution was (nbgrader's default,\n"
        "# `raise NotImplementedError()`, would fail every answer).\n"
        f'c.ClearSolutions.code_stub = {{"python": "{CODE_STUB}"}}\n' + _grading_settings()
    )


def _grading_settings() -> str:
    """The settings of autograde, the feedback pages and the exchange.

    See :mod:`eulerlib_course.nbgrader_hooks`.
    """
    return (
        "\n"
        "# autograde: a test cell handed back as it was released is not reported as changed\n"
        "# (nbgrader stores its checksum with the hidden tests, which the release never had).\n"
        "# The feedback pages and the formgrader's view of a submission: MathJax written into\n"
        "# each page, so that it typesets offline.\n"
        "import warnings\n"
        "\n"
        "from eulerlib_course import nbgrader_hooks\n"
        "\n"
        "c.Autograde.sanitize_preprocessors = nbgrader_hooks.sanitize_preprocessors()\n"
        "c.HTMLExporter.extra_template_basedirs = nbgrader_hooks.feedback_template_dirs()\n"
        "c.HTMLExporter.filters = {\n"
        '    "mathjax_script": "eulerlib_course.nbgrader_hooks.mathjax_script"\n'
        "}\n"
        "\n"
        "# nbgrader 0.9 with SQLAlchemy 2 warns about its own gradebook sessions on every\n"
        "# submission; nothing is wrong with the grades.\n"
        "warnings.filterwarnings('ignore', message=r'Object of type <\\w+> not in session')\n"
        "\n"
        "# The course's name in nbgrader's exchange (release_assignment, collect,\n"
        "# release_feedback; students fetch with --course eulerlib). The exchange is\n"
        "# /srv/nbgrader/exchange unless you set another folder that teacher and students\n"
        "# can all write, e.g. c.Exchange.root = '/home/shared/exchange'.\n"
        f"c.CourseDirectory.course_id = {COURSE_ID!r}\n"
    )


@dataclass(frozen=True)
class Edition:
    """The files of the nbgrader edition: path relative to the output folder → what to write.

    ``notebooks`` holds the notebooks (nbformat nodes), ``files`` the files copied as they are
    (relative path → source path), ``config`` the text of ``nbgrader_config.py``, ``texts``
    the text files written (relative path → text: the glossary page).
    """

    notebooks: dict[Path, Any]
    files: dict[Path, Path]
    config: str
    texts: dict[Path, str] = field(default_factory=dict)

    @property
    def assignments(self) -> list[str]:
        """The assignments, in course order."""
        return sorted({path.parts[1] for path in self.notebooks})

    def paths(self) -> Iterator[Path]:
        """Every file the edition writes, relative to the output folder."""
        yield Path(CONFIG_NAME)
        yield from self.notebooks
        yield from self.texts
        yield from self.files


def _mentions_data(notebook: Any, data: Path) -> bool:
    """True when a code cell names the data folder or a file in it."""
    code = "\n".join(cell.source for cell in notebook.cells if cell.cell_type == "code")
    names = [path.name for path in data.iterdir() if path.is_file()]
    return bool(re.search(r"""["']data(?:["'/\\])""", code)) or any(n in code for n in names)


def nbgrader_edition(source: str | Path, *, graded: bool = False) -> Edition:
    """Build the nbgrader edition of every numbered notebook (``NN_*.ipynb``) in ``source``.

    Raises
    ------
    ValueError
        If ``source`` is not a folder, holds no numbered notebooks, or an exercise is not in the
        course's form (see :func:`nbgrader_notebook`).
    """
    source = Path(source)
    if not source.is_dir():
        raise ValueError(f"no notebook folder at {source}")
    paths = sorted(p for p in source.glob("*.ipynb") if _NOTEBOOK_NAME.fullmatch(p.name))
    if not paths:
        raise ValueError(f"no course notebooks (NN_name.ipynb) in {source}")
    glossary_path, data = source / _GLOSSARY, source / _DATA
    glossary = _glossary_page(read_notebook(glossary_path)) if glossary_path.is_file() else None
    texts: dict[Path, str] = {}
    notebooks: dict[Path, Any] = {}
    files: dict[Path, Path] = {}
    for path in paths:
        notebook = read_notebook(path)
        folder = Path("source", path.stem)
        notebooks[folder / path.name] = nbgrader_notebook(notebook, path.name, graded=graded)
        text = "\n".join(cell.source for cell in notebook.cells if cell.cell_type == "markdown")
        if glossary is not None and _GLOSSARY in text:
            texts[folder / _GLOSSARY_PAGE] = glossary
            _linking_glossary_page(notebooks[folder / path.name])
        if data.is_dir() and _mentions_data(notebook, data):
            for file in sorted(data.rglob("*")):
                if file.is_file() and "__pycache__" not in file.parts:
                    files[folder / _DATA / file.relative_to(data)] = file
    return Edition(notebooks, files, nbgrader_config(), texts)


def write_nbgrader_edition(
    source: str | Path, out: str | Path, *, force: bool = False, graded: bool = False
) -> Edition:
    """Write the nbgrader edition of the notebooks in ``source`` into the course folder ``out``.

    Parameters
    ----------
    source : str or Path
        The folder of the course notebooks (teacher's edition).
    out : str or Path
        The nbgrader course folder: ``nbgrader_config.py`` and ``source/`` go in it. Created if
        needed; other files in it are left alone.
    force : bool, optional
        Overwrite files of an earlier edition. Without it nothing is written when any of the
        files exists.
    graded : bool, optional
        Graded mode (see the module docstring); practice mode without it.

    Returns
    -------
    Edition
        What was written (:attr:`Edition.assignments` lists the assignments).

    Raises
    ------
    ValueError
        If ``source`` is not a folder of course notebooks, ``out`` is that folder, or an exercise
        is not in the course's form; nothing is written then.
    TypeError
        If ``force`` is not True or False.
    FileExistsError
        If files of the edition exist already and ``force`` is not set; the message says how many.
    """
    force = check_flag(force, "force")
    graded = check_flag(graded, "graded")
    out = Path(out)
    if out.resolve() == Path(source).resolve():
        raise ValueError("the nbgrader edition must go to another folder than the course notebooks")
    edition = nbgrader_edition(source, graded=graded)
    existing = [path for path in edition.paths() if (out / path).exists()]
    if existing and not force:
        total = len(list(edition.paths()))
        raise FileExistsError(
            f"{len(existing)} of the {total} files of the nbgrader edition already exist in "
            f"{out} (first: {existing[0].as_posix()})"
        )
    out.mkdir(parents=True, exist_ok=True)
    (out / CONFIG_NAME).write_text(edition.config, encoding="utf-8")
    for relative, notebook in edition.notebooks.items():
        (out / relative).parent.mkdir(parents=True, exist_ok=True)
        write_notebook(notebook, out / relative)
    for relative, text in edition.texts.items():
        (out / relative).parent.mkdir(parents=True, exist_ok=True)
        (out / relative).write_text(text, encoding="utf-8")
    for relative, file in edition.files.items():
        (out / relative).parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(file, out / relative)
    return edition
