"""The compiled kernels of quaternions, rotation vectors and axis-angle pairs against the
numpy-only path, on the same inputs: the same bits, the same shapes, the same errors.

The oracle is the numpy-only path, which the other test files hold against SciPy, mpmath and
the papers; these tests show that the optional kernels change nothing but the time.
"""

from __future__ import annotations

import numpy as np
import pytest
from budget import examples
from compiled import assert_same_bits, both, needs_compiled
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

import eulerlib

pytestmark = needs_compiled

# numbers of every scale, so that lengths that need rescaling (declined by the kernels) occur
scaled = st.one_of(
    st.floats(-2.0, 2.0),
    st.floats(-1e-160, 1e-160),
    st.floats(-1e160, 1e160),
    st.sampled_from([0.0, -0.0, 1.0, -1.0, 5e-324, 1.7e308]),
)
shapes = st.sampled_from([(), (1,), (3,), (2, 3), (17,)])


def outcome(function, *args, **kwargs):
    """The result of a call, or the type and message of what it raised."""
    try:
        return function(*args, **kwargs)
    except (ValueError, TypeError) as error:
        return type(error), str(error)


def assert_same_outcome(function, *args, **kwargs) -> None:
    compiled, pure = both(outcome, function, *args, **kwargs)
    if isinstance(pure, tuple) and isinstance(pure[0], type):
        assert compiled == pure
    else:
        assert_same_bits(compiled, pure)


@settings(max_examples=examples(300))
@given(shape=shapes, data=st.data(), first=st.booleans())
def test_quaternion_to_matrix(shape, data, first) -> None:
    q = data.draw(arrays(np.float64, (*shape, 4), elements=scaled))
    assert_same_outcome(eulerlib.quaternion_to_matrix, q, scalar_first=first)


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_quaternion_to_matrix_refuses_alike(bad) -> None:
    q = np.array([[0.0, 0.0, 0.0, 1.0], [0.5, 0.5, bad, 0.5]])
    assert_same_outcome(eulerlib.quaternion_to_matrix, q)
    assert_same_outcome(eulerlib.quaternion_to_matrix, np.zeros((3, 4)))
