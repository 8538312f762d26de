"""Shared colours, view and small helpers of the plotting modules."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._validation import ROTATION_ATOL, RotationCheck, as_rotations, as_vectors
from eulerlib.elementary import elementary_rotation
from eulerlib.sequences import parse_sequence

if TYPE_CHECKING:
    from mpl_toolkits.mplot3d.axes3d import Axes3D

_CHECKED = RotationCheck(validate=True, repair=False, atol=ROTATION_ATOL)

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


def _one_matrix(R: ArrayLike | None, name: str = "R") -> NDArray[np.float64]:
    """``R`` as a single 3×3 rotation matrix (the identity when ``R`` is None)."""
    if R is None:
        return np.eye(3)
    matrix = as_rotations(R, name, _CHECKED)
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
