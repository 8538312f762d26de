"""Coordinate frames: one or several, and the steps of an Euler sequence.

A frame is drawn as three labelled arrows, x red, y green and z blue; arrow ``i`` is column
``i`` of the rotation matrix, which is where that basis vector lands. A step panel shows each
elementary rotation of a sequence read about the moving axes and about the fixed axes.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._validation import ROTATION_ATOL, RotationCheck, as_rotations, as_vectors
from eulerlib.elementary import elementary_rotation
from eulerlib.sequences import parse_sequence

if TYPE_CHECKING:
    from matplotlib.figure import Figure
    from mpl_toolkits.mplot3d.axes3d import Axes3D

from eulerlib.plotting._base import (
    AXIS_COLORS,
    AXIS_LETTERS,
    HIGHLIGHT_COLOR,
    PRIME,
    _degrees_text,
    _intrinsic_steps,
    _one_matrix,
    _partial_products,
    _style_axes,
)

_CHECKED = RotationCheck(validate=True, repair=False, atol=ROTATION_ATOL)

__all__ = [
    "draw_frame",
    "new_3d_axes",
    "plot_frames",
    "plot_sequence_steps",
]


def new_3d_axes(
    fig: Figure | None = None,
    position: int | tuple[int, int, int] = 111,
    *,
    limit: float = 1.2,
    title: str | None = None,
    figsize: tuple[float, float] = (5, 5),
) -> Axes3D:
    """A 3D axes with equal aspect, labelled x/y/z axes and the course's standard view.

    Parameters
    ----------
    fig : matplotlib.figure.Figure, optional
        Figure to add the axes to. By default a new pyplot figure of size ``figsize``.
    position : int or tuple of int, optional
        Subplot position, as ``fig.add_subplot`` takes it: ``111`` or ``(1, 3, 2)``.
    limit : float, optional
        The axes show ``[-limit, limit]`` in x, y and z (a cube, drawn as a cube).
    title : str, optional
        Title of the axes.
    figsize : tuple of float, optional
        Size of a new figure, in inches.

    Returns
    -------
    mpl_toolkits.mplot3d.axes3d.Axes3D

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> ax = new_3d_axes(title="reference frame")
    >>> ax.get_xlim() == ax.get_zlim()
    True
    >>> plt.close(ax.figure)
    """
    import matplotlib.pyplot as plt

    if limit <= 0:
        raise ValueError(f"limit must be positive, got {limit}")
    if fig is None:
        fig = plt.figure(figsize=figsize)
    if isinstance(position, tuple):
        ax = fig.add_subplot(*position, projection="3d")
    else:
        ax = fig.add_subplot(position, projection="3d")
    _style_axes(ax, limit, title)
    return ax


def _arrow_head(
    ax: Axes3D, tip: NDArray[np.float64], direction: NDArray[np.float64], size: float, **style: Any
) -> Any:
    """A small filled cone with its point at ``tip``, pointing along ``direction``."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    helper = np.eye(3)[int(np.argmin(np.abs(direction)))]
    u = np.cross(direction, helper)
    u /= np.linalg.norm(u)
    v = np.cross(direction, u)
    t = np.linspace(0.0, 2.0 * np.pi, 9)
    base = tip - 2.5 * size * direction
    rim = base + size * (np.cos(t)[:, None] * u + np.sin(t)[:, None] * v)
    faces = [[tip, rim[n], rim[n + 1]] for n in range(len(t) - 1)]
    cone = Poly3DCollection(faces, linewidths=0.0, **style)
    ax.add_collection3d(cone)
    return cone


def draw_frame(
    ax: Axes3D,
    R: ArrayLike | None = None,
    *,
    origin: ArrayLike = (0, 0, 0),
    scale: float = 1.0,
    alpha: float = 1.0,
    linestyle: str = "-",
    linewidth: float = 2.0,
    colors: Sequence[Any] = AXIS_COLORS,
    labels: Sequence[str] = AXIS_LETTERS,
    label_suffix: str = "",
) -> list[Any]:
    """Draw the frame of a rotation matrix: three labelled arrows, arrow ``i`` along column ``i``.

    Parameters
    ----------
    ax : Axes3D
        Where to draw, for example from :func:`new_3d_axes`.
    R : array_like, shape (3, 3), optional
        Rotation matrix; the identity (the reference frame) by default.
    origin : array_like, shape (3,), optional
        Where the arrows start.
    scale : float, optional
        Length of the arrows.
    alpha : float, optional
        Opacity, 0 to 1.
    linestyle : str, optional
        Line style of the arrow shafts: ``"-"`` for a rotated frame, ``"--"`` for a reference.
    linewidth : float, optional
        Width of the shafts.
    colors : sequence of 3 colours, optional
        Colours of the x, y, z arrows; red, green, blue by default.
    labels : sequence of 3 str, optional
        Names of the axes, written at the arrow tips.
    label_suffix : str, optional
        Appended to every label, for example ``"'"`` for the frame after one rotation.

    Returns
    -------
    list
        Nine artists, three per axis in the order x, y, z: the shaft (a ``Line3D`` from the
        origin to the tip, labelled with the axis name), the arrowhead (a ``Poly3DCollection``)
        and the label (a ``Text3D``).

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> import eulerlib
    >>> ax = new_3d_axes()
    >>> artists = draw_frame(ax, eulerlib.rot_z(90, degrees=True), label_suffix="'")
    >>> shaft_x = artists[0]
    >>> shaft_x.get_label()
    "x'"
    >>> np.round(shaft_x.get_data_3d(), 12) + 0.0    # x' runs from the origin along y
    array([[0., 0.],
           [0., 1.],
           [0., 0.]])
    >>> plt.close(ax.figure)
    """
    matrix = _one_matrix(R)
    start = as_vectors(origin, "origin")
    if start.shape != (3,):
        raise ValueError(f"origin must be one point (3 numbers), got shape {start.shape}")
    if len(colors) != 3 or len(labels) != 3:
        raise ValueError(
            f"colors and labels must have 3 entries (x, y, z), got {len(colors)} and {len(labels)}"
        )
    if scale <= 0:
        raise ValueError(f"scale must be positive, got {scale}")
    artists: list[Any] = []
    for i in range(3):
        direction = matrix[:, i]
        tip = start + scale * direction
        name = f"{labels[i]}{label_suffix}"
        (shaft,) = ax.plot(
            [start[0], tip[0]],
            [start[1], tip[1]],
            [start[2], tip[2]],
            color=colors[i],
            alpha=alpha,
            linestyle=linestyle,
            linewidth=linewidth,
            label=name,
        )
        head = _arrow_head(ax, tip, direction, 0.045 * scale, color=colors[i], alpha=alpha)
        where = start + 1.15 * scale * direction
        text = ax.text(
            where[0],
            where[1],
            where[2],
            name,
            color=colors[i],
            alpha=alpha,
            ha="center",
            va="center",
            fontsize=10,
        )
        artists.extend([shaft, head, text])
    return artists


def _default_suffixes(count: int) -> list[str]:
    return ["'" * (k + 1) if count <= 3 else f"{k + 1}" for k in range(count)]


def plot_frames(
    rotations: ArrayLike,
    *,
    labels: Sequence[str] | None = None,
    reference: bool = True,
    figsize: tuple[float, float] = (5, 5),
    title: str | None = None,
) -> Figure:
    """Draw one or several rotated frames in one axes, with the fixed reference frame dashed.

    Parameters
    ----------
    rotations : array_like, shape (3, 3) or (n, 3, 3)
        Rotation matrices; each one is drawn as a solid frame.
    labels : sequence of str, optional
        One suffix per rotated frame, appended to its axis names. By default primes
        (``x'``, ``x''``, ``x'''``) for up to three frames, then ``x1``, ``x2``, …
    reference : bool, optional
        Also draw the reference frame (the identity), dashed and faint.
    figsize : tuple of float, optional
        Figure size in inches.
    title : str, optional
        Title of the axes.

    Returns
    -------
    matplotlib.figure.Figure
        A pyplot figure with one 3D axes.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> import eulerlib
    >>> Rs = eulerlib.euler_to_matrix([[30, 0, 0], [30, 20, 0]], "ZYX", degrees=True)
    >>> fig = plot_frames(Rs)
    >>> sorted(line.get_label() for line in fig.axes[0].get_lines())
    ['x', "x'", "x''", 'y', "y'", "y''", 'z', "z'", "z''"]
    >>> plt.close(fig)
    """
    matrices = as_rotations(rotations, "rotations", _CHECKED)
    if matrices.ndim == 2:
        matrices = matrices[None]
    if matrices.ndim != 3:
        raise ValueError(
            f"rotations must have shape (3, 3) or (n, 3, 3), got shape {matrices.shape}"
        )
    count = matrices.shape[0]
    suffixes = _default_suffixes(count) if labels is None else list(labels)
    if len(suffixes) != count:
        raise ValueError(f"labels must have one entry per rotation ({count}), got {len(suffixes)}")
    ax = new_3d_axes(figsize=figsize, title=title)
    if reference:
        draw_frame(ax, None, linestyle="--", alpha=0.45, linewidth=1.5)
    for matrix, suffix in zip(matrices, suffixes, strict=True):
        draw_frame(ax, matrix, label_suffix=suffix)
    figure: Figure = ax.figure
    return figure


def _highlight_axis(ax: Axes3D, direction: NDArray[np.float64], limit: float = 1.1) -> Any:
    """A thick translucent line through the origin along ``direction``: the axis of a step."""
    ends = np.stack([-limit * direction, limit * direction])
    (line,) = ax.plot(
        ends[:, 0],
        ends[:, 1],
        ends[:, 2],
        color=HIGHLIGHT_COLOR,
        linewidth=7.0,
        alpha=0.6,
        solid_capstyle="round",
        label="rotation axis",
        zorder=0,
    )
    line.set_gid("rotation-axis")
    return line


def plot_sequence_steps(
    angles: ArrayLike,
    seq: str = "ZYX",
    *,
    degrees: bool = False,
    figsize: tuple[float, float] | None = None,
) -> Figure:
    """The three elementary rotations of a sequence, step by step, read two ways.

    Top row, *intrinsic* reading: turn about the first axis, then about the **moved** second
    axis, then about the twice-moved third axis. Bottom row, *extrinsic* reading of the same
    rotation: the same angles in reverse order, each about a **fixed** reference axis. Each
    panel shows the frame before the step (dashed), the frame after it (solid, one more prime
    on the axis names) and the axis of the step (a thick golden line). The last panels of the
    two rows show the same frame, because both rows build the same product
    ``R = R_a(α) R_b(β) R_c(γ)``: the top row from left to right (each new factor on the right
    turns about a moved axis), the bottom row from right to left (each new factor on the left
    turns about a fixed axis).

    Parameters
    ----------
    angles : array_like, shape (3,)
        Angle ``i`` goes with letter ``i`` of ``seq``.
    seq : str, optional
        Any of the 24 sequences; an extrinsic one is shown through its intrinsic twin.
    degrees : bool, optional
        Read ``angles`` in degrees.
    figsize : tuple of float, optional
        Figure size; ``(11, 7.5)`` by default.

    Returns
    -------
    matplotlib.figure.Figure
        Six 3D axes: intrinsic steps 1–3 on the top row, extrinsic steps 1–3 below.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig = plot_sequence_steps([30, 20, 10], "ZYX", degrees=True)
    >>> [ax.get_title() for ax in fig.axes[:3]]
    ['1. 30° about z', "2. 20° about y'", "3. 10° about x''"]
    >>> plt.close(fig)
    """
    import matplotlib.pyplot as plt

    parsed = parse_sequence(seq)
    axes, values = _intrinsic_steps(angles, seq, degrees)
    moving = _partial_products(axes, values)
    # Extrinsic reading: the reversed steps about the fixed axes, each multiplied on the left.
    fixed = np.empty((3, 3, 3))
    previous = np.eye(3)
    for step in range(3):
        axis = axes[2 - step]
        previous = elementary_rotation(axis, values[2 - step]) @ previous
        fixed[step] = previous
    intrinsic_seq = "".join(AXIS_LETTERS[a] for a in axes).upper()
    fig = plt.figure(figsize=figsize if figsize is not None else (11, 7.5))
    for step in range(3):
        before = np.eye(3) if step == 0 else moving[step - 1]
        axis = axes[step]
        degrees_text = f"{np.degrees(values[step]) + 0.0:.4g}°"
        ax = new_3d_axes(
            fig,
            (2, 3, step + 1),
            title=f"{step + 1}. {degrees_text} about {AXIS_LETTERS[axis]}{PRIME * step}",
        )
        _highlight_axis(ax, before[:, axis])
        draw_frame(ax, before, linestyle="--", alpha=0.45, linewidth=1.5, label_suffix="'" * step)
        draw_frame(ax, moving[step], label_suffix="'" * (step + 1))
    for step in range(3):
        before = np.eye(3) if step == 0 else fixed[step - 1]
        axis = axes[2 - step]
        degrees_text = f"{np.degrees(values[2 - step]) + 0.0:.4g}°"
        ax = new_3d_axes(
            fig,
            (2, 3, step + 4),
            title=f"{step + 1}. {degrees_text} about fixed {AXIS_LETTERS[axis]}",
        )
        _highlight_axis(ax, np.eye(3)[:, axis])
        draw_frame(ax, before, linestyle="--", alpha=0.45, linewidth=1.5, label_suffix="'" * step)
        draw_frame(ax, fixed[step], label_suffix="'" * (step + 1))
    fig.text(0.01, 0.73, f"intrinsic {intrinsic_seq}\n(moving axes)", fontsize=11, va="center")
    fig.text(
        0.01,
        0.27,
        f"extrinsic {intrinsic_seq[::-1].lower()}\n(fixed axes)",
        fontsize=11,
        va="center",
    )
    given = values if parsed.intrinsic else values[::-1]
    fig.suptitle(
        f"{seq} with angles ({_degrees_text(given)}): the same rotation, read two ways",
        fontsize=12,
    )
    return fig
