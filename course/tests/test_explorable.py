"""Tests of the explorables' Python side (:mod:`eulerlib_course.explorable`), without a browser.

What the kernel computes is compared with SciPy's ``Rotation`` and with the library's own
gimbal-lock report; the widget is driven as its view drives it, by setting its controls. The
browser tests are ``test_explorable_port.py`` (the JavaScript port against eulerlib) and
``test_explorable_jupyterlab.py`` (the widget in JupyterLab).
"""

from __future__ import annotations

import base64
import hashlib
import html
import inspect
import json
import re
import subprocess
import sys
import warnings
from typing import Any

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import eulerlib
from eulerlib_course import explorable as explorable_module
from eulerlib_course.explorable import (
    MODULE_FILES,
    MODULE_FOLDER,
    RUN_SENTENCE,
    Explorable,
    ExplorableState,
    explorable_state,
    track,
)

NAN, INF = float("nan"), float("inf")
ANGLES_BAD = [([1, 2], ValueError), ([[1, 2, 3]], ValueError), ("abc", TypeError),
              ([1, NAN, 3], ValueError), ([1, INF, 3], ValueError), (None, TypeError),
              ([1, 2, None], TypeError), (np.ma.masked_array([1.0, 2, 3]), TypeError),
              ([True, False, True], TypeError)]  # fmt: skip
SEQ_BAD = [("ABC", ValueError), ("ZZX", ValueError), ("rosé", ValueError), (3, TypeError),
           (None, TypeError)]  # fmt: skip


def scipy_matrix(seq: str, angles: Any) -> np.ndarray:
    return np.asarray(Rotation.from_euler(seq, angles, degrees=True).as_matrix())


@pytest.mark.parametrize(("bad", "error"), ANGLES_BAD)
def test_bad_angles_are_named(bad: Any, error: type[Exception]) -> None:
    for call in (lambda: explorable_state(bad, "rose"), lambda: Explorable("rose", bad)):
        with pytest.raises(error, match=r"^angles\b"):
            call()


@pytest.mark.parametrize(("bad", "error"), SEQ_BAD)
def test_bad_conventions_are_named(bad: Any, error: type[Exception]) -> None:
    with pytest.raises(error, match=r"^seq\b"):
        Explorable(bad)
    with pytest.raises(error, match=r"^seq\b"):
        explorable_state([1, 2, 3], bad)


@pytest.mark.parametrize(
    ("call", "name", "error"),
    [
        (lambda: Explorable(compare=["nope"]), "compare", ValueError),
        (lambda: Explorable(compare="rose"), "compare", TypeError),
        (lambda: Explorable(quaternion=1), "quaternion", TypeError),
        (lambda: Explorable.paths([0, 0, 0], [1, 2], "rose"), "end", ValueError),
        (lambda: Explorable.paths([0, 0, 0], [1, 2, 3], "rose", steps=1), "steps", ValueError),
        (lambda: Explorable.replay(np.eye(3), [0.0]), "matrices", ValueError),
        (lambda: Explorable.replay(np.eye(3)[None] * 2, [0.0]), "matrices", ValueError),
        (lambda: Explorable.replay(np.eye(3)[None], [0.0, 1.0]), "times", ValueError),
        (lambda: Explorable.replay(np.eye(3)[None], [0.0], label=3), "label", TypeError),
    ],
)
def test_other_bad_arguments_are_named(call: Any, name: str, error: type[Exception]) -> None:
    with pytest.raises(error, match=rf"^{name}\b"):
        call()


def test_a_control_set_to_a_bad_value_is_refused() -> None:
    panel = Explorable("rose")
    with pytest.raises(ValueError, match=r"^seq\b"):
        panel.seq = "ABC"
    with pytest.raises(ValueError, match=r"^angles\b"):
        panel.angles = [1.0, NAN, 2.0]
    assert panel.seq == "rose" and panel.angles == [30.0, 20.0, 10.0]


def test_explorable_state_is_a_typed_record() -> None:
    state = explorable_state([30, 20, 10], "ZYX")
    assert isinstance(state, ExplorableState)
    assert state.convention == eulerlib.get_convention("ZYX")
    assert isinstance(state.locked, bool) and isinstance(state.distance, float)
    given = np.array([30.0, 20.0, 10.0])
    kept = explorable_state(given)
    given[0] = 99.0  # the state keeps its own angles
    np.testing.assert_array_equal(kept.angles, [30.0, 20.0, 10.0])


def test_explorable_state_away_from_lock() -> None:
    state = explorable_state([30, 20, 10], "rose")
    np.testing.assert_allclose(state.matrix, scipy_matrix("ZYX", [30, 20, 10]), atol=1e-15)
    np.testing.assert_allclose(state.recovered, [30, 20, 10], atol=1e-12)
    assert not state.locked and state.lock is None
    assert state.distance == pytest.approx(70.0, abs=1e-12)
    lines = state.text.splitlines()
    assert lines[0] == "rose (ZYX): yaw 30°, pitch 20°, roll 10°"
    assert lines[5] == "recovered: yaw 30°, pitch 20°, roll 10°"
    assert lines[6] == "distance to gimbal lock: 70°"


@pytest.mark.parametrize(
    ("seq", "angles", "expected", "zeroed", "carrier", "defined"),
    [
        ("rose", [30, 90, 10], [0, 90, -20], "yaw", "roll", "roll - yaw"),
        ("ZYX", [30, 90, 10], [0, 90, -20], "z", "x''", "x'' - z"),
        ("xyz", [10, 90, 30], [-20, 90, 0], "z", "x", "x - z"),
        ("baker", [40, 90, 10], [50, 90, 0], "bank", "heading", "heading + bank"),
        ("YZX", [40, 90, 10], [0, 90, 50], "y", "x''", "y + x''"),
        ("ZXZ", [30, 0, 10], [0, 0, 40], "z", "z''", "z + z''"),
    ],
)
def test_at_lock_the_conventions_policy_is_followed(
    seq: str, angles: list[float], expected: list[float], zeroed: str, carrier: str, defined: str
) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no warning reaches the caller
        state = explorable_state(angles, seq)
        body = Explorable(seq, angles).state["tracks"][0]
    assert state.locked and state.distance == 0.0
    np.testing.assert_allclose(state.recovered, expected, atol=1e-12)
    seq_of = eulerlib.get_convention(seq).seq
    np.testing.assert_allclose(
        scipy_matrix(seq_of, state.recovered), scipy_matrix(seq_of, angles), atol=1e-12
    )
    assert state.lock is not None
    assert (state.lock.zeroed, state.lock.carrier) == (zeroed, carrier)
    assert list(state.lock.combinations.values()) == [defined]
    assert f"{zeroed} set to 0, {carrier} carries the whole turn" in state.text
    assert body["locked"] and body["lock"]["combination"] == defined
    assert (body["lock"]["zeroed"], body["lock"]["carrier"]) == (zeroed, carrier)
    np.testing.assert_allclose(body["angles"], expected, atol=1e-12)
    assert body["rings"] == [float(a) for a in angles]  # the rings stand as they were set


def test_the_state_locks_exactly_when_the_library_does() -> None:
    for offset in (0.0, 1e-14, 1e-13, 1e-12, 1e-10, 1e-6):
        for pitch in (90.0 - offset, -90.0 + offset):
            body = Explorable("rose", [25.0, pitch, 70.0]).state["tracks"][0]
            status = eulerlib.gimbal_lock_status(body["matrix"], "rose", degrees=True)
            assert body["locked"] == bool(status.locked), (offset, pitch)
            assert body["distance"] == float(status.distance)


def test_the_controls_recompute_the_state() -> None:
    panel = Explorable("rose", [30, 20, 10], compare=["baker", "ros"], quaternion=True)
    first = panel.state
    panel.angles = [30.0, 90.0, 10.0]
    assert panel.state["tracks"][0]["locked"]
    panel.seq = "baker"
    body = panel.state["tracks"][0]
    assert body["names"] == ["heading", "attitude", "bank"]
    np.testing.assert_allclose(body["matrix"], eulerlib.heading_attitude_bank_to_matrix(
        30, 90, 10, degrees=True), atol=1e-15)  # fmt: skip
    R = np.array(first["tracks"][0]["matrix"])
    for other, compared in zip(("baker", "ros"), first["compare"], strict=True):
        np.testing.assert_allclose(
            eulerlib.euler_to_matrix(compared["angles"], other, degrees=True), R, atol=1e-14
        )
    q = np.array(first["quaternion"]["q"])
    scipy_q = Rotation.from_matrix(R).as_quat(scalar_first=True, canonical=True)
    np.testing.assert_allclose(q, scipy_q, atol=1e-15)
    panel.seq, panel.angles = "rose", [30.0, 20.0, 10.0]
    panel.flip = True
    np.testing.assert_array_equal(panel.state["quaternion"]["q"], -q)
    np.testing.assert_allclose(panel.state["quaternion"]["matrix"], R, atol=1e-15)


def test_paths_and_replay_follow_the_frame() -> None:
    start, end = [-40.0, 10.0, -20.0], [60.0, 50.0, 70.0]
    panel = Explorable.paths(start, end, "rose", steps=5)
    assert panel.config["times"] == [0.0, 0.25, 0.5, 0.75, 1.0]
    panel.frame = 2
    by_angles, by_slerp = panel.state["tracks"]
    np.testing.assert_allclose(by_angles["rings"], [10.0, 30.0, 25.0])
    R0, R1 = scipy_matrix("ZYX", start), scipy_matrix("ZYX", end)
    halfway = Rotation.from_matrix(R0) * Rotation.from_matrix(R0.T @ R1) ** 0.5
    np.testing.assert_allclose(by_slerp["matrix"], halfway.as_matrix(), atol=1e-14)
    panel.frame = 99  # held to the last moment
    assert panel.frame == 4
    matrices = eulerlib.euler_to_matrix([[0, 0, 0], [10, 89.8, 20]], "rose", degrees=True)
    replay = Explorable.replay(matrices, [0.0, 1.0], "rose", label="device")
    replay.frame = 1
    assert replay.state["tracks"][0]["label"] == "device"
    assert replay.state["tracks"][0]["distance"] == pytest.approx(0.2, abs=1e-9)


def test_the_widget_module_is_the_two_modules_as_one() -> None:
    joined = Explorable()._esm
    for name in MODULE_FILES:
        assert (MODULE_FOLDER / name).is_file()
    assert "import " not in "".join(
        line for line in joined.splitlines() if line.startswith("import ")
    )
    assert "export function computeState" in joined and "export default { render }" in joined


def test_the_stored_output_is_the_words_a_picture_and_the_settings() -> None:
    panel = Explorable("rose", [30, 85, 10])
    data, _ = panel._repr_mimebundle_()
    assert set(data) == {"application/vnd.jupyter.widget-view+json", "text/html", "text/plain"}
    assert data["text/plain"] == explorable_state([30, 85, 10], "rose").text + "\n" + RUN_SENTENCE
    assert not re.search(r"[0-9a-f]{32}|model_id|0x[0-9a-f]{6,}", data["text/plain"])
    found = re.fullmatch(
        r'<div class="eulerlib-explorable" data-settings="([^"]*)">'
        r'<img src="data:image/png;base64,([^"]+)" alt="[^"]+"><p><em>[^<]+</em></p></div>',
        data["text/html"],
    )
    assert found is not None
    settings = json.loads(html.unescape(found[1]))
    assert settings == {"config": panel.config, "controls": {
        "seq": "rose", "angles": [30.0, 85.0, 10.0], "flip": False, "frame": 0}}  # fmt: skip
    picture = base64.b64decode(found[2])
    assert picture[:8] == b"\x89PNG\r\n\x1a\n"
    code = (
        "import base64, hashlib, re, matplotlib; matplotlib.use('Agg');"
        "from eulerlib_course.explorable import Explorable;"
        "page = Explorable('rose', [30, 85, 10])._repr_mimebundle_()[0]['text/html'];"
        "print(hashlib.sha256(base64.b64decode(re.search('base64,([^\"]+)', page)[1])).hexdigest())"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout
    assert out.strip() == hashlib.sha256(picture).hexdigest()
    assert plt.get_fignums() == []  # its figures are not pyplot's


def test_repr_names_the_setting_without_ids(capsys: pytest.CaptureFixture[str]) -> None:
    assert repr(Explorable("baker", [1, 2, 3])) == (
        "<Explorable baker (YZX): heading 1°, attitude 2°, bank 3°>"
    )
    panel = Explorable.paths([0, 0, 0], [1, 2, 3])
    panel._repr_mimebundle_()
    assert repr(panel) == "<Explorable paths: frame 0>"
    assert capsys.readouterr() == ("", "")  # nothing is printed


def test_track_reads_a_matrix_as_the_library_does() -> None:
    R = eulerlib.euler_to_matrix([10, -90, 20], "rose", degrees=True)
    body = track(R, "rose", "R")
    assert body["lock"] == {"pole": -90, "combination": "yaw + roll", "zeroed": "yaw",
                            "carrier": "roll"}  # fmt: skip
    np.testing.assert_allclose(body["angles"], [0, -90, 30], atol=1e-12)


def test_everything_public_is_documented_with_an_example() -> None:
    for name in explorable_module.__all__:
        value = getattr(explorable_module, name)
        doc = inspect.getdoc(value) or ""
        assert "Examples" in doc and ">>> " in doc, name
        if inspect.isfunction(value):
            assert "Parameters" in doc and "Returns" in doc, name


def test_the_explorable_uses_only_the_librarys_public_api() -> None:
    """No import of a private module or name of eulerlib (``eulerlib._x``, ``_name``)."""
    import ast

    source = (MODULE_FOLDER / "__init__.py").read_text(encoding="utf-8")
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("eulerlib"):
            assert not any(part.startswith("_") for part in (node.module or "").split("."))
            assert not any(alias.name.startswith("_") for alias in node.names)
        if isinstance(node, ast.Import):
            for alias in node.names:
                assert not any(part.startswith("_") for part in alias.name.split("."))
