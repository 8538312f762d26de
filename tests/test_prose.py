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


def glossary_anchors() -> set[str]:
    anchors = set()
    for cell in read(GLOSSARY).cells:
        for heading in re.findall(r"^#{2,4} (.+)$", cell.source, flags=re.MULTILINE):
            anchors.add(heading.strip().lower().replace(" ", "-"))
    return anchors


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


def test_glossary_headings_are_plain_lowercase_words() -> None:
    """So that the heading's anchor is the same in JupyterLab and on the website."""
    for cell in read(GLOSSARY).cells:
        for heading in re.findall(r"^#{3} (.+)$", cell.source, flags=re.MULTILINE):
            assert re.fullmatch(r"[a-z0-9]+(?: [a-z0-9]+)*", heading), heading


@notebook_params
def test_students_do_not_see_the_machinery(path: Path) -> None:
    for index, cell in enumerate(read(path).cells):
        found = _MACHINERY.search(cell.source)
        assert not found, f"{path.name}, cell {index}: {found.group(0)!r}"
