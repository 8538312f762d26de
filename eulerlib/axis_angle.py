"""Axis and angle: every rotation is one turn about one axis.

Euler's rotation theorem
------------------------
Every rotation of space that keeps the origin fixed is a single turn by some angle θ about some
line through the origin: a rotation matrix ``R`` has the eigenvalue 1 (``det(R − I) = 0`` for
``R Rᵀ = I``, ``det R = 1``), and its eigenvector ``n`` is the axis. So three Euler angles, or
nine matrix entries, always describe one axis and one angle. The pair is unique for
0 < θ < π (taking θ ≥ 0); at θ = 0 every axis will do, and at θ = π the axes ``n`` and ``-n``
give the same half turn.

Rodrigues' formula
------------------
With ``[n]×`` the matrix of the cross product ``n × ·``, the turn by θ about the unit axis ``n``
is

.. math::

    R = I + \\sin θ\\, [n]_× + (1 − \\cos θ)\\, [n]_×^2
      = \\cos θ\\, I + \\sin θ\\, [n]_× + (1 − \\cos θ)\\, n n^T .

Back from ``R``: its trace is ``1 + 2 cos θ`` and its skew part ``(R − Rᵀ) / 2`` is ``sin θ [n]×``.
eulerlib takes θ as ``atan2(|s|, trace − 1)`` with ``s = (r21 − r12, r02 − r20, r10 − r01) =
2 sin θ n``, an ``atan2`` of a sine and a cosine, accurate near 0 and near π alike
(``acos((trace − 1) / 2)`` would lose half the digits at both ends). Near π the skew part
vanishes and says nothing about the axis; the axis then comes from the symmetric part
``(R + Rᵀ) / 2 = cos θ I + (1 − cos θ) n nᵀ``, which is what Shepperd's choice of the largest
component of the quaternion does (:mod:`eulerlib.quaternion`).

No digit is lost at small angles either: the matrices are built from the half-angle form
``w = cos(θ/2)``, ``v = sin(θ/2) n`` (entries ``1 − 2(y² + z²)`` and ``2(xy ∓ wz)``), so that
``1 − cos θ`` is never computed by subtraction, and ``sin(θ/2) / θ``, the factor that turns a
rotation vector into ``v``, is a quotient of two accurate numbers (its limit 1/2 is used only at
θ = 0 itself).

The rotation vector
-------------------
``θ n``, one vector of length θ along the axis: three numbers, no constraint, and small for
small rotations, which makes it the natural coordinates for rotation rates and for averaging
nearby rotations. SciPy calls it ``rotvec``.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib import _compiled, _scalar
from eulerlib._blocks import BLOCK_SIZE, block_slices
from eulerlib._broadcast import broadcast_blocks, broadcast_shape
from eulerlib._length_kernels import lengths
from eulerlib._quaternion_kernels import (
    entries_to_quaternions,
    quaternions_to_entries,
    relative_angles,
    rotation_angles,
    rotation_vectors,
    rotvecs_to_entries,
    unit_axes,
)
from eulerlib._scalar_kernels import (
    axis_angle_to_entries,
    entries_to_quaternion,
    relative_angle,
    rotvec_to_entries,
    vector_part,
)
from eulerlib._scalar_kernels import rotation_angle as one_rotation_angle
from eulerlib._trig import half_angle_pair
from eulerlib._unit import refuse_overlong, scaled_to_unit_size
from eulerlib._validation import (
    ROTATION_ATOL,
    RotationCheck,
    as_float_array,
    as_matrix_stack,
    as_rotations,
    as_vectors,
    check_flag,
    matrix_entries,
    rotation_check,
    rotation_entry_blocks,
)

__all__ = [
    "AxisAngle",
    "angle_between",
    "axis_angle_to_matrix",
    "matrix_to_axis_angle",
    "matrix_to_rotvec",
    "rotation_angle",
    "rotvec_to_matrix",
]


class AxisAngle(NamedTuple):
    """A rotation as one turn about one axis.

    Attributes
    ----------
    axis : ndarray, shape (..., 3)
        Unit axes.
    angle : ndarray, shape (...)
        Angles in [0, π] (or [0, 180] in degrees), turning by the right-hand rule about
        ``axis``.
    """

    axis: NDArray[np.float64]
    angle: NDArray[np.float64]


def _one_axis_angle(
    R: ArrayLike, check: RotationCheck
) -> tuple[tuple[float, float, float], float] | None:
    """Unit axis and angle (radians) of a single plain rotation matrix in Python floats, as the
    array path computes them; None for anything else, and for the identity and the turns so
    small that a length needs rescaling (see :mod:`eulerlib._scalar`)."""
    entries = _scalar.rotation(R, check)
    if entries is None:
        return None
    angle = one_rotation_angle(entries)
    part = vector_part(entries_to_quaternion(entries))
    if angle is None or part is None:
        return None
    (x, y, z), length = part
    return (x / length, y / length, z / length), angle


def _compiled_axis_angle(axis: object, angle: object, degrees: bool) -> NDArray[np.float64] | None:
    """The matrices of :func:`axis_angle_to_matrix` from the compiled kernels (C, numpy's tan,
    C), for float64 arrays whose shapes are equal or one of which is single; else None."""
    kernels, axes = _compiled.rotations, _compiled.batch(axis, (3,))
    if kernels is None or axes is None:
        return None
    angles = _compiled.batch(np.array(angle) if isinstance(angle, float) else angle, ())
    if angles is None:
        return None
    lead = axes.shape[:-1]
    if angles.shape == lead or angles.ndim == 0:
        shape = lead
    elif not lead:
        shape = angles.shape
    else:
        return None
    half = np.empty(angles.shape)
    if not kernels.half_angles(half, angles, degrees):
        return None
    np.tan(half, out=half)
    out = np.empty((*shape, 3, 3))
    return out if kernels.axis_angles_to_matrices(out, axes, angles, half, degrees) else None


def _arctangents(
    lead: tuple[int, ...], fill: Callable[[NDArray[np.float64], slice], bool]
) -> NDArray[np.float64] | None:
    """Angles of leading shape ``lead`` as numpy's arctan2 of the pairs that ``fill`` writes,
    block by block, into rows ``(2, block)`` of y and x; None when ``fill`` declines."""
    angles = np.empty(lead)  # written through out=: a 0-d array for one rotation
    column = angles.reshape(-1)
    scratch = np.empty(2 * min(column.size, BLOCK_SIZE))
    for block in block_slices(column.size):
        yx = scratch[: 2 * (block.stop - block.start)].reshape(2, -1)
        if not fill(yx, block):
            return None
        np.arctan2(yx[0], yx[1], out=column[block])
    return angles


def _compiled_angles(R: object, check: RotationCheck) -> tuple[Any, NDArray[np.float64]] | None:
    """The matrices ``R`` as a float64 batch and their angles in radians, from the compiled
    kernels (C, numpy's arctan2), block by block; None where the kernels do not take them."""
    kernels, given = _compiled.rotations, _compiled.batch(R, (3, 3))
    if kernels is None or given is None or check.repair:
        return None
    flat = given.reshape(-1, 3, 3)

    def fill(yx: NDArray[np.float64], block: slice) -> bool:
        done: bool = kernels.angle_arguments(yx, flat[block], check.validate, check.atol)
        return done

    angles = _arctangents(given.shape[:-2], fill)
    return None if angles is None else (given, angles)


def axis_angle_to_matrix(
    axis: ArrayLike, angle: ArrayLike, *, degrees: bool = False
) -> NDArray[np.float64]:
    """Rotation matrices of turns by ``angle`` about ``axis`` (Rodrigues' formula).

    Parameters
    ----------
    axis : array_like, shape (..., 3)
        Rotation axes, of any nonzero length: each is normalized.
    angle : array_like, shape (...)
        Angles, by the right-hand rule about the axis, in radians unless ``degrees``. Its shape
        broadcasts with the leading shape of ``axis``: one axis with many angles, many axes
        with one angle, or one angle per axis.
    degrees : bool, optional
        Read ``angle`` in degrees. Degrees are reduced modulo 360° exactly, so angles of any
        size are exact, and multiples of 90° about a coordinate axis give exact zeros and ones.

    Returns
    -------
    ndarray, shape (broadcast of ``axis.shape[:-1]`` and ``angle.shape``, 3, 3)
        The rotation matrices.

    Raises
    ------
    TypeError
        If ``axis`` or ``angle`` is not real numbers, or ``degrees`` is not a bool.
    ValueError
        If ``axis`` does not have shape ``(..., 3)``, an axis is zero (the message gives its
        index), a value is NaN or infinite, or the shapes do not broadcast.

    Notes
    -----
    ``R = cos θ I + sin θ [n]× + (1 − cos θ) n nᵀ``, evaluated in the half-angle form
    ``R = I + 2 w [v]× + 2 [v]×²`` with ``w = cos(θ/2)``, ``v = sin(θ/2) n``, which never
    subtracts ``cos θ`` from 1. See the module docstring.

    Examples
    --------
    >>> import numpy as np
    >>> axis_angle_to_matrix([0, 0, 2], 90, degrees=True)     # the axis is normalized
    array([[ 0., -1.,  0.],
           [ 1.,  0.,  0.],
           [ 0.,  0.,  1.]])
    >>> axis_angle_to_matrix([1, 1, 1], np.linspace(0, np.pi, 5)).shape
    (5, 3, 3)
    """
    in_degrees = check_flag(degrees, "degrees")
    compiled = _compiled_axis_angle(axis, angle, in_degrees)
    if compiled is not None:
        return compiled
    one_axis, one_angle = _scalar.vector(axis), _scalar.number(angle)
    if one_axis is not None and one_angle is not None:
        one_entries = axis_angle_to_entries(one_axis, one_angle, in_degrees)
        if one_entries is not None:  # None for a zero axis, which the array path refuses
            return _scalar.as_array(one_entries, (3, 3))
    axes = as_vectors(axis, "axis")
    angles = as_float_array(angle, "angle")
    axis_lead = axes.shape[:-1]
    shape = broadcast_shape({"axis": axis_lead, "angle": angles.shape})
    flat_axes, flat_angles = axes.reshape(-1, 3), angles.reshape(-1)
    out = np.empty((math.prod(shape), 9))
    for block, (on_axis, on_angle) in broadcast_blocks(shape, (axis_lead, angles.shape)):
        rows = np.ascontiguousarray(flat_axes[on_axis].T)
        rows, squared = scaled_to_unit_size(rows, "axis", "a rotation axis", axis_lead, on_axis)
        a, b = half_angle_pair(flat_angles[on_angle], in_degrees)
        # (a |n|, b n) is a multiple of (cos(θ/2), sin(θ/2) n / |n|), and with |n| near 1 its
        # squared length can neither overflow nor underflow
        q = np.empty((4, rows.shape[1]))
        np.multiply(a, np.sqrt(squared), out=q[0])
        np.multiply(rows, b, out=q[1:])
        entries = np.empty((9, q.shape[1]))
        quaternions_to_entries(q, entries)
        out[block] = entries.T
    return out.reshape(*shape, 3, 3)


def matrix_to_axis_angle(
    R: ArrayLike,
    *,
    degrees: bool = False,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
) -> AxisAngle:
    """Axis and angle of rotation matrices: each is one turn about one axis.

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotation matrices. Leading axes are batch axes.
    degrees : bool, optional
        Return the angle in degrees.
    validate, repair, atol
        As in :func:`eulerlib.matrix_to_euler`: check that ``R`` holds rotations within
        ``atol`` (default), or use the nearest rotations.

    Returns
    -------
    AxisAngle
        ``(axis, angle)``: unit axes, shape ``(..., 3)``, and angles in [0, π] (radians) or
        [0, 180] (degrees), shape ``(...)`` (0-d arrays for one matrix). Where the angle is
        0 the axis is ``(1, 0, 0)``, by convention. Where it is π, both ``n`` and ``-n`` are
        axes: the one returned has its first nonzero component positive. It is the axis of
        the canonical quaternion (:func:`eulerlib.matrix_to_quaternion`).

    Raises
    ------
    TypeError
        If ``R`` is not real numbers or a flag is not a bool.
    ValueError
        If ``R`` has a wrong shape, non-finite entries, is a reflection or not orthogonal
        within ``atol`` (or cannot be repaired), or ``atol`` is not a finite number ≥ 0.

    Notes
    -----
    The angle is ``atan2(|s|, trace − 1)`` with ``s`` the skew part of ``R`` (see
    :func:`rotation_angle`), the axis is the vector part of the quaternion by Shepperd's
    method, normalized: from the skew part for small angles, from the symmetric part near π.
    Both are accurate to a few units in the last place everywhere.

    Examples
    --------
    >>> import numpy as np
    >>> from eulerlib import rot_y
    >>> axis, angle = matrix_to_axis_angle(rot_y(-30, degrees=True), degrees=True)
    >>> axis, angle                       # −30° about y is +30° about −y
    (array([ 0., -1.,  0.]), array(30.))
    >>> matrix_to_axis_angle(np.diag([-1.0, 1.0, -1.0])).axis     # half turn about y
    array([0., 1., 0.])
    """
    in_degrees = check_flag(degrees, "degrees")
    check = rotation_check(validate, repair, atol)
    compiled = _compiled_angles(R, check)
    if compiled is not None:  # C, numpy's arctan2, C; or the paths below
        given, angles = compiled
        axes = np.empty((*given.shape[:-2], 3))
        if _compiled.rotations.matrices_to_axes(axes, given):
            return AxisAngle(axes, np.degrees(angles, out=angles) if in_degrees else angles)
    single = _one_axis_angle(R, check)
    if single is not None:
        one_axis, one_angle = single
        return AxisAngle(
            _scalar.as_array(one_axis, (3,)),
            np.array(math.degrees(one_angle) if in_degrees else one_angle),
        )
    matrices = as_matrix_stack(R, "R")
    lead = matrices.shape[:-2]
    count = math.prod(lead)
    axes, angles = np.empty((count, 3)), np.empty(count)
    for block, entries in rotation_entry_blocks(matrices, "R", check):
        axes[block] = unit_axes(entries_to_quaternions(entries)).T
        angles[block] = rotation_angles(entries)
    if in_degrees:
        np.degrees(angles, out=angles)
    return AxisAngle(axes.reshape(*lead, 3), angles.reshape(lead))


def rotvec_to_matrix(v: ArrayLike, *, degrees: bool = False) -> NDArray[np.float64]:
    """Rotation matrices of rotation vectors: turns by ``|v|`` about ``v``.

    Parameters
    ----------
    v : array_like, shape (..., 3)
        Rotation vectors: the angle times the unit axis, as SciPy's ``Rotation.from_rotvec``.
        The zero vector is the identity. Leading axes are batch axes.
    degrees : bool, optional
        Read the length of ``v`` in degrees, as ``from_rotvec(v, degrees=True)``.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        The rotation matrices.

    Raises
    ------
    TypeError
        If ``v`` is not real numbers or ``degrees`` is not a bool.
    ValueError
        If ``v`` does not have shape ``(..., 3)``, has NaN or infinite entries, or a vector is
        longer than the largest float (about 1.8e308; the message gives its index).

    Notes
    -----
    With θ = ``|v|``, the quaternion is ``(cos(θ/2), (sin(θ/2) / θ) v)``, and the matrix is
    built from it as in :func:`axis_angle_to_matrix`. ``sin(θ/2) / θ`` is a quotient of two
    accurate numbers, so rotation vectors as short as 1e-300 give matrices accurate in every
    entry; the length itself is found without underflow or overflow, scaled by a power of two.

    Long vectors turn by their length rounded to a float, reduced modulo 2π (or modulo 360°,
    exactly) with no further error, so ``(3, 4, 0) · 2**1020`` turns by ``5 · 2**1020`` rad
    about ``(0.6, 0.8, 0)``, where SciPy's ``from_rotvec`` gives NaN. Beyond about 1e16 rad
    one unit in the last place of the length is more than a turn, so such a rotation is exact
    for the float given but says little about the motion it came from. A vector longer than the
    largest float has no float length to reduce; it is refused rather than given an angle
    that no input determines.

    Examples
    --------
    >>> import numpy as np
    >>> rotvec_to_matrix([0, 0, np.pi / 2]).round(15) + 0.0     # 90° about z
    array([[ 0., -1.,  0.],
           [ 1.,  0.,  0.],
           [ 0.,  0.,  1.]])
    >>> rotvec_to_matrix([180, 0, 0], degrees=True)             # a half turn about x
    array([[ 1.,  0.,  0.],
           [ 0., -1.,  0.],
           [ 0.,  0., -1.]])
    >>> rotvec_to_matrix([1.7e308, 1.7e308, 0.0])               # |v| is not a float
    Traceback (most recent call last):
    ...
    ValueError: v has a length above the largest float (about 1.8e308): the angle of its turn is
    not a number
    """
    in_degrees = check_flag(degrees, "degrees")
    kernels, given = _compiled.rotations, _compiled.batch(v, (3,))
    if kernels is not None and given is not None:  # C, numpy's tan, C; or the paths below
        half = np.empty(given.shape[:-1])
        if kernels.rotvec_half_angles(half, given, in_degrees):
            np.tan(half, out=half)
            out = np.empty((*given.shape[:-1], 3, 3))
            if kernels.rotvecs_to_matrices(out, given, half, in_degrees):
                return out
    single = _scalar.vector(v)
    entries = None if single is None else rotvec_to_entries(single, in_degrees)
    if entries is not None:  # None for the zero vector and lengths that need rescaling
        return _scalar.as_array(entries, (3, 3))
    vectors = as_vectors(v, "v")
    flat = vectors.reshape(-1, 3)
    out = np.empty((flat.shape[0], 9))
    for block in block_slices(flat.shape[0]):
        rows = np.ascontiguousarray(flat[block].T)
        length = lengths(rows)
        refuse_overlong(length, "v", vectors.shape[:-1], block)
        out[block] = rotvecs_to_entries(rows, in_degrees, length).T
    return out.reshape(*vectors.shape[:-1], 3, 3)


def matrix_to_rotvec(
    R: ArrayLike,
    *,
    degrees: bool = False,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
) -> NDArray[np.float64]:
    """Rotation vectors of rotation matrices: the angle times the unit axis.

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotation matrices. Leading axes are batch axes.
    degrees : bool, optional
        Give the length of the vectors in degrees, as SciPy's ``as_rotvec(degrees=True)``.
    validate, repair, atol
        As in :func:`eulerlib.matrix_to_euler`.

    Returns
    -------
    ndarray, shape (..., 3)
        ``angle * axis`` of :func:`matrix_to_axis_angle`: length in [0, π] (or [0, 180]); the
        zero vector for the identity; for a half turn, the axis whose first nonzero component
        is positive.

    Raises
    ------
    TypeError
        If ``R`` is not real numbers or a flag is not a bool.
    ValueError
        If ``R`` has a wrong shape, non-finite entries, is a reflection or not orthogonal
        within ``atol`` (or cannot be repaired), or ``atol`` is not a finite number ≥ 0.

    Examples
    --------
    >>> from eulerlib import rot_x
    >>> matrix_to_rotvec(rot_x(-45, degrees=True), degrees=True)
    array([-45.,   0.,   0.])
    >>> matrix_to_rotvec(rot_x(1e-10))         # tiny turns come back to the last digit
    array([1.e-10, 0.e+00, 0.e+00])
    """
    in_degrees = check_flag(degrees, "degrees")
    check = rotation_check(validate, repair, atol)
    compiled = _compiled_angles(R, check)
    if compiled is not None:  # C, numpy's arctan2, C; or the paths below
        given, angles = compiled
        if in_degrees:
            np.degrees(angles, out=angles)
        out = np.empty((*given.shape[:-2], 3))
        if _compiled.rotations.matrices_to_rotvecs(out, given, angles):
            return out
    single = _scalar.rotation(R, check)
    if single is not None:
        turn = one_rotation_angle(single)
        part = vector_part(entries_to_quaternion(single))
        if turn is not None and part is not None:
            if in_degrees:
                turn = math.degrees(turn)
            (x, y, z), length = part
            factor = turn / length
            return _scalar.as_array((x * factor, y * factor, z * factor), (3,))
    matrices = as_matrix_stack(R, "R")
    lead = matrices.shape[:-2]
    out = np.empty((math.prod(lead), 3))
    for block, entries in rotation_entry_blocks(matrices, "R", check):
        angle = rotation_angles(entries)
        if in_degrees:
            np.degrees(angle, out=angle)
        out[block] = rotation_vectors(entries_to_quaternions(entries), angle).T
    return out.reshape(*lead, 3)


def rotation_angle(
    R: ArrayLike,
    *,
    degrees: bool = False,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
) -> NDArray[np.float64]:
    """The angle of each rotation: how far it turns, about its own axis.

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotation matrices. Leading axes are batch axes.
    degrees : bool, optional
        Return degrees instead of radians.
    validate, repair, atol
        As in :func:`eulerlib.matrix_to_euler`.

    Returns
    -------
    ndarray, shape (...)
        Angles in [0, π] (or [0, 180]); a 0-d array for one matrix. The same numbers as
        ``matrix_to_axis_angle(R).angle`` and SciPy's ``Rotation.magnitude()``.

    Raises
    ------
    TypeError
        If ``R`` is not real numbers or a flag is not a bool.
    ValueError
        If ``R`` has a wrong shape, non-finite entries, is a reflection or not orthogonal
        within ``atol`` (or cannot be repaired), or ``atol`` is not a finite number ≥ 0.

    Notes
    -----
    ``θ = atan2(|s|, trace − 1)``, where ``s = (r21 − r12, r02 − r20, r10 − r01) = 2 sin θ n``
    and ``trace − 1 = 2 cos θ``: accurate to a few units in the last place for every angle,
    where ``acos((trace − 1) / 2)`` loses half the digits near 0 and near π.

    Examples
    --------
    >>> from eulerlib import euler_to_matrix
    >>> rotation_angle(euler_to_matrix([90, 0, 0], degrees=True), degrees=True)
    array(90.)
    >>> float(rotation_angle(euler_to_matrix([1e-9, 0, 0])))   # acos would give 0.0
    1e-09
    """
    in_degrees = check_flag(degrees, "degrees")
    check = rotation_check(validate, repair, atol)
    compiled = _compiled_angles(R, check)
    if compiled is not None:  # C, then numpy's arctan2
        angles = compiled[1]
        return np.degrees(angles, out=angles) if in_degrees else angles
    single = _scalar.rotation(R, check)
    turn = None if single is None else one_rotation_angle(single)
    if turn is not None:
        return np.array(math.degrees(turn) if in_degrees else turn)
    matrices = as_matrix_stack(R, "R")
    lead = matrices.shape[:-2]
    angles = np.empty(math.prod(lead))
    for block, entries in rotation_entry_blocks(matrices, "R", check):
        angles[block] = rotation_angles(entries)
    if in_degrees:
        np.degrees(angles, out=angles)
    return angles.reshape(lead)


def _compiled_relative_angles(
    R0: object, R1: object, check: RotationCheck
) -> NDArray[np.float64] | None:
    """The angles of :func:`angle_between` in radians from the compiled kernels (C, numpy's
    arctan2), block by block, for float64 batches of equal leading shapes or one of them
    single; else None."""
    kernels = _compiled.rotations
    first, second = _compiled.batch(R0, (3, 3)), _compiled.batch(R1, (3, 3))
    if kernels is None or first is None or second is None or check.repair:
        return None
    lead0, lead1 = first.shape[:-2], second.shape[:-2]
    if lead0 != lead1 and lead0 and lead1:
        return None
    flat0, flat1 = first.reshape(-1, 3, 3), second.reshape(-1, 3, 3)

    def fill(yx: NDArray[np.float64], block: slice) -> bool:
        on0 = flat0[block] if lead0 else flat0
        on1 = flat1[block] if lead1 else flat1
        done: bool = kernels.relative_angle_arguments(yx, on0, on1, check.validate, check.atol)
        return done

    return _arctangents(lead0 or lead1, fill)


def angle_between(
    R0: ArrayLike,
    R1: ArrayLike,
    *,
    degrees: bool = False,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
) -> NDArray[np.float64]:
    """The geodesic distance between rotations: the angle of the turn from ``R0`` to ``R1``.

    Parameters
    ----------
    R0, R1 : array_like, shape (..., 3, 3)
        Rotation matrices; their leading axes broadcast.
    degrees : bool, optional
        Return degrees instead of radians.
    validate, repair, atol
        As in :func:`eulerlib.matrix_to_euler`, for both arguments.

    Returns
    -------
    ndarray, shape (broadcast leading shape)
        ``rotation_angle(R0ᵀ R1)``, in [0, π] (or [0, 180]). It is a metric on rotations:
        symmetric, zero exactly when ``R0 == R1``, and it satisfies the triangle inequality.

    Raises
    ------
    TypeError
        If an argument is not real numbers or a flag is not a bool.
    ValueError
        If a shape is wrong, the leading shapes do not broadcast, or an argument is not a
        rotation within ``atol`` (or cannot be repaired).

    Notes
    -----
    The trace and the skew part of ``R0ᵀ R1`` are found from the rows ``A_k`` of ``R0`` and
    ``B_k`` of ``R1`` without forming the product: ``trace = Σ A_k · B_k`` and
    ``s = Σ B_k × A_k``; then ``θ = atan2(|s|, trace − 1)`` as in :func:`rotation_angle`. The
    result is accurate to a few units of 1e-16 in absolute terms, which is as closely as two
    float64 rotation matrices, each orthogonal only to rounding, determine it.

    Examples
    --------
    >>> from eulerlib import rot_x, rot_z
    >>> angle_between(rot_z(10, degrees=True), rot_z(50, degrees=True), degrees=True)
    array(40.)
    >>> angle_between(rot_x(0.0), [rot_x(0.1), rot_z(0.2)]).round(15)
    array([0.1, 0.2])
    """
    in_degrees = check_flag(degrees, "degrees")
    check = rotation_check(validate, repair, atol)
    compiled = _compiled_relative_angles(R0, R1, check)
    if compiled is not None:
        return np.degrees(compiled, out=compiled) if in_degrees else compiled
    one_first = _scalar.rotation(R0, check)
    one_second = None if one_first is None else _scalar.rotation(R1, check)
    if one_first is not None and one_second is not None:
        angle = relative_angle(one_first, one_second)
        if angle is not None:
            return np.array(math.degrees(angle) if in_degrees else angle)
    first = as_rotations(R0, "R0", check)
    second = as_rotations(R1, "R1", check)
    lead0, lead1 = first.shape[:-2], second.shape[:-2]
    shape = broadcast_shape({"R0": lead0, "R1": lead1})
    flat0, flat1 = first.reshape(-1, 3, 3), second.reshape(-1, 3, 3)
    angles = np.empty(math.prod(shape))
    for block, (on0, on1) in broadcast_blocks(shape, (lead0, lead1)):
        angles[block] = relative_angles(matrix_entries(flat0[on0]), matrix_entries(flat1[on1]))
    if in_degrees:
        np.degrees(angles, out=angles)
    return angles.reshape(shape)
