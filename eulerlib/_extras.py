"""Optional dependencies: what to install when a part of eulerlib needs more than numpy.

The core library needs numpy only. The other parts name their dependencies as *extras* of the
package, installed with ``pip install "eulerlib[EXTRA]"``:

* ``symbolic``: SymPy, for :mod:`eulerlib.symbolic`;
* ``plot``: matplotlib, for :mod:`eulerlib.plotting`.

The course built on the library (its notebooks, exercise checker, figures and website) is a
package of its own, ``eulerlib-course``, with its own dependencies.

A part that cannot import what it needs raises :class:`MissingExtraError`, an ``ImportError``
whose one-line message says which extra to install. The command line prints that line as it is.
"""

from __future__ import annotations

import importlib


class MissingExtraError(ImportError):
    """A part of eulerlib needs a package of an extra that is not installed.

    Parameters
    ----------
    needed_by : str
        What needs the package, as the user wrote it (``"eulerlib.symbolic"``).
    package : str
        The importable name of the missing package (``"sympy"``).
    extra : str
        The extra of eulerlib that installs it (``"symbolic"``).
    """

    def __init__(self, needed_by: str, package: str, extra: str) -> None:
        super().__init__(
            f'{needed_by} needs {package} (the {extra} extra): pip install "eulerlib[{extra}]"',
            name=package,
        )
        self.extra = extra


def require(packages: tuple[str, ...], *, extra: str, needed_by: str) -> None:
    """Import ``packages`` or raise :class:`MissingExtraError` naming ``extra``.

    The cause (the original ``ImportError``) stays attached, for a package that is installed
    but cannot be imported.
    """
    for package in packages:
        try:
            importlib.import_module(package)
        except ImportError as error:
            raise MissingExtraError(needed_by, package, extra) from error
