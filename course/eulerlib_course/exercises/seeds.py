"""Whose data: the teacher's fixed data, or a student's own, drawn from a seed.

An exercise whose key can make data (its ``per_student`` maker) gives each student data of
their own: the seed is made from the exercise and the student's name, so the same student gets
the same data in every session and on every machine, and two students get different data. The
judge is then built from that student's data, so the check compares with the reference of what
the student was given.

Who the student is, in this order:

1. when nbgrader grades a submission, the student id in the folder it runs in
   (``autograded/STUDENT/ASSIGNMENT/`` or ``submitted/STUDENT/ASSIGNMENT/``: nbgrader's
   ``autograde`` executes each notebook in its autograded copy of the submission folder);
2. the name given to :func:`student_name` in the notebook (a student copy made with
   ``--student NAME`` has that cell; a student may type their name in it);
3. the environment variable ``EULERLIB_STUDENT``;
4. nobody: the teacher's edition, with the data its worked solutions and stored outputs use.

A login name (JupyterHub's ``JUPYTERHUB_USER``) is not used: a teacher who refreshes the
teacher's edition on a hub must get the teacher's data. Under nbgrader a student types their
student id in the name cell, and graded mode's form check reminds them while none is given.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import re
from collections.abc import Iterator
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "as_student",
    "current_student",
    "rng_for",
    "signed_degrees",
    "student_name",
    "whole_degree_angles",
]

#: The environment variable that names the student when no notebook cell does.
ENVIRONMENT = "EULERLIB_STUDENT"
_GRADED_FOLDER = re.compile(r"(?:autograded|submitted)$")

_named: str | None = None


def _check_name(name: object) -> str | None:
    if name is None or name is Ellipsis:
        return None
    if not isinstance(name, str):
        raise TypeError(f"name must be text, such as 'ada', got {type(name).__name__}")
    name = name.strip()
    if not name:
        return None
    return name


def student_name(name: str | None) -> None:
    """Say whose data the exercises of this notebook give: ``student_name("ada")``.

    ``...``, ``None`` or empty text means nobody: the teacher's data. While nbgrader grades a
    submission, the student id of the submission folder wins over the name given here.

    Raises
    ------
    TypeError
        If ``name`` is not text.

    Examples
    --------
    >>> student_name("ada"); current_student()
    'ada'
    >>> student_name(None); current_student() is None
    True
    """
    global _named
    _named = _check_name(name)


def _nbgrader_student(folder: Path) -> str | None:
    """The student id when ``folder`` is ``…/autograded/STUDENT/ASSIGNMENT``, else None."""
    parts = folder.parts
    if len(parts) >= 3 and _GRADED_FOLDER.fullmatch(parts[-3]):
        return parts[-2]
    return None


def current_student() -> str | None:
    """The student whose data the exercises give now (see the module docstring), or None."""
    graded = _nbgrader_student(Path.cwd())
    if graded is not None:
        return graded
    if _named is not None:
        return _named
    return _check_name(os.environ.get(ENVIRONMENT))


def rng_for(exercise: str, name: str) -> np.random.Generator:
    """The random generator of one exercise's data for one student (the same everywhere).

    Examples
    --------
    >>> bool(rng_for("05.1", "ada").integers(1000) == rng_for("05.1", "ada").integers(1000))
    True
    """
    digest = hashlib.sha256(f"eulerlib course · {exercise} · {name}".encode()).digest()
    return np.random.default_rng(int.from_bytes(digest[:16], "little"))


def signed_degrees(rng: np.random.Generator, low: int, high: int) -> float:
    """A whole number of degrees from ``low`` to ``high`` (both included), of either sign.

    Examples
    --------
    >>> 15 <= abs(signed_degrees(np.random.default_rng(1), 15, 60)) <= 60
    True
    """
    return float(rng.choice([-1, 1]) * rng.integers(low, high + 1))


def whole_degree_angles(rng: np.random.Generator, pitch_limit: int) -> NDArray[np.float64]:
    """Yaw, pitch, roll in whole degrees: yaw and roll within ±170°, pitch within ±``pitch_limit``.

    Examples
    --------
    >>> angles = whole_degree_angles(np.random.default_rng(1), 60)
    >>> bool(abs(angles[1]) <= 60 and np.all(angles == np.round(angles)))
    True
    """
    limits = np.array([170, pitch_limit, 170])
    return rng.integers(-limits, limits + 1).astype(np.float64)


@contextlib.contextmanager
def as_student(name: str | None) -> Iterator[None]:
    """Within the block, the exercises give ``name``'s data (None: the teacher's); for tests."""
    global _named
    saved, saved_env = _named, os.environ.pop(ENVIRONMENT, None)
    _named = _check_name(name)
    try:
        yield
    finally:
        _named = saved
        if saved_env is not None:
            os.environ[ENVIRONMENT] = saved_env
