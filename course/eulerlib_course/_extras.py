"""What to install when a course command needs more than the course package's dependencies.

``pip install -e ./course`` (from the top folder of the repository) installs the course with
what every notebook and most commands need: the library with its ``symbolic`` and ``plot``
extras, JupyterLab with widgets, and the notebook tools (nbformat, nbclient, nbconvert). Two
commands need more, named as *extras* of the course package:

* ``teach``: nbgrader, for ``eulerlib-course notebooks nbgrader``;
* ``site``: Jupyter Book and a MathJax to bundle, for ``eulerlib-course site build``.

A command that cannot import what it needs raises :class:`MissingExtraError`, an
``ImportError`` whose one-line message says what to install. The command line prints that
line as it is.
"""

from __future__ import annotations

import importlib


class MissingExtraError(ImportError):
    """A course command needs a package that is not installed.

    Parameters
    ----------
    needed_by : str
        What needs the package, as the user wrote it (``"eulerlib-course site build"``).
    package : str
        The importable name of the missing package (``"jupyter_book"``).
    extra : str or None
        The extra of the course package that installs it (``"site"``), or None for a
        dependency of the course package itself.

    Examples
    --------
    >>> print(MissingExtraError("eulerlib-course site build", "jupyter_book", "site"))
    eulerlib-course site build needs jupyter_book (the site extra of eulerlib-course): pip install -e "./course[site]"
    >>> print(MissingExtraError("eulerlib-course figures", "matplotlib", None))
    eulerlib-course figures needs matplotlib, a dependency of eulerlib-course: pip install -e ./course
    """  # noqa: E501

    def __init__(self, needed_by: str, package: str, extra: str | None) -> None:
        if extra is None:
            message = f"{needed_by} needs {package}, a dependency of eulerlib-course"
            command = "pip install -e ./course"
        else:
            message = f"{needed_by} needs {package} (the {extra} extra of eulerlib-course)"
            command = f'pip install -e "./course[{extra}]"'
        super().__init__(f"{message}: {command}", name=package)
        self.extra = extra


def require(packages: tuple[str, ...], *, extra: str | None, needed_by: str) -> None:
    """Import ``packages`` or raise :class:`MissingExtraError` naming what to install.

    ``extra`` is the course extra that installs them, or None for the course's own
    dependencies. The cause (the original ``ImportError``) stays attached, for a package that
    is installed but cannot be imported.
    """
    for package in packages:
        try:
            importlib.import_module(package)
        except ImportError as error:
            raise MissingExtraError(needed_by, package, extra) from error
