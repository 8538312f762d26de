"""Gimbal lock reported: the tolerance, the combination that stays defined, and the warning.

The public face is :mod:`eulerlib.gimbal_lock`, which explains the lock and re-exports
:data:`GIMBAL_LOCK_TOLERANCE`, :func:`lock_combination` and :class:`GimbalLockWarning`; the
conversions call :func:`warn_if_locked`, or gather the facts block by block in a
:class:`LockTally` when they keep no lock mask of the whole batch.
"""

from __future__ import annotations

import math
import os
import sys
import warnings

import numpy as np
from numpy.typing import NDArray

from eulerlib._conventions import Convention, get_convention
from eulerlib._euler_kernels import frame

#: A matrix is in gimbal lock when its middle angle is within this many radians of the
#: singular value (±π/2 for Tait–Bryan, 0 or π for proper Euler). 2⁻⁴⁹ ≈ 1.8e-15 is eight units
#: in the last place of 1: about four times the distance that ordinary rounding noise puts
#: between a lock matrix and the lock (measured on ``Q @ Q.T @ R``), and small enough that
#: setting the first angle to 0 moves no entry of the rebuilt matrix by more than 2 × 2⁻⁴⁹.
GIMBAL_LOCK_TOLERANCE = 2.0**-49


def lock_combination(convention: Convention | str, pole: float) -> tuple[int, str]:
    """The combination of the outer angles that a locked matrix still defines.

    Parameters
    ----------
    convention : Convention or str
        A convention or anything :func:`eulerlib.get_convention` accepts.
    pole : {90, -90, 0, 180}
        The singular middle angle, in degrees: ±90 for Tait–Bryan, 0 or 180 for proper Euler.

    Returns
    -------
    sign : int
        ``+1`` or ``-1``: at this pole the matrix depends on ``third + sign · first`` only,
        with first and third in argument order.
    words : str
        The same, with the convention's angle names, for example ``"roll − yaw"``.

    Examples
    --------
    >>> lock_combination("rose", 90)
    (-1, 'roll - yaw')
    >>> lock_combination("rose", -90)
    (1, 'yaw + roll')
    >>> lock_combination("ZXZ", 180)
    (-1, "z'' - z")
    """
    chosen = get_convention(convention, "convention")
    parsed = chosen.parsed
    if isinstance(pole, (bool, np.bool_)) or not isinstance(
        pole, (int, float, np.integer, np.floating)
    ):
        raise TypeError(f"pole must be a number of degrees, got {pole!r} ({type(pole).__name__})")
    if parsed.proper:
        if pole not in (0, 180):
            raise ValueError(f"pole must be 0 or 180 for {chosen.seq!r}, got {pole!r}")
        sign = 1 if pole == 0 else -1
    else:
        if pole not in (90, -90):
            raise ValueError(f"pole must be 90 or -90 for {chosen.seq!r}, got {pole!r}")
        sign = int(frame(parsed)[1][2]) * (1 if pole > 0 else -1)
    # in intrinsic order the matrix depends on third + sign·first; written order reverses an
    # extrinsic sequence, which swaps the roles of the two names but not the sign
    first, _, third = chosen.angle_names
    if sign > 0:
        return 1, f"{first} + {third}"
    if parsed.intrinsic:
        return -1, f"{third} - {first}"
    return -1, f"{first} - {third}"


class GimbalLockWarning(UserWarning):
    """Some matrices were in gimbal lock, and one outer angle was set to 0 for each of them.

    Attributes
    ----------
    convention : Convention
        The convention the angles were asked in (for a bare ``seq``, its own convention).
    seq : str
        Its axis sequence.
    count, total : int
        How many of how many rotations were locked.
    zeroed : str
        Name of the angle set to 0 (``convention.zeroed_name``).
    zeroed_position : int
        Its position in argument order: 0 (the first angle) or 2 (the third).
    carrier : str
        Name of the angle that carries the whole turn.
    combinations : dict
        For each pole met (the singular middle angle in degrees: 90, -90, 0 or 180), the
        combination of the outer angles that stays defined there, in words.
    rates : bool
        False when angles were computed (the angle ``zeroed`` was set to 0); True when angle
        *rates* were (:func:`eulerlib.angular_velocity_to_euler_rates`): then the rate of
        ``zeroed`` was set to 0, the rate of ``carrier`` carries the whole turn, and the part
        of the angular velocity that no angle rates can produce at lock was left out.

    Examples
    --------
    >>> import warnings, eulerlib
    >>> R = eulerlib.euler_to_matrix([30, 90, 10], "rose", degrees=True)
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     _ = eulerlib.matrix_to_euler(R, "rose")
    >>> facts = caught[0].message
    >>> facts.count, facts.zeroed, facts.carrier, facts.combinations
    (1, 'yaw', 'roll', {90: 'roll - yaw'})
    >>> print(facts)
    gimbal lock in 1 of 1 rotation(s) for 'rose' (seq 'ZYX'): pitch is at 90°, so yaw and roll
    turn about the same axis and only roll - yaw is defined; yaw (angle 1) was set to 0 and roll
    carries the whole turn
    """

    def __init__(
        self,
        convention: Convention,
        count: int,
        total: int,
        poles: tuple[int, ...],
        rates: bool = False,
    ) -> None:
        self.convention = convention
        self.seq = convention.seq
        self.count = count
        self.total = total
        self.zeroed = convention.zeroed_name
        self.zeroed_position = convention.zeroed_index
        self.carrier = convention.carrier_name
        self.poles = poles
        self.combinations = {pole: lock_combination(convention, pole)[1] for pole in poles}
        self.rates = rates
        super().__init__(self._words())

    def _words(self) -> str:
        chosen = self.convention
        label = chosen.quoted_label
        first, middle, third = chosen.angle_names
        poles = " or ".join(f"{pole}°" for pole in self.combinations)
        situation = (
            f"gimbal lock in {self.count} of {self.total} rotation(s) for {label}: {middle} is "
            f"at {poles}, so {first} and {third} turn about the same axis"
        )
        rate = "the rate of " if self.rates else ""
        if len(self.combinations) == 1:
            (combination,) = self.combinations.values()
            defined = f"only {rate}{combination} is defined"
        else:  # both poles met: each has its own combination, named with the pole
            each = ", ".join(f"{words} at {pole}°" for pole, words in self.combinations.items())
            defined = f"at each pole only {rate}one combination of them is defined ({each})"
        position = f"(angle {self.zeroed_position + 1})"
        if self.rates:
            return (
                f"{situation} and {defined}; the rate of {self.zeroed} {position} was set to 0, "
                f"the rate of {self.carrier} carries the whole turn, and the part of the angular "
                "velocity that no angle rates can produce was left out"
            )
        return (
            f"{situation} and {defined}; {self.zeroed} {position} was set to 0 and "
            f"{self.carrier} carries the whole turn"
        )

    def __reduce__(self) -> tuple[object, ...]:  # so that a warning can be pickled and rebuilt
        return (type(self), (self.convention, self.count, self.total, self.poles, self.rates))


_PACKAGE = os.path.dirname(os.path.abspath(__file__)) + os.sep


def _stacklevel_outside_package() -> int:
    """``stacklevel`` for :func:`warnings.warn` that points at the first caller outside eulerlib."""
    level, caller = 1, sys._getframe(1)
    while caller is not None and os.path.abspath(caller.f_code.co_filename).startswith(_PACKAGE):
        caller = caller.f_back  # type: ignore[assignment]
        level += 1
    return level


class LockTally:
    """What the gimbal-lock warning of one call says, gathered block by block.

    A call that converts many rotations in blocks adds each block's lock mask and middle
    angles with :meth:`add`, then :meth:`warn` emits the one warning of the call. Only three
    numbers are kept, whatever the size of the batch: how many rotations are locked, and the
    least and greatest middle angle among them, which tell the poles.
    """

    def __init__(self) -> None:
        self.count = 0
        self.low = math.inf
        self.high = -math.inf

    def add(self, locked: NDArray[np.bool_], middle: NDArray[np.float64]) -> None:
        """Count the locked rotations of a block; ``middle`` holds their middle angles in
        radians, in [-π/2, π/2] for Tait–Bryan, [0, π] for proper Euler (other entries are
        not read)."""
        count = int(np.count_nonzero(locked))
        if count:
            at_lock = middle[locked]
            self.count += count
            self.low = min(self.low, float(at_lock.min()))
            self.high = max(self.high, float(at_lock.max()))

    def warn(self, convention: Convention, total: int, rates: bool = False) -> None:
        """Emit one :class:`GimbalLockWarning` if a rotation of the ``total`` was locked.

        ``rates`` says that angle rates, not angles, were computed (see
        :attr:`GimbalLockWarning.rates`).
        """
        if not self.count:
            return
        found = {convention.pole(angle) for angle in (self.low, self.high)}
        poles = tuple(pole for pole in convention.poles if pole in found)
        warning = GimbalLockWarning(convention, self.count, total, poles, rates)
        warnings.warn(warning, stacklevel=_stacklevel_outside_package())


def warn_if_locked(
    convention: Convention,
    locked: NDArray[np.bool_],
    middle: NDArray[np.float64],
    rates: bool = False,
) -> None:
    """Emit one :class:`GimbalLockWarning` if any rotation is locked.

    ``middle`` holds the middle angles in radians, the same shape as ``locked``, as
    :meth:`LockTally.add` reads them; ``rates`` as in :meth:`LockTally.warn`.
    """
    tally = LockTally()
    tally.add(locked, middle)
    tally.warn(convention, int(locked.size), rates)
