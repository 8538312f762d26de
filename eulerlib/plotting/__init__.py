"""Seeing rotations: frames, step-by-step sequences, a rotating body, and a gimbal.

A rotation matrix ``R`` is easiest to understand as a picture of the frame it produces: its
columns are where the reference axes x, y and z end up (``R @ e_i`` is column ``i``). Every
function here draws that picture on a matplotlib 3D axes, in the same colours throughout the
course: **x red, y green, z blue**, the fixed reference frame **dashed**, a rotated frame
**solid**, and equal scales on the three axes so that right angles look like right angles.

What there is
-------------
* :mod:`~eulerlib.plotting.frames`: :func:`new_3d_axes`, :func:`draw_frame` and
  :func:`plot_frames` for one or several frames; :func:`plot_sequence_steps` for the three
  elementary rotations of a sequence, one panel each, read intrinsically (about the moving
  axes) on the top row and extrinsically (about the fixed axes, in reverse order) on the
  bottom row. Both rows end in the same frame.
* :mod:`~eulerlib.plotting.aircraft`: :func:`aircraft_segments`, :func:`draw_aircraft` and
  :func:`plot_body_rotation`: a wireframe aircraft, nose along x and up along z (Rose) or y
  (Baker), so that yaw, pitch and roll are obvious; drawn before a rotation, after it, and back
  again with the transpose.
* :mod:`~eulerlib.plotting.gimbal`: :func:`gimbal_ring_points`, :func:`gimbal_ring_normals`,
  :func:`plot_gimbal` and :func:`animate_gimbal_lock`: three nested rings driven by the three
  angles. At the singular middle angle (±90° for Tait–Bryan, 0° or 180° for proper Euler) two
  rings lie in one plane and the first and third rotation axes coincide: gimbal lock.
* :mod:`~eulerlib.plotting.paths`: :func:`draw_axis_path` and :func:`plot_axis_paths`: the path
  that one body axis (the nose, by default) traces on the unit sphere while the body turns
  through a stack of rotations, to compare interpolations or follow a motion.

Everything listed is available directly from ``eulerlib.plotting``. The course's interactive
explorables (rotations to turn with the mouse in JupyterLab and on the website, whose
stored pictures are drawn with these functions) are part of the course package,
:mod:`eulerlib_course.explorable`.

A sequence ``seq`` means what it means everywhere in eulerlib (and in SciPy): uppercase is
intrinsic, lowercase extrinsic, angle ``i`` goes with letter ``i``. An extrinsic sequence is
drawn as its intrinsic twin (letters and angles reversed), which is the same rotation. A preset
such as ``"rose"`` or ``"baker"`` is accepted wherever a ``seq`` is, and drawn with its
sequence.

Every function checks all of its arguments before it creates a figure or draws anything, by
the same rules as the rest of eulerlib (:mod:`eulerlib.plotting._checks`): a bad argument
raises a ``TypeError`` or ``ValueError`` that names it and leaves no figure open in pyplot.

matplotlib comes with the ``plot`` extra (``pip install "eulerlib[plot]"``): importing this
package without it fails with an ``ImportError`` that says so. pyplot is imported inside the
functions that draw, and this package is not imported by ``eulerlib/__init__.py``, so
``import eulerlib`` stays light.

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

from eulerlib._extras import MissingExtraError

try:
    import matplotlib  # noqa: F401  (the functions import pyplot when they draw)
except ImportError as error:
    raise MissingExtraError("eulerlib.plotting", "matplotlib", "plot") from error

from eulerlib.plotting._base import AXIS_COLORS, HIGHLIGHT_COLOR, RING_COLORS, RING_RADII
from eulerlib.plotting.aircraft import aircraft_segments, draw_aircraft, plot_body_rotation
from eulerlib.plotting.frames import draw_frame, new_3d_axes, plot_frames, plot_sequence_steps
from eulerlib.plotting.gimbal import (
    animate_gimbal_lock,
    gimbal_ring_normals,
    gimbal_ring_points,
    plot_gimbal,
)
from eulerlib.plotting.paths import draw_axis_path, plot_axis_paths

__all__ = [
    "AXIS_COLORS",
    "HIGHLIGHT_COLOR",
    "RING_COLORS",
    "RING_RADII",
    "aircraft_segments",
    "animate_gimbal_lock",
    "draw_aircraft",
    "draw_axis_path",
    "draw_frame",
    "gimbal_ring_normals",
    "gimbal_ring_points",
    "new_3d_axes",
    "plot_axis_paths",
    "plot_body_rotation",
    "plot_frames",
    "plot_gimbal",
    "plot_sequence_steps",
]
