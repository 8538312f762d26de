"""Up axes: the same physical rotation written in frames whose up axis differs.

Three frames, all right-handed with x forward (the nose): Rose's and ROS's z-up frame (y left,
z up), Baker's y-up frame (y up, z right), and the aerospace body frame with z *down* (y right,
z down; north-east-down), written ``"-z"``.

Going from Baker's axes to z-up axes is the rotation ``P = R_x(+90°)``: it keeps x and sends y
to z and z to −y. A rotation ``R`` written in Baker's coordinates is ``P R Pᵀ`` in z-up
coordinates (:func:`change_up_axis`). Under this relabelling heading becomes yaw, bank becomes
roll, and attitude becomes *minus* pitch: Baker's positive attitude lifts the nose, Rose's
positive pitch (right-handed about y, which points left) lowers it.

Going from the aerospace frame to z up is ``P = R_x(180°)``: x stays, y and z change sign; a
rotation's yaw and pitch change sign with them, and its roll stays.

Every ``P`` here is a signed permutation, so ``P R Pᵀ`` only moves and negates entries:
``(P R Pᵀ)[a, b] = s_a s_b R[p(a), p(b)]``. It is computed that way, block by block.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._blocks import block_slices
from eulerlib._euler_kernels import relabel_into
from eulerlib._validation import ROTATION_ATOL, as_rotations, check_choice, rotation_check

__all__ = ["change_up_axis", "up_axis_matrix"]

UP_AXES = ("y", "z", "-z")
#: For each frame, the matrix taking its coordinates to z-up coordinates (x forward, y left,
#: z up): from y up (x forward, y up, z right) it is R_x(+90°), from z down (x forward, y right,
#: z down) R_x(180°).
_TO_Z_UP = {
    "z": np.eye(3),
    "y": np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]]),
    "-z": np.diag([1.0, -1.0, -1.0]),
}


def up_axis_matrix(from_up: str = "y", to_up: str = "z") -> NDArray[np.float64]:
    """The rotation that relabels coordinates from a ``from_up`` frame to a ``to_up`` frame.

    All frames are right-handed with x forward. The y-up frame is Baker's (x forward, y up,
    z right); the z-up frame is Rose's and ROS's (x forward, y left, z up); the ``"-z"`` frame is
    the aerospace body frame (x forward, y right, z down). The matrix ``P`` returned turns
    coordinates of a vector in the first frame into coordinates of the same vector in the
    second: ``v_to = P @ v_from``.

    Parameters
    ----------
    from_up, to_up : {"y", "z", "-z"}
        Up axis of the frame the coordinates are in, and of the frame they should be in (any
        letter case; ``"-z"`` means z points down).

    Returns
    -------
    ndarray, shape (3, 3)
        ``R_x(+90°)`` for y-up to z-up, ``R_x(180°)`` for z-down to z-up, products of these for
        the other pairs, the identity when the frames agree. Always a proper rotation
        (determinant +1): no axis is mirrored, unlike swapping two axes, which would turn a
        right-handed frame into a left-handed one.

    Raises
    ------
    TypeError, ValueError
        If an up axis is not ``"y"``, ``"z"`` or ``"-z"``.

    Examples
    --------
    >>> P = up_axis_matrix("y", "z")
    >>> P @ [0.0, 1.0, 0.0]     # Baker's up is z
    array([0., 0., 1.])
    >>> P @ [0.0, 0.0, 1.0]     # Baker's right is −y (y points left in the z-up frame)
    array([ 0., -1.,  0.])
    >>> up_axis_matrix("-z", "z") @ [0.0, 1.0, 0.0]   # the aerospace right wing points to −y
    array([ 0., -1.,  0.])
    """
    source = check_choice(from_up, "from_up", UP_AXES)
    target = check_choice(to_up, "to_up", UP_AXES)
    matrix: NDArray[np.float64] = _TO_Z_UP[target].T @ _TO_Z_UP[source]
    return matrix + 0.0  # no negative zeros


def change_up_axis(
    R: ArrayLike,
    from_up: str = "y",
    to_up: str = "z",
    *,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
) -> NDArray[np.float64]:
    """The same physical rotation, written in a frame with another up axis: ``P R Pᵀ``.

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotation matrices in coordinates of the ``from_up`` frame.
    from_up, to_up : {"y", "z", "-z"}
        Up axes of the two frames (see :func:`up_axis_matrix` for the frames).
    validate, repair, atol
        As in :func:`eulerlib.matrix_to_euler`.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        ``P @ R @ P.T`` with ``P = up_axis_matrix(from_up, to_up)``: if ``R`` turns a vector
        ``v`` into ``w`` in the first frame's coordinates, the result turns ``P v`` into
        ``P w``.

    Raises
    ------
    TypeError, ValueError
        If ``R`` is not an array of rotation matrices, an up axis is not ``"y"``, ``"z"`` or
        ``"-z"``, or a keyword is invalid.

    Notes
    -----
    Heading about Baker's y becomes a turn by the same angle about z (yaw), bank about x stays
    bank (roll), and attitude about Baker's z (which points right) becomes a turn by the same
    angle about −y, that is, pitch = −attitude:
    ``P R_y(h) R_z(a) R_x(b) Pᵀ = R_z(h) R_y(−a) R_x(b)``.

    Examples
    --------
    >>> import numpy as np
    >>> from eulerlib import euler_to_matrix
    >>> R_baker = euler_to_matrix([40, 25, -15], "baker", degrees=True)
    >>> R_rose = euler_to_matrix([40, -25, -15], "rose", degrees=True)
    >>> np.allclose(change_up_axis(R_baker, "y", "z"), R_rose)
    True
    >>> np.allclose(change_up_axis(R_rose, "z", "y"), R_baker)
    True
    """
    P = up_axis_matrix(from_up, to_up)
    matrices = as_rotations(R, "R", rotation_check(validate, repair, atol))
    result = np.empty(matrices.shape)
    flat_out, flat_in = result.reshape(-1, 3, 3), matrices.reshape(-1, 3, 3)
    for block in block_slices(flat_in.shape[0]):
        relabel_into(flat_out[block], flat_in[block], P)
    return result
