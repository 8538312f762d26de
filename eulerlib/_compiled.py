"""The optional compiled kernels, and how the public functions hand them an array.

eulerlib is numpy only; where a C compiler was present at installation, three small extension
modules add kernels that do in one pass what the array path does in many numpy operations:
read a batch, check each rotation, and compute the same formulas in the same order
(``eulerlib/_compiled.h`` gives the rules that keep their results identical to the numpy-only
ones, to the last bit). They take plain float64 arrays of any size; for anything they do not
take, and whenever a check fails or a rotation needs the array path's care (a lock, a length
that needs rescaling), a kernel returns ``False`` and the public function goes on to the array
path, which gives the same result or words the error or warning.

``EULERLIB_COMPILED=0`` in the environment turns them off, as if they had not been built:
:data:`euler`, :data:`rotations` and :data:`operations` are ``None`` then, and the tests set
them to ``None`` to compare both paths (``tests/compiled.py``).
"""

from __future__ import annotations

import importlib
import os
from types import ModuleType
from typing import Any

import numpy as np
from numpy.typing import NDArray


def _load(name: str) -> ModuleType | None:
    """The extension module ``eulerlib.<name>``, or None when it was not built or is off."""
    if os.environ.get("EULERLIB_COMPILED", "1") == "0":
        return None
    try:
        return importlib.import_module(f"eulerlib.{name}")
    except ImportError:
        return None


#: Kernels of Euler angles (eulerlib/_compiled_euler.c), or None.
euler: Any = _load("_compiled_euler")
#: Kernels of quaternions, rotation vectors and matrix operations
#: (eulerlib/_compiled_rotations.c), or None.
rotations: Any = _load("_compiled_rotations")
#: Kernels of operations on matrices: rotating points, inverse, product, slerp, integration
#: (eulerlib/_compiled_operations.c), or None.
operations: Any = _load("_compiled_operations")


def batch(value: Any, shape: tuple[int, ...]) -> NDArray[np.float64] | None:
    """``value`` when it is a C-contiguous float64 array of shape ``(..., *shape)`` with at
    least one element, else None: the only arrays the kernels take."""
    if type(value) is not np.ndarray or value.dtype != np.float64:
        return None
    if value.shape[value.ndim - len(shape) :] != shape or not value.flags.c_contiguous:
        return None
    return value if value.size else None
