"""The import contract of eulerlib: which layer may import which, checked on the source.

Every module under ``eulerlib/`` is read with :mod:`ast` (not imported) and each of its imports,
at the top or inside a function, is held against these rules:

* **kernels** (``eulerlib/_*_kernels.py``, ``eulerlib/_trig.py`` and ``eulerlib/_sequences.py``,
  the sequence type they compute with) import only numpy, the standard library and each other;
* **private modules** of the library (every other ``eulerlib/_*.py``: checks, shared bodies of
  the conversions, the lock warning, the conventions) import kernels and each other, never a
  public module of eulerlib;
* **public modules** (``eulerlib/*.py``: the documented functions, thin fronts that check the
  arguments and call one hop below) never import ``eulerlib.symbolic``, ``eulerlib.plotting``,
  or the command line;
* ``eulerlib.symbolic`` and ``eulerlib.plotting`` may use the public layer; their own private
  modules (``_*.py``) never import the package's public modules;
* the command line (``eulerlib/cli.py``, ``convert_cli.py``, ``__main__.py``) sits on top;
* a private name (``_x``) is imported only from a private module: anyone may import
  ``eulerlib._validation``, nobody imports ``eulerlib.euler._helper``;
* nothing under ``eulerlib`` imports ``eulerlib_course``, the course's own package.

So a new representation (say modified Rodrigues parameters) puts its arithmetic in a kernel
(``_mrp_kernels.py``), its checks and shared bodies in a private module, and its documented
functions in a public module (``mrp.py``) that the package's ``__init__`` re-exports.
"""

from __future__ import annotations

import ast
import sys
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parent.parent / "eulerlib"
KERNELS = {"eulerlib._trig", "eulerlib._sequences"}
COMMAND_LINE = {"eulerlib.cli", "eulerlib.convert_cli", "eulerlib.__main__"}
ADD_ONS = ("eulerlib.symbolic", "eulerlib.plotting")
ALLOWED_OUTSIDE = {"numpy", "__future__"} | set(sys.stdlib_module_names)


def module_name(path: Path) -> str:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def is_private(name: str) -> bool:
    last = name.rsplit(".", 1)[-1]
    return last.startswith("_") and not last.startswith("__")


def is_kernel(name: str) -> bool:
    return name in KERNELS or (
        name.count(".") == 1 and name.endswith("_kernels") and is_private(name)
    )


def subpackage(name: str) -> str | None:
    """``eulerlib.plotting`` for a module of that package (itself included), else None."""
    for package in ADD_ONS:
        if name == package or name.startswith(package + "."):
            return package
    return None


def imports(tree: ast.Module, name: str, is_package: bool) -> list[tuple[int, str, list[str]]]:
    """Every import: (line, module imported from, names taken from it) with ``[]`` for
    ``import x``; relative imports resolved against ``name``."""
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found.extend((node.lineno, alias.name, []) for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = name.split(".") if is_package else name.split(".")[:-1]
                anchor = anchor[: len(anchor) - (node.level - 1)]
                base = ".".join([*anchor, base]) if base else ".".join(anchor)
            names = [alias.name for alias in node.names]
            # ``from eulerlib import convert_cli`` imports a module: count it as one
            if base == "eulerlib" or subpackage(base) == base:
                found.extend((node.lineno, f"{base}.{item}", []) for item in names)
            else:
                found.append((node.lineno, base, names))
    return found


def violations(name: str, source: str, is_package: bool = False) -> list[str]:
    """What breaks the contract in module ``name`` with this source, one line each."""
    tree = ast.parse(source)
    problems = []
    own = subpackage(name)
    for line, target, names in imports(tree, name, is_package):
        where = f"{name} (line {line}) imports {target}"
        top = target.split(".")[0]
        if top == "eulerlib_course":
            problems.append(f"{where}: the library never imports the course's package")
            continue
        if top != "eulerlib":
            if is_kernel(name) and top not in ALLOWED_OUTSIDE:
                problems.append(f"{where}: a kernel imports only numpy and other kernels")
            continue
        for item in names:
            if is_private(item) and not is_private(target):
                problems.append(
                    f"{where}, name {item}: a private name is imported only from a private module"
                )
        if is_kernel(name):
            if not is_kernel(target):
                problems.append(f"{where}: a kernel imports only numpy and other kernels")
        elif own is None and is_private(name):
            if not is_private(target):
                problems.append(f"{where}: a private module never imports a public module")
        elif own is None and name not in COMMAND_LINE and name != "eulerlib":
            if subpackage(target) or target in COMMAND_LINE:
                problems.append(
                    f"{where}: the public layer never imports symbolic, plotting, the course "
                    "or the command line"
                )
        elif name == "eulerlib" and (subpackage(target) or target in COMMAND_LINE):
            problems.append(f"{where}: 'import eulerlib' loads the public layer only")
        elif own is not None and is_private(name):
            if subpackage(target) == own and not is_private(target) and target != own:
                problems.append(
                    f"{where}: a private module of {own} never imports its public modules"
                )
    return problems


MODULES = sorted(path for path in PACKAGE.rglob("*.py"))


@pytest.mark.parametrize("path", MODULES, ids=lambda path: module_name(path))
def test_module_keeps_the_import_contract(path: Path) -> None:
    found = violations(
        module_name(path), path.read_text(encoding="utf-8"), path.name == "__init__.py"
    )
    assert not found, "\n".join(found)


@pytest.mark.parametrize(
    ("name", "source", "words"),
    [
        ("eulerlib._validation", "from eulerlib.euler import matrix_to_euler", "public module"),
        ("eulerlib._euler_kernels", "from eulerlib._validation import check_flag", "kernel"),
        ("eulerlib._trig", "import scipy", "kernel"),
        ("eulerlib.named", "from eulerlib.euler import _helper", "private name"),
        ("eulerlib.euler", "from eulerlib.plotting import plot_frames", "public layer"),
        ("eulerlib.euler", "from eulerlib import convert_cli", "public layer"),
        ("eulerlib.quaternion", "import eulerlib_course", "course's package"),
        ("eulerlib.plotting._base", "from eulerlib.plotting.frames import x", "private module"),
        ("eulerlib.plotting._base", "from .frames import draw_frame", "private module"),
    ],
)
def test_a_crossing_is_named(name: str, source: str, words: str) -> None:
    """The checker itself: each kind of crossing is found, naming the module and the import."""
    (problem,) = violations(name, source)
    assert problem.startswith(f"{name} (line 1) imports ")
    assert words in problem


@pytest.mark.parametrize(
    ("name", "source"),
    [
        (
            "eulerlib._euler_kernels",
            "import math\nimport numpy as np\nfrom eulerlib._trig import sin_cos",
        ),
        ("eulerlib.euler", "from eulerlib._euler import angles_to_matrices"),
        ("eulerlib.plotting.frames", "from eulerlib.plotting._base import arrow_head"),
        ("eulerlib.plotting.frames", "from eulerlib.euler import euler_to_matrix"),
        ("eulerlib.cli", "from eulerlib.convert_cli import configure_parser"),
    ],
)
def test_allowed_imports_pass(name: str, source: str) -> None:
    assert violations(name, source) == []
