"""The numeric quaternions and axis–angle agree with the symbolic algebra of eulerlib.symbolic.

The symbolic functions derive the matrices another way (the sandwich ``q v q*``, Rodrigues'
construction from the parts along and across the axis) and compute exactly, so for integer
quaternions and exact angles the float results must be the exact values to about an ulp.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from eulerlib import axis_angle_to_matrix, matrix_to_quaternion, quaternion_to_matrix
from eulerlib.symbolic import quaternion_from_axis_angle, rodrigues_matrix
from eulerlib.symbolic import quaternion_to_matrix as sandwich_matrix

EPS = float(np.finfo(np.float64).eps)


@pytest.mark.parametrize(
    "q", [(1, 2, 3, 4), (0, 1, 1, 0), (1, 0, 0, 1), (-5, 1, 0, 2), (0, 0, 0, 7), (9, -1, 4, 4)]
)
def test_quaternion_to_matrix_is_the_sandwich_over_the_squared_length(q) -> None:
    """For a quaternion that is not unit, the sandwich gives |q|² times the rotation."""
    exact = sandwich_matrix(q) / sum(c * c for c in q)  # rational entries
    R = quaternion_to_matrix(np.array(q, dtype=float), scalar_first=True)
    error = max(abs(sp.Rational(R[i, j]) - exact[i, j]) for i in range(3) for j in range(3))
    assert error <= sp.Rational(EPS), q


@pytest.mark.parametrize(
    ("axis", "degrees"),
    [((1, 2, 2), 72), ((0, 0, 1), 90), ((2, -3, 6), 120), ((1, 1, 1), -200), ((4, 4, 7), 1e20)],
)
def test_axis_angle_to_matrix_is_rodrigues_construction(axis, degrees) -> None:
    length = sp.sqrt(sum(c * c for c in axis))
    unit = [sp.Integer(c) / length for c in axis]
    turns = sp.Rational(int(degrees) % 360) if degrees == int(degrees) else sp.Rational(degrees)
    exact = rodrigues_matrix(unit, sp.pi * turns / 180).evalf(50)
    R = axis_angle_to_matrix(np.array(axis, dtype=float), degrees, degrees=True)
    assert np.abs(R - np.array(exact, dtype=float)).max() <= 2 * EPS
    q = quaternion_from_axis_angle(unit, sp.pi * turns / 180)
    exact_q = np.array([sp.N(c, 50) for c in (q.x, q.y, q.z, q.w)], dtype=float)
    exact_q *= 1.0 if exact_q[3] > 0 else -1.0  # the canonical one of ±q (no half turn here)
    assert np.abs(matrix_to_quaternion(R) - exact_q).max() <= 2 * EPS
