"""What a check says: correct, off (and why), or not yet.

A check never prints and never raises because of the learner's answer: it returns a
:class:`Feedback`, which Jupyter shows as the output of the check cell, like any value. Its first
words are the exercise and the verdict, so a glance at a notebook shows where a learner stands.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

Status = Literal["correct", "off", "not yet", "received"]

NOT_YET = "there is no answer yet; replace the ... with your answer and run the cell again"


@dataclass(frozen=True)
class Feedback:
    """The verdict of a check.

    Attributes
    ----------
    exercise : str
        The exercise, for example ``"05.2"`` (notebook 05, exercise 2).
    status : {'correct', 'off', 'not yet', 'received'}
        ``'not yet'`` while the answer is still ``...``; ``'received'`` when graded mode's
        visible check found the form right (it does not judge the answer).
    message : str
        What is right, or what is off and the likely reason, in a sentence or two.

    Examples
    --------
    >>> Feedback("05.2", "off", "yaw is off by 180°")
    Exercise 05.2 — off: yaw is off by 180°
    >>> bool(Feedback("05.2", "correct", "these angles give the rotation"))
    True
    """

    exercise: str
    status: Status
    message: str

    @property
    def passed(self) -> bool | None:
        """True when correct, False when off, None when not attempted or not judged."""
        return None if self.status in ("not yet", "received") else self.status == "correct"

    def __bool__(self) -> bool:
        return self.status == "correct"

    def __str__(self) -> str:
        return f"Exercise {self.exercise} — {self.status}: {self.message}"

    __repr__ = __str__


@dataclass(frozen=True)
class Verdict:
    """What a judge decides, before the exercise id is attached."""

    status: Status
    message: str


def correct(message: str) -> Verdict:
    """A verdict that the answer is right."""
    return Verdict("correct", message)


def off(message: str) -> Verdict:
    """A verdict that the answer is wrong, with the reason."""
    return Verdict("off", message)
