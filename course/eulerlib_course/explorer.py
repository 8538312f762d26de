"""An interactive explorer for JupyterLab: three angle sliders and a convention selector.

:func:`explorer_state` is the explorer's logic as a plain function, testable without a browser:
the matrix of three angles in a convention, the angles :func:`eulerlib.matrix_to_euler` gives
back with that convention's own lock policy, and the distance to gimbal lock. At lock the
words come from a :class:`eulerlib.GimbalLockWarning` built from :func:`eulerlib.gimbal_lock_status`
and the :class:`eulerlib.Convention` (which angle was set to 0, which one carries the turn,
which combination is still defined), the facts the conversion's own warning carries, so the
explorer says exactly what the library did.

:func:`explorer` wires the logic to ipywidgets and returns an :class:`Explorer`. With a live
kernel, JupyterLab shows its widgets. A stored notebook opened without a kernel, or rendered as
a web page (nbconvert, Jupyter Book, GitHub), cannot show widgets; there the explorer's output
falls back to a picture of its frame and text with the sentence "Run this cell in JupyterLab to
move the sliders." The picture is rendered at a fixed resolution without any date or version
in the file, so the same settings give the same bytes on every run.
"""

from __future__ import annotations

import base64
import html
import io
from typing import TYPE_CHECKING, Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._validation import as_vectors
from eulerlib.conventions import CONVENTIONS, Convention, get_convention
from eulerlib.gimbal_lock import GimbalLockWarning
from eulerlib.plotting import draw_frame, new_3d_axes
from eulerlib.sequences import ALL_SEQUENCES

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "Explorer",
    "ExplorerState",
    "explorer",
    "explorer_state",
]

#: What a page without a kernel shows under the explorer's picture.
RUN_SENTENCE = "Run this cell in JupyterLab to move the sliders."
#: Where the sliders start, in degrees.
INITIAL_ANGLES = (30.0, 20.0, 10.0)
#: Resolution of the explorer's pictures; fixed so that the stored picture is reproducible.
PICTURE_DPI = 72


class ExplorerState(NamedTuple):
    """What the explorer shows for one setting of its sliders.

    Attributes
    ----------
    convention : Convention
        The convention the angles are read in.
    angles : ndarray, shape (3,)
        The slider values, degrees, in the convention's argument order.
    matrix : ndarray, shape (3, 3)
        Their rotation matrix.
    recovered : ndarray, shape (3,)
        The angles :func:`eulerlib.matrix_to_euler` gives back for the matrix, degrees, with
        the convention's lock policy.
    locked : bool
        Whether the matrix is in gimbal lock (the conversion set one angle to 0).
    distance : float
        Distance of the middle angle from gimbal lock, degrees
        (:func:`eulerlib.gimbal_lock_status`).
    lock : GimbalLockWarning or None
        At lock, the warning the conversion would emit, with its facts (``zeroed``,
        ``carrier``, ``combinations``); None otherwise.
    text : str
        All of it in words, as the explorer prints it.

    Examples
    --------
    >>> state = explorer_state([30, 20, 10], "rose")
    >>> state.convention.name, state.locked, round(state.distance, 9)
    ('rose', False, 70.0)
    >>> state.recovered.round(9)
    array([30., 20., 10.])
    """

    convention: Convention
    angles: NDArray[np.float64]
    matrix: NDArray[np.float64]
    recovered: NDArray[np.float64]
    locked: bool
    distance: float
    lock: GimbalLockWarning | None
    text: str


def explorer_state(angles: ArrayLike, seq: str | Convention = "ZYX") -> ExplorerState:
    """What the explorer shows for angles (in degrees) in a convention.

    Parameters
    ----------
    angles : array_like, shape (3,)
        The three slider values, in degrees, in the convention's argument order.
    seq : str or Convention, optional
        Any of the 24 sequences, or a preset such as ``"rose"`` or ``"baker"``, whose angle
        names and lock policy are used.

    Returns
    -------
    ExplorerState
        The matrix, the recovered angles, whether the matrix is locked and how far from lock
        it is, the :class:`eulerlib.GimbalLockWarning` at lock, and the text.

    Raises
    ------
    TypeError, ValueError
        For a bad argument; the message names the argument.

    Notes
    -----
    At gimbal lock (Rose 2015, Part 2, eq 4; Baker's poles) only one combination of the first
    and third angles is defined. The recovered angles follow the convention's policy: Rose's
    preset and a bare intrinsic sequence set the first angle to 0, Baker's preset sets bank to
    0. The text repeats what the warning of the conversion says.

    Examples
    --------
    >>> state = explorer_state([30, 90, 10], "rose")
    >>> state.locked, state.lock.zeroed, state.lock.carrier
    (True, 'yaw', 'roll')
    >>> print(state.text)
    rose (ZYX): yaw 30°, pitch 90°, roll 10°
    R =
    [[ 0.0000 -0.3420  0.9397]
     [ 0.0000  0.9397  0.3420]
     [-1.0000  0.0000  0.0000]]
    recovered: yaw 0°, pitch 90°, roll -20°
    distance to gimbal lock: 0° (LOCKED)
    only roll - yaw is defined at pitch 90°:
    yaw set to 0, roll carries the whole turn
    >>> explorer_state([40, 90, 10], "baker").recovered    # Baker sets bank to 0
    array([50., 90.,  0.])
    """
    values = as_vectors(angles, "angles").copy()  # the state keeps its own angles
    if values.shape != (3,):
        raise ValueError(f"angles must be three numbers, got shape {values.shape}")
    return _state(values, get_convention(seq))


def _state(values: NDArray[np.float64], convention: Convention) -> ExplorerState:
    """Body of :func:`explorer_state` for checked angles (degrees) and convention."""
    from eulerlib.euler import euler_to_matrix, matrix_to_euler
    from eulerlib.gimbal_lock import gimbal_lock_status

    matrix = euler_to_matrix(values, convention, degrees=True)
    # no warning is caught (that would swap process-wide state); the facts are read once
    recovered = matrix_to_euler(matrix, convention, degrees=True, warn=False)
    status = gimbal_lock_status(matrix, convention, degrees=True)
    lock = None
    if status.locked:
        pole = convention.pole(np.radians(recovered[1]))
        lock = GimbalLockWarning(convention, 1, 1, (pole,))
    distance = float(status.distance)
    text = _state_text(convention, values, matrix, recovered, distance, lock)
    return ExplorerState(
        convention, values, matrix, recovered, lock is not None, distance, lock, text
    )


def _degrees(value: float) -> str:
    return f"{np.round(value, 9) + 0.0:.4g}°"


def _state_text(
    convention: Convention,
    values: NDArray[np.float64],
    matrix: NDArray[np.float64],
    recovered: NDArray[np.float64],
    distance: float,
    lock: GimbalLockWarning | None,
) -> str:
    names = convention.angle_names

    def listing(angles: NDArray[np.float64]) -> str:
        return ", ".join(
            f"{name} {_degrees(angle)}" for name, angle in zip(names, angles, strict=True)
        )

    matrix_text = np.array2string(
        np.round(matrix, 4) + 0.0, separator=" ", formatter={"float_kind": lambda v: f"{v: .4f}"}
    )
    lines = [
        f"{convention.label}: {listing(values)}",
        f"R =\n{matrix_text}",
        f"recovered: {listing(recovered)}",
        f"distance to gimbal lock: {_degrees(distance)}" + (" (LOCKED)" if lock else ""),
    ]
    if lock is not None:
        # one matrix meets one pole; the words are the warning's
        for pole, combination in lock.combinations.items():
            lines.append(f"only {combination} is defined at {names[1]} {pole}°:")
        lines.append(f"{lock.zeroed} set to 0, {lock.carrier} carries the whole turn")
    return "\n".join(lines)


def _png(fig: Figure) -> bytes:
    """The figure as PNG bytes: fixed resolution, no software version or date in the file."""
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=PICTURE_DPI, metadata={"Software": None})
    return buffer.getvalue()


def _draw_state(fig: Any, position: tuple[int, int, int], state: ExplorerState) -> Any:
    """A new 3D axes of ``fig`` with the reference frame (dashed) and the frame of a state."""
    values = ", ".join(_degrees(angle) for angle in state.angles)
    ax = new_3d_axes(fig, position, limit=1.2, title=f"{state.convention.label} ({values})")
    draw_frame(ax, linestyle="--", alpha=0.45, linewidth=1.5)
    draw_frame(ax, state.matrix, label_suffix="'", validate=False)
    return ax


def _selector_options(convention: Convention) -> list[tuple[str, Convention]]:
    """The presets, then the 24 sequences; a convention made by the caller comes first."""
    presets = [CONVENTIONS[name] for name in ("rose", "baker", "ros")]
    sequences = [get_convention(seq) for seq in ALL_SEQUENCES]
    options = [(choice.label, choice) for choice in presets + sequences]
    if convention not in presets + sequences:
        options.insert(0, (convention.label, convention))
    return options


class Explorer:
    """Three angle sliders and a convention selector, with the frame and text they produce.

    Made by :func:`explorer`. Display it as the last expression of a cell: with a live kernel
    JupyterLab shows the widgets (:attr:`widget`); a page without a kernel shows a picture of
    the current setting with the sentence "Run this cell in JupyterLab to move the sliders."

    Attributes
    ----------
    sliders : tuple of 3 ipywidgets.FloatSlider
        The angles, degrees, each labelled with the convention's name for it.
    selector : ipywidgets.Dropdown
        The convention: the presets ``rose``, ``baker``, ``ros``, then the 24 sequences.
    image : ipywidgets.Image
        The frame (PNG), redrawn on every change.
    text : ipywidgets.HTML
        The text of :func:`explorer_state`.
    widget : ipywidgets.VBox
        All of the above: the controls on top, the picture and the text below.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> panel = explorer("rose")
    >>> [slider.description for slider in panel.sliders]
    ['yaw', 'pitch', 'roll']
    >>> panel.sliders[1].value = 90.0
    >>> panel.state.locked, panel.state.lock.zeroed
    (True, 'yaw')
    """

    _state: ExplorerState

    def __init__(self, seq: str | Convention = "ZYX") -> None:
        convention = get_convention(seq)
        try:
            import ipywidgets as widgets
        except ImportError:  # pragma: no cover - depends on the installation
            raise ImportError(
                "the explorer needs ipywidgets, a dependency of eulerlib-course: "
                "pip install -e ./course"
            ) from None
        from matplotlib.figure import Figure

        self.sliders = tuple(
            widgets.FloatSlider(
                value=INITIAL_ANGLES[i],
                min=-180.0,
                max=180.0,
                step=1.0,
                description=convention.angle_names[i],
                continuous_update=True,
                readout_format=".0f",
            )
            for i in range(3)
        )
        self.selector = widgets.Dropdown(
            options=_selector_options(convention), value=convention, description="convention"
        )
        self.image = widgets.Image(format="png")
        self.text = widgets.HTML()
        self.widget = widgets.VBox(
            [widgets.HBox([*self.sliders, self.selector]), widgets.HBox([self.image, self.text])]
        )
        self._figure = Figure(figsize=(4, 4))  # not managed by pyplot: nothing to close
        for slider in self.sliders:
            slider.observe(self._update, names="value")
        self.selector.observe(self._update, names="value")
        self._update()

    @property
    def convention(self) -> Convention:
        """The convention selected."""
        chosen: Convention = self.selector.value
        return chosen

    @property
    def angles(self) -> NDArray[np.float64]:
        """The slider values, degrees."""
        return np.array([float(slider.value) for slider in self.sliders])

    @property
    def state(self) -> ExplorerState:
        """What the explorer shows now (see :func:`explorer_state`)."""
        return self._state

    def _update(self, *_: Any) -> None:
        convention = self.convention
        for slider, name in zip(self.sliders, convention.angle_names, strict=True):
            slider.description = name
        self._state = _state(self.angles, convention)
        self._figure.clear()
        _draw_state(self._figure, (1, 1, 1), self._state)
        self.image.value = _png(self._figure)
        self.text.value = f"<pre>{html.escape(self._state.text)}</pre>"

    def static_png(self) -> bytes:
        """A picture of the current setting for a page without a kernel, as PNG bytes.

        The frame on the left, the text of :attr:`state` on the right, and below them the
        sentence "Run this cell in JupyterLab to move the sliders." The same setting gives
        the same bytes on every run.
        """
        from matplotlib.figure import Figure

        fig = Figure(figsize=(8.5, 4.2))
        ax = _draw_state(fig, (1, 2, 1), self._state)
        ax.set_position((0.04, 0.12, 0.42, 0.78))
        fig.text(0.5, 0.55, self._state.text, family="monospace", fontsize=10, va="center")
        fig.text(0.5, 0.04, RUN_SENTENCE, ha="center", fontsize=11, style="italic")
        return _png(fig)

    def _repr_mimebundle_(
        self, include: Any = None, exclude: Any = None, **kwargs: Any
    ) -> dict[str, Any]:
        """The widget view, with a picture and text for a page without a kernel."""
        bundle: dict[str, Any] = dict(self.widget._repr_mimebundle_(**kwargs) or {})
        bundle["image/png"] = base64.b64encode(self.static_png()).decode("ascii")
        bundle["text/plain"] = f"{self._state.text}\n{RUN_SENTENCE}"
        return bundle

    def __repr__(self) -> str:
        values = ", ".join(_degrees(angle) for angle in self.angles)
        return f"<Explorer {self.convention.label}: {values}>"


def explorer(seq: str | Convention = "ZYX") -> Explorer:
    """An interactive explorer for JupyterLab: three angle sliders and a convention selector.

    Moving a slider or choosing another convention redraws the frame (with the reference frame
    dashed) and updates the text of :func:`explorer_state`: the matrix, the angles recovered
    from it with the convention's lock policy, and the distance to gimbal lock. The sliders are
    labelled with the convention's angle names (yaw, pitch, roll for ``"rose"``).

    Parameters
    ----------
    seq : str or Convention, optional
        Convention selected at the start: any of the 24 sequences or a preset such as
        ``"rose"``.

    Returns
    -------
    Explorer
        Display it as the last expression of a cell. Where no kernel runs (a stored notebook,
        a web page), its output is a picture of the starting setting and the sentence "Run this
        cell in JupyterLab to move the sliders."

    Raises
    ------
    TypeError, ValueError
        For a bad ``seq``; the message names it.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> panel = explorer("ZYX")
    >>> panel.sliders[1].value = 90.0
    >>> "LOCKED" in panel.text.value
    True
    >>> sorted(panel._repr_mimebundle_())
    ['application/vnd.jupyter.widget-view+json', 'image/png', 'text/plain']
    """
    return Explorer(seq)
