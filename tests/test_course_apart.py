"""The library never depends on the course: no module of ``eulerlib/`` and no library test
imports ``eulerlib_course``.

The course package (``course/eulerlib_course``) is built on the library and may import it; the
other way round would put the course back into the library's wheel and its tests. The imports
are read from the source with :mod:`ast`, so an import inside a function counts too.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
COURSE = "eulerlib_course"
LIBRARY_MODULES = sorted((ROOT / "eulerlib").rglob("*.py"))
LIBRARY_TESTS = sorted((ROOT / "tests").rglob("*.py"))


def imported_modules(path: Path) -> set[str]:
    """Every module that ``path`` imports, by its full dotted name."""
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    found: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module is not None and node.level == 0:
            found.add(node.module)
            found.update(f"{node.module}.{alias.name}" for alias in node.names)
        elif (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Attribute)
            and node.func.attr == "import_module"
            and node.args
            and isinstance(node.args[0], ast.Constant)
            and isinstance(node.args[0].value, str)
        ):
            found.add(node.args[0].value)
    return found


def imports_the_course(path: Path) -> list[str]:
    return sorted(
        name
        for name in imported_modules(path)
        if name == COURSE or name.startswith(f"{COURSE}.") or name.startswith("eulerlib.course")
    )


@pytest.mark.parametrize(
    "path", LIBRARY_MODULES + LIBRARY_TESTS, ids=lambda p: p.relative_to(ROOT).as_posix()
)
def test_no_library_file_imports_the_course(path: Path) -> None:
    assert imports_the_course(path) == []


def test_the_check_sees_an_import_of_the_course(tmp_path: Path) -> None:
    """The check itself works, for each way of importing."""
    for line in (
        "import eulerlib_course",
        "from eulerlib_course.explorable import Explorable",
        "from eulerlib_course import check",
        "def f():\n    import eulerlib_course.cli",
        "import importlib\nimportlib.import_module('eulerlib_course')",
    ):
        probe = tmp_path / "probe.py"
        probe.write_text(line + "\n", encoding="utf-8")
        assert imports_the_course(probe), line
    probe.write_text("import eulerlib\nfrom eulerlib import plotting\n", encoding="utf-8")
    assert imports_the_course(probe) == []


def test_the_library_has_no_course_folder() -> None:
    assert not (ROOT / "eulerlib" / "course").exists()
    assert LIBRARY_MODULES and LIBRARY_TESTS
