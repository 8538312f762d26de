"""Three nested gimbal rings driven by the three Euler angles, and the slide into gimbal lock.

The outer ring turns with the first angle about the first axis, the middle ring is carried by
it and turns with the second angle, the inner ring with the third. At the singular middle
angle the outer and middle rings lie in one plane and one degree of freedom is gone.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib.conventions import Convention, get_convention
from eulerlib.plotting._base import (
    AXIS_LETTERS,
    PRIME,
    RING_COLORS,
    RING_RADII,
    add_3d_axes,
    intrinsic_steps,
    partial_products,
    pyplot_figure,
    style_axes,
)
from eulerlib.plotting._checks import (
    check_axes3d,
    check_count,
    check_figsize,
    three_angles,
)
from eulerlib.plotting.frames import frame_artists

if TYPE_CHECKING:
    from matplotlib.animation import FuncAnimation
    from matplotlib.figure import Figure
    from mpl_toolkits.mplot3d.axes3d import Axes3D

__all__ = [
    "animate_gimbal_lock",
    "gimbal_ring_normals",
    "gimbal_ring_points",
    "plot_gimbal",
]


def _ring_bases(
    axes: tuple[int, int, int], frames: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """For each ring, two in-plane unit vectors and the normal, as world vectors (3, 3) each.

    Ring 0 (outer) turns about axis a0 and holds the pivots of ring 1 (axis a1); ring 1 turns
    about a1 and holds the pivots of ring 2 (axis a2); ring 2 (inner) turns about a2 and carries
    the body. Ring ``r`` lies in the plane of its own axis and the next one (for the inner ring:
    its axis and the remaining axis ⟂ a1), so its normal is the third coordinate axis of the
    frame it moves with.
    """
    a0, a1, a2 = axes
    in_plane = ((a0, a1), (a1, a2), (a2, 3 - a1 - a2))
    first = np.empty((3, 3))
    second = np.empty((3, 3))
    normal = np.empty((3, 3))
    for ring, (p, q) in enumerate(in_plane):
        n = 3 - p - q
        first[ring] = frames[ring][:, p]
        second[ring] = frames[ring][:, q]
        normal[ring] = frames[ring][:, n]
    return first, second, normal


def gimbal_ring_normals(
    angles: ArrayLike, seq: str | Convention = "ZYX", *, degrees: bool = False
) -> NDArray[np.float64]:
    """Unit normals of the three gimbal rings, outer to inner.

    The gimbal realises the intrinsic form of ``seq`` with axes (a0, a1, a2) and angles
    (α, β, γ): the outer ring turns by α about the fixed axis a0; the middle ring, pivoted in
    it, turns by β about the once-moved a1; the inner ring turns by γ about the twice-moved a2.
    Each ring lies in the plane of its own axis and the axis of the ring it carries, so its
    normal is a coordinate axis of the frame it moves with:

    * outer ring: axis ``k`` of ``R_a0(α)``, where ``k`` is neither a0 nor a1;
    * middle ring: axis ``m`` of ``R_a0(α) R_a1(β)``, where ``m`` is neither a1 nor a2;
    * inner ring: axis ``a1`` of ``R_a0(α) R_a1(β) R_a2(γ)``.

    At the singular middle angle (β = ±90° for Tait–Bryan, 0° or 180° for proper Euler) the
    outer and middle normals are parallel: those two rings are coplanar and the first and third
    axes coincide, which is gimbal lock (Rose 2015, Part 2, eq 4).

    Parameters
    ----------
    angles : array_like, shape (3,)
        Angle ``i`` goes with letter ``i`` of ``seq``.
    seq : str or Convention, optional
        Any of the 24 sequences, or a preset such as ``"rose"``; an extrinsic sequence is built
        as its intrinsic twin (so the outer ring turns with its *last* angle).
    degrees : bool, optional
        Read ``angles`` in degrees.

    Returns
    -------
    ndarray, shape (3, 3)
        Row ``i`` is the unit normal of ring ``i`` (outer, middle, inner).

    Raises
    ------
    TypeError, ValueError
        For a bad argument; the message names the argument.

    Examples
    --------
    >>> gimbal_ring_normals([0, 0, 0], "ZYX")          # at rest: three orthogonal rings
    array([[1., 0., 0.],
           [0., 0., 1.],
           [0., 1., 0.]])
    >>> n = gimbal_ring_normals([30, 90, 10], "ZYX", degrees=True)
    >>> bool(np.isclose(abs(n[0] @ n[1]), 1.0))      # outer and middle rings coplanar
    True
    """
    values = three_angles(angles, degrees)
    axes, steps = intrinsic_steps(values, get_convention(seq))
    return _ring_bases(axes, partial_products(axes, steps))[2]


def gimbal_ring_points(
    angles: ArrayLike, seq: str | Convention = "ZYX", *, degrees: bool = False, n: int = 120
) -> list[NDArray[np.float64]]:
    """Points on the three gimbal rings, outer to inner (see :func:`gimbal_ring_normals`).

    Parameters
    ----------
    angles : array_like, shape (3,)
        Angle ``i`` goes with letter ``i`` of ``seq``.
    seq : str or Convention, optional
        Any of the 24 sequences, or a preset such as ``"rose"``.
    degrees : bool, optional
        Read ``angles`` in degrees.
    n : int, optional
        Points per ring, at least 3; the first point is repeated at the end so the ring closes.

    Returns
    -------
    list of 3 ndarrays, shape (n, 3)
        Circles of radius 1.0, 0.8 and 0.6 around the origin, each perpendicular to its normal.

    Raises
    ------
    TypeError, ValueError
        For a bad argument; the message names the argument.

    Examples
    --------
    >>> rings = gimbal_ring_points([30, 20, 10], "ZYX", degrees=True, n=60)
    >>> [ring.shape for ring in rings]
    [(60, 3), (60, 3), (60, 3)]
    >>> np.linalg.norm(rings[1], axis=1).round(12).min()
    np.float64(0.8)
    """
    values = three_angles(angles, degrees)
    convention = get_convention(seq)
    count = check_count(n, "n", 3)
    return _ring_points(values, convention, count)


def _ring_points(
    values: NDArray[np.float64], convention: Convention, n: int
) -> list[NDArray[np.float64]]:
    """Body of :func:`gimbal_ring_points` for checked angles (radians)."""
    axes, steps = intrinsic_steps(values, convention)
    first, second, _ = _ring_bases(axes, partial_products(axes, steps))
    t = np.linspace(0.0, 2.0 * np.pi, n)
    c, s = np.cos(t)[:, None], np.sin(t)[:, None]
    return [RING_RADII[r] * (c * first[r] + s * second[r]) for r in range(3)]


#: Line styles of the outer, middle and inner ring, so that the rings differ by more than colour.
RING_STYLES: tuple[Any, ...] = ("-", (0, (4.0, 1.5)), (0, (1.0, 1.2)))
#: Words for the rings, outer to inner.
RING_NAMES = ("outer", "middle", "inner")
_STYLE_WORDS = ("solid", "dashed", "dotted")


def _draw_gimbal(ax: Axes3D, values: NDArray[np.float64], convention: Convention) -> None:
    """Rings, pivots, first and third axes and the body frame, for checked angles (radians).

    The rings differ in colour, line style (outer solid, middle dashed, inner dotted) and
    radius; the legend names each ring with its style, its angle and its axis. The tick labels
    are left out (the rings have radius 1, 0.8 and 0.6; the numbers would only crowd them).
    """
    from eulerlib.gimbal_lock import gimbal_lock_status

    axes, steps = intrinsic_steps(values, convention)
    frames = partial_products(axes, steps)
    rings = _ring_points(values, convention, 120)
    named = convention.name != convention.seq
    angle_names = convention.to_intrinsic(convention.angle_names)
    names = [f"{AXIS_LETTERS[a]}{PRIME * r}" for r, a in enumerate(axes)]
    handles = []
    for r in range(3):
        ring = rings[r]
        angle = f"{angle_names[r]} " if named else ""
        (line,) = ax.plot(
            ring[:, 0],
            ring[:, 1],
            ring[:, 2],
            color=RING_COLORS[r],
            linestyle=RING_STYLES[r],
            linewidth=3.0,
            label=f"{RING_NAMES[r]} ({_STYLE_WORDS[r]}): {angle}"
            f"{np.degrees(steps[r]) + 0.0:.0f}° about {names[r]}",
        )
        handles.append(line)
        # Pivots: ring r turns about axis a_r of the frame before it (fixed for the outer one).
        pivot = (np.eye(3) if r == 0 else frames[r - 1])[:, axes[r]]
        outer = RING_RADII[r - 1] if r > 0 else RING_RADII[0] + 0.15
        for sign in (-1.0, 1.0):
            ends = sign * np.stack([RING_RADII[r] * pivot, outer * pivot])
            ax.plot(ends[:, 0], ends[:, 1], ends[:, 2], color="0.25", linewidth=4.0)
    # The axes of the first and third angle, thin and in the colour of their ring: they
    # coincide at gimbal lock.
    for r, direction in ((0, np.eye(3)[:, axes[0]]), (2, frames[1][:, axes[2]])):
        ends = np.stack([-1.25 * direction, 1.25 * direction])
        ax.plot(
            ends[:, 0],
            ends[:, 1],
            ends[:, 2],
            color=RING_COLORS[r],
            linestyle="-.",
            linewidth=1.2,
        )
    frame_artists(ax, frames[2], scale=0.45, linewidth=1.5, fontsize=8.0)
    ax.set_xticklabels([])
    ax.set_yticklabels([])
    ax.set_zticklabels([])
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        axis.labelpad = -8
    status = gimbal_lock_status(frames[2], convention)
    given = np.degrees(values) + 0.0
    if named:
        shown = ", ".join(
            f"{name} {v:.0f}°" for name, v in zip(convention.angle_names, given, strict=True)
        )
        heading = f"{convention.name} ({convention.seq}): {shown}"
    else:
        heading = f"{convention.seq} ({', '.join(f'{v:.0f}°' for v in given)})"
    between = np.degrees(np.arccos(np.clip(abs(frames[1][:, axes[2]][axes[0]]), 0.0, 1.0)))
    state = (
        "GIMBAL LOCK" if status.locked else f"{float(np.degrees(status.distance)):.0f}° from lock"
    )
    ax.set_title(
        f"{heading}\naxes 1 and 3 are {float(between):.0f}° apart: {state}",
        fontsize=9,
    )
    ax.legend(
        handles=handles,
        loc="upper left",
        bbox_to_anchor=(0.0, 0.97),
        fontsize=7,
        frameon=False,
        handlelength=3.2,
        borderaxespad=0.0,
    )


def plot_gimbal(
    angles: ArrayLike,
    seq: str | Convention = "ZYX",
    *,
    degrees: bool = False,
    ax: Axes3D | None = None,
    figsize: tuple[float, float] = (5, 5),
) -> Figure:
    """Draw a three-ring gimbal set to ``angles``, with the body frame inside.

    The rings are the ones of :func:`gimbal_ring_points`, told apart by colour, radius and line
    style (outer solid, middle dashed, inner dotted), with their pivots as short dark bars, and
    the axes of the first and third angle as thin dash-dotted lines in the colour of their ring:
    at gimbal lock those two lines coincide and the outer and middle rings lie in one plane.
    The title says how far apart the two axes are; the legend, inside the axes, says which
    angle turns which ring.

    Parameters
    ----------
    angles : array_like, shape (3,)
        Angle ``i`` goes with letter ``i`` of ``seq``.
    seq : str or Convention, optional
        Any of the 24 sequences, or a preset such as ``"rose"`` (its angle names then appear in
        the title and the legend).
    degrees : bool, optional
        Read ``angles`` in degrees.
    ax : Axes3D, optional
        Draw into this 3D axes; by default a new figure with one axes from
        :func:`~eulerlib.plotting.new_3d_axes`.
    figsize : tuple of float, optional
        Size of a new figure.

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    TypeError, ValueError
        For a bad argument, before any figure is created; the message names the argument.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig = plot_gimbal([30, 90, 10], "ZYX", degrees=True)
    >>> fig.axes[0].get_title().splitlines()[1]
    'axes 1 and 3 are 0° apart: GIMBAL LOCK'
    >>> plt.close(fig)
    """
    values = three_angles(angles, degrees)
    convention = get_convention(seq)
    target = None if ax is None else check_axes3d(ax)
    size = check_figsize(figsize)
    if target is not None:
        _draw_gimbal(target, values, convention)
        figure: Figure = target.figure
        return figure
    with pyplot_figure(size) as fig:
        _draw_gimbal(add_3d_axes(fig, (1, 1, 1), 1.2, None), values, convention)
    return fig


def animate_gimbal_lock(
    *,
    seq: str | Convention = "ZYX",
    frames: int = 48,
    figsize: tuple[float, float] = (5, 5),
) -> FuncAnimation:
    """An animation that turns the middle gimbal ring into lock.

    The first and third angles stay at 40° and 25° while the middle angle sweeps from 0° to 90°
    (Tait–Bryan) or from 90° to 0° (proper Euler). The dash-dotted axes of the first and third
    angle close in on each other until they coincide in the last frame: from then on turning
    the outer ring or the inner ring does the same thing, and the two angles can no longer be
    told apart.

    Parameters
    ----------
    seq : str or Convention, optional
        Any of the 24 sequences, or a preset such as ``"rose"``.
    frames : int, optional
        Number of frames, at least 2; the last one is exactly at lock.
    figsize : tuple of float, optional
        Figure size in inches.

    Returns
    -------
    matplotlib.animation.FuncAnimation
        On a figure that is not managed by pyplot (nothing to close, nothing shown twice). In a
        notebook show it with ``HTML(anim.to_jshtml())``; save it with
        ``anim.save("gimbal.gif", writer=PillowWriter(fps=8))``.

    Raises
    ------
    TypeError, ValueError
        For a bad argument, before any figure is created; the message names the argument.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> anim = animate_gimbal_lock(frames=4)
    >>> len(list(anim.new_frame_seq()))
    4
    >>> anim.to_jshtml().count("data:image/png;base64")  # one picture per frame
    4
    """
    from matplotlib.animation import FuncAnimation
    from matplotlib.figure import Figure

    convention = get_convention(seq)
    count = check_count(frames, "frames", 2)
    size = check_figsize(figsize)
    parsed = convention.parsed
    lock = 0.0 if parsed.proper else 90.0
    middle = np.linspace(90.0 - lock, lock, count)
    outer_inner = (40.0, 25.0) if parsed.intrinsic else (25.0, 40.0)
    fig = Figure(figsize=size)
    ax = add_3d_axes(fig, (1, 1, 1), 1.2, None)

    def update(value: float) -> list[Any]:
        ax.cla()
        style_axes(ax, 1.2, None)
        angles = np.radians([outer_inner[0], value, outer_inner[1]])
        _draw_gimbal(ax, angles, convention)
        return []

    return FuncAnimation(fig, update, frames=middle, interval=120, blit=False, repeat=True)
