"""The course's commands: ``eulerlib-course notebooks student|nbgrader|copy|refresh``,
``eulerlib-course figures`` and ``eulerlib-course site build``.

* ``eulerlib-course notebooks student --out DIR [--src DIR] [--force]`` (for teachers) writes a
  student copy of every course notebook into ``DIR`` (:mod:`eulerlib_course.student`). It does
  not overwrite existing copies unless ``--force`` is given.
* ``eulerlib-course notebooks nbgrader --out DIR [--src DIR] [--force]`` (for teachers who
  grade with nbgrader) writes the course as an nbgrader course folder:
  ``DIR/nbgrader_config.py`` and one assignment per notebook under ``DIR/source/``
  (:mod:`eulerlib_course.nbgrader_edition`). It needs the ``teach`` extra (nbgrader) and does
  not overwrite an earlier edition unless ``--force`` is given.
* ``eulerlib-course notebooks copy --out DIR [--src DIR]`` (for learners) copies the course into
  a working folder to open in JupyterLab (:mod:`eulerlib_course.working_copy`), keeping every
  file already there.
* ``eulerlib-course notebooks refresh [NOTEBOOK ...]`` (for maintainers) re-executes notebooks
  and stores them in normal form (:mod:`eulerlib_course.notebook_form`); all of ``notebooks/`` by
  default.
* ``eulerlib-course figures [--out DIR] [--force]`` (for maintainers) redraws every figure of
  the course (:mod:`eulerlib_course.figures`) into ``figures/`` by default, replacing pictures
  already there only with ``--force``.
* ``eulerlib-course site build [--out DIR]`` (for teachers and maintainers) builds the course
  website from the stored notebooks (:mod:`eulerlib_course.site`) into ``build/site/`` by default.

The course itself (``notebooks/``, ``figures/``) lives in the repository, not in the installed
package: without ``--src`` or ``--out`` the commands work on those folders of the current
directory, and say so when they are not there. The notebook tools (nbformat, nbclient,
nbconvert), matplotlib and Jupyter Book are imported only when a command runs; when they are
missing, the command ends with one line naming what to install (:mod:`eulerlib_course._extras`).
Like every subcommand of :mod:`eulerlib_course.cli`, these end with one line on standard error
and a non-zero exit status when something is wrong, never with a traceback.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from eulerlib_course._extras import require

__all__ = [
    "configure_figures",
    "configure_notebooks",
    "configure_site",
    "run_figures",
    "run_notebooks",
    "run_site",
]

#: The course's folders, relative to the top folder of the repository.
NOTEBOOK_FOLDER = Path("notebooks")
FIGURE_FOLDER = Path("figures")
#: The notebook tools (dependencies of the course package) that ``eulerlib-course notebooks``
#: imports.
NOTEBOOK_TOOLS = ("nbformat", "nbclient", "nbconvert")
#: The packages of the ``site`` extra that ``eulerlib-course site build`` imports (the MathJax
#: package's name is its import name).
SITE_TOOLS = ("jupyter_book", "sphinx-mathjax-offline", "nbformat", "nbconvert")
#: What ``eulerlib-course notebooks nbgrader`` needs: the notebook tools, and nbgrader to use
#: the edition.
GRADING_TOOLS = ("nbformat", "nbconvert", "nbgrader")


def output_folder(text: str) -> Path:
    """The ``--out`` of every course command: a folder, or a name for one still to be made.

    An empty name is refused (it would mean the current folder), and so is an existing file.
    What is already in the folder is the command's own business: none of them replaces a file
    there unless ``--force`` is given.
    """
    if not text.strip():
        raise argparse.ArgumentTypeError("is empty: name a folder")
    folder = Path(text)
    if folder.exists() and not folder.is_dir():
        raise argparse.ArgumentTypeError(f"{text} is a file, not a folder")
    return folder


def configure_notebooks(parser: argparse.ArgumentParser) -> None:
    """Add the ``student`` and ``refresh`` actions to the ``notebooks`` sub-parser."""
    actions = parser.add_subparsers(dest="action", metavar="ACTION", required=True)
    student = actions.add_parser(
        "student",
        help="write student copies: worked solutions and outputs removed",
        description="Write a student copy of every course notebook, without the worked "
        "solutions and outputs.",
    )
    student.add_argument(
        "--out", type=output_folder, required=True, help="folder for the student copies"
    )
    student.add_argument(
        "--src", type=Path, help="folder of the course notebooks (default: notebooks/)"
    )
    student.add_argument(
        "--student",
        metavar="NAME",
        help="make the copies for this student: their own data in every exercise that has some",
    )
    student.add_argument(
        "--force", action="store_true", help="overwrite student copies already in --out"
    )
    grading = actions.add_parser(
        "nbgrader",
        help="write the course as an nbgrader course folder, one assignment per notebook",
        description="Write the course as an nbgrader course folder: nbgrader_config.py and one "
        "assignment per notebook under source/, each exercise an autograded answer with a hidden "
        "test that asks the course's answer key.",
    )
    grading.add_argument(
        "--out", type=output_folder, required=True, help="the nbgrader course folder to write into"
    )
    grading.add_argument(
        "--src", type=Path, help="folder of the course notebooks (default: notebooks/)"
    )
    grading.add_argument(
        "--force", action="store_true", help="overwrite the files of an earlier edition in --out"
    )
    grading.add_argument(
        "--graded",
        action="store_true",
        help="graded mode: the visible checks check the form only, the hidden tests carry the "
        "answer key (the students' environment runs `eulerlib-course key remove`)",
    )
    refresh = actions.add_parser(
        "refresh",
        help="re-execute notebooks in place and store them in normal form",
        description="Re-execute notebooks in place and store them in normal form (the stored "
        "outputs that CI compares).",
    )
    refresh.add_argument(
        "notebooks", nargs="*", type=Path, help="notebooks to refresh (default: notebooks/*.ipynb)"
    )
    working = actions.add_parser(
        "copy",
        help="make a working copy of the course to open in JupyterLab, keeping your work",
        description="Copy the course notebooks, the glossary and data/ into a working folder, to "
        "open in JupyterLab instead of the committed notebooks. Files already in the folder "
        "(your work) are kept; only missing ones are copied.",
    )
    working.add_argument(
        "--out", type=output_folder, required=True, help="the working copy's folder"
    )
    working.add_argument(
        "--src", type=Path, help="folder of the course notebooks (default: notebooks/)"
    )
    parser.set_defaults(run=run_notebooks)


def configure_figures(parser: argparse.ArgumentParser) -> None:
    """Add ``--out`` to the ``figures`` sub-parser."""
    parser.add_argument(
        "--out", type=output_folder, help="folder for the figures (default: figures/)"
    )
    parser.add_argument(
        "--force", action="store_true", help="replace pictures of the same names already there"
    )
    parser.set_defaults(run=run_figures)


def _course_folder(folder: Path, instead: str) -> Path:
    """``folder`` of the current directory, or a one-line error saying what to do instead."""
    if not folder.is_dir():
        raise ValueError(
            f"no {folder}/ folder here: run from the top folder of the repository "
            f"(the course is not part of the installed package), or {instead}"
        )
    return folder


def configure_key(parser: argparse.ArgumentParser) -> None:
    """Add the ``remove`` action to the ``key`` sub-parser."""
    actions = parser.add_subparsers(dest="action", metavar="ACTION", required=True)
    remove = actions.add_parser(
        "remove",
        help="remove the answer key from this environment (students' side of graded mode)",
        description="Delete the answer key modules from the installed eulerlib_course, so that "
        "nothing in this environment can compute a graded reference (graded mode).",
    )
    remove.add_argument(
        "--package", type=Path, help="the eulerlib_course folder (default: the installed one)"
    )
    parser.set_defaults(run=run_key)


def run_key(args: argparse.Namespace) -> int:
    """Carry out ``eulerlib-course key remove``."""
    from eulerlib_course.exercises.keyless import remove_answer_key

    removed = remove_answer_key(args.package)
    print(f"removed {len(removed)} files of the answer key")
    return 0


def run_notebooks(args: argparse.Namespace) -> int:
    """Carry out ``eulerlib-course notebooks student|nbgrader|copy|refresh``."""
    if args.action == "nbgrader":
        require(GRADING_TOOLS, extra="teach", needed_by="eulerlib-course notebooks nbgrader")
        return _nbgrader(args.src, args.out, force=args.force, graded=args.graded)
    require(NOTEBOOK_TOOLS, extra=None, needed_by=f"eulerlib-course notebooks {args.action}")
    if args.action == "refresh":
        return _refresh(args.notebooks)
    if args.action == "copy":
        return _working_copy(args.src, args.out)
    return _student(args.src, args.out, force=args.force, student=args.student)


def _student(src: Path | None, out: Path, *, force: bool, student: str | None = None) -> int:
    from eulerlib_course.student import write_student_copies

    source = src if src is not None else _course_folder(NOTEBOOK_FOLDER, "pass --src DIR")
    try:
        written = write_student_copies(source, out, force=force, student=student)
    except FileExistsError as error:
        raise ValueError(f"{error}; pass --force to overwrite them") from None
    print(f"wrote {len(written)} student copies to {out}")
    return 0


def _working_copy(src: Path | None, out: Path) -> int:
    from eulerlib_course.working_copy import write_working_copy

    source = src if src is not None else _course_folder(NOTEBOOK_FOLDER, "pass --src DIR")
    copied, kept = write_working_copy(source, out)
    print(f"copied {len(copied)} files of the course to {out} ({len(kept)} already there, kept)")
    return 0


def _nbgrader(src: Path | None, out: Path, *, force: bool, graded: bool = False) -> int:
    from eulerlib_course.nbgrader_edition import write_nbgrader_edition

    source = src if src is not None else _course_folder(NOTEBOOK_FOLDER, "pass --src DIR")
    try:
        edition = write_nbgrader_edition(source, out, force=force, graded=graded)
    except FileExistsError as error:
        raise ValueError(f"{error}; pass --force to overwrite them") from None
    print(f"wrote {len(edition.assignments)} nbgrader assignments and nbgrader_config.py to {out}")
    return 0


def _refresh(paths: list[Path]) -> int:
    from nbclient.exceptions import CellExecutionError

    from eulerlib_course.notebook_form import refresh_notebook

    if not paths:
        folder = _course_folder(NOTEBOOK_FOLDER, "name the notebooks to refresh")
        paths = sorted(folder.glob("*.ipynb"))
        if not paths:
            raise ValueError(f"no notebooks in {folder}/")
    missing = [path for path in paths if not path.is_file()]
    if missing:
        raise ValueError(f"no notebook at {missing[0]}")
    for path in paths:
        try:
            refresh_notebook(path)
        except CellExecutionError as error:  # one line, not the kernel's traceback
            raise ValueError(f"{path}: a cell raised {error.ename}: {error.evalue}") from None
        print(f"refreshed {path}")
    return 0


def run_figures(args: argparse.Namespace) -> int:
    """Carry out ``eulerlib-course figures``."""
    require(("matplotlib",), extra=None, needed_by="eulerlib-course figures")
    from eulerlib_course.figures import write_figures

    out = args.out if args.out is not None else _course_folder(FIGURE_FOLDER, "pass --out DIR")
    try:
        written = write_figures(out, force=args.force)
    except FileExistsError as error:
        raise ValueError(f"{error}; pass --force to replace them") from None
    print(f"wrote {len(written)} figures to {out}")
    return 0


def configure_site(parser: argparse.ArgumentParser) -> None:
    """Add the ``build`` action to the ``site`` sub-parser."""
    actions = parser.add_subparsers(dest="action", metavar="ACTION", required=True)
    build = actions.add_parser(
        "build",
        help="build the course website from the stored notebooks",
        description="Build the course website from the stored notebooks (nothing is executed). "
        "Run it from the top folder of the repository.",
    )
    build.add_argument(
        "--out", type=output_folder, help="folder for the website (default: build/site/); replaced"
    )
    parser.set_defaults(run=run_site)


def run_site(args: argparse.Namespace) -> int:
    """Carry out ``eulerlib-course site build``."""
    require(SITE_TOOLS, extra="site", needed_by=f"eulerlib-course site {args.action}")
    from eulerlib_course.site import DEFAULT_OUT, build_site

    out = args.out if args.out is not None else DEFAULT_OUT
    built = build_site(Path("."), out)
    for warning in built.warnings:  # "file:line: WARNING: what", as Sphinx reports them
        print(warning, file=sys.stderr)
    print(
        f"built {len(built.pages)} notebook pages into {out} in {built.seconds:.1f} s; "
        f"to read it, run: python3 -m http.server --directory {out}"
    )
    return 0
