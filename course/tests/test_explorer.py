"""Tests of the course's interactive explorer (:mod:`eulerlib_course.explorer`).

Its logic, :func:`explorer_state`, is compared with SciPy's ``Rotation`` and with the library's
own gimbal-lock report; the widgets are driven as a user would drive them, without a browser.
"""

from __future__ import annotations

import base64
import hashlib
import inspect
import io
import re
import subprocess
import sys
import warnings
from collections.abc import Iterator
from typing import Any

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import eulerlib
from eulerlib_course import explorer as explorer_module
from eulerlib_course.explorer import Explorer, ExplorerState, explorer, explorer_state

NAN, INF = float("nan"), float("inf")


@pytest.fixture(autouse=True)
def _close_figures() -> Iterator[None]:
    yield
    plt.close("all")


def scipy_matrix(seq: str, angles: Any) -> np.ndarray:
    """SciPy's matrix of three angles in degrees."""
    return np.asarray(Rotation.from_euler(seq, angles, degrees=True).as_matrix())


# --------------------------------------------------------------------------- bad arguments

#: Bad values of each parameter, with the error each must raise.
SEQ = [("ABC", ValueError), ("ZZX", ValueError), ("rosé", ValueError), (3, TypeError),
       (None, TypeError)]  # fmt: skip
ANGLES = [([1, 2], ValueError), ([[1, 2, 3]], ValueError), ("abc", TypeError),
          ([1, NAN, 3], ValueError), ([1, INF, 3], ValueError), (None, TypeError),
          ([1, 2, None], TypeError), (np.ma.masked_array([1.0, 2, 3]), TypeError)]  # fmt: skip
BAD: dict[str, dict[str, list[tuple[Any, type[Exception]]]]] = {
    "explorer_state": {"angles": ANGLES, "seq": SEQ},
    "explorer": {"seq": SEQ},
    "Explorer": {"seq": SEQ},
}
CALLABLES = {
    name: getattr(explorer_module, name)
    for name in explorer_module.__all__
    if name != "ExplorerState"
}
VALID: dict[str, dict[str, Any]] = {
    "explorer_state": {"angles": [30.0, 20.0, 10.0]},
    "explorer": {},
    "Explorer": {},
}


def test_every_parameter_has_bad_values_here() -> None:
    assert set(BAD) == set(CALLABLES)
    for name, function in CALLABLES.items():
        assert set(BAD[name]) == set(inspect.signature(function).parameters), name
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            function(**VALID[name])


@pytest.mark.parametrize(
    ("name", "parameter", "bad", "error"),
    [
        pytest.param(name, parameter, value, error, id=f"{name}-{parameter}-{index}")
        for name, parameters in BAD.items()
        for parameter, values in parameters.items()
        for index, (value, error) in enumerate(values)
    ],
)
def test_a_bad_argument_is_named_and_leaves_no_figure_behind(
    name: str, parameter: str, bad: Any, error: type[Exception], capsys: pytest.CaptureFixture[str]
) -> None:
    arguments = {**VALID[name], parameter: bad}
    figures_before = plt.get_fignums()
    with pytest.raises(error) as caught:
        CALLABLES[name](**arguments)
    assert re.match(rf"{re.escape(parameter)}\b", str(caught.value)), str(caught.value)
    assert plt.get_fignums() == figures_before
    assert capsys.readouterr() == ("", "")


def test_nothing_is_printed(capsys: pytest.CaptureFixture[str]) -> None:
    panel = explorer()
    panel.sliders[1].value = 90.0  # a lock, too
    panel._repr_mimebundle_()
    explorer_state([30, 90, 10], "baker")
    assert capsys.readouterr() == ("", "")


def test_everything_public_is_documented_with_an_example() -> None:
    for name in explorer_module.__all__:
        value = getattr(explorer_module, name)
        doc = inspect.getdoc(value) or ""
        for section in ("Examples", ">>> "):
            assert section in doc, f"{name} has no {section.strip()}"
        if inspect.isfunction(value):
            assert "Parameters" in doc and "Returns" in doc, name


# --------------------------------------------------------------------------- what it shows


def test_explorer_state_is_a_typed_record() -> None:
    state = explorer_state([30, 20, 10], "ZYX")
    assert isinstance(state, ExplorerState)
    assert state._fields == (
        "convention", "angles", "matrix", "recovered", "locked", "distance", "lock", "text"
    )  # fmt: skip
    assert state.convention == eulerlib.get_convention("ZYX")
    assert isinstance(state.locked, bool) and isinstance(state.distance, float)
    assert state.lock is None
    np.testing.assert_array_equal(state.angles, [30.0, 20.0, 10.0])
    given = np.array([30.0, 20.0, 10.0])
    kept = explorer_state(given)
    given[0] = 99.0  # the state does not change with the caller's array
    np.testing.assert_array_equal(kept.angles, [30.0, 20.0, 10.0])


def test_explorer_state_away_from_lock() -> None:
    state = explorer_state([30, 20, 10], "rose")
    np.testing.assert_allclose(state.matrix, scipy_matrix("ZYX", [30, 20, 10]), atol=1e-15)
    np.testing.assert_allclose(state.recovered, [30, 20, 10], atol=1e-12)
    assert not state.locked
    assert state.distance == pytest.approx(70.0, abs=1e-12)
    lines = state.text.splitlines()
    assert lines[0] == "rose (ZYX): yaw 30°, pitch 20°, roll 10°"
    assert lines[5] == "recovered: yaw 30°, pitch 20°, roll 10°"
    assert lines[6] == "distance to gimbal lock: 70°"
    assert "LOCKED" not in state.text
    assert f"{scipy_matrix('ZYX', [30, 20, 10])[2, 0]: .4f}" in lines[4]  # -sin(pitch)
    bare = explorer_state([30, 20, 10], "ZYX").text.splitlines()[0]
    assert bare == "ZYX: z 30°, y' 20°, x'' 10°"


@pytest.mark.parametrize(
    ("seq", "angles", "expected", "zeroed", "carrier", "defined"),
    [
        # Rose's preset and eulerlib's rule for a bare intrinsic sequence: the first angle is 0,
        # the third carries third − first (pitch +90°: only roll − yaw is defined, Rose eq 4).
        ("rose", [30, 90, 10], [0, 90, -20], "yaw", "roll", "roll - yaw"),
        ("ZYX", [30, 90, 10], [0, 90, -20], "z", "x''", "x'' - z"),
        # the extrinsic twin: the last written angle is the first of the intrinsic form
        ("xyz", [10, 90, 30], [-20, 90, 0], "z", "x", "x - z"),
        # Baker's preset keeps Baker's choice: bank = 0, heading carries heading + bank
        ("baker", [40, 90, 10], [50, 90, 0], "bank", "heading", "heading + bank"),
        ("YZX", [40, 90, 10], [0, 90, 50], "y", "x''", "y + x''"),
        ("ZXZ", [30, 0, 10], [0, 0, 40], "z", "z''", "z + z''"),
    ],
)
def test_explorer_state_at_lock_follows_the_conventions_policy(
    seq: str,
    angles: list[float],
    expected: list[float],
    zeroed: str,
    carrier: str,
    defined: str,
) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the explorer catches its warning; none reaches here
        state = explorer_state(angles, seq)
    assert state.locked and state.distance == 0.0
    np.testing.assert_allclose(state.recovered, expected, atol=1e-12)
    convention = eulerlib.get_convention(seq)
    np.testing.assert_allclose(
        scipy_matrix(convention.seq, state.recovered),
        scipy_matrix(convention.seq, angles),
        atol=1e-12,
    )
    lock = state.lock
    assert isinstance(lock, eulerlib.GimbalLockWarning)
    assert (lock.zeroed, lock.carrier) == (zeroed, carrier)
    assert list(lock.combinations.values()) == [defined]
    assert "distance to gimbal lock: 0° (LOCKED)" in state.text
    assert f"only {defined} is defined at {convention.angle_names[1]} " in state.text
    assert f"{zeroed} set to 0, {carrier} carries the whole turn" in state.text
    assert "angle 1" not in state.text and "angle 3" not in state.text


def test_explorer_state_locks_exactly_when_the_library_does() -> None:
    for offset in (0.0, 1e-14, 1e-13, 1e-12, 1e-10, 1e-6):
        for pitch in (90.0 - offset, -90.0 + offset):
            state = explorer_state([25.0, pitch, 70.0], "rose")
            status = eulerlib.gimbal_lock_status(state.matrix, "rose", degrees=True)
            assert state.locked == bool(status.locked), (offset, pitch)
            assert state.distance == float(status.distance)


def test_explorer_state_passes_other_warnings_on(monkeypatch: pytest.MonkeyPatch) -> None:
    import eulerlib.euler

    original = eulerlib.euler.matrix_to_euler

    def noisy(*args: Any, **kwargs: Any) -> Any:
        warnings.warn("something else", RuntimeWarning, stacklevel=2)
        return original(*args, **kwargs)

    monkeypatch.setattr(eulerlib.euler, "matrix_to_euler", noisy)
    with pytest.warns(RuntimeWarning, match="something else"):
        explorer_state([30, 20, 10])


def test_explorer_sliders_carry_the_conventions_angle_names() -> None:
    before = plt.get_fignums()
    panel = explorer("rose")
    assert isinstance(panel, Explorer)
    assert plt.get_fignums() == before  # its figures are not pyplot's
    assert [s.description for s in panel.sliders] == ["yaw", "pitch", "roll"]
    assert [s.value for s in panel.sliders] == [30.0, 20.0, 10.0]
    labels = [label for label, _ in panel.selector.options]
    assert labels[:3] == ["rose (ZYX)", "baker (YZX)", "ros (xyz)"]
    assert labels[3:] == list(eulerlib.ALL_SEQUENCES)
    panel.selector.value = eulerlib.get_convention("baker")
    assert [s.description for s in panel.sliders] == ["heading", "attitude", "bank"]
    assert panel.text.value.startswith("<pre>baker (YZX): heading 30°, attitude 20°, bank 10°")
    panel.selector.value = eulerlib.get_convention("XZX")
    assert [s.description for s in panel.sliders] == ["x", "z'", "x''"]


def test_explorer_updates_live_and_reads_the_lock_policy() -> None:
    panel = explorer("baker")
    assert panel.image.value[:8] == b"\x89PNG\r\n\x1a\n"
    first_image = panel.image.value
    assert "distance to gimbal lock: 70°" in panel.text.value
    panel.sliders[0].value = 40.0
    panel.sliders[1].value = 90.0
    assert panel.image.value != first_image
    assert panel.state.locked
    np.testing.assert_allclose(panel.state.recovered, [50, 90, 0], atol=1e-12)
    assert "bank set to 0, heading carries the whole turn" in panel.text.value
    np.testing.assert_array_equal(panel.angles, [40.0, 90.0, 10.0])
    assert panel.convention.name == "baker"


def test_a_convention_made_by_the_caller_is_offered_first() -> None:
    custom = eulerlib.Convention(
        "camera", "ZYX", ("pan", "tilt", "spin"), "z", "a camera head", "third"
    )
    panel = explorer(custom)
    assert panel.selector.options[0] == ("camera (ZYX)", custom)
    assert [s.description for s in panel.sliders] == ["pan", "tilt", "spin"]
    panel.sliders[1].value = 90.0
    assert panel.state.lock is not None and panel.state.lock.zeroed == "spin"


def decoded_png(bundle: dict[str, Any]) -> bytes:
    data = base64.b64decode(bundle["image/png"])
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    return data


def test_explorer_output_has_a_picture_and_a_sentence_for_pages_without_a_kernel() -> None:
    panel = explorer("rose")
    bundle = panel._repr_mimebundle_()
    assert set(bundle) == {"application/vnd.jupyter.widget-view+json", "image/png", "text/plain"}
    view = bundle["application/vnd.jupyter.widget-view+json"]
    assert view["model_id"] == panel.widget.model_id
    assert bundle["text/plain"].endswith("\nRun this cell in JupyterLab to move the sliders.")
    assert bundle["text/plain"].startswith("rose (ZYX): yaw 30°, pitch 20°, roll 10°\n")
    assert "VBox" not in bundle["text/plain"]
    from PIL import Image

    picture = Image.open(io.BytesIO(decoded_png(bundle)))
    assert picture.size == (612, 302)  # 8.5 × 4.2 inches at 72 dpi
    assert "Software" not in picture.info and "date" not in str(picture.info).lower()
    # IPython asks the object for its bundle: the explorer, not the VBox, is displayed
    from IPython.core.formatters import DisplayFormatter

    data, _ = DisplayFormatter().format(panel)
    assert set(data) == set(bundle)


def test_the_stored_picture_is_the_same_bytes_on_every_run() -> None:
    first = decoded_png(explorer("rose")._repr_mimebundle_())
    assert decoded_png(explorer("rose")._repr_mimebundle_()) == first
    code = (
        "import base64, hashlib, matplotlib; matplotlib.use('Agg');"
        "from eulerlib_course.explorer import explorer;"
        "b = explorer('rose')._repr_mimebundle_()['image/png'];"
        "print(hashlib.sha256(base64.b64decode(b)).hexdigest())"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout
    assert out.strip() == hashlib.sha256(first).hexdigest()
    moved = explorer("rose")
    moved.sliders[0].value = 31.0
    assert decoded_png(moved._repr_mimebundle_()) != first
