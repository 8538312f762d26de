"""eulerlib: Euler angles and rotation matrices, exact at gimbal lock, vectorized over arrays.

The library behind the eulerlib course. Conventions follow D. Rose, "Rotations in
Three-Dimensions: Euler Angles and Rotation Matrices, Part 2" (2015) and M. J. Baker, "Maths -
Conversion Matrix to Euler" (euclideanspace.com); every one of the 24 axis sequences is
available through the same ``seq`` strings as SciPy's ``Rotation.from_euler``.

``import eulerlib`` loads numpy only; SymPy and matplotlib load inside the submodules that use
them (:mod:`eulerlib.symbolic`, :mod:`eulerlib.plotting`).

Examples
--------
>>> import eulerlib
>>> R = eulerlib.euler_to_matrix([30, 20, 10], "ZYX", degrees=True)
>>> eulerlib.matrix_to_euler(R, "ZYX", degrees=True)
array([30., 20., 10.])
"""

from eulerlib.conventions import CONVENTIONS, Convention, convert_angles, get_convention
from eulerlib.elementary import rot_x, rot_y, rot_z
from eulerlib.euler import (
    GIMBAL_LOCK_TOLERANCE,
    GimbalLockStatus,
    GimbalLockWarning,
    euler_to_matrix,
    gimbal_lock_status,
    matrix_to_euler,
)
from eulerlib.heading_attitude_bank import (
    heading_attitude_bank_to_matrix,
    matrix_to_heading_attitude_bank,
)
from eulerlib.operations import compose, invert, is_rotation_matrix, rotate_points
from eulerlib.sequences import ALL_SEQUENCES, PROPER_EULER, TAIT_BRYAN
from eulerlib.yaw_pitch_roll import matrix_to_yaw_pitch_roll, yaw_pitch_roll_to_matrix

__version__ = "0.1.0"

__all__ = [
    "ALL_SEQUENCES",
    "CONVENTIONS",
    "GIMBAL_LOCK_TOLERANCE",
    "PROPER_EULER",
    "TAIT_BRYAN",
    "Convention",
    "GimbalLockStatus",
    "GimbalLockWarning",
    "compose",
    "convert_angles",
    "euler_to_matrix",
    "get_convention",
    "gimbal_lock_status",
    "heading_attitude_bank_to_matrix",
    "invert",
    "is_rotation_matrix",
    "matrix_to_euler",
    "matrix_to_heading_attitude_bank",
    "matrix_to_yaw_pitch_roll",
    "rot_x",
    "rot_y",
    "rot_z",
    "rotate_points",
    "yaw_pitch_roll_to_matrix",
]
