"""Self-checks for the exercises in the course notebooks.

Each exercise in a notebook ends with a check cell that calls one of these functions with the
learner's answer and a reference computed independently in the notebook. The function returns
a :class:`CheckResult`; its text (shown as the cell's output) says what is right, or what is
off and by how much, so the learner gets feedback without a grading server. An exercise that
has not been attempted still holds ``...`` as its answer, and the check says "not yet".

Nothing here prints: the result is a value, displayed by Jupyter like any other.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

__all__ = [
    "CheckResult",
    "check_angles",
    "check_matrix",
    "check_number",
    "check_symbolic",
    "check_true",
]

_NOT_YET = "not yet: replace the ... with your answer and run the cell again"


@dataclass(frozen=True)
class CheckResult:
    """Outcome of a self-check.

    Attributes
    ----------
    passed : bool or None
        True if the answer is right, False if it is off, None if it was not attempted.
    message : str
        Feedback for the learner; it starts with "correct", "off" or "not yet".
    """

    passed: bool | None
    message: str

    def __bool__(self) -> bool:
        return bool(self.passed)

    def __repr__(self) -> str:
        return self.message

    __str__ = __repr__


def _unanswered(answer: object) -> bool:
    return answer is Ellipsis or answer is None


def _as_numbers(answer: object, what: str) -> tuple[np.ndarray[Any, Any] | None, str]:
    try:
        array = np.asarray(answer, dtype=np.float64)
    except (TypeError, ValueError):
        return None, f"off: {what} should be numbers, but got {type(answer).__name__}"
    return array, ""


def check_matrix(
    answer: object, expected: ArrayLike, *, atol: float = 1e-9, name: str = "your matrix"
) -> CheckResult:
    """Compare a matrix (or any array) entry by entry.

    Parameters
    ----------
    answer : object
        The learner's answer; ``...`` means not attempted.
    expected : array_like
        The reference value.
    atol : float, optional
        Largest accepted difference in any entry.
    name : str, optional
        What the answer is, for the message.

    Returns
    -------
    CheckResult
        With a hint when the answer is the transpose of the reference (active and passive, or
        the product order, mixed up).

    Examples
    --------
    >>> import numpy as np
    >>> check_matrix(np.eye(3), np.eye(3))
    correct: your matrix matches the reference (largest difference 0.0e+00)
    >>> check_matrix(..., np.eye(3))
    not yet: replace the ... with your answer and run the cell again
    """
    if _unanswered(answer):
        return CheckResult(None, _NOT_YET)
    got, problem = _as_numbers(answer, name)
    if got is None:
        return CheckResult(False, problem)
    want = np.asarray(expected, dtype=np.float64)
    if got.shape != want.shape:
        return CheckResult(False, f"off: {name} has shape {got.shape}, expected {want.shape}")
    error = np.abs(got - want)
    worst = float(error.max()) if error.size else 0.0
    if worst <= atol:
        return CheckResult(
            True, f"correct: {name} matches the reference (largest difference {worst:.1e})"
        )
    index = tuple(int(i) for i in np.unravel_index(int(np.argmax(error)), error.shape))
    message = (
        f"off: {name} differs from the reference by up to {worst:.3g}, at entry {index} "
        f"(you have {float(got[index]):.6g}, expected {float(want[index]):.6g})"
    )
    if got.ndim >= 2 and got.shape[-1] == got.shape[-2]:
        if np.allclose(np.swapaxes(got, -1, -2), want, atol=atol):
            message += "; it is the transpose of the reference: check the order of the product "
            message += "or active versus passive"
    return CheckResult(False, message)


def check_number(
    answer: object, expected: float, *, atol: float = 1e-9, name: str = "your number"
) -> CheckResult:
    """Compare a single number.

    Examples
    --------
    >>> check_number(0.5, 0.5)
    correct: your number is 0.5
    >>> check_number(0.4, 0.5)
    off: your number is 0.4, expected 0.5 (difference 0.1)
    """
    if _unanswered(answer):
        return CheckResult(None, _NOT_YET)
    got, problem = _as_numbers(answer, name)
    if got is None:
        return CheckResult(False, problem)
    if got.shape != ():
        return CheckResult(False, f"off: {name} should be a single number, got shape {got.shape}")
    value = float(got)
    if abs(value - expected) <= atol:
        return CheckResult(True, f"correct: {name} is {value:.6g}")
    return CheckResult(
        False,
        f"off: {name} is {value:.6g}, expected {expected:.6g} "
        f"(difference {abs(value - expected):.3g})",
    )


def check_angles(
    answer: object,
    expected: ArrayLike,
    *,
    seq: str = "ZYX",
    degrees: bool = False,
    atol: float = 1e-9,
) -> CheckResult:
    """Compare Euler angles by the rotation they describe.

    Two different triples can describe the same rotation (for example at gimbal lock, or the
    second solution with the middle angle reflected); such an answer is accepted, and the
    message says that it differs from the reference triple.

    Examples
    --------
    >>> check_angles([30, 20, 10], [30, 20, 10], degrees=True)
    correct: these angles give the reference rotation
    >>> check_angles([210, 160, 190], [30, 20, 10], degrees=True).message.split(",")[0]
    'correct: these angles give the reference rotation'
    >>> check_angles([10, 20, 30], [30, 20, 10], degrees=True).passed
    False
    """
    from eulerlib.euler import euler_to_matrix

    if _unanswered(answer):
        return CheckResult(None, _NOT_YET)
    got, problem = _as_numbers(answer, "your angles")
    if got is None:
        return CheckResult(False, problem)
    want = np.asarray(expected, dtype=np.float64)
    if got.shape != want.shape:
        return CheckResult(False, f"off: your angles have shape {got.shape}, expected {want.shape}")
    if not np.all(np.isfinite(got)):
        return CheckResult(
            False, "off: your angles contain NaN or infinity, expected finite numbers"
        )
    unit = "°" if degrees else " rad"
    difference = np.abs(
        euler_to_matrix(got, seq, degrees=degrees) - euler_to_matrix(want, seq, degrees=degrees)
    ).max()
    if difference <= atol:
        if np.allclose(got, want, atol=atol):
            return CheckResult(True, "correct: these angles give the reference rotation")
        shown = np.array2string(np.round(want, 6) + 0.0, separator=", ")
        return CheckResult(
            True,
            "correct: these angles give the reference rotation, although they differ from "
            f"the reference angles {shown}",
        )
    return CheckResult(
        False,
        f"off: these angles give a different rotation (the matrices differ by up to "
        f"{difference:.3g}); check the sequence {seq!r}, which angle goes with which axis, "
        f"and the unit ({unit.strip()})",
    )


def check_symbolic(answer: object, expected: Any, *, name: str = "your expression") -> CheckResult:
    """Compare SymPy expressions or matrices by simplifying their difference.

    Examples
    --------
    >>> import sympy as sp
    >>> x = sp.symbols("x")
    >>> check_symbolic(sp.sin(x) ** 2, 1 - sp.cos(x) ** 2)
    correct: your expression equals the reference
    """
    import sympy as sp

    if _unanswered(answer):
        return CheckResult(None, _NOT_YET)
    try:
        difference = sp.simplify(sp.sympify(answer) - sp.sympify(expected))
    except (sp.SympifyError, TypeError, ValueError, AttributeError) as error:
        return CheckResult(False, f"off: {name} could not be compared with the reference ({error})")
    is_zero = (
        difference.is_zero_matrix if isinstance(difference, sp.MatrixBase) else difference == 0
    )
    if is_zero:
        return CheckResult(True, f"correct: {name} equals the reference")
    return CheckResult(False, f"off: {name} differs from the reference by {difference}")


def check_true(answer: object, *, correct: str, wrong: str) -> CheckResult:
    """Check a yes/no answer (``True`` or ``False``) and explain.

    Parameters
    ----------
    answer : object
        The learner's answer; the exercise is right when it is ``True``.
    correct, wrong : str
        What to say in each case.

    Examples
    --------
    >>> check_true(True, correct="yes, it is a rotation", wrong="look at the determinant")
    correct: yes, it is a rotation
    """
    if _unanswered(answer):
        return CheckResult(None, _NOT_YET)
    if answer is True or answer is np.True_:
        return CheckResult(True, f"correct: {correct}")
    return CheckResult(False, f"off: {wrong}")
