"""A wireframe aircraft, so that yaw, pitch and roll can be seen.

The nose points along +x and the top along the convention's up axis (+z for Rose, +y for
Baker). Turning the body with a rotation matrix and back with its transpose shows eq 5–7 of
Rose (2015) at work.
"""

from __future__ import annotations

import itertools
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._validation import ROTATION_ATOL, check_choice, rotation_check
from eulerlib.plotting._base import add_3d_axes, pyplot_figure
from eulerlib.plotting._checks import (
    check_alpha,
    check_axes3d,
    check_color,
    check_figsize,
    check_linestyle,
    one_rotation,
)
from eulerlib.plotting.frames import frame_artists

if TYPE_CHECKING:
    from matplotlib.figure import Figure
    from mpl_toolkits.mplot3d.axes3d import Axes3D

__all__ = [
    "aircraft_segments",
    "draw_aircraft",
    "plot_body_rotation",
]

#: The up axes a body can have: z (Rose, aerospace) or y (Baker).
UP_AXES = ("z", "y")


def aircraft_segments(*, up: str = "z") -> NDArray[np.float64]:
    """A wireframe aircraft as line segments: nose along +x, vertical fin along +``up``.

    A fuselage (keel, spine with a windscreen and cabin roof, sides at half height and two
    cross-sections), swept wings, a tailplane and a fin, so that the nose, the wings and the top
    can be told apart from any side. The body is symmetric about the plane spanned by x and
    ``up``; the nose is the point ``(1, 0, 0)``, the belly and the wings lie in the plane
    ``up = 0``, the tail reaches back to x = -0.96, the wings span ±0.9 along the third axis,
    and the fin rises along ``up`` to 0.4. Segment 0 is the keel, from the tail to the nose.

    Parameters
    ----------
    up : {"z", "y"}, optional
        The body's up axis, in either letter case: ``"z"`` as in Rose's yaw-pitch-roll
        (aerospace, z up), ``"y"`` as in Baker's heading-attitude-bank (y up; the wings then
        lie along z).

    Returns
    -------
    ndarray, shape (n, 2, 3)
        Segment ``k`` runs from ``segments[k, 0]`` to ``segments[k, 1]``.

    Raises
    ------
    TypeError, ValueError
        If ``up`` is not ``"z"`` or ``"y"``.

    Examples
    --------
    >>> segments = aircraft_segments(up="z")
    >>> points = segments.reshape(-1, 3)
    >>> points[np.argmax(points[:, 0])]        # the nose
    array([1., 0., 0.])
    >>> float(points[:, 2].max()), float(points[:, 1].max())   # fin height, half span
    (0.4, 0.9)
    """
    return _segments(check_choice(up, "up", UP_AXES))


def _polyline(*points: tuple[float, float, float]) -> list[tuple[Any, Any]]:
    """The segments of a line through ``points``, in order."""
    return list(itertools.pairwise(points))


def _ring(forward: float, half_width: float, height: float) -> list[tuple[Any, Any]]:
    """Half a cross-section of the fuselage (the side > 0), an ellipse from belly to top."""
    angles = np.radians([-90.0, -45.0, 0.0, 45.0, 90.0])
    middle = height / 2.0
    points = [
        (forward, float(half_width * np.cos(a)), float(middle + middle * np.sin(a))) for a in angles
    ]
    return _polyline(*points)


def _segments(up: str) -> NDArray[np.float64]:
    """Body of :func:`aircraft_segments` for a checked up axis."""
    # Body coordinates: (forward, side, up). The belly is the plane up = 0, the wings are low
    # on the fuselage, in that plane; everything else rises above it.
    top = 0.16  # height of the fuselage
    width = 0.09  # half width of the fuselage
    body = [
        ((-0.9, 0.0, 0.0), (1.0, 0.0, 0.0)),  # keel, tail to nose
        *_polyline(  # spine: nose, windscreen, cabin roof, tail cone
            (1.0, 0.0, 0.0),
            (0.88, 0.0, 0.09),
            (0.72, 0.0, 0.2),
            (0.5, 0.0, 0.21),
            (0.35, 0.0, top),
            (-0.55, 0.0, top),
            (-0.9, 0.0, 0.11),
            (-0.9, 0.0, 0.0),
        ),
        *_polyline((-0.55, 0.0, top), (-0.84, 0.0, 0.4), (-0.96, 0.0, 0.4), (-0.9, 0.0, 0.11)),
    ]
    half = [
        *_polyline(  # side of the fuselage, at half its height
            (1.0, 0.0, 0.0),
            (0.86, 0.06, 0.07),
            (0.65, width, 0.08),
            (-0.45, width, 0.08),
            (-0.9, 0.02, 0.08),
        ),
        *_ring(0.65, width, top),
        *_ring(-0.45, width, top),
        *_polyline(  # wing: leading edge, tip, trailing edge
            (0.3, width, 0.0), (-0.05, 0.9, 0.0), (-0.25, 0.9, 0.0), (-0.2, width, 0.0)
        ),
        *_polyline(  # tailplane, at half the fuselage's height
            (-0.62, 0.05, 0.08), (-0.84, 0.35, 0.08), (-0.94, 0.35, 0.08), (-0.9, 0.02, 0.08)
        ),
    ]
    half_array = np.array(half, dtype=np.float64)
    mirrored = half_array * np.array([1.0, -1.0, 1.0])
    segments = np.concatenate([np.array(body, dtype=np.float64), half_array, mirrored])
    if up == "y":  # (forward, side, up) -> (x, y, z) = (forward, up, side)
        segments = segments[..., [0, 2, 1]]
    return segments


def draw_aircraft(
    ax: Axes3D,
    R: ArrayLike | None = None,
    *,
    up: str = "z",
    color: Any = "0.2",
    alpha: float = 1.0,
    linestyle: str = "-",
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
) -> list[Any]:
    """Draw the wireframe aircraft of :func:`aircraft_segments`, turned by ``R``.

    Parameters
    ----------
    ax : Axes3D
        Where to draw.
    R : array_like, shape (3, 3), optional
        Rotation applied to every point of the body (``R @ p``); identity by default.
    up : {"z", "y"}, optional
        Up axis of the body (see :func:`aircraft_segments`).
    color, alpha, linestyle : optional
        Line style of the wireframe: a matplotlib colour, an opacity from 0 to 1, a line style.
    validate, repair, atol
        How ``R`` is checked, as in :func:`eulerlib.plotting.draw_frame`.

    Returns
    -------
    list of Line3D
        One line per segment, in the order of :func:`aircraft_segments`.

    Raises
    ------
    TypeError, ValueError
        For a bad argument, before anything is drawn; the message names the argument.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> import eulerlib
    >>> from eulerlib.plotting import new_3d_axes
    >>> ax = new_3d_axes()
    >>> lines = draw_aircraft(ax, eulerlib.rot_z(90, degrees=True))
    >>> x, y, z = lines[0].get_data_3d()          # the fuselage now points along y
    >>> np.round(y, 12) + 0.0
    array([-0.9,  1. ])
    >>> plt.close(ax.figure)
    """
    target = check_axes3d(ax)
    matrix = one_rotation(R, "R", rotation_check(validate, repair, atol))
    return aircraft_lines(
        target,
        matrix,
        check_choice(up, "up", UP_AXES),
        color=check_color(color, "color"),
        alpha=check_alpha(alpha),
        linestyle=check_linestyle(linestyle),
    )


def aircraft_lines(
    ax: Axes3D,
    matrix: NDArray[np.float64],
    up: str,
    *,
    color: Any = "0.2",
    alpha: float = 1.0,
    linestyle: Any = "-",
) -> list[Any]:
    """Body of :func:`draw_aircraft` for checked arguments."""
    segments = _segments(up) @ matrix.T
    lines = []
    for segment in segments:
        (line,) = ax.plot(
            segment[:, 0],
            segment[:, 1],
            segment[:, 2],
            color=color,
            alpha=alpha,
            linestyle=linestyle,
            linewidth=1.8,
        )
        lines.append(line)
    return lines


def plot_body_rotation(
    R: ArrayLike,
    *,
    up: str = "z",
    figsize: tuple[float, float] = (12, 4),
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
) -> Figure:
    """An aircraft before a rotation, after it, and back again with the inverse ``Rᵀ``.

    Parameters
    ----------
    R : array_like, shape (3, 3)
        The rotation.
    up : {"z", "y"}, optional
        Up axis of the body (see :func:`aircraft_segments`).
    figsize : tuple of float, optional
        Figure size in inches.
    validate, repair, atol
        How ``R`` is checked, as in :func:`eulerlib.plotting.draw_frame`.

    Returns
    -------
    matplotlib.figure.Figure
        Three 3D axes: "before" (identity), "after R" (the rotated body and frame, the original
        faint), and "back with Rᵀ" (the body turned by ``Rᵀ R``, which is the identity).

    Raises
    ------
    TypeError, ValueError
        For a bad argument, before any figure is created; the message names the argument.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> import eulerlib
    >>> fig = plot_body_rotation(eulerlib.euler_to_matrix([30, 20, 10], degrees=True))
    >>> [ax.get_title() for ax in fig.axes]
    ['before', 'after R', 'back with Rᵀ']
    >>> plt.close(fig)
    """
    if R is None:
        raise TypeError("R must be a rotation matrix, got None")
    matrix = one_rotation(R, "R", rotation_check(validate, repair, atol))
    body_up = check_choice(up, "up", UP_AXES)
    size = check_figsize(figsize)
    back = matrix.T @ matrix
    identity = np.eye(3)
    with pyplot_figure(size) as fig:
        ax = add_3d_axes(fig, (1, 3, 1), 1.2, "before")
        frame_artists(ax, identity, alpha=0.6, linewidth=1.5)
        aircraft_lines(ax, identity, body_up)
        ax = add_3d_axes(fig, (1, 3, 2), 1.2, "after R")
        frame_artists(ax, identity, linestyle="--", alpha=0.35, linewidth=1.2)
        aircraft_lines(ax, identity, body_up, alpha=0.25, linestyle="--")
        frame_artists(ax, matrix, alpha=0.8, linewidth=1.5, label_suffix="'")
        aircraft_lines(ax, matrix, body_up)
        ax = add_3d_axes(fig, (1, 3, 3), 1.2, "back with Rᵀ")
        frame_artists(ax, back, alpha=0.6, linewidth=1.5)
        aircraft_lines(ax, back, body_up)
    return fig
