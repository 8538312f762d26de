"""How pytest runs in this repository, and four costs it no longer pays in every process.

The test command starts several pytest processes (the controller, one worker per core, and the
sessions some tests run). Four costs there had nothing to do with the tests:

* **Linear-algebra threads fighting over the cores.** Each worker already has a core, and every
  notebook runs in a kernel of its own beside it; OpenBLAS (which NumPy and SciPy use for
  ``@``, ``solve`` and the SVD) starts a thread per core in each of those processes, and its
  idle threads spin while they wait. On two cores that made the README's test command take
  about 73 s instead of 58 s, a fifth of its CPU time spent spinning. The test processes
  therefore run OpenBLAS (and any OpenMP or MKL build) on one thread each:
  :data:`ONE_THREAD` is set before NumPy is first imported, and the kernels and commands the
  tests start inherit it. A variable the user has set is left as it is. The suite passes with
  and without it; only the time differs.

* **Assertion rewriting of every installed plugin.** When pytest loads plugins automatically,
  it rewrites the asserts of each plugin's whole distribution as it is imported, Hypothesis'
  80 modules and AnyIO's 30 among them. With ``PYTHONDONTWRITEBYTECODE`` set (as CI sets it)
  pytest cannot cache the result, so every process did it again: about a second each.
  ``pyproject.toml`` therefore turns automatic loading off (``--disable-plugin-autoload``) and
  names the plugins the suite uses, ``-p xdist`` and ``-p hypothesispytest``; nbval is loaded
  here (``pytest_plugins``), after the step below. The asserts of the tests and of this file
  are rewritten as before.
* **rfc3987_syntax.** nbval reads notebooks with nbformat, which imports jsonschema, which
  imports rfc3987_syntax for its IRI format checks; that package builds three Earley parsers
  when imported, about a second of work per process. Nothing in a test session checks an IRI
  (nbformat validates notebooks against a draft-4 schema, with no format checker), so
  :func:`defer_rfc3987_syntax` puts off importing it until a first IRI check asks for it.
* **The garbage collector going over the same objects again and again.** Collecting the tests
  imports SymPy, matplotlib, SciPy and Hypothesis and makes some 4000 test items, objects that
  live all session; Python's cyclic garbage collector walked them again at every full
  collection, during the collection of the tests and after it. It is therefore off while the
  tests are collected (which makes next to no garbage), and afterwards what is alive is frozen
  out of its view (:func:`pytest_collection`). What the tests throw away is reclaimed as
  before: by reference counting at once, and in cycles by the collector, which runs as often
  as before.

Besides, every test (of the library, of the course, doctests) finds NumPy's print options as
they were before it: :func:`_numpy_print_options`. The other shared fixtures and the checks
around the session are in ``tests/conftest.py``.
"""

from __future__ import annotations

import gc
import importlib
import importlib.util
import os
import sys
import types
from collections.abc import Generator, Iterator
from typing import Any

#: One thread for OpenBLAS, OpenMP and MKL in every test process (see the module docstring).
ONE_THREAD = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")
for _variable in ONE_THREAD:
    os.environ.setdefault(_variable, "1")

import numpy as np  # noqa: E402  (after the thread counts, which NumPy reads when imported)
import pytest  # noqa: E402

#: The package whose import is put off, and the one function jsonschema takes from it.
DEFERRED = "rfc3987_syntax"


def defer_rfc3987_syntax() -> None:
    """Stand in for ``rfc3987_syntax`` in ``sys.modules`` until it is first used.

    The stand-in forwards ``is_valid_syntax`` (all jsonschema imports from it) and any other
    attribute to the real package, which it imports at that moment. Nothing changes when the
    package is not installed or is already imported.
    """
    if DEFERRED in sys.modules or importlib.util.find_spec(DEFERRED) is None:
        return
    stand_in = types.ModuleType(DEFERRED, "Stands in for rfc3987_syntax until it is used.")

    def real() -> Any:
        if sys.modules.get(DEFERRED) is stand_in:
            del sys.modules[DEFERRED]
        return importlib.import_module(DEFERRED)

    def is_valid_syntax(term: str, value: str) -> bool:
        return bool(real().is_valid_syntax(term, value))

    def __getattr__(name: str) -> Any:
        if name.startswith("__"):  # the import system asking what kind of module this is
            raise AttributeError(name)
        return getattr(real(), name)

    stand_in.is_valid_syntax = is_valid_syntax
    stand_in.__getattr__ = __getattr__
    sys.modules[DEFERRED] = stand_in


defer_rfc3987_syntax()

pytest_plugins = ["nbval.plugin"]


@pytest.hookimpl(wrapper=True)
def pytest_collection(session: pytest.Session) -> Generator[None, object, object]:
    """Collect the tests with the garbage collector off, then collect once and freeze."""
    gc.disable()
    try:
        return (yield)
    finally:
        gc.enable()
        gc.collect()
        gc.freeze()


@pytest.fixture(autouse=True)
def _numpy_print_options() -> Iterator[None]:
    """NumPy's print options as they were before each test.

    A test that runs notebook code in this process (the course's exercise tests) runs its
    ``np.set_printoptions``; without this, a doctest that happens to run after it on the same
    worker would print numbers differently.
    """
    options = np.get_printoptions()
    yield
    np.set_printoptions(**options)


#: Modules that cannot be imported without an extra of the course, by the package they need: their
#: doctests are collected only where it is installed (nbgrader comes with the ``teach`` extra,
#: which the README's test command does not install; CI's nbgrader step does).
NEEDS_EXTRA = {"course/eulerlib_course/nbgrader_hooks.py": "nbgrader"}


def pytest_ignore_collect(collection_path: Any, config: pytest.Config) -> bool | None:
    """Leave out a module whose extra is missing, instead of failing to import it."""
    for path, package in NEEDS_EXTRA.items():
        if str(collection_path).endswith(path) and importlib.util.find_spec(package) is None:
            return True
    return None
