"""Paths on the unit sphere: where one body axis goes while the body turns.

A rotation ``R`` sends the body's x axis (an aircraft's nose) to column 0 of ``R``, a point on
the unit sphere; y and z go to columns 1 and 2. A sequence of rotations ``R(t)`` (an
interpolation, a recorded motion) therefore moves each body axis along a path on the sphere,
and that path shows at a glance what the sequence does: a turn about one fixed axis moves every
body axis along a circle about that axis, a detour shows as a bend, and samples taken at equal
steps of ``t`` lie at equal distances when the body turns at constant speed.

:func:`draw_axis_path` draws the path of one body axis of a stack of rotations on a 3D axes: a
line through the samples, a dot where it starts, an arrowhead where it ends, and optionally a
dot at every few samples. :func:`plot_axis_paths` draws the paths of several stacks on a faint
wire sphere in a new figure, with a legend, to compare them.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._validation import ROTATION_ATOL, as_rotations, rotation_check
from eulerlib.plotting._base import AXIS_LETTERS, add_3d_axes, pyplot_figure
from eulerlib.plotting._base import arrow_head as _arrow_head
from eulerlib.plotting._checks import (
    check_alpha,
    check_axes3d,
    check_color,
    check_count,
    check_figsize,
    check_linestyle,
    check_optional_text,
    check_positive,
    check_texts,
    rotation_stack,
)
from eulerlib.sequences import parse_axis

if TYPE_CHECKING:
    from matplotlib.figure import Figure
    from mpl_toolkits.mplot3d.axes3d import Axes3D

__all__ = ["draw_axis_path", "plot_axis_paths"]

#: Colours of the paths of :func:`plot_axis_paths`, in order: none of them is the red, green or
#: blue of the x, y and z axes.
PATH_COLORS = ("tab:orange", "tab:purple", "tab:brown", "tab:pink", "tab:olive", "tab:cyan")
_SPHERE_COLOR = "0.82"


def draw_axis_path(
    ax: Axes3D,
    rotations: ArrayLike,
    *,
    axis: str | int = "x",
    color: Any = "tab:orange",
    label: str | None = None,
    linewidth: float = 2.0,
    linestyle: str = "-",
    alpha: float = 1.0,
    dot_every: int = 0,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
) -> list[Any]:
    """Draw the path of one body axis of a stack of rotations: column ``axis`` of each ``R``.

    Parameters
    ----------
    ax : Axes3D
        Where to draw, for example from :func:`eulerlib.plotting.new_3d_axes`.
    rotations : array_like, shape (n, 3, 3)
        The rotations along the path, in order; at least two.
    axis : {'x', 'y', 'z', 0, 1, 2}, optional
        The body axis whose path is drawn (read by :func:`eulerlib.parse_axis`): ``'x'``, the
        nose of an aircraft, by default.
    color : matplotlib colour, optional
        Colour of the line, the dots and the arrowhead.
    label : str, optional
        Legend entry of the line.
    linewidth : float, optional
        Width of the line; > 0.
    linestyle : str, optional
        Line style of the path.
    alpha : float, optional
        Opacity, 0 to 1.
    dot_every : int, optional
        Also put a small dot on every ``dot_every``-th sample, starting with the first: with
        samples at equal steps of time, evenly spaced dots mean constant speed. 0 (default)
        draws no such dots.
    validate, repair, atol
        How ``rotations`` are checked, as in :func:`eulerlib.plotting.draw_frame`.

    Returns
    -------
    list
        The line (a ``Line3D`` through the ``n`` points), the start dot (a ``Line3D`` with one
        point), the arrowhead at the end (a ``Poly3DCollection``), and, with ``dot_every``, the
        dots (a ``Line3D`` of points without a line).

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
    >>> turns = eulerlib.rot_z(np.linspace(0, 90, 4), degrees=True)
    >>> ax = new_3d_axes()
    >>> line, start, head = draw_axis_path(ax, turns, label="nose")
    >>> np.round(line.get_data_3d(), 3) + 0.0      # the nose swings from x to y
    array([[1.   , 0.866, 0.5  , 0.   ],
           [0.   , 0.5  , 0.866, 1.   ],
           [0.   , 0.   , 0.   , 0.   ]])
    >>> plt.close(ax.figure)
    """
    target = check_axes3d(ax)
    matrices = _path_stack(rotations, "rotations", validate, repair, atol)
    column = parse_axis(axis, "axis")
    return path_artists(
        target,
        matrices[:, :, column],
        color=check_color(color, "color"),
        label=check_optional_text(label, "label"),
        linewidth=check_positive(linewidth, "linewidth"),
        linestyle=check_linestyle(linestyle),
        alpha=check_alpha(alpha),
        dot_every=check_count(dot_every, "dot_every", 0),
    )


def _path_stack(
    rotations: ArrayLike, name: str, validate: object, repair: object, atol: object
) -> NDArray[np.float64]:
    """``rotations`` as a checked stack ``(n, 3, 3)`` with n ≥ 2."""
    matrices = rotation_stack(rotations, name, rotation_check(validate, repair, atol))
    if matrices.shape[0] < 2:
        raise ValueError(f"{name} must hold at least two rotations to make a path, got 1")
    return matrices


def path_artists(
    ax: Axes3D,
    points: NDArray[np.float64],
    *,
    color: Any,
    label: str | None,
    linewidth: float,
    linestyle: Any,
    alpha: float,
    dot_every: int,
) -> list[Any]:
    """Body of :func:`draw_axis_path` for checked arguments and the points of the path."""
    (line,) = ax.plot(
        points[:, 0],
        points[:, 1],
        points[:, 2],
        color=color,
        linewidth=linewidth,
        linestyle=linestyle,
        alpha=alpha,
        label=label,
    )
    (start,) = ax.plot(
        points[:1, 0],
        points[:1, 1],
        points[:1, 2],
        linestyle="none",
        marker="o",
        markersize=5,
        color=color,
        alpha=alpha,
    )
    head = _arrow_head(ax, points[-1], points[-1] - points[-2], 0.04, color=color, alpha=alpha)
    artists = [line, start, head]
    if dot_every:
        dots = points[::dot_every]
        (marks,) = ax.plot(
            dots[:, 0],
            dots[:, 1],
            dots[:, 2],
            linestyle="none",
            marker=".",
            markersize=6,
            color=color,
            alpha=alpha,
        )
        artists.append(marks)
    return artists


def _wire_sphere(ax: Axes3D) -> None:
    """A faint unit sphere: six meridians and five parallels."""
    t = np.linspace(0.0, 2.0 * np.pi, 73)
    for longitude in np.radians(np.arange(0.0, 180.0, 30.0)):
        ax.plot(
            np.cos(longitude) * np.cos(t),
            np.sin(longitude) * np.cos(t),
            np.sin(t),
            color=_SPHERE_COLOR,
            linewidth=0.6,
        )
    for latitude in np.radians(np.arange(-60.0, 61.0, 30.0)):
        ax.plot(
            np.cos(latitude) * np.cos(t),
            np.cos(latitude) * np.sin(t),
            np.full_like(t, np.sin(latitude)),
            color=_SPHERE_COLOR,
            linewidth=0.6,
        )


def plot_axis_paths(
    paths: ArrayLike,
    *,
    labels: Sequence[str] | None = None,
    axis: str | int = "x",
    colors: Sequence[Any] | None = None,
    dot_every: int = 0,
    title: str | None = None,
    figsize: tuple[float, float] = (5, 5),
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
) -> Figure:
    """Paths of one body axis for one or several stacks of rotations, on a faint unit sphere.

    Parameters
    ----------
    paths : array_like, shape (n, 3, 3) or (k, n, 3, 3)
        One path of ``n`` rotations, or ``k`` paths of ``n`` rotations each (``n`` ≥ 2).
    labels : sequence of str, optional
        One legend entry per path; without them there is no legend.
    axis : {'x', 'y', 'z', 0, 1, 2}, optional
        The body axis whose paths are drawn: ``'x'``, the nose, by default.
    colors : sequence of matplotlib colours, optional
        One colour per path; by default orange, purple, brown, … (never the red, green or blue
        of the coordinate axes).
    dot_every : int, optional
        A dot on every ``dot_every``-th sample of each path (see :func:`draw_axis_path`).
    title : str, optional
        Title of the axes.
    figsize : tuple of float, optional
        Figure size in inches.
    validate, repair, atol
        How the rotations are checked, as in :func:`eulerlib.plotting.draw_frame`.

    Returns
    -------
    matplotlib.figure.Figure
        A pyplot figure with one 3D axes: the sphere, the fixed x, y, z axes as short dashed
        lines, and the paths in order. The box, ticks and panes of the axes are hidden (the
        dashed lines show the frame); the axes keep the course's view, which ``view_init``
        changes.

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
    >>> t = np.linspace(0.0, 1.0, 11)
    >>> end = eulerlib.euler_to_matrix([90, 0, 0], degrees=True)
    >>> fig = plot_axis_paths(eulerlib.slerp(np.eye(3), end, t), labels=["slerp"])
    >>> [text.get_text() for text in fig.axes[0].get_legend().get_texts()]
    ['slerp']
    >>> plt.close(fig)
    """
    stacks = _paths(paths, validate, repair, atol)
    count = stacks.shape[0]
    names = None if labels is None else check_texts(labels, "labels", count, "one per path")
    column = parse_axis(axis, "axis")
    palette = _path_colors(colors, count)
    every = check_count(dot_every, "dot_every", 0)
    heading = check_optional_text(title, "title")
    size = check_figsize(figsize)
    with pyplot_figure(size) as fig:
        ax = add_3d_axes(fig, (1, 1, 1), 1.1, heading)
        ax.set_axis_off()  # the sphere and its own x, y, z lines show the frame
        ax.set_box_aspect((1, 1, 1), zoom=1.3)  # without the box, the sphere may fill the axes
        _wire_sphere(ax)
        for index in range(3):
            end = 1.1 * np.eye(3)[index]
            ax.plot(*np.stack([np.zeros(3), end], axis=1), color="0.45", linestyle="--", lw=1.0)
            ax.text(*(1.18 * end), AXIS_LETTERS[index], color="0.35", fontsize=9, ha="center")
        for index in range(count):
            path_artists(
                ax,
                stacks[index, :, :, column],
                color=palette[index],
                label=None if names is None else names[index],
                linewidth=2.0,
                linestyle="-",
                alpha=1.0,
                dot_every=every,
            )
        if names is not None:
            ax.legend(loc="upper left", fontsize=8, framealpha=0.9)
    return fig


def _paths(paths: ArrayLike, validate: object, repair: object, atol: object) -> NDArray[np.float64]:
    """``paths`` as a checked array ``(k, n, 3, 3)`` with n ≥ 2."""
    matrices = as_rotations(paths, "paths", rotation_check(validate, repair, atol))
    if matrices.ndim == 3:
        matrices = matrices[None]
    if matrices.ndim != 4:
        raise ValueError(
            f"paths must have shape (n, 3, 3) or (k, n, 3, 3), got shape {matrices.shape}"
        )
    if matrices.shape[1] < 2:
        raise ValueError("paths must hold at least two rotations per path, got 1")
    return matrices


def _path_colors(colors: object, count: int) -> tuple[Any, ...]:
    """``count`` checked colours, or the default palette."""
    if colors is None:
        return tuple(PATH_COLORS[index % len(PATH_COLORS)] for index in range(count))
    if not isinstance(colors, (list, tuple)):
        raise TypeError(
            f"colors must be a list or tuple of {count} colours (one per path), got "
            f"{type(colors).__name__}"
        )
    if len(colors) != count:
        raise ValueError(f"colors must have {count} entries (one per path), got {len(colors)}")
    return tuple(check_color(item, f"colors[{index}]") for index, item in enumerate(colors))
