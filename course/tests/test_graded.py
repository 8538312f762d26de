"""Graded mode: a release that cannot be read off, and hidden tests that grade each student's data.

The threat: a student with the released notebook, the course package installed in their
environment and a Python kernel, who looks for a graded reference instead of working the
exercise — in the files they can open, in the modules they can import, through the answer key's
functions applied to their own data. The tests build a graded release as nbgrader does (its
own preprocessors strip the solutions and the hidden tests), set up the students' side (the
release, the library, the course package with its answer key removed) and search it: the
references of a student's exercises must not be in any file, in any object reachable from an
importable module, or come out of the key's routes. The same search run on the full package (the
practice mode's, with the key) finds them, which shows the search would see a key that is there.

The hidden tests, run as nbgrader's autograde runs them (in ``autograded/STUDENT/ASSIGNMENT``),
grade a right answer of that student's data as right and the right answer of another student's
data as wrong.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import nbformat
import numpy as np
import pytest

from eulerlib_course.exercises import exercises
from eulerlib_course.exercises.graded import check_form, form_of
from eulerlib_course.exercises.keyless import key_modules, remove_answer_key
from eulerlib_course.exercises.seeds import as_student
from eulerlib_course.nbgrader_edition import write_nbgrader_edition

REPO = Path(__file__).resolve().parents[2]
PACKAGE = REPO / "course" / "eulerlib_course"
KEY = exercises()
GRADED = ("05_matrix_to_angles", "07_gimbal_lock_seen", "08_conventions_compared")
STUDENTS = ("ada", "grace")


def reference(exercise_id: str, student: str | None) -> np.ndarray:
    judge = KEY[exercise_id].judge_for(student)
    return np.asarray(judge.reference, dtype=float)  # type: ignore[attr-defined]


def seeded() -> list[str]:
    return [i for i in KEY if KEY[i].per_student is not None and i[:2] in {g[:2] for g in GRADED}]


@pytest.fixture(scope="module")
def release(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A graded edition of three notebooks, released by nbgrader's own preprocessors."""
    pytest.importorskip("nbgrader")
    from nbgrader.preprocessors import ClearHiddenTests, ClearOutput, ClearSolutions

    root = tmp_path_factory.mktemp("graded")
    source = root / "notebooks"
    source.mkdir()
    for name in GRADED:
        shutil.copyfile(REPO / "notebooks" / f"{name}.ipynb", source / f"{name}.ipynb")
    shutil.copyfile(REPO / "notebooks" / "glossary.ipynb", source / "glossary.ipynb")
    write_nbgrader_edition(source, root / "course", graded=True)
    released = root / "release"
    for name in GRADED:
        notebook = nbformat.read(str(root / "course" / "source" / name / f"{name}.ipynb"), 4)
        resources: dict[str, Any] = {"language": "python"}
        for step in (ClearSolutions(), ClearHiddenTests(), ClearOutput()):
            notebook, resources = step.preprocess(notebook, resources)
        (released / name).mkdir(parents=True)
        nbformat.write(notebook, str(released / name / f"{name}.ipynb"))
    return root


@pytest.fixture(scope="module")
def keyless(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The students' environment: a copy of the course package with its answer key removed."""
    site = tmp_path_factory.mktemp("students-site")
    shutil.copytree(PACKAGE, site / "eulerlib_course")
    removed = remove_answer_key(site / "eulerlib_course")
    assert removed and not key_modules(site / "eulerlib_course")
    return site


SEARCH = r"""
import importlib, json, pkgutil, sys
import numpy as np

by_student = json.loads(sys.argv[1])
wanted = {
    f"{student} {k}": np.array(v) for student, refs in by_student.items() for k, v in refs.items()
}
found = []

seen, kept = set(), []

def look(value, where, depth=0):
    if depth > 4 or id(value) in seen:
        return
    seen.add(id(value))
    kept.append(value)  # an id stays unique while its object lives
    try:
        array = np.asarray(value, dtype=float)
        for name, ref in wanted.items():
            if array.shape == ref.shape and np.allclose(array, ref, atol=1e-6):
                found.append(f"{name} in {where}")
    except Exception:
        pass
    if isinstance(value, dict):
        items = list(value.items())[:200]
    elif isinstance(value, (list, tuple, set)):
        items = list(enumerate(value))[:200]
    elif hasattr(value, "__dataclass_fields__"):
        items = [(f, getattr(value, f, None)) for f in value.__dataclass_fields__]
    else:
        return
    for key, item in items:
        look(item, f"{where}[{key!r}]", depth + 1)

import eulerlib_course
for info in pkgutil.walk_packages(eulerlib_course.__path__, "eulerlib_course."):
    try:
        module = importlib.import_module(info.name)
    except Exception:
        continue
    for name, value in vars(module).items():
        if not name.startswith("__") and not callable(value):
            look(value, f"{info.name}.{name}")

# the answer key's own routes, for each student
from eulerlib_course.exercises import exercises
for student in by_student:
    for exercise_id, key in exercises().items():
        try:
            look(key.judge_for(student).reference, f"judge_for({student!r}) of {exercise_id}")
        except Exception:
            pass
print(json.dumps(found))
"""


def search(site: Path, wanted: dict[str, dict[str, np.ndarray]]) -> list[str]:
    """What a kernel on ``site`` can reach of the references ``wanted`` (student → exercise →
    reference): ``"STUDENT EXERCISE in WHERE"`` for each found."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(site), str(REPO)]))
    env["MPLBACKEND"] = "Agg"
    payload = json.dumps(
        {student: {k: v.tolist() for k, v in refs.items()} for student, refs in wanted.items()}
    )
    result = subprocess.run(
        [sys.executable, "-c", SEARCH, payload],
        env=env,
        capture_output=True,
        text=True,
        timeout=300,
        cwd=site,
    )
    assert result.returncode == 0, result.stderr[-2000:]
    return list(json.loads(result.stdout.strip().splitlines()[-1]))


def written_forms(values: np.ndarray) -> list[str]:
    """How a reference could be written in a file: as Python and NumPy print it, rounded."""
    forms = {repr(values.tolist()), np.array2string(values, separator=", ")}
    for digits in (4, 6, 10):
        forms.add(", ".join(f"{v:.{digits}g}" for v in values.ravel()))
        forms.add(", ".join(str(round(float(v), digits)) for v in values.ravel()))
    return sorted(forms)


def test_the_students_side_of_a_graded_release_holds_no_reference(
    release: Path, keyless: Path
) -> None:
    exercise_ids = seeded()
    assert exercise_ids
    wanted = {s: {i: reference(i, s) for i in exercise_ids} for s in STUDENTS}
    texts = [
        path.read_text(encoding="utf-8", errors="ignore")
        for folder in (release / "release", keyless)
        for path in folder.rglob("*")
        if path.is_file()
    ]
    for student, references in wanted.items():
        for exercise_id, values in references.items():
            for form in written_forms(values):
                assert not any(form in text for text in texts), f"{student}, {exercise_id}: {form}"
    assert search(keyless, wanted) == []


@pytest.mark.skipif(
    os.environ.get("EULERLIB_NBGRADER") != "1",
    reason="half a minute: runs in CI's nbgrader step "
    "(EULERLIB_NBGRADER=1 python -m pytest course/tests/test_graded.py)",
)
def test_the_search_finds_the_reference_where_the_key_is_installed(tmp_path: Path) -> None:
    """The search of the test above can fail: on the full package it finds every reference.
    (It imports every module of the course, so it takes long: it runs in CI's nbgrader step.)"""
    full = tmp_path / "site"
    shutil.copytree(PACKAGE, full / "eulerlib_course")
    wanted = {s: {i: reference(i, s) for i in seeded()} for s in STUDENTS}
    found = {entry.split(" in ")[0] for entry in search(full, wanted)}
    assert found == {f"{s} {i}" for s in STUDENTS for i in seeded()}


def test_the_release_calls_only_the_form_check_and_keeps_the_name_cell(release: Path) -> None:
    for name in GRADED:
        notebook = nbformat.read(str(release / "release" / name / f"{name}.ipynb"), 4)
        code = "\n".join(c.source for c in notebook.cells if c.cell_type == "code")
        assert "check(" not in re.sub(r"check_form\(", "", code)
        assert "_KEY_SOURCE" not in code and "EXERCISES" not in code
        assert "student_name(...)" in code
        source = nbformat.read(str(release / "course" / "source" / name / f"{name}.ipynb"), 4)
        hidden = "\n".join(c.source for c in source.cells if "HIDDEN TESTS" in c.source)
        assert "_KEY_SOURCE" in hidden  # the teacher's source carries the key


@pytest.mark.parametrize("student", STUDENTS)
def test_hidden_tests_grade_each_students_own_data(
    release: Path, student: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The hidden test of 05.1, run where nbgrader's autograde runs it, for two students."""
    from eulerlib import matrix_to_euler

    source = nbformat.read(str(release / "course" / "source" / GRADED[0] / f"{GRADED[0]}.ipynb"), 4)
    (test,) = [c for c in source.cells if c.metadata["nbgrader"]["grade_id"] == "test-05-1"]
    hidden = test.source.split("### BEGIN HIDDEN TESTS\n")[1]
    folder = tmp_path / "autograded" / student / GRADED[0]
    folder.mkdir(parents=True)
    monkeypatch.chdir(folder)
    other = STUDENTS[1 - STUDENTS.index(student)]
    with as_student(other):  # the name typed in the notebook does not change the graded data
        R = KEY["05.1"].data_for(student)
        own = matrix_to_euler(R, "rose", degrees=True)
        theirs = matrix_to_euler(KEY["05.1"].data_for(other), "rose", degrees=True)
        exec(compile(hidden, "hidden test", "exec"), {"answer_1": own})
        with pytest.raises(AssertionError, match=r"05\.1 — off"):
            exec(compile(hidden, "hidden test", "exec"), {"answer_1": theirs})


def test_the_form_check_says_nothing_about_right_or_wrong() -> None:
    form = form_of(KEY["05.1"].judge)
    with as_student("ada"):
        right = reference("05.1", "ada")
        wrong = right + 7.0
        said = {check_form("05.1", answer, **form).message for answer in (right, wrong)}
    assert len(said) == 1 and "has the form" in said.pop()
    assert check_form("05.1", [1, 2], **form).status == "off"
    assert check_form("05.1", ..., **form).status == "not yet"
    choice = form_of(KEY["07.2"].judge)
    assert check_form("07.2", ("c", 12.0), **choice).status == "received"
    assert "pair" in check_form("07.2", "c", **choice).message
    assert check_form("07.2", ("e", 1.0), **choice).status == "off"


def test_a_prediction_is_recorded_and_settled_without_the_key(keyless: Path) -> None:
    choice = form_of(KEY["07.2"].judge)
    program = (
        "from eulerlib_course.exercises import settle\n"
        "from eulerlib_course.exercises.graded import check_form\n"
        "print(settle('07.2', lambda: 'computed'))\n"
        f"print(check_form('07.2', ('a', ...), prediction=True, **{choice!r}).status)\n"
        f"print(check_form('07.2', ('a', 12.0), prediction=True, **{choice!r}).status)\n"
        "print(settle('07.2', lambda: 'computed'))\n"
    )
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(keyless), str(REPO)]))
    out = subprocess.run(
        [sys.executable, "-c", program], env=env, capture_output=True, text=True, cwd=keyless
    )
    assert out.returncode == 0, out.stderr
    refused, blank, received, computed = out.stdout.splitlines()
    assert refused.startswith("predict first") and "07.2" in refused
    assert (blank, received, computed) == ("not yet", "received", "computed")


def test_graded_mode_counts_the_prediction_made_before_the_computation() -> None:
    from eulerlib_course.exercises.graded import grade
    from eulerlib_course.exercises.predictions import forget, settle

    forget()
    try:
        choice = form_of(KEY["07.2"].judge)
        assert check_form("07.2", ("a", 12.0), prediction=True, **choice).status == "received"
        assert settle("07.2", lambda: "computed") == "computed"
        late = grade(KEY.values(), "07.2", ("c", 160.0))
        assert late.status == "off"
        forget()
        assert grade(KEY.values(), "07.2", ("c", 160.0)).status == "correct"
    finally:
        forget()


def test_check_without_the_key_says_answers_are_graded_when_handed_in(keyless: Path) -> None:
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(keyless), str(REPO)]))
    program = (
        "from eulerlib_course.exercises import check\n"
        "try:\n    check('05.1', [1, 2, 3])\nexcept ValueError as e:\n    print(e)\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", program], env=env, capture_output=True, text=True, cwd=keyless
    )
    assert "graded when you hand them in" in out.stdout, out.stderr


def test_the_key_is_never_removed_from_a_git_working_tree() -> None:
    with pytest.raises(ValueError, match="git working tree"):
        remove_answer_key(PACKAGE)
    assert key_modules(PACKAGE)
