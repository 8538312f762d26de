"""Three nested gimbal rings driven by the three Euler angles, and the slide into gimbal lock.

The outer ring turns with the first angle about the first axis, the middle ring is carried by
it and turns with the second angle, the inner ring with the third. At the singular middle
angle the outer and middle rings lie in one plane and one degree of freedom is gone.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._validation import as_vectors
from eulerlib.sequences import parse_sequence

if TYPE_CHECKING:
    from matplotlib.animation import FuncAnimation
    from matplotlib.figure import Figure
    from mpl_toolkits.mplot3d.axes3d import Axes3D

from eulerlib.plotting._base import (
    AXIS_LETTERS,
    PRIME,
    RING_COLORS,
    RING_RADII,
    _intrinsic_steps,
    _partial_products,
    _style_axes,
)
from eulerlib.plotting.frames import draw_frame, new_3d_axes

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
    angles: ArrayLike, seq: str = "ZYX", *, degrees: bool = False
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
    seq : str, optional
        Any of the 24 sequences; an extrinsic one is built as its intrinsic twin (so the outer
        ring turns with its *last* angle).
    degrees : bool, optional
        Read ``angles`` in degrees.

    Returns
    -------
    ndarray, shape (3, 3)
        Row ``i`` is the unit normal of ring ``i`` (outer, middle, inner).

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
    axes, values = _intrinsic_steps(angles, seq, degrees)
    return _ring_bases(axes, _partial_products(axes, values))[2]


def gimbal_ring_points(
    angles: ArrayLike, seq: str = "ZYX", *, degrees: bool = False, n: int = 120
) -> list[NDArray[np.float64]]:
    """Points on the three gimbal rings, outer to inner (see :func:`gimbal_ring_normals`).

    Parameters
    ----------
    angles : array_like, shape (3,)
        Angle ``i`` goes with letter ``i`` of ``seq``.
    seq : str, optional
        Any of the 24 sequences.
    degrees : bool, optional
        Read ``angles`` in degrees.
    n : int, optional
        Points per ring; the first point is repeated at the end so the ring closes.

    Returns
    -------
    list of 3 ndarrays, shape (n, 3)
        Circles of radius 1.0, 0.8 and 0.6 around the origin, each perpendicular to its normal.

    Examples
    --------
    >>> rings = gimbal_ring_points([30, 20, 10], "ZYX", degrees=True, n=60)
    >>> [ring.shape for ring in rings]
    [(60, 3), (60, 3), (60, 3)]
    >>> np.linalg.norm(rings[1], axis=1).round(12).min()
    np.float64(0.8)
    """
    if not isinstance(n, (int, np.integer)) or n < 4:
        raise ValueError(f"n must be an integer of at least 4, got {n!r}")
    axes, values = _intrinsic_steps(angles, seq, degrees)
    first, second, _ = _ring_bases(axes, _partial_products(axes, values))
    t = np.linspace(0.0, 2.0 * np.pi, int(n))
    c, s = np.cos(t)[:, None], np.sin(t)[:, None]
    return [RING_RADII[r] * (c * first[r] + s * second[r]) for r in range(3)]


def _draw_gimbal(ax: Axes3D, angles: NDArray[np.float64], seq: str) -> None:
    """Rings, pivots, first and third axes and the body frame, angles in radians."""
    from eulerlib.gimbal_lock import gimbal_lock_status

    axes, values = _intrinsic_steps(angles, seq, False)
    frames = _partial_products(axes, values)
    rings = gimbal_ring_points(angles, seq, n=120)
    names = [f"{AXIS_LETTERS[a]}{PRIME * r}" for r, a in enumerate(axes)]
    handles = []
    for r in range(3):
        ring = rings[r]
        (line,) = ax.plot(
            ring[:, 0],
            ring[:, 1],
            ring[:, 2],
            color=RING_COLORS[r],
            linewidth=3.0,
            label=f"ring {r + 1}: {np.degrees(values[r]) + 0.0:.0f}° about {names[r]}",
        )
        handles.append(line)
        # Pivots: ring r turns about axis a_r of the frame before it (fixed for the outer one).
        pivot = (np.eye(3) if r == 0 else frames[r - 1])[:, axes[r]]
        outer = RING_RADII[r - 1] if r > 0 else RING_RADII[0] + 0.15
        for sign in (-1.0, 1.0):
            ends = sign * np.stack([RING_RADII[r] * pivot, outer * pivot])
            ax.plot(ends[:, 0], ends[:, 1], ends[:, 2], color="0.25", linewidth=4.0)
    # The axes of the first and third angle: they coincide at gimbal lock.
    for r, direction in ((0, np.eye(3)[:, axes[0]]), (2, frames[1][:, axes[2]])):
        ends = np.stack([-1.25 * direction, 1.25 * direction])
        ax.plot(
            ends[:, 0],
            ends[:, 1],
            ends[:, 2],
            color=RING_COLORS[r],
            linestyle=":",
            linewidth=1.5,
        )
    draw_frame(ax, frames[2], scale=0.45, linewidth=1.5)
    matrix = frames[2]
    status = gimbal_lock_status(matrix, "".join(AXIS_LETTERS[a] for a in axes).upper())
    given = np.degrees(values if seq.isupper() else values[::-1]) + 0.0
    shown = ", ".join(f"{v:.0f}°" for v in given)
    between = np.degrees(np.arccos(np.clip(abs(frames[1][:, axes[2]][axes[0]]), 0.0, 1.0)))
    state = (
        "GIMBAL LOCK" if status.locked else f"{float(np.degrees(status.distance)):.0f}° from lock"
    )
    ax.set_title(
        f"{seq} ({shown})\naxes 1 and 3 are {float(between):.0f}° apart: {state}",
        fontsize=9,
    )
    ax.legend(handles=handles, loc="upper left", fontsize=7, frameon=False)


def plot_gimbal(
    angles: ArrayLike,
    seq: str = "ZYX",
    *,
    degrees: bool = False,
    ax: Axes3D | None = None,
    figsize: tuple[float, float] = (5, 5),
) -> Figure:
    """Draw a three-ring gimbal set to ``angles``, with the body frame inside.

    The rings are the ones of :func:`gimbal_ring_points` (outer purple, middle orange, inner
    cyan), with their pivots as short dark bars, and the axes of the first and third angle as
    dotted lines: at gimbal lock those two lines coincide and the outer and middle rings lie in
    one plane. The title says how far apart the two axes are.

    Parameters
    ----------
    angles : array_like, shape (3,)
        Angle ``i`` goes with letter ``i`` of ``seq``.
    seq : str, optional
        Any of the 24 sequences.
    degrees : bool, optional
        Read ``angles`` in degrees.
    ax : Axes3D, optional
        Draw into this axes; by default a new figure with one axes from :func:`new_3d_axes`.
    figsize : tuple of float, optional
        Size of a new figure.

    Returns
    -------
    matplotlib.figure.Figure

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
    values = as_vectors(angles, "angles")
    if values.shape != (3,):
        raise ValueError(f"angles must be three numbers, got shape {values.shape}")
    radians = np.radians(values) if degrees else values
    if ax is None:
        ax = new_3d_axes(figsize=figsize)
    _draw_gimbal(ax, radians, seq)
    figure: Figure = ax.figure
    return figure


def animate_gimbal_lock(
    *, seq: str = "ZYX", frames: int = 48, figsize: tuple[float, float] = (5, 5)
) -> FuncAnimation:
    """An animation that turns the middle gimbal ring into lock.

    The first and third angles stay at 40° and 25° while the middle angle sweeps from 0° to 90°
    (Tait–Bryan) or from 90° to 0° (proper Euler). The dotted axes of the first and third
    angle close in on each other until they coincide in the last frame: from then on turning
    the outer ring or the inner ring does the same thing, and the two angles can no longer be
    told apart.

    Parameters
    ----------
    seq : str, optional
        Any of the 24 sequences.
    frames : int, optional
        Number of frames; the last one is exactly at lock.
    figsize : tuple of float, optional
        Figure size in inches.

    Returns
    -------
    matplotlib.animation.FuncAnimation
        On a figure that is not managed by pyplot (nothing to close, nothing shown twice). In a
        notebook show it with ``HTML(anim.to_jshtml())``; save it with
        ``anim.save("gimbal.gif", writer=PillowWriter(fps=8))``.

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

    parsed = parse_sequence(seq)
    if not isinstance(frames, (int, np.integer)) or frames < 2:
        raise ValueError(f"frames must be an integer of at least 2, got {frames!r}")
    lock = 0.0 if parsed.proper else 90.0
    middle = np.linspace(90.0 - lock, lock, int(frames))
    outer_inner = (40.0, 25.0) if parsed.intrinsic else (25.0, 40.0)
    fig = Figure(figsize=figsize)
    ax = new_3d_axes(fig)

    def update(value: float) -> list[Any]:
        ax.cla()
        _style_axes(ax, 1.2, None)
        angles = np.radians([outer_inner[0], value, outer_inner[1]])
        _draw_gimbal(ax, angles, seq)
        return []

    return FuncAnimation(fig, update, frames=middle, interval=120, blit=False, repeat=True)
