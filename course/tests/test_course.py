"""The course as a whole: notebook hygiene, exercises with self-checks, and the course tooling.

Every test that concerns the course notebooks runs over ``notebooks/*.ipynb``, so a notebook
added to the course is covered without touching this file. These tests read the stored
notebooks and never execute them: nbval executes each notebook once per session, and the checks
around the session (``tests/conftest.py``) see that no notebook writes into the repository or
takes too long. The tooling (refresh, student copies) is exercised on small notebooks built
here.
"""

from __future__ import annotations

import copy
import re
import sys
from pathlib import Path

import nbformat
import pytest

from eulerlib_course import cli
from eulerlib_course.notebook_form import KERNELSPEC, is_normalized, normalize_notebook
from eulerlib_course.student import name_cell_source, student_copy, write_student_copies

REPO = Path(__file__).resolve().parents[2]
NOTEBOOK_DIR = REPO / "notebooks"
NOTEBOOKS = sorted(NOTEBOOK_DIR.glob("[0-9][0-9]_*.ipynb"))
GLOSSARY = NOTEBOOK_DIR / "glossary.ipynb"
IDS = [path.name for path in NOTEBOOKS]

#: The folding state of JupyterLab that the normal form keeps, besides the tags.
FOLDING = {"source_hidden", "outputs_hidden"}

notebook_params = pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)


# --- helpers -----------------------------------------------------------------------------------


def read(path: Path) -> nbformat.NotebookNode:
    return nbformat.read(str(path), as_version=4)


def tags_of(cell: nbformat.NotebookNode) -> list[str]:
    return list(cell.get("metadata", {}).get("tags", []))


def output_text(cell: nbformat.NotebookNode) -> str:
    """The text a code cell shows: streams and the plain-text form of results, in order."""
    parts = []
    for output in cell.get("outputs", []):
        if output.get("output_type") == "stream":
            parts.append(output.get("text", ""))
        elif "data" in output:
            parts.append(output["data"].get("text/plain", ""))
        elif output.get("output_type") == "error":
            parts.append(f"{output.get('ename')}: {output.get('evalue')}")
    return "".join(parts)


# --- stored form -------------------------------------------------------------------------------


def test_there_are_notebooks() -> None:
    assert NOTEBOOKS, f"no notebooks in {NOTEBOOK_DIR}"


def test_file_names_are_numbered_consecutively_from_01() -> None:
    pattern = re.compile(r"(\d\d)_[a-z0-9]+(?:_[a-z0-9]+)*\.ipynb")
    numbers = []
    for path in NOTEBOOKS:
        match = pattern.fullmatch(path.name)
        assert match, f"{path.name} is not named NN_snake_case.ipynb"
        numbers.append(int(match.group(1)))
    assert numbers == list(range(1, len(numbers) + 1)), f"notebook numbers {numbers}"


@notebook_params
def test_notebook_is_normalized(path: Path) -> None:
    assert is_normalized(path), (
        f"{path.name} is not in normal form: run `eulerlib-course notebooks refresh {path}`"
    )


@notebook_params
def test_notebook_metadata_and_counts(path: Path) -> None:
    notebook = read(path)
    assert notebook.metadata.get("kernelspec", {}).get("name") == "python3"
    assert set(notebook.metadata) <= {"kernelspec", "language_info", "widgets"}, sorted(
        notebook.metadata
    )
    counts = [cell.execution_count for cell in notebook.cells if cell.cell_type == "code"]
    assert counts == list(range(1, len(counts) + 1)), f"execution counts {counts}"
    for index, cell in enumerate(notebook.cells):
        extra = set(cell.get("metadata", {})) - {"tags", "jupyter", "alt"}
        assert not extra, f"cell {index} carries stray metadata {sorted(extra)}"
        folding = set(cell.get("metadata", {}).get("jupyter", {}))
        assert folding <= FOLDING, f"cell {index} carries stray metadata {sorted(folding)}"
        for output in cell.get("outputs", []):
            if output.get("output_type") == "execute_result":
                assert output["execution_count"] == cell.execution_count


@notebook_params
def test_notebook_is_stored_with_outputs(path: Path) -> None:
    # Strict nbval compares stored outputs: a notebook saved without them compares nothing.
    notebook = read(path)
    assert any(cell.get("outputs") for cell in notebook.cells if cell.cell_type == "code"), (
        f"{path.name} has no outputs: refresh it"
    )


# --- course structure --------------------------------------------------------------------------


def first_list_items(text: str) -> list[str]:
    """Items of the first Markdown list in ``text`` (continuation lines and nested items are
    part of their item; a paragraph that is not indented ends the list)."""
    item = re.compile(r"(?:[-*+]|\d+[.)])\s+\S")
    items: list[str] = []
    for line in text.splitlines():
        if item.match(line):
            items.append(line)
        elif items and (not line.strip() or line[:1].isspace()):
            continue
        elif items:
            break
    return items


@notebook_params
def test_learning_objectives_near_the_top(path: Path) -> None:
    notebook = read(path)
    head = [cell for cell in notebook.cells[:5] if cell.cell_type == "markdown"]
    found = [i for i, cell in enumerate(head) if "objective" in cell.source.lower()]
    assert found, f"{path.name}: no learning objectives in its first cells"
    # The list of objectives follows the word, in the same cell or in the next markdown cell.
    text = "\n\n".join(cell.source for cell in head[found[0] : found[0] + 2])
    items = first_list_items(text[text.lower().index("objective") :])
    assert 3 <= len(items) <= 5, f"{path.name}: {len(items)} learning objectives, expected 3 to 5"


@notebook_params
def test_prerequisites_next_to_the_objectives(path: Path) -> None:
    head = " ".join(cell.source for cell in read(path).cells[:5] if cell.cell_type == "markdown")
    assert "prerequisite" in head.lower(), f"{path.name}: no prerequisites in its first cells"


def test_the_glossary_is_in_normal_form_and_only_words() -> None:
    assert is_normalized(GLOSSARY)
    assert all(cell.cell_type == "markdown" for cell in read(GLOSSARY).cells)
    assert sorted(NOTEBOOK_DIR.glob("*.ipynb")) == sorted([*NOTEBOOKS, GLOSSARY])


@notebook_params
def test_summary(path: Path) -> None:
    notebook = read(path)
    headings = [
        line
        for cell in notebook.cells
        if cell.cell_type == "markdown"
        for line in cell.source.splitlines()
        if line.lstrip().startswith("#")
    ]
    assert any("summary" in line.lower() for line in headings), f"{path.name}: no summary"


# --- student copies of the course notebooks ---------------------------------------------------


@notebook_params
def test_student_copy_has_no_solutions_and_no_outputs(path: Path) -> None:
    original = read(path)
    student = student_copy(original)
    nbformat.validate(student)
    assert not any("solution" in tags_of(cell) for cell in student.cells)
    assert not any(cell.get("outputs") for cell in student.cells if cell.cell_type == "code")
    assert all(cell.execution_count is None for cell in student.cells if cell.cell_type == "code")
    kept = [c.source for c in original.cells if "solution" not in tags_of(c)]
    first = next(i for i, source in enumerate(kept) if "from eulerlib_course import" in source)
    kept.insert(first + 1, name_cell_source(None))  # whose data: the student types a name
    assert [c.source for c in student.cells] == kept
    named = student_copy(original, "ada")
    assert [c.source for c in named.cells if "student_name(" in c.source] == [
        name_cell_source("ada")
    ]
    for tag in ("exercise", "check"):
        count = sum(tag in tags_of(cell) for cell in original.cells)
        assert sum(tag in tags_of(cell) for cell in student.cells) == count


# --- the tooling, on small notebooks built here ------------------------------------------------


def run_cli(capsys: pytest.CaptureFixture[str], *args: str) -> tuple[int, str, str]:
    """``eulerlib ARGS`` in this process: (exit status, standard output, standard error)."""
    status = cli.main(list(args))
    captured = capsys.readouterr()
    return status, captured.out, captured.err


def assert_one_line_failure(status: int, err: str, *words: str) -> None:
    assert status != 0
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    for word in words:
        assert word in lines[0], lines[0]


def tiny_notebook() -> nbformat.NotebookNode:
    """A small course notebook as an editor leaves it: counts out of order, stray metadata,
    one exercise whose worked solution is folded."""
    notebook = nbformat.v4.new_notebook()
    notebook.metadata = {
        "kernelspec": {"display_name": "Some Python", "language": "python", "name": "python3"},
        "widgets": {"state": {}},
        "toc": {"number_sections": True},
    }
    title = nbformat.v4.new_markdown_cell("# A tiny notebook")
    title.metadata = {"editable": False, "jupyter": {"source_hidden": False, "other": 1}}
    first = nbformat.v4.new_code_cell(
        "import sys\nx = 6 * 7\nprint('x is', end=' ')\nsys.stdout.flush()\nprint(x)",
        execution_count=7,
    )
    first.metadata = {"collapsed": True, "execution": {"iopub.status.busy": "2020-01-01"}}
    second = nbformat.v4.new_code_cell("x + 1", execution_count=3)
    second.metadata = {"scrolled": True, "tags": []}
    exercise = nbformat.v4.new_code_cell("answer = ...", metadata={"tags": ["exercise"]})
    solution = nbformat.v4.new_code_cell("answer = x")
    solution.metadata = {
        "tags": ["solution"],
        "jupyter": {"source_hidden": True, "outputs_hidden": True},
        "editable": True,
    }
    check = nbformat.v4.new_code_cell(
        "print('not yet' if answer is ... else 'correct' if answer == 42 else 'off')",
        metadata={"tags": ["check"], "deletable": False},
    )
    notebook.cells = [title, first, second, exercise, solution, check]
    return notebook


def test_normal_form_keeps_tags_and_folding_only() -> None:
    normal = normalize_notebook(tiny_notebook())
    assert normal.metadata == {"kernelspec": KERNELSPEC, "language_info": {"name": "python"}}
    assert [cell.metadata for cell in normal.cells] == [
        {"jupyter": {"source_hidden": False}},
        {},
        {},
        {"tags": ["exercise"]},
        {"tags": ["solution"], "jupyter": {"source_hidden": True, "outputs_hidden": True}},
        {"tags": ["check"]},
    ]
    assert [cell.get("execution_count") for cell in normal.cells] == [None, 1, 2, 3, 4, 5]
    assert [cell.id for cell in normal.cells] == [f"cell-00{i}" for i in range(6)]


def test_normal_form_joins_split_prints() -> None:
    notebook = tiny_notebook()
    notebook.cells[1].outputs = [
        nbformat.v4.new_output("stream", name="stdout", text="x is "),
        nbformat.v4.new_output("stream", name="stdout", text="42\n"),
        nbformat.v4.new_output("stream", name="stderr", text="a warning\n"),
    ]
    outputs = normalize_notebook(notebook).cells[1].outputs
    assert [(o.name, o.text) for o in outputs] == [
        ("stdout", "x is 42\n"),
        ("stderr", "a warning\n"),
    ]


def test_normalize_is_idempotent_and_keeps_sources() -> None:
    once = normalize_notebook(tiny_notebook())
    twice = normalize_notebook(once)
    assert once == twice
    assert [c.source for c in once.cells] == [c.source for c in tiny_notebook().cells]
    original = tiny_notebook()
    unchanged = copy.deepcopy(original)
    normalize_notebook(original)
    assert original == unchanged


def test_is_normalized_detects_stray_metadata(tmp_path: Path) -> None:
    path = tmp_path / "n.ipynb"
    nbformat.write(normalize_notebook(tiny_notebook()), str(path))
    assert is_normalized(path)
    notebook = read(path)
    notebook.cells[1].metadata["collapsed"] = True
    nbformat.write(notebook, str(path))
    assert not is_normalized(path)


def test_refresh_command_executes_and_normalizes(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "01_tiny.ipynb"
    nbformat.write(tiny_notebook(), str(path))
    assert not is_normalized(path)
    status, out, err = run_cli(capsys, "notebooks", "refresh", str(path))
    assert (status, out, err) == (0, f"refreshed {path}\n", "")
    assert is_normalized(path)
    notebook = read(path)
    nbformat.validate(notebook)
    expected = normalize_notebook(tiny_notebook())
    assert notebook.metadata == expected.metadata
    assert [cell.metadata for cell in notebook.cells] == [cell.metadata for cell in expected.cells]
    _, first, second, _, solution, check = notebook.cells
    assert [(o.output_type, o.get("name")) for o in first.outputs] == [("stream", "stdout")]
    assert output_text(first) == "x is 42\n"  # one print, although flushed in two pieces
    assert output_text(second) == "43"
    assert second.outputs[0]["execution_count"] == 2
    assert solution.metadata["jupyter"] == {"source_hidden": True, "outputs_hidden": True}
    assert output_text(check) == "correct\n"
    assert list(tmp_path.iterdir()) == [path]  # nothing else written


def test_student_command_writes_copies_whose_checks_say_not_yet(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source, out = tmp_path / "course", tmp_path / "student"
    source.mkdir()
    nbformat.write(tiny_notebook(), str(source / "01_tiny.ipynb"))
    nbformat.write(nbformat.v4.new_notebook(), str(source / "02_empty.ipynb"))
    status, stdout, err = run_cli(
        capsys, "notebooks", "student", "--src", str(source), "--out", str(out)
    )
    assert (status, stdout, err) == (0, f"wrote 2 student copies to {out}\n", "")
    assert sorted(p.name for p in out.iterdir()) == ["01_tiny.ipynb", "02_empty.ipynb"]
    copy_path = out / "01_tiny.ipynb"
    student = read(copy_path)
    assert [tags_of(cell) for cell in student.cells] == [[], [], [], ["exercise"], ["check"]]
    # The copy runs top to bottom, and its check finds the answer not given yet.
    assert run_cli(capsys, "notebooks", "refresh", str(copy_path))[0] == 0
    assert output_text(read(copy_path).cells[-1]) == "not yet\n"


def test_student_copies_bring_the_data_the_notebooks_read(tmp_path: Path) -> None:
    source, out = tmp_path / "course", tmp_path / "student"
    (source / "data" / "inner").mkdir(parents=True)
    nbformat.write(tiny_notebook(), str(source / "01_tiny.ipynb"))
    (source / "data" / "samples.csv").write_bytes(b"t,x\r\n0,1\r\n")
    (source / "data" / "inner" / "README.md").write_text("origin\n", encoding="utf-8")
    write_student_copies(source, out)
    assert (out / "data" / "samples.csv").read_bytes() == b"t,x\r\n0,1\r\n"
    assert (out / "data" / "inner" / "README.md").read_text(encoding="utf-8") == "origin\n"


def test_student_command_overwrites_only_with_force(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source, out = tmp_path / "course", tmp_path / "student"
    source.mkdir()
    out.mkdir()
    for name in ("01_a.ipynb", "02_b.ipynb", "03_c.ipynb"):
        nbformat.write(tiny_notebook(), str(source / name))
    for name in ("01_a.ipynb", "03_c.ipynb", "notes.txt"):
        (out / name).write_text("a learner's work\n")
    arguments = ("notebooks", "student", "--src", str(source), "--out", str(out))
    status, stdout, err = run_cli(capsys, *arguments)
    assert_one_line_failure(
        status, err, "2 of the 3 files of the student copies already exist", "--force"
    )
    assert stdout == ""
    assert sorted(p.name for p in out.iterdir()) == ["01_a.ipynb", "03_c.ipynb", "notes.txt"]
    assert all(
        (out / name).read_text() == "a learner's work\n" for name in ("01_a.ipynb", "03_c.ipynb")
    )
    status, stdout, _ = run_cli(capsys, *arguments, "--force")
    assert (status, stdout) == (0, f"wrote 3 student copies to {out}\n")
    assert (out / "notes.txt").read_text() == "a learner's work\n"
    assert read(out / "01_a.ipynb") == student_copy(tiny_notebook())


def test_student_command_keeps_data_already_in_out_without_force(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # No notebook copy there yet, but a data file of the same name: nothing is replaced.
    source, out = tmp_path / "course", tmp_path / "student"
    (source / "data").mkdir(parents=True)
    (out / "data").mkdir(parents=True)
    nbformat.write(tiny_notebook(), str(source / "01_tiny.ipynb"))
    (source / "data" / "samples.csv").write_bytes(b"t,x\r\n0,1\r\n")
    (out / "data" / "samples.csv").write_bytes(b"a learner's own recording")
    arguments = ("notebooks", "student", "--src", str(source), "--out", str(out))
    status, _, err = run_cli(capsys, *arguments)
    assert_one_line_failure(status, err, "data/samples.csv", "--force")
    assert (out / "data" / "samples.csv").read_bytes() == b"a learner's own recording"
    assert not (out / "01_tiny.ipynb").exists()
    assert run_cli(capsys, *arguments, "--force")[0] == 0
    assert (out / "data" / "samples.csv").read_bytes() == b"t,x\r\n0,1\r\n"


@pytest.mark.parametrize("action", ["student", "nbgrader"])
@pytest.mark.parametrize("force", [[], ["--force"]])
def test_student_and_nbgrader_refuse_an_empty_or_file_out(
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
    action: str,
    force: list[str],
) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "a_file").write_text("kept")
    for out, words in (("", "is empty"), ("a_file", "a_file is a file, not a folder")):
        with pytest.raises(SystemExit) as exit_:
            run_cli(capsys, "notebooks", action, "--src", str(NOTEBOOK_DIR), "--out", out, *force)
        assert exit_.value.code == 2
        error = capsys.readouterr().err.splitlines()[-1]
        assert words in error and "--force" not in error
    assert sorted(path.name for path in tmp_path.iterdir()) == ["a_file"]
    assert (tmp_path / "a_file").read_text() == "kept"


def test_student_command_without_notebook_folder_fails_in_one_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    status, _, err = run_cli(capsys, "notebooks", "student", "--out", "out")
    assert_one_line_failure(status, err, "no notebooks/ folder here", "repository", "--src")
    status, _, err = run_cli(capsys, "notebooks", "student", "--src", "missing", "--out", "out")
    assert_one_line_failure(status, err, "no notebook folder at missing")
    assert list(tmp_path.iterdir()) == []


def test_refresh_without_notebook_folder_fails_in_one_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    status, _, err = run_cli(capsys, "notebooks", "refresh")
    assert_one_line_failure(status, err, "no notebooks/ folder here", "repository")


def test_refresh_of_a_missing_notebook_fails_in_one_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    status, out, err = run_cli(capsys, "notebooks", "refresh", str(tmp_path / "absent.ipynb"))
    assert_one_line_failure(status, err, "absent.ipynb")
    assert out == ""


def test_refresh_of_a_failing_notebook_fails_in_one_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    notebook = nbformat.v4.new_notebook()
    notebook.cells = [nbformat.v4.new_code_cell("1 / 0")]
    path = tmp_path / "broken.ipynb"
    nbformat.write(notebook, str(path))
    before = path.read_bytes()
    status, out, err = run_cli(capsys, "notebooks", "refresh", str(path))
    assert (status, out) == (1, "")
    assert err.strip().splitlines() == [
        f"eulerlib-course notebooks: error: {path}: "
        "a cell raised ZeroDivisionError: division by zero"
    ]
    assert path.read_bytes() == before  # left as it was


def test_student_copy_function_drops_solution_cells() -> None:
    notebook = nbformat.v4.new_notebook()
    cells = [
        nbformat.v4.new_code_cell("answer_1 = ...", metadata={"tags": ["exercise"]}),
        nbformat.v4.new_code_cell("answer_1 = 1", metadata={"tags": ["solution"]}),
        nbformat.v4.new_code_cell("check_number(answer_1, 1)", metadata={"tags": ["check"]}),
    ]
    cells[2].outputs = [nbformat.v4.new_output("stream", text="correct\n")]
    cells[2].execution_count = 3
    notebook.cells = cells
    student = student_copy(notebook)
    assert [c.source for c in student.cells] == ["answer_1 = ...", "check_number(answer_1, 1)"]
    assert [c.id for c in student.cells] == ["cell-000", "cell-001"]
    assert all(c.outputs == [] and c.execution_count is None for c in student.cells)
    assert len(notebook.cells) == 3 and notebook.cells[2].outputs  # the original is left alone


def test_student_copies_refuse_the_course_folder_and_bad_flags(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="another folder"):
        write_student_copies(tmp_path, tmp_path)
    with pytest.raises(ValueError, match="no notebook folder"):
        write_student_copies(tmp_path / "missing", tmp_path / "out")
    with pytest.raises(TypeError, match=r"^force must be True or False"):
        write_student_copies(tmp_path, tmp_path / "out", force="yes")  # type: ignore[arg-type]


# --- without the notebook tools -----------------------------------------------------------------


@pytest.mark.parametrize(
    ("hidden", "action"),
    [
        ("nbformat", ("student", "--out", "out")),
        ("nbclient", ("refresh",)),
        ("nbconvert", ("student", "--out", "out")),
    ],
)
def test_notebook_commands_name_what_to_install_when_a_tool_is_missing(
    hidden: str,
    action: tuple[str, ...],
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "notebooks").mkdir()
    monkeypatch.setitem(sys.modules, hidden, None)  # `import hidden` fails, as when not installed
    status, out, err = run_cli(capsys, "notebooks", *action)
    assert (status, out) == (1, "")
    assert err.splitlines() == [
        f"eulerlib-course notebooks: error: eulerlib-course notebooks {action[0]} needs {hidden}, "
        "a dependency of eulerlib-course: pip install -e ./course"
    ]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["notebooks"]
