"""The axis sequence as data: parsing the three letters, and the written and intrinsic orders.

The public face, with what a sequence means, is :mod:`eulerlib.sequences`. This module is one
of the kernels' own: the numeric kernels compute with a :class:`Sequence`, so it imports numpy
only.
"""

from __future__ import annotations

from typing import Any, NamedTuple, TypeVar, overload

import numpy as np
from numpy.typing import NDArray

_Item = TypeVar("_Item")

TAIT_BRYAN = ("XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX")
PROPER_EULER = ("XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ")
#: All 24 valid sequences: 12 intrinsic (uppercase) then 12 extrinsic (lowercase).
ALL_SEQUENCES = TAIT_BRYAN + PROPER_EULER + tuple(s.lower() for s in TAIT_BRYAN + PROPER_EULER)

_AXIS_INDEX = {"x": 0, "y": 1, "z": 2}
_AXIS_WORDS = "'x', 'y', 'z' (either case) or 0, 1, 2"


def parse_axis(axis: object, name: str = "axis") -> int:
    """Check a coordinate axis and return its index: 0 for x, 1 for y, 2 for z.

    Every function of eulerlib that takes one axis (:func:`eulerlib.elementary_rotation`,
    :func:`eulerlib.symbolic.elementary_matrix`) reads it here, so both accept the same values
    and refuse the rest with the same words.

    Parameters
    ----------
    axis : {'x', 'y', 'z', 'X', 'Y', 'Z', 0, 1, 2}
        A letter in either case, or an integer index (Python or NumPy integer; not a bool).
    name : str, optional
        The argument's name, for messages.

    Returns
    -------
    int

    Raises
    ------
    TypeError
        If ``axis`` is neither a string nor an integer (a bool, a float and None are refused).
    ValueError
        If it is a string or integer that names no axis.

    Examples
    --------
    >>> parse_axis("Y"), parse_axis(2)
    (1, 2)
    >>> parse_axis(1.0)
    Traceback (most recent call last):
    ...
    TypeError: axis must be 'x', 'y', 'z' (either case) or 0, 1, 2; got 1.0 (float)
    """
    if isinstance(axis, str):
        key = axis.lower()
        if key in _AXIS_INDEX:
            return _AXIS_INDEX[key]
        raise ValueError(f"{name} must be {_AXIS_WORDS}; got {axis!r}")
    if isinstance(axis, (bool, np.bool_)) or not isinstance(axis, (int, np.integer)):
        raise TypeError(f"{name} must be {_AXIS_WORDS}; got {axis!r} ({type(axis).__name__})")
    index = int(axis)
    if index not in (0, 1, 2):
        raise ValueError(f"{name} must be {_AXIS_WORDS}; got {axis!r}")
    return index


class Sequence(NamedTuple):
    """A parsed axis sequence.

    Attributes
    ----------
    seq : str
        The sequence as given, for example ``"ZYX"``.
    axes : tuple of int
        Axis indices (0 for x, 1 for y, 2 for z) in the order the letters are written.
    intrinsic : bool
        True for uppercase (moving axes), False for lowercase (fixed axes).
    proper : bool
        True for a proper Euler sequence (first axis repeated), False for Tait–Bryan.
    """

    seq: str
    axes: tuple[int, int, int]
    intrinsic: bool
    proper: bool

    @property
    def intrinsic_axes(self) -> tuple[int, int, int]:
        """Axes of the equivalent intrinsic sequence (reversed when the sequence is extrinsic)."""
        return self.axes if self.intrinsic else self.axes[::-1]

    @overload
    def intrinsic_order(self, values: NDArray[Any]) -> NDArray[Any]: ...
    @overload
    def intrinsic_order(self, values: tuple[_Item, _Item, _Item]) -> tuple[_Item, _Item, _Item]: ...
    def intrinsic_order(self, values: Any) -> Any:
        """Three values (the last axis of an array, or a tuple) between written and intrinsic order.

        The written order of an extrinsic sequence is the reverse of its intrinsic form, so the
        values are reversed for it and returned unchanged for an intrinsic sequence. Reversing
        twice is the identity: the same call maps intrinsic order back to written order. This is
        the one place eulerlib writes that rule down.

        Examples
        --------
        >>> parse_sequence("xyz").intrinsic_order(("roll", "pitch", "yaw"))
        ('yaw', 'pitch', 'roll')
        >>> parse_sequence("ZYX").intrinsic_order(np.array([[1.0, 2.0, 3.0]]))
        array([[1., 2., 3.]])
        """
        if self.intrinsic:
            return values
        if isinstance(values, tuple):
            return values[::-1]
        return values[..., ::-1]


def sequence_problem(seq: str) -> str:
    """Why ``seq`` is not one of the 24 sequences, in a few words ("" when it is one).

    Examples
    --------
    >>> sequence_problem("XXY")
    'two neighbouring axes are the same, so two rotations would merge into one'
    """
    if seq in ALL_SEQUENCES:
        return ""
    if len(seq) != 3:
        return f"it has {len(seq)} characters, not 3"
    if not set(seq.lower()) <= set("xyz"):
        return "it uses letters other than x, y, z"
    if not (seq.isupper() or seq.islower()):
        return "it mixes uppercase (intrinsic) and lowercase (extrinsic) letters"
    return "two neighbouring axes are the same, so two rotations would merge into one"


def parse_sequence(seq: object) -> Sequence:
    """Check an axis sequence and return it parsed.

    Parameters
    ----------
    seq : str
        Three letters from x, y, z, all uppercase (intrinsic) or all lowercase (extrinsic),
        with no two neighbours alike.

    Returns
    -------
    Sequence
        The axes as indices and whether the sequence is intrinsic and proper.

    Raises
    ------
    TypeError
        If ``seq`` is not a string.
    ValueError
        If ``seq`` is not one of the 24 valid sequences; the message lists them.

    Examples
    --------
    >>> parse_sequence("ZYX")
    Sequence(seq='ZYX', axes=(2, 1, 0), intrinsic=True, proper=False)
    >>> parse_sequence("zxz").proper
    True
    """
    if not isinstance(seq, str):
        raise TypeError(f"seq must be a string such as 'ZYX', got {type(seq).__name__}")
    if seq not in ALL_SEQUENCES:
        raise ValueError(
            f"invalid axis sequence {seq!r}: {sequence_problem(seq)}. Use three letters from x, "
            "y, z with no two neighbours alike, all uppercase for intrinsic (moving axes) or all "
            f"lowercase for extrinsic (fixed axes): {', '.join(ALL_SEQUENCES)}"
        )
    lower = seq.lower()
    axes = (_AXIS_INDEX[lower[0]], _AXIS_INDEX[lower[1]], _AXIS_INDEX[lower[2]])
    return Sequence(seq, axes, seq.isupper(), axes[0] == axes[2])
