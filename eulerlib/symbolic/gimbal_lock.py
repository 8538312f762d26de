"""The matrix at gimbal lock, written with the one combination of outer angles it keeps."""

from __future__ import annotations

from collections.abc import Sequence as SequenceABC
from typing import Any

import sympy as sp

from eulerlib.sequences import Sequence
from eulerlib.symbolic.euler import _angles, euler_matrix


def _singular_middle(parsed: Sequence, middle: Any) -> Any:
    value = sp.sympify(middle)
    if parsed.proper:
        choices = {1: 0, -1: sp.pi, 0: 0, sp.pi: sp.pi}
        expected = "1 or 0 (middle angle 0), -1 or pi (middle angle pi)"
    else:
        choices = {1: sp.pi / 2, -1: -sp.pi / 2, sp.pi / 2: sp.pi / 2, -sp.pi / 2: -sp.pi / 2}
        expected = "1 or pi/2 (middle angle +90°), -1 or -pi/2 (middle angle -90°)"
    for key, angle in choices.items():
        if sp.simplify(value - key) == 0:
            return angle
    kind = "proper Euler" if parsed.proper else "Tait–Bryan"
    raise ValueError(
        f"middle must name a singular middle angle of the {kind} sequence {parsed.seq!r}: "
        f"{expected}; got {middle!r}"
    )


def gimbal_lock_matrix(seq: str, middle: Any = 1, angles: SequenceABC[Any] | None = None) -> Any:
    """The matrix at gimbal lock, written with the one combination of outer angles it depends on.

    Parameters
    ----------
    seq : str
        One of the 24 axis sequences.
    middle : {1, -1} or the singular angle itself, optional
        Which singular middle angle: for a Tait–Bryan sequence ``1`` (or ``pi/2``) means +90°
        and ``-1`` (or ``-pi/2``) means −90°; for a proper Euler sequence ``1`` (or ``0``)
        means 0 and ``-1`` (or ``pi``) means 180°. In both cases ``middle = ±1`` is the value
        of the middle entry's sine (Tait–Bryan) or cosine (proper Euler). Default ``1``.
    angles : sequence of 3 sympy expressions, optional
        Angle symbols; the middle one is replaced by the singular value. Default
        :func:`euler_symbols`.

    Returns
    -------
    sympy.Matrix, shape (3, 3)
        The matrix, whose entries involve the outer angles only through one sum or difference
        (for example ``sin(u - w)`` for ``"ZYX"`` at pitch +90°, Rose (2015), Part 2, eq 4).

    Raises
    ------
    TypeError, ValueError
        If ``seq`` or ``angles`` are invalid, or ``middle`` is not a singular value.

    Notes
    -----
    At lock the first and third rotations turn about the same line, so the matrix equals the
    one with the first angle of the intrinsic form set to 0 and the other outer angle replaced
    by the combination (eulerlib's lock policy). The combination's sign is found by comparing
    the two candidates, ``third + first`` and ``third − first``, with the substituted matrix
    after expanding the trigonometric functions of the sums, and is then checked exactly.

    Examples
    --------
    >>> import sympy as sp
    >>> w, v, u = sp.symbols("w v u", real=True)
    >>> gimbal_lock_matrix("ZYX", 1, (w, v, u))
    Matrix([
    [ 0, sin(u - w),  cos(u - w)],
    [ 0, cos(u - w), -sin(u - w)],
    [-1,          0,           0]])
    """
    parsed, (a, _, c) = _angles(seq, angles)
    singular = _singular_middle(parsed, middle)
    locked = euler_matrix(seq, (a, singular, c))
    # the first angle of the intrinsic form is a for intrinsic sequences, c for extrinsic ones
    zeroed, carrier = (a, c) if parsed.intrinsic else (c, a)
    for combination in (carrier - zeroed, carrier + zeroed):
        values = (0, singular, combination) if parsed.intrinsic else (combination, singular, 0)
        candidate = euler_matrix(seq, values)
        difference = (candidate - locked).applyfunc(lambda e: sp.expand(sp.expand_trig(e)))
        if difference.is_zero_matrix:
            return candidate
    raise AssertionError(  # pragma: no cover - at lock one of the two always matches
        f"no sum or difference form found for {seq!r} at middle angle {singular}"
    )
