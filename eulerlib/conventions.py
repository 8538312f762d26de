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

from __future__ import annotations

import math
from typing import Any, Literal, NamedTuple, TypeVar, overload

from numpy.typing import NDArray

from eulerlib.sequences import ALL_SEQUENCES, Sequence, parse_sequence, sequence_problem

__all__ = [
    "CONVENTIONS",
    "PRESET_ALIASES",
    "Convention",
    "LockedAngle",
    "get_convention",
]

_Item = TypeVar("_Item")

#: Which angle, in argument order, is set to 0 at gimbal lock.
LockedAngle = Literal["first", "third"]


class Convention(NamedTuple):
    """An Euler-angle convention with a name, angle names and a lock policy.

    Attributes
    ----------
    name : str
        Preset name (``"rose"``) or, for a bare sequence, the sequence itself.
    seq : str
        Axis sequence as in SciPy's ``Rotation.from_euler`` (uppercase intrinsic, lowercase
        extrinsic); angle ``i`` goes with letter ``i``.
    angle_names : tuple of str
        Names of the three angles in argument order, for example ``("yaw", "pitch", "roll")``.
    up_axis : str or None
        The axis that points up in the convention's frame: ``"z"``, ``"y"``, or ``"-z"`` when z
        points down (x is forward in all three); None when the convention does not say (a bare
        sequence).
    description : str
        One sentence saying where the convention comes from and what it means.
    lock_zeroes : {'first', 'third'}
        The angle, in argument order, set to 0 at gimbal lock.

    Examples
    --------
    >>> rose = CONVENTIONS["rose"]
    >>> rose.seq, rose.angle_names, rose.up_axis, rose.lock_zeroes
    ('ZYX', ('yaw', 'pitch', 'roll'), 'z', 'first')
    >>> rose.zeroed_name, rose.carrier_name, rose.zeroed_index
    ('yaw', 'roll', 0)
    >>> rose.label, rose.poles
    ('rose (ZYX)', (90, -90))
    >>> CONVENTIONS["ros"].to_intrinsic(CONVENTIONS["ros"].angle_names)
    ('yaw', 'pitch', 'roll')
    """

    name: str
    seq: str
    angle_names: tuple[str, str, str]
    up_axis: str | None
    description: str
    lock_zeroes: LockedAngle

    @property
    def parsed(self) -> Sequence:
        """The axis sequence, parsed."""
        return parse_sequence(self.seq)

    @property
    def zeroed_index(self) -> int:
        """Position, in argument order, of the angle set to 0 at gimbal lock: 0 or 2."""
        return 0 if self.lock_zeroes == "first" else 2

    @property
    def carrier_index(self) -> int:
        """Position, in argument order, of the angle that carries the whole turn at lock."""
        return 2 - self.zeroed_index

    @property
    def zeroed_name(self) -> str:
        """Name of the angle set to 0 at gimbal lock."""
        return self.angle_names[self.zeroed_index]

    @property
    def carrier_name(self) -> str:
        """Name of the angle that carries the whole turn at gimbal lock."""
        return self.angle_names[self.carrier_index]

    @property
    def zeroes_intrinsic_first(self) -> bool:
        """Whether the angle set to 0 at lock is the first angle of the intrinsic form.

        The kernels work in intrinsic order; this is the policy in their terms. For a bare
        sequence it is always True (eulerlib's rule); Baker's preset makes it False.
        """
        return (self.lock_zeroes == "first") == self.parsed.intrinsic

    @overload
    def to_intrinsic(self, values: NDArray[Any]) -> NDArray[Any]: ...
    @overload
    def to_intrinsic(self, values: tuple[_Item, _Item, _Item]) -> tuple[_Item, _Item, _Item]: ...
    def to_intrinsic(self, values: Any) -> Any:
        """Angles in argument order (the last axis of an array, or a tuple) in intrinsic order.

        Reversed for an extrinsic sequence, unchanged for an intrinsic one
        (:meth:`eulerlib.sequences.Sequence.intrinsic_order`).
        """
        return self.parsed.intrinsic_order(values)

    @overload
    def from_intrinsic(self, values: NDArray[Any]) -> NDArray[Any]: ...
    @overload
    def from_intrinsic(self, values: tuple[_Item, _Item, _Item]) -> tuple[_Item, _Item, _Item]: ...
    def from_intrinsic(self, values: Any) -> Any:
        """Angles in intrinsic order back in argument order; the inverse of :meth:`to_intrinsic`."""
        return self.parsed.intrinsic_order(values)

    @property
    def label(self) -> str:
        """``"ZYX"`` for a bare sequence, ``"rose (ZYX)"`` for a named convention."""
        if self.name == self.seq:
            return self.seq
        return f"{self.name} ({self.seq})"

    @property
    def quoted_label(self) -> str:
        """The label for prose: ``"'ZYX'"``, or ``"'rose' (seq 'ZYX')"`` for a named convention."""
        if self.name == self.seq:
            return repr(self.seq)
        return f"{self.name!r} (seq {self.seq!r})"

    @property
    def poles(self) -> tuple[int, int]:
        """The singular middle angles, in degrees: (90, -90) for Tait–Bryan, (0, 180) for proper."""
        return (0, 180) if self.parsed.proper else (90, -90)

    def pole(self, middle: float) -> int:
        """The singular middle angle (degrees) nearest to a middle angle given in radians.

        ``middle`` lies in [-π/2, π/2] (Tait–Bryan) or [0, π] (proper Euler), as the
        conversions return it.
        """
        if self.parsed.proper:
            return 0 if middle < math.pi / 2 else 180
        return 90 if middle > 0 else -90


def default_lock_zeroes(parsed: Sequence) -> LockedAngle:
    """eulerlib's rule for a bare sequence: the first angle of the intrinsic form gives way."""
    return "first" if parsed.intrinsic else "third"


_ROSE = Convention(
    "rose",
    "ZYX",
    ("yaw", "pitch", "roll"),
    "z",
    "Rose (2015): yaw about z, pitch about the new y, roll about the newest x; "
    "R = Rz(yaw) Ry(pitch) Rx(roll), z up; yaw set to 0 at gimbal lock (eq 4)",
    "first",
)
_AEROSPACE = Convention(
    "aerospace",
    "ZYX",
    ("yaw", "pitch", "roll"),
    "-z",
    "aerospace 3-2-1 in the aircraft's body frame (x forward, y right, z down, NED): yaw about "
    "z, pitch about the new y, roll about the newest x; R = Rz(yaw) Ry(pitch) Rx(roll); "
    "yaw set to 0 at gimbal lock",
    "first",
)
_BAKER = Convention(
    "baker",
    "YZX",
    ("heading", "attitude", "bank"),
    "y",
    "Baker (euclideanspace.com): heading about y, attitude about the new z, bank about the "
    "newest x; R = Ry(heading) Rz(attitude) Rx(bank), y up; bank set to 0 at the poles",
    "third",
)
_ROS = Convention(
    "ros",
    "xyz",
    ("roll", "pitch", "yaw"),
    "z",
    "ROS (REP 103, tf setRPY): roll about the fixed x, pitch about the fixed y, yaw about the "
    "fixed z; R = Rz(yaw) Ry(pitch) Rx(roll), z up (x forward, y left); yaw set to 0 at lock",
    "third",
)

#: Other names accepted for a preset.
PRESET_ALIASES = {"nasa": "aerospace"}

#: Preset name → :class:`Convention`. Aliases map to the same object as the preset they name.
CONVENTIONS: dict[str, Convention] = {
    "rose": _ROSE,
    "aerospace": _AEROSPACE,
    "baker": _BAKER,
    "ros": _ROS,
}
CONVENTIONS.update({alias: CONVENTIONS[target] for alias, target in PRESET_ALIASES.items()})

_AXIS_LETTERS = "xyz"


def _from_sequence(parsed: Sequence) -> Convention:
    letters = [_AXIS_LETTERS[axis] for axis in parsed.axes]
    if parsed.intrinsic:
        names = (letters[0], letters[1] + "'", letters[2] + "''")
        kind = "intrinsic (moving axes)"
    else:
        third = letters[2] + "2" if parsed.proper else letters[2]
        names = (letters[0], letters[1], third)
        kind = "extrinsic (fixed axes)"
    family = "proper Euler" if parsed.proper else "Tait-Bryan"
    description = f"{kind} {family} sequence {'-'.join(letters)}, as SciPy reads {parsed.seq!r}"
    return Convention(parsed.seq, parsed.seq, names, None, description, default_lock_zeroes(parsed))


_SEQUENCE_CONVENTIONS = {seq: _from_sequence(parse_sequence(seq)) for seq in ALL_SEQUENCES}


def _checked(convention: Convention, name: str) -> Convention:
    """A convention made by the caller, checked field by field."""
    parse_sequence(convention.seq)
    names = convention.angle_names
    if not (
        isinstance(names, tuple)
        and len(names) == 3
        and all(isinstance(item, str) and item for item in names)
        and len(set(names)) == 3
    ):
        raise ValueError(
            f"{name}.angle_names must be three different non-empty strings, got {names!r}"
        )
    if convention.lock_zeroes not in ("first", "third"):
        raise ValueError(
            f"{name}.lock_zeroes must be 'first' or 'third' (the angle set to 0 at gimbal "
            f"lock), got {convention.lock_zeroes!r}"
        )
    if convention.up_axis not in (None, "y", "z", "-z"):
        raise ValueError(
            f"{name}.up_axis must be 'y', 'z', '-z' or None, got {convention.up_axis!r}"
        )
    return convention


def get_convention(seq: object, name: str = "seq") -> Convention:
    """The convention named by a preset name or an axis sequence.

    Parameters
    ----------
    seq : str or Convention
        A preset name, any letter case (``"rose"``, ``"Baker"``, ``"ROS"``, ``"aerospace"``),
        or one of the 24 axis sequences exactly as SciPy spells them (``"ZYX"``, ``"xyz"``;
        the case of a sequence matters: uppercase is intrinsic, lowercase extrinsic). A
        :class:`Convention` is returned unchanged.
    name : str, optional
        The argument's name, for messages.

    Returns
    -------
    Convention

    Raises
    ------
    TypeError
        If ``seq`` is neither a string nor a Convention.
    ValueError
        If it is neither a preset nor a valid sequence; the message lists both.

    Examples
    --------
    >>> get_convention("ROS").angle_names
    ('roll', 'pitch', 'yaw')
    >>> get_convention("ZXZ").angle_names
    ('z', "x'", "z''")
    >>> get_convention("zxz").angle_names
    ('z', 'x', 'z2')
    >>> get_convention("yzx").description
    "extrinsic (fixed axes) Tait-Bryan sequence y-z-x, as SciPy reads 'yzx'"
    """
    if isinstance(seq, Convention):
        return _checked(seq, name)
    if not isinstance(seq, str):
        raise TypeError(
            f"{name} must be a convention: a preset name such as 'rose' or an axis sequence "
            f"such as 'ZYX' (a string), got {type(seq).__name__}"
        )
    if seq in _SEQUENCE_CONVENTIONS:
        return _SEQUENCE_CONVENTIONS[seq]
    key = seq.strip().lower()
    if key in CONVENTIONS:
        return CONVENTIONS[key]
    presets = ", ".join(CONVENTIONS)
    raise ValueError(
        f"{name} {seq!r} is neither a preset ({presets}; any letter case) nor a valid axis "
        f"sequence ({sequence_problem(seq)}). An axis sequence is three letters from x, y, z "
        "with no two neighbours alike, all uppercase for intrinsic (moving axes) or all "
        f"lowercase for extrinsic (fixed axes): {', '.join(ALL_SEQUENCES)}"
    )
