"""Integrating an angular velocity: one exact step of a body turning at a constant rate.

A gyroscope reports the angular velocity ``ω`` of a body in the body's own axes, sample after
sample. The attitude ``R`` (body coordinates to fixed coordinates) then obeys
``Ṙ = R [ω]×``: the body-frame form of ``Rᵀ Ṙ = [ω]×`` (:mod:`eulerlib.angular_velocity`). If
``ω`` stays constant over a step of length ``Δt``, this linear equation has the exact solution

.. math:: R(t + Δt) = R(t)\\, \\exp([ω Δt]_×),

and ``exp([ω Δt]×)`` is the turn by the angle ``|ω| Δt`` about the axis ``ω``: Rodrigues' formula,
that is :func:`eulerlib.rotvec_to_matrix` of the rotation vector ``ω Δt``. With ``ω`` written in
the fixed axes, ``Ṙ = [ω]× R`` and the step multiplies from the left instead,
``R(t + Δt) = exp([ω Δt]×) R(t)``. Either way the step is a product of two rotations, so it never
leaves the rotations except by rounding, and a constant rate is integrated without any error
of the method: ``n`` steps give ``R(0) exp([ω n Δt]×)``, to rounding.

Compare the other two ways of integrating, which the course measures:

* the first-order step ``R + R [ω]× Δt`` is not a rotation at all (a column perpendicular to
  ``ω`` grows by a factor of about ``1 + ½ (|ω| Δt)²`` per step);
* integrating the Euler-angle rates (:func:`eulerlib.angular_velocity_to_euler_rates`) divides by
  ``cos β`` and fails near gimbal lock.

What remains is the drift of rounding: after many steps ``R Rᵀ`` moves away from ``I`` by about
1e-16 per step. ``repair=True`` replaces the attitude by its nearest rotation before the
step (:func:`eulerlib.nearest_rotation`).

A sequence of samples is integrated one step per sample, by a loop over time, which cannot be
avoided (each step starts where the last one ended); each step is vectorized over any number of
independent bodies, whose leading axes broadcast against those of ``omega`` and ``dt``.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib import _compiled, _scalar
from eulerlib._blocks import BLOCK_SIZE, block_slices
from eulerlib._broadcast import (
    block_part,
    broadcast_blocks,
    broadcast_shape,
    common_lead,
    selected_index,
)
from eulerlib._length_kernels import lengths
from eulerlib._quaternion_kernels import product, rotvecs_to_entries
from eulerlib._scalar_kernels import product as product_of_two
from eulerlib._scalar_kernels import rotvec_to_entries
from eulerlib._unit import refuse_overlong
from eulerlib._validation import (
    ROTATION_ATOL,
    RotationCheck,
    _index_text,
    as_float_array,
    as_rotations,
    as_vectors,
    check_choice,
    check_flag,
    rotation_check,
)
from eulerlib.angular_velocity import FRAMES

__all__ = ["integrate_angular_velocity"]


def integrate_angular_velocity(
    R: ArrayLike,
    omega: ArrayLike,
    dt: ArrayLike,
    *,
    frame: str = "body",
    degrees: bool = False,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
) -> NDArray[np.float64]:
    """The attitude after turning at a constant angular velocity for a time ``dt``.

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Attitudes at the start of the step: rotation matrices that turn body coordinates into
        fixed coordinates.
    omega : array_like, shape (..., 3)
        Angular velocities, constant over the step, in radians per unit of time (degrees with
        ``degrees=True``), written in the axes ``frame`` names.
    dt : array_like, shape (...)
        Lengths of the steps, in the same unit of time; negative steps go back in time.
    frame : {'body', 'space'}, optional
        ``'body'`` (default): ``omega`` is in the body's own axes, as a gyroscope measures it,
        and the step is ``R · exp([ω dt]×)``; ``'space'``: ``omega`` is in the fixed axes and
        the step is ``exp([ω dt]×) · R``. Any letter case.
    degrees : bool, optional
        Read ``omega`` in degrees per unit of time.
    validate, repair, atol
        As in :func:`eulerlib.matrix_to_euler`: check that ``R`` holds rotations within
        ``atol`` (default), or start from the nearest rotations (which also undoes the drift
        that rounding leaves after many steps).

    Returns
    -------
    ndarray, shape (broadcast leading shape, 3, 3)
        The attitudes at the end of the step. The leading shapes of ``R``, ``omega`` (without
        its last axis) and ``dt`` broadcast: one attitude with many rates or steps, or one of
        each per body.

    Raises
    ------
    TypeError
        If an argument is not real numbers, ``frame`` is not a string, or a flag is not a bool.
    ValueError
        If a shape is wrong, the leading shapes do not broadcast, a value is NaN or infinite,
        ``omega * dt`` overflows or has a length above the largest float, ``R`` is not a
        rotation within ``atol`` (or cannot be repaired), ``frame`` is not one of the accepted
        words, or ``atol`` is not a finite number ≥ 0.

    Notes
    -----
    ``exp([ω dt]×)`` is the rotation by ``|ω| dt`` about ``ω``, computed by
    :func:`eulerlib.rotvec_to_matrix` from the half-angle form of Rodrigues' formula, accurate
    for turns of any size, from 1e-300 rad to many turns. The step is exact for a constant
    rate (see the module docstring). SciPy's equivalent is
    ``Rotation.from_matrix(R) * Rotation.from_rotvec(omega * dt)`` (body frame).

    Examples
    --------
    >>> import numpy as np
    >>> from eulerlib import rot_z
    >>> R = np.eye(3)
    >>> for _ in range(90):                     # 1°/s about the body's z axis, for 90 s
    ...     R = integrate_angular_velocity(R, [0, 0, 1], 1.0, degrees=True)
    >>> bool(np.allclose(R, rot_z(90, degrees=True), atol=1e-14))
    True
    >>> tilted = rot_z(90, degrees=True)           # many bodies, one step each
    >>> integrate_angular_velocity(tilted, [[0.1, 0, 0], [0, 0.1, 0]], 2.0).shape
    (2, 3, 3)
    """
    in_space = check_choice(frame, "frame", FRAMES) == "space"
    in_degrees = check_flag(degrees, "degrees")
    check = rotation_check(validate, repair, atol)
    if _compiled.operations is not None and not check.repair:
        compiled = _compiled_steps(R, omega, dt, in_degrees, in_space, check)
        if compiled is not None:
            return compiled
    one_R, one_omega, one_dt = _scalar.rotation(R, check), _scalar.vector(omega), None
    if one_R is not None and one_omega is not None:
        one_dt = _scalar.number(dt)
    if one_R is not None and one_omega is not None and one_dt is not None:
        with np.errstate(over="ignore", invalid="ignore"):
            turn = (one_omega[0] * one_dt, one_omega[1] * one_dt, one_omega[2] * one_dt)
        one_step = rotvec_to_entries(turn, in_degrees) if _scalar.finite(turn) else None
        if one_step is not None:  # one step in Python floats, then the same product
            pair = (one_step, one_R) if in_space else (one_R, one_step)
            return _scalar.as_array(product_of_two(*pair), (3, 3))
    matrices = as_rotations(R, "R", check)
    rates = as_vectors(omega, "omega")
    steps = as_float_array(dt, "dt")
    leads = (matrices.shape[:-2], rates.shape[:-1], steps.shape)
    shape = broadcast_shape({"R": leads[0], "omega": leads[1], "dt": leads[2]})
    flat_R = matrices.reshape(-1, 3, 3)
    flat_omega, flat_dt = rates.reshape(-1, 3), steps.reshape(-1)
    out = np.empty((math.prod(shape), 3, 3))
    out_entries = out.reshape(-1, 9).T  # (9, n), a view
    for block, (on_R, on_omega, on_dt) in broadcast_blocks(shape, leads):
        with np.errstate(over="ignore", invalid="ignore"):
            turns = flat_omega[on_omega].T * flat_dt[on_dt]  # rotation vectors, shape (3, n)
        _refuse_overflow(turns, shape, block.start, on_omega, on_dt)
        rows = np.ascontiguousarray(turns)
        length = lengths(rows)
        refuse_overlong(length, "omega * dt", shape, block)
        step = rotvecs_to_entries(rows, in_degrees, length)
        start = flat_R[on_R].reshape(-1, 9).T  # rows of entries, a view where on_R is a slice
        # entry by entry in a fixed order, as the path of one step and the compiled kernel
        # (a BLAS product may add in another order, or fuse a multiply with an add)
        target = out_entries[:, block]
        if in_space:
            product(step, start, target)
        else:
            product(start, step, target)
        target += 0.0  # no negative zeros
    return out.reshape(*shape, 3, 3)


def _compiled_steps(
    R: ArrayLike,
    omega: ArrayLike,
    dt: ArrayLike,
    in_degrees: bool,
    in_space: bool,
    check: RotationCheck,
) -> NDArray[np.float64] | None:
    """The steps in two compiled stages around numpy's tangent (the path of one step for a
    whole batch), or None for what the kernels do not take: the paths of
    :func:`integrate_angular_velocity` then give the result or the refusal."""
    kernels = _compiled.operations
    matrices, rates = _compiled.batch(R, (3, 3)), _compiled.batch(omega, (3,))
    if matrices is None or rates is None:
        return None
    number = _scalar.number(dt)
    steps = np.array([number]) if number is not None else _compiled.batch(dt, ())
    if steps is None:
        return None
    dt_shape = () if number is not None else steps.shape
    lead = common_lead((matrices.shape[:-2], rates.shape[:-1], dt_shape))
    if lead is None:
        return None
    count = math.prod(lead)
    flat_R, flat_omega = matrices.reshape(-1, 3, 3), rates.reshape(-1, 3)
    flat_dt = steps.reshape(-1)
    out = np.empty((*lead, 3, 3))
    flat_out = out.reshape(-1, 3, 3)
    size = min(count, BLOCK_SIZE)  # what the stages hold between them: one block
    half_rows, turn_rows = np.empty(size), np.empty((size, 5))
    for block in block_slices(count):
        size = block.stop - block.start
        half, turns = half_rows[:size], turn_rows[:size]
        start = block_part(flat_R, block)
        taken = kernels.integration_turns(
            half,
            turns,
            start,
            block_part(flat_omega, block),
            block_part(flat_dt, block),
            in_degrees,
            check.validate,
            check.atol,
        )
        if not taken or not kernels.integration_steps(
            flat_out[block], start, turns, np.tan(half), in_degrees, in_space
        ):
            return None
    return out


def _refuse_overflow(
    turns: NDArray[np.float64],
    shape: tuple[int, ...],
    offset: int,
    on_omega: slice | NDArray[np.intp],
    on_dt: slice | NDArray[np.intp],
) -> None:
    """Raise ``ValueError`` if some ``omega * dt`` of a block is not finite (it overflowed)."""
    with np.errstate(over="ignore", invalid="ignore"):
        if math.isfinite(float(np.sum(turns))):  # the usual case: one sum, no temporary
            return
    overflowed = np.flatnonzero(~np.all(np.isfinite(turns), axis=0))
    if not overflowed.size:  # only the sum overflowed
        return
    bad = int(overflowed[0])
    raise ValueError(
        f"omega * dt overflows{_index_text(shape, offset + bad)} (omega at flat index "
        f"{selected_index(on_omega, bad)}, dt at flat index {selected_index(on_dt, bad)}): "
        "the turn of one step must be a finite number"
    )
