"""What the notebooks say: no number the code could contradict, terms linked to the glossary.

* A number in a markdown cell that looks computed (a decimal with two or more digits after the
  point, scientific notation, a power such as 2⁻⁴⁹ or ×10⁻¹⁵, "… million") must also appear in a
  code line of the same notebook, where it is printed or asserted: then a change to the library
  that changes the number fails strict nbval or the assertion, instead of leaving a stale
  sentence.
* Every link into the glossary points at a term it defines, every notebook links to it, and no
  student-facing text talks about the machinery of the tests.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import nbformat
import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted((REPO / "notebooks").glob("[0-9][0-9]_*.ipynb"))
GLOSSARY = REPO / "notebooks" / "glossary.ipynb"
IDS = [path.name for path in NOTEBOOKS]
notebook_params = pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)

_SUPERSCRIPTS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻", "0123456789-")
#: Numbers that look computed, in the forms prose writes them.
_COMPUTED = re.compile(
    r"\d+\.\d{2,}(?:e[+-]?\d+)?"  # 1.985, 0.998, 3.6e-15
    r"|\d+(?:\.\d+)?e[+-]?\d+"  # 1e-15
    r"|\d+(?:\.\d+)?\s*(?:×|\\times)\s*10\^?\{?[⁻−-]?[\d⁰¹²³⁴⁵⁶⁷⁸⁹]+\}?"  # 1.8 × 10⁻¹⁵
    r"|\d+[⁻][⁰¹²³⁴⁵⁶⁷⁸⁹]+"  # 2⁻⁴⁹
    r"|\d+(?:\.\d+)?\s+(?:million|billion|thousand)"  # 56 million
)
_MACHINERY = re.compile(r"\bnbval\b|NBVAL|notebook tests?\b|\bCI\b|normal form", re.IGNORECASE)


def read(path: Path) -> Any:
    return nbformat.read(str(path), as_version=4)


def spellings(literal: str) -> set[str]:
    """The literal as prose writes it and as code could write it."""
    plain = literal.replace("−", "-")
    forms = {literal, plain}
    power = re.fullmatch(r"(\d+)([⁻][⁰¹²³⁴⁵⁶⁷⁸⁹]+)", literal)
    if power:
        exponent = power.group(2).translate(_SUPERSCRIPTS)
        forms |= {f"{power.group(1)}**{exponent}", f"{power.group(1)}.0**{exponent}"}
    times = re.fullmatch(r"([\d.]+)\s*(?:×|\\times)\s*10\^?\{?([⁻−-]?[\d⁰¹²³⁴⁵⁶⁷⁸⁹]+)\}?", literal)
    if times:
        exponent = times.group(2).translate(_SUPERSCRIPTS).replace("−", "-")
        forms.add(f"{times.group(1)}e{exponent}")
    return forms


def code_lines(notebook: Any) -> list[str]:
    return [
        line
        for cell in notebook.cells
        if cell.cell_type == "code"
        for line in cell.source.splitlines()
        if line.strip() and not line.lstrip().startswith("#")
    ]


@notebook_params
def test_numbers_in_prose_are_printed_or_asserted_by_code(path: Path) -> None:
    notebook = read(path)
    lines = code_lines(notebook)
    stale = []
    for index, cell in enumerate(notebook.cells):
        if cell.cell_type != "markdown":
            continue
        for literal in _COMPUTED.findall(cell.source):
            if not any(form in line for form in spellings(literal) for line in lines):
                stale.append(f"cell {index}: {literal!r}")
    assert not stale, f"{path.name}: numbers in prose that no code line prints or asserts: {stale}"


#: An explicit anchor in a glossary heading, for a term whose spelling JupyterLab would not turn
#: into the anchor the notebooks link to (``### <span id="ned"></span>NED``).
_EXPLICIT_ANCHOR = re.compile(r'<span id="([^"]+)"></span>')


def glossary_headings() -> list[str]:
    return [
        heading.strip()
        for cell in read(GLOSSARY).cells
        for heading in re.findall(r"^#{3} (.+)$", cell.source, flags=re.MULTILINE)
    ]


def heading_anchor(heading: str) -> str:
    explicit = _EXPLICIT_ANCHOR.search(heading)
    return explicit.group(1) if explicit else heading.replace(" ", "-")


def glossary_anchors() -> set[str]:
    return {heading_anchor(heading) for heading in glossary_headings()}


@notebook_params
def test_glossary_links_point_at_defined_terms(path: Path) -> None:
    anchors = glossary_anchors()
    links = [
        anchor
        for cell in read(path).cells
        if cell.cell_type == "markdown"
        for anchor in re.findall(r"\]\(glossary\.ipynb#([^)]+)\)", cell.source)
    ]
    assert links, f"{path.name} never links to the glossary"
    missing = sorted(set(links) - anchors)
    assert not missing, f"{path.name} links to terms the glossary lacks: {missing}"


def test_glossary_anchors_are_the_same_in_jupyterlab_and_on_the_website() -> None:
    """A term is spelt as it is written (NED, Rodrigues' formula) and linked by one anchor in both.

    The website (MyST) makes a heading's anchor from its text in lower case, spaces as hyphens,
    punctuation dropped; JupyterLab takes the text as it is, spaces as hyphens, or finds the
    explicit anchor in the heading.
    """
    for heading in glossary_headings():
        text = _EXPLICIT_ANCHOR.sub("", heading).strip()
        anchor = heading_anchor(heading)
        assert re.fullmatch(r"[a-z0-9]+(?:-[a-z0-9]+)*", anchor), heading
        website = re.sub(r"[^\w\- ]", "", text.lower()).replace(" ", "-")
        assert website == anchor, heading
        jupyterlab = text.replace(" ", "-")
        assert jupyterlab == anchor or _EXPLICIT_ANCHOR.search(heading), heading


def heading_anchors(path: Path) -> set[str]:
    """The anchors a notebook's headings offer on the website and in JupyterLab alike: an
    explicit ``<span id="...">`` in a heading, or a heading of words only, whose website anchor
    (lower case, spaces as hyphens) JupyterLab's (the text as it is) equals."""
    anchors = set()
    for cell in read(path).cells:
        if cell.cell_type != "markdown":
            continue
        for heading in re.findall(r"^#{1,6} (.+)$", cell.source, re.MULTILINE):
            explicit = _EXPLICIT_ANCHOR.search(heading)
            if explicit:
                anchors.add(explicit.group(1))
            elif re.fullmatch(r"[a-z0-9]+(?: [a-z0-9]+)*", heading.strip()):
                anchors.add(heading.strip().replace(" ", "-"))
    return anchors


def test_the_section_on_naming_frames_has_its_anchor() -> None:
    """01 introduces the frame notation in a heading that carries the anchor later notebooks link
    to, ``#naming-frames-ar-b``, the same on the website and in JupyterLab: JupyterLab finds the
    explicit anchor, the website (MyST) makes it from the heading's words, leaving out HTML tags
    and mathematics, in lower case, spaces as hyphens, punctuation dropped."""
    notebook = REPO / "notebooks" / "01_rotations_in_the_plane_and_about_one_axis.ipynb"
    headings = [
        heading
        for cell in read(notebook).cells
        if cell.cell_type == "markdown"
        for heading in re.findall(r"^#{2,3} (.+)$", cell.source, re.MULTILINE)
        if '<span id="naming-frames-ar-b"></span>' in heading
    ]
    assert len(headings) == 1 and "Naming frames" in headings[0], headings
    words = re.sub(r"<[^>]*>", "", re.sub(r"\$[^$]*\$", "", headings[0]))
    website = re.sub(r"[^\w\- ]", "", words.lower().replace(" ", "-"))
    assert website == "naming-frames-ar-b", website
    assert "naming-frames-ar-b" in heading_anchors(notebook)


@pytest.mark.parametrize("path", [*NOTEBOOKS, GLOSSARY], ids=[*IDS, GLOSSARY.name])
def test_links_to_the_frame_notation_land_on_its_heading(path: Path) -> None:
    """Every link into notebook 01's sections names an anchor that 01's headings carry."""
    first = REPO / "notebooks" / "01_rotations_in_the_plane_and_about_one_axis.ipynb"
    links = [
        anchor
        for cell in read(path).cells
        if cell.cell_type == "markdown"
        for anchor in re.findall(rf"\]\({re.escape(first.name)}#([^)]+)\)", cell.source)
    ]
    missing = sorted(set(links) - heading_anchors(first))
    assert not missing, f"{path.name} links to sections 01 does not mark: {missing}"


@pytest.mark.parametrize("path", NOTEBOOKS[1:], ids=IDS[1:])
def test_the_first_use_of_the_frame_notation_links_back_to_01(path: Path) -> None:
    """A notebook after 01 that names frames (``${}^{W}R_{B}$``) links, where it first does, to
    01's section on the notation."""
    cells = [cell.source for cell in read(path).cells if cell.cell_type == "markdown"]
    using = [source for source in cells if "{}^{" in source]
    if not using:
        pytest.skip(f"{path.name} does not use the frame notation")
    assert "01_rotations_in_the_plane_and_about_one_axis.ipynb#naming-frames-ar-b" in using[0], (
        f"{path.name}: the first cell that names frames does not link to 01's section"
    )


def test_glossary_gives_the_range_of_atan2_as_numpy_computes_it() -> None:
    (cell,) = [cell for cell in read(GLOSSARY).cells if cell.source.startswith("### atan2")]
    assert "$[-180°, 180°]$" in cell.source
    assert np.degrees(np.arctan2(0.0, -1.0)) == 180.0
    assert np.degrees(np.arctan2(-0.0, -1.0)) == -180.0


def test_glossary_references_link_to_the_notebooks() -> None:
    names = {path.name for path in NOTEBOOKS}
    for cell in read(GLOSSARY).cells[1:]:
        assert not re.search(r"\[\d\d(?:, \d\d)*\](?!\()", cell.source), cell.source[:40]
        for number, target in re.findall(r"\[(\d\d)\]\(([^)]+)\)", cell.source):
            assert target in names and target.startswith(number), target


@notebook_params
def test_students_do_not_see_the_machinery(path: Path) -> None:
    for index, cell in enumerate(read(path).cells):
        found = _MACHINERY.search(cell.source)
        assert not found, f"{path.name}, cell {index}: {found.group(0)!r}"
