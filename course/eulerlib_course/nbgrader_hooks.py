"""What the nbgrader edition's ``nbgrader_config.py`` plugs into nbgrader.

Two things, each fixing something a teacher would otherwise meet on every run:

* :class:`OverwriteCellsKnowingHiddenTests`, in place of nbgrader's ``OverwriteCells`` when
  ``autograde`` sanitizes a submission. nbgrader stores a test cell's checksum *with* its hidden
  tests (``generate_assignment`` computes it before it removes them), then compares it with the
  submitted cell, which never had them: every hidden test would be reported as "checksum has
  changed" although nobody changed anything (nbgrader issue 1961). This class puts the hidden
  tests back first when the submitted cell is exactly the released one, so only a cell that a
  student really changed is reported (and restored, as nbgrader does).
* The feedback pages' MathJax: nbgrader's feedback template loads MathJax 2 from a CDN, so
  offline a student reads raw ``$R$``. The configuration adds :data:`TEMPLATES` to nbconvert's
  template folders, where ``feedback/mathjax.html.j2`` takes the place of nbconvert's macro and
  writes MathJax 3 into the page itself (:func:`mathjax_script`, from the
  ``sphinx-mathjax-offline`` package, which the ``teach`` extra installs): a feedback page
  typesets its mathematics wherever it is opened, with no network, after ``release_feedback``
  too. The formgrader's view of a submission is the same kind of page (nbgrader's ``formgrade``
  template, rendered by the formgrader with the ``HTMLExporter`` settings of the course folder's
  ``nbgrader_config.py``, which it reads after its own), so ``formgrade/mathjax.html.j2`` does
  the same there and also answers the one MathJax 2 call of the formgrader's script.

This module needs nbgrader (the ``teach`` extra).
"""

from __future__ import annotations

import copy
from importlib import metadata
from pathlib import Path
from typing import Any

from nbgrader import utils
from nbgrader.api import MissingEntry
from nbgrader.preprocessors import ClearHiddenTests, OverwriteCells

__all__ = [
    "TEMPLATES",
    "OverwriteCellsKnowingHiddenTests",
    "feedback_template_dirs",
    "mathjax_script",
    "sanitize_preprocessors",
]

#: nbconvert template folders of the edition (``feedback/`` and ``formgrade/mathjax.html.j2``).
TEMPLATES = Path(__file__).resolve().parent / "nbgrader_templates"

_MATHJAX_PACKAGE = "sphinx-mathjax-offline"
_MATHJAX_FILES = "sphinx-mathjax-offline/static/mathjax"


def mathjax_script(name: str) -> str:
    """The text of MathJax 3's component ``name`` (``"tex-svg.js"``), to write into a page.

    The SVG output needs no font files, so the one script is all a page needs. ``</script`` is
    written ``<\\/script`` so that the text can stand inside a ``<script>`` element.

    Raises
    ------
    FileNotFoundError
        If the ``sphinx-mathjax-offline`` package is not installed or has no such file.
    """
    try:
        distribution = metadata.distribution(_MATHJAX_PACKAGE)
    except metadata.PackageNotFoundError:
        raise FileNotFoundError(
            f"MathJax for the feedback pages comes from the {_MATHJAX_PACKAGE} package "
            '(the teach extra of eulerlib-course): pip install -e "./course[teach]"'
        ) from None
    path = Path(str(distribution.locate_file(f"{_MATHJAX_FILES}/{name}")))
    return path.read_text(encoding="utf-8").replace("</script", "<\\/script")


class OverwriteCellsKnowingHiddenTests(OverwriteCells):  # type: ignore[misc]
    """nbgrader's ``OverwriteCells``, without the false "checksum has changed" of hidden tests.

    A locked grade cell whose submitted source is the released one (the source cell of the
    gradebook with its hidden tests removed, by nbgrader's own ``ClearHiddenTests``) gets the
    source cell's text back before nbgrader checks it; any other difference is reported and
    undone by nbgrader as before.
    """

    def preprocess_cell(self, cell: Any, resources: Any, cell_index: int) -> tuple[Any, Any]:
        grade_id = cell.metadata.get("nbgrader", {}).get("grade_id")
        if grade_id is not None and utils.is_grade(cell) and utils.is_locked(cell):
            try:
                source = self.gradebook.find_source_cell(
                    grade_id, self.notebook_id, self.assignment_id
                )
            except MissingEntry:
                source = None  # nbgrader's own method says so
            if source is not None and source.locked:
                released = copy.deepcopy(cell)
                released.source = source.source
                ClearHiddenTests(parent=self).preprocess_cell(released, {}, cell_index)
                if released.source == cell.source:
                    cell.source = source.source
        return super().preprocess_cell(cell, resources, cell_index)  # type: ignore[no-any-return]


def sanitize_preprocessors() -> list[Any]:
    """nbgrader's ``Autograde.sanitize_preprocessors``, with ``OverwriteCells`` replaced by
    :class:`OverwriteCellsKnowingHiddenTests`."""
    from nbgrader.converters import Autograde

    default = Autograde.class_traits()["sanitize_preprocessors"].default()
    return [OverwriteCellsKnowingHiddenTests if p is OverwriteCells else p for p in default]


def feedback_template_dirs() -> list[str]:
    """nbconvert's ``extra_template_basedirs`` for the feedback pages and the formgrader's view of
    a submission: :data:`TEMPLATES` first, then nbgrader's own templates (which nbgrader adds
    itself only when none are configured)."""
    import nbgrader

    nbgrader_templates = (
        Path(nbgrader.__file__)
        .resolve()
        .parent.joinpath("server_extensions", "formgrader", "templates")
    )
    return [str(TEMPLATES), str(nbgrader_templates)]
