"""Exercises that check themselves: the course's answer key and the ``check`` a student runs.

Every exercise of a course notebook ends with a check cell that names the exercise and the
learner's answer, and nothing else::

    check("05.2", answer_2)

The reference, the tolerance and the typical mistakes live here, in the answer key
(:mod:`.key` and one module ``nbNN`` per notebook), never in a visible cell. Data the question
gives comes from :func:`given`, so the exercise cell shows the data without showing how it was
made. See :mod:`.judges` for what counts as equally right and which mistakes are diagnosed.

An exercise can give each student data of their own (:mod:`.seeds`; ``student_name("ada")`` in
the notebook); a prediction is recorded by its check and fixed once the cell that settles it has
run (:mod:`.predictions`); graded mode checks only the form in the student's notebook
(:mod:`.graded`) and grades with a key the students' side does not hold (:mod:`.keyless`).
"""

from .feedback import Feedback
from .judges import (
    AnglesJudge,
    ArrayJudge,
    ChoiceJudge,
    Constraint,
    ExpressionJudge,
    Mistake,
    NumberJudge,
    QuaternionJudge,
)
from .key import Example, Exercise, check, exercises, given
from .predictions import predict, settle
from .seeds import student_name

__all__ = [
    "AnglesJudge",
    "ArrayJudge",
    "ChoiceJudge",
    "Constraint",
    "Example",
    "Exercise",
    "ExpressionJudge",
    "Feedback",
    "Mistake",
    "NumberJudge",
    "QuaternionJudge",
    "check",
    "exercises",
    "given",
    "predict",
    "settle",
    "student_name",
]
