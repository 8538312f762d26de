"""Exercises that teach: the answer key, the check cells, the student copies run with wrong answers.

For every notebook of the course, the exercises of its student copy are executed cell by cell —
the notebook's first code cell (its imports), then each exercise cell with the ``...`` replaced by
every answer of the exercise's test table, then its check cell — and the feedback must say what
the table says: ``correct`` for the answers that are right in another form, ``off`` with the
expected diagnosis for the typical mistakes, ``not yet`` for the untouched ``...``. The cells run
in this process (their sources are executed as they stand in the student copy), which takes a
fraction of a second; the teacher's edition is executed once, by strict nbval.

The tests also check the structure the course promises: the check cell names the exercise and
the answer only, nothing a student sees gives the answer away, the exercises climb from applying
to predicting to extending, no question is a yes/no a guess can pass.
"""

from __future__ import annotations

import ast
import contextlib
import io
import re
from pathlib import Path
from typing import Any

import nbformat
import pytest

from eulerlib_course.exercises import ChoiceJudge, Exercise, exercises, given
from eulerlib_course.exercises import check as check_answer
from eulerlib_course.exercises.seeds import as_student
from eulerlib_course.student import student_copy

REPO = Path(__file__).resolve().parents[2]
NOTEBOOKS = sorted((REPO / "notebooks").glob("[0-9][0-9]_*.ipynb"))
IDS = [path.name for path in NOTEBOOKS]
KEY = exercises()

CHECK_CELL = re.compile(r'check\("(\d\d\.\d)", (answer_\d)\)')
PLACEHOLDER = re.compile(r"^(answer_\d) = \.\.\.\s*$", re.MULTILINE)
SETTLE_CELL = re.compile(r'^settle\(\s*"(\d\d\.\d)"', re.MULTILINE)
LEVELS = ("apply", "predict", "extend")

notebook_params = pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)


def tags(cell: Any) -> list[str]:
    return list(cell.get("metadata", {}).get("tags", []))


def read(path: Path) -> Any:
    return nbformat.read(str(path), as_version=4)


def number_of(path: Path) -> str:
    return path.name[:2]


def exercise_cells(notebook: Any) -> list[tuple[Any, Any | None, Any]]:
    """``(exercise, solution or None, check)`` cells of each exercise, in order."""
    found: list[list[Any]] = []
    for cell in notebook.cells:
        kind = [t for t in tags(cell) if t in ("exercise", "solution", "check")]
        if not kind:
            continue
        if kind[0] == "exercise":
            found.append([cell, None, None])
        elif kind[0] == "solution":
            found[-1][1] = cell
        else:
            found[-1][2] = cell
    return [(e, s, c) for e, s, c in found]


def key_of(path: Path) -> list[Exercise]:
    return [ex for ex in KEY.values() if ex.id.startswith(number_of(path) + ".")]


def without_magics(source: str) -> str:
    return "\n".join(
        line for line in source.splitlines() if not line.lstrip().startswith(("%", "!"))
    )


def run(source: str, namespace: dict[str, Any]) -> tuple[Any, str]:
    """Execute a cell's source; return the value of its last expression and what it printed."""
    tree = ast.parse(source)
    last = tree.body.pop() if tree.body and isinstance(tree.body[-1], ast.Expr) else None
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        exec(compile(tree, "<cell>", "exec"), namespace)
        value = (
            eval(compile(ast.Expression(last.value), "<cell>", "eval"), namespace)
            if last is not None
            else None
        )
    return value, printed.getvalue()


# --- structure -----------------------------------------------------------------------------------


@notebook_params
def test_three_or_four_exercises_that_climb(path: Path) -> None:
    cells = exercise_cells(read(path))
    keys = key_of(path)
    assert 3 <= len(cells) <= 4, f"{path.name}: {len(cells)} exercises, expected 3 or 4"
    assert [k.id for k in keys] == [f"{number_of(path)}.{n}" for n in range(1, len(cells) + 1)]
    levels = [k.level for k in keys]
    assert set(levels) == set(LEVELS), f"{path.name}: levels {levels}"
    assert levels == sorted(levels, key=LEVELS.index), f"{path.name}: levels {levels} do not climb"


@notebook_params
def test_cells_of_each_exercise(path: Path) -> None:
    for number, (exercise, solution, check) in enumerate(exercise_cells(read(path)), start=1):
        where = f"{path.name}, exercise {number}"
        assert solution is not None and check is not None, f"{where}: solution and check needed"
        match = CHECK_CELL.fullmatch(check.source.strip())
        assert match, f'{where}: the check cell must be exactly check("NN.k", answer_k)'
        assert match.group(1) == f"{number_of(path)}.{number}", where
        assert match.group(2) == f"answer_{number}", where
        assert PLACEHOLDER.search(exercise.source), f"{where}: no `answer_{number} = ...` line"
        assert f"answer_{number} =" in solution.source, f"{where}: the solution sets no answer"
        assert "hide-input" in tags(solution), f"{where}: the solution is not folded on the site"
        hidden = solution.get("metadata", {}).get("jupyter", {}).get("source_hidden")
        assert hidden is True, f"{where}: the solution is not folded in JupyterLab"


@notebook_params
def test_one_exercise_is_more_than_a_one_line_call(path: Path) -> None:
    sizes = [len(ast.parse(solution.source).body) for _, solution, _ in exercise_cells(read(path))]
    assert max(sizes) >= 2, f"{path.name}: every worked solution is a single statement"


def test_every_exercise_of_the_key_is_in_a_notebook() -> None:
    in_notebooks = {
        CHECK_CELL.fullmatch(check.source.strip()).group(1)  # type: ignore[union-attr]
        for path in NOTEBOOKS
        for _, _, check in exercise_cells(read(path))
    }
    assert set(KEY) == in_notebooks


def settle_cells(notebook: Any) -> dict[str, tuple[int, Any]]:
    """The cells that settle a prediction, by exercise, with their positions."""
    found: dict[str, tuple[int, Any]] = {}
    for position, cell in enumerate(notebook.cells):
        match = SETTLE_CELL.search(cell.source) if cell.cell_type == "code" else None
        if match:
            assert match.group(1) not in found, f"{match.group(1)} is settled twice"
            found[match.group(1)] = (position, cell)
    return found


@notebook_params
def test_every_prediction_is_settled_right_after_its_check(path: Path) -> None:
    notebook = read(path)
    settled = settle_cells(notebook)
    predictions = {k.id for k in key_of(path) if k.level == "predict"}
    assert set(settled) == predictions, f"{path.name}: settle cells {sorted(settled)}"
    for exercise_id, (position, cell) in settled.items():
        before = notebook.cells[position - 1]
        assert before.source.strip() == f'check("{exercise_id}", answer_{exercise_id[-1]})', (
            f"{path.name}: the cell that settles {exercise_id} does not follow its check"
        )
        assert not {"exercise", "solution", "check"} & set(tags(cell)), path.name
        text = "".join(o.get("data", {}).get("text/plain", "") for o in cell.get("outputs", []))
        assert text and "predict first" not in text, f"{path.name}: {exercise_id} shows {text!r}"


@notebook_params
def test_without_a_prediction_the_settle_cell_says_so_and_shows_nothing(path: Path) -> None:
    import matplotlib.pyplot as plt

    from eulerlib_course.exercises.predictions import forget

    copy = student_copy(read(path))
    settled = settle_cells(copy)
    first = next(cell for cell in copy.cells if cell.cell_type == "code")
    namespace: dict[str, Any] = {}
    run(without_magics(first.source), namespace)
    forget()
    try:
        for exercise, _, check in exercise_cells(copy):
            exercise_id = CHECK_CELL.fullmatch(check.source.strip()).group(1)  # type: ignore[union-attr]
            if exercise_id not in settled:
                continue
            if PLACEHOLDER.fullmatch(exercise.source.strip()):  # nothing but answer_k = ...
                run(exercise.source, namespace)
                feedback, _ = run(check.source, namespace)
                assert feedback.status == "not yet", f"{exercise_id}: {feedback}"
            plt.close("all")
            value, printed = run(settled[exercise_id][1].source, namespace)
            assert isinstance(value, str) and "\n" not in value, f"{exercise_id}: {value!r}"
            assert value.startswith("predict first") and exercise_id in value, value
            assert printed == "" and not plt.get_fignums(), f"{exercise_id} showed something"
    finally:
        forget()


def test_test_tables_have_equivalent_answers_and_typical_mistakes() -> None:
    for exercise in KEY.values():
        right = [e for e in exercise.examples if e.status == "correct"]
        wrong = [e for e in exercise.examples if e.status == "off"]
        assert right, f"{exercise.id}: no answer that is right in another form"
        assert len(wrong) >= 2, f"{exercise.id}: fewer than two typical wrong answers"
        assert all(e.says for e in wrong), f"{exercise.id}: a wrong answer without a diagnosis"


def test_no_yes_no_question() -> None:
    for exercise in KEY.values():
        if isinstance(exercise.judge, ChoiceJudge):
            assert len(exercise.judge.options) >= 3, exercise.id


@notebook_params
def test_stored_teachers_edition_says_correct(path: Path) -> None:
    for _, _, check in exercise_cells(read(path)):
        text = "".join(
            output.get("data", {}).get("text/plain", "") for output in check.get("outputs", [])
        )
        assert re.match(r"Exercise \d\d\.\d — correct", text), f"{path.name}: {text[:100]!r}"


# --- the student copy ---------------------------------------------------------------------------


@notebook_params
def test_student_copy_gives_nothing_away(path: Path) -> None:
    copy = student_copy(read(path))
    visible = "\n".join(cell.source for cell in copy.cells)
    for exercise in key_of(path):
        for text in exercise.forbidden:
            assert text not in visible, f"{path.name}: {exercise.id} is given away by {text!r}"


@notebook_params
def test_student_copy_diagnoses_every_answer_of_the_test_tables(path: Path) -> None:
    copy = student_copy(read(path))
    first = next(cell for cell in copy.cells if cell.cell_type == "code")
    namespace: dict[str, Any] = {}
    run(without_magics(first.source), namespace)  # its print options: see the top conftest.py
    check_every_example(path, copy, namespace)


def check_every_example(path: Path, copy: Any, namespace: dict[str, Any]) -> None:
    keys = {k.id: k for k in key_of(path)}
    for exercise, solution, check in exercise_cells(copy):
        assert solution is None, f"{path.name}: the student copy kept a solution"
        exercise_id = CHECK_CELL.fullmatch(check.source.strip()).group(1)  # type: ignore[union-attr]
        _, printed = run(exercise.source, namespace)
        for text in keys[exercise_id].forbidden:
            assert text not in printed, f"{exercise_id}: the exercise cell prints {text!r}"
        feedback, _ = run(check.source, namespace)
        assert feedback.status == "not yet", f"{exercise_id}: {feedback}"
        for example in keys[exercise_id].examples:
            source = PLACEHOLDER.sub(
                lambda m, c=example.code: f"{m.group(1)} = {c}", exercise.source
            )
            run(source, namespace)
            feedback, _ = run(check.source, namespace)
            assert feedback.status == example.status, f"{example.code!r}: {feedback}"
            assert example.says in feedback.message, f"{example.code!r}: {feedback}"


# --- every student copy, run for two students ------------------------------------------------

STUDENTS = ("ada", "grace")


def run_copies_with_solutions(path: Path, students: tuple[str, ...]) -> dict[str, dict[str, Any]]:
    """Run each student's copy of a notebook, each worked solution of the teacher's edition put
    back after its exercise cell; return each student's feedback of each exercise.

    The first student's copy runs whole; for the next ones only the cells that depend on whose
    copy it is run again, in the same kernel's namespace: the name cell and each exercise's
    cell, solution and check, and the cells that settle a prediction (the rest of a notebook
    gives every student the same). What a settle cell shows is kept as ``"settled NN.k"``.
    """
    import matplotlib.pyplot as plt

    from eulerlib_course.exercises.predictions import forget

    teacher = read(path)
    solutions = {
        CHECK_CELL.fullmatch(check.source.strip()).group(1): solution  # type: ignore[union-attr]
        for _, solution, check in exercise_cells(teacher)
    }
    namespace: dict[str, Any] = {}
    results: dict[str, dict[str, Any]] = {}
    with as_student(None):
        for number, student in enumerate(students):
            copy = student_copy(teacher, student)
            forget()
            results[student] = {}
            for cell in copy.cells:
                if cell.cell_type != "code":
                    continue
                is_name = "student_name(" in cell.source
                settles = SETTLE_CELL.search(cell.source)
                if number and not (is_name or settles or {"exercise", "check"} & set(tags(cell))):
                    continue
                value, _ = run(without_magics(cell.source), namespace)
                match = CHECK_CELL.fullmatch(cell.source.strip())
                if "exercise" in tags(cell):
                    placeholder = PLACEHOLDER.search(cell.source)
                    assert placeholder, cell.source
                    run(
                        solutions[f"{number_of(path)}.{placeholder.group(1)[-1]}"].source, namespace
                    )
                if match:
                    results[student][match.group(1)] = value
                if settles:
                    results[student][f"settled {settles.group(1)}"] = value
                plt.close("all")
            forget()
    return results


@pytest.mark.slow
@notebook_params
def test_every_student_copy_runs_for_two_students_and_the_solutions_pass(
    path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(path.parent)  # where the notebooks read their data from
    for student, results in run_copies_with_solutions(path, STUDENTS).items():
        feedback = {k: v for k, v in results.items() if not k.startswith("settled ")}
        assert set(feedback) == {k.id for k in key_of(path)}, student
        for exercise_id, verdict in feedback.items():
            assert verdict.status == "correct", f"{student}, {exercise_id}: {verdict}"
        predictions = {k.id for k in key_of(path) if k.level == "predict"}
        assert {k[len("settled ") :] for k in results if k.startswith("settled ")} == predictions
        for exercise_id in predictions:
            shown = results[f"settled {exercise_id}"]
            assert not (isinstance(shown, str) and shown.startswith("predict first")), (
                f"{student}, {exercise_id}: the settle cell refused after the prediction"
            )


@notebook_params
def test_rows_written_with_the_given_data_hold_for_each_students_data(path: Path) -> None:
    """The rows of a per-student exercise's table that compute from the question's data (not
    typed-in numbers) get the same verdict with each student's own data (a wrong one may get
    another diagnosis: atan, for one, goes wrong in another angle for other data)."""
    from eulerlib_course.exercises.predictions import forget

    seeded = {k.id: k for k in key_of(path) if k.per_student is not None}
    if not seeded:
        pytest.skip("no per-student data in this notebook")
    teacher = read(path)
    for student in STUDENTS:
        copy = student_copy(teacher, student)
        namespace: dict[str, Any] = {}
        with as_student(None):
            first = next(cell for cell in copy.cells if cell.cell_type == "code")
            run(without_magics(first.source), namespace)
            name_cell = next(cell for cell in copy.cells if "student_name(" in cell.source)
            run(name_cell.source, namespace)
            forget()
            names: set[str] = set()  # the data the questions give, so far in the notebook
            for exercise, _, check in exercise_cells(copy):
                exercise_id = CHECK_CELL.fullmatch(check.source.strip()).group(1)  # type: ignore[union-attr]
                for group in re.findall(r"^(\w+(?:, \w+)*) = given\(", exercise.source, re.M):
                    names |= set(group.split(", "))
                if exercise_id not in seeded:
                    continue
                rows = [
                    e
                    for e in seeded[exercise_id].examples
                    if names & set(re.findall(r"\w+", e.code))
                ]
                assert rows, f"{exercise_id}: no row computes from the question's data"
                for example in rows:
                    source = PLACEHOLDER.sub(
                        lambda m, c=example.code: f"{m.group(1)} = {c}", exercise.source
                    )
                    run(source, namespace)
                    feedback, _ = run(check.source, namespace)
                    where = f"{student}, {exercise_id}, {example.code!r}: {feedback}"
                    assert feedback.status == example.status, where
            forget()


def test_per_student_data_differ_between_students_and_from_the_teachers() -> None:
    import numpy as np

    def numbers(data: Any) -> Any:  # the data's numbers in one flat array (a tuple may mix shapes)
        parts = data if isinstance(data, tuple) else (data,)
        return np.concatenate([np.ravel(np.asarray(part, dtype=float)) for part in parts])

    seeded = [e for e in KEY.values() if e.per_student is not None and not e.seed_of]
    assert len(seeded) >= 6
    for exercise in seeded:
        teacher, ada, grace = (numbers(exercise.data_for(name)) for name in (None, *STUDENTS))
        assert not np.allclose(ada, grace), exercise.id
        assert not np.allclose(ada, teacher), exercise.id
        again = numbers(exercise.data_for("ada"))
        assert np.array_equal(ada, again), f"{exercise.id}: the same student, other data"
        with as_student("ada"):
            judge = exercise.judge_for()
        assert not np.array_equal(
            np.asarray(judge.reference, dtype=float),  # type: ignore[attr-defined]
            np.asarray(exercise.judge.reference, dtype=float),  # type: ignore[attr-defined]
        ), exercise.id


def test_the_judge_checks_against_the_students_own_data() -> None:
    from eulerlib import matrix_to_euler

    for student in STUDENTS:
        with as_student(student):
            R = given("05.1")
            own = matrix_to_euler(R, "rose", degrees=True)  # the library reads the angles
            assert check_answer("05.1", own).status == "correct"
    with as_student("ada"):
        ada = matrix_to_euler(given("05.1"), "rose", degrees=True)
    with as_student("grace"):
        assert check_answer("05.1", ada).status == "off"
