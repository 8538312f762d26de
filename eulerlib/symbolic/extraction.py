"""Reading the angles back: which entries of the matrix give each angle, found in the algebra.

One entry of an Euler-angle matrix depends on the middle angle alone (``±sin β`` for
Tait–Bryan sequences, ``cos β`` for proper Euler sequences); two entries in its row and two in
its column are a common factor times the sine and cosine of the first or of the third angle.
:func:`extraction_relations` finds those entries in the symbolic matrix, by the symbols they
contain, and states the ``atan2`` formulas they give (Rose 2015, Part 2, eq 3; Baker's three
formulas), valid wherever the common factor is positive.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import sympy as sp

from eulerlib.conventions import Convention, get_convention
from eulerlib.symbolic._arguments import as_distinct_symbols
from eulerlib.symbolic.euler import euler_product, refuse_convention_first

__all__ = ["ExtractionRelations", "extraction_relations"]


class ExtractionRelations(NamedTuple):
    """Which entries of a sequence's matrix give back its three angles.

    Indices are 0-based ``(row, column)`` pairs; Rose's ``r31`` is ``(2, 0)``.

    Attributes
    ----------
    seq : str
        The axis sequence (of the preset, when one was given).
    angles : tuple of sympy expressions
        The angle symbols ``(first, middle, third)`` used in the expressions below.
    matrix : sympy.Matrix
        ``euler_matrix(angles, seq)``.
    middle_entry : tuple of int
        The one entry that depends on the middle angle alone.
    middle_value : sympy expression
        Its value: ``±sin(middle)`` (Tait–Bryan) or ``cos(middle)`` (proper Euler).
    scale : sympy expression
        The factor shared by the four entries below: ``cos(middle)`` (Tait–Bryan) or
        ``sin(middle)`` (proper Euler). It vanishes at gimbal lock.
    first_entries, third_entries : tuple of two index pairs
        ``(sine entry, cosine entry)`` of the first and of the third angle: the matrix holds
        ``±scale·sin`` and ``±scale·cos`` of that angle there.
    first_values, third_values : tuple of two sympy expressions
        The values of those entries.
    formulas : tuple of three sympy expressions
        The angles as ``atan2`` formulas in the entries of the matrix symbol ``R`` (a
        ``sympy.MatrixSymbol``), valid whenever ``scale > 0``, which is the range of the middle
        angle eulerlib returns: ``[-π/2, π/2]`` (Tait–Bryan) or ``[0, π]`` (proper Euler). Use
        ``sympy.lambdify(R, formula)`` to evaluate one on a numeric matrix.

    Examples
    --------
    >>> import numpy as np, sympy as sp
    >>> from eulerlib import euler_to_matrix
    >>> rel = extraction_relations(sp.symbols("w v u", real=True), "ZYX")
    >>> rel.scale
    cos(v)
    >>> yaw = sp.lambdify(sp.MatrixSymbol("R", 3, 3), rel.formulas[0])
    >>> round(float(np.degrees(yaw(euler_to_matrix([30, 20, 10], "ZYX", degrees=True)))), 9)
    30.0
    """

    seq: str
    angles: tuple[Any, Any, Any]
    matrix: Any
    middle_entry: tuple[int, int]
    middle_value: Any
    scale: Any
    first_entries: tuple[tuple[int, int], tuple[int, int]]
    first_values: tuple[Any, Any]
    third_entries: tuple[tuple[int, int], tuple[int, int]]
    third_values: tuple[Any, Any]
    formulas: tuple[Any, Any, Any]


def _entries_with(matrix: Any, symbols: set[Any]) -> list[tuple[int, int]]:
    """Entries whose free symbols are exactly ``symbols``, in row-major order."""
    return [(r, c) for r in range(3) for c in range(3) if matrix[r, c].free_symbols == symbols]


def _sine_cosine(
    matrix: Any, entries: list[tuple[int, int]], angle: Any, scale: Any
) -> tuple[tuple[tuple[int, int], tuple[int, int]], tuple[int, int]]:
    """Order two entries as (sine entry, cosine entry) of ``angle`` and return their signs."""
    if len(entries) != 2:  # pragma: no cover - impossible for a valid sequence
        raise AssertionError(f"expected two entries for {angle}, found {entries}")
    first, second = entries
    if sp.simplify(matrix[first].subs(angle, 0)) != 0:
        first, second = second, first
    sine_sign = sp.simplify(matrix[first] / (scale * sp.sin(angle)))
    cosine_sign = sp.simplify(matrix[second] / (scale * sp.cos(angle)))
    if sine_sign not in (1, -1) or cosine_sign not in (1, -1):  # pragma: no cover
        raise AssertionError(f"entries {entries} are not ±scale·sin, ±scale·cos of {angle}")
    return (first, second), (int(sine_sign), int(cosine_sign))


def extraction_relations(angles: Any, seq: str | Convention) -> ExtractionRelations:
    """Find the entries of the symbolic matrix that give back each angle, and the formulas.

    The relations are read off the symbolic matrix itself: the middle entry is the only one
    whose value involves the middle angle alone; the first angle's two entries are the ones
    that involve only the first and middle angles, and likewise for the third angle.

    Parameters
    ----------
    angles : sequence of 3 sympy.Symbol
        Three distinct symbols for the angles, in the order of the letters of ``seq``, for
        example ``sp.symbols("w v u", real=True)`` or :func:`euler_symbols`.
    seq : str or Convention
        One of the 24 axis sequences, or a preset such as ``"rose"``.

    Returns
    -------
    ExtractionRelations
        Entries, their values, and ``atan2`` formulas for the three angles.

    Raises
    ------
    TypeError, ValueError
        If ``seq`` is neither a sequence nor a preset, or ``angles`` are not three distinct
        symbols.

    Notes
    -----
    For ``"ZYX"`` with yaw ``w``, pitch ``v`` and roll ``u`` these are Rose (2015), Part 2,
    eq 3: ``r31 = −sin v``, ``tan w = r21 / r11`` and ``tan u = r32 / r33``. For ``"YZX"`` they
    are Baker's three formulas for heading, attitude and bank.

    Examples
    --------
    >>> import sympy as sp
    >>> w, v, u = sp.symbols("w v u", real=True)
    >>> rel = extraction_relations((w, v, u), "ZYX")
    >>> rel.middle_entry, rel.middle_value
    ((2, 0), -sin(v))
    >>> rel.first_entries, rel.first_values
    (((1, 0), (0, 0)), (sin(w)*cos(v), cos(v)*cos(w)))
    >>> for formula in rel.formulas:   # yaw, pitch, roll
    ...     print(formula)
    atan2(R[1, 0], R[0, 0])
    atan2(-R[2, 0], sqrt(R[2, 1]**2 + R[2, 2]**2))
    atan2(R[2, 1], R[2, 2])
    """
    refuse_convention_first(angles)
    parsed = get_convention(seq).parsed
    a, b, c = as_distinct_symbols(angles, "angles", 3)
    M = euler_product(parsed, (a, b, c))
    (middle_entry,) = _entries_with(M, {b})
    middle_value = M[middle_entry]
    scale = sp.sin(b) if parsed.proper else sp.cos(b)
    first_entries, first_signs = _sine_cosine(M, _entries_with(M, {a, b}), a, scale)
    third_entries, third_signs = _sine_cosine(M, _entries_with(M, {b, c}), c, scale)

    R = sp.MatrixSymbol("R", 3, 3)

    def atan2(entries: tuple[tuple[int, int], tuple[int, int]], signs: tuple[int, int]) -> Any:
        (ys, xs), (sy, sx) = entries, signs
        return sp.atan2(sy * R[ys], sx * R[xs])

    hypot = sp.sqrt(R[third_entries[0]] ** 2 + R[third_entries[1]] ** 2)
    if parsed.proper:
        middle_formula = sp.atan2(hypot, R[middle_entry])
    else:
        middle_sign = 1 if middle_value == sp.sin(b) else -1
        middle_formula = sp.atan2(middle_sign * R[middle_entry], hypot)
    return ExtractionRelations(
        seq=parsed.seq,
        angles=(a, b, c),
        matrix=M,
        middle_entry=middle_entry,
        middle_value=middle_value,
        scale=scale,
        first_entries=first_entries,
        first_values=(M[first_entries[0]], M[first_entries[1]]),
        third_entries=third_entries,
        third_values=(M[third_entries[0]], M[third_entries[1]]),
        formulas=(
            atan2(first_entries, first_signs),
            middle_formula,
            atan2(third_entries, third_signs),
        ),
    )
