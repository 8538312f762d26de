"""The explorables' JavaScript port (``rotations.js``) against eulerlib, in a real browser.

The website computes what its explorables show with ``rotations.js``; JupyterLab computes the
same with eulerlib. Here both get the same inputs: random angles and random matrices, angles at
gimbal lock and 1e-3° to 1e-12° from it, matrices with rounding noise, in all 24 sequences and
with both lock policies (the first or the third angle set to 0 at lock), and the states of the
three kinds of explorable. Chromium (the system's, driven by Playwright, as in
``test_site.py``) runs the module from a loopback server; every matrix entry, angle (degrees)
and distance to gimbal lock must agree to 1e-12, and every lock decision exactly.

Without Playwright or Chromium the test is skipped (the README's test command has neither);
``EULERLIB_SITE_TEST=required`` (``.ci/run``) turns the skip into a failure.
"""

from __future__ import annotations

import functools
import http.server
import importlib.util
import json
import os
import shutil
import threading
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import eulerlib
from eulerlib_course.explorable import MODULE_FILES, MODULE_FOLDER, Explorable, compute_state

LOOPBACK = "127.0.0.1"
TOLERANCE = 1e-12


def chromium() -> str | None:
    """The system's Chromium: ``EULERLIB_CHROMIUM``, else ``chromium`` on the PATH."""
    named = os.environ.get("EULERLIB_CHROMIUM")
    if named:
        return named if Path(named).is_file() else None
    return shutil.which("chromium") or shutil.which("chromium-browser")


def browser_or_skip() -> str:
    """The Chromium to drive, or a skip (a failure when the browser tests are required)."""
    reason = None
    if importlib.util.find_spec("playwright") is None:
        reason = (
            'no Playwright (the site extra of eulerlib-course): pip install -e "./course[site]"'
        )
    elif chromium() is None:
        reason = "no Chromium: install Debian's chromium package, or name one in EULERLIB_CHROMIUM"
    if reason is not None:
        if os.environ.get("EULERLIB_SITE_TEST") == "required":
            pytest.fail(reason)
        pytest.skip(reason)
    return str(chromium())


@pytest.fixture(scope="module")
def module_page(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Any]:
    """A Chromium page on a loopback server that serves the ES modules; other hosts refused."""
    executable = browser_or_skip()
    from playwright.sync_api import sync_playwright

    folder = tmp_path_factory.mktemp("modules")
    for name in MODULE_FILES:
        shutil.copyfile(MODULE_FOLDER / name, folder / name)
    (folder / "index.html").write_text("<!doctype html><title>port</title>\n", encoding="utf-8")

    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, format: str, *args: Any) -> None:
            pass

    server = http.server.ThreadingHTTPServer(
        (LOOPBACK, 0), functools.partial(Quiet, directory=str(folder))
    )
    threading.Thread(target=server.serve_forever, daemon=True).start()
    refused: list[str] = []
    arguments = ["--disable-background-networking", "--disable-component-update"]
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        arguments.append("--no-sandbox")
    try:
        with sync_playwright() as playwright:
            browser = playwright.chromium.launch(
                executable_path=executable, headless=True, args=arguments
            )
            page = browser.new_page()

            def route(request_route: Any) -> None:
                if request_route.request.url.startswith(f"http://{LOOPBACK}:"):
                    request_route.continue_()
                else:
                    refused.append(request_route.request.url)
                    request_route.abort()

            page.route("**/*", route)
            page.goto(f"http://{LOOPBACK}:{server.server_address[1]}/index.html")
            yield page
            browser.close()
    finally:
        server.shutdown()
        server.server_close()
    assert refused == []


def port(page: Any, function: str, cases: list[Any]) -> list[Any]:
    """``rotations.js``'s ``function`` applied to each case (a list of arguments)."""
    script = """async ([name, cases]) => {
      const port = await import("./rotations.js");
      return cases.map((args) => port[name](...args));
    }"""
    return list(page.evaluate(script, [function, cases]))


def conventions() -> list[tuple[Any, eulerlib.Convention]]:
    """Every sequence with both lock policies (as the port spells it, and as eulerlib does),
    and the presets."""
    found: list[tuple[Any, eulerlib.Convention]] = []
    for seq in eulerlib.ALL_SEQUENCES:
        names = eulerlib.get_convention(seq).angle_names
        for policy in ("first", "third"):
            ours = eulerlib.Convention(f"{seq}-{policy}", seq, names, None, "test", policy)
            spelled = {"name": ours.name, "seq": seq, "names": list(names), "lockZeroes": policy}
            found.append((spelled, ours))
    found += [
        (name, eulerlib.get_convention(name)) for name in ("rose", "aerospace", "baker", "ros")
    ]
    return found


def angle_sets(convention: eulerlib.Convention, rng: np.random.Generator) -> np.ndarray:
    """Random angles, then angles at each pole and 1e-3° to 1e-12° from it (degrees)."""
    random = rng.uniform(-180.0, 180.0, size=(6, 3))
    poles = (0.0, 180.0) if convention.parsed.proper else (90.0, -90.0)
    middles = []
    for pole in poles:
        inward = 1.0 if pole in (0.0, -90.0) else -1.0
        middles += [pole] + [pole + inward * 10.0**-k for k in (3, 6, 9, 12)]
    outer = rng.uniform(-180.0, 180.0, size=(len(middles), 2))
    near = np.column_stack([outer[:, 0], middles, outer[:, 1]])
    near = np.asarray(convention.from_intrinsic(near))
    return np.vstack([random, near, [[0.0, 0.0, 0.0], [180.0, 45.0, -180.0]]])


def wrapped(a: Any, b: Any) -> float:
    difference = (np.asarray(a) - np.asarray(b) + 180.0) % 360.0 - 180.0
    return float(np.abs(difference).max())


def test_the_port_agrees_with_eulerlib_on_all_24_sequences_and_both_policies(
    module_page: Any,
) -> None:
    rng = np.random.default_rng(19)
    noisy = Rotation.random(20, random_state=5).as_matrix()
    Q = Rotation.random(20, random_state=6).as_matrix()
    noisy = np.einsum("nij,nkj,nkl->nil", Q, Q, noisy)  # Q Qᵀ R: rounding noise
    worst = {"matrix": 0.0, "angles": 0.0, "distance": 0.0}
    count = 0
    for spelled, convention in conventions():
        angles = angle_sets(convention, rng)
        ours = eulerlib.euler_to_matrix(angles, convention, degrees=True)
        theirs = np.array(
            port(module_page, "eulerToMatrix", [[a, spelled] for a in angles.tolist()])
        )
        worst["matrix"] = max(worst["matrix"], float(np.abs(ours - theirs).max()))
        locked_stack = np.concatenate(
            [ours, Rotation.random(8, random_state=count).as_matrix(), noisy]
        )
        read = port(module_page, "matrixToEuler", [[R, spelled] for R in locked_stack.tolist()])
        expected = eulerlib.matrix_to_euler(locked_stack, convention, degrees=True, warn=False)
        status = eulerlib.gimbal_lock_status(locked_stack, convention, degrees=True, validate=False)
        for k, result in enumerate(read):
            assert result["locked"] == bool(status.locked[k]), (convention.name, k)
            worst["angles"] = max(worst["angles"], wrapped(result["angles"], expected[k]))
            worst["distance"] = max(
                worst["distance"], abs(result["distance"] - float(status.distance[k]))
            )
        assert any(result["locked"] for result in read)  # the poles are met
        count += len(locked_stack)
    assert count > 2000
    assert worst["matrix"] <= TOLERANCE, worst
    assert worst["angles"] <= TOLERANCE, worst
    assert worst["distance"] <= TOLERANCE, worst


def test_the_port_agrees_on_quaternions_and_slerp(module_page: Any) -> None:
    matrices = Rotation.random(200, random_state=7).as_matrix()
    halves = eulerlib.euler_to_matrix([[180, 0, 0], [0, 180, 0], [90, 0, 180], [0, 0, 0]], "ZYX",
                                      degrees=True)  # fmt: skip
    stack = np.concatenate([matrices, halves])
    theirs = np.array(port(module_page, "matrixToQuaternion", [[R] for R in stack.tolist()]))
    ours = eulerlib.matrix_to_quaternion(stack, scalar_first=True)
    assert np.abs(ours - theirs).max() <= TOLERANCE
    back = np.array(port(module_page, "quaternionToMatrix", [[q] for q in ours.tolist()]))
    assert np.abs(back - eulerlib.quaternion_to_matrix(ours, scalar_first=True)).max() <= TOLERANCE
    t = np.linspace(0.0, 1.0, 200)
    ours_slerp = eulerlib.slerp(matrices[:100], matrices[100:], t[:100])
    pairs = zip(matrices[:100].tolist(), matrices[100:].tolist(), t[:100].tolist(), strict=True)
    theirs_slerp = np.array(port(module_page, "slerp", [list(pair) for pair in pairs]))
    assert np.abs(ours_slerp - theirs_slerp).max() <= TOLERANCE


def numbers(state: Any) -> list[float]:
    """Every number in a state, in order, and the lock decisions as 0 or 1."""
    if isinstance(state, bool):
        return [float(state)]
    if isinstance(state, (int, float)):
        return [float(state)]
    if isinstance(state, dict):
        return [x for key in sorted(state) for x in numbers(state[key])]
    if isinstance(state, list):
        return [x for item in state for x in numbers(item)]
    return []


def texts(state: Any) -> list[str]:
    if isinstance(state, str):
        return [state]
    if isinstance(state, dict):
        return [x for key in sorted(state) for x in texts(state[key])]
    if isinstance(state, list):
        return [x for item in state for x in texts(item)]
    return []


def test_the_explorables_states_agree(module_page: Any) -> None:
    near = eulerlib.euler_to_matrix(
        [[10, 89.99, 5], [10, 90, 5], [10, 90 - 1e-9, 5], [-30, -90, 60]], "rose", degrees=True
    )
    panels = [
        Explorable("rose", [30, 20, 10], compare=["baker", "ros", "ZXZ"], quaternion=True),
        Explorable.paths([-40, 10, -20], [60, 50, 70], "rose", steps=9),
        Explorable.paths([30, 85, 10], [30, 95, 10], "rose", steps=9),
        Explorable.replay(near, [0.0, 0.1, 0.2, 0.3], "rose"),
    ]
    cases = []
    for panel in panels:
        config = panel.config
        if config["kind"] == "angles":
            for seq in config["choices"]:
                for angles in ([30.0, 20.0, 10.0], [40.0, 90.0, 10.0], [10.0, 0.0, 20.0],
                               [25.0, 180.0, -70.0], [5.0, 89.999999, 7.0]):  # fmt: skip
                    for flip in (False, True):
                        cases.append(
                            (config, {"seq": seq, "angles": angles, "flip": flip, "frame": 0})
                        )
        else:
            for frame in range(len(config["times"])):
                cases.append((config, {"seq": panel.seq, "angles": panel.angles, "flip": False,
                                       "frame": frame}))  # fmt: skip
    theirs = port(module_page, "computeState", [list(case) for case in cases])
    assert len(theirs) == len(cases) > 250
    worst = 0.0
    for (config, controls), state in zip(cases, theirs, strict=True):
        expected = json.loads(json.dumps(compute_state(config, controls)))
        assert texts(state) == texts(expected), controls
        a, b = np.array(numbers(state)), np.array(numbers(expected))
        assert a.shape == b.shape, controls
        difference = np.abs(a - b)
        difference = np.minimum(difference, np.abs(difference - 360.0))  # -180° is 180°
        worst = max(worst, float(difference.max()))
    assert worst <= TOLERANCE
