"""Elementary rotations: turning about one coordinate axis.

Everything in eulerlib is built from three matrices. With column vectors, a right-handed
coordinate system and the right-hand rule for positive angles (thumb along the axis, fingers
curl the way the rotation goes), an *active* rotation by angle θ moves a vector ``v`` to
``R v``:

.. math::

    R_x(θ) = \\begin{bmatrix} 1 & 0 & 0 \\\\ 0 & \\cos θ & -\\sin θ \\\\ 0 & \\sin θ & \\cos θ
    \\end{bmatrix},\\quad
    R_y(θ) = \\begin{bmatrix} \\cos θ & 0 & \\sin θ \\\\ 0 & 1 & 0 \\\\ -\\sin θ & 0 & \\cos θ
    \\end{bmatrix},\\quad
    R_z(θ) = \\begin{bmatrix} \\cos θ & -\\sin θ & 0 \\\\ \\sin θ & \\cos θ & 0 \\\\ 0 & 0 & 1
    \\end{bmatrix}.

Read each matrix by its columns: column ``j`` is where the basis vector ``e_j`` lands. A
quarter turn about z sends x to y and y to −x, which is the first two columns of ``R_z(90°)``.
(The *passive* reading, re-expressing a fixed vector in turned axes, uses the transpose.)
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib import _scalar
from eulerlib._euler import compiled_elementary
from eulerlib._scalar_kernels import sin_cos as one_sin_cos
from eulerlib._trig import sin_cos
from eulerlib._validation import as_float_array, check_flag
from eulerlib.sequences import parse_axis

__all__ = ["elementary_rotation", "rot_x", "rot_y", "rot_z"]


def elementary_rotation(
    axis: str | int, angle: ArrayLike, *, degrees: bool = False
) -> NDArray[np.float64]:
    """Active right-handed rotation about a coordinate axis.

    Parameters
    ----------
    axis : {'x', 'y', 'z', 0, 1, 2}
        The axis, as a letter in either case or an index; exactly what
        :func:`eulerlib.symbolic.elementary_matrix` accepts (see
        :func:`eulerlib.parse_axis`).
    angle : array_like, shape (...)
        Rotation angle(s), in radians unless ``degrees`` is true.
    degrees : bool, optional
        Read ``angle`` in degrees, reduced modulo 360° exactly; multiples of 90° then give
        exact zeros and ones.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        One matrix per angle.

    Raises
    ------
    TypeError
        If ``angle`` is not real numbers, ``axis`` is neither a letter nor an integer, or
        ``degrees`` is not a bool.
    ValueError
        If ``axis`` names no axis, or ``angle`` is NaN or infinite.

    Examples
    --------
    >>> elementary_rotation("z", 90, degrees=True)
    array([[ 0., -1.,  0.],
           [ 1.,  0.,  0.],
           [ 0.,  0.,  1.]])
    """
    index = parse_axis(axis)
    in_degrees = check_flag(degrees, "degrees")
    compiled = compiled_elementary(index, angle, in_degrees)
    if compiled is not None:  # compiled kernels, or the paths below
        return compiled
    i, j = (index + 1) % 3, (index + 2) % 3
    single = _scalar.number(angle)
    if single is not None:  # one angle: the same numbers in Python floats
        (sine, *_), (cosine, *_) = one_sin_cos((single, 0.0, 0.0), in_degrees)
        entries = [0.0] * 9
        entries[4 * index], entries[4 * i], entries[4 * j] = 1.0, cosine, cosine
        entries[3 * i + j], entries[3 * j + i] = 0.0 - sine, sine
        return _scalar.as_array(tuple(entries), (3, 3))
    theta = as_float_array(angle, "angle")
    s, c = sin_cos(theta, in_degrees)
    R = np.zeros((*theta.shape, 3, 3))
    R[..., index, index] = 1.0
    R[..., i, i] = c
    R[..., j, j] = c
    R[..., i, j] = 0.0 - s  # not -s, which would print a zero sine as -0.
    R[..., j, i] = s
    return R


def rot_x(angle: ArrayLike, *, degrees: bool = False) -> NDArray[np.float64]:
    """Active right-handed rotation about the x axis (roll in Rose's convention).

    Parameters
    ----------
    angle : array_like, shape (...)
        Rotation angle(s), in radians unless ``degrees`` is true.
    degrees : bool, optional
        Read ``angle`` in degrees.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        ``[[1, 0, 0], [0, cos, -sin], [0, sin, cos]]`` for each angle.

    Examples
    --------
    >>> rot_x(90, degrees=True) @ [0.0, 1.0, 0.0]   # y turns into z
    array([0., 0., 1.])
    >>> rot_x([0.0, 0.1]).shape
    (2, 3, 3)
    """
    return elementary_rotation(0, angle, degrees=degrees)


def rot_y(angle: ArrayLike, *, degrees: bool = False) -> NDArray[np.float64]:
    """Active right-handed rotation about the y axis (pitch in Rose's convention).

    Parameters
    ----------
    angle : array_like, shape (...)
        Rotation angle(s), in radians unless ``degrees`` is true.
    degrees : bool, optional
        Read ``angle`` in degrees.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        ``[[cos, 0, sin], [0, 1, 0], [-sin, 0, cos]]`` for each angle.

    Examples
    --------
    >>> rot_y(90, degrees=True) @ [0.0, 0.0, 1.0]   # z turns into x
    array([1., 0., 0.])
    """
    return elementary_rotation(1, angle, degrees=degrees)


def rot_z(angle: ArrayLike, *, degrees: bool = False) -> NDArray[np.float64]:
    """Active right-handed rotation about the z axis (yaw in Rose's convention).

    Parameters
    ----------
    angle : array_like, shape (...)
        Rotation angle(s), in radians unless ``degrees`` is true.
    degrees : bool, optional
        Read ``angle`` in degrees.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        ``[[cos, -sin, 0], [sin, cos, 0], [0, 0, 1]]`` for each angle.

    Examples
    --------
    >>> rot_z(90, degrees=True) @ [1.0, 0.0, 0.0]   # x turns into y
    array([0., 1., 0.])
    """
    return elementary_rotation(2, angle, degrees=degrees)
