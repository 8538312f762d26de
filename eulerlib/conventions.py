"""Named Euler-angle conventions, and translating angles from one convention to another.

Three angles mean nothing until their convention is named: which axes, in which order, about
fixed or moving axes, which angle comes first in the argument list, which axis points up. This
module gives the conventions of the course names and converts between them.

The presets
-----------
``"rose"`` (aliases ``"aerospace"``, ``"nasa"``)
    D. Rose (2015), Part 2: yaw ``w`` about z, then pitch ``v`` about the new y, then roll ``u``
    about the newest x: ``R = R_z(w) R_y(v) R_x(u)`` (eq 2), ``seq="ZYX"``, angles
    ``(yaw, pitch, roll)``, z up. The aerospace "3-2-1" sequence is the same formula; aerospace
    frames often point z *down* (north-east-down), which changes what a positive pitch looks
    like but not the algebra.
``"baker"``
    M. J. Baker, "Maths - Conversion Matrix to Euler": heading about y, then attitude about the
    new z, then bank about the newest x: ``R = R_y(h) R_z(a) R_x(b)``, ``seq="YZX"``, angles
    ``(heading, attitude, bank)``, y up.
``"ros"``
    Roll, pitch, yaw as ROS (REP 103, ``tf``'s ``setRPY``) uses them: roll about the fixed x,
    then pitch about the fixed y, then yaw about the fixed z, ``seq="xyz"`` with angles
    ``(roll, pitch, yaw)``. That is Rose's matrix with the argument order reversed:
    ``R_z(yaw) R_y(pitch) R_x(roll)``. z up (x forward, y left).

Any of SciPy's 24 ``seq`` strings (``"ZYX"``, ``"xyz"``, ``"ZXZ"``, …) is accepted wherever a
preset name is, with angles named after their axes: ``z, y', x''`` for an intrinsic sequence
(each prime marks an axis that has moved), ``x, y, z`` for an extrinsic one (a repeated
fixed axis gets a 2: ``z, x, z2``).

Gimbal lock
-----------
At lock only the sum or difference of the first and third angles is defined, so one of them
is set to 0. A preset records which (:attr:`Convention.lock_zeroes`): Rose zeroes yaw (eq 4),
ROS zeroes yaw too (eulerlib's policy for ``"xyz"``, the same rotation as ``"ZYX"``), and
``"baker"`` keeps Baker's own choice, bank = 0 at the poles, exactly as
:func:`eulerlib.matrix_to_heading_attitude_bank` does. A bare ``seq`` string follows
eulerlib's policy (the first angle of the intrinsic form is set to 0; see
:mod:`eulerlib.euler`).

Up axes
-------
Rose's frame has z up, Baker's has y up; in both, x points forward (the nose). Going from
Baker's axes (x forward, y up, z right) to z-up axes (x forward, y left, z up) is the rotation
``P = R_x(+90°)``: it keeps x and sends y to z and z to −y. A rotation ``R`` written in
Baker's coordinates is ``P R Pᵀ`` in z-up coordinates (:func:`change_up_axis`). Under this
relabelling heading becomes yaw, bank becomes roll, and attitude becomes *minus* pitch: Baker's
positive attitude lifts the nose, Rose's positive pitch (right-handed about y, which points
left) lowers it.

Examples
--------
>>> import numpy as np
>>> convert_angles([30, 20, 10], "rose", "ros", degrees=True)   # same matrix, reversed order
array([10., 20., 30.])
>>> get_convention("Baker").seq
'YZX'
>>> hab = [40, 25, -15]                            # heading, attitude, bank (y up)
>>> convert_angles(hab, "baker", "rose", degrees=True, relabel=True).round(9)
array([ 40., -25., -15.])
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._validation import ROTATION_ATOL, as_float_array, as_matrices
from eulerlib.euler import angles_from_matrix, euler_to_matrix
from eulerlib.sequences import ALL_SEQUENCES, parse_sequence

__all__ = [
    "CONVENTIONS",
    "PRESET_ALIASES",
    "Convention",
    "angles_to_matrix",
    "change_up_axis",
    "convert_angles",
    "get_convention",
    "matrix_to_angles",
    "up_axis_matrix",
]


class Convention(NamedTuple):
    """An Euler-angle convention with a name.

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
        The axis that points up in the convention's frame (``"z"`` or ``"y"``), or None when
        the convention does not say (a bare sequence).
    description : str
        One sentence saying where the convention comes from and what it means.
    lock_zeroes : int or None
        Position in argument order of the angle set to 0 at gimbal lock: 0 (the first) or 2
        (the third). None means eulerlib's policy: the first angle of the intrinsic form,
        which is the last angle of an extrinsic sequence.

    Examples
    --------
    >>> rose = CONVENTIONS["rose"]
    >>> rose.seq, rose.angle_names, rose.up_axis
    ('ZYX', ('yaw', 'pitch', 'roll'), 'z')
    >>> rose.zeroed_at_lock
    0
    """

    name: str
    seq: str
    angle_names: tuple[str, str, str]
    up_axis: str | None
    description: str
    lock_zeroes: int | None = None

    @property
    def zeroed_at_lock(self) -> int:
        """Position (in argument order) of the angle set to 0 at gimbal lock: 0 or 2."""
        if self.lock_zeroes is not None:
            return self.lock_zeroes
        return 0 if parse_sequence(self.seq).intrinsic else 2


_ROSE = Convention(
    "rose",
    "ZYX",
    ("yaw", "pitch", "roll"),
    "z",
    "Rose (2015): yaw about z, pitch about the new y, roll about the newest x; "
    "R = Rz(yaw) Ry(pitch) Rx(roll), z up; yaw set to 0 at gimbal lock (eq 4)",
    0,
)
_BAKER = Convention(
    "baker",
    "YZX",
    ("heading", "attitude", "bank"),
    "y",
    "Baker (euclideanspace.com): heading about y, attitude about the new z, bank about the "
    "newest x; R = Ry(heading) Rz(attitude) Rx(bank), y up; bank set to 0 at the poles",
    2,
)
_ROS = Convention(
    "ros",
    "xyz",
    ("roll", "pitch", "yaw"),
    "z",
    "ROS (REP 103, tf setRPY): roll about the fixed x, pitch about the fixed y, yaw about the "
    "fixed z; R = Rz(yaw) Ry(pitch) Rx(roll), z up (x forward, y left); yaw set to 0 at lock",
    2,
)

#: Other names accepted for a preset.
PRESET_ALIASES = {"aerospace": "rose", "nasa": "rose"}

#: Preset name → :class:`Convention`. Aliases map to the same object as the preset they name.
CONVENTIONS: dict[str, Convention] = {"rose": _ROSE, "baker": _BAKER, "ros": _ROS}
CONVENTIONS.update({alias: CONVENTIONS[target] for alias, target in PRESET_ALIASES.items()})

_AXIS_LETTERS = "xyz"


def _from_sequence(seq: str) -> Convention:
    parsed = parse_sequence(seq)
    letters = [_AXIS_LETTERS[axis] for axis in parsed.axes]
    if parsed.intrinsic:
        names = (letters[0], letters[1] + "'", letters[2] + "''")
        kind = "intrinsic (moving axes)"
    else:
        third = letters[2] + "2" if parsed.proper else letters[2]
        names = (letters[0], letters[1], third)
        kind = "extrinsic (fixed axes)"
    family = "proper Euler" if parsed.proper else "Tait-Bryan"
    description = f"{kind} {family} sequence {'-'.join(letters)}, as SciPy reads {seq!r}"
    return Convention(seq, seq, names, None, description)


def get_convention(name_or_seq: str | Convention) -> Convention:
    """The convention named by a preset name or an axis sequence.

    Parameters
    ----------
    name_or_seq : str or Convention
        A preset name, any letter case (``"rose"``, ``"Baker"``, ``"ROS"``, ``"aerospace"``),
        or one of the 24 axis sequences exactly as SciPy spells them (``"ZYX"``, ``"xyz"``;
        the case of a sequence matters: uppercase is intrinsic, lowercase extrinsic). A
        :class:`Convention` is returned unchanged.

    Returns
    -------
    Convention

    Raises
    ------
    TypeError
        If ``name_or_seq`` is neither a string nor a Convention.
    ValueError
        If it is neither a preset nor a valid sequence; the message lists both.

    Examples
    --------
    >>> get_convention("ROS").angle_names
    ('roll', 'pitch', 'yaw')
    >>> get_convention("aerospace").name
    'rose'
    >>> get_convention("ZXZ").angle_names
    ('z', "x'", "z''")
    >>> get_convention("zxz").angle_names
    ('z', 'x', 'z2')
    >>> get_convention("yzx").description
    "extrinsic (fixed axes) Tait-Bryan sequence y-z-x, as SciPy reads 'yzx'"
    """
    if isinstance(name_or_seq, Convention):
        return name_or_seq
    if not isinstance(name_or_seq, str):
        raise TypeError(
            "a convention must be a preset name or an axis sequence (a string), "
            f"got {type(name_or_seq).__name__}"
        )
    if name_or_seq in ALL_SEQUENCES:
        return _from_sequence(name_or_seq)
    key = name_or_seq.strip().lower()
    if key in CONVENTIONS:
        return CONVENTIONS[key]
    presets = ", ".join(CONVENTIONS)
    raise ValueError(
        f"unknown convention {name_or_seq!r}: expected a preset name ({presets}; any letter "
        "case) or an axis sequence of three letters from x, y, z with no two neighbours alike, "
        "uppercase for intrinsic (moving axes) or lowercase for extrinsic (fixed axes), "
        "such as 'ZYX', 'xyz' or 'ZXZ'"
    )


def angles_to_matrix(
    angles: ArrayLike, convention: str | Convention = "rose", *, degrees: bool = False
) -> NDArray[np.float64]:
    """Rotation matrices from angles given in a named convention.

    Parameters
    ----------
    angles : array_like, shape (..., 3)
        The three angles in the convention's argument order.
    convention : str or Convention, optional
        Preset name or axis sequence (see :func:`get_convention`). Default ``"rose"``.
    degrees : bool, optional
        Read the angles in degrees.

    Returns
    -------
    ndarray, shape (..., 3, 3)

    Raises
    ------
    TypeError, ValueError
        For an unknown convention or bad angles.

    Examples
    --------
    >>> import numpy as np
    >>> R = angles_to_matrix([90, 0, 0], "baker", degrees=True)   # heading 90° about y
    >>> R @ np.array([1.0, 0.0, 0.0])                             # the nose swings to −z
    array([ 0.,  0., -1.])
    """
    return euler_to_matrix(angles, get_convention(convention).seq, degrees=degrees)


def _lock_words(convention: Convention, zeroed: int, count: int, total: int) -> str:
    names = convention.angle_names
    parsed = parse_sequence(convention.seq)
    singular = "0° or 180°" if parsed.proper else "±90°"
    kept = 2 - zeroed
    return (
        f"gimbal lock in {count} of {total} rotation(s) for convention {convention.name!r} "
        f"(seq {convention.seq!r}): {names[1]} is {singular}, so {names[0]} and {names[2]} turn "
        f"about the same axis and only their sum or difference is defined; {names[zeroed]} "
        f"was set to 0 and {names[kept]} carries the whole turn"
    )


def _angles_in(
    R: ArrayLike,
    chosen: Convention,
    degrees: bool,
    validate: bool,
    repair: bool,
    atol: float,
    warn: bool,
    stacklevel: int,
) -> NDArray[np.float64]:
    """Body of :func:`matrix_to_angles`; ``stacklevel`` points the warning at the user's call."""
    zeroed = chosen.zeroed_at_lock
    if zeroed not in (0, 2):
        raise ValueError(
            f"convention {chosen.name!r} has lock_zeroes={zeroed}; only the first (0) or the "
            "third (2) angle can be set to 0 at gimbal lock"
        )
    return angles_from_matrix(
        R,
        parse_sequence(chosen.seq),
        zeroed,
        degrees=degrees,
        validate=validate,
        repair=repair,
        atol=atol,
        warn=warn,
        describe=lambda count, total: _lock_words(chosen, zeroed, count, total),
        stacklevel=stacklevel + 1,
    )


def matrix_to_angles(
    R: ArrayLike,
    convention: str | Convention = "rose",
    *,
    degrees: bool = False,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
    warn: bool = True,
) -> NDArray[np.float64]:
    """Angles of rotation matrices in a named convention, with that convention's lock policy.

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotation matrices.
    convention : str or Convention, optional
        Preset name or axis sequence (see :func:`get_convention`). Default ``"rose"``.
    degrees : bool, optional
        Return degrees.
    validate, repair, atol, warn
        As in :func:`eulerlib.matrix_to_euler`.

    Returns
    -------
    ndarray, shape (..., 3)
        The angles in the convention's argument order. At gimbal lock the angle at
        :attr:`Convention.zeroed_at_lock` is 0.

    Raises
    ------
    TypeError, ValueError
        For an unknown convention or a matrix that is not a rotation.

    Warns
    -----
    GimbalLockWarning
        Once per call when some matrix is in gimbal lock, naming the angles.

    Notes
    -----
    For ``"rose"`` this equals :func:`eulerlib.matrix_to_yaw_pitch_roll` (Rose 2015, eq 3–4),
    for ``"baker"`` :func:`eulerlib.matrix_to_heading_attitude_bank` (bank = 0 at the poles),
    and for a bare sequence :func:`eulerlib.matrix_to_euler`.

    Examples
    --------
    >>> import warnings
    >>> R = angles_to_matrix([40, 90, 10], "baker", degrees=True)   # north pole
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     hab = matrix_to_angles(R, "baker", degrees=True)
    >>> hab.round(9) + 0.0   # heading + bank = 50° survives; Baker sets bank to 0
    array([50., 90.,  0.])
    >>> print(str(caught[0].message).split(";")[1].strip())
    bank was set to 0 and heading carries the whole turn
    """
    return _angles_in(R, get_convention(convention), degrees, validate, repair, atol, warn, 3)


_UP_AXES = ("y", "z")
#: Matrix taking y-up coordinates (x forward, y up, z right) to z-up coordinates
#: (x forward, y left, z up): R_x(+90°).
_Y_UP_TO_Z_UP = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])


def _check_up(value: object, name: str) -> str:
    if not isinstance(value, str) or value.lower() not in _UP_AXES:
        raise ValueError(f"{name} must be 'y' or 'z', got {value!r}")
    return value.lower()


def up_axis_matrix(from_up: str = "y", to_up: str = "z") -> NDArray[np.float64]:
    """The rotation that relabels coordinates from a ``from_up`` frame to a ``to_up`` frame.

    Both frames are right-handed with x forward. The y-up frame is Baker's (x forward, y up,
    z right); the z-up frame is Rose's and ROS's (x forward, y left, z up). The matrix ``P``
    returned turns coordinates of a vector in the first frame into coordinates of the same
    vector in the second: ``v_to = P @ v_from``.

    Parameters
    ----------
    from_up, to_up : {"y", "z"}
        Up axis of the frame the coordinates are in, and of the frame they should be in.

    Returns
    -------
    ndarray, shape (3, 3)
        ``R_x(+90°)`` for y-up to z-up, its transpose ``R_x(−90°)`` for z-up to y-up, the
        identity when the frames agree. Always a proper rotation (determinant +1): no axis is
        mirrored, unlike swapping two axes, which would turn a right-handed frame into a
        left-handed one.

    Raises
    ------
    ValueError
        If an up axis is not ``"y"`` or ``"z"``.

    Examples
    --------
    >>> P = up_axis_matrix("y", "z")
    >>> P @ [0.0, 1.0, 0.0]     # Baker's up is z
    array([0., 0., 1.])
    >>> P @ [0.0, 0.0, 1.0]     # Baker's right is −y (y points left in the z-up frame)
    array([ 0., -1.,  0.])
    """
    source, target = _check_up(from_up, "from_up"), _check_up(to_up, "to_up")
    matrix: NDArray[np.float64] = np.eye(3)
    if source != target:
        matrix = _Y_UP_TO_Z_UP.copy() if source == "y" else _Y_UP_TO_Z_UP.T.copy()
    return matrix


def change_up_axis(R: ArrayLike, from_up: str = "y", to_up: str = "z") -> NDArray[np.float64]:
    """The same physical rotation, written in a frame with another up axis: ``P R Pᵀ``.

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotation matrices in coordinates of the ``from_up`` frame.
    from_up, to_up : {"y", "z"}
        Up axes of the two frames (see :func:`up_axis_matrix` for the frames).

    Returns
    -------
    ndarray, shape (..., 3, 3)
        ``P @ R @ P.T`` with ``P = up_axis_matrix(from_up, to_up)``: if ``R`` turns a vector
        ``v`` into ``w`` in the first frame's coordinates, the result turns ``P v`` into
        ``P w``.

    Raises
    ------
    TypeError, ValueError
        If ``R`` is not an array of rotation matrices or an up axis is not ``"y"``/``"z"``.

    Notes
    -----
    Heading about Baker's y becomes a turn by the same angle about z (yaw), bank about x stays
    bank (roll), and attitude about Baker's z (which points right) becomes a turn by the same
    angle about −y, that is, pitch = −attitude:
    ``P R_y(h) R_z(a) R_x(b) Pᵀ = R_z(h) R_y(−a) R_x(b)``.

    Examples
    --------
    >>> import numpy as np
    >>> R_baker = angles_to_matrix([40, 25, -15], "baker", degrees=True)
    >>> R_rose = angles_to_matrix([40, -25, -15], "rose", degrees=True)
    >>> np.allclose(change_up_axis(R_baker, "y", "z"), R_rose)
    True
    >>> np.allclose(change_up_axis(R_rose, "z", "y"), R_baker)
    True
    """
    P = up_axis_matrix(from_up, to_up)
    matrices = as_matrices(R, "R")
    result: NDArray[np.float64] = P @ matrices @ P.T
    return result


def convert_angles(
    angles: ArrayLike,
    from_: str | Convention,
    to: str | Convention,
    *,
    degrees: bool = False,
    warn: bool = True,
    relabel: bool = False,
) -> NDArray[np.float64]:
    """Angles in one convention → the angles of the same rotation in another, via the matrix.

    Parameters
    ----------
    angles : array_like, shape (..., 3)
        Angles in the argument order of ``from_``. Leading axes are batch axes.
    from_, to : str or Convention
        Preset names or axis sequences (see :func:`get_convention`).
    degrees : bool, optional
        Angles in and out in degrees.
    warn : bool, optional
        Emit a :class:`eulerlib.GimbalLockWarning` when the rotation is in gimbal lock for
        ``to`` (default).
    relabel : bool, optional
        False (default): the matrix is shared, so both sets of angles give the same matrix in
        the same coordinates. True: also move between the presets' up axes with
        :func:`change_up_axis`, so both sets describe the same physical attitude of a body
        whose nose is x (for example Baker's heading/attitude/bank, y up, into Rose's
        yaw/pitch/roll, z up). Both conventions then need an up axis.

    Returns
    -------
    ndarray, shape (..., 3)
        Angles in the argument order of ``to``, with ``to``'s lock policy.

    Raises
    ------
    TypeError, ValueError
        For unknown conventions, bad angles, or ``relabel=True`` without up axes.

    Warns
    -----
    GimbalLockWarning
        When some rotation is in gimbal lock for ``to``.

    Examples
    --------
    >>> convert_angles([30, 20, 10], "ZYX", "xyz", degrees=True)
    array([10., 20., 30.])
    >>> convert_angles([[30, 20, 10], [0, 0, 45]], "rose", "XYZ", degrees=True).round(4)
    array([[-1.1161, 22.2422, 28.4518],
           [45.    ,  0.    ,  0.    ]])
    """
    source, target = get_convention(from_), get_convention(to)
    values = as_float_array(angles, "angles")
    R = euler_to_matrix(values, source.seq, degrees=degrees)
    if relabel:
        if source.up_axis is None or target.up_axis is None:
            missing = source if source.up_axis is None else target
            raise ValueError(
                f"relabel=True needs an up axis for both conventions, but {missing.name!r} has "
                "none; use presets such as 'rose' (z up) or 'baker' (y up)"
            )
        R = change_up_axis(R, source.up_axis, target.up_axis)
    return _angles_in(R, target, degrees, False, False, ROTATION_ATOL, warn, 3)
