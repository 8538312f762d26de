"""Seeing rotations: frames, step-by-step sequences, a rotating body, and a gimbal.

A rotation matrix ``R`` is easiest to understand as a picture of the frame it produces: its
columns are where the reference axes x, y and z end up (``R @ e_i`` is column ``i``). Every
function here draws that picture on a matplotlib 3D axes, in the same colours throughout the
course: **x red, y green, z blue**, the fixed reference frame **dashed**, a rotated frame
**solid**, and equal scales on the three axes so that right angles look like right angles.

What there is
-------------
* :func:`new_3d_axes`, :func:`draw_frame`, :func:`plot_frames`: one or several frames.
* :func:`plot_sequence_steps`: the three elementary rotations of a sequence, one panel each,
  read intrinsically (about the moving axes) on the top row and extrinsically (about the fixed
  axes, in reverse order) on the bottom row. Both rows end in the same frame.
* :func:`aircraft_segments`, :func:`draw_aircraft`, :func:`plot_body_rotation`: a wireframe
  aircraft, nose along x and up along z (Rose) or y (Baker), so that yaw, pitch and roll are
  obvious; drawn before a rotation, after it, and back again with the transpose.
* :func:`gimbal_ring_points`, :func:`gimbal_ring_normals`, :func:`plot_gimbal`,
  :func:`animate_gimbal_lock`: three nested rings driven by the three angles. At the singular
  middle angle (±90° for Tait–Bryan, 0° or 180° for proper Euler) two rings lie in one plane and
  the first and third rotation axes coincide: gimbal lock.
* :func:`explorer` (JupyterLab, needs ipywidgets) with its testable core
  :func:`explorer_state`: sliders for the three angles and a convention selector.

A sequence ``seq`` means what it means everywhere in eulerlib (and in SciPy): uppercase is
intrinsic, lowercase extrinsic, angle ``i`` goes with letter ``i``. An extrinsic sequence is
drawn as its intrinsic twin (letters and angles reversed), which is the same rotation.

matplotlib is imported inside the functions, so ``import eulerlib`` stays light; this module
itself is not imported by ``eulerlib/__init__.py``.

Examples
--------
>>> import matplotlib
>>> matplotlib.use("Agg")
>>> import matplotlib.pyplot as plt
>>> import eulerlib
>>> from eulerlib.plotting import plot_frames
>>> R = eulerlib.euler_to_matrix([30, 20, 10], "ZYX", degrees=True)
>>> fig = plot_frames(R, title="yaw 30°, pitch 20°, roll 10°")
>>> len(fig.axes)
1
>>> plt.close(fig)
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._validation import as_matrices, as_vectors
from eulerlib.elementary import elementary_rotation
from eulerlib.sequences import ALL_SEQUENCES, parse_sequence

if TYPE_CHECKING:
    from matplotlib.animation import FuncAnimation
    from matplotlib.figure import Figure
    from mpl_toolkits.mplot3d.axes3d import Axes3D

__all__ = [
    "aircraft_segments",
    "animate_gimbal_lock",
    "draw_aircraft",
    "draw_frame",
    "explorer",
    "explorer_state",
    "gimbal_ring_normals",
    "gimbal_ring_points",
    "new_3d_axes",
    "plot_body_rotation",
    "plot_frames",
    "plot_gimbal",
    "plot_sequence_steps",
]

AXIS_COLORS = ("tab:red", "tab:green", "tab:blue")
AXIS_LETTERS = ("x", "y", "z")
#: Colours of the outer, middle and inner gimbal ring.
RING_COLORS = ("tab:purple", "tab:orange", "tab:cyan")
#: Radii of the outer, middle and inner gimbal ring.
RING_RADII = (1.0, 0.8, 0.6)
#: Colour of the axis a step of a sequence turns about.
HIGHLIGHT_COLOR = "gold"
PRIME = "'"
_VIEW = {"elev": 28.0, "azim": 50.0}


# --------------------------------------------------------------------------- helpers


def _one_matrix(R: ArrayLike | None, name: str = "R") -> NDArray[np.float64]:
    """``R`` as a single 3×3 rotation matrix (the identity when ``R`` is None)."""
    if R is None:
        return np.eye(3)
    matrix = as_matrices(R, name)
    if matrix.shape != (3, 3):
        raise ValueError(f"{name} must be one 3×3 rotation matrix, got shape {matrix.shape}")
    return matrix


def _intrinsic_steps(
    angles: ArrayLike, seq: str, degrees: bool
) -> tuple[tuple[int, int, int], NDArray[np.float64]]:
    """Axes and angles (radians) of the intrinsic form of ``seq``, for one set of angles."""
    parsed = parse_sequence(seq)
    values = as_vectors(angles, "angles")
    if values.shape != (3,):
        raise ValueError(f"angles must be three numbers, got shape {values.shape}")
    if degrees:
        values = np.radians(values)
    if not parsed.intrinsic:
        values = values[::-1]
    return parsed.intrinsic_axes, values


def _partial_products(
    axes: tuple[int, int, int], values: NDArray[np.float64]
) -> NDArray[np.float64]:
    """Frames after one, two and three intrinsic steps, shape (3, 3, 3)."""
    steps = [elementary_rotation(axes[index], values[index]) for index in range(3)]
    frames = np.empty((3, 3, 3))
    frames[0] = steps[0]
    frames[1] = frames[0] @ steps[1]
    frames[2] = frames[1] @ steps[2]
    return frames


def _style_axes(ax: Axes3D, limit: float, title: str | None) -> None:
    ax.set_xlim(-limit, limit)
    ax.set_ylim(-limit, limit)
    ax.set_zlim(-limit, limit)
    ax.set_box_aspect((1, 1, 1))
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    ticks = [-1.0, 0.0, 1.0] if limit >= 1 else [-limit, 0.0, limit]
    ax.set_xticks(ticks)
    ax.set_yticks(ticks)
    ax.set_zticks(ticks)
    ax.tick_params(labelsize=7, pad=0)
    ax.view_init(**_VIEW)
    if title is not None:
        ax.set_title(title, fontsize=10)


def _degrees_text(values: NDArray[np.float64]) -> str:
    return ", ".join(f"{v:.4g}°" for v in np.degrees(values) + 0.0)


# --------------------------------------------------------------------------- frames


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
    matrices = as_matrices(rotations, "rotations")
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


# --------------------------------------------------------------------------- a body


def aircraft_segments(*, up: str = "z") -> NDArray[np.float64]:
    """A wireframe aircraft as line segments: nose along +x, vertical fin along +``up``.

    The body is symmetric about the plane spanned by x and ``up``; the nose is the point
    ``(1, 0, 0)``, the tail reaches back to x = -0.9, the wings span ±0.9 along the third axis,
    and the fin (and the cockpit bump) rise along ``up`` up to 0.4.

    Parameters
    ----------
    up : {"z", "y"}, optional
        The body's up axis: ``"z"`` as in Rose's yaw-pitch-roll (aerospace, z up), ``"y"`` as
        in Baker's heading-attitude-bank (y up; the wings then lie along z).

    Returns
    -------
    ndarray, shape (n, 2, 3)
        Segment ``k`` runs from ``segments[k, 0]`` to ``segments[k, 1]``.

    Examples
    --------
    >>> segments = aircraft_segments(up="z")
    >>> points = segments.reshape(-1, 3)
    >>> points[np.argmax(points[:, 0])]        # the nose
    array([1., 0., 0.])
    >>> float(points[:, 2].max()), float(points[:, 1].max())   # fin height, half span
    (0.4, 0.9)
    """
    if up not in ("z", "y"):
        raise ValueError(f"up must be 'z' (Rose, aerospace) or 'y' (Baker), got {up!r}")
    # Body coordinates: (forward, side, up).
    half = [
        ((0.3, 0.0, 0.0), (-0.1, 0.9, 0.0)),  # wing leading edge
        ((-0.1, 0.9, 0.0), (-0.3, 0.9, 0.0)),  # wing tip
        ((-0.3, 0.9, 0.0), (-0.2, 0.0, 0.0)),  # wing trailing edge
        ((-0.6, 0.0, 0.0), (-0.85, 0.35, 0.0)),  # tailplane leading edge
        ((-0.85, 0.35, 0.0), (-0.9, 0.0, 0.0)),  # tailplane trailing edge
    ]
    body = [
        ((-0.9, 0.0, 0.0), (1.0, 0.0, 0.0)),  # fuselage, tail to nose
        ((-0.55, 0.0, 0.0), (-0.8, 0.0, 0.4)),  # fin leading edge
        ((-0.8, 0.0, 0.4), (-0.9, 0.0, 0.4)),  # fin top
        ((-0.9, 0.0, 0.4), (-0.9, 0.0, 0.0)),  # fin trailing edge
        ((0.75, 0.0, 0.0), (0.55, 0.0, 0.12)),  # cockpit
        ((0.55, 0.0, 0.12), (0.3, 0.0, 0.12)),
        ((0.3, 0.0, 0.12), (0.2, 0.0, 0.0)),
    ]
    half_array = np.array(half)
    mirrored = half_array * np.array([1.0, -1.0, 1.0])
    segments = np.concatenate([np.array(body), half_array, mirrored])
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
        Line style of the wireframe.

    Returns
    -------
    list of Line3D
        One line per segment, in the order of :func:`aircraft_segments`.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> import eulerlib
    >>> ax = new_3d_axes()
    >>> lines = draw_aircraft(ax, eulerlib.rot_z(90, degrees=True))
    >>> x, y, z = lines[0].get_data_3d()          # the fuselage now points along y
    >>> np.round(y, 12) + 0.0
    array([-0.9,  1. ])
    >>> plt.close(ax.figure)
    """
    matrix = _one_matrix(R)
    segments = aircraft_segments(up=up) @ matrix.T
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
    R: ArrayLike, *, up: str = "z", figsize: tuple[float, float] = (12, 4)
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

    Returns
    -------
    matplotlib.figure.Figure
        Three 3D axes: "before" (identity), "after R" (the rotated body and frame, the original
        faint), and "back with Rᵀ" (the body turned by ``Rᵀ R``, which is the identity).

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
    import matplotlib.pyplot as plt

    matrix = _one_matrix(R)
    back = matrix.T @ matrix
    fig = plt.figure(figsize=figsize)
    ax = new_3d_axes(fig, (1, 3, 1), title="before")
    draw_frame(ax, None, alpha=0.6, linewidth=1.5)
    draw_aircraft(ax, None, up=up)
    ax = new_3d_axes(fig, (1, 3, 2), title="after R")
    draw_frame(ax, None, linestyle="--", alpha=0.35, linewidth=1.2)
    draw_aircraft(ax, None, up=up, alpha=0.25, linestyle="--")
    draw_frame(ax, matrix, alpha=0.8, linewidth=1.5, label_suffix="'")
    draw_aircraft(ax, matrix, up=up)
    ax = new_3d_axes(fig, (1, 3, 3), title="back with Rᵀ")
    draw_frame(ax, back, alpha=0.6, linewidth=1.5)
    draw_aircraft(ax, back, up=up)
    return fig


# --------------------------------------------------------------------------- gimbal


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
    from eulerlib.euler import gimbal_lock_status

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


# --------------------------------------------------------------------------- explorer


def explorer_state(angles: ArrayLike, seq: str = "ZYX") -> dict[str, Any]:
    """What the explorer shows for angles (in degrees) in convention ``seq``.

    Parameters
    ----------
    angles : array_like, shape (3,)
        The three slider values, in degrees.
    seq : str, optional
        Any of the 24 sequences.

    Returns
    -------
    dict
        ``"matrix"`` (3×3), ``"recovered"`` (the angles :func:`eulerlib.matrix_to_euler` gives
        back, degrees), ``"locked"`` (bool), ``"distance"`` (degrees from gimbal lock, from
        :func:`eulerlib.gimbal_lock_status`) and ``"text"``: all of it as the explorer prints
        it.

    Examples
    --------
    >>> print(explorer_state([30, 90, 10], "ZYX")["text"])
    ZYX, angles (30°, 90°, 10°)
    R =
    [[ 0.0000 -0.3420  0.9397]
     [ 0.0000  0.9397  0.3420]
     [-1.0000  0.0000  0.0000]]
    recovered angles: (0°, 90°, -20°)
    distance to gimbal lock: 0° (LOCKED: angle 1 set to 0, angle 3 carries the turn)
    """
    from eulerlib.euler import euler_to_matrix, gimbal_lock_status, matrix_to_euler

    parsed = parse_sequence(seq)
    values = as_vectors(angles, "angles")
    if values.shape != (3,):
        raise ValueError(f"angles must be three numbers, got shape {values.shape}")
    matrix = np.round(euler_to_matrix(values, seq, degrees=True), 12) + 0.0
    recovered = np.round(matrix_to_euler(matrix, seq, degrees=True, warn=False), 9) + 0.0
    status = gimbal_lock_status(matrix, seq, degrees=True)
    locked = bool(status.locked)
    distance = float(status.distance)
    matrix_text = np.array2string(
        matrix, separator=" ", formatter={"float_kind": lambda v: f"{v: .4f}"}
    )
    zeroed, carrier = (1, 3) if parsed.intrinsic else (3, 1)
    lock_text = (
        f" (LOCKED: angle {zeroed} set to 0, angle {carrier} carries the turn)" if locked else ""
    )
    text = (
        f"{seq}, angles ({', '.join(f'{v:.4g}°' for v in values + 0.0)})\n"
        f"R =\n{matrix_text}\n"
        f"recovered angles: ({', '.join(f'{v:.4g}°' for v in recovered)})\n"
        f"distance to gimbal lock: {distance:.4g}°{lock_text}"
    )
    return {
        "seq": seq,
        "angles": values,
        "matrix": matrix,
        "recovered": recovered,
        "locked": locked,
        "distance": distance,
        "text": text,
    }


def _render_png(fig: Figure) -> bytes:
    import io

    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=72, metadata={"Software": None})
    return buffer.getvalue()


def explorer(seq: str = "ZYX") -> Any:
    """An interactive explorer for JupyterLab: three angle sliders and a convention selector.

    Moving a slider or choosing another of the 24 sequences redraws the frame (with the
    reference frame dashed) and updates the text of :func:`explorer_state`: the matrix, the
    angles recovered from it, and the distance to gimbal lock.

    Parameters
    ----------
    seq : str, optional
        Convention selected at the start.

    Returns
    -------
    ipywidgets.VBox
        ``children[0]`` holds the three sliders (degrees) and the dropdown, ``children[1]`` the
        picture (an ``Image`` widget, PNG) and the text (an ``HTML`` widget). Display it as the
        last expression of a cell.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> box = explorer("ZYX")
    >>> sliders = box.children[0].children[:3]
    >>> sliders[1].value = 90.0
    >>> "LOCKED" in box.children[1].children[1].value
    True
    """
    import html

    import ipywidgets as widgets
    from matplotlib.figure import Figure

    parse_sequence(seq)
    initial = (30.0, 20.0, 10.0)
    sliders = [
        widgets.FloatSlider(
            value=initial[i],
            min=-180.0,
            max=180.0,
            step=1.0,
            description=f"angle {i + 1}",
            continuous_update=True,
            readout_format=".0f",
        )
        for i in range(3)
    ]
    dropdown = widgets.Dropdown(options=list(ALL_SEQUENCES), value=seq, description="seq")
    image = widgets.Image(format="png")
    text = widgets.HTML()
    fig = Figure(figsize=(4, 4))
    ax = new_3d_axes(fig)

    def update(*_: Any) -> None:
        current = dropdown.value
        angles = [slider.value for slider in sliders]
        for i, slider in enumerate(sliders):
            slider.description = f"angle {i + 1} ({current[i]})"
        state = explorer_state(angles, current)
        ax.cla()
        _style_axes(ax, 1.2, f"{current} ({_degrees_text(np.radians(angles))})")
        draw_frame(ax, None, linestyle="--", alpha=0.45, linewidth=1.5)
        draw_frame(ax, state["matrix"], label_suffix="'")
        image.value = _render_png(fig)
        text.value = f"<pre>{html.escape(state['text'])}</pre>"

    for slider in sliders:
        slider.observe(update, names="value")
    dropdown.observe(update, names="value")
    update()
    return widgets.VBox([widgets.HBox([*sliders, dropdown]), widgets.HBox([image, text])])
