"""Rotations you can turn with the mouse: one explorable for JupyterLab and the website.

An :class:`Explorable` is an `anywidget <https://anywidget.dev>`_ widget: one ES module
(``explorable.js``) draws, in an SVG of its own, an aircraft with its body frame, the fixed
frame (dashed) and the three gimbal rings, which a learner turns by dragging (mouse or touch)
or with the arrow keys; below it are the controls (a full-width slider with a number field for
each angle, the convention chooser with the presets and the 24 sequences) and what the angles
give: the matrix, the angles read back from it with the convention's choice at gimbal lock,
the distance to gimbal lock, and a sentence with all of it that a screen reader reads out.

Where the numbers come from depends on the host, never on the view:

* **in JupyterLab** the view only sends the control values; the kernel computes the state with
  eulerlib (:func:`explorable_state`, :func:`track`) and sends it back, so every number shown
  is eulerlib's;
* **on the website** no kernel runs; the same ES module is loaded by the page with a small
  stand-in model that computes the same state with ``rotations.js``, a port of the few
  conversions the explorables need. A browser test holds the port against eulerlib on the same
  inputs (random, at and near gimbal lock, all 24 sequences, both lock policies) to 1e-12.

Three kinds of explorable teach in the notebooks:

* :class:`Explorable` with angles and a convention (notebooks 07, 08, 11): the sliders, with the
  same rotation read in other conventions side by side (``compare``) or its quaternion and the
  other one of the pair q, −q (``quaternion``);
* :meth:`Explorable.paths` (notebook 12): two attitudes joined by interpolating the Euler
  angles and by slerp, played side by side with a time slider;
* :meth:`Explorable.replay` (notebook 14): a recording of attitude matrices replayed in 3D.

Its stored output is deterministic, so strict nbval can compare it: ``text/plain`` is the
state in words (no widget ids), ``text/html`` a picture of the first state drawn with
:mod:`eulerlib.plotting` with the sentence "Run this cell in JupyterLab to turn it", and a
marker that carries the explorable's settings, from which the website build
(:func:`eulerlib_course.site.live_explorables`) makes the live explorable.
"""

from __future__ import annotations

import base64
import html
import io
import json
import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any, NamedTuple

import anywidget
import numpy as np
import traitlets
from numpy.typing import ArrayLike, NDArray

import eulerlib
from eulerlib import (
    ALL_SEQUENCES,
    Convention,
    GimbalLockWarning,
    euler_to_matrix,
    get_convention,
    gimbal_lock_status,
    lock_combination,
    matrix_to_euler,
)

__all__ = [
    "Explorable",
    "ExplorableState",
    "explorable_state",
    "track",
]

#: The folder of the ES modules (copied into the website by the site build).
MODULE_FOLDER = Path(__file__).parent
#: The ES modules, in the order the widget joins them into one.
MODULE_FILES = ("rotations.js", "explorable.js")
#: What a page without a kernel shows under the explorable's picture.
RUN_SENTENCE = "Run this cell in JupyterLab to turn it."
#: Where the angles start, in degrees.
INITIAL_ANGLES = (30.0, 20.0, 10.0)
#: The presets the chooser offers before the 24 sequences.
PRESETS = ("rose", "baker", "ros", "aerospace")
#: Resolution of the stored picture; fixed so that the picture is reproducible.
PICTURE_DPI = 72
#: The comment that marks an explorable in a stored ``text/html`` output; the settings follow.
MARKER = "eulerlib-explorable"


def _widget_module() -> str:
    """The two ES modules as one (the widget's module is loaded from a string, without a
    folder from which ``explorable.js`` could import ``rotations.js``)."""
    rotations, view = ((MODULE_FOLDER / name).read_text(encoding="utf-8") for name in MODULE_FILES)
    lines = [line for line in view.splitlines() if not line.startswith("import ")]
    return rotations + "\n" + "\n".join(lines) + "\n"


class ExplorableState(NamedTuple):
    """What the explorable shows for three angles in a convention.

    Attributes
    ----------
    convention : Convention
        The convention the angles are read in.
    angles : ndarray, shape (3,)
        The angles set, degrees, in the convention's argument order.
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
        All of it in words.

    Examples
    --------
    >>> state = explorable_state([30, 20, 10], "rose")
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


def _angle_triple(angles: ArrayLike, name: str = "angles") -> NDArray[np.float64]:
    """Three finite numbers of degrees, as a new float array; a one-line error otherwise."""
    if isinstance(angles, np.ma.MaskedArray):
        raise TypeError(f"{name} must be three numbers, got a masked array")
    if isinstance(angles, (str, bytes)) or angles is None:
        raise TypeError(f"{name} must be three numbers, got {type(angles).__name__}")
    items = np.asarray(angles, dtype=object).ravel()
    if not all(
        isinstance(item, (int, float, np.integer, np.floating))
        and not isinstance(item, (bool, np.bool_))
        for item in items
    ):
        raise TypeError(f"{name} must be three numbers, got {angles!r}")
    values = np.array(angles, dtype=float)
    if values.shape != (3,):
        raise ValueError(f"{name} must be three numbers, got shape {values.shape}")
    if not np.all(np.isfinite(values)):
        raise ValueError(f"{name} must be finite, got {values.tolist()}")
    return values


def _degrees(value: float) -> str:
    return f"{np.round(value, 9) + 0.0:.4g}°"


def explorable_state(angles: ArrayLike, seq: str | Convention = "ZYX") -> ExplorableState:
    """What the explorable shows for angles (in degrees) in a convention.

    Parameters
    ----------
    angles : array_like, shape (3,)
        The three angles, in degrees, in the convention's argument order.
    seq : str or Convention, optional
        Any of the 24 sequences, or a preset such as ``"rose"`` or ``"baker"``, whose angle
        names and lock policy are used.

    Returns
    -------
    ExplorableState
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
    >>> state = explorable_state([30, 90, 10], "rose")
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
    >>> explorable_state([40, 90, 10], "baker").recovered    # Baker sets bank to 0
    array([50., 90.,  0.])
    """
    values = _angle_triple(angles)
    convention = get_convention(seq)
    matrix = euler_to_matrix(values, convention, degrees=True)
    # no warning is caught (that would swap process-wide state); the facts are read once
    recovered = matrix_to_euler(matrix, convention, degrees=True, warn=False)
    status = gimbal_lock_status(matrix, convention, degrees=True)
    lock = None
    if status.locked:
        pole = convention.pole(math.radians(float(recovered[1])))
        lock = GimbalLockWarning(convention, 1, 1, (pole,))
    distance = float(status.distance)
    names = convention.angle_names

    def listing(triple: NDArray[np.float64]) -> str:
        return ", ".join(f"{n} {_degrees(a)}" for n, a in zip(names, triple, strict=True))

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
        for pole, combination in lock.combinations.items():  # one matrix meets one pole
            lines.append(f"only {combination} is defined at {names[1]} {pole}°:")
        lines.append(f"{lock.zeroed} set to 0, {lock.carrier} carries the whole turn")
    text = "\n".join(lines)
    return ExplorableState(
        convention, values, matrix, recovered, lock is not None, distance, lock, text
    )


def track(
    matrix: ArrayLike, seq: str | Convention, label: str, rings: ArrayLike | None = None
) -> dict[str, Any]:
    """One body of an explorable's picture, as the view draws it and states it in words.

    Parameters
    ----------
    matrix : array_like, shape (3, 3)
        The body's attitude.
    seq : str or Convention
        The convention its angles are read in.
    label : str
        What the body is called on the page.
    rings : array_like, shape (3,), optional
        The angles (degrees, argument order) the gimbal rings are set to; the recovered angles
        by default. The rings of set angles show a lock the recovered ones have resolved.

    Returns
    -------
    dict
        ``label``, ``seq``, ``names``, ``matrix`` (three rows), ``angles`` (recovered, degrees),
        ``rings``, ``locked``, ``distance`` (degrees) and ``lock`` (None, or the pole, the
        combination still defined, the zeroed angle and the carrier), as plain JSON values.

    Examples
    --------
    >>> body = track(eulerlib.euler_to_matrix([30, 90, 10], "rose", degrees=True), "rose", "R")
    >>> body["locked"], body["lock"]["combination"], [round(a, 9) for a in body["angles"]]
    (True, 'roll - yaw', [0.0, 90.0, -20.0])
    """
    convention = get_convention(seq)
    R = np.array(matrix, dtype=float)
    recovered = matrix_to_euler(R, convention, degrees=True, warn=False)
    status = gimbal_lock_status(R, convention, degrees=True)
    lock = None
    if status.locked:
        pole = convention.pole(math.radians(float(recovered[1])))
        lock = {
            "pole": pole,
            "combination": lock_combination(convention, pole)[1],
            "zeroed": convention.zeroed_name,
            "carrier": convention.carrier_name,
        }
    return {
        "label": label,
        "seq": convention.name,
        "names": list(convention.angle_names),
        "matrix": (R + 0.0).tolist(),
        "angles": (recovered + 0.0).tolist(),
        "rings": (recovered if rings is None else np.asarray(rings, dtype=float)).tolist(),
        "locked": bool(status.locked),
        "distance": float(status.distance),
        "lock": lock,
    }


def _convention_name(seq: str | Convention, name: str = "seq") -> str:
    """A preset name or a sequence the chooser offers (a Convention of the caller is refused:
    the page has only the presets and the 24 sequences)."""
    if not isinstance(seq, str):
        raise TypeError(f"{name} must be a preset name or a sequence (a string), got {seq!r}")
    convention = get_convention(seq, name)
    return convention.name


def compute_state(config: dict[str, Any], controls: dict[str, Any]) -> dict[str, Any]:
    """The state of an explorable for its settings and the values of its controls, by eulerlib.

    ``rotations.js`` computes the same dict on the website (``computeState``); the browser test
    compares the two.
    """
    kind = config["kind"]
    if kind == "angles":
        seq = controls["seq"]
        angles = _angle_triple(controls["angles"])
        matrix = euler_to_matrix(angles, seq, degrees=True)
        state: dict[str, Any] = {
            "tracks": [track(matrix, seq, get_convention(seq).label, rings=angles)],
            "compare": [
                {
                    "label": get_convention(other).label,
                    "names": list(get_convention(other).angle_names),
                    "angles": (
                        matrix_to_euler(matrix, other, degrees=True, warn=False) + 0.0
                    ).tolist(),
                }
                for other in config.get("compare", [])
            ],
            "quaternion": None,
        }
        if config.get("quaternion"):
            q = eulerlib.matrix_to_quaternion(matrix, scalar_first=True)
            shown = -q if controls.get("flip") else q
            state["quaternion"] = {
                "q": (shown + 0.0).tolist(),
                "matrix": (eulerlib.quaternion_to_matrix(shown, scalar_first=True) + 0.0).tolist(),
            }
        return state
    frame = int(controls["frame"])
    if kind == "paths":
        count = len(config["times"])
        t = config["times"][frame]
        seq = config["seq"]
        start, end = np.array(config["start"]), np.array(config["end"])
        angles = (1.0 - t) * start + t * end
        R0 = euler_to_matrix(start, seq, degrees=True)
        R1 = euler_to_matrix(end, seq, degrees=True)
        by_angles = euler_to_matrix(angles, seq, degrees=True)
        by_slerp = eulerlib.slerp(R0, R1, t)
        return {
            "tracks": [
                track(by_angles, seq, "interpolated angles", rings=angles),
                track(by_slerp, seq, "slerp"),
            ],
            "compare": [],
            "quaternion": None,
            "time": t,
            "frames": count,
        }
    matrix = np.array(config["matrices"][frame])
    return {
        "tracks": [track(matrix, config["seq"], config.get("label", "recording"))],
        "compare": [],
        "quaternion": None,
        "time": config["times"][frame],
        "frames": len(config["times"]),
    }


class Explorable(anywidget.AnyWidget):
    """A 3D explorable of Euler angles: turn the view with the mouse, set the angles below.

    Display it as the last expression of a cell. In JupyterLab with a kernel every change of a
    control is computed by eulerlib and shown at once; on the course website the page computes
    with the JavaScript port; where JavaScript is off, a picture of the first state shows.

    Parameters
    ----------
    seq : str, optional
        The convention at the start: a preset (``"rose"``, ``"baker"``, ``"ros"``,
        ``"aerospace"``) or any of the 24 sequences. The chooser offers them all.
    angles : array_like, shape (3,), optional
        The angles at the start, degrees.
    compare : sequence of str, optional
        Other conventions in which the same rotation is read, shown side by side.
    quaternion : bool, optional
        Also show the rotation's quaternion (w, x, y, z) and a switch to its negative, with
        the matrix of the quaternion shown: R(q) = R(−q).

    Attributes
    ----------
    seq, angles, flip, frame : traitlets
        The controls (the view sets them; a notebook may too).
    state : dict
        What the view shows, computed by eulerlib (:func:`track`).

    Raises
    ------
    TypeError, ValueError
        For a bad argument; the message names it.

    Examples
    --------
    >>> panel = Explorable("rose", [30, 90, 10])
    >>> panel.state["tracks"][0]["locked"], panel.state["tracks"][0]["lock"]["zeroed"]
    (True, 'yaw')
    >>> panel.seq = "baker"
    >>> [round(a, 9) for a in panel.state["tracks"][0]["angles"]]
    [40.0, 90.0, 0.0]
    >>> print(repr(panel))
    <Explorable baker (YZX): heading 30°, attitude 90°, bank 10°>
    """

    _esm = traitlets.Unicode(_widget_module()).tag(sync=True)
    config = traitlets.Dict().tag(sync=True)
    seq = traitlets.Unicode("rose").tag(sync=True)
    angles = traitlets.List(traitlets.Float(), default_value=list(INITIAL_ANGLES)).tag(sync=True)
    flip = traitlets.Bool(False).tag(sync=True)
    frame = traitlets.Int(0).tag(sync=True)
    state = traitlets.Dict().tag(sync=True)

    def __init__(
        self,
        seq: str = "rose",
        angles: ArrayLike = INITIAL_ANGLES,
        *,
        compare: Sequence[str] = (),
        quaternion: bool = False,
        _config: dict[str, Any] | None = None,
    ) -> None:
        if _config is None:
            if not isinstance(quaternion, bool):
                raise TypeError(f"quaternion must be True or False, got {quaternion!r}")
            if isinstance(compare, str) or not isinstance(compare, (tuple, list)):
                raise TypeError(f"compare must be a list of conventions, got {compare!r}")
            _config = {
                "kind": "angles",
                "choices": [*PRESETS, *ALL_SEQUENCES],
                "compare": [_convention_name(other, "compare") for other in compare],
                "quaternion": quaternion,
            }
        name = _convention_name(seq)
        values = _angle_triple(angles).tolist()
        super().__init__(config=_config, seq=name, angles=values)
        self._update()

    @classmethod
    def paths(
        cls,
        start: ArrayLike,
        end: ArrayLike,
        seq: str = "rose",
        *,
        steps: int = 41,
    ) -> Explorable:
        """Two attitudes joined by interpolated Euler angles and by slerp, side by side.

        Parameters
        ----------
        start, end : array_like, shape (3,)
            The angles of the two attitudes, degrees.
        seq : str, optional
            Their convention (a preset or a sequence).
        steps : int, optional
            How many moments from start to end (at least 2) the time slider offers.

        Returns
        -------
        Explorable
            With a time slider and a play button; the nose of each body traces its path.

        Examples
        --------
        >>> panel = Explorable.paths([-40, 10, -20], [60, 50, 70], "rose", steps=5)
        >>> panel.frame = 4
        >>> [round(a, 9) for a in panel.state["tracks"][1]["angles"]]
        [60.0, 50.0, 70.0]
        """
        if isinstance(steps, bool) or not isinstance(steps, int) or steps < 2:
            raise ValueError(f"steps must be an integer of at least 2, got {steps!r}")
        first = _angle_triple(start, "start").tolist()
        last = _angle_triple(end, "end").tolist()
        name = _convention_name(seq)
        times = np.linspace(0.0, 1.0, steps).tolist()
        config = {"kind": "paths", "seq": name, "start": first, "end": last, "times": times}
        moments = np.array(times)
        by_angles = euler_to_matrix(
            np.outer(1 - moments, first) + np.outer(moments, last), name, degrees=True
        )
        by_slerp = eulerlib.slerp(
            euler_to_matrix(first, name, degrees=True),
            euler_to_matrix(last, name, degrees=True),
            moments,
        )
        # the noses' paths, for drawing only: rounded, so that the stored output is the same
        # wherever it is computed
        config["trails"] = [
            (np.round(path[:, :, 0], 6) + 0.0).tolist() for path in (by_angles, by_slerp)
        ]
        return cls(name, first, _config=config)

    @classmethod
    def replay(
        cls,
        matrices: ArrayLike,
        times: ArrayLike,
        seq: str = "rose",
        *,
        label: str = "recording",
    ) -> Explorable:
        """A recording of attitudes replayed in 3D, with a time slider and a play button.

        Parameters
        ----------
        matrices : array_like, shape (n, 3, 3)
            The attitudes, rotation matrices.
        times : array_like, shape (n,)
            Their times, seconds.
        seq : str, optional
            The convention whose angles are shown.
        label : str, optional
            What the body is called on the page.

        Returns
        -------
        Explorable

        Examples
        --------
        >>> turns = eulerlib.euler_to_matrix([[0, 0, 0], [0, 89, 0]], "rose", degrees=True)
        >>> panel = Explorable.replay(turns, [0.0, 0.5])
        >>> panel.frame = 1
        >>> round(panel.state["tracks"][0]["distance"], 9)
        1.0
        """
        stack = np.array(matrices, dtype=float)
        moments = np.array(times, dtype=float)
        if stack.ndim != 3 or stack.shape[1:] != (3, 3) or len(stack) < 1:
            raise ValueError(f"matrices must have shape (n, 3, 3), got {stack.shape}")
        if moments.shape != (len(stack),):
            raise ValueError(f"times must be one number per matrix, got shape {moments.shape}")
        if not (np.all(np.isfinite(stack)) and np.all(np.isfinite(moments))):
            raise ValueError("matrices and times must be finite")
        if not eulerlib.is_rotation_matrix(stack).all():
            raise ValueError("matrices must all be rotation matrices")
        if not isinstance(label, str):
            raise TypeError(f"label must be a string, got {label!r}")
        name = _convention_name(seq)
        config = {
            "kind": "replay",
            "seq": name,
            "label": label,
            "matrices": (stack + 0.0).tolist(),
            "times": moments.tolist(),
            "trails": [(np.round(stack[:, :, 0], 6) + 0.0).tolist()],
        }
        first = matrix_to_euler(stack[0], name, degrees=True, warn=False)
        return cls(name, first, _config=config)

    @traitlets.validate("seq")
    def _valid_seq(self, proposal: Any) -> str:
        return _convention_name(proposal["value"])

    @traitlets.validate("angles")
    def _valid_angles(self, proposal: Any) -> list[float]:
        return _angle_triple(proposal["value"]).tolist()  # type: ignore[no-any-return]

    @traitlets.validate("frame")
    def _valid_frame(self, proposal: Any) -> int:
        count = len(self.config.get("times", [0]))
        return min(max(int(proposal["value"]), 0), count - 1)

    @traitlets.observe("seq", "angles", "flip", "frame")
    def _update(self, *_: Any) -> None:
        if not self.config:
            return
        controls = {"seq": self.seq, "angles": self.angles, "flip": self.flip, "frame": self.frame}
        self.state = compute_state(self.config, controls)

    def _text(self) -> str:
        """The state in words, as ``text/plain`` (no widget ids, so nbval can compare it)."""
        kind = self.config["kind"]
        if kind == "angles":
            return explorable_state(self.angles, self.seq).text
        lines = []
        if "time" in self.state:
            lines.append(f"t = {self.state['time']:.4g} of {self.config['times'][-1]:.4g}")
        for body in self.state["tracks"]:
            listing = ", ".join(
                f"{n} {_degrees(a)}" for n, a in zip(body["names"], body["angles"], strict=True)
            )
            lines.append(
                f"{body['label']}: {listing}; distance to gimbal lock {_degrees(body['distance'])}"
            )
        return "\n".join(lines)

    def static_png(self) -> bytes:
        """A picture of the current state, as PNG bytes: the same state gives the same bytes."""
        from matplotlib.figure import Figure

        from eulerlib.plotting import draw_aircraft, draw_frame, new_3d_axes, plot_gimbal

        bodies = self.state["tracks"]
        text = self._text()
        lines = text.count("\n") + 1
        width, height = 4.0 * len(bodies) + 0.4, 3.9 + 0.17 * lines + 0.4
        fig = Figure(figsize=(width, height))
        for k, body in enumerate(bodies):
            ax = new_3d_axes(fig, (1, len(bodies), k + 1), title=body["label"])
            bottom = (0.17 * lines + 0.45) / height
            ax.set_position((k / len(bodies), bottom, 1 / len(bodies), 3.4 / height))
            R = np.array(body["matrix"])
            plot_gimbal(body["rings"], body["seq"], degrees=True, ax=ax)
            draw_frame(ax, None, linestyle="--", alpha=0.45, linewidth=1.2)
            draw_aircraft(ax, R, up="y" if get_convention(body["seq"]).up_axis == "y" else "z")
            legend = ax.get_legend()
            if legend is not None:
                legend.remove()
        fig.text(0.03, 0.4 / height, text, family="monospace", fontsize=8.5, va="bottom")
        fig.text(0.5, 0.1 / height, RUN_SENTENCE, ha="center", fontsize=10, style="italic")
        buffer = io.BytesIO()
        fig.savefig(buffer, format="png", dpi=PICTURE_DPI, metadata={"Software": None})
        return buffer.getvalue()

    def page_settings(self) -> dict[str, Any]:
        """What the website needs to rebuild this explorable: its settings and controls."""
        return {
            "config": self.config,
            "controls": {
                "seq": self.seq,
                "angles": self.angles,
                "flip": self.flip,
                "frame": self.frame,
            },
        }

    def _repr_mimebundle_(self, **kwargs: Any) -> tuple[dict[str, Any], dict[str, Any]] | None:
        """The widget view; for a page without a kernel, the picture, the words and a marker."""
        shown = super()._repr_mimebundle_(**kwargs)
        data: dict[str, Any] = dict(shown[0] if isinstance(shown, tuple) else shown or {})
        metadata: dict[str, Any] = dict(shown[1]) if isinstance(shown, tuple) else {}
        picture = base64.b64encode(self.static_png()).decode("ascii")
        settings = html.escape(json.dumps(self.page_settings(), separators=(",", ":")))
        summary = html.escape(self._text())
        data["text/html"] = (
            f'<div class="{MARKER}" data-settings="{settings}">'
            f'<img src="data:image/png;base64,{picture}" alt="{summary}">'
            f"<p><em>{html.escape(RUN_SENTENCE)}</em></p></div>"
        )
        data["text/plain"] = f"{self._text()}\n{RUN_SENTENCE}"
        return data, metadata

    def __repr__(self) -> str:
        if self.config.get("kind") == "angles":
            names = get_convention(self.seq).angle_names
            values = ", ".join(
                f"{n} {_degrees(a)}" for n, a in zip(names, self.angles, strict=True)
            )
            return f"<Explorable {get_convention(self.seq).label}: {values}>"
        return f"<Explorable {self.config.get('kind')}: frame {self.frame}>"
