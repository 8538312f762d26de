"""The nbgrader edition: built from the course, then generated, autograded and exported by nbgrader.

Two parts.

* **The edition itself** (fast; nbformat only): ``eulerlib-course notebooks nbgrader`` on a small
  course in the course's exercise form, built here — its layout, nbgrader's cell metadata, the
  hidden tests, the refusals (an exercise not in the course's form, an earlier edition without
  ``--force``, nbgrader not installed).
* **nbgrader's own run** (slow, so it is its own step of ``.ci/run`` and runs only when
  ``EULERLIB_NBGRADER=1``): the edition is turned into the students' version by
  ``nbgrader generate_assignment``; submissions are made from it by filling in the answer cells
  — the worked solutions, rows of the exercises' test tables (answers right in another form and
  typical mistakes) and untouched ``...`` — and graded by ``nbgrader autograde``; the grades
  exported by ``nbgrader export`` (CSV) must be the points of the answers the test tables call
  correct, and each graded notebook must show the diagnosis the test table expects. This runs on
  the small course and on the real one (``notebooks/``) once its notebooks are in the exercise
  form. The README's whole cycle runs once more through nbgrader's exchange
  (``release_assignment``, a student's ``fetch_assignment`` and ``submit``, ``collect``,
  ``autograde``, ``generate_feedback``, ``release_feedback``, ``fetch_feedback``): no command
  may print a warning but the one the README explains, the formgrader (JupyterLab started in
  the course folder) lists each assignment's notebook alone, and the feedback page and the
  formgrader's view of a submission typeset their mathematics in Chromium with every other host
  refused.
"""

from __future__ import annotations

import copy
import csv
import importlib.util
import json
import os
import re
import secrets
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import types
import urllib.error
import urllib.request
from pathlib import Path
from typing import Any
from urllib.parse import urlsplit

import nbformat
import pytest

from eulerlib_course import cli
from eulerlib_course.exercises import Exercise, exercises
from eulerlib_course.nbgrader_edition import (
    CODE_STUB,
    CONFIG_NAME,
    nbgrader_edition,
    write_nbgrader_edition,
)
from eulerlib_course.student import name_cell_source, student_copy

REPO = Path(__file__).resolve().parents[2]
COURSE = REPO / "notebooks"
KEY = exercises()

#: Points by level, as the edition promises them (the README says so too).
POINTS = {"apply": 1, "predict": 2, "extend": 3}
#: The notebook of the small course; its exercises are those of the key's notebook 05.
SMALL = "05_matrix_to_angles"
#: The course is graded in this many parts, so that pytest-xdist can spread them over the cores.
PARTS = 2

RUN_NBGRADER = os.environ.get("EULERLIB_NBGRADER") == "1"
needs_nbgrader_run = pytest.mark.skipif(
    not RUN_NBGRADER,
    reason="nbgrader's generate_assignment, autograde and export take a minute or more: they run "
    "as their own step of .ci/run "
    "(EULERLIB_NBGRADER=1 python -m pytest course/tests/test_nbgrader.py)",
)

CHECK = re.compile(r'check\("(\d\d\.\d)", (answer_\d)\)')
#: The one warning left in an nbgrader run, which the README explains: ipykernel's, when
#: autograde starts a kernel on the loopback interface.
KERNEL_TCP = r"\[IPKernelApp\] WARNING \| Kernel is running over TCP without encryption"


# --- a small course in the course's exercise form -------------------------------------------------

md, code = nbformat.v4.new_markdown_cell, nbformat.v4.new_code_cell


def tagged(source: str, *tags: str, folded: bool = False) -> Any:
    cell = code(source, metadata={"tags": list(tags)})
    if folded:
        cell.metadata["jupyter"] = {"source_hidden": True}
    return cell


def exercise(exercise_id: str, title: str, question: str, data: str, solution: str) -> list[Any]:
    """The four cells of an exercise, as course.md describes them."""
    k = exercise_id.split(".")[1]
    lines = [data] if data else []
    return [
        md(f"**Exercise {exercise_id} ({title}).** {question}"),
        tagged("\n".join([*lines, f"answer_{k} = ..."]), "exercise"),
        tagged(solution, "solution", "hide-input", folded=True),
        tagged(f'check("{exercise_id}", answer_{k})', "check"),
    ]


def small_notebook() -> Any:
    """Notebook 05 of a small course: the key's three exercises 05.1–05.3, a link to the glossary
    and a cell that reads a file of ``data/``; stored as a refreshed notebook is, with outputs."""
    cells = [
        md("# 05 · From the matrix back to the angles\n\nReading angles off a matrix."),
        md(
            "**Prerequisites**: notebook 04.\n\n**Learning objectives**\n\n"
            "- read yaw, pitch and roll off a matrix\n- use `atan2`\n- find the second triple"
        ),
        code(
            "%matplotlib inline\nimport numpy as np\n\nfrom eulerlib import matrix_to_euler\n"
            "from eulerlib_course import check, given"
        ),
        md("At [gimbal lock](glossary.ipynb#gimbal-lock) the pitch is ±90°: $r_{31} = \\mp 1$."),
        code('samples = np.loadtxt("data/samples.csv", delimiter=",")\nprint(samples.shape)'),
        *exercise(
            "05.1",
            "read the angles",
            "Recover yaw, pitch and roll, in degrees, from `R_ex`.",
            'R_ex = given("05.1")  # the matrix of some yaw, pitch and roll',
            "yaw = np.arctan2(R_ex[1, 0], R_ex[0, 0])\npitch = -np.arcsin(R_ex[2, 0])\n"
            "roll = np.arctan2(R_ex[2, 1], R_ex[2, 2])\nanswer_1 = np.degrees([yaw, pitch, roll])",
        ),
        *exercise(
            "05.2",
            "the other triple",
            "Give the other triple of `R_ex`, the one with pitch outside [-90°, 90°].",
            "",
            "answer_2 = np.degrees(\n    [\n        np.arctan2(-R_ex[1, 0], -R_ex[0, 0]),\n"
            "        np.pi + np.arcsin(R_ex[2, 0]),\n"
            "        np.arctan2(-R_ex[2, 1], -R_ex[2, 2]),\n    ]\n)",
        ),
        *exercise(
            "05.3",
            "another convention",
            "Give the angles of `M_ex` for the sequence `'XYZ'`, in degrees.",
            'M_ex = given("05.3")',
            'answer_3 = matrix_to_euler(M_ex, "XYZ", degrees=True)',
        ),
        md("## Summary\n\nRose eq 3; Baker's formulas."),
    ]
    notebook = nbformat.v4.new_notebook(cells=cells)
    notebook.metadata["kernelspec"] = {
        "display_name": "Python 3",
        "language": "python",
        "name": "python3",
    }
    for cell in notebook.cells:  # outputs as a refreshed notebook stores them
        if cell.cell_type == "code":
            cell.outputs = [nbformat.v4.new_output("stream", text="stored output\n")]
            cell.execution_count = 1
    return notebook


def write_small_course(folder: Path) -> Path:
    """The small course in ``folder``: notebook 05, the glossary and ``data/samples.csv``."""
    folder.mkdir(parents=True)
    nbformat.write(small_notebook(), str(folder / f"{SMALL}.ipynb"))
    term = "## Gimbal lock\n\nTwo axes of rotation line up. [[05](05_a.ipynb), [07](07_b.ipynb)]"
    glossary = nbformat.v4.new_notebook(cells=[md("# Glossary"), md(term)])
    nbformat.write(glossary, str(folder / "glossary.ipynb"))
    (folder / "data").mkdir()
    (folder / "data" / "samples.csv").write_text("1,2,3\n4,5,6\n")
    return folder


@pytest.fixture
def small_course(tmp_path: Path) -> Path:
    return write_small_course(tmp_path / "course")


@pytest.fixture
def nbgrader_importable(monkeypatch: pytest.MonkeyPatch) -> None:
    """The command requires nbgrader; where it is not installed, a stand-in module answers the
    import (writing the edition itself uses nbformat only)."""
    try:
        import nbgrader  # noqa: F401
    except ImportError:
        monkeypatch.setitem(sys.modules, "nbgrader", types.ModuleType("nbgrader"))


def run_cli(capsys: pytest.CaptureFixture[str], *args: str) -> tuple[int, str, str]:
    status = cli.main(list(args))
    captured = capsys.readouterr()
    return status, captured.out, captured.err


def read(path: Path) -> Any:
    return nbformat.read(str(path), as_version=4)


def grading(cell: Any) -> dict[str, Any]:
    return dict(cell.get("metadata", {}).get("nbgrader", {}))


def tags(cell: Any) -> list[str]:
    return list(cell.get("metadata", {}).get("tags", []))


# --- the edition ----------------------------------------------------------------------------------


def test_command_writes_one_assignment_per_notebook_with_what_it_uses(
    small_course: Path,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    nbgrader_importable: None,
) -> None:
    out = tmp_path / "grading"
    status, stdout, err = run_cli(
        capsys, "notebooks", "nbgrader", "--src", str(small_course), "--out", str(out)
    )
    assert (status, err) == (0, "")
    assert stdout == f"wrote 1 nbgrader assignments and nbgrader_config.py to {out}\n"
    written = sorted(p.relative_to(out).as_posix() for p in out.rglob("*") if p.is_file())
    assert written == [
        "nbgrader_config.py",
        f"source/{SMALL}/{SMALL}.ipynb",
        f"source/{SMALL}/data/samples.csv",
        f"source/{SMALL}/glossary.md",
    ]
    assert (out / "source" / SMALL / "data" / "samples.csv").read_text() == "1,2,3\n4,5,6\n"
    config = (out / CONFIG_NAME).read_text()
    assert f'c.ClearSolutions.code_stub = {{"python": "{CODE_STUB}"}}' in config.splitlines()
    compile(config, CONFIG_NAME, "exec")
    # The glossary is a page, not a second notebook of the assignment, and the links go there.
    glossary = (out / "source" / SMALL / "glossary.md").read_text(encoding="utf-8")
    assert glossary == "# Glossary\n\n## Gimbal lock\n\nTwo axes of rotation line up. [05, 07]\n"
    notebook = read(out / "source" / SMALL / f"{SMALL}.ipynb")
    links = [c.source for c in notebook.cells if "glossary" in c.source]
    assert links == [
        "At [gimbal lock](glossary.md#gimbal-lock) the pitch is ±90°: $r_{31} = \\mp 1$."
    ]


def test_a_notebook_without_links_or_data_gets_no_companions(tmp_path: Path) -> None:
    course = write_small_course(tmp_path / "course")
    plain = small_notebook()
    plain.cells = [cell for cell in plain.cells if "data/" not in cell.source]
    plain.cells = [cell for cell in plain.cells if "glossary.ipynb" not in cell.source]
    nbformat.write(plain, str(course / f"{SMALL}.ipynb"))
    assert [path.as_posix() for path in nbgrader_edition(course).paths()] == [
        CONFIG_NAME,
        f"source/{SMALL}/{SMALL}.ipynb",
    ]


def test_each_exercise_becomes_an_answer_cell_and_a_hidden_test(small_course: Path) -> None:
    edition = nbgrader_edition(small_course)
    notebook = edition.notebooks[Path("source", SMALL, f"{SMALL}.ipynb")]
    nbformat.validate(notebook)
    course = small_notebook()
    # Every cell that is not part of an exercise is kept as it is, read-only.
    kept = [c for c in course.cells if not {"exercise", "solution", "check"} & set(tags(c))]
    locked = [c for c in notebook.cells if grading(c)["locked"] and not grading(c)["grade"]]
    glossary_page = [c.source.replace("glossary.ipynb", "glossary.md") for c in kept]
    assert [c.source for c in locked] == glossary_page
    assert all(grading(c)["solution"] is False for c in locked)
    answers = [c for c in notebook.cells if grading(c)["grade_id"].startswith("answer-")]
    tests = [c for c in notebook.cells if grading(c)["grade"]]
    # the name cell follows the cell that imports from eulerlib_course, as in a student copy
    (name,) = [c for c in notebook.cells if grading(c)["grade_id"] == "student-name"]
    assert grading(name)["solution"] and not grading(name)["locked"]
    assert name.source == f"{name_cell_source(None)}\n### BEGIN SOLUTION\n### END SOLUTION"
    before = notebook.cells[notebook.cells.index(name) - 1]
    assert "from eulerlib_course import" in before.source
    assert len(notebook.cells) == len(kept) + len(answers) + len(tests) + 1
    assert [grading(c)["grade_id"] for c in answers] == [
        "answer-05-1",
        "answer-05-2",
        "answer-05-3",
    ]
    assert [grading(c)["grade_id"] for c in tests] == ["test-05-1", "test-05-2", "test-05-3"]
    assert [grading(c)["points"] for c in tests] == [
        POINTS[KEY[f"05.{k}"].level] for k in (1, 2, 3)
    ]
    ids = [grading(c)["grade_id"] for c in notebook.cells]
    assert len(set(ids)) == len(ids)
    assert all(re.fullmatch(r"[a-zA-Z0-9_\-]+", grade_id) for grade_id in ids)

    def sources(tag: str) -> list[str]:
        return [cell.source for cell in course.cells if tag in tags(cell)]

    triples = zip(sources("exercise"), sources("solution"), sources("check"), strict=True)
    for k, (answer, test, (question, solution, check)) in enumerate(
        zip(answers, tests, triples, strict=True)
    ):
        assert answer.source == f"{question}\n### BEGIN SOLUTION\n{solution}\n### END SOLUTION"
        assert grading(answer) == {
            "grade": False,
            "grade_id": f"answer-05-{k + 1}",
            "locked": False,
            "schema_version": 3,
            "solution": True,
        }
        visible, hidden = test.source.split("\n### BEGIN HIDDEN TESTS\n")
        assert visible == check
        assert hidden.endswith("\n### END HIDDEN TESTS")
        assert f'_answer_key.check("05.{k + 1}", answer_{k + 1})' in hidden
        assert "raise AssertionError(str(_feedback))" in hidden
        assert grading(test)["locked"] and not grading(test)["solution"]
        assert "hide-input" not in tags(answer) and "jupyter" not in answer.metadata
    assert all(c.get("outputs", []) == [] for c in notebook.cells if c.cell_type == "code")
    assert all(c.get("execution_count") is None for c in notebook.cells if c.cell_type == "code")
    assert [c.id for c in notebook.cells] == [f"cell-{i:03d}" for i in range(len(notebook.cells))]


def test_the_edition_passes_nbgraders_own_metadata_check(small_course: Path) -> None:
    nbgraderformat = pytest.importorskip("nbgrader.nbgraderformat")
    validator = nbgraderformat.MetadataValidator()
    for notebook in nbgrader_edition(small_course).notebooks.values():
        validator.validate_nb(notebook)  # raises on a schema or consistency problem
        for cell in notebook.cells:
            validator.validate_cell(cell)


def test_hidden_tests_grade_with_the_key_and_say_why(
    small_course: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """The hidden test of 05.1, run here on every answer of the exercise's test table and on
    ``...``, after the notebook's imports and the exercise's data, and with ``check`` redefined
    as a notebook might."""
    edition = nbgrader_edition(small_course)
    notebook = edition.notebooks[Path("source", SMALL, f"{SMALL}.ipynb")]
    test = next(c for c in notebook.cells if grading(c).get("grade_id") == "test-05-1")
    hidden = test.source.split("### BEGIN HIDDEN TESTS\n")[1]
    imports = next(c for c in notebook.cells if c.cell_type == "code").source
    namespace: dict[str, Any] = {}
    exec("\n".join(line for line in imports.splitlines() if not line.startswith("%")), namespace)
    exec('R_ex = given("05.1")\ncheck = lambda *_: True', namespace)
    for example in KEY["05.1"].examples:
        exec(f"answer_1 = {example.code}", namespace)
        if example.status == "correct":
            exec(hidden, namespace)  # passes, and says so
            assert capsys.readouterr().out.startswith("Exercise 05.1 — correct: ")
        else:
            with pytest.raises(AssertionError) as failed:
                exec(hidden, namespace)
            assert str(failed.value).startswith("Exercise 05.1 — off: "), example.code
            assert example.says in str(failed.value), example.code
    exec("answer_1 = ...", namespace)  # no answer: said so, not "replace the ... and run again"
    with pytest.raises(AssertionError) as failed:
        exec(hidden, namespace)
    assert str(failed.value) == "Exercise 05.1 — no answer: answer_1 was handed in as ..."


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (
            lambda cells: cells[8].update(source="check_angles(answer_1, [-100, 35, 160])"),
            r"05_matrix_to_angles\.ipynb, exercise 05\.1: the check cell must be exactly",
        ),
        (
            lambda cells: cells[8].update(source='check("05.2", answer_1)'),
            r"exercise 05\.1: the check cell names exercise 05\.2",
        ),
        (
            lambda cells: cells[6].update(source='R_ex = given("05.1")\nanswer_1 = None'),
            r"exercise 05\.1: the exercise cell has no `answer_1 = \.\.\.` line",
        ),
        (
            lambda cells: cells.insert(7, code("print(R_ex)")),
            r"exercise 05\.1: expected an exercise cell, its solution cell and its check cell",
        ),
        (
            lambda cells: cells.extend(exercise("05.4", "more", "?", "", "answer_4 = 1")),
            r"exercise 05\.4: the answer key has no exercise 05\.4",
        ),
    ],
    ids=["old-style check", "wrong id", "no placeholder", "cells apart", "not in the key"],
)
def test_an_exercise_not_in_the_course_form_stops_the_edition(
    change: Any,
    message: str,
    small_course: Path,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    nbgrader_importable: None,
) -> None:
    notebook = small_notebook()
    change(notebook.cells)
    nbformat.write(notebook, str(small_course / f"{SMALL}.ipynb"))
    out = tmp_path / "grading"
    status, stdout, err = run_cli(
        capsys, "notebooks", "nbgrader", "--src", str(small_course), "--out", str(out)
    )
    assert (status, stdout) == (1, "")
    assert len(err.splitlines()) == 1 and re.search(message, err), err
    assert not out.exists()  # nothing written


def test_an_earlier_edition_is_overwritten_only_with_force(
    small_course: Path,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    nbgrader_importable: None,
) -> None:
    out = tmp_path / "grading"
    arguments = ("notebooks", "nbgrader", "--src", str(small_course), "--out", str(out))
    assert run_cli(capsys, *arguments)[0] == 0
    notebook = out / "source" / SMALL / f"{SMALL}.ipynb"
    notebook.write_text("a teacher's change\n")
    (out / "gradebook.db").write_text("grades\n")
    status, stdout, err = run_cli(capsys, *arguments)
    assert (status, stdout) == (1, "")
    assert err.splitlines() == [
        "eulerlib-course notebooks: error: 4 of the 4 files of the nbgrader edition already "
        f"exist in {out} (first: nbgrader_config.py); pass --force to overwrite them"
    ]
    assert notebook.read_text() == "a teacher's change\n"
    assert run_cli(capsys, *arguments, "--force")[0] == 0
    assert read(notebook) == nbgrader_edition(small_course).notebooks[notebook.relative_to(out)]
    assert (out / "gradebook.db").read_text() == "grades\n"  # not the edition's: left alone


def test_the_edition_refuses_the_course_folder_and_bad_flags(small_course: Path) -> None:
    with pytest.raises(ValueError, match="another folder"):
        write_nbgrader_edition(small_course, small_course)
    with pytest.raises(ValueError, match="no notebook folder at"):
        write_nbgrader_edition(small_course / "missing", small_course.parent / "out")
    with pytest.raises(ValueError, match=r"no course notebooks \(NN_name\.ipynb\)"):
        write_nbgrader_edition(small_course / "data", small_course.parent / "out")
    with pytest.raises(TypeError, match=r"^force must be True or False"):
        write_nbgrader_edition(small_course, small_course.parent / "out", force="yes")  # type: ignore[arg-type]


def test_command_without_notebook_folder_fails_in_one_line(
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
    nbgrader_importable: None,
) -> None:
    monkeypatch.chdir(tmp_path)
    status, _, err = run_cli(capsys, "notebooks", "nbgrader", "--out", "grading")
    assert status == 1 and len(err.splitlines()) == 1
    assert "no notebooks/ folder here" in err and "--src" in err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("hidden", ["nbgrader", "nbformat", "nbconvert"])
def test_command_names_the_teach_extra_when_a_tool_is_missing(
    hidden: str,
    small_course: Path,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setitem(sys.modules, hidden, None)  # `import hidden` fails, as when not installed
    out = tmp_path / "grading"
    status, stdout, err = run_cli(
        capsys, "notebooks", "nbgrader", "--src", str(small_course), "--out", str(out)
    )
    assert (status, stdout) == (1, "")
    assert err.splitlines() == [
        f"eulerlib-course notebooks: error: eulerlib-course notebooks nbgrader needs {hidden} "
        '(the teach extra of eulerlib-course): pip install -e "./course[teach]"'
    ]
    assert not out.exists()


# --- nbgrader's own run: generate_assignment, autograde, export -----------------------------------


def exercises_of(notebook: Any) -> list[tuple[str, str]]:
    """(exercise id, worked solution) of each exercise of a course notebook, in order."""
    found = []
    for index, cell in enumerate(notebook.cells):
        if "check" in tags(cell):
            match = CHECK.fullmatch(cell.source.strip())
            assert match, cell.source
            found.append((match.group(1), notebook.cells[index - 1].source))
    return found


def fill_in(release: Any, answers: dict[str, str | None]) -> Any:
    """A submission: the released notebook with ``answer_k = ...`` of each exercise replaced by
    the code given for it (``None`` leaves the ``...``)."""
    submission = copy.deepcopy(release)
    for cell in submission.cells:
        grade_id = grading(cell).get("grade_id", "")
        if not grade_id.startswith("answer-"):
            continue
        exercise_id = grade_id.removeprefix("answer-").replace("-", ".")
        code = answers[exercise_id]
        if code is None:
            continue
        placeholder = re.compile(rf"^answer_{exercise_id[-1]} = \.\.\.$", flags=re.MULTILINE)
        assert placeholder.search(cell.source), cell.source
        cell.source = placeholder.sub(lambda _, c=code: c, cell.source)
    return submission


def row(exercise: Exercise, status: str, index: int) -> tuple[str, str, str]:
    """``(code that sets answer_k, verdict, words of the feedback)``: row ``index`` (cycling) of
    the test table's rows of that verdict; for ``correct`` counted from the end, as the first
    rows tend to repeat the worked solution."""
    rows = [e for e in exercise.examples if e.status == status]
    if status == "correct":
        rows.reverse()
    example = rows[index % len(rows)]
    return f"answer_{exercise.id[-1]} = {example.code}", example.status, example.says


def answer(exercise: Exercise, verdict: str, index: int) -> tuple[str | None, str, str]:
    """An answer with that verdict: a row of the test table, or None (the untouched ``...``).

    An exercise with data of each student's own is graded on the submitting student's data,
    where the rows of the test table (written for the teacher's data) need not hold; it gets
    an answer in the wrong form as its mistake, and its worked solution as its right answer
    (see :func:`grade_course`)."""
    if verdict == "not yet":
        return None, "no answer", f"answer_{exercise.id[-1]} was handed in as ..."
    if exercise.per_student is not None and verdict == "off":
        return f"answer_{exercise.id[-1]} = 'three numbers'", "off", "is text"
    if exercise.per_student is not None:
        return "", "correct", ""  # filled in with the worked solution
    return row(exercise, verdict, index)


def nbgrader(course: Path, *args: str, **settings: str) -> str:
    """Run an nbgrader command in the course folder exactly as the README writes it: the
    environment's ``nbgrader`` script by its path, with the environment not on ``PATH`` (the
    edition's configuration finds nbgrader's ``alembic`` itself); ``settings`` are environment
    variables (a student's ``USER``). Returns what it wrote to stdout and stderr, which must
    hold no warning."""
    scripts = Path(sys.executable).parent
    path = [
        entry
        for entry in os.environ.get("PATH", "").split(os.pathsep)
        if entry and Path(entry).resolve() != scripts.resolve()
    ]
    environment = dict(os.environ, PATH=os.pathsep.join(path), **settings)
    environment.pop("VIRTUAL_ENV", None)
    result = subprocess.run(
        [str(scripts / "nbgrader"), *args],
        cwd=course,
        env=environment,
        capture_output=True,
        text=True,
        timeout=1800,
    )
    assert result.returncode == 0, f"nbgrader {' '.join(args)} failed:\n{result.stderr[-4000:]}"
    said = result.stdout + result.stderr
    alarms = [
        line
        for line in said.splitlines()
        if re.search(r"WARNING|ERROR|Warning:", line) and not re.search(KERNEL_TCP, line)
    ]
    assert not alarms, f"nbgrader {' '.join(args)} warned:\n" + "\n".join(alarms)
    return said


def grade_course(
    source: Path, course: Path, capsys: pytest.CaptureFixture[str], *, graded: bool = False
) -> None:
    """Write the edition of ``source``, let nbgrader generate, autograde and export it, and check
    the exported grades and the diagnoses in the graded notebooks. Two students hand in, with
    different ids, so each is graded on their own data where an exercise has some."""
    mode = ["--graded"] if graded else []
    status, _, err = run_cli(
        capsys, "notebooks", "nbgrader", "--src", str(source), "--out", str(course), *mode
    )
    assert status == 0, err
    nbgrader(course, "generate_assignment", "*")

    # students: what each answers to each exercise, what it should score, what it should be told
    expected_score: dict[tuple[str, str], float] = {}
    expected_max: dict[str, float] = {}
    diagnoses: dict[tuple[str, str], dict[str, tuple[str, str]]] = {}
    for number, path in enumerate(sorted(source.glob("[0-9][0-9]_*.ipynb"))):
        assignment = path.stem
        release = read(course / "release" / assignment / path.name)
        solved = exercises_of(read(path))
        assert solved, f"{path.name} has no exercises"
        keys = [KEY[exercise_id] for exercise_id, _ in solved]
        expected_max[assignment] = float(sum(POINTS[k.level] for k in keys))

        # The released notebook is the student copy, with nbgrader's note after each `...`.
        visible = "\n".join(cell.source for cell in release.cells)
        for key in keys:
            for text in key.forbidden:
                assert text not in visible, f"{path.name}: the release gives away {text!r}"
        copy_sources = [  # with the glossary as a page
            c.source.replace("glossary.ipynb", "glossary.md")
            if c.cell_type == "markdown"
            else c.source
            for c in student_copy(read(path)).cells
        ]
        released = [c.source.removesuffix(f"\n{CODE_STUB}") for c in release.cells]
        if graded:  # the visible checks check the form only, and the key is nowhere
            forms = [i for i, c in enumerate(released) if "check_form(" in c]
            assert len(forms) == len(keys), f"{path.name}: {len(forms)} form checks"
            assert all(CHECK.fullmatch(copy_sources[i].strip()) for i in forms), path.name
            released = [c for i, c in enumerate(released) if i not in forms]
            copy_sources = [c for i, c in enumerate(copy_sources) if i not in forms]
            assert "_KEY_SOURCE" not in visible and "_answer_key" not in visible
        assert released == copy_sources, f"{path.name}: the release is not the student copy"

        # Two students: one hands in the worked solutions; the other typical answers, in turn
        # (shifted from notebook to notebook) a mistake of the test table, an answer right in
        # another form, the untouched `...`, another mistake.
        typical = ("off", "correct", "not yet", "off")
        plans: dict[str, dict[str, tuple[str | None, str, str]]] = {
            "reference": {
                k.id: (solution.strip(), "correct", "")
                for k, (_, solution) in zip(keys, solved, strict=True)
            },
            "typical": {k.id: answer(k, typical[(n + number) % 4], n) for n, k in enumerate(keys)},
        }
        for k, (_, solution) in zip(keys, solved, strict=True):
            code, verdict, says = plans["typical"][k.id]
            if code == "":
                plans["typical"][k.id] = (solution.strip(), verdict, says)
        for student, plan in plans.items():
            folder = course / "submitted" / student / assignment
            shutil.copytree(course / "release" / assignment, folder)
            answers = {exercise_id: code for exercise_id, (code, _, _) in plan.items()}
            nbformat.write(fill_in(release, answers), str(folder / path.name))
            expected_score[student, assignment] = float(
                sum(
                    POINTS[KEY[i].level]
                    for i, (_, verdict, _) in plan.items()
                    if verdict == "correct"
                )
            )
            diagnoses[student, assignment] = {i: (v, says) for i, (_, v, says) in plan.items()}

    nbgrader(course, "autograde", "*")
    nbgrader(course, "export", "--to", "grades.csv")

    with (course / "grades.csv").open(newline="") as stream:
        grades = {(r["student_id"], r["assignment"]): r for r in csv.DictReader(stream)}
    assert set(grades) == set(expected_score)
    for (student, assignment), score in expected_score.items():
        exported = grades[student, assignment]
        assert float(exported["max_score"]) == expected_max[assignment], exported
        assert float(exported["score"]) == score, f"{student}, {assignment}: {exported}"
    assert all(
        grades["reference", a]["score"] == grades["reference", a]["max_score"] for a in expected_max
    )

    # Each graded test cell shows the key's verdict: "correct" printed, else the diagnosis.
    for (student, assignment), verdicts in diagnoses.items():
        graded = read(course / "autograded" / student / assignment / f"{assignment}.ipynb")
        for cell in graded.cells:
            grade_id = grading(cell).get("grade_id", "")
            if not grade_id.startswith("test-"):
                continue
            exercise_id = grade_id.removeprefix("test-").replace("-", ".")
            verdict, says = verdicts[exercise_id]
            errors = [o for o in cell.outputs if o.output_type == "error"]
            where = f"{student}, {exercise_id}"
            if verdict == "correct":
                assert not errors, f"{where}: {errors}"
                printed = "".join(o.get("text", "") for o in cell.outputs)
                assert printed.startswith(f"Exercise {exercise_id} — correct: "), where
            elif verdict == "no answer":
                assert [e.ename for e in errors] == ["AssertionError"], f"{where}: {errors}"
                assert errors[0].evalue == f"Exercise {exercise_id} — no answer: {says}", where
            else:
                assert [e.ename for e in errors] == ["AssertionError"], f"{where}: {errors}"
                assert errors[0].evalue.startswith(f"Exercise {exercise_id} — {verdict}: "), where
                assert says in errors[0].evalue, f"{where}: {errors[0].evalue}"


@needs_nbgrader_run
def test_nbgrader_generates_autogrades_and_exports_the_small_course(
    small_course: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    grade_course(small_course, tmp_path / "grading", capsys)


@needs_nbgrader_run
def test_nbgrader_grades_the_small_course_in_graded_mode(
    small_course: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    grade_course(small_course, tmp_path / "grading", capsys, graded=True)


def course_not_in_exercise_form() -> str | None:
    """Why the real course cannot be graded yet (its notebooks are being rewritten into the
    exercise form of the answer key), or None when it can."""
    for path in sorted(COURSE.glob("[0-9][0-9]_*.ipynb")):
        for cell in read(path).cells:
            if "check" in tags(cell) and not CHECK.fullmatch(cell.source.strip()):
                return f"{path.name} still has check cells of the older style"
    return None


def course_part(part: int, folder: Path) -> Path:
    """Every other notebook of the course, from the ``part``-th on, with the glossary and the
    data, in ``folder``: the course is graded in two halves, one per core."""
    folder.mkdir()
    for path in sorted(COURSE.glob("[0-9][0-9]_*.ipynb"))[part::PARTS]:
        shutil.copyfile(path, folder / path.name)
    shutil.copyfile(COURSE / "glossary.ipynb", folder / "glossary.ipynb")
    shutil.copytree(COURSE / "data", folder / "data", ignore=shutil.ignore_patterns("__pycache__"))
    return folder


@needs_nbgrader_run
@pytest.mark.parametrize(
    "part", range(PARTS), ids=[f"part {p + 1} of {PARTS}" for p in range(PARTS)]
)
def test_nbgrader_generates_autogrades_and_exports_the_course(
    part: int, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    reason = course_not_in_exercise_form()
    if reason is not None:
        pytest.skip(f"the course is not in the exercise form yet: {reason}")
    grade_course(course_part(part, tmp_path / "course"), tmp_path / "grading", capsys)


# --- the README's whole cycle: release, collect, feedback ----------------------------------------


def chromium_executable() -> str | None:
    """The system's Chromium, as the website's test finds it (``EULERLIB_CHROMIUM`` or PATH)."""
    named = os.environ.get("EULERLIB_CHROMIUM")
    if named:
        return named if Path(named).is_file() else None
    return shutil.which("chromium") or shutil.which("chromium-browser")


#: Collected in a feedback page once MathJax has finished: its typeset formulas, TeX errors and
#: the text outside them (where a ``$`` would be math left raw).
MATH_FACTS = """async () => {
  if (window.MathJax && window.MathJax.startup) { await window.MathJax.startup.promise; }
  const copy = document.body.cloneNode(true);
  copy.querySelectorAll("mjx-container, pre, code, script, style").forEach((e) => e.remove());
  return {
    typeset: document.querySelectorAll("mjx-container").length,
    texErrors: [...document.querySelectorAll("mjx-merror")].map((e) => e.textContent),
    text: copy.textContent,
  };
}"""


def open_offline(
    address: Path | str, headers: dict[str, str] | None = None, ready: str | None = None
) -> tuple[dict[str, Any], list[str], list[str]]:
    """Open a local page (a file, or an address on the loopback interface, sent with
    ``headers``) in the system's Chromium (headless, a fresh profile) with every request to
    another host refused; wait until the script ``ready`` is true, if one is given: what
    :data:`MATH_FACTS` finds, the refused requests and the console's errors."""
    from playwright.sync_api import TimeoutError as PlaywrightTimeoutError
    from playwright.sync_api import sync_playwright

    refused: list[str] = []
    errors: list[str] = []

    def route(request_route: Any) -> None:
        url = request_route.request.url
        if url.startswith("file:") or urlsplit(url).hostname == "127.0.0.1":
            request_route.continue_()
        else:
            refused.append(url)
            request_route.abort()

    arguments = ["--disable-background-networking", "--disable-component-update", "--no-first-run"]
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        arguments.append("--no-sandbox")  # Chromium refuses to run as root otherwise
    url = address.as_uri() if isinstance(address, Path) else address
    with tempfile.TemporaryDirectory() as profile, sync_playwright() as playwright:
        context = playwright.chromium.launch_persistent_context(
            profile,
            executable_path=chromium_executable(),
            headless=True,
            args=arguments,
            extra_http_headers=headers or {},
        )
        try:
            page = context.new_page()
            page.route("**/*", route)
            page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
            page.on("pageerror", lambda error: errors.append(str(error)))
            page.goto(url, wait_until="load")
            if ready is not None:
                try:
                    page.wait_for_function(ready, timeout=30_000)
                except PlaywrightTimeoutError:
                    errors.append(f"still not true after 30 s: {ready}")
            facts = page.evaluate(MATH_FACTS)
        finally:
            context.close()
    return facts, refused, errors


def browser_missing() -> str | None:
    """Why a page cannot be opened in Chromium here, or None."""
    if importlib.util.find_spec("playwright") is None:
        return 'no Playwright: pip install -e "./course[site]"'
    if chromium_executable() is None:
        return "no Chromium: install Debian's chromium package, or name one in EULERLIB_CHROMIUM"
    return None


#: True in the formgrader's view of a submission once its script has heard that MathJax is done
#: (formgrade.js sets ``MathJax.loaded`` when MathJax 2's startup signals "End").
FORMGRADER_READY = "() => window.MathJax !== undefined && window.MathJax.loaded === true"


def visit_formgrader(
    course: Path, tmp_path: Path, assignment: str, *, in_browser: bool
) -> tuple[list[str], list[str], tuple[dict[str, Any], list[str], list[str]] | None]:
    """Start JupyterLab in the course folder as the README says (the environment's ``jupyter``,
    here headless on the loopback interface with a token and its own runtime and configuration
    folders) and ask nbgrader's formgrader for the assignments and the notebooks of
    ``assignment``, by name; if ``in_browser``, also open the formgrader's view of the first
    submission of ``assignment``'s first notebook as a teacher does, in Chromium with every
    request to another host refused (:func:`open_offline`, once the formgrader's script has
    heard from MathJax)."""
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = int(probe.getsockname()[1])
    token = secrets.token_hex(16)
    command = [
        str(Path(sys.executable).parent / "jupyter"),
        "lab",
        "--no-browser",
        "--ServerApp.ip=127.0.0.1",
        f"--ServerApp.port={port}",
        "--ServerApp.port_retries=0",
        f"--IdentityProvider.token={token}",
    ]
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        command.append("--allow-root")
    folders = {name: tmp_path / f"lab-{name}" for name in ("runtime", "config")}
    for folder in folders.values():
        folder.mkdir()
    environment = dict(
        os.environ,
        JUPYTER_RUNTIME_DIR=str(folders["runtime"]),
        JUPYTER_CONFIG_DIR=str(folders["config"]),
    )
    log_path = tmp_path / "lab.log"
    with log_path.open("w") as log:
        server = subprocess.Popen(
            command, cwd=course, env=environment, stdout=log, stderr=subprocess.STDOUT
        )
        try:

            def ask(route: str) -> Any:
                request = urllib.request.Request(
                    f"http://127.0.0.1:{port}/formgrader/api/{route}",
                    headers={"Authorization": f"token {token}"},
                )
                with urllib.request.urlopen(request, timeout=60) as reply:
                    return json.load(reply)

            deadline = time.monotonic() + 120
            while True:
                try:
                    assignments = ask("assignments")
                    break
                except (urllib.error.URLError, ConnectionError):
                    if server.poll() is not None or time.monotonic() > deadline:
                        log.flush()
                        pytest.fail("JupyterLab did not start:\n" + log_path.read_text())
                    time.sleep(0.5)
            notebooks = ask(f"notebooks/{assignment}")
            view = None
            if in_browser:
                notebook = notebooks[0]["name"]
                (submitted, *_) = ask(f"submitted_notebooks/{assignment}/{notebook}")
                view = open_offline(
                    f"http://127.0.0.1:{port}/formgrader/submissions/{submitted['id']}/",
                    headers={"Authorization": f"token {token}"},
                    ready=FORMGRADER_READY,
                )
        finally:
            server.terminate()
            try:
                server.wait(timeout=30)
            except subprocess.TimeoutExpired:
                server.kill()
    return [a["name"] for a in assignments], [n["name"] for n in notebooks], view


@needs_nbgrader_run
def test_the_readme_cycle_release_collect_autograde_feedback(
    small_course: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """The README's cycle through nbgrader's exchange, as a teacher and a student run it: the
    teacher releases, the student fetches, answers one exercise and submits, the teacher collects,
    autogrades, writes and releases the feedback, the student fetches it. The feedback page
    shows the right answer as correct, the blank ones as not handed in, and typesets its math in
    Chromium with the network refused. The formgrader lists the notebook alone, not the
    glossary, and its view of the submission typesets its math with the network refused too."""
    course, exchange, student = tmp_path / "grading", tmp_path / "exchange", tmp_path / "alice"
    status, _, err = run_cli(
        capsys, "notebooks", "nbgrader", "--src", str(small_course), "--out", str(course)
    )
    assert status == 0, err
    exchange.mkdir()
    exchange.chmod(0o777)  # a folder every user can write, as nbgrader's exchange must be
    setting = f"c.Exchange.root = {str(exchange)!r}\n"  # as the README says to set it
    with (course / CONFIG_NAME).open("a", encoding="utf-8") as config:
        config.write(setting)
    student.mkdir()
    (student / CONFIG_NAME).write_text(
        f"c = get_config()\n{setting}c.Exchange.cache = {str(tmp_path / 'cache')!r}\n",
        encoding="utf-8",
    )

    nbgrader(course, "generate_assignment", SMALL)
    nbgrader(course, "release_assignment", SMALL)
    nbgrader(student, "fetch_assignment", SMALL, "--course", "eulerlib")
    fetched = student / SMALL / f"{SMALL}.ipynb"
    solution = dict(exercises_of(small_notebook()))["05.1"]
    nbformat.write(fill_in(read(fetched), {"05.1": solution, "05.2": None, "05.3": None}), fetched)
    nbgrader(student, "submit", SMALL, "--course", "eulerlib")  # as the user who runs the test
    nbgrader(course, "collect", SMALL)
    from nbgrader.utils import get_username

    alice = get_username()  # the exchange knows a student by their login
    assert (course / "submitted" / alice / SMALL / f"{SMALL}.ipynb").is_file()
    nbgrader(course, "autograde", SMALL)
    nbgrader(course, "generate_feedback", SMALL)
    nbgrader(course, "release_feedback", SMALL)
    nbgrader(student, "fetch_feedback", SMALL, "--course", "eulerlib")
    nbgrader(course, "export", "--to", "grades.csv")

    with (course / "grades.csv").open(newline="") as stream:
        (grade,) = list(csv.DictReader(stream))
    assert (grade["student_id"], float(grade["score"])) == (alice, POINTS[KEY["05.1"].level])

    from nbgrader.api import Gradebook

    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gradebook:
        listed = [notebook.name for notebook in gradebook.find_assignment(SMALL).notebooks]
    assert listed == [SMALL]  # what the formgrader lists: no glossary
    reason = browser_missing()
    if reason is not None and os.environ.get("EULERLIB_SITE_TEST") == "required":
        pytest.fail(reason)
    assignments, notebooks, view = visit_formgrader(
        course, tmp_path, SMALL, in_browser=reason is None
    )
    assert (assignments, notebooks) == ([SMALL], [SMALL])

    (page,) = (student / SMALL / "feedback").glob(f"*/{SMALL}.html")
    text = page.read_text(encoding="utf-8")
    assert "Exercise 05.1 — correct: " in text
    assert "Exercise 05.2 — no answer: answer_2 was handed in as ..." in text
    assert "replace the ..." not in text
    assert "cdnjs" not in text and "mathjax/2.7" not in text.lower()

    if reason is not None:
        pytest.skip(f"the feedback page and the formgrader are not opened in a browser: {reason}")
    facts, refused, errors = open_offline(page)
    assert refused == [] and errors == []
    assert facts["typeset"] >= 1 and facts["texErrors"] == []
    assert "r_{31}" not in facts["text"] and "$" not in facts["text"]

    assert view is not None  # the formgrader's view of the submission, offline as well
    facts, refused, errors = view
    assert refused == [] and errors == []
    assert facts["typeset"] >= 1 and facts["texErrors"] == []
    assert "r_{31}" not in facts["text"] and "$" not in facts["text"]
