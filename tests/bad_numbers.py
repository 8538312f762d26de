"""Values that break the rules for numbers, shared by the tests of bad input.

Every public function reads its numbers through one rule (``eulerlib._validation``): real,
finite, not masked, not too large for a float. :func:`bad_values` makes, from a valid value of
an argument, one value that breaks each part of that rule, with the error and the words that
must follow the argument's name in the message.
"""

from __future__ import annotations

import re
from typing import Any

import numpy as np


def bad_values(valid: Any) -> list[tuple[object, type[Exception], str]]:
    """Values that break the rules, each with its exception and the words after the name."""
    array = np.asarray(valid, dtype=float)
    with_nan, with_inf, huge = array.copy(), array.copy(), array.astype(object)
    with_nan.flat[-1] = np.nan
    with_inf.flat[0] = -np.inf
    huge.flat[0] = 10**400
    last = tuple(int(i) for i in np.unravel_index(array.size - 1, array.shape))
    where = f" at index {last}" if array.ndim else ""
    return [
        ("text", TypeError, "must be numbers, got text"),
        (None, TypeError, "must be real numbers; got an array of objects that are not numbers"),
        (array.astype(bool), TypeError, "must be real numbers, got booleans"),
        (array + 1j, TypeError, "must be real numbers, got complex numbers"),
        (np.ma.masked_array(array), TypeError, "is a masked array"),
        (with_nan, ValueError, re.escape(f"must be finite, got nan{where}")),
        (with_inf, ValueError, "must be finite, got -inf"),
        (huge.tolist(), ValueError, "holds a number too large for a float"),
    ]
