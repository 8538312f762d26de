"""The course as a static website, built from the stored notebooks, that works offline.

The website is a Jupyter Book 1 (Sphinx) build of the committed notebooks. It executes nothing:
every page shows the stored outputs, which are exactly what strict nbval compares. The book's
configuration and the landing page's source live in the repository's ``site/`` folder; the
landing page includes the README's course map at build time, so the README stays its one
source.

:func:`build_site` works in a temporary staging folder and writes only the finished site:

* it copies ``site/``, the README, the notebooks and the pictures the README shows there;
* it writes the table of contents from ``notebooks/*.ipynb``: the numbered notebooks in
  their order, then the others (the glossary), so whatever notebooks the course has become
  its pages (:func:`table_of_contents`);
* it prepares every notebook for reading on the web (:func:`prepare_notebook`): a box under
  the title offers the notebook for download, as the teacher's edition (the committed file)
  and as a student copy (:mod:`eulerlib_course.student`), and shows the README's command that
  opens the course in JupyterLab; worked solutions are folded behind a "Show the worked
  solution" button; an explorable (:mod:`eulerlib_course.explorable`) becomes live, computed
  in the page by its JavaScript port, with its stored picture for a browser without
  JavaScript (:func:`live_explorables`); another widget shows the picture stored next to it,
  with a sentence on running it live, and the widgets' saved state is dropped so that no
  widget JavaScript is fetched; an animation's player takes its icons from the theme's own
  Font Awesome instead of a CDN;
* it copies the explorables' ES modules into the site (:func:`copy_explorable_modules`);
* it runs Sphinx, with MathJax 3 copied into the site from the ``sphinx-mathjax-offline``
  package, and copies the HTML into the output folder, replacing a site built there before.

Nothing on the pages asks for a file from another host; ``tests/test_site.py`` opens every
page in a headless Chromium to check it. This module needs the ``site`` extra (Jupyter Book 1,
MathJax) besides the ``notebooks`` extra's notebook tools; the command line is
``eulerlib-course site build [--out DIR]`` (:mod:`eulerlib_course.commands`).
"""

from __future__ import annotations

import base64
import contextlib
import copy
import hashlib
import html as html_text
import io
import json
import re
import shutil
import subprocess
import tempfile
import time
import zipfile
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import nbformat

from eulerlib_course.notebook_form import read_notebook, write_notebook
from eulerlib_course.student import SOLUTION_TAG, student_copy

__all__ = [
    "SiteBuild",
    "build_site",
    "copy_explorable_modules",
    "course_pages",
    "figure_alts",
    "jupyterlab_command",
    "live_explorables",
    "prepare_notebook",
    "table_of_contents",
]

#: The folder of the book's configuration and landing page, relative to the repository.
SITE_FOLDER = Path("site")
#: Where ``eulerlib-course site build`` writes the site unless told otherwise (git-ignored).
DEFAULT_OUT = Path("build") / "site"
#: The zip of the repository's files that every page offers, in the site's ``downloads/``.
COURSE_ZIP = "eulerlib-course.zip"
#: The teachers' page, beside the landing page (``site/teachers.md``).
TEACHERS_PAGE = "teachers"

#: Extensions of Jupyter Book's default set that the site does without (see :func:`build_site`).
_LEFT_OUT_EXTENSIONS = frozenset({"sphinx_thebe"})
_ANSI_COLOUR = re.compile(r"\x1b\[[0-9;]*m")
_WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"
_PICTURES = frozenset({"image/png", "image/svg+xml", "image/jpeg"})
_FOLDED_TAG = "hide-input"
#: A stylesheet link to Font Awesome on another host (what matplotlib's ``to_jshtml`` writes).
_REMOTE_FONT_AWESOME = re.compile(
    r"<link\b[^>]*\bhref=[\"']https?://[^\"']*font-?awesome[^\"']*[\"'][^>]*>\s*", re.IGNORECASE
)
#: Where the landing page cuts the README: ``:start-after: "..."`` or ``:end-before: "..."``.
_INCLUDE_MARKER = re.compile(r"""^:(?:start-after|end-before):\s*"([^"]+)"\s*$""", re.MULTILINE)
#: A file the README shows on the landing page: ``src="figures/..."``.
_README_PICTURE = re.compile(r"""\bsrc=["'](figures/[^"']+)["']""")
#: An image of a page, by the file myst-nb wrote for it (named by the SHA-256 of its bytes).
_PAGE_IMAGE = re.compile(r"""<img alt="[^"]*" src="((?:\.\./)*_images/([0-9a-f]{64})\.\w+)" """)
#: The folding button myst-nb writes, named "Toggle hidden content" whatever it shows; its
#: visible text ("Show the worked solution") is its name (WCAG 2.5.3, label in name).
_TOGGLE_LABEL = '<summary aria-label="Toggle hidden content">'
#: A code cell that opens a file of the notebooks' ``data/`` folder.
_READS_DATA = re.compile(r"""["'(/]data/""")
#: What a copy of the course leaves out when it is not a git checkout.
_NOT_COURSE = frozenset({"build", "__pycache__", ".ipynb_checkpoints", ".venv", ".git"})

_RUN_IT_YOURSELF = """\
:::{{admonition}} Run this notebook yourself
:class: tip
{downloads} The notebooks use the repository's `eulerlib`: from the top folder of a copy of the
repository ({copy}), this command installs it and opens the course in JupyterLab.

```bash
{command}
```
:::
"""
_BOTH_EDITIONS = (
    "Download the [teacher's edition](path:{teacher}) (worked solutions and outputs included) "
    "or the [student copy](path:{student}) (exercises to fill in)."
)
_ONE_EDITION = "Download [this notebook](path:{teacher})."
_WITH_DATA = (
    " This notebook reads the files of `data/`: each download is a zip of a folder that holds the "
    "notebook and its `data/` folder; unpack it and open the notebook where it is."
)
_WHOLE_COURSE = "download [the whole course](path:{course}) as a zip of the repository's files"
_CLONE = ", or clone [the repository]({url})"
_WIDGET_NOTE = (
    "*A picture of the controls in their first state: to move them, run this notebook in "
    "JupyterLab, as the box at the top of the page says.*"
)


@dataclass(frozen=True)
class SiteBuild:
    """What :func:`build_site` made.

    Attributes
    ----------
    out : Path
        The folder of the site; ``index.html`` is its landing page.
    pages : tuple of str
        The notebook pages in reading order, as paths of the HTML files relative to ``out``.
    warnings : tuple of str
        The warnings Sphinx reported, one per entry (none for a clean build).
    seconds : float
        How long the build took.
    """

    out: Path
    pages: tuple[str, ...]
    warnings: tuple[str, ...]
    seconds: float


def jupyterlab_command(readme: str) -> str:
    """The README's one-line command that installs the course and opens it in JupyterLab.

    Raises
    ------
    ValueError
        If no line of a ``bash`` block of the README copies the course and opens it in
        JupyterLab.

    Examples
    --------
    >>> jupyterlab_command("```bash\\nx && notebooks copy --out c/ && jupyter lab c/\\n```")
    'x && notebooks copy --out c/ && jupyter lab c/'
    """
    for block in re.findall(r"```bash\n(.*?)```", readme, flags=re.DOTALL):
        for line in block.splitlines():
            if "notebooks copy --out" in line and "jupyter lab " in line:
                return str(line).strip()
    raise ValueError("the README shows no command that opens a copy of the course in JupyterLab")


def course_pages(notebook_folder: Path) -> list[Path]:
    """The notebooks of the course in reading order: numbered ones first, then the others."""
    notebooks = sorted(notebook_folder.glob("*.ipynb"))
    numbered = [path for path in notebooks if re.match(r"\d+_", path.name)]
    return numbered + [path for path in notebooks if path not in numbered]


def table_of_contents(pages: list[str], teachers: str | None = None) -> dict[str, Any]:
    """The book's table of contents (``_toc.yml``) for notebook pages given in reading order.

    Numbered notebooks (``notebooks/01_...``) form the part "The course", the others (the
    glossary) the part "Reference"; the landing page ``index`` is the root, and the teachers'
    page, when given, is the part "For teachers".

    Examples
    --------
    >>> toc = table_of_contents(["notebooks/01_a", "notebooks/glossary"])
    >>> [part["caption"] for part in toc["parts"]], toc["parts"][1]["chapters"]
    (['The course', 'Reference'], [{'file': 'notebooks/glossary'}])
    """
    numbered = [page for page in pages if re.match(r"\d+_", Path(page).name)]
    others = [page for page in pages if page not in numbered]
    parts = [("The course", numbered), ("Reference", others)]
    if teachers is not None:
        parts.append(("For teachers", [teachers]))
    return {
        "format": "jb-book",
        "root": "index",
        "parts": [
            {"caption": caption, "chapters": [{"file": page} for page in chapter]}
            for caption, chapter in parts
            if chapter
        ],
    }


def prepare_notebook(
    notebook: Any,
    *,
    teacher: str,
    student: str | None,
    command: str,
    name: str = "notebook",
    course: str = "../downloads/eulerlib-course.zip",
    repository: str = "",
    with_data: bool = False,
) -> Any:
    """A copy of a course notebook made ready for its page on the website.

    Parameters
    ----------
    notebook : nbformat.NotebookNode
        The teacher's edition, as committed; it is left unchanged.
    teacher, student : str
        Paths of the two downloads relative to the notebook's page; ``student`` is None for a
        notebook without worked solutions (the glossary), which is offered once.
    command : str
        The command that opens the course in JupyterLab (:func:`jupyterlab_command`).
    name : str, optional
        The notebook's file name, for error messages.
    course : str, optional
        Path of the zip of the whole course relative to the notebook's page.
    repository : str, optional
        The repository's address (``repository: url:`` in ``site/_config.yml``), or empty.
    with_data : bool, optional
        Whether the downloads are zips that carry the notebook's ``data/`` folder.

    Returns
    -------
    nbformat.NotebookNode
        The page's notebook: the "Run this notebook yourself" box after the title cell, worked
        solutions folded, widgets replaced by their stored pictures (each followed by a note
        on running it live) and no widget state, no Font Awesome from another host.

    Raises
    ------
    ValueError
        If a widget is stored without a picture to show in its place.
    """
    page = copy.deepcopy(notebook)
    page.metadata.pop("widgets", None)
    cells = []
    for index, cell in enumerate(page.cells):
        cells.append(cell)
        if cell.cell_type != "code":
            continue
        tags = cell.metadata.setdefault("tags", [])
        if SOLUTION_TAG in tags:
            if _FOLDED_TAG not in tags:
                tags.append(_FOLDED_TAG)
            cell.metadata["mystnb"] = {
                "code_prompt_show": "Show the worked solution",
                "code_prompt_hide": "Hide the worked solution",
            }
        live_explorables(cell)
        if _replace_widgets(cell, f"{name}, cell {index}"):
            cells.append(nbformat.v4.new_markdown_cell(_WIDGET_NOTE))
    downloads = (
        _BOTH_EDITIONS.format(teacher=teacher, student=student)
        if student is not None
        else _ONE_EDITION.format(teacher=teacher)
    )
    if with_data:
        downloads += _WITH_DATA
    where = _WHOLE_COURSE.format(course=course) + (
        _CLONE.format(url=repository) if repository else ""
    )
    box = nbformat.v4.new_markdown_cell(
        _RUN_IT_YOURSELF.format(downloads=downloads, command=command, copy=where)
    )
    title_first = bool(cells) and cells[0].cell_type == "markdown" and cells[0].source[:1] == "#"
    cells.insert(1 if title_first else 0, box)
    page.cells = cells
    for position, cell in enumerate(page.cells):  # unique ids, by position
        cell["id"] = f"cell-{position:03d}"
    return page


def _replace_widgets(cell: Any, where: str) -> bool:
    """Drop widget views (keeping their pictures) and remote Font Awesome from a cell's outputs.

    Returns True when the cell showed a widget.
    """
    widget = False
    for output in cell.get("outputs", []):
        data = output.get("data", {})
        if _WIDGET_VIEW in data:
            if not _PICTURES & set(data):
                raise ValueError(f"{where} shows a widget without a stored picture to show instead")
            del data[_WIDGET_VIEW]
            widget = True
        if "text/html" in data:
            html = data["text/html"]
            text = "".join(html) if isinstance(html, list) else html
            data["text/html"] = _REMOTE_FONT_AWESOME.sub("", text)
    return widget


#: Where the explorables' ES modules are in the site, relative to its top folder.
EXPLORABLE_MODULES = "explorable"
_EXPLORABLE = re.compile(
    r'<div class="eulerlib-explorable" data-settings="(?P<settings>[^"]*)">.*?</div>\s*\Z',
    re.DOTALL,
)
_LIVE_EXPLORABLE = """\
<div class="eulerlib-explorable-live" data-settings="{settings}"></div>
<noscript>{fallback}</noscript>
<script type="module">
import {{ mount }} from "../{modules}/explorable.js";
for (const el of document.querySelectorAll(".eulerlib-explorable-live:not([data-mounted])")) {{
  el.dataset.mounted = "true";
  mount(el, JSON.parse(el.dataset.settings));
}}
</script>
"""


def copy_explorable_modules(extra: Path) -> list[Path]:
    """Copy the explorables' ES modules into ``extra``/explorable/ (the site's top folder).

    Returns the files copied. The modules are part of the course package; nothing is fetched.
    """
    from eulerlib_course.explorable import MODULE_FILES, MODULE_FOLDER

    target = extra / EXPLORABLE_MODULES
    target.mkdir(parents=True, exist_ok=True)
    copied = []
    for name in MODULE_FILES:
        shutil.copyfile(MODULE_FOLDER / name, target / name)
        copied.append(target / name)
    return copied


def live_explorables(cell: Any) -> int:
    """Turn each stored explorable of a cell's outputs into a live one; return how many.

    An explorable's stored output (:class:`eulerlib_course.explorable.Explorable`) is a widget
    view and a ``text/html`` picture marked with its settings. On the page the widget view is
    dropped and the picture becomes a ``<div>`` that a ``<script type="module">`` fills with the
    explorable, computed by the port in the page; the picture stays inside ``<noscript>``.

    Examples
    --------
    >>> import nbformat
    >>> stored = '<div class="eulerlib-explorable" data-settings="{}"><img src="p.png"></div>'
    >>> output = nbformat.v4.new_output("display_data", data={"text/html": stored})
    >>> cell = nbformat.v4.new_code_cell("Explorable()", outputs=[output])
    >>> live_explorables(cell), "<noscript><div" in cell.outputs[0].data["text/html"]
    (1, True)
    """
    count = 0
    for output in cell.get("outputs", []):
        data = output.get("data", {})
        page = data.get("text/html")
        text = "".join(page) if isinstance(page, list) else page
        found = _EXPLORABLE.match(text.strip()) if isinstance(text, str) else None
        if found is None:
            continue
        data.pop(_WIDGET_VIEW, None)
        data["text/html"] = _LIVE_EXPLORABLE.format(
            settings=found["settings"], fallback=text.strip(), modules=EXPLORABLE_MODULES
        )
        count += 1
    return count


def landing_page_gaps(landing: str, readme: str) -> list[str]:
    """The places where the landing page cuts the README at a line that no line of it begins with.

    The landing page (``site/index.md``) includes parts of the README between headings it names;
    a heading renamed in the README would otherwise empty that part of the page without a word.

    Examples
    --------
    >>> page = ':start-after: "## The course"\\n:end-before: "## The library"\\n'
    >>> landing_page_gaps(page, "## The course\\n...\\n## The library\\n")
    []
    >>> landing_page_gaps(page, "## The course\\n...\\n## Using the library\\n")
    ["the README has no line '## The library' where the landing page cuts it"]
    """
    return [
        f"the README has no line {marker!r} where the landing page cuts it"
        for marker in _INCLUDE_MARKER.findall(landing)
        if not re.search(rf"^{re.escape(marker)}", readme, flags=re.MULTILINE)
    ]


def repository_url(config: str) -> str:
    """The repository's address from the site's ``_config.yml`` (``repository: url:``), or "".

    Examples
    --------
    >>> repository_url("repository:\\n  url: https://example.org/eulerlib\\n")
    'https://example.org/eulerlib'
    >>> repository_url("title: x\\n")
    ''
    """
    import yaml  # type: ignore[import-untyped]  # PyYAML, a dependency of Jupyter Book

    settings = yaml.safe_load(config) or {}
    url = (settings.get("repository") or {}).get("url") or ""
    return str(url).strip()


def reads_data(notebook: Any) -> bool:
    """Whether a code cell of ``notebook`` opens a file of the ``data/`` folder beside it.

    Examples
    --------
    >>> cell = nbformat.v4.new_code_cell('np.loadtxt("data/x.csv")')
    >>> reads_data(nbformat.v4.new_notebook(cells=[cell]))
    True
    >>> reads_data(nbformat.v4.new_notebook(cells=[nbformat.v4.new_markdown_cell("`data/x`")]))
    False
    """
    return any(
        cell.cell_type == "code" and _READS_DATA.search(cell.source) for cell in notebook.cells
    )


def _notebook_bytes(notebook: Any) -> bytes:
    """The notebook as :func:`write_notebook` stores it."""
    stream = io.StringIO()
    nbformat.write(notebook, stream)
    return stream.getvalue().encode("utf-8")


def _zip_with_data(target: Path, folder: str, name: str, content: bytes, data: Path) -> None:
    """A zip of ``folder/name`` (the notebook) and ``folder/data/...`` (its data files)."""
    with zipfile.ZipFile(target, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        archive.writestr(f"{folder}/{name}", content)
        for path in sorted(data.rglob("*")):
            if path.is_file() and not _NOT_COURSE & set(path.parts):
                archive.write(path, f"{folder}/data/{path.relative_to(data).as_posix()}")


def _course_files(root: Path) -> list[Path]:
    """The repository's files: git's list in a checkout, otherwise every file but builds."""
    try:
        listed = subprocess.run(
            ["git", "ls-files", "-z"], cwd=root, capture_output=True, check=True, timeout=60
        ).stdout.decode("utf-8")
    except (OSError, subprocess.SubprocessError):
        listed = ""
    if listed:
        files = [root / name for name in listed.split("\0") if name]
        return [path for path in files if path.is_file()]
    return [
        path
        for path in sorted(root.rglob("*"))
        if path.is_file()
        and not _NOT_COURSE & set(path.relative_to(root).parts)
        and not any(part.endswith(".egg-info") for part in path.parts)
    ]


def _zip_course(root: Path, target: Path) -> None:
    """A zip of the repository's files in a folder ``eulerlib/``, for readers without git."""
    with zipfile.ZipFile(target, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        for path in _course_files(root):
            archive.write(path, f"eulerlib/{path.relative_to(root).as_posix()}")


def _picture_bytes(mime: str, content: Any) -> bytes:
    """The bytes myst-nb writes for a picture output (and hashes to name the file)."""
    text = "".join(content) if isinstance(content, list) else str(content)
    if mime == "image/svg+xml":
        return "\n".join(text.splitlines()).encode("utf-8")
    return base64.b64decode(text)


def figure_alts(notebook: Any) -> dict[str, str]:
    """The text alternatives of a notebook's figures, by the SHA-256 of each picture's bytes.

    A code cell that shows pictures stores their text alternatives in its metadata ``alt``
    (nbconvert's name for it): a list with one string per picture output, in order, or one
    string for a cell with one picture. A picture without one is left out.

    Examples
    --------
    >>> png = base64.b64encode(b"a picture").decode()
    >>> output = nbformat.v4.new_output("display_data", data={"image/png": png})
    >>> cell = nbformat.v4.new_code_cell("plot()", outputs=[output])
    >>> cell.metadata["alt"] = ["A red line climbs from left to right."]
    >>> list(figure_alts(nbformat.v4.new_notebook(cells=[cell])).values())
    ['A red line climbs from left to right.']
    """
    alts: dict[str, str] = {}
    for cell in notebook.cells:
        given = cell.get("metadata", {}).get("alt")
        if cell.cell_type != "code" or not given:
            continue
        texts = [given] if isinstance(given, str) else list(given)
        pictures = [
            _picture_bytes(mime, output["data"][mime])
            for output in cell.get("outputs", [])
            for mime in sorted(_PICTURES & set(output.get("data", {})))[:1]
        ]
        for picture, text in zip(pictures, texts, strict=False):
            alts[hashlib.sha256(picture).hexdigest()] = str(text)
    return alts


def _finish_pages(folder: Path, alts: dict[str, str]) -> None:
    """Give the built pages' figures their text alternatives, and name the folding buttons."""
    for page in folder.rglob("*.html"):
        source = page.read_text(encoding="utf-8")

        def alt(match: re.Match[str]) -> str:
            text = alts.get(match.group(2))
            if text is None:
                return match.group(0)
            return f'<img alt="{html_text.escape(text)}" src="{match.group(1)}" '

        finished = _PAGE_IMAGE.sub(alt, source).replace(_TOGGLE_LABEL, "<summary>")
        if finished != source:
            page.write_text(finished, encoding="utf-8")


def _stage(root: Path, stage: Path) -> tuple[list[str], list[str], dict[str, str]]:
    """Copy and prepare the book's sources in ``stage``.

    Returns the notebook pages in reading order, warnings about the README's course map, and
    the text alternatives of the notebooks' figures (:func:`figure_alts`).
    """
    site, notebook_folder = root / SITE_FOLDER, root / "notebooks"
    for folder in (site, notebook_folder):
        if not folder.is_dir():
            raise ValueError(
                f"no {folder.name}/ folder in {root.resolve()}: build the site from the top "
                "folder of the repository (the course is not part of the installed package)"
            )
    readme = (root / "README.md").read_text(encoding="utf-8")
    command = jupyterlab_command(readme)
    shutil.copytree(site, stage, dirs_exist_ok=True)
    (stage / "README.md").write_text(readme, encoding="utf-8")
    warnings = [
        f"site/{page.name}: WARNING: {gap}"
        for page in sorted(site.glob("*.md"))
        for gap in landing_page_gaps(page.read_text(encoding="utf-8"), readme)
    ]
    for picture in sorted(set(_README_PICTURE.findall(readme))):
        if not (root / picture).is_file():
            warnings.append(f"README.md: WARNING: the course map shows {picture}, which is missing")
            continue
        target = stage / "_extra" / picture
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(root / picture, target)
    (stage / "_extra").mkdir(exist_ok=True)
    copy_explorable_modules(stage / "_extra")
    downloads = stage / "downloads"
    downloads.mkdir(parents=True, exist_ok=True)
    (stage / "notebooks").mkdir(parents=True, exist_ok=True)
    _zip_course(root, downloads / COURSE_ZIP)
    repository = repository_url((site / "_config.yml").read_text(encoding="utf-8"))
    pages = []
    alts: dict[str, str] = {}
    for path in course_pages(notebook_folder):
        notebook = read_notebook(path)
        alts.update(figure_alts(notebook))
        has_solutions = any(
            SOLUTION_TAG in cell.metadata.get("tags", []) for cell in notebook.cells
        )
        editions = {"teacher": path.read_bytes()}
        if has_solutions:
            editions["student"] = _notebook_bytes(student_copy(notebook))
        with_data = reads_data(notebook) and (notebook_folder / "data").is_dir()
        names = {}
        for edition, content in editions.items():
            stem = f"{path.stem}-{edition}" if has_solutions else path.stem
            if with_data:
                names[edition] = f"{stem}.zip"
                _zip_with_data(
                    downloads / names[edition],
                    path.stem,
                    f"{stem}.ipynb",
                    content,
                    notebook_folder / "data",
                )
            else:
                names[edition] = f"{stem}.ipynb"
                (downloads / names[edition]).write_bytes(content)
        page = prepare_notebook(
            notebook,
            teacher=f"../downloads/{names['teacher']}",
            student=f"../downloads/{names['student']}" if has_solutions else None,
            command=command,
            name=path.name,
            course=f"../downloads/{COURSE_ZIP}",
            repository=repository,
            with_data=with_data,
        )
        write_notebook(page, stage / "notebooks" / path.name)
        pages.append(f"notebooks/{path.stem}")
    teachers = TEACHERS_PAGE if (stage / f"{TEACHERS_PAGE}.md").is_file() else None
    toc = json.dumps(table_of_contents(pages, teachers), indent=2)  # JSON is YAML
    (stage / "_toc.yml").write_text(toc + "\n", encoding="utf-8")
    return pages, warnings, alts


def build_site(root: str | Path = ".", out: str | Path | None = None) -> SiteBuild:
    """Build the course website from the repository at ``root`` into ``out``.

    Parameters
    ----------
    root : str or Path, optional
        The top folder of the repository (``site/``, ``notebooks/``, ``figures/``, README).
    out : str or Path, optional
        The folder for the site, ``build/site`` of ``root`` by default. A site built before is
        replaced; any other folder that is not empty is refused.

    Returns
    -------
    SiteBuild
        The output folder, the notebook pages, Sphinx's warnings and the time taken.

    Raises
    ------
    ValueError
        If ``root`` is not the repository, ``out`` holds something else than a site, a widget
        has no stored picture, or Sphinx fails.
    """
    start = time.perf_counter()
    root = Path(root)
    out = Path(out) if out is not None else root / DEFAULT_OUT
    if out.exists() and not out.is_dir():
        raise ValueError(f"{out} is a file, not a folder for the site")
    if out.is_dir() and any(out.iterdir()) and not (out / ".buildinfo").is_file():
        raise ValueError(f"{out} is not empty and holds no site built before; choose another --out")

    from jupyter_book.config import get_final_config
    from jupyter_book.sphinx import build_sphinx

    with tempfile.TemporaryDirectory(prefix="eulerlib-site-") as temporary:
        stage, html = Path(temporary) / "book", Path(temporary) / "html"
        pages, readme_warnings, alts = _stage(root, stage)
        config = stage / "_config.yml"
        overrides: dict[str, Any] = {
            "external_toc_path": (stage / "_toc.yml").as_posix(),
            "latex_individualpages": False,
        }
        # Jupyter Book always loads sphinx-thebe, whose script (declared twice on every page,
        # an error in the console) would fetch thebe from a CDN when clicked; the site has no
        # live cells, so the extension is left out.
        sphinx_config, _ = get_final_config(
            user_yaml=config, cli_config=dict(overrides), sourcedir=stage
        )
        overrides["extensions"] = [
            name for name in sphinx_config["extensions"] if name not in _LEFT_OUT_EXTENSIONS
        ]
        if repository_url(config.read_text(encoding="utf-8")):
            overrides["html_theme_options"] = {
                **sphinx_config.get("html_theme_options", {}),
                "use_repository_button": True,
            }
        log = io.StringIO()
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(log):
            result = build_sphinx(
                stage,
                html,
                noconfig=True,
                path_config=str(config),
                confoverrides=overrides,
                doctreedir=Path(temporary) / "doctrees",
                freshenv=True,
            )
        if result != 0:
            raise ValueError(f"the site did not build: {log.getvalue().strip() or result}")
        _finish_pages(html, alts)
        if out.exists():
            shutil.rmtree(out)
        out.parent.mkdir(parents=True, exist_ok=True)
        shutil.copytree(html, out)
    messages = _ANSI_COLOUR.sub("", log.getvalue()).replace(f"{stage}/", "")
    warnings = tuple(readme_warnings) + tuple(
        line.strip() for line in messages.splitlines() if "WARNING" in line or "ERROR" in line
    )
    return SiteBuild(
        out=out,
        pages=tuple(f"{page}.html" for page in pages),
        warnings=warnings,
        seconds=time.perf_counter() - start,
    )
