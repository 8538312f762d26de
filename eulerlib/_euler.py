"""The bodies of the Euler-angle conversions, for checked arguments, shared by every path.

:func:`eulerlib.euler_to_matrix` and :func:`eulerlib.matrix_to_euler` check their arguments
and call these; the named-angle functions and the quaternion conversions call them too, so
that the lock policy and its warning are applied in one place, for all of them.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Iterator
from typing import Any

import numpy as np
from numpy.typing import NDArray

from eulerlib import _compiled
from eulerlib._blocks import BLOCK_SIZE, block_slices
from eulerlib._conventions import Convention
from eulerlib._euler_kernels import fill_matrices, frame, intrinsic_angles
from eulerlib._lock import GIMBAL_LOCK_TOLERANCE, warn_if_locked
from eulerlib._scalar import as_array, degrees_of, rotation
from eulerlib._scalar_kernels import Nine
from eulerlib._scalar_kernels import intrinsic_angles as one_intrinsic
from eulerlib._validation import RotationCheck, rotation_entry_blocks


def angles_to_matrices(
    values: NDArray[np.float64], convention: Convention, degrees: bool
) -> NDArray[np.float64]:
    """Body of :func:`euler_to_matrix` for checked angles of shape ``(..., 3)``."""
    parsed = convention.parsed
    flat = convention.to_intrinsic(values.reshape(-1, 3))
    R = np.empty((flat.shape[0], 3, 3))
    for block in block_slices(flat.shape[0]):
        fill_matrices(R[block], flat[block], parsed, degrees)
    return R.reshape(*values.shape[:-1], 3, 3)


def matrices_to_angles(
    matrices: NDArray[np.float64],
    convention: Convention,
    check: RotationCheck,
    degrees: bool,
    warn: bool,
) -> NDArray[np.float64]:
    """Body of :func:`matrix_to_euler` for a stack of matrices ``(..., 3, 3)`` to be checked."""
    blocks = rotation_entry_blocks(matrices, "R", check)
    return entry_blocks_to_angles(blocks, matrices.shape[:-2], convention, degrees, warn)


def entry_blocks_to_angles(
    blocks: Iterable[tuple[slice, NDArray[np.float64]]],
    lead: tuple[int, ...],
    convention: Convention,
    degrees: bool,
    warn: bool,
) -> NDArray[np.float64]:
    """Euler angles, shape ``(*lead, 3)``, of rotations given block by block.

    ``blocks`` yields ``(block, entries)`` as :func:`eulerlib._validation.rotation_entry_blocks`
    does, for rotation matrices or for anything turned into their entries block by block (such
    as quaternions); the lock policy and the warning are applied here, for both.
    """
    parsed = convention.parsed
    count = math.prod(lead)
    angles, locked = np.empty((count, 3)), np.empty(count, dtype=bool)
    # the kernels give the intrinsic order; write it through a view of the result in that
    # order (reversed for an extrinsic sequence), so the result is in argument order in place
    intrinsic = convention.to_intrinsic(angles)
    zero_first = convention.zeroes_intrinsic_first
    for block, entries in blocks:
        intrinsic[block], locked[block] = intrinsic_angles(
            entries, parsed, zero_first, GIMBAL_LOCK_TOLERANCE
        )
    if warn:
        warn_if_locked(convention, locked, angles[:, 1])  # the middle angle either way
    if degrees:
        np.degrees(angles, out=angles)
    return angles.reshape(*lead, 3)


def entries_to_angles(
    entries: Nine, convention: Convention, degrees: bool
) -> NDArray[np.float64] | None:
    """Euler angles, shape ``(3,)``, of one checked rotation given by its nine entries, in
    Python floats; None at gimbal lock, where the array path applies the policy and warns."""
    angles = one_intrinsic(
        entries, convention.parsed, convention.zeroes_intrinsic_first, GIMBAL_LOCK_TOLERANCE
    )
    if angles is None:
        return None
    ordered = convention.from_intrinsic(angles)
    return as_array(degrees_of(ordered) if degrees else ordered, (3,))


def one_matrix_to_angles(
    R: Any, convention: Convention, check: RotationCheck, degrees: bool
) -> NDArray[np.float64] | None:
    """:func:`matrices_to_angles` for a single plain rotation matrix in Python floats; None
    for anything else (see :mod:`eulerlib._scalar`)."""
    entries = rotation(R, check)
    return None if entries is None else entries_to_angles(entries, convention, degrees)


# The compiled kernels (eulerlib/_compiled_euler.c) take a convention as one integer.
_CODES: dict[tuple[str, str], int] = {}


def compiled_code(convention: Convention) -> int:
    """The integer that names ``convention`` to the compiled kernels: the frame's axes i, j, k
    in bits 0-5, a negative third axis in bit 6, a proper sequence in bit 7, an extrinsic one
    (written order reversed) in bit 8, the policy of zeroing the first intrinsic angle at lock
    in bit 9. Remembered, by sequence and lock policy (all it depends on), for the first few
    seen."""
    key = (convention.seq, convention.lock_zeroes)
    code = _CODES.get(key)
    if code is None:
        parsed = convention.parsed
        (i, j, k), sign = frame(parsed)
        flags = (sign[2] < 0, parsed.proper, not parsed.intrinsic)
        code = i | j << 2 | k << 4 | sum(bit << (6 + n) for n, bit in enumerate(flags))
        code |= convention.zeroes_intrinsic_first << 9
        if len(_CODES) < 64:
            _CODES[key] = code
    return code


def compiled_sines(kernels: Any, given: NDArray[np.float64], degrees: bool) -> Any:
    """numpy's sines and cosines that the compiled kernels of angles take for ``given`` (in
    degrees, of the rests after the quarter turns), or None for angles that are not finite."""
    rests = np.empty(given.shape) if degrees else given
    if not kernels.angle_rests(rests, given, degrees):
        return None
    return np.sin(rests), np.cos(rests)


def _parts(given: NDArray[np.float64], width: int) -> Iterator[NDArray[np.float64]]:
    """``given`` whole when it holds one block of rotations (the common case, with no
    reshaping), else its rotations ``(n, width)`` block by block, so that the temporaries of a
    large batch stay the size of a block."""
    count = given.size // width
    if count <= BLOCK_SIZE:
        yield given
        return
    flat = given.reshape(-1, width)
    for block in block_slices(count):
        yield flat[block]


def _out_parts(out: NDArray[np.float64], count: int, width: int) -> Iterator[NDArray[np.float64]]:
    """The parts of a new output that go with :func:`_parts` of its input."""
    if count <= BLOCK_SIZE:
        yield out
        return
    flat = out.reshape(-1, width)
    for block in block_slices(count):
        yield flat[block]


def compiled_matrices(
    angles: object, convention: Convention, degrees: bool
) -> NDArray[np.float64] | None:
    """:func:`angles_to_matrices` in compiled kernels for a float64 array of angles in argument
    order, or None where they do not take it (see :mod:`eulerlib._compiled`)."""
    kernels, given = _compiled.euler, _compiled.batch(angles, (3,))
    if kernels is None or given is None:
        return None
    out = np.empty((*given.shape[:-1], 3, 3))
    code = compiled_code(convention)
    for part, out_part in zip(_parts(given, 3), _out_parts(out, out.size // 9, 9), strict=True):
        sines = compiled_sines(kernels, part, degrees)  # numpy's, a block at a time
        if sines is None:
            return None
        kernels.angles_to_matrices(out_part, part, *sines, code, degrees)
    return out


# writes into ``pairs`` (2, n, 4) the arctangent pairs of a part of the rotations; False to
# decline
PairFill = Callable[[NDArray[np.float64], NDArray[np.float64]], bool]


def compiled_from_pairs(
    kernels: Any,
    given: NDArray[np.float64],
    width: int,
    fill: PairFill,
    convention: Convention,
    degrees: bool,
) -> NDArray[np.float64] | None:
    """The angles in argument order, shape ``(..., 3)``, of the rotations ``given``
    ``(..., *shape)`` with ``width`` numbers each, whose arctangent pairs ``fill`` writes part
    by part; None when ``fill`` declines or a rotation is at gimbal lock (the array path then
    applies the policy and warns)."""
    count = given.size // width
    out = np.empty((*given.shape[: given.ndim - (2 if width == 9 else 1)], 3))
    code = compiled_code(convention)
    if count <= BLOCK_SIZE:  # the same as the loop below, with less set-up for one block
        pairs = np.empty((2, count, 4))
        if fill(pairs, given) and kernels.pairs_to_angles(
            out, np.arctan2(pairs[0], pairs[1]), code, degrees, GIMBAL_LOCK_TOLERANCE
        ):
            return out
        return None
    for part, out_part in zip(_parts(given, width), _out_parts(out, count, 3), strict=True):
        pairs = np.empty((2, part.size // width, 4))
        if not fill(pairs, part):
            return None
        arctangents = np.arctan2(pairs[0], pairs[1])
        if not kernels.pairs_to_angles(out_part, arctangents, code, degrees, GIMBAL_LOCK_TOLERANCE):
            return None
    return out


def compiled_angles(
    R: object, convention: Convention, check: RotationCheck, degrees: bool
) -> NDArray[np.float64] | None:
    """:func:`matrices_to_angles` in compiled kernels for a float64 array of matrices that
    passes ``check`` without repair and has no rotation at lock, or None."""
    kernels, given = _compiled.euler, _compiled.batch(R, (3, 3))
    if kernels is None or given is None or check.repair:
        return None
    code = compiled_code(convention)

    def fill(pairs: NDArray[np.float64], part: NDArray[np.float64]) -> bool:
        done: bool = kernels.matrices_to_pairs(pairs, part, code, check.validate, check.atol)
        return done

    return compiled_from_pairs(kernels, given, 9, fill, convention, degrees)


def compiled_conversion(
    angles: object, source: Convention, target: Convention, degrees: bool
) -> NDArray[np.float64] | None:
    """The angles of ``target`` for angles of ``source`` (a float64 array), through their
    matrices, in compiled kernels; None where they do not take them or at gimbal lock."""
    kernels, given = _compiled.euler, _compiled.batch(angles, (3,))
    if kernels is None or given is None:
        return None
    code, target_code = compiled_code(source), compiled_code(target)

    def fill(pairs: NDArray[np.float64], part: NDArray[np.float64]) -> bool:
        sines = compiled_sines(kernels, part, degrees)
        if sines is None:
            return False
        kernels.angles_to_pairs(pairs, part, *sines, code, degrees, target_code)
        return True

    return compiled_from_pairs(kernels, given, 3, fill, target, degrees)


def compiled_quaternions(
    angles: object, convention: Convention, degrees: bool, scalar_first: bool
) -> NDArray[np.float64] | None:
    """The canonical quaternions of a float64 array of angles in compiled kernels, stored as
    ``scalar_first`` says, or None where they do not take it."""
    kernels, given = _compiled.euler, _compiled.batch(angles, (3,))
    if kernels is None or given is None:
        return None
    out = np.empty((*given.shape[:-1], 4))
    code = compiled_code(convention)
    for part, out_part in zip(_parts(given, 3), _out_parts(out, out.size // 4, 4), strict=True):
        halves = np.empty(part.shape)
        if not kernels.half_angles(halves, part, degrees):
            return None
        tangents = np.tan(halves)  # numpy's, a block at a time
        kernels.angles_to_quaternions(out_part, part, tangents, code, degrees, scalar_first)
    return out


def compiled_quaternion_angles(
    q: object, convention: Convention, scalar_first: bool, degrees: bool
) -> NDArray[np.float64] | None:
    """The angles of a float64 array of quaternions in compiled kernels, or None where they do
    not take it (a length that needs rescaling, a rotation at gimbal lock)."""
    kernels, given = _compiled.euler, _compiled.batch(q, (4,))
    if kernels is None or given is None:
        return None
    code = compiled_code(convention)

    def fill(pairs: NDArray[np.float64], part: NDArray[np.float64]) -> bool:
        done: bool = kernels.quaternions_to_pairs(pairs, part, scalar_first, code)
        return done

    return compiled_from_pairs(kernels, given, 4, fill, convention, degrees)


def compiled_elementary(axis: int, angle: object, degrees: bool) -> NDArray[np.float64] | None:
    """The matrices of turns by a float64 array of angles about ``axis`` in compiled kernels,
    as :func:`eulerlib.elementary_rotation` gives them, or None where they do not take it."""
    kernels, given = _compiled.euler, _compiled.batch(angle, ())
    if kernels is None or given is None:
        return None
    out = np.empty((*given.shape, 3, 3))
    for part, out_part in zip(_parts(given, 1), _out_parts(out, given.size, 9), strict=True):
        sines = compiled_sines(kernels, part, degrees)  # numpy's, a block at a time
        if sines is None:
            return None
        kernels.elementary_matrices(out_part, part, *sines, axis, degrees)
    return out
