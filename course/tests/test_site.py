"""The course website: built by ``eulerlib-course site build``, read in a real browser with no
network.

Two groups of tests.

* **Preparing the pages** (:mod:`eulerlib_course.site`): a notebook made ready for the web, the
  table of contents, the README's JupyterLab command. They need the notebook tools only, so they
  run with the rest of the suite.
* **The site itself.** The documented command builds it once for this module into a temporary
  folder; a small HTTP server serves that folder on the loopback interface, and the system's
  Chromium, driven headless by Playwright (never a downloaded browser), opens every page. A page
  fails when it asks any other host for anything (such requests are refused, as with the network
  off, and listed), when a request fails or an image does not load, when math is left untypeset
  (the math elements of the HTML against MathJax's containers, TeX errors, and ``$...$`` left in
  the text), or when the console shows an error. Without the ``site`` extra or a ``chromium``
  executable these tests are skipped, with the reason; ``.ci/run`` sets ``EULERLIB_SITE_TEST``
  to ``required``, which turns the skip into a failure.

Two full-page screenshots (the landing page, and the page of a notebook that shows a widget)
are saved for a human to look at: into the folder named by ``EULERLIB_SITE_SCREENSHOTS``, or
into the test's temporary folder.
"""

from __future__ import annotations

import base64
import functools
import hashlib
import html
import http.server
import importlib.util
import io
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import urllib.request
import zipfile
from collections.abc import Iterator
from dataclasses import dataclass, field
from html.parser import HTMLParser
from pathlib import Path
from typing import Any
from urllib.parse import unquote, urljoin, urlsplit

import nbformat
import pytest

from eulerlib_course.site import (
    build_site,
    course_pages,
    figure_alts,
    jupyterlab_command,
    landing_page_gaps,
    prepare_notebook,
    table_of_contents,
)
from eulerlib_course.student import student_copy

REPO = Path(__file__).resolve().parents[2]
README = (REPO / "README.md").read_text(encoding="utf-8")
NOTEBOOKS = course_pages(REPO / "notebooks")
NOTEBOOK_PAGES = [f"notebooks/{path.stem}.html" for path in NOTEBOOKS]
#: Every page of the site: the landing page, one page per notebook, the teachers' page and the
#: search page.
PAGES = ["index.html", *NOTEBOOK_PAGES, "teachers.html", "search.html"]
#: The widths at which every page is opened: a desktop's and a phone's (CSS pixels).
DESKTOP, PHONE = 1280, 390
#: axe-core, vendored with its licence and origin (vendor/axe-core/ORIGIN.md).
AXE = Path(__file__).parent / "vendor" / "axe-core" / "axe.min.js"
AXE_SHA256 = "29348999450cdf2849a8e70b7912fc2da85a849da39c0d0d5394f51d4a9ed95c"
AXE_RULES = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa"]
notebook_pages = pytest.mark.parametrize(
    ("name", "path"), list(zip(NOTEBOOK_PAGES, NOTEBOOKS, strict=True)), ids=NOTEBOOK_PAGES
)
WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"
PICTURES = ("image/png", "image/svg+xml", "image/jpeg")
LOOPBACK = "127.0.0.1"
#: Chromium's own background traffic off (the machine's network is closed to it anyway).
CHROMIUM_ARGS = [
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]


def page_text(source: str) -> str:
    """The text of an HTML page, tags removed and entities decoded."""
    return html.unescape(re.sub(r"<[^>]+>", "", source))


def read(path: Path) -> Any:
    return nbformat.read(str(path), as_version=4)


def tags(cell: Any) -> list[str]:
    return list(cell.get("metadata", {}).get("tags", []))


def solution_count(notebook: Any) -> int:
    return sum("solution" in tags(cell) for cell in notebook.cells)


def picture_count(notebook: Any) -> int:
    return sum(
        any(mime in output.get("data", {}) for mime in PICTURES)
        for cell in notebook.cells
        for output in cell.get("outputs", [])
    )


def shows_widget(notebook: Any) -> bool:
    return any(
        WIDGET_VIEW in output.get("data", {})
        for cell in notebook.cells
        for output in cell.get("outputs", [])
    )


# --- preparing the pages ------------------------------------------------------------------------


def small_notebook() -> Any:
    new = nbformat.v4
    widget = new.new_output(
        "display_data",
        data={WIDGET_VIEW: {"model_id": "abc"}, "image/png": "iVBORw0K", "text/plain": "Box()"},
    )
    player = new.new_output(
        "display_data",
        data={
            "text/html": '<link rel="stylesheet"\nhref="https://maxcdn.example/font-awesome/4.4.0/'
            'css/font-awesome.min.css">\n<i class="fa fa-play"></i>'
        },
    )
    cells = [
        new.new_markdown_cell("# 99 · A title\n\nWhy it matters."),
        new.new_code_cell("explorer()", outputs=[widget]),
        new.new_code_cell("HTML(animation.to_jshtml())", outputs=[player]),
        new.new_code_cell("answer_1 = ...", metadata={"tags": ["exercise"]}),
        new.new_code_cell("answer_1 = 42", metadata={"tags": ["solution"]}),
    ]
    notebook = new.new_notebook(cells=cells)
    notebook.metadata["widgets"] = {"application/vnd.jupyter.widget-state+json": {"state": {}}}
    return notebook


def test_prepared_page_offers_both_editions_and_the_command_after_the_title() -> None:
    page = prepare_notebook(
        small_notebook(), teacher="t/99.ipynb", student="s/99.ipynb", command="jupyter lab x/"
    )
    box = page.cells[1]
    assert page.cells[0].source.startswith("# 99 · A title")
    assert box.cell_type == "markdown"
    assert "Run this notebook yourself" in box.source
    assert "[teacher's edition](path:t/99.ipynb)" in box.source
    assert "[student copy](path:s/99.ipynb)" in box.source
    assert "```bash\njupyter lab x/\n```" in box.source


def test_prepared_page_of_a_notebook_without_solutions_offers_it_once() -> None:
    page = prepare_notebook(
        nbformat.v4.new_notebook(cells=[nbformat.v4.new_markdown_cell("# Glossary")]),
        teacher="t/glossary.ipynb",
        student=None,
        command="jupyter lab x/",
    )
    assert "[this notebook](path:t/glossary.ipynb)" in page.cells[1].source
    assert "student copy" not in page.cells[1].source


def test_prepared_page_folds_solutions_and_shows_widget_pictures() -> None:
    notebook = small_notebook()
    before = nbformat.writes(notebook)
    page = prepare_notebook(notebook, teacher="t", student="s", command="c")
    assert nbformat.writes(notebook) == before  # the committed notebook is left alone
    assert "widgets" not in page.metadata
    solution = next(cell for cell in page.cells if "solution" in tags(cell))
    assert "hide-input" in tags(solution)
    assert solution.metadata["mystnb"]["code_prompt_show"] == "Show the worked solution"
    explorer = next(i for i, cell in enumerate(page.cells) if cell.source == "explorer()")
    assert set(page.cells[explorer].outputs[0].data) == {"image/png", "text/plain"}
    note = page.cells[explorer + 1]
    assert note.cell_type == "markdown" and "run this notebook in" in note.source
    player = next(cell for cell in page.cells if "to_jshtml" in cell.source)
    shown = player.outputs[0].data["text/html"]
    assert "font-awesome" not in shown and shown.startswith('<i class="fa fa-play">')
    assert len({cell.id for cell in page.cells}) == len(page.cells)
    nbformat.validate(page)


def test_a_widget_without_a_picture_is_refused() -> None:
    output = nbformat.v4.new_output("display_data", data={WIDGET_VIEW: {}, "text/plain": "Box()"})
    notebook = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("w", outputs=[output])])
    with pytest.raises(ValueError, match="cell 0 shows a widget without a stored picture"):
        prepare_notebook(notebook, teacher="t", student=None, command="c", name="99_x.ipynb")


def picture_outputs(cell: Any) -> int:
    return sum(
        any(mime in output.get("data", {}) for mime in PICTURES)
        for output in cell.get("outputs", [])
    )


def meaningless_alt(text: Any) -> str | None:
    """Why ``text`` is no text alternative of a figure, or None when it is one."""
    if not isinstance(text, str) or not text.strip():
        return "empty"
    if re.search(r"\.(png|svg|jpe?g|gif)\b", text) or re.fullmatch(r"[\w./-]+", text):
        return f"a file name, not a description: {text!r}"
    if len(text.split()) < 8:
        return f"a few words, not a description: {text!r}"
    if text.startswith(("<Figure", "Figure(", "Box(", "VBox(")):
        return f"the output's text representation: {text!r}"
    return None


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[path.name for path in NOTEBOOKS])
def test_every_figure_says_what_it_shows(path: Path) -> None:
    problems = []
    for index, cell in enumerate(read(path).cells):
        count = picture_outputs(cell)
        if cell.cell_type != "code" or not count:
            continue
        alts = cell.metadata.get("alt")
        alts = [alts] if isinstance(alts, str) else list(alts or [])
        if len(alts) != count:
            problems.append(f"cell {index}: {count} figures, {len(alts)} text alternatives")
        problems += [f"cell {index}: {why}" for why in map(meaningless_alt, alts) if why]
    assert problems == []


def test_the_animation_asks_no_other_host_and_says_what_it_shows() -> None:
    notebook = read(REPO / "notebooks" / "07_gimbal_lock_seen.ipynb")
    players = [
        "".join(output["data"]["text/html"])
        for cell in notebook.cells
        for output in cell.get("outputs", [])
        if "_anim_img" in "".join(output.get("data", {}).get("text/html", ""))
    ]
    assert len(players) == 1
    (player,) = players
    assert not re.search(r"(href|src)=[\"']https?://", player), "the player asks another host"
    assert 'class="fa ' not in player, "the player still uses Font Awesome icons"
    alt = re.search(r'<img id="_anim_img\w*" alt="([^"]*)"', player)
    assert alt is not None and meaningless_alt(html.unescape(alt.group(1))) is None
    assert re.search(r'<input id="_anim_slider\w*" aria-label="Frame"', player)


def test_figure_alts_follow_the_pictures_of_each_cell() -> None:
    pngs = [b"first picture", b"second picture"]
    outputs = [
        nbformat.v4.new_output("display_data", data={"image/png": base64.b64encode(png).decode()})
        for png in pngs
    ]
    cell = nbformat.v4.new_code_cell("plot()", outputs=outputs)
    cell.metadata["alt"] = ["what the first one shows", "what the second one shows"]
    alts = figure_alts(nbformat.v4.new_notebook(cells=[cell]))
    assert alts == {
        hashlib.sha256(pngs[0]).hexdigest(): "what the first one shows",
        hashlib.sha256(pngs[1]).hexdigest(): "what the second one shows",
    }


def test_table_of_contents_follows_the_notebooks_and_ends_with_the_glossary() -> None:
    pages = [f"notebooks/{path.stem}" for path in NOTEBOOKS]
    toc = table_of_contents(pages)
    chapters = [chapter["file"] for part in toc["parts"] for chapter in part["chapters"]]
    assert chapters == pages
    with_teachers = table_of_contents(pages, "teachers")
    assert with_teachers["parts"][-1] == {
        "caption": "For teachers",
        "chapters": [{"file": "teachers"}],
    }
    numbered = [path.stem for path in NOTEBOOKS if re.match(r"\d\d_", path.name)]
    assert [Path(page).name for page in chapters[: len(numbered)]] == numbered
    assert chapters[-1] == "notebooks/glossary"


def test_the_pages_show_the_readme_command_that_opens_jupyterlab() -> None:
    command = jupyterlab_command(README)
    assert command.startswith("python3 -m venv .venv") and command.endswith(
        "eulerlib-course notebooks copy --out my-course/ && .venv/bin/jupyter lab my-course/"
    )
    with pytest.raises(ValueError, match="no command that opens a copy of the course"):
        jupyterlab_command("# no commands here\n")


def test_the_landing_page_cuts_the_readme_where_it_has_those_lines() -> None:
    landing = (REPO / "site" / "index.md").read_text(encoding="utf-8")
    assert landing.count(":start-after:") + landing.count(":end-before:") >= 4
    assert landing_page_gaps(landing, README) == []
    renamed = README.replace("\n## The course\n", "\n## The notebooks\n")
    assert landing_page_gaps(landing, renamed) == [
        "the README has no line '## The course' where the landing page cuts it"
    ]


def test_the_site_is_not_built_over_another_folder_or_a_file(tmp_path: Path) -> None:
    (tmp_path / "notes.txt").write_text("a teacher's notes", encoding="utf-8")
    with pytest.raises(ValueError, match="not empty and holds no site built before"):
        build_site(REPO, tmp_path)
    with pytest.raises(ValueError, match="is a file, not a folder"):
        build_site(REPO, tmp_path / "notes.txt")
    assert [path.name for path in tmp_path.iterdir()] == ["notes.txt"]


def test_the_site_command_names_its_extra(tmp_path: Path) -> None:
    code = (
        "import sys\nsys.modules['jupyter_book'] = None\n"
        "from eulerlib_course.cli import main\n"
        f"raise SystemExit(main(['site', 'build', '--out', {str(tmp_path / 'site')!r}]))\n"
    )
    result = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO, check=False
    )
    assert result.returncode == 1
    assert result.stderr.splitlines() == [
        "eulerlib-course site: error: eulerlib-course site build needs jupyter_book "
        '(the site extra of eulerlib-course): pip install -e "./course[site]"'
    ]
    assert not (tmp_path / "site").exists()


# --- the site, built and read in a browser -------------------------------------------------------


def chromium_executable() -> str | None:
    """The system's Chromium: ``EULERLIB_CHROMIUM``, else ``chromium`` on the PATH."""
    named = os.environ.get("EULERLIB_CHROMIUM")
    if named:
        return named if Path(named).is_file() else None
    return shutil.which("chromium") or shutil.which("chromium-browser")


def missing_prerequisite() -> str | None:
    """Why the site cannot be built and read here, or None."""
    for module in ("jupyter_book", "sphinx-mathjax-offline", "playwright"):
        if importlib.util.find_spec(module) is None:
            return f'the site extra is not installed (no {module}): pip install -e "./course[site]"'
    if chromium_executable() is None:
        return "no Chromium: install Debian's chromium package, or name one in EULERLIB_CHROMIUM"
    return None


@dataclass
class Site:
    """The built site and where it is served."""

    folder: Path
    url: str
    build_output: str
    build_errors: str


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Site]:
    reason = missing_prerequisite()
    if reason is not None:
        if os.environ.get("EULERLIB_SITE_TEST") == "required":
            pytest.fail(reason)
        pytest.skip(reason)
    folder = tmp_path_factory.mktemp("site") / "html"
    result = subprocess.run(
        [sys.executable, "-m", "eulerlib_course", "site", "build", "--out", str(folder)],
        capture_output=True,
        text=True,
        cwd=REPO,
        check=False,
        timeout=600,
    )
    assert result.returncode == 0, result.stderr

    class QuietHandler(http.server.SimpleHTTPRequestHandler):
        def log_message(self, format: str, *args: Any) -> None:
            pass

    handler = functools.partial(QuietHandler, directory=str(folder))
    server = http.server.ThreadingHTTPServer((LOOPBACK, 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield Site(
            folder, f"http://{LOOPBACK}:{server.server_address[1]}/", result.stdout, result.stderr
        )
    finally:
        server.shutdown()
        server.server_close()


@dataclass
class Visit:
    """What happened while one page was open."""

    refused: list[str] = field(default_factory=list)
    failed: list[str] = field(default_factory=list)
    console_errors: list[str] = field(default_factory=list)
    facts: dict[str, Any] = field(default_factory=dict)
    source: str = ""


#: Collected in the page once MathJax has finished.
FACTS = """async () => {
  if (window.MathJax && window.MathJax.startup) { await window.MathJax.startup.promise; }
  const text = (root) => {
    const copy = root.cloneNode(true);
    copy.querySelectorAll("mjx-container, pre, code, script, style").forEach((e) => e.remove());
    return copy.textContent;
  };
  const folds = [...document.querySelectorAll("details")].filter(
    (d) => (d.querySelector("summary") || {}).textContent.includes("worked solution"));
  return {
    typeset: document.querySelectorAll("mjx-container").length,
    texErrors: [...document.querySelectorAll("mjx-merror")].map((e) => e.textContent),
    text: text(document.querySelector("main") || document.body),
    brokenImages: [...document.images]
      .filter((i) => !(i.complete && i.naturalWidth > 0))
      .map((i) => i.currentSrc || i.src),
    outputPictures: [...document.querySelectorAll(".cell_output img")]
      .filter((i) => !i.closest(".text_html")).length,
    figureAlts: [...document.querySelectorAll(".cell_output img")]
      .filter((i) => !i.closest(".text_html")).map((i) => i.alt),
    imagesWithoutAlt: [...document.images].filter((i) => !i.hasAttribute("alt"))
      .map((i) => i.id || i.src.slice(0, 80)),
    folds: folds.map((d) => ({
      open: d.open,
      visible: [...d.querySelectorAll("pre")].some((p) => p.checkVisibility()),
    })),
    navigation: [...document.querySelectorAll("nav.bd-docs-nav a.reference.internal")]
      .map((a) => new URL(a.href).pathname),
  };
}"""


def watch(page: Any, visit: Visit) -> None:
    """Record into ``visit`` what ``page`` asks for and what its console says.

    Requests to any host but the loopback interface are refused, as with the network off, and
    listed.
    """

    def route(request_route: Any) -> None:
        url = request_route.request.url
        if urlsplit(url).hostname == LOOPBACK:
            request_route.continue_()
        else:
            visit.refused.append(url)
            request_route.abort()

    def console(message: Any) -> None:
        if message.type == "error":
            visit.console_errors.append(message.text)

    def response(reply: Any) -> None:
        if reply.status >= 400:
            visit.failed.append(f"{reply.status} {reply.url}")

    def request_failed(request: Any) -> None:
        if urlsplit(request.url).hostname == LOOPBACK:  # the refused ones are listed already
            visit.failed.append(f"{request.failure} {request.url}")

    page.route("**/*", route)
    page.on("console", console)
    page.on("pageerror", lambda error: visit.console_errors.append(str(error)))
    page.on("response", response)
    page.on("requestfailed", request_failed)


#: The axe-core rules of WCAG 2.1 A and AA, run in the page; each violation with its first nodes.
AXE_RUN = """async (tags) => {
  const result = await axe.run(document, {runOnly: {type: "tag", values: tags}});
  return result.violations.map((v) => ({
    rule: v.id,
    impact: v.impact,
    nodes: v.nodes.slice(0, 3).map((n) => n.target.join(" ") + " :: " + n.html.slice(0, 200)),
  }));
}"""

#: What the phone sees: horizontal overflow of the page, and the course map's layout.
PHONE_FACTS = """() => {
  const map = document.querySelector("table.course-map");
  return {
    overflow: document.documentElement.scrollWidth - document.documentElement.clientWidth,
    mapRowsAsCards: map ? [...map.querySelectorAll("tbody tr")].every(
      (row) => getComputedStyle(row).display === "block") : null,
    mapWidth: map ? map.getBoundingClientRect().width : null,
  };
}"""


def axe_source() -> str:
    source = AXE.read_bytes()
    assert hashlib.sha256(source).hexdigest() == AXE_SHA256, "axe.min.js is not the vendored file"
    return source.decode("utf-8")


def open_page(context: Any, site: Site, name: str, width: int, visit: Visit) -> Any:
    page = context.new_page()
    page.set_viewport_size({"width": width, "height": 900})
    watch(page, visit)
    response = page.goto(site.url + name, wait_until="load")
    assert response is not None
    visit.source = response.text()
    visit.facts = page.evaluate(FACTS)
    page.wait_for_load_state("networkidle")
    return page


@pytest.fixture(scope="module")
def driver(site: Site) -> Iterator[Any]:
    """Playwright, started once for the module: its synchronous API runs one driver at a time."""
    from playwright.sync_api import sync_playwright

    with sync_playwright() as playwright:
        yield playwright


def launch(driver: Any, profile: str, **options: Any) -> Any:
    """A headless Chromium (the system's) with the fresh profile folder ``profile``."""
    arguments = [*CHROMIUM_ARGS]
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        arguments.append("--no-sandbox")  # Chromium refuses to run as root otherwise
    return driver.chromium.launch_persistent_context(
        profile,  # a fresh --user-data-dir
        executable_path=chromium_executable(),
        headless=True,
        args=arguments,
        **options,
    )


@pytest.fixture(scope="module")
def browser(driver: Any) -> Iterator[Any]:
    """A headless Chromium with a fresh profile, at a desktop's width."""
    with tempfile.TemporaryDirectory() as profile:
        context = launch(driver, profile, viewport={"width": DESKTOP, "height": 900})
        yield context
        context.close()


@pytest.fixture(scope="module")
def visits(
    site: Site, browser: Any, tmp_path_factory: pytest.TempPathFactory
) -> dict[tuple[str, int], Visit]:
    """Open every page once at a desktop's width and once at a phone's; run axe-core on each;
    take two screenshots at each width."""
    shots = Path(os.environ.get("EULERLIB_SITE_SCREENSHOTS") or tmp_path_factory.mktemp("shots"))
    shots.mkdir(parents=True, exist_ok=True)
    widget_pages = [
        page
        for page, path in zip(NOTEBOOK_PAGES, NOTEBOOKS, strict=True)
        if shows_widget(read(path))
    ]
    second = (widget_pages or NOTEBOOK_PAGES)[0]
    screenshots = {"index.html": "landing", second: Path(second).stem}
    axe = axe_source()
    results: dict[tuple[str, int], Visit] = {}
    for width in (DESKTOP, PHONE):
        for name in PAGES:
            visit = results[name, width] = Visit()
            page = open_page(browser, site, name, width, visit)
            if width == PHONE:
                visit.facts.update(page.evaluate(PHONE_FACTS))
            page.add_script_tag(content=axe)
            visit.facts["axe"] = page.evaluate(AXE_RUN, AXE_RULES)
            if name in screenshots:
                shot = shots / f"{screenshots[name]}-{width}.png"
                page.screenshot(path=str(shot), full_page=True)
            page.close()
    print(
        f"screenshots of the site: {', '.join(str(path) for path in sorted(shots.glob('*.png')))}"
    )
    return results


def test_the_build_is_clean(site: Site) -> None:
    assert site.build_errors == "", "Sphinx warned:\n" + site.build_errors
    assert f"built {len(NOTEBOOKS)} notebook pages" in site.build_output


def test_every_page_is_opened(site: Site) -> None:
    built = sorted(
        path.relative_to(site.folder).as_posix()
        for path in site.folder.rglob("*.html")
        if not path.relative_to(site.folder).parts[0].startswith("_")
    )
    assert built == sorted(PAGES)


@pytest.mark.parametrize("name", PAGES)
@pytest.mark.parametrize("width", [DESKTOP, PHONE])
def test_page_asks_no_other_host_and_loads_everything(
    visits: dict[tuple[str, int], Visit], name: str, width: int
) -> None:
    visit = visits[name, width]
    assert visit.refused == [], "requests to other hosts"
    assert visit.failed == [], "failed requests"
    assert visit.facts["brokenImages"] == [], "images that did not load"
    assert visit.console_errors == [], "errors in the console"


@pytest.mark.parametrize("name", PAGES)
def test_page_math_is_typeset(visits: dict[tuple[str, int], Visit], name: str) -> None:
    visit = visits[name, DESKTOP]
    math_elements = len(re.findall(r'class="[^"]*\bmath\b[^"]*"', visit.source))
    assert visit.facts["typeset"] == math_elements
    assert visit.facts["texErrors"] == []
    left = re.findall(r"\$[^$\s][^$]*\$|\\\(|\\\[|\\begin\{", visit.facts["text"])
    assert left == [], "TeX left in the text"


@notebook_pages
def test_page_folds_worked_solutions_and_shows_pictures(
    visits: dict[tuple[str, int], Visit], name: str, path: Path
) -> None:
    notebook, visit = read(path), visits[name, DESKTOP]
    folds = visit.facts["folds"]
    assert len(folds) == solution_count(notebook)
    assert all(not fold["open"] and not fold["visible"] for fold in folds)
    assert visit.facts["outputPictures"] == picture_count(notebook)
    assert "widget-view+json" not in visit.source and "widget-state+json" not in visit.source
    assert jupyterlab_command(README) in page_text(visit.source)


def test_pages_are_in_course_order(visits: dict[tuple[str, int], Visit]) -> None:
    navigation = [path.lstrip("/") for path in visits["index.html", DESKTOP].facts["navigation"]]
    shown = [path for path in navigation if path in NOTEBOOK_PAGES]
    assert shown == NOTEBOOK_PAGES


@pytest.mark.parametrize("width", [DESKTOP, PHONE])
@pytest.mark.parametrize("name", PAGES)
def test_page_has_no_accessibility_violation(
    visits: dict[tuple[str, int], Visit], name: str, width: int
) -> None:
    """axe-core's WCAG 2.1 A and AA rules find nothing, at a desktop's and at a phone's width."""
    visit = visits[name, width]
    assert visit.facts["axe"] == [], "axe-core found violations"
    assert visit.facts["imagesWithoutAlt"] == []


@notebook_pages
def test_page_figures_carry_their_text_alternatives(
    visits: dict[tuple[str, int], Visit], name: str, path: Path
) -> None:
    expected = []
    for cell in read(path).cells:
        if cell.cell_type == "code" and picture_outputs(cell):
            alts = cell.metadata.get("alt")
            expected += [alts] if isinstance(alts, str) else list(alts or [])
    assert visits[name, DESKTOP].facts["figureAlts"] == expected


def test_the_course_map_fits_a_phone(visits: dict[tuple[str, int], Visit]) -> None:
    facts = visits["index.html", PHONE].facts
    assert facts["mapRowsAsCards"] is True
    assert facts["mapWidth"] <= PHONE
    for name in PAGES:
        assert visits[name, PHONE].facts["overflow"] <= 0, f"{name} scrolls sideways on a phone"


@pytest.mark.parametrize("width", [PHONE, 900, DESKTOP])
def test_the_menu_button_shows_and_hides_the_chapters(site: Site, browser: Any, width: int) -> None:
    """The ☰ button a reader sees opens the chapter list on a phone (as a dialog) and folds it
    away and back on a desktop."""
    visit = Visit()
    page = open_page(browser, site, NOTEBOOK_PAGES[4], width, visit)
    chapters = page.locator("nav.bd-docs-nav a.reference.internal:visible")
    button = page.locator(".primary-toggle:visible")
    assert button.count() == 1
    shown_at_first = chapters.count()
    button.click()
    page.wait_for_timeout(700)  # the theme's transition
    shown_after = chapters.count()
    if width < 992:
        assert (shown_at_first, shown_after) == (0, len(PAGES) - 1)  # all pages but search
        assert page.evaluate("document.getElementById('pst-primary-sidebar-modal').open")
        target = chapters.nth(7).evaluate("(a) => a.href")
        chapters.nth(7).click()
        page.wait_for_load_state("load")
        assert page.url == target != site.url + NOTEBOOK_PAGES[4]
    else:
        assert (shown_at_first, shown_after) == (len(PAGES) - 1, 0)
        button.click()
        page.wait_for_timeout(700)
        assert chapters.count() == len(PAGES) - 1
    page.close()
    assert visit.console_errors == [] and visit.refused == []


class Links(HTMLParser):
    """The ``href`` and ``src`` of a page, and the ids it defines."""

    def __init__(self) -> None:
        super().__init__()
        self.targets: list[str] = []
        self.ids: set[str] = set()
        self.downloads: dict[str, str] = {}
        self._download: str | None = None

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        values = dict(attrs)
        if values.get("id"):
            self.ids.add(str(values["id"]))
        for key in ("href", "src"):
            if values.get(key):
                self.targets.append(str(values[key]))
        if tag == "a" and "download" in (values.get("class") or ""):
            self._download = str(values["href"])

    def handle_data(self, data: str) -> None:
        if self._download is not None and data.strip():
            self.downloads[data.strip()] = self._download
            self._download = None


def links_of(site: Site, name: str) -> Links:
    parser = Links()
    parser.feed((site.folder / name).read_text(encoding="utf-8"))
    return parser


@pytest.mark.parametrize("name", PAGES)
def test_local_links_and_anchors_exist(site: Site, name: str) -> None:
    broken = []
    for target in links_of(site, name).targets:
        parts = urlsplit(target)
        if parts.scheme or target.startswith(("#", "//")):
            continue
        resolved = urlsplit(urljoin(f"http://site/{name}", target))
        path = site.folder / unquote(resolved.path.lstrip("/"))
        if path.is_dir():
            path = path / "index.html"
        if not path.is_file():
            broken.append(target)
        elif resolved.fragment and path.suffix == ".html":
            if (
                resolved.fragment
                not in links_of(site, path.relative_to(site.folder).as_posix()).ids
            ):
                broken.append(target)
    assert broken == []


def fetch(site: Site, name: str, href: str) -> tuple[str, bytes]:
    """The file name and the bytes of a download linked from the page ``name``."""
    url = urljoin(site.url + name, href)
    with urllib.request.urlopen(url) as reply:
        return unquote(urlsplit(url).path).rsplit("/", 1)[-1], bytes(reply.read())


def unpack(content: bytes, into: Path) -> list[str]:
    archive = zipfile.ZipFile(io.BytesIO(content))
    archive.extractall(into)
    return sorted(archive.namelist())


@notebook_pages
def test_page_offers_the_teacher_edition_and_the_student_copy(
    site: Site, name: str, path: Path, tmp_path: Path
) -> None:
    """Each download has a name of its own and works alone: a notebook that reads data/ comes
    as a zip of a folder that holds it and its data."""
    downloads = links_of(site, name).downloads
    downloads.pop("the whole course", None)  # test_page_says_how_to_get_the_whole_course
    committed = path.read_bytes()
    data = REPO / "notebooks" / "data"
    with_data = (
        re.search(
            r"""["'(/]data/""",
            "".join(cell.source for cell in read(path).cells if cell.cell_type == "code"),
        )
        is not None
    )
    editions = {"teacher’s edition": "teacher", "student copy": "student"}
    if not solution_count(read(path)):
        editions = {"this notebook": ""}
    assert set(downloads) == set(editions)
    received = {}
    for label, edition in editions.items():
        file_name, content = fetch(site, name, downloads[label])
        stem = f"{path.stem}-{edition}" if edition else path.stem
        if with_data:
            assert file_name == f"{stem}.zip"
            names = unpack(content, tmp_path / edition)
            folder = tmp_path / edition / path.stem
            expected = sorted(
                f"{path.stem}/data/{file.relative_to(data).as_posix()}"
                for file in data.rglob("*")
                if file.is_file() and "__pycache__" not in file.parts
            )
            assert names == sorted([f"{path.stem}/{stem}.ipynb", *expected])
            content = (folder / f"{stem}.ipynb").read_bytes()
        else:
            assert file_name == f"{stem}.ipynb"
        received[edition] = content
    if "teacher" in received:
        assert received["teacher"] == committed
        student = nbformat.reads(received["student"].decode("utf-8"), as_version=4)
        assert student == student_copy(read(path))
        assert solution_count(student) == 0
    else:
        assert received[""] == committed


def test_a_downloaded_notebook_with_data_runs_alone(site: Site, tmp_path: Path) -> None:
    """The teacher's edition of a notebook that reads data/, unpacked from its zip into an empty
    folder, runs from top to bottom there."""
    from nbclient import NotebookClient

    readers = [
        (page, path)
        for page, path in zip(NOTEBOOK_PAGES, NOTEBOOKS, strict=True)
        if "-teacher.zip" in " ".join(links_of(site, page).downloads.values())
    ]
    assert readers, "no notebook is offered with its data"
    page, path = readers[0]
    _, content = fetch(site, page, links_of(site, page).downloads["teacher’s edition"])
    unpack(content, tmp_path)
    notebook_path = tmp_path / path.stem / f"{path.stem}-teacher.ipynb"
    notebook = nbformat.read(str(notebook_path), as_version=4)
    NotebookClient(
        notebook,
        timeout=300,
        kernel_name="python3",
        resources={"metadata": {"path": str(notebook_path.parent)}},
    ).execute()
    errors = [
        output
        for cell in notebook.cells
        for output in cell.get("outputs", [])
        if output.get("output_type") == "error"
    ]
    assert errors == []


@pytest.mark.parametrize("name", [*NOTEBOOK_PAGES, "teachers.html"])
def test_page_says_how_to_get_the_whole_course(site: Site, name: str, tmp_path: Path) -> None:
    """With no public address for the repository, every notebook page and the teachers' page
    offer the repository's files as one zip, which holds what the README's commands need."""
    links = [target for target in links_of(site, name).targets if target.endswith(".zip")]
    course = [target for target in links if target.endswith("/eulerlib-course.zip")]
    assert course, "no link to the whole course"
    _, content = fetch(site, name, course[0])
    names = set(unpack(content, tmp_path))
    for needed in (
        "README.md",
        "pyproject.toml",
        ".ci/constraints.txt",
        "course/pyproject.toml",
        "eulerlib/__init__.py",
        "notebooks/14_a_real_imu_recording.ipynb",
        "notebooks/data/00033_Quaternion.csv",
    ):
        assert f"eulerlib/{needed}" in names
    assert not any("/build/" in name or "/.venv/" in name for name in names)


def test_landing_page_is_the_readme_course_map(site: Site) -> None:
    landing = (site.folder / "index.html").read_text(encoding="utf-8")
    course = README.split("## The course", 1)[1].split("\n## ", 1)[0]
    for notebook in re.findall(r"\]\(notebooks/([^)#]+)\.ipynb\)", course):
        assert f'href="notebooks/{notebook}.html"' in landing
    for picture in re.findall(r'src="(figures/[^"]+)"', course):
        assert f'src="{picture}"' in landing
    assert jupyterlab_command(README) in page_text(landing)


# --- the live explorables on the built site ------------------------------------------------------

#: What the page of a live explorable says about it: the picture's drawing, its view angles,
#: the numbers and the live summary.
EXPLORABLE_FACTS = """(root) => {
  const svg = root.querySelector("svg");
  return {
    drawing: svg ? svg.innerHTML : "",
    azimuth: svg ? Number(svg.dataset.azimuth) : null,
    matrix: [...root.querySelectorAll(".eulexp-matrix")].map((e) => e.textContent).join("|"),
    recovered: [...root.querySelectorAll(".eulexp-recovered")].map((e) => e.textContent),
    lock: [...root.querySelectorAll(".eulexp-lock")].map((e) => e.dataset.locked),
    summary: (root.querySelector("[aria-live]") || {}).textContent || "",
    sliders: [...root.querySelectorAll("input[type=range]")].map((e) => e.labels.length
      + (e.getAttribute("aria-label") ? 1 : 0)),
    overflow: document.documentElement.scrollWidth > window.innerWidth + 1,
  };
}"""


def explorable_notebooks() -> list[str]:
    """The pages whose notebook stores an explorable."""
    return [
        page
        for page, path in zip(NOTEBOOK_PAGES, NOTEBOOKS, strict=True)
        if any(
            'class="eulerlib-explorable"' in "".join(output.get("data", {}).get("text/html", ""))
            for cell in read(path).cells
            for output in cell.get("outputs", [])
        )
    ]


def test_five_notebooks_show_explorables() -> None:
    names = [Path(page).stem[:2] for page in explorable_notebooks()]
    assert names == ["07", "08", "11", "12", "14"]


@pytest.mark.parametrize("width", [1280, 390], ids=["desktop", "phone"])
def test_explorables_are_live_on_the_site(site: Site, driver: Any, width: int) -> None:
    """Drag the view and operate a control: the picture and the numbers change, computed in the
    page; nothing is asked of another host; the page fits a phone's width (where the browser
    asks for reduced motion, and nothing offers to play)."""
    with tempfile.TemporaryDirectory() as profile:
        context = launch(
            driver,
            profile,
            viewport={"width": width, "height": 900},
            reduced_motion="reduce" if width < 500 else "no-preference",
        )
        for name in explorable_notebooks():
            visit = Visit()
            page = context.new_page()
            watch(page, visit)
            page.goto(site.url + name, wait_until="load")
            live = page.locator(".eulerlib-explorable-live").first
            live.locator("svg").first.wait_for()
            live.locator("svg").first.scroll_into_view_if_needed()
            before = live.evaluate(EXPLORABLE_FACTS)
            assert all(count >= 1 for count in before["sliders"]), "a slider without a label"
            assert before["summary"] and before["matrix"]
            # drag the view
            box = live.locator("svg").first.bounding_box()
            assert box is not None
            x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
            page.mouse.move(x, y)
            page.mouse.down()
            page.mouse.move(x + 60, y + 20, steps=5)
            page.mouse.up()
            dragged = live.evaluate(EXPLORABLE_FACTS)
            assert dragged["azimuth"] != before["azimuth"]
            assert dragged["drawing"] != before["drawing"]
            assert dragged["matrix"] == before["matrix"]  # turning the view turns no body
            # operate a control from the keyboard: the first slider, five steps of 1°
            slider = live.locator("input[type=range]").first
            slider.focus()
            for _ in range(5):
                page.keyboard.press("ArrowRight")
            after = live.evaluate(EXPLORABLE_FACTS)
            assert after["drawing"] != dragged["drawing"]
            assert after["summary"] != before["summary"]
            assert (after["matrix"], after["recovered"]) != (before["matrix"], before["recovered"])
            assert not after["overflow"], "wider than the window"
            # a recording or a path plays only on request, and not at all with reduced motion
            steps = live.get_by_role("button", name="step on ▶").count()
            plays = live.get_by_role("button", name="play").count()
            assert plays == (steps if width >= 500 else 0)
            if plays:
                moment = live.locator("input[type=range]").first
                start = moment.input_value()
                live.get_by_role("button", name="play").click()
                page.wait_for_function(
                    "([e, v]) => e.value !== v", arg=[moment.element_handle(), start]
                )
            page.close()
            assert visit.refused == [], name
            assert visit.failed == [], name
            assert visit.console_errors == [], name
        context.close()


def test_the_gimbal_locks_on_the_page_of_notebook_07(site: Site, driver: Any) -> None:
    """Raise the pitch of notebook 07's explorable from 85° to 90°: the page says LOCKED and
    reads back yaw 0, as eulerlib does."""
    with tempfile.TemporaryDirectory() as profile:
        context = launch(driver, profile)
        page = context.new_page()
        page.goto(site.url + explorable_notebooks()[0], wait_until="load")
        live = page.locator(".eulerlib-explorable-live").first
        pitch = live.locator("input[type=number]").nth(1)
        pitch.fill("90")
        pitch.press("Enter")
        facts = live.evaluate(EXPLORABLE_FACTS)
        assert facts["lock"] == ["true"]
        assert facts["recovered"] == ["read back: yaw 0°, pitch 90°, roll -20°"]
        assert "gimbal lock: only roll - yaw is defined" in facts["summary"]
        context.close()


def test_a_stored_explorable_becomes_live_on_its_page(tmp_path: Path) -> None:
    """Without a browser: the page's cell loads the copied ES module and keeps the picture for
    a browser without JavaScript; no widget view and no note on running it in JupyterLab."""
    from eulerlib_course.explorable import Explorable
    from eulerlib_course.site import EXPLORABLE_MODULES, copy_explorable_modules

    data, _ = Explorable("rose", [30, 85, 10])._repr_mimebundle_()
    output = nbformat.v4.new_output("display_data", data=data)
    notebook = nbformat.v4.new_notebook(
        cells=[nbformat.v4.new_code_cell('Explorable("rose", [30, 85, 10])', outputs=[output])]
    )
    page = prepare_notebook(notebook, teacher="t", student=None, command="c")
    cell = next(cell for cell in page.cells if cell.cell_type == "code")
    shown = cell.outputs[0].data
    assert set(shown) == {"text/html", "text/plain"}
    live = shown["text/html"]
    assert '<div class="eulerlib-explorable-live" data-settings="' in live
    assert f'import {{ mount }} from "../{EXPLORABLE_MODULES}/explorable.js";' in live
    assert '<noscript><div class="eulerlib-explorable"' in live and "base64," in live
    assert not any("run this notebook in" in c.source for c in page.cells)
    copied = copy_explorable_modules(tmp_path)
    assert sorted(path.name for path in copied) == ["explorable.js", "rotations.js"]
    assert all(path.parent == tmp_path / EXPLORABLE_MODULES for path in copied)
