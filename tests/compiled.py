"""Running a public function with and without the compiled kernels, for the tests that hold
the two paths against each other (eulerlib/_compiled.py).

Where the kernels were not built, the tests that need them are skipped, unless
``EULERLIB_COMPILED=required`` (CI sets it): a kernel that failed to build must fail CI, not
make its tests vanish.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

import numpy as np
import pytest

from eulerlib import _compiled

_KINDS = ("euler", "rotations", "operations")
_LOADED = {kind: getattr(_compiled, kind) for kind in _KINDS}

if os.environ.get("EULERLIB_COMPILED") == "required":
    _missing = [kind for kind, module in _LOADED.items() if module is None]
    assert not _missing, f"compiled kernels required but not built: {_missing}"

#: Skips a test where the compiled kernels are not there (see the module's docstring).
needs_compiled = pytest.mark.skipif(
    any(module is None for module in _LOADED.values()),
    reason="the compiled kernels were not built (or EULERLIB_COMPILED=0)",
)


@contextmanager
def numpy_only() -> Iterator[None]:
    """Within the block, eulerlib runs as if the compiled kernels had not been built."""
    saved = {kind: getattr(_compiled, kind) for kind in _KINDS}
    for kind in _KINDS:
        setattr(_compiled, kind, None)
    try:
        yield
    finally:
        for kind, module in saved.items():
            setattr(_compiled, kind, module)


def both(function: Callable[..., Any], *args: Any, **kwargs: Any) -> tuple[Any, Any]:
    """``function(*args, **kwargs)`` with the compiled kernels, then without them."""
    compiled = function(*args, **kwargs)
    with numpy_only():
        pure = function(*args, **kwargs)
    return compiled, pure


def assert_same_bits(compiled: Any, pure: Any) -> None:
    """The two results are arrays of the same type, dtype and shape with the same bytes (so a
    ``-0.0`` against a ``0.0`` fails too)."""
    if isinstance(pure, tuple):
        assert isinstance(compiled, tuple) and len(compiled) == len(pure)
        for one, other in zip(compiled, pure, strict=True):
            assert_same_bits(one, other)
        return
    assert type(compiled) is type(pure)
    if isinstance(pure, np.ndarray):
        assert compiled.dtype == pure.dtype and compiled.shape == pure.shape
        assert compiled.tobytes() == pure.tobytes(), (compiled, pure)
    else:
        assert np.float64(compiled).tobytes() == np.float64(pure).tobytes(), (compiled, pure)
