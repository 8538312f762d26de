"""Course tooling: what keeps the notebooks a reliable record, and what a teacher hands out.

The library (:mod:`eulerlib`) computes; this package looks after the course built on it:

* :mod:`~eulerlib_course.notebook_form`: the normal form in which notebooks are stored (so that
  strict nbval compares exactly what a fresh run writes), and refreshing a notebook into it;
* :mod:`~eulerlib_course.exercises`: the answer key of the course and the ``check`` and
  ``given`` that the exercise cells call (numpy only; SymPy when an answer is an expression);
* :mod:`~eulerlib_course.student`: student copies, without the worked solutions and outputs;
* :mod:`~eulerlib_course.nbgrader_edition`: the course as an nbgrader course folder, its
  exercises graded by the same answer key;
* :mod:`~eulerlib_course.site`: the course as a static website that needs no network;
* :mod:`~eulerlib_course.figures`: every figure of the course, drawn from the library;
* :mod:`~eulerlib_course.explorable`: rotations to turn with the mouse, an anywidget in
  JupyterLab (eulerlib computes) whose ES module also runs on the website (a JavaScript port
  computes, held against eulerlib by the tests);
* :mod:`~eulerlib_course.commands` and :mod:`~eulerlib_course.cli`: the command line
  ``eulerlib-course``, with ``notebooks student|nbgrader|refresh``, ``figures`` and
  ``site build``.

The package is ``eulerlib-course``, in the ``course/`` folder of the repository; it depends on
the library (never the other way round). ``pip install -e ./course`` installs it with what the
notebooks and most commands need (the library's ``symbolic`` and ``plot`` extras, JupyterLab,
widgets, nbformat, nbclient, nbconvert); its ``teach`` extra (nbgrader) and ``site`` extra
(Jupyter Book) add what the edition and the website need. Importing this package loads none of
the tools; it offers the two names a notebook's exercises use, and
:mod:`~eulerlib_course.explorable` the notebooks' explorables:

>>> from eulerlib_course import check, given
"""

from eulerlib_course.exercises import check, given, predict, settle, student_name

__all__ = ["check", "given", "predict", "settle", "student_name"]
