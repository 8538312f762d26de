"""Named Euler-angle conventions: which axes, in which order, and which angle gives way at lock.

Three angles mean nothing until their convention is named: which axes, in which order, about
fixed or moving axes, which angle comes first in the argument list, which axis points up, and
which angle is set to 0 when gimbal lock leaves only a combination of two of them defined.
A :class:`Convention` records all of that, and every function of eulerlib that takes a
``seq`` also takes a convention's name.

The presets
-----------
``"rose"``
    D. Rose (2015), Part 2: yaw ``w`` about z, then pitch ``v`` about the new y, then roll ``u``
    about the newest x: ``R = R_z(w) R_y(v) R_x(u)`` (eq 2), ``seq="ZYX"``, angles
    ``(yaw, pitch, roll)``; yaw is set to 0 at lock (eq 4). Rose draws z up (x forward, y left).
``"aerospace"`` (alias ``"nasa"``)
    The aerospace "3-2-1" sequence: the same formula and lock policy as Rose's, in the body frame
    of an aircraft, x forward, y right, z *down* (north-east-down). Only the frame differs, and
    with it what a positive angle looks like: a positive pitch raises the nose (it lowers it in
    Rose's z-up frame), a positive yaw turns it right. ``up_axis`` is ``"-z"``.
``"baker"``
    M. J. Baker, "Maths - Conversion Matrix to Euler": heading about y, then attitude about the
    new z, then bank about the newest x: ``R = R_y(h) R_z(a) R_x(b)``, ``seq="YZX"``, angles
    ``(heading, attitude, bank)``, y up; bank is set to 0 at the poles, as Baker does.
``"ros"``
    Roll, pitch, yaw as ROS uses them (REP 103, ``tf``'s ``setRPY``): roll about the fixed x,
    then pitch about the fixed y, then yaw about the fixed z, ``seq="xyz"`` with angles
    ``(roll, pitch, yaw)``. That is Rose's matrix with the argument order reversed, z up
    (x forward, y left); yaw is set to 0 at lock, as for Rose.

Any of SciPy's 24 ``seq`` strings (``"ZYX"``, ``"xyz"``, ``"ZXZ"``, …) is a convention too, with
angles named after their axes: ``z, y', x''`` for an intrinsic sequence (each prime marks an
axis that has moved), ``x, y, z`` for an extrinsic one (a repeated fixed axis gets a 2:
``z, x, z2``).

The lock policy
---------------
At gimbal lock only the sum or difference of the first and third angles is defined, so one of
them is set to 0 and the other carries the whole turn. :attr:`Convention.lock_zeroes` says
which, in argument order. For a bare sequence the rule is eulerlib's: **the first angle of the
intrinsic form** is set to 0, which is the first angle of an intrinsic sequence and the last
angle of an extrinsic one. So ``"ZYX"`` and ``"xyz"`` (the same rotations with the angles
reversed) give identical numbers at lock too, and for ``"ZYX"`` the rule is Rose's (yaw = 0).
Baker's preset keeps Baker's own choice (bank = 0). This module is the only place that rule is
written down, and what follows from it is read from the :class:`Convention` by every path
(matrices, quaternions, rates, conversion, plots, the command line): the position of the angle
set to 0 (:attr:`Convention.zeroed_index`), the same policy in the intrinsic order the kernels
work in (:attr:`Convention.zeroes_intrinsic_first`), the reversal of the angles of a fixed-axis
sequence (:meth:`Convention.to_intrinsic`, :meth:`Convention.from_intrinsic`), the poles and the
label. :mod:`eulerlib.gimbal_lock` words it.

Examples
--------
>>> get_convention("Baker").seq
'YZX'
>>> get_convention("xyz").lock_zeroes      # the last written angle, the intrinsic first
'third'
>>> get_convention("nasa").up_axis      # the aerospace body frame: z points down
'-z'
"""

from eulerlib._conventions import (
    CONVENTIONS,
    PRESET_ALIASES,
    Convention,
    LockedAngle,
    get_convention,
)

__all__ = [
    "CONVENTIONS",
    "PRESET_ALIASES",
    "Convention",
    "LockedAngle",
    "get_convention",
]
