"""Shared colours, view and small helpers of the plotting modules.

The helpers here take arguments that the public functions have already checked
(:mod:`eulerlib.plotting._checks`); they never check again.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from eulerlib.conventions import Convention
from eulerlib.elementary import elementary_rotation

if TYPE_CHECKING:
    from matplotlib.figure import Figure, FigureBase
    from mpl_toolkits.mplot3d.axes3d import Axes3D

# The colours are Okabe and Ito's set for readers with any kind of colour vision deficiency
# (Okabe & Ito, "Color Universal Design", 2008): no two of them are told apart by red versus
# green alone, and the axes carry their letters as well, so that no colour has to be told at all.
#: Colours of the x, y and z axes: vermillion, bluish green, blue.
AXIS_COLORS = ("#D55E00", "#009E73", "#0072B2")
AXIS_LETTERS = ("x", "y", "z")
#: Colours of the outer, middle and inner gimbal ring: reddish purple, orange, sky blue.
RING_COLORS = ("#CC79A7", "#E69F00", "#56B4E9")
#: Radii of the outer, middle and inner gimbal ring.
RING_RADII = (1.0, 0.8, 0.6)
#: Colour of the axis a step of a sequence turns about: yellow, unlike every colour above.
HIGHLIGHT_COLOR = "#F0E442"
PRIME = "'"
_VIEW = {"elev": 28.0, "azim": 50.0}


@contextmanager
def pyplot_figure(figsize: tuple[float, float]) -> Iterator[Figure]:
    """A new pyplot figure that is closed again if drawing into it raises."""
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=figsize)
    try:
        yield fig
    except BaseException:
        plt.close(fig)
        raise


def intrinsic_steps(
    values: NDArray[np.float64], convention: Convention
) -> tuple[tuple[int, int, int], NDArray[np.float64]]:
    """Axes and angles (radians) of the intrinsic form of a convention, for one set of angles."""
    return convention.parsed.intrinsic_axes, convention.to_intrinsic(values)


def partial_products(
    axes: tuple[int, int, int], values: NDArray[np.float64]
) -> NDArray[np.float64]:
    """Frames after one, two and three intrinsic steps, shape (3, 3, 3)."""
    steps = [elementary_rotation(axes[index], values[index]) for index in range(3)]
    frames = np.empty((3, 3, 3))
    frames[0] = steps[0]
    frames[1] = frames[0] @ steps[1]
    frames[2] = frames[1] @ steps[2]
    return frames


def style_axes(ax: Axes3D, limit: float, title: str | None) -> None:
    """Equal cube ``[-limit, limit]³``, labelled x/y/z axes, few ticks, the course's view."""
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


def add_3d_axes(
    fig: FigureBase, position: tuple[int, int, int], limit: float, title: str | None
) -> Axes3D:
    """A styled 3D axes (see :func:`style_axes`) at a checked subplot position of ``fig``."""
    ax: Axes3D = fig.add_subplot(*position, projection="3d")
    style_axes(ax, limit, title)
    return ax


def degrees_text(values: NDArray[np.float64]) -> str:
    """Angles given in radians, written in degrees: ``"30°, 20°, 10°"``."""
    return ", ".join(f"{v:.4g}°" for v in np.degrees(values) + 0.0)


def arrow_head(
    ax: Axes3D, tip: NDArray[np.float64], direction: NDArray[np.float64], size: float, **style: Any
) -> Any:
    """A small filled cone with its point at ``tip``, pointing along ``direction``.

    A zero ``direction`` (a column of a matrix drawn with ``validate=False``) gets an empty cone.
    """
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    length = float(np.linalg.norm(direction))
    faces = []
    if length > 0.0:
        unit = direction / length
        helper = np.eye(3)[int(np.argmin(np.abs(unit)))]
        u = np.cross(unit, helper)
        u /= np.linalg.norm(u)
        v = np.cross(unit, u)
        t = np.linspace(0.0, 2.0 * np.pi, 9)
        base = tip - 2.5 * size * unit
        rim = base + size * (np.cos(t)[:, None] * u + np.sin(t)[:, None] * v)
        faces = [[tip, rim[n], rim[n + 1]] for n in range(len(t) - 1)]
    cone = Poly3DCollection(faces, linewidths=0.0, **style)
    ax.add_collection3d(cone)
    return cone
