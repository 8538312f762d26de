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

from eulerlib._validation import ROTATION_ATOL, as_vectors, check_flag, rotation_check
from eulerlib.conventions import Convention, get_convention
from eulerlib.elementary import elementary_rotation
from eulerlib.plotting._base import (
    AXIS_COLORS,
    AXIS_LETTERS,
    HIGHLIGHT_COLOR,
    PRIME,
    add_3d_axes,
    arrow_head,
    degrees_text,
    intrinsic_steps,
    partial_products,
    pyplot_figure,
)
from eulerlib.plotting._checks import (
    check_alpha,
    check_axes3d,
    check_colors,
    check_figsize,
    check_figure,
    check_linestyle,
    check_optional_text,
    check_position,
    check_positive,
    check_text,
    check_texts,
    one_rotation,
    rotation_stack,
    three_angles,
)

if TYPE_CHECKING:
    from matplotlib.figure import Figure, FigureBase
    from mpl_toolkits.mplot3d.axes3d import Axes3D

__all__ = [
    "draw_frame",
    "new_3d_axes",
    "plot_frames",
    "plot_sequence_steps",
]


def new_3d_axes(
    fig: FigureBase | None = None,
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
        Figure (or subfigure) to add the axes to. By default a new pyplot figure of size
        ``figsize``.
    position : int or tuple of int, optional
        Subplot position, as ``fig.add_subplot`` takes it: ``111`` or ``(1, 3, 2)``.
    limit : float, optional
        The axes show ``[-limit, limit]`` in x, y and z (a cube, drawn as a cube); > 0.
    title : str, optional
        Title of the axes.
    figsize : tuple of float, optional
        Size of a new figure, in inches (two numbers > 0).

    Returns
    -------
    mpl_toolkits.mplot3d.axes3d.Axes3D

    Raises
    ------
    TypeError, ValueError
        For a bad argument, before any figure is created; the message names the argument.

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
    target = check_figure(fig)
    where = check_position(position)
    half = check_positive(limit, "limit")
    heading = check_optional_text(title, "title")
    size = check_figsize(figsize)
    if target is not None:
        return add_3d_axes(target, where, half, heading)
    with pyplot_figure(size) as new:
        return add_3d_axes(new, where, half, heading)


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
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
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
        Length of the arrows; > 0.
    alpha : float, optional
        Opacity, 0 to 1.
    linestyle : str, optional
        Line style of the arrow shafts: ``"-"`` for a rotated frame, ``"--"`` for a reference.
    linewidth : float, optional
        Width of the shafts; > 0.
    colors : sequence of 3 colours, optional
        Colours of the x, y, z arrows; by default :data:`AXIS_COLORS` (vermillion, bluish
        green, blue: told apart with any colour vision, and by their labels too).
    labels : sequence of 3 str, optional
        Names of the axes, written at the arrow tips (``""`` writes none).
    label_suffix : str, optional
        Appended to every label, for example ``"'"`` for the frame after one rotation.
    validate, repair, atol
        As in :func:`eulerlib.matrix_to_euler`: ``R`` must be a rotation within ``atol``
        (default), or is replaced by the nearest rotation (``repair=True``), or is drawn as it
        is (``validate=False``: the columns of any matrix, for example a shear).

    Returns
    -------
    list
        Nine artists, three per axis in the order x, y, z: the shaft (a ``Line3D`` from the
        origin to the tip, labelled with the axis name), the arrowhead (a ``Poly3DCollection``)
        and the label (a ``Text3D``).

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
    target = check_axes3d(ax)
    matrix = one_rotation(R, "R", rotation_check(validate, repair, atol))
    start = as_vectors(origin, "origin")
    if start.shape != (3,):
        raise ValueError(f"origin must be one point (3 numbers), got shape {start.shape}")
    return frame_artists(
        target,
        matrix,
        origin=start,
        scale=check_positive(scale, "scale"),
        alpha=check_alpha(alpha),
        linestyle=check_linestyle(linestyle),
        linewidth=check_positive(linewidth, "linewidth"),
        colors=check_colors(colors, "colors", 3),
        labels=check_texts(labels, "labels", 3, "the names of x, y, z"),
        label_suffix=check_text(label_suffix, "label_suffix"),
    )


def frame_artists(
    ax: Axes3D,
    matrix: NDArray[np.float64],
    *,
    origin: NDArray[np.float64] | None = None,
    scale: float = 1.0,
    alpha: float = 1.0,
    linestyle: Any = "-",
    linewidth: float = 2.0,
    colors: Sequence[Any] = AXIS_COLORS,
    labels: Sequence[str] = AXIS_LETTERS,
    label_suffix: str = "",
    fontsize: float = 10.0,
) -> list[Any]:
    """Body of :func:`draw_frame` for checked arguments (the plotting modules call it)."""
    start = np.zeros(3) if origin is None else origin
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
        head = arrow_head(ax, tip, direction, 0.045 * scale, color=colors[i], alpha=alpha)
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
            fontsize=fontsize,
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
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
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
    validate, repair, atol
        How ``rotations`` are checked, as in :func:`draw_frame`.

    Returns
    -------
    matplotlib.figure.Figure
        A pyplot figure with one 3D axes.

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
    >>> Rs = eulerlib.euler_to_matrix([[30, 0, 0], [30, 20, 0]], "ZYX", degrees=True)
    >>> fig = plot_frames(Rs)
    >>> sorted(line.get_label() for line in fig.axes[0].get_lines())
    ['x', "x'", "x''", 'y', "y'", "y''", 'z', "z'", "z''"]
    >>> plt.close(fig)
    """
    matrices = rotation_stack(rotations, "rotations", rotation_check(validate, repair, atol))
    count = matrices.shape[0]
    suffixes = (
        _default_suffixes(count)
        if labels is None
        else check_texts(labels, "labels", count, "one suffix per rotation")
    )
    with_reference = check_flag(reference, "reference")
    size = check_figsize(figsize)
    heading = check_optional_text(title, "title")
    with pyplot_figure(size) as fig:
        ax = add_3d_axes(fig, (1, 1, 1), 1.2, heading)
        if with_reference:
            frame_artists(ax, np.eye(3), linestyle="--", alpha=0.45, linewidth=1.5)
        for matrix, suffix in zip(matrices, suffixes, strict=True):
            frame_artists(ax, matrix, label_suffix=suffix)
    return fig


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
    seq: str | Convention = "ZYX",
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
    turns about a fixed axis). The name of each row stands upright in the left margin, clear
    of the axis labels of the panels.

    Parameters
    ----------
    angles : array_like, shape (3,)
        Angle ``i`` goes with letter ``i`` of ``seq``.
    seq : str or Convention, optional
        Any of the 24 sequences, or a preset such as ``"rose"`` (drawn with its sequence); an
        extrinsic sequence is shown through its intrinsic twin.
    degrees : bool, optional
        Read ``angles`` in degrees.
    figsize : tuple of float, optional
        Figure size; ``(11, 7.5)`` by default.

    Returns
    -------
    matplotlib.figure.Figure
        Six 3D axes: intrinsic steps 1–3 on the top row, extrinsic steps 1–3 below.

    Raises
    ------
    TypeError, ValueError
        For a bad argument, before any figure is created; the message names the argument.

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
    values = three_angles(angles, degrees)
    convention = get_convention(seq)
    size = (11.0, 7.5) if figsize is None else check_figsize(figsize)
    axes, steps = intrinsic_steps(values, convention)
    moving = partial_products(axes, steps)
    # Extrinsic reading: the reversed steps about the fixed axes, each multiplied on the left.
    fixed = np.empty((3, 3, 3))
    previous = np.eye(3)
    for step in range(3):
        axis = axes[2 - step]
        previous = elementary_rotation(axis, steps[2 - step]) @ previous
        fixed[step] = previous
    intrinsic_seq = "".join(AXIS_LETTERS[a] for a in axes).upper()
    with pyplot_figure(size) as fig:
        for step in range(3):
            before = np.eye(3) if step == 0 else moving[step - 1]
            axis = axes[step]
            angle_text = f"{np.degrees(steps[step]) + 0.0:.4g}°"
            ax = add_3d_axes(
                fig,
                (2, 3, step + 1),
                1.2,
                f"{step + 1}. {angle_text} about {AXIS_LETTERS[axis]}{PRIME * step}",
            )
            _highlight_axis(ax, before[:, axis])
            frame_artists(
                ax, before, linestyle="--", alpha=0.45, linewidth=1.5, label_suffix=PRIME * step
            )
            frame_artists(ax, moving[step], label_suffix=PRIME * (step + 1))
        for step in range(3):
            before = np.eye(3) if step == 0 else fixed[step - 1]
            axis = axes[2 - step]
            angle_text = f"{np.degrees(steps[2 - step]) + 0.0:.4g}°"
            ax = add_3d_axes(
                fig,
                (2, 3, step + 4),
                1.2,
                f"{step + 1}. {angle_text} about fixed {AXIS_LETTERS[axis]}",
            )
            _highlight_axis(ax, np.eye(3)[:, axis])
            frame_artists(
                ax, before, linestyle="--", alpha=0.45, linewidth=1.5, label_suffix=PRIME * step
            )
            frame_artists(ax, fixed[step], label_suffix=PRIME * (step + 1))
        rows = (
            (0.73, f"intrinsic {intrinsic_seq}\n(moving axes)"),
            (0.29, f"extrinsic {intrinsic_seq[::-1].lower()}\n(fixed axes)"),
        )
        for height, words in rows:
            fig.text(
                0.01,
                height,
                words,
                rotation=90,
                fontsize=11,
                ha="left",
                va="center",
                gid="row",
                multialignment="center",
            )
        fig.suptitle(
            f"{convention.label} with angles ({degrees_text(values)}): "
            "the same rotation, read two ways",
            fontsize=12,
        )
    return fig
