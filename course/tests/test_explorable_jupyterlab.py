"""Notebook 07's explorable in JupyterLab, in a real browser, with eulerlib computing.

The test starts ``jupyter lab`` on the loopback interface with a token, on a copy of notebook 07
in a temporary folder (so nothing is written into the repository), with its configuration,
settings and runtime files in that folder too and JupyterLab's news and update checks off. It
opens the notebook in the system's Chromium (driven by Playwright; no browser is downloaded),
runs all cells, then, as a learner would, drags the explorable's picture and raises the pitch
slider from the keyboard: the picture and the numbers change, the numbers come from the kernel
(at pitch 90° the read-back yaw is eulerlib's 0), and no request leaves the loopback interface
but one that is not the explorable's: the stylesheet that matplotlib's animation player of
section 8 links to (the website strips it; here it is refused, as with the network off).

Skipped without Playwright or Chromium, like the other browser tests (``.ci/run`` sets
``EULERLIB_SITE_TEST=required``, which makes the skip a failure).
"""

from __future__ import annotations

import json
import os
import secrets
import shutil
import socket
import subprocess
import sys
import time
import urllib.request
from collections.abc import Iterator
from pathlib import Path
from typing import Any
from urllib.parse import urlsplit

import pytest
from test_explorable_port import browser_or_skip

REPO = Path(__file__).resolve().parents[2]
NOTEBOOK = "07_gimbal_lock_seen.ipynb"
LOOPBACK = "127.0.0.1"

FACTS = """(root) => ({
  drawing: root.querySelector("svg").innerHTML,
  azimuth: Number(root.querySelector("svg").dataset.azimuth),
  matrix: root.querySelector(".eulexp-matrix").textContent,
  recovered: root.querySelector(".eulexp-recovered").textContent,
  locked: root.querySelector(".eulexp-lock").dataset.locked,
  summary: root.querySelector("[aria-live]").textContent,
})"""


KERNEL_IDLE = """() => {
  const context = window.jupyterapp.shell.currentWidget?.sessionContext;
  return Boolean(context?.isReady && context.session?.kernel?.status === "idle");
}"""
RUN_ALL = "() => window.jupyterapp.commands.execute('notebook:run-all-cells')"


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind((LOOPBACK, 0))
        return int(probe.getsockname()[1])


@pytest.fixture(scope="module")
def jupyterlab(tmp_path_factory: pytest.TempPathFactory) -> Iterator[tuple[str, str]]:
    """A JupyterLab server on the loopback interface: its address and token."""
    browser_or_skip()
    home = tmp_path_factory.mktemp("jupyterlab")
    work = home / "notebooks"
    work.mkdir()
    shutil.copyfile(REPO / "notebooks" / NOTEBOOK, work / NOTEBOOK)
    config = home / "config"
    config.mkdir()
    (config / "jupyter_server_config.json").write_text(
        json.dumps(
            {
                "LabApp": {
                    "news_url": None,
                    "check_for_updates_class": "jupyterlab.NeverCheckForUpdate",
                }
            }
        ),
        encoding="utf-8",
    )
    token, port = secrets.token_hex(16), free_port()
    paths = [str(REPO), str(REPO / "course"), os.environ.get("PYTHONPATH", "")]
    environment = {
        **os.environ,
        "JUPYTER_CONFIG_DIR": str(config),
        "JUPYTER_RUNTIME_DIR": str(home / "runtime"),
        "JUPYTERLAB_SETTINGS_DIR": str(home / "settings"),
        "JUPYTERLAB_WORKSPACES_DIR": str(home / "workspaces"),
        "PYTHONPATH": os.pathsep.join(path for path in paths if path),
        "MPLBACKEND": "Agg",
    }
    command = [
        sys.executable, "-m", "jupyterlab", "--no-browser", f"--ServerApp.ip={LOOPBACK}",
        f"--ServerApp.port={port}", "--ServerApp.port_retries=0",
        f"--IdentityProvider.token={token}", f"--ServerApp.root_dir={work}",
        "--expose-app-in-browser",
    ]  # fmt: skip
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        command.append("--allow-root")
    log = (home / "server.log").open("w")
    server = subprocess.Popen(command, env=environment, stdout=log, stderr=subprocess.STDOUT)
    url = f"http://{LOOPBACK}:{port}/"
    try:
        deadline = time.monotonic() + 120
        while True:
            try:
                with urllib.request.urlopen(f"{url}api/status?token={token}", timeout=5):
                    break
            except OSError:
                if server.poll() is not None or time.monotonic() > deadline:
                    raise AssertionError((home / "server.log").read_text()) from None
                time.sleep(0.5)
        yield url, token
    finally:
        server.terminate()
        try:
            server.wait(timeout=30)
        except subprocess.TimeoutExpired:
            server.kill()
            server.wait()
        log.close()


def test_the_explorable_turns_and_computes_in_jupyterlab(jupyterlab: tuple[str, str]) -> None:
    from playwright.sync_api import sync_playwright

    url, token = jupyterlab
    executable = browser_or_skip()
    refused: list[str] = []
    errors: list[str] = []
    arguments = ["--disable-background-networking", "--disable-component-update"]
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        arguments.append("--no-sandbox")
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(
            executable_path=executable, headless=True, args=arguments
        )
        page = browser.new_page(viewport={"width": 1280, "height": 1000})

        def route(request_route: Any) -> None:
            if urlsplit(request_route.request.url).hostname == LOOPBACK:
                request_route.continue_()
            else:
                refused.append(request_route.request.url)
                request_route.abort()

        page.route("**/*", route)
        page.on("pageerror", lambda error: errors.append(str(error)))
        page.goto(f"{url}lab/tree/{NOTEBOOK}?token={token}")
        page.wait_for_function(
            "() => window.jupyterapp && document.querySelector('.jp-Notebook .jp-Cell')",
            timeout=120_000,
        )
        page.wait_for_function(KERNEL_IDLE, timeout=120_000)
        # the stored widget state draws the explorable at once; running every cell replaces it
        # with one whose model lives in the kernel (the command returns when all have run)
        assert page.evaluate(RUN_ALL) is True
        root = page.locator(".eulexp").first
        root.locator("svg").wait_for(timeout=240_000)
        svg = root.locator("svg")
        svg.scroll_into_view_if_needed()
        before = root.evaluate(FACTS)
        assert "pitch 85°" in before["summary"] and before["locked"] == "false"

        # The view that Run All puts in place of the stored one can still be arriving when the
        # cells have run: a drag that lands on the view being replaced turns nothing. Drag the
        # explorable as it stands until a drag turns it (a few tries, half a second apart).
        for _ in range(10):
            root = page.locator(".eulexp").first
            svg = root.locator("svg")
            svg.scroll_into_view_if_needed()
            before = root.evaluate(FACTS)
            box = svg.bounding_box()
            assert box is not None
            x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
            page.mouse.move(x, y)
            page.mouse.down()
            page.mouse.move(x - 50, y + 30, steps=5)
            page.mouse.up()
            dragged = root.evaluate(FACTS)
            if dragged["azimuth"] != before["azimuth"]:
                break
            page.wait_for_timeout(500)
        assert dragged["azimuth"] != before["azimuth"]
        assert dragged["drawing"] != before["drawing"]

        pitch = root.locator("input[type=range]").nth(1)
        pitch.focus()
        for _ in range(5):  # 1° a step: 85° → 90°
            page.keyboard.press("ArrowRight")
        page.wait_for_function(
            "(root) => root.querySelector('.eulexp-lock').dataset.locked === 'true'",
            arg=root.element_handle(),
            timeout=60_000,
        )
        after = root.evaluate(FACTS)
        assert after["recovered"] == "read back: yaw 0°, pitch 90°, roll -20°"  # eulerlib's choice
        assert after["matrix"] != before["matrix"]
        assert after["drawing"] != dragged["drawing"]
        assert "gimbal lock: only roll - yaw is defined" in after["summary"]
        browser.close()
    assert refused == [], "other hosts"
    assert errors == [], "errors in the page"
