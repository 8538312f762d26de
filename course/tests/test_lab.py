"""JupyterLab stays on this computer: the course opened in JupyterLab, in a real browser, with the
network refused.

The test starts ``jupyter lab`` as a learner would (the environment's own, ``--no-browser``), on
the loopback interface with a token and a free port, with its settings, workspaces, runtime and
configuration folders in a temporary folder (a learner's own settings change nothing, and
nothing is left behind). It serves the working copy that the README's command opens
(``eulerlib-course notebooks copy``, into the temporary folder): the committed notebooks are
never opened, so nothing the browser does can write over them, and the test checks that, after
running and saving notebook 07, the committed notebook is unchanged and the copy was saved. The
system's Chromium, driven headless by Playwright (never a downloaded browser), opens notebook 07
(the animation and the explorer's widgets) and runs all its cells, then the glossary; every
request to a host other than the loopback interface is refused, as with the network off, and
listed, and the test fails on any. It also fails when a cell of notebook 07
ends in an error or does not run, or when the glossary's mathematics is not typeset.

Like the website's test it needs Playwright (the ``site`` extra) and a ``chromium`` executable;
without them it is skipped, and ``.ci/run`` sets ``EULERLIB_SITE_TEST=required``, which makes the
skip a failure.
"""

from __future__ import annotations

import importlib.util
import os
import secrets
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any
from urllib.parse import urlsplit

import pytest

from eulerlib_course.working_copy import write_working_copy

REPO = Path(__file__).resolve().parents[2]
LOOPBACK = "127.0.0.1"
ANIMATED = "07_gimbal_lock_seen.ipynb"
GLOSSARY = "glossary.ipynb"
NOTATION = "01_rotations_in_the_plane_and_about_one_axis.ipynb"
#: The anchor of 01's section on naming frames, which later notebooks link to.
NOTATION_ANCHOR = "naming-frames-ar-b"
CHROMIUM_ARGS = [
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]

#: Runs every cell of the notebook open in JupyterLab, then reports each code cell's execution
#: count and the errors among its outputs.
RUN_ALL = """async () => {
  const app = window.jupyterapp;
  const panel = app.shell.currentWidget;
  await panel.context.ready;
  await panel.sessionContext.ready;
  await app.commands.execute("notebook:run-all-cells");
  const cells = [];
  for (const cell of panel.content.widgets) {
    if (cell.model.type !== "code") { continue; }
    const outputs = cell.model.outputs.toJSON();
    cells.push({
      count: cell.model.executionCount,
      errors: outputs.filter((o) => o.output_type === "error")
        .map((o) => o.ename + ": " + o.evalue),
    });
  }
  return cells;
}"""

#: What the glossary shows once JupyterLab has rendered it: typeset formulas and TeX errors.
RENDERED_MATH = """async () => {
  const app = window.jupyterapp;
  const panel = app.shell.currentWidget;
  await panel.context.ready;
  for (const cell of panel.content.widgets) { await cell.ready; }
  await new Promise((resolve) => setTimeout(resolve, 2000));
  return {
    typeset: document.querySelectorAll(".jp-MarkdownCell mjx-container").length,
    texErrors: [...document.querySelectorAll("mjx-merror")].map((e) => e.textContent),
  };
}"""


#: The text of the heading that holds the anchor ``id``, once JupyterLab has rendered the
#: notebook (null if there is none): where a link to ``notebook.ipynb#id`` lands. JupyterLab's
#: sanitizer turns an ``id`` written in Markdown into ``data-jupyter-id``, which is what its
#: links to a fragment look for.
HEADING_WITH_ID = """async (id) => {
  const app = window.jupyterapp;
  const panel = app.shell.currentWidget;
  await panel.context.ready;
  for (const cell of panel.content.widgets) { await cell.ready; }
  const name = CSS.escape(id);
  const target = document.querySelector(`[data-jupyter-id="${name}"], [id="${name}"]`);
  const heading = target && target.closest("h1, h2, h3, h4, h5, h6");
  return heading ? heading.textContent : null;
}"""


def chromium_executable() -> str | None:
    """The system's Chromium: ``EULERLIB_CHROMIUM``, else ``chromium`` on the PATH."""
    named = os.environ.get("EULERLIB_CHROMIUM")
    if named:
        return named if Path(named).is_file() else None
    return shutil.which("chromium") or shutil.which("chromium-browser")


def missing_prerequisite() -> str | None:
    if importlib.util.find_spec("playwright") is None:
        return 'no Playwright (the site extra): pip install -e "./course[site]"'
    if importlib.util.find_spec("jupyterlab") is None:
        return "no JupyterLab"
    if chromium_executable() is None:
        return "no Chromium: install Debian's chromium package, or name one in EULERLIB_CHROMIUM"
    return None


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind((LOOPBACK, 0))
        return int(probe.getsockname()[1])


@dataclass
class Lab:
    """A running JupyterLab: its address, token and the folder it serves."""

    url: str
    token: str
    root: Path


@pytest.fixture(scope="module")
def lab(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Lab]:
    reason = missing_prerequisite()
    if reason is not None:
        if os.environ.get("EULERLIB_SITE_TEST") == "required":
            pytest.fail(reason)
        pytest.skip(reason)
    base = tmp_path_factory.mktemp("lab")
    root = base / "my-course"
    write_working_copy(REPO / "notebooks", root)  # what the README's command opens
    token, port = secrets.token_hex(16), free_port()
    folders = {name: base / name for name in ("settings", "workspaces", "runtime", "config")}
    for folder in folders.values():
        folder.mkdir()
    command = [
        sys.executable,
        "-m",
        "jupyterlab",
        "--no-browser",
        f"--ServerApp.ip={LOOPBACK}",
        f"--ServerApp.port={port}",
        "--ServerApp.port_retries=0",
        f"--IdentityProvider.token={token}",
        f"--ServerApp.root_dir={root}",
        f"--LabApp.user_settings_dir={folders['settings']}",
        f"--LabApp.workspaces_dir={folders['workspaces']}",
        "--LabApp.expose_app_in_browser=True",
    ]
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        command.append("--allow-root")  # JupyterLab refuses to run as root otherwise
    environment = dict(
        os.environ,
        JUPYTER_RUNTIME_DIR=str(folders["runtime"]),
        JUPYTER_CONFIG_DIR=str(folders["config"]),
        MPLBACKEND="module://matplotlib_inline.backend_inline",
    )
    log = (base / "lab.log").open("w")
    server = subprocess.Popen(
        command, cwd=root, env=environment, stdout=log, stderr=subprocess.STDOUT
    )
    url = f"http://{LOOPBACK}:{port}/"
    try:
        deadline = time.monotonic() + 120
        while True:
            try:
                with urllib.request.urlopen(f"{url}api/status?token={token}", timeout=5):
                    break
            except (urllib.error.URLError, ConnectionError):
                if server.poll() is not None or time.monotonic() > deadline:
                    log.flush()
                    pytest.fail("JupyterLab did not start:\n" + (base / "lab.log").read_text())
                time.sleep(0.5)
        yield Lab(url, token, root)
    finally:
        server.terminate()
        try:
            server.wait(timeout=30)
        except subprocess.TimeoutExpired:
            server.kill()
        log.close()


@dataclass
class Requests:
    """What the pages asked for: refused (another host) and failed requests."""

    refused: list[str]
    console_errors: list[str]


@pytest.fixture(scope="module")
def browser(lab: Lab) -> Iterator[tuple[Any, Requests]]:
    """A headless Chromium with a fresh profile, every request to another host refused."""
    from playwright.sync_api import sync_playwright

    requests = Requests([], [])

    def route(request_route: Any) -> None:
        url = request_route.request.url
        if urlsplit(url).hostname == LOOPBACK or url.startswith(("data:", "blob:")):
            request_route.continue_()
        else:
            requests.refused.append(url)
            request_route.abort()

    arguments = [*CHROMIUM_ARGS]
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        arguments.append("--no-sandbox")  # Chromium refuses to run as root otherwise
    with tempfile.TemporaryDirectory() as profile, sync_playwright() as playwright:
        context = playwright.chromium.launch_persistent_context(
            profile,
            executable_path=chromium_executable(),
            headless=True,
            args=arguments,
            viewport={"width": 1280, "height": 900},
        )
        context.route("**/*", route)
        yield context, requests
        context.close()


def open_notebook(context: Any, lab: Lab, name: str, requests: Requests) -> Any:
    page = context.new_page()
    page.on("pageerror", lambda error: requests.console_errors.append(str(error)))
    page.goto(f"{lab.url}lab/tree/{name}?token={lab.token}", wait_until="load")
    page.wait_for_function(
        "() => window.jupyterapp && window.jupyterapp.shell.currentWidget"
        f" && window.jupyterapp.shell.currentWidget.title.label === {name!r}",
        timeout=120_000,
    )
    return page


def test_notebook_07_runs_in_jupyterlab_and_asks_no_other_host(
    lab: Lab, browser: tuple[Any, Requests]
) -> None:
    context, requests = browser
    committed = (REPO / "notebooks" / ANIMATED).read_bytes()
    page = open_notebook(context, lab, ANIMATED, requests)
    page.set_default_timeout(600_000)
    cells = page.evaluate(RUN_ALL)
    page.evaluate('() => window.jupyterapp.commands.execute("docmanager:save")')
    page.wait_for_load_state("networkidle")
    assert cells, "no code cell found"
    assert [c for c in cells if c["errors"]] == []
    assert all(isinstance(c["count"], int) for c in cells), cells
    assert requests.refused == []
    assert requests.console_errors == []
    page.close()
    assert (REPO / "notebooks" / ANIMATED).read_bytes() == committed
    assert (lab.root / ANIMATED).read_bytes() != committed  # saved, into the copy


def test_the_glossary_typesets_in_jupyterlab_and_asks_no_other_host(
    lab: Lab, browser: tuple[Any, Requests]
) -> None:
    context, requests = browser
    page = open_notebook(context, lab, GLOSSARY, requests)
    facts = page.evaluate(RENDERED_MATH)
    page.wait_for_load_state("networkidle")
    assert facts["typeset"] >= 1 and facts["texErrors"] == []
    assert requests.refused == []
    page.close()


def test_the_section_on_naming_frames_has_its_anchor_in_jupyterlab(
    lab: Lab, browser: tuple[Any, Requests]
) -> None:
    """Later notebooks link to ``01_….ipynb#naming-frames-ar-b``: JupyterLab must render an
    element with that id in the section's heading (its own heading ids keep the letter case and
    the symbols, so the heading carries the anchor explicitly)."""
    context, requests = browser
    page = open_notebook(context, lab, NOTATION, requests)
    heading = page.evaluate(HEADING_WITH_ID, NOTATION_ANCHOR)
    assert heading is not None and "Naming frames" in heading, heading
    assert requests.refused == []
    page.close()
