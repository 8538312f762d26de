"""eulerlib: Euler angles and rotation matrices, exact at gimbal lock, vectorized over arrays.

The library behind the eulerlib course. Conventions follow D. Rose, "Rotations in
Three-Dimensions: Euler Angles and Rotation Matrices, Part 2" (2015) and M. J. Baker, "Maths -
Conversion Matrix to Euler" (euclideanspace.com); every one of the 24 axis sequences is
available through the same ``seq`` strings as SciPy's ``Rotation.from_euler``, and the papers'
conventions by name (``"rose"``, ``"baker"``, ``"ros"``) wherever a ``seq`` is taken.

Beyond Euler angles, rotations convert to and from the representations that have no gimbal
lock: axis and angle (:func:`axis_angle_to_matrix`, :func:`matrix_to_axis_angle`), rotation
vectors (:func:`rotvec_to_matrix`, :func:`matrix_to_rotvec`) and unit quaternions
(:func:`quaternion_to_matrix`, :func:`matrix_to_quaternion`, :func:`euler_to_quaternion`,
:func:`quaternion_to_euler`, stored as SciPy stores them); :func:`rotation_angle` and
:func:`angle_between` measure rotations, and :func:`slerp` interpolates between them.
Quaternion algebra in Hamilton's convention (:func:`quaternion_multiply`,
:func:`quaternion_conjugate`, :func:`quaternion_inverse`, :func:`quaternion_exp`,
:func:`quaternion_log`, :func:`quaternion_power`) works on quaternions of any length.

Attitude from what sensors see: :func:`align_vectors` solves Wahba's problem (the rotation
that best maps reference directions onto observed ones, TRIAD included);
:func:`random_rotations` draws uniformly distributed rotations and :func:`mean_rotation`
averages rotations.

Rotations in motion: :func:`euler_rates_to_angular_velocity` and
:func:`angular_velocity_to_euler_rates` convert between Euler-angle rates and angular velocity
(in the body's axes or the fixed ones), and :func:`integrate_angular_velocity` advances an
attitude by one exact step of a constant angular velocity, as from a gyroscope's samples.

Every public function checks its arguments once, by the same rules (:mod:`eulerlib._validation`),
and the same keyword means the same thing everywhere: ``degrees`` (angles in and out in
degrees), ``validate``/``repair``/``atol`` (how rotation matrices are checked), ``warn`` (the
:class:`GimbalLockWarning`).

``import eulerlib`` loads numpy only; SymPy and matplotlib load in :mod:`eulerlib.symbolic` and
:mod:`eulerlib.plotting`.

Examples
--------
>>> import eulerlib
>>> R = eulerlib.euler_to_matrix([30, 20, 10], "ZYX", degrees=True)
>>> eulerlib.matrix_to_euler(R, "ZYX", degrees=True)
array([30., 20., 10.])
"""

from eulerlib._validation import REPAIR_LIMIT, ROTATION_ATOL
from eulerlib.angular_velocity import (
    angular_velocity_to_euler_rates,
    euler_rates_to_angular_velocity,
)
from eulerlib.axis_angle import (
    AxisAngle,
    angle_between,
    axis_angle_to_matrix,
    matrix_to_axis_angle,
    matrix_to_rotvec,
    rotation_angle,
    rotvec_to_matrix,
)
from eulerlib.conventions import CONVENTIONS, Convention, get_convention
from eulerlib.convert import convert_angles
from eulerlib.elementary import elementary_rotation, rot_x, rot_y, rot_z
from eulerlib.euler import euler_to_matrix, matrix_to_euler
from eulerlib.gimbal_lock import (
    GIMBAL_LOCK_TOLERANCE,
    GimbalLockStatus,
    GimbalLockWarning,
    gimbal_lock_status,
    lock_combination,
)
from eulerlib.integration import integrate_angular_velocity
from eulerlib.interpolation import slerp
from eulerlib.named import (
    HeadingAttitudeBank,
    YawPitchRoll,
    heading_attitude_bank_to_matrix,
    matrix_to_heading_attitude_bank,
    matrix_to_yaw_pitch_roll,
    yaw_pitch_roll_to_matrix,
)
from eulerlib.observations import Alignment, align_vectors
from eulerlib.operations import (
    compose,
    invert,
    is_rotation_matrix,
    nearest_rotation,
    rotate_points,
)
from eulerlib.quaternion import (
    euler_to_quaternion,
    matrix_to_quaternion,
    quaternion_to_euler,
    quaternion_to_matrix,
)
from eulerlib.quaternion_algebra import (
    quaternion_conjugate,
    quaternion_exp,
    quaternion_inverse,
    quaternion_log,
    quaternion_multiply,
    quaternion_power,
)
from eulerlib.random_mean import mean_rotation, random_rotations
from eulerlib.sequences import (
    ALL_SEQUENCES,
    PROPER_EULER,
    TAIT_BRYAN,
    Sequence,
    parse_axis,
    parse_sequence,
)
from eulerlib.up_axis import change_up_axis, up_axis_matrix

__version__ = "0.2.0"

__all__ = [
    "ALL_SEQUENCES",
    "CONVENTIONS",
    "GIMBAL_LOCK_TOLERANCE",
    "PROPER_EULER",
    "REPAIR_LIMIT",
    "ROTATION_ATOL",
    "TAIT_BRYAN",
    "Alignment",
    "AxisAngle",
    "Convention",
    "GimbalLockStatus",
    "GimbalLockWarning",
    "HeadingAttitudeBank",
    "Sequence",
    "YawPitchRoll",
    "align_vectors",
    "angle_between",
    "angular_velocity_to_euler_rates",
    "axis_angle_to_matrix",
    "change_up_axis",
    "compose",
    "convert_angles",
    "elementary_rotation",
    "euler_rates_to_angular_velocity",
    "euler_to_matrix",
    "euler_to_quaternion",
    "get_convention",
    "gimbal_lock_status",
    "heading_attitude_bank_to_matrix",
    "integrate_angular_velocity",
    "invert",
    "is_rotation_matrix",
    "lock_combination",
    "matrix_to_axis_angle",
    "matrix_to_euler",
    "matrix_to_heading_attitude_bank",
    "matrix_to_quaternion",
    "matrix_to_rotvec",
    "matrix_to_yaw_pitch_roll",
    "mean_rotation",
    "nearest_rotation",
    "parse_axis",
    "parse_sequence",
    "quaternion_conjugate",
    "quaternion_exp",
    "quaternion_inverse",
    "quaternion_log",
    "quaternion_multiply",
    "quaternion_power",
    "quaternion_to_euler",
    "quaternion_to_matrix",
    "random_rotations",
    "rot_x",
    "rot_y",
    "rot_z",
    "rotate_points",
    "rotation_angle",
    "rotvec_to_matrix",
    "slerp",
    "up_axis_matrix",
    "yaw_pitch_roll_to_matrix",
]
