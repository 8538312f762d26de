"""The :class:`Convention` and its presets: the data and the one lock rule.

What a convention is, the presets and the lock policy are explained in
:mod:`eulerlib.conventions`, the public face of this module, which re-exports its names.
Every path (matrices, quaternions, rates, conversion, plots, the command line) reads the
consequences of the lock policy from the :class:`Convention` defined here.
"""

from __future__ import annotations

import math
from typing import Any, Literal, NamedTuple, TypeVar, overload

from numpy.typing import NDArray

from eulerlib._sequences import ALL_SEQUENCES, Sequence, parse_sequence, sequence_problem

_Item = TypeVar("_Item")

_PARSED = {seq: parse_sequence(seq) for seq in ALL_SEQUENCES}

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
        """The axis sequence, parsed (looked up: the 24 are parsed once, on import)."""
        found = _PARSED.get(self.seq)
        return parse_sequence(self.seq) if found is None else found

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


def _default_lock_zeroes(parsed: Sequence) -> LockedAngle:
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
    return Convention(
        parsed.seq, parsed.seq, names, None, description, _default_lock_zeroes(parsed)
    )


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
