"""Course tooling: what keeps the notebooks a reliable record, and what a teacher hands out.

The library (:mod:`eulerlib`) computes; this package looks after the course built on it:

* :mod:`~eulerlib.course.notebook_form`: the normal form in which notebooks are stored (so that
  strict nbval compares exactly what a fresh run writes), and refreshing a notebook into it;
* :mod:`~eulerlib.course.exercises`: the answer key of the course and the ``check`` and
  ``given`` that the exercise cells call (numpy only; SymPy when an answer is an expression);
* :mod:`~eulerlib.course.student`: student copies, without the worked solutions and outputs;
* :mod:`~eulerlib.course.nbgrader_edition`: the course as an nbgrader course folder, its
  exercises graded by the same answer key;
* :mod:`~eulerlib.course.site`: the course as a static website that needs no network;
* :mod:`~eulerlib.course.figures`: every figure of the course, drawn from the library;
* :mod:`~eulerlib.course.commands`: the command-line glue, ``eulerlib notebooks
  student|nbgrader|refresh``, ``eulerlib figures`` and ``eulerlib site build``.

The tooling modules need the ``notebooks`` extra (``pip install "eulerlib[notebooks]"``:
nbformat, nbclient, nbconvert, and matplotlib for the figures), and ``teach`` (nbgrader) or
``site`` (Jupyter Book) for the edition and the website. Importing this package loads
none of them; it offers the two names a notebook's exercises use:

>>> from eulerlib.course import check, given
"""

from eulerlib.course.exercises import check, given

__all__ = ["check", "given"]
