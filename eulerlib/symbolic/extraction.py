"""Which entries of a matrix give back the angles, read off the symbolic matrix."""

from __future__ import annotations

from collections.abc import Sequence as SequenceABC
from typing import Any, NamedTuple

import sympy as sp

from eulerlib.symbolic.euler import _angles, euler_matrix


class ExtractionRelations(NamedTuple):
    """Which entries of a sequence's matrix give back its three angles.

    Indices are 0-based ``(row, column)`` pairs; Rose's ``r31`` is ``(2, 0)``.

    Attributes
    ----------
    seq : str
        The sequence.
    angles : tuple of sympy expressions
        The angle symbols ``(first, middle, third)`` used in the expressions below.
    matrix : sympy.Matrix
        ``euler_matrix(seq, angles)``.
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


def extraction_relations(seq: str, angles: SequenceABC[Any] | None = None) -> ExtractionRelations:
    """Find the entries of the symbolic matrix that give back each angle, and the formulas.

    The relations are read off the symbolic matrix itself: the middle entry is the only one
    whose value involves the middle angle alone; the first angle's two entries are the ones
    that involve only the first and middle angles, and likewise for the third angle.

    Parameters
    ----------
    seq : str
        One of the 24 axis sequences.
    angles : sequence of 3 sympy symbols, optional
        Symbols for the angles (they must be three distinct symbols). Default
        :func:`euler_symbols`.

    Returns
    -------
    ExtractionRelations
        Entries, their values, and ``atan2`` formulas for the three angles.

    Raises
    ------
    TypeError, ValueError
        If ``seq`` is invalid or ``angles`` are not three distinct symbols.

    Notes
    -----
    For ``"ZYX"`` with yaw ``w``, pitch ``v`` and roll ``u`` these are Rose (2015), Part 2,
    eq 3: ``r31 = −sin v``, ``tan w = r21 / r11`` and ``tan u = r32 / r33``. For ``"YZX"`` they
    are Baker's three formulas for heading, attitude and bank.

    Examples
    --------
    >>> import sympy as sp
    >>> w, v, u = sp.symbols("w v u", real=True)
    >>> rel = extraction_relations("ZYX", (w, v, u))
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
    parsed, (a, b, c) = _angles(seq, angles)
    if not all(isinstance(s, sp.Symbol) for s in (a, b, c)) or len({a, b, c}) != 3:
        raise ValueError(f"angles must be three distinct SymPy symbols, got {(a, b, c)}")
    M = euler_matrix(seq, (a, b, c))
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
        seq=seq,
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
