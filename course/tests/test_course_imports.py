"""The course uses the library as any user would: through its public modules.

Every module of ``course/eulerlib_course`` is read with :mod:`ast` (not imported), and each
import of ``eulerlib`` — at the top or inside a function — must name a public module
(``eulerlib``, ``eulerlib.euler``, ``eulerlib.plotting``, …), never a private one
(``eulerlib._euler_kernels``, ``eulerlib.plotting._base``). The one exception is
``eulerlib._validation``, the library's argument rules, so that a flag such as ``force`` or a
tolerance is checked by the same rule in the course as in the library.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

COURSE = Path(__file__).resolve().parents[1] / "eulerlib_course"
MODULES = sorted(COURSE.rglob("*.py"))
#: Private modules of the library that the course may use, and why: see the docstring.
ALLOWED_PRIVATE = {"eulerlib._validation"}


def library_imports(source: str) -> list[str]:
    """The dotted names of the ``eulerlib`` modules and names that ``source`` imports."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            found += [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            found += [f"{node.module}.{alias.name}" for alias in node.names]
    return [name for name in found if name == "eulerlib" or name.startswith("eulerlib.")]


def private_parts(name: str) -> bool:
    """Whether a dotted name passes through a private module or names a private object."""
    for allowed in ALLOWED_PRIVATE:
        if name == allowed or name.startswith(f"{allowed}."):
            name = name[len(allowed) :].lstrip(".")
            return any(part.startswith("_") for part in name.split(".") if part)
    return any(part.startswith("_") and not part.startswith("__") for part in name.split("."))


def offending(source: str) -> list[str]:
    return [name for name in library_imports(source) if private_parts(name)]


@pytest.mark.parametrize("path", MODULES, ids=lambda p: p.relative_to(COURSE).as_posix())
def test_the_course_imports_only_public_library_modules(path: Path) -> None:
    assert offending(path.read_text(encoding="utf-8")) == [], path.name


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("from eulerlib.plotting._base import style_axes", ["eulerlib.plotting._base.style_axes"]),
        ("import eulerlib._euler_kernels", ["eulerlib._euler_kernels"]),
        ("def f():\n    from eulerlib.euler import _helper", ["eulerlib.euler._helper"]),
        ("from eulerlib._validation import _index_text", ["eulerlib._validation._index_text"]),
        ("from eulerlib._validation import check_flag", []),
        ("from eulerlib import euler_to_matrix\nimport eulerlib.plotting", []),
        ("from eulerlib.plotting import draw_frame, new_3d_axes", []),
    ],
)
def test_the_check_tells_private_from_public(source: str, expected: list[str]) -> None:
    assert offending(source) == expected


def test_there_are_course_modules_to_check() -> None:
    assert len(MODULES) > 10
