"""Rotation matrices as SymPy expressions: the derivations behind the numeric library.

Every formula that :mod:`eulerlib` evaluates with numbers can be *derived* here with symbols,
so that a notebook can show where it comes from and a test can assert that the numbers agree
with the algebra.

The idea in four steps
----------------------
1. **An elementary rotation is known by where it sends the basis vectors.** Turning a vector
   ``v`` by θ about a unit axis ``k`` (right-hand rule: thumb along ``k``, fingers curl the way
   the turn goes) keeps the part of ``v`` along ``k`` and turns the rest in the plane
   perpendicular to ``k``:

   .. math:: R v = (k \\cdot v)\\,k + \\cos θ\\,(v - (k \\cdot v)\\,k) + \\sin θ\\,(k \\times v).

   Column ``j`` of the matrix is the image of the basis vector ``e_j``.
   :func:`elementary_matrix` builds ``R_x``, ``R_y`` and ``R_z`` column by column in exactly
   this way, instead of typing the three matrices in.
2. **A convention is a product of three elementary rotations.** For an intrinsic (uppercase)
   sequence such as ``"ZYX"`` with angles ``(α, β, γ)`` the matrix is ``R_z(α) R_y(β) R_x(γ)``:
   the product is written in the order in which the rotations about the *moving* axes happen.
   An extrinsic (lowercase) sequence turns about *fixed* axes and the product is reversed:
   ``"zyx"`` gives ``R_x(γ) R_y(β) R_z(α)``. :func:`euler_matrix` does this for all 24
   sequences, with the same ``seq`` strings as :func:`eulerlib.euler_to_matrix` and SciPy's
   ``Rotation.from_euler``. With Rose's yaw ``w``, pitch ``v`` and roll ``u``,
   ``euler_matrix("ZYX", (w, v, u))`` is Rose (2015), Part 2, eq 2; with Baker's heading,
   attitude and bank, ``euler_matrix("YZX", (h, a, b))`` is the matrix of Baker's
   "Matrix to Euler" page.
3. **Reading the angles back.** One entry of the matrix depends on the middle angle alone
   (``±sin β`` for Tait–Bryan sequences, ``cos β`` for proper Euler sequences); two entries in
   its row and two in its column are a common factor times the sine and cosine of the first or
   of the third angle. :func:`extraction_relations` finds those entries in the symbolic matrix
   and states the ``atan2`` formulas they give (Rose, eq 3; Baker's three formulas).
4. **Gimbal lock.** When the common factor (``cos β`` or ``sin β``) vanishes the first and
   third axes coincide and the matrix depends on a single combination of the outer angles
   (Rose, eq 4): :func:`gimbal_lock_matrix` writes it in that form. The same factor is the
   determinant of the map from angle rates to angular velocity,
   :func:`angular_velocity_jacobian` and :func:`jacobian_determinant`: at lock one direction of
   angular velocity cannot be produced by any angle rates.

This module imports SymPy, so :mod:`eulerlib` does not import it; use
``from eulerlib import symbolic`` or ``import eulerlib.symbolic``.

Examples
--------
>>> import sympy as sp
>>> from eulerlib.symbolic import euler_matrix
>>> w, v, u = sp.symbols("w v u", real=True)   # yaw, pitch, roll
>>> R = euler_matrix("ZYX", (w, v, u))
>>> R[:, 0].T    # where the body's x axis (the nose) points
Matrix([[cos(v)*cos(w), sin(w)*cos(v), -sin(v)]])
"""

from __future__ import annotations

from collections.abc import Sequence as SequenceABC
from typing import Any, NamedTuple

import sympy as sp

from eulerlib.sequences import Sequence, parse_sequence

__all__ = [
    "ExtractionRelations",
    "angular_velocity_jacobian",
    "elementary_matrix",
    "euler_matrix",
    "euler_symbols",
    "extraction_relations",
    "gimbal_lock_matrix",
    "jacobian_determinant",
]

_AXIS_NAMES = {"x": 0, "y": 1, "z": 2, 0: 0, 1: 1, 2: 2}


def _axis_index(axis: object) -> int:
    key = axis.lower() if isinstance(axis, str) else axis
    if not isinstance(key, (str, int)) or isinstance(key, bool) or key not in _AXIS_NAMES:
        raise ValueError(f"axis must be 'x', 'y', 'z' or 0, 1, 2, got {axis!r}")
    return _AXIS_NAMES[key]


def _basis(index: int) -> Any:
    return sp.Matrix([1 if i == index else 0 for i in range(3)])


def elementary_matrix(axis: str | int, angle: Any) -> Any:
    """Active right-handed rotation by ``angle`` about a coordinate axis, as a SymPy matrix.

    The matrix is derived, not typed in: column ``j`` is the image of the basis vector ``e_j``
    under a right-handed turn about the axis ``k``, namely
    ``(k·e_j) k + cos θ (e_j − (k·e_j) k) + sin θ (k × e_j)``.

    Parameters
    ----------
    axis : {'x', 'y', 'z', 0, 1, 2}
        The axis to turn about (letters in either case).
    angle : sympy expression or number
        The angle in radians; a symbol, an expression, or an exact number such as ``sp.pi/2``.

    Returns
    -------
    sympy.Matrix, shape (3, 3)
        ``R`` such that ``R * v`` is the column vector ``v`` turned by ``angle``.

    Raises
    ------
    ValueError
        If ``axis`` is not one of the accepted values.
    sympy.SympifyError
        If ``angle`` cannot be read by SymPy.

    Examples
    --------
    >>> import sympy as sp
    >>> t = sp.Symbol("theta", real=True)
    >>> elementary_matrix("z", t)
    Matrix([
    [cos(theta), -sin(theta), 0],
    [sin(theta),  cos(theta), 0],
    [         0,           0, 1]])
    >>> elementary_matrix("x", sp.pi / 2) * sp.Matrix([0, 1, 0])   # y turns into z
    Matrix([
    [0],
    [0],
    [1]])
    """
    index = _axis_index(axis)
    theta = sp.sympify(angle)
    k = _basis(index)
    columns = []
    for j in range(3):
        e = _basis(j)
        along = k.dot(e) * k
        image = along + sp.cos(theta) * (e - along) + sp.sin(theta) * k.cross(e)
        columns.append(image.applyfunc(sp.expand))
    return sp.Matrix.hstack(*columns)


def euler_symbols(seq: str) -> tuple[Any, Any, Any]:
    """Default symbols for the three angles of a sequence: ``alpha``, ``beta``, ``gamma``.

    ``alpha`` goes with the first letter of ``seq``, ``beta`` with the middle letter and
    ``gamma`` with the third, whatever the axes are and whether the sequence is intrinsic or
    extrinsic (so ``beta`` is always the angle that decides gimbal lock). The symbols are real,
    which lets SymPy simplify ``sqrt(cos(beta)**2)`` to ``Abs(cos(beta))``.

    Parameters
    ----------
    seq : str
        One of the 24 axis sequences (checked).

    Returns
    -------
    tuple of sympy.Symbol
        ``(alpha, beta, gamma)``.

    Raises
    ------
    TypeError, ValueError
        If ``seq`` is not a valid sequence.

    Examples
    --------
    >>> euler_symbols("ZYX")
    (alpha, beta, gamma)
    >>> euler_symbols("ZYX")[1].is_real
    True
    """
    parse_sequence(seq)
    alpha, beta, gamma = sp.symbols("alpha beta gamma", real=True)
    return alpha, beta, gamma


def _angles(seq: str, angles: SequenceABC[Any] | None) -> tuple[Sequence, tuple[Any, Any, Any]]:
    parsed = parse_sequence(seq)
    if angles is None:
        return parsed, euler_symbols(seq)
    if isinstance(angles, (str, bytes)) or not isinstance(angles, SequenceABC):
        raise TypeError(
            f"angles must be a sequence of three SymPy expressions or numbers, got "
            f"{type(angles).__name__}"
        )
    if len(angles) != 3:
        raise ValueError(f"angles must hold exactly 3 angles, got {len(angles)}")
    a, b, c = (sp.sympify(angle) for angle in angles)
    return parsed, (a, b, c)


def euler_matrix(seq: str, angles: SequenceABC[Any] | None = None) -> Any:
    """The rotation matrix of an Euler-angle sequence, as a product of elementary rotations.

    Parameters
    ----------
    seq : str
        One of the 24 axis sequences, read as in :func:`eulerlib.euler_to_matrix` and SciPy's
        ``Rotation.from_euler``: uppercase intrinsic (moving axes), lowercase extrinsic (fixed
        axes), angle ``i`` with letter ``i``.
    angles : sequence of 3 sympy expressions or numbers, optional
        The angles in radians. Default: :func:`euler_symbols` (``alpha``, ``beta``, ``gamma``).

    Returns
    -------
    sympy.Matrix, shape (3, 3)
        For an intrinsic sequence ``"ABC"`` and angles ``(a, b, c)``: ``R_A(a) R_B(b) R_C(c)``;
        for an extrinsic sequence ``"abc"``: ``R_C(c) R_B(b) R_A(a)``. The product is multiplied
        out but not simplified further.

    Raises
    ------
    TypeError, ValueError
        If ``seq`` is invalid, or ``angles`` is not three values.

    Notes
    -----
    ``euler_matrix("ZYX", (w, v, u))`` with yaw ``w``, pitch ``v`` and roll ``u`` is
    Rose (2015), Part 2, eq 2. ``euler_matrix("YZX", (h, a, b))`` with heading, attitude and
    bank is the matrix of Baker, "Matrix to Euler" (y up).

    Examples
    --------
    >>> import sympy as sp
    >>> euler_matrix("ZYX", (sp.pi / 2, 0, 0))   # yaw 90°: x turns into y
    Matrix([
    [0, -1, 0],
    [1,  0, 0],
    [0,  0, 1]])
    >>> a, b, c = euler_symbols("ZYX")
    >>> euler_matrix("ZYX") == euler_matrix("xyz", (c, b, a))   # same rotation, fixed axes
    True
    """
    parsed, values = _angles(seq, angles)
    factors = [
        elementary_matrix(axis, angle) for axis, angle in zip(parsed.axes, values, strict=True)
    ]
    if not parsed.intrinsic:
        factors.reverse()
    product = factors[0] * factors[1] * factors[2]
    return product.applyfunc(sp.expand)


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


def angular_velocity_jacobian(
    seq: str, angles: SequenceABC[Any] | None = None, frame: str = "body"
) -> Any:
    """The matrix that turns angle rates into angular velocity.

    If the angles change at rates ``(α̇, β̇, γ̇)`` (in the order of ``seq``), the rotation
    ``R(t) = euler_matrix(seq, angles(t))`` turns with angular velocity ``ω = J (α̇, β̇, γ̇)``,
    that is ``Ṙ Rᵀ = [ω]×`` in the fixed (space) frame, or ``Rᵀ Ṙ = [ω]×`` in the body frame.

    Parameters
    ----------
    seq : str
        One of the 24 axis sequences.
    angles : sequence of 3 sympy expressions, optional
        Default :func:`euler_symbols`.
    frame : {'body', 'space'}, optional
        Express ``ω`` in the rotating body's axes (default) or in the fixed axes.

    Returns
    -------
    sympy.Matrix, shape (3, 3)
        Column ``i`` is the unit axis of rotation ``i`` of ``seq``, as it lies when that
        rotation happens, expressed in the requested frame.

    Raises
    ------
    TypeError, ValueError
        If ``seq``, ``angles`` or ``frame`` are invalid.

    Notes
    -----
    For the intrinsic form ``R = A(a) B(b) C(c)`` (axes ``e_A``, ``e_B``, ``e_C``) the space-frame
    angular velocity is ``ȧ e_A + ḃ A e_B + ċ A B e_C``: each rate turns about its axis as
    moved by the rotations before it. The body-frame one is ``Rᵀ`` times that,
    ``ȧ Cᵀ Bᵀ e_A + ḃ Cᵀ e_B + ċ e_C``. An extrinsic sequence is the intrinsic one with the angles
    reversed, so its columns are the same, in reversed order.

    Examples
    --------
    >>> import sympy as sp
    >>> w, v, u = sp.symbols("w v u", real=True)
    >>> angular_velocity_jacobian("ZYX", (w, v, u))    # body rates (p, q, r) of an aircraft
    Matrix([
    [       -sin(v),       0, 1],
    [sin(u)*cos(v),  cos(u), 0],
    [cos(u)*cos(v), -sin(u), 0]])
    """
    parsed, values = _angles(seq, angles)
    if frame not in ("body", "space"):
        raise ValueError(f"frame must be 'body' or 'space', got {frame!r}")
    axes = parsed.intrinsic_axes
    intrinsic_values = values if parsed.intrinsic else values[::-1]
    A, B, C = (
        elementary_matrix(axis, angle) for axis, angle in zip(axes, intrinsic_values, strict=True)
    )
    e = [_basis(axis) for axis in axes]
    if frame == "space":
        columns = [e[0], A * e[1], A * B * e[2]]
    else:
        columns = [C.T * B.T * e[0], C.T * e[1], e[2]]
    if not parsed.intrinsic:
        columns.reverse()
    return sp.Matrix.hstack(*columns).applyfunc(sp.expand)


def jacobian_determinant(
    seq: str, angles: SequenceABC[Any] | None = None, frame: str = "body"
) -> Any:
    """Determinant of :func:`angular_velocity_jacobian`, simplified.

    Parameters
    ----------
    seq : str
        One of the 24 axis sequences.
    angles : sequence of 3 sympy expressions, optional
        Default :func:`euler_symbols`.
    frame : {'body', 'space'}, optional
        Either frame gives the same determinant, since the two Jacobians differ by a rotation.

    Returns
    -------
    sympy expression
        ``±cos(middle)`` for a Tait–Bryan sequence, ``±sin(middle)`` for a proper Euler one:
        zero exactly at gimbal lock, where the three rates can no longer produce every angular
        velocity.

    Examples
    --------
    >>> import sympy as sp
    >>> w, v, u = sp.symbols("w v u", real=True)
    >>> jacobian_determinant("ZYX", (w, v, u))
    -cos(v)
    >>> jacobian_determinant("ZXZ")
    -sin(beta)
    """
    J = angular_velocity_jacobian(seq, angles, frame)
    return sp.factor(sp.trigsimp(sp.expand(J.det())))
