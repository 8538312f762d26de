"""Messages about a tolerance show a measured number that visibly breaks it.

A matrix just past a tolerance used to be described with both numbers rounded to the same few
digits ("max |R Rᵀ − I| = 1e-06 exceeds the tolerance 1e-06"). Here each message is read back:
the number it prints as measured must lie beyond the tolerance it prints, in the decimal
arithmetic a reader does on the printed digits, and the message stays one line. The measured
values are found independently, with numpy's linear algebra, to make sure each matrix really
is just past its limit.
"""

from __future__ import annotations

import re
from decimal import Decimal

import numpy as np
import pytest

from eulerlib import REPAIR_LIMIT, matrix_to_euler, nearest_rotation


def message(call) -> str:
    with pytest.raises(ValueError) as caught:
        call()
    text = str(caught.value)
    assert "\n" not in text
    return text


def orthonormality_error(M: np.ndarray) -> float:
    return float(np.abs(M @ M.T - np.eye(3)).max())


@pytest.mark.parametrize("atol", [1e-6, 1e-8, 0.001, 1.2345678901e-5])
def test_orthonormality_just_past_the_tolerance(atol: float) -> None:
    stretch = np.sqrt(1.0 + atol)
    while orthonormality_error(np.diag([stretch, 1.0, 1.0])) <= atol:  # the first one past
        stretch = np.nextafter(stretch, 2.0)
    for factor in (stretch, stretch + 1e-9 * atol, stretch + 1e-3 * atol):
        M = np.diag([factor, 1.0, 1.0])
        assert orthonormality_error(M) > atol
        text = message(lambda M=M: matrix_to_euler(M, atol=atol))
        measured, tolerance = re.search(r"= (\S+) exceeds the tolerance (\S+);", text).groups()
        assert float(tolerance) == atol, text
        assert Decimal(measured) > Decimal(tolerance), text


@pytest.mark.parametrize("scale", [1.01, 1.1])
def test_determinant_just_past_the_tolerance(scale: float) -> None:
    # s I is orthogonal within s² − 1, and its determinant s³ is off by more: a tolerance
    # between the two lets only the determinant break it
    M = scale * np.eye(3)
    off = abs(np.linalg.det(M) - 1.0)
    for atol in (off * (1 - 1e-12), off * (1 - 1e-9), off * 0.99):
        assert np.abs(M @ M.T - np.eye(3)).max() <= atol < off
        text = message(lambda M=M, atol=atol: matrix_to_euler(M, atol=atol))
        determinant, by, tolerance = re.search(
            r"has determinant (\S+), which differs from 1 by (\S+), more than the tolerance "
            r"(\S+)$",
            text,
        ).groups()
        assert float(tolerance) == atol, text
        assert abs(Decimal(determinant) - 1) > Decimal(tolerance), text
        assert Decimal(by) > Decimal(tolerance), text


def test_repair_just_past_its_limit() -> None:
    first = 1.0 + REPAIR_LIMIT
    while not np.linalg.svd(np.diag([first, 1.0, 1.0]), compute_uv=False)[0] - 1.0 > REPAIR_LIMIT:
        first = np.nextafter(first, 2.0)
    for value in (first, first + 1e-12, first + 1e-6):
        M = np.diag([value, 1.0, 1.0])
        text = message(lambda M=M: nearest_rotation(M))
        values, by, limit = re.search(
            r"its singular values \((.*)\) differ from 1 by up to (\S+), more than (\S+);", text
        ).groups()
        assert float(limit) == REPAIR_LIMIT, text
        assert Decimal(by) > Decimal(limit), text
        assert max(abs(Decimal(s) - 1) for s in values.split(", ")) > Decimal(limit), text
