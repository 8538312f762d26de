"""Euler-angle rates and angular velocity: how fast the angles change when a body turns.

A body whose three Euler angles change at the rates ``(α̇, β̇, γ̇)`` turns with an angular velocity
``ω`` that is linear in the rates: ``ω = J (α̇, β̇, γ̇)``. Each rate turns the body about its own
axis, *as that axis lies when its rotation happens*. For the intrinsic form
``R = A(α) B(β) C(γ)`` about the axes ``e_A``, ``e_B``, ``e_C``:

* in the fixed (space) frame, ``ω = α̇ e_A + β̇ A e_B + γ̇ A B e_C``: the first axis stays put,
  the second has been moved by the first turn, the third by the first two;
* in the body's own axes (what a gyroscope measures), ``ω_body = Rᵀ ω``, that is
  ``α̇ Cᵀ Bᵀ e_A + β̇ Cᵀ e_B + γ̇ e_C``.

An extrinsic sequence is the intrinsic one with the angles reversed, so its rates are reversed
too. For Rose's yaw ``w``, pitch ``v`` and roll ``u`` (``"ZYX"``) the body rates are the
aircraft's ``p, q, r``::

    p = u̇ − ẇ sin v
    q = v̇ cos u + ẇ sin u cos v
    r = −v̇ sin u + ẇ cos u cos v

Why the rates blow up at gimbal lock
------------------------------------
Going back, from ``ω`` to the rates, means solving ``J θ̇ = ω``. The determinant of ``J`` is
``±cos β`` for a Tait–Bryan sequence and ``±sin β`` for a proper Euler one: the same factor that
vanishes at gimbal lock. For yaw-pitch-roll the solution is::

    ẇ = (q sin u + r cos u) / cos v
    v̇ = q cos u − r sin u
    u̇ = p + ẇ sin v

As the pitch nears ±90° a fixed angular velocity needs yaw and roll rates that grow like
``1 / cos v``; at ±90° itself the first and third axes coincide, one direction of ``ω`` cannot
be produced by any rates, and only the rate of the sum or difference of the outer angles is
defined. :func:`angular_velocity_to_euler_rates` then follows the convention's lock policy, the
same one :func:`eulerlib.matrix_to_euler` follows for the angles (:mod:`eulerlib.conventions`):
the rate of the angle that is set to 0 there is 0, the other outer angle carries the whole rate
of the combination, the middle rate is the least-squares one, and the part of ``ω`` along the
lost direction is left out; one :class:`eulerlib.GimbalLockWarning` says so. A rotation counts as
locked when its middle angle lies within :data:`eulerlib.GIMBAL_LOCK_TOLERANCE` of the pole, as
in every conversion; :func:`eulerlib.gimbal_lock_status` tells how near a rotation is.

How it is computed
------------------
As in :mod:`eulerlib.euler`, every sequence is relabelled to x-y-z or x-y-x by a signed
permutation ``P`` that is a rotation, ``R = P M Pᵀ``. Then ``Rᵀ Ṙ = P (Mᵀ Ṁ) Pᵀ``, so the angular
velocity of ``R`` is ``P`` times that of ``M``, and only two shapes of Jacobian are written out.
The formulas above, and the inverse, are evaluated entry by entry on blocks of rotations, with
sines and cosines of degrees reduced exactly (:mod:`eulerlib._trig`). Everything is linear in the
rates, so with ``degrees=True`` angles are read in degrees and rates and ``ω`` are in degrees
per unit of time, with no conversion of the rates at all.

SciPy has no function for Euler-angle rates; the tests compare with the Jacobian that
:func:`eulerlib.symbolic.angular_velocity_jacobian` derives in SymPy, with ``ω`` read off
``Ṙ Rᵀ`` by finite differences of SciPy's matrices, and with a 50-digit reference.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._broadcast import broadcast_blocks, broadcast_shape
from eulerlib._euler_kernels import frame as relabelling
from eulerlib._lock import GIMBAL_LOCK_TOLERANCE, LockTally
from eulerlib._overflow import overflowed, rescaled
from eulerlib._trig import sin_cos
from eulerlib._validation import as_vectors, check_choice, check_flag
from eulerlib.conventions import Convention, get_convention
from eulerlib.sequences import Sequence

__all__ = ["FRAMES", "angular_velocity_to_euler_rates", "euler_rates_to_angular_velocity"]

Array = NDArray[np.float64]

#: The frames an angular velocity can be written in: the body's own axes or the fixed axes.
FRAMES = ("body", "space")


def euler_rates_to_angular_velocity(
    angles: ArrayLike,
    rates: ArrayLike,
    seq: str | Convention = "ZYX",
    *,
    frame: str = "body",
    degrees: bool = False,
) -> Array:
    """Angular velocity of a body whose Euler angles change at the given rates.

    Parameters
    ----------
    angles : array_like, shape (..., 3)
        The Euler angles at the instant, angle ``i`` with letter ``i`` of ``seq``.
    rates : array_like, shape (..., 3)
        Their rates of change, in the same order, per unit of time. The leading shapes of
        ``angles`` and ``rates`` broadcast: one attitude with many rates, or one per attitude.
    seq : str or Convention, optional
        Axis sequence or preset (see :func:`eulerlib.euler_to_matrix`). Default ``"ZYX"``:
        yaw, pitch, roll.
    frame : {'body', 'space'}, optional
        Write ``ω`` in the body's own axes (default; what a gyroscope strapped to the body
        measures) or in the fixed axes. Any letter case.
    degrees : bool, optional
        Angles in degrees, and rates and ``ω`` in degrees per unit of time.

    Returns
    -------
    ndarray, shape (broadcast leading shape, 3)
        The angular velocity ``ω``, with ``Rᵀ Ṙ = [ω]×`` (body) or ``Ṙ Rᵀ = [ω]×`` (space), where
        ``R = euler_to_matrix(angles, seq)``.

    Raises
    ------
    TypeError
        If ``angles`` or ``rates`` is not real numbers, ``seq`` or ``frame`` is not a string,
        or ``degrees`` is not a bool.
    ValueError
        If a shape is wrong, the leading shapes do not broadcast, a value is NaN or infinite,
        ``seq`` or ``frame`` is not one of the accepted words, or ``rates`` is so large that a
        component of ``ω`` would be above the largest float (about 1.8e308).

    Notes
    -----
    ``ω = J θ̇`` with the Jacobian of :func:`eulerlib.symbolic.angular_velocity_jacobian`
    (column ``i``: the axis of rotation ``i`` as it lies when that rotation happens). For
    ``"ZYX"`` with Rose's (2015, Part 2, eq 2) yaw ``w``, pitch ``v`` and roll ``u``, the body
    rates are ``p = u̇ − ẇ sin v``, ``q = v̇ cos u + ẇ sin u cos v``,
    ``r = −v̇ sin u + ẇ cos u cos v``. SciPy has no equivalent. See the module docstring.

    Examples
    --------
    >>> import numpy as np
    >>> euler_rates_to_angular_velocity([0, 0, 0], [1, 2, 3])   # at rest: (roll, pitch, yaw)
    array([3., 2., 1.])
    >>> # pitched up 90°: a yaw rate turns the body about its own x axis, as a roll would
    >>> euler_rates_to_angular_velocity([0, -90, 0], [10, 0, 0], degrees=True)
    array([10.,  0.,  0.])
    >>> euler_rates_to_angular_velocity([0, -90, 0], [10, 0, 0], frame="space", degrees=True)
    array([ 0.,  0., 10.])
    """
    convention = get_convention(seq)
    in_space = check_choice(frame, "frame", FRAMES) == "space"
    in_degrees = check_flag(degrees, "degrees")
    values = as_vectors(angles, "angles")
    speeds = as_vectors(rates, "rates")
    leads = (values.shape[:-1], speeds.shape[:-1])
    shape = broadcast_shape({"angles": leads[0], "rates": leads[1]})
    flat_angles, flat_rates = values.reshape(-1, 3), speeds.reshape(-1, 3)
    parsed = convention.parsed
    out = np.empty((math.prod(shape), 3))
    for block, (on_angles, on_rates) in broadcast_blocks(shape, leads):
        out[block] = _omega_of_block(
            flat_angles[on_angles], flat_rates[on_rates], parsed, in_space, in_degrees,
            shape, block.start,
        )  # fmt: skip
    return out.reshape(*shape, 3)


def angular_velocity_to_euler_rates(
    angles: ArrayLike,
    omega: ArrayLike,
    seq: str | Convention = "ZYX",
    *,
    frame: str = "body",
    degrees: bool = False,
    warn: bool = True,
) -> Array:
    """The Euler-angle rates that produce a given angular velocity at a given attitude.

    Parameters
    ----------
    angles : array_like, shape (..., 3)
        The Euler angles at the instant, angle ``i`` with letter ``i`` of ``seq``.
    omega : array_like, shape (..., 3)
        The angular velocity, in the frame ``frame``. The leading shapes of ``angles`` and
        ``omega`` broadcast.
    seq : str or Convention, optional
        Axis sequence or preset (see :func:`eulerlib.euler_to_matrix`). Default ``"ZYX"``:
        yaw, pitch, roll.
    frame : {'body', 'space'}, optional
        The axes ``omega`` is written in: the body's own (default; a gyroscope's reading) or
        the fixed ones. Any letter case.
    degrees : bool, optional
        Angles in degrees, and ``omega`` and the rates in degrees per unit of time.
    warn : bool, optional
        Emit one :class:`eulerlib.GimbalLockWarning` if some attitude is in gimbal lock
        (default).

    Returns
    -------
    ndarray, shape (broadcast leading shape, 3)
        The rates ``(α̇, β̇, γ̇)`` in the order of ``seq``, with
        ``euler_rates_to_angular_velocity(angles, rates, seq, frame=frame) == omega`` away from
        gimbal lock. Near lock the outer rates grow like ``1 / cos β`` (Tait–Bryan) or
        ``1 / sin β`` (proper Euler). At lock (middle angle within
        :data:`eulerlib.GIMBAL_LOCK_TOLERANCE` radians of its pole) they are finite, by the
        convention's lock policy: the rate of the angle :func:`eulerlib.matrix_to_euler` sets to
        0 there is 0, the other outer rate carries the whole rate of the combination that stays
        defined (:func:`eulerlib.lock_combination`), the middle rate is the least-squares one,
        and the part of ``omega`` that no rates can produce is left out.

    Raises
    ------
    TypeError
        If ``angles`` or ``omega`` is not real numbers, ``seq`` or ``frame`` is not a string,
        or a flag is not a bool.
    ValueError
        If a shape is wrong, the leading shapes do not broadcast, a value is NaN or infinite,
        ``seq`` or ``frame`` is not one of the accepted words, or ``omega`` is so large that a
        rate would be above the largest float (about 1.8e308).

    Warns
    -----
    GimbalLockWarning
        Once per call when some attitude is in gimbal lock; its attribute ``rates`` is True.

    Notes
    -----
    Solves ``J θ̇ = ω`` in closed form (see the module docstring). The determinant of ``J`` is
    ``±cos β`` (Tait–Bryan) or ``±sin β`` (proper Euler). For ``"ZYX"``, with Rose's (2015,
    Part 2, eq 2) yaw ``w``, pitch ``v`` and roll ``u`` and the body rates ``(p, q, r)``:
    ``ẇ = (q sin u + r cos u) / cos v``, ``v̇ = q cos u − r sin u``, ``u̇ = p + ẇ sin v``.
    SciPy has no equivalent.

    Examples
    --------
    >>> import numpy as np
    >>> angles = [30, 20, 10]
    >>> omega = euler_rates_to_angular_velocity(angles, [1, 2, 3], degrees=True)
    >>> angular_velocity_to_euler_rates(angles, omega, degrees=True).round(12)
    array([1., 2., 3.])
    >>> # near pitch 90° a small turn about the body's z axis needs large yaw and roll rates
    >>> angular_velocity_to_euler_rates([0, 89.9, 0], [0, 0, 1], degrees=True).round(3)
    array([572.958,   0.   , 572.957])
    """
    convention = get_convention(seq)
    in_space = check_choice(frame, "frame", FRAMES) == "space"
    in_degrees = check_flag(degrees, "degrees")
    warn_lock = check_flag(warn, "warn")
    values = as_vectors(angles, "angles")
    velocities = as_vectors(omega, "omega")
    leads = (values.shape[:-1], velocities.shape[:-1])
    shape = broadcast_shape({"angles": leads[0], "omega": leads[1]})
    flat_angles, flat_omega = values.reshape(-1, 3), velocities.reshape(-1, 3)
    parsed = convention.parsed
    zero_first = convention.zeroes_intrinsic_first
    count = math.prod(shape)
    out, tally = np.empty((count, 3)), LockTally()  # the warning keeps 3 numbers, not a mask
    for block, (on_angles, on_omega) in broadcast_blocks(shape, leads):
        out[block], locked, middle = _rates_of_block(
            flat_angles[on_angles], flat_omega[on_omega], parsed, in_space, in_degrees,
            zero_first, shape, block.start,
        )  # fmt: skip
        tally.add(locked, middle)
    if warn_lock:
        tally.warn(convention, count, rates=True)
    return out.reshape(*shape, 3)


# --- one block: the kernels, then the rare vectors whose result overflowed ----------------------


def _omega_of_block(
    angles: Array,
    rates: Array,
    parsed: Sequence,
    space: bool,
    degrees: bool,
    shape: tuple[int, ...],
    offset: int,
) -> Array:
    """:func:`_rates_to_omega`, with rates near the largest float handled as
    :mod:`eulerlib._overflow` says; ``offset`` is the block's first flat index in ``shape``."""
    with np.errstate(over="ignore", invalid="ignore"):  # huge rates: redone below
        omega = _rates_to_omega(angles, rates, parsed, space, degrees)
    bad = overflowed(omega)
    if bad.size:
        at, of = angles[bad], rates[bad]
        omega[bad] = rescaled(
            lambda scale: _rates_to_omega(at, of * scale, parsed, space, degrees),
            bad, "rates", "the angular velocity", shape, offset,
        )  # fmt: skip
    return omega


def _rates_of_block(
    angles: Array,
    omega: Array,
    parsed: Sequence,
    space: bool,
    degrees: bool,
    zero_first: bool,
    shape: tuple[int, ...],
    offset: int,
) -> tuple[Array, NDArray[np.bool_], Array]:
    """:func:`_omega_to_rates`, with ``omega`` near the largest float handled as
    :mod:`eulerlib._overflow` says; ``offset`` is the block's first flat index in ``shape``."""
    with np.errstate(over="ignore", invalid="ignore"):  # huge omega: redone below
        rates, locked, middle = _omega_to_rates(angles, omega, parsed, space, degrees, zero_first)
    bad = overflowed(rates)
    if bad.size:
        at, of = angles[bad], omega[bad]
        rates[bad] = rescaled(
            lambda scale: _omega_to_rates(at, of * scale, parsed, space, degrees, zero_first)[0],
            bad, "omega", "the Euler rates", shape, offset,
        )  # fmt: skip
    return rates, locked, middle


# --- the kernels, on one block of checked values ---------------------------------------------


def _rates_to_omega(
    angles: Array, rates: Array, parsed: Sequence, space: bool, degrees: bool
) -> Array:
    """``ω = J θ̇`` for a block: ``angles`` and ``rates`` of shape ``(n, 3)``, in ``seq`` order."""
    index, sign = relabelling(parsed)
    s, c = sin_cos(parsed.intrinsic_order(angles), degrees)
    da, db, dc = parsed.intrinsic_order(rates).T
    sa, sb, sc = s.T
    ca, cb, cc = c.T
    if parsed.proper:  # M = R_x(a) R_y(b) R_x(c)
        if space:
            w = (da + dc * cb, db * ca + dc * sa * sb, db * sa - dc * ca * sb)
        else:
            w = (da * cb + dc, da * sb * sc + db * cc, da * sb * cc - db * sc)
    else:  # M = R_x(a) R_y(b) R_z(σ c), σ = sign[2]
        sigma_dc = sign[2] * dc
        if space:
            w = (da + sigma_dc * sb, db * ca - sigma_dc * sa * cb, db * sa + sigma_dc * ca * cb)
        else:
            sg = sign[2] * sc  # sin(σ c)
            w = (da * cb * cc + db * sg, db * cc - da * cb * sg, da * sb + sigma_dc)
    out = np.empty((angles.shape[0], 3))
    for r in range(3):  # ω of R = P ω of M
        out[:, index[r]] = w[r] if sign[r] > 0 else -w[r]
    out += 0.0  # turns every -0.0 into 0.0
    return out


def _omega_to_rates(
    angles: Array,
    omega: Array,
    parsed: Sequence,
    space: bool,
    degrees: bool,
    zero_first: bool,
) -> tuple[Array, NDArray[np.bool_], Array]:
    """Solve ``J θ̇ = ω`` for a block; also return the lock mask and the middle angles (radians).

    ``angles`` and ``omega`` have shape ``(n, 3)``, the angles in ``seq`` order. ``zero_first``:
    at lock the rate of the first angle of the intrinsic form is 0 (else the third's). The
    middle angles of the locked attitudes are returned as
    :meth:`eulerlib._lock.LockTally.add` reads them (0 for the others, which it ignores).
    """
    index, sign = relabelling(parsed)
    s, c = sin_cos(parsed.intrinsic_order(angles), degrees)
    sa, sb, sc = s.T
    ca, cb, cc = c.T
    w1, w2, w3 = (omega[:, index[r]] if sign[r] > 0 else -omega[:, index[r]] for r in range(3))
    # at lock the two outer rates enter one equation, first · ȧ + third · ċ = combined, with
    # first and third ±1 (one of them the sign of the pole)
    first: float | Array
    third: float | Array
    if parsed.proper:  # det J = ±sin b
        locked = np.arctan2(np.abs(sb), np.abs(cb)) <= GIMBAL_LOCK_TOLERANCE
        middle = np.arctan2(np.abs(sb), cb, where=locked, out=np.zeros_like(sb))
        divisor = np.where(locked, 1.0, sb)
        pole = np.where(cb < 0, -1.0, 1.0)  # cos b at the pole
        if space:
            db = ca * w2 + sa * w3
            dc = (sa * w2 - ca * w3) / divisor
            da = w1 - dc * cb
            first, third, combined = 1.0, pole, w1  # at lock: ȧ + pole · ċ = w1
        else:
            db = cc * w2 - sc * w3
            da = (sc * w2 + cc * w3) / divisor
            dc = w1 - da * cb
            first, third, combined = pole, 1.0, w1  # at lock: pole · ȧ + ċ = w1
    else:  # M = R_x(a) R_y(b) R_z(σ c), det J = ±cos b
        sigma = sign[2]
        locked = np.arctan2(np.abs(cb), np.abs(sb)) <= GIMBAL_LOCK_TOLERANCE
        middle = np.arctan2(sb, np.abs(cb), where=locked, out=np.zeros_like(sb))
        divisor = np.where(locked, 1.0, cb)
        pole = np.where(sb < 0, -1.0, 1.0)  # sin b at the pole
        if space:
            db = ca * w2 + sa * w3
            turned = (ca * w3 - sa * w2) / divisor  # σ ċ
            dc = sigma * turned
            da = w1 - turned * sb
            first, third, combined = 1.0, sigma * pole, w1  # at lock: ȧ + σ pole ċ = w1
        else:
            sg = sigma * sc  # sin(σ c)
            db = sg * w1 + cc * w2
            da = (cc * w1 - sg * w2) / divisor
            dc = sigma * (w3 - da * sb)
            first, third, combined = pole, sigma, w3  # at lock: pole · ȧ + σ ċ = w3
    if np.any(locked):
        # the convention's lock policy: one rate is 0, the other carries the whole combination
        if zero_first:
            da = np.where(locked, 0.0, da)
            dc = np.where(locked, third * combined, dc)
        else:
            da = np.where(locked, first * combined, da)
            dc = np.where(locked, 0.0, dc)
    rates = np.stack([da, db, dc], axis=-1)
    rates += 0.0  # turns every -0.0 into 0.0
    return parsed.intrinsic_order(rates), locked, middle
