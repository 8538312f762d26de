"""A working copy of the course, for reading and running it in JupyterLab.

The committed notebooks in ``notebooks/`` are the course's record: CI re-executes them and
compares what they show with what they store. JupyterLab saves what happens to an open notebook
by itself (autosave), so working in them directly would change that record: a *Run All* that
clears the outputs and then stops (a kernel that does not start on a first launch), a cell tried
out, an answer typed in. The README's command therefore opens a working copy, made by
``eulerlib-course notebooks copy --out DIR``: the notebooks as they are committed (the
teacher's edition, with their outputs and worked solutions), the glossary and the ``data/``
folder, copied byte for byte.

Running the command again keeps every file already in the copy (the learner's work) and adds
only what is missing, so the same command opens the course the first time and every time after;
to start a notebook afresh, delete it from the copy and run the command again.
"""

from __future__ import annotations

import shutil
from pathlib import Path

__all__ = ["write_working_copy"]

#: Folders that are never part of the course, wherever they are.
_SKIPPED = frozenset({"__pycache__", ".ipynb_checkpoints"})


def write_working_copy(source: str | Path, out: str | Path) -> tuple[list[Path], list[Path]]:
    """Copy the course in ``source`` into ``out``, keeping every file already there.

    Parameters
    ----------
    source : str or Path
        The folder of the course notebooks (``notebooks/``).
    out : str or Path
        The working copy's folder, created if needed.

    Returns
    -------
    (list of Path, list of Path)
        The files copied now, and those already in ``out`` and kept, as paths in ``out``.

    Raises
    ------
    ValueError
        If ``source`` is not a folder of notebooks, or ``out`` is that folder or inside it.

    Examples
    --------
    >>> import tempfile
    >>> folder = Path(tempfile.mkdtemp())
    >>> _ = (folder / "course").mkdir(), (folder / "course" / "01_a.ipynb").write_text("{}")
    >>> copied, kept = write_working_copy(folder / "course", folder / "mine")
    >>> [path.name for path in copied], kept
    (['01_a.ipynb'], [])
    >>> copied, kept = write_working_copy(folder / "course", folder / "mine")
    >>> copied, [path.name for path in kept]
    ([], ['01_a.ipynb'])
    """
    source, out = Path(source), Path(out)
    if not source.is_dir() or not any(source.glob("*.ipynb")):
        raise ValueError(f"no course notebooks in {source}")
    if out.resolve() == source.resolve() or source.resolve() in out.resolve().parents:
        raise ValueError("the working copy must go to a folder outside the course notebooks")
    files = [
        path
        for path in sorted(source.rglob("*"))
        if path.is_file() and not _SKIPPED & set(path.relative_to(source).parts)
    ]
    copied: list[Path] = []
    kept: list[Path] = []
    for path in files:
        target = out / path.relative_to(source)
        if target.exists():
            kept.append(target)
            continue
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(path, target)
        copied.append(target)
    return copied, kept
