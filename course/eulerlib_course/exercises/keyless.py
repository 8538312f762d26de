"""Removing the answer key from an installed course, for the students' side of graded mode.

Whatever data a student's kernel shows, a function installed next to it that turns those data
into the reference would give the graded answer away. The answer key is such a function (its
modules ``nbNN``), so in graded mode the students' environment holds the course without it:
:func:`remove_answer_key` deletes the key modules (and their compiled copies) from an installed
``eulerlib_course``. The checker, the judges, the data makers of :mod:`.seeds` and the form check
stay; ``check`` then says that answers are graded when handed in.

It refuses to touch a package that sits in a git working tree (an editable install from the
repository), where the key is the course's source.
"""

from __future__ import annotations

from pathlib import Path

__all__ = ["key_modules", "remove_answer_key"]


def key_modules(package: Path) -> list[Path]:
    """The files of the answer key in the ``eulerlib_course`` package folder ``package``."""
    folder = package / "exercises"
    found = sorted(folder.glob("nb[0-9][0-9].py"))
    found += sorted((folder / "__pycache__").glob("nb[0-9][0-9].*.pyc"))
    return found


def _in_git_tree(path: Path) -> bool:
    return any((parent / ".git").exists() for parent in (path, *path.parents))


def remove_answer_key(package: str | Path | None = None) -> list[Path]:
    """Delete the answer key from the installed ``eulerlib_course`` (or the package folder given).

    Returns
    -------
    list of Path
        The files deleted.

    Raises
    ------
    ValueError
        If ``package`` is not an ``eulerlib_course`` package folder, or lies in a git working
        tree (an editable install).
    """
    if package is None:
        import eulerlib_course

        package = Path(eulerlib_course.__file__).parent
    package = Path(package).resolve()
    if not (package / "exercises" / "judges.py").is_file():
        raise ValueError(f"{package} is not the folder of an installed eulerlib_course")
    if _in_git_tree(package):
        raise ValueError(
            f"{package} is in a git working tree (an editable install): its answer key is the "
            "course's source; remove the key only from a students' environment"
        )
    files = key_modules(package)
    for path in files:
        path.unlink()
    return files
