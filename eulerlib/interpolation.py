"""Slerp: the shortest way from one rotation to another, at constant angular speed.

Interpolating rotations entry by entry, ``(1 − t) R0 + t R1``, leaves the rotations: halfway
between a turn and its opposite it gives a matrix that squashes space. Interpolating Euler
angles stays among rotations but takes a detour, at a speed that changes along the way, and
near gimbal lock a wild one. The rotations themselves have a natural straight line: turn from
``R0`` toward ``R1`` about the one axis that takes the first to the second.

With ``R0ᵀ R1`` a turn by θ about the unit axis ``n`` (Euler's rotation theorem,
:mod:`eulerlib.axis_angle`), spherical linear interpolation is

.. math::

    \\operatorname{slerp}(R_0, R_1; t) = R_0 \\, \\operatorname{Rot}(n, t θ),

the turn from ``R0`` by the fraction ``t`` of θ about ``n``. It starts at ``R0`` (t = 0), ends at
``R1`` (t = 1), and turns at the constant rate θ per unit of ``t``: equal steps in ``t`` are equal
angles. It is the geodesic, the shortest path on the space of rotations, for θ ≤ π. In
quaternions it is K. Shoemake's formula (1985), ``q(t) = (sin((1 − t) Ω) q0 + sin(t Ω) q1) /
sin Ω`` with ``cos Ω = q0 · q1`` and the sign of ``q1`` chosen so that ``q0 · q1 ≥ 0``: the
great-circle arc on the sphere of unit quaternions, along which the angle of rotation grows
twice as fast as the arc, ``θ = 2 Ω``.

eulerlib evaluates the first form: the axis and angle of ``R0ᵀ R1`` come from its canonical
quaternion, which always takes the short way (θ ≤ π), and ``Rot(n, t θ)`` is built in the
half-angle form. At t = 0 the result is ``R0`` exactly.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib import _compiled, _scalar
from eulerlib._blocks import BLOCK_SIZE, block_slices
from eulerlib._broadcast import block_part, broadcast_blocks, broadcast_shape, common_lead
from eulerlib._length_kernels import TINY, lengths
from eulerlib._quaternion_kernels import (
    entries_to_quaternions,
    product,
    quaternions_to_entries,
    transposed_product,
)
from eulerlib._scalar_kernels import slerp_entries
from eulerlib._validation import (
    ROTATION_ATOL,
    RotationCheck,
    _index_text,
    as_float_array,
    as_rotations,
    matrix_entries,
    rotation_check,
)

__all__ = ["slerp"]


def slerp(
    R0: ArrayLike,
    R1: ArrayLike,
    t: ArrayLike,
    *,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
) -> NDArray[np.float64]:
    """Rotations along the geodesic from ``R0`` to ``R1``, at the fractions ``t`` of the way.

    Parameters
    ----------
    R0, R1 : array_like, shape (..., 3, 3)
        The rotations at ``t = 0`` and at ``t = 1``.
    t : array_like, shape (...)
        Fractions of the way. Values outside [0, 1] extrapolate: the turn continues about the
        same axis at the same rate (``t = 2`` turns twice as far as ``t = 1``, ``t = -1`` as far
        the other way). The turn ``t θ`` is computed in floats and reduced modulo 2π with no
        further error, so a huge ``t`` gives the rotation by that float angle; where ``t θ``
        is above the largest float there is no such angle, and ``t`` is refused.
    validate, repair, atol
        As in :func:`eulerlib.matrix_to_euler`, for ``R0`` and ``R1``.

    Returns
    -------
    ndarray, shape (S, 3, 3)
        ``S`` is the broadcast of ``R0.shape[:-2]``, ``R1.shape[:-2]`` and ``t.shape``, by
        numpy's rules. So one pair of rotations and ``t`` of shape ``(k,)`` give ``(k, 3, 3)``;
        ``n`` pairs and one ``t`` give ``(n, 3, 3)``; ``n`` pairs and ``t`` of shape ``(k, 1)``
        give ``k`` rotations along each of the ``n`` paths, ``(k, n, 3, 3)``.

    Raises
    ------
    TypeError
        If an argument is not real numbers or a flag is not a bool.
    ValueError
        If a shape is wrong, the shapes do not broadcast, a value is not finite, ``R0`` or
        ``R1`` is not a rotation within ``atol`` (or cannot be repaired), or ``t`` times the
        angle from ``R0`` to ``R1`` is above the largest float (the message gives the index).

    Notes
    -----
    ``slerp(R0, R1, t) = R0 Rot(n, t θ)`` with ``(n, θ)`` the axis and angle of ``R0ᵀ R1``
    (θ in [0, π]): the geodesic, at constant angular speed, equal to SciPy's ``Slerp``. When
    ``R0`` and ``R1`` are exactly a half turn apart (θ = π) two geodesics are equally short, one
    about ``n`` and one about ``-n``; eulerlib turns about the axis that
    :func:`eulerlib.matrix_to_axis_angle` gives ``R0ᵀ R1``, the one whose first nonzero
    component is positive. Near a half turn the path is unique but depends sensitively on
    ``R0`` and ``R1``, as any geodesic does there.

    Examples
    --------
    >>> import numpy as np
    >>> from eulerlib import rot_z, rotation_angle
    >>> path = slerp(np.eye(3), rot_z(90, degrees=True), [0.0, 0.5, 1.0])
    >>> path.shape
    (3, 3, 3)
    >>> np.allclose(path[1], rot_z(45, degrees=True))
    True
    >>> rotation_angle(slerp(np.eye(3), rot_z(90, degrees=True), 2.0), degrees=True)
    array(180.)
    """
    check = rotation_check(validate, repair, atol)
    if _compiled.operations is not None and not check.repair:
        compiled = _compiled_slerp(R0, R1, t, check)
        if compiled is not None:
            return compiled
    one_first, one_t = _scalar.rotation(R0, check), _scalar.number(t)
    one_second = None if one_first is None else _scalar.rotation(R1, check)
    if one_first is not None and one_second is not None and one_t is not None:
        one_entries = slerp_entries(one_first, one_second, one_t)
        if one_entries is not None:  # one pair at one fraction, in Python floats
            return _scalar.as_array(one_entries, (3, 3))
    first = as_rotations(R0, "R0", check)
    second = as_rotations(R1, "R1", check)
    fractions = as_float_array(t, "t")
    lead0, lead1 = first.shape[:-2], second.shape[:-2]
    shape = broadcast_shape({"R0": lead0, "R1": lead1, "t": fractions.shape})
    flat0, flat1 = first.reshape(-1, 3, 3), second.reshape(-1, 3, 3)
    flat_t = fractions.reshape(-1)
    out = np.empty((math.prod(shape), 9))
    operands = (lead0, lead1, fractions.shape)
    # slerp holds about twice as many numbers per rotation as a conversion does (both ends, the
    # turn between them and the turn to make), so half a block keeps the same few MB in cache
    for block, (on0, on1, on_t) in broadcast_blocks(shape, operands, BLOCK_SIZE // 2):
        start = matrix_entries(flat0[on0])
        relative = entries_to_quaternions(transposed_product(start, matrix_entries(flat1[on1])))
        # R0ᵀ R1 turns by θ = 2 atan2(|v|, w) about v / |v|. The turn by t θ about the same axis
        # has a quaternion that is a multiple of (1, tan(t θ / 2) v / |v|).
        sine = lengths(relative[1:])
        with np.errstate(over="ignore"):
            half_turn = np.arctan2(sine, relative[0]) * flat_t[on_t]  # t θ / 2
        _refuse_overflow(half_turn, shape, block.start)
        tangent = np.tan(half_turn)
        step = np.empty_like(relative)
        step[0] = 1.0
        np.multiply(relative[1:], tangent / np.maximum(sine, TINY), out=step[1:])
        turn = np.empty_like(start)
        quaternions_to_entries(step, turn)
        product(start, turn, out[block].T)
        out[block] += 0.0  # no negative zeros
    return out.reshape(*shape, 3, 3)


def _compiled_slerp(
    R0: ArrayLike, R1: ArrayLike, t: ArrayLike, check: RotationCheck
) -> NDArray[np.float64] | None:
    """slerp in compiled stages around numpy's arctangent and tangent (the body of
    :func:`eulerlib._scalar_kernels.slerp_entries` for a whole batch), or None for what the
    kernels do not take: the paths of :func:`slerp` then give the result or the refusal."""
    kernels = _compiled.operations
    first, second = _compiled.batch(R0, (3, 3)), _compiled.batch(R1, (3, 3))
    if first is None or second is None:
        return None
    number = _scalar.number(t)
    fractions = number if number is not None else _compiled.batch(t, ())
    if fractions is None:
        return None
    t_shape = () if number is not None else np.shape(fractions)
    lead = common_lead((first.shape[:-2], second.shape[:-2], t_shape))
    if lead is None:
        return None
    count = math.prod(lead)
    flat0, flat1 = first.reshape(-1, 3, 3), second.reshape(-1, 3, 3)
    flat_t = np.array([number]) if number is not None else np.reshape(fractions, -1)
    out = np.empty((*lead, 3, 3))
    flat_out = out.reshape(-1, 3, 3)
    size = min(count, BLOCK_SIZE)  # what the stages hold between them: one block
    relative_rows, sine_rows = np.empty((size, 4)), np.empty(size)
    for block in block_slices(count):
        size = block.stop - block.start
        relative, sine = relative_rows[:size], sine_rows[:size]
        start = block_part(flat0, block)
        end = block_part(flat1, block)
        if not kernels.slerp_relative(relative, sine, start, end, check.validate, check.atol):
            return None
        half_turn = np.arctan2(sine, relative[:, 0])
        if not kernels.slerp_half_turns(half_turn, block_part(flat_t, block)):
            return None  # t θ / 2 is not a number: refused by the array path
        if not kernels.slerp_turn(flat_out[block], start, relative, sine, np.tan(half_turn)):
            return None
    return out


def _refuse_overflow(half_turn: NDArray[np.float64], shape: tuple[int, ...], offset: int) -> None:
    """Raise ``ValueError`` if some ``t θ / 2`` of a block overflowed to infinity.

    ``offset`` is the flat index of the block's first rotation in the result of ``shape``.
    """
    if not half_turn.size or np.isfinite(np.max(np.abs(half_turn))):
        return
    infinite = np.flatnonzero(np.isinf(half_turn))
    if not infinite.size:  # NaN only: unchecked ends (validate=False) far from any rotation
        return
    first = int(infinite[0])
    raise ValueError(
        f"t{_index_text(shape, offset + first)} times the angle from R0 to R1 is above the "
        "largest float (about 1.8e308): the turn to make is not a number"
    )
