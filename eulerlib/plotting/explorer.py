"""An interactive explorer for JupyterLab: three angle sliders and a convention selector.

:func:`explorer_state` holds the logic (matrix, recovered angles, distance to gimbal lock) as
a plain function, so it can be tested without a browser; :func:`explorer` wires it to
ipywidgets.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike

from eulerlib.conventions import Convention, get_convention
from eulerlib.plotting._base import degrees_text, style_axes
from eulerlib.plotting._checks import angle_triple
from eulerlib.plotting.frames import draw_frame, new_3d_axes
from eulerlib.sequences import ALL_SEQUENCES

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "explorer",
    "explorer_state",
]


def explorer_state(angles: ArrayLike, seq: str | Convention = "ZYX") -> dict[str, Any]:
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
    from eulerlib import euler_to_matrix, gimbal_lock_status, matrix_to_euler

    values = angle_triple(angles)
    seq = get_convention(seq).seq
    parsed = get_convention(seq).parsed
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


def explorer(seq: str | Convention = "ZYX") -> Any:
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

    seq = get_convention(seq).seq
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
        style_axes(ax, 1.2, f"{current} ({degrees_text(np.radians(angles))})")
        draw_frame(ax, None, linestyle="--", alpha=0.45, linewidth=1.5)
        draw_frame(ax, state["matrix"], label_suffix="'")
        image.value = _render_png(fig)
        text.value = f"<pre>{html.escape(state['text'])}</pre>"

    for slider in sliders:
        slider.observe(update, names="value")
    dropdown.observe(update, names="value")
    update()
    return widgets.VBox([widgets.HBox([*sliders, dropdown]), widgets.HBox([image, text])])
