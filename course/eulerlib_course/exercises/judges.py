"""Judges: how an answer is compared with the reference, and how a wrong answer is diagnosed.

Each exercise of the course has one judge, built in the answer key with the reference and the
tolerance. A judge accepts every answer that is *equally right*, not only the one the key
holds, and names the *likely mistake* when an answer is wrong, without giving the reference
away:

* angles are judged by the rotation they give, so angles equal modulo a turn, the other branch
  of eq 3 and the free outer angle at gimbal lock all pass, unless the question states a
  constraint (yaw = 0, a range), which is then enforced and named;
* quaternions ``q`` and ``−q`` are the same rotation;
* SymPy answers are judged by their value at random values of their symbols, so an answer that
  differs from the reference only by simplification passes, whatever assumptions the learner's
  symbols carry, and a wrong matrix is answered with the learner's first entry that is off;
* the typical mistakes are recognised: degrees for radians, the transpose (the inverse), the
  reversed order (``AB`` for ``BA``, intrinsic for extrinsic), ``atan`` for ``atan2`` (an angle off
  by 180°), a sign error in one angle, scalar-first for scalar-last, the conjugate;
* an exercise can add its own typical mistakes (:class:`Mistake`), each with its diagnosis.

A judge is not an oracle that a search could follow: a wrong answer that matches no mistake gets
the exercise's ``hint`` (where to look), never a side ("too large") or a distance; an answer
within a coarse band of the reference (:data:`CLOSE_DEGREES`, :data:`CLOSE_RELATIVE`) is called
*close*, the same words on every side of it. Tolerances are the library's ``ROTATION_ATOL`` for
computed answers and :func:`rounded_to` for answers worked by hand to the digits asked. A choice
comes with a computed part (:class:`ChoiceJudge`), so that trying the options passes nothing.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib import ROTATION_ATOL
from eulerlib._validation import check_tolerance

from .feedback import Verdict, correct, off
from .reading import read_expression, read_numbers


@dataclass(frozen=True)
class Mistake:
    """A typical wrong answer of one exercise and what it tells about the learner's reasoning.

    ``value`` is what the mistake produces, of the same kind as the reference (a number, an
    array, three angles, a SymPy expression); ``message`` says which idea went wrong.
    """

    value: Any
    message: str


@dataclass(frozen=True)
class Constraint:
    """A condition the question states for an answer that is otherwise right (yaw = 0, a range).

    ``holds(answer)`` gets the answer as read (a float array); ``message`` names what the
    question asked, and is shown when the condition fails.
    """

    holds: Callable[[NDArray[np.float64]], bool]
    message: str


def _close(a: NDArray[np.float64], b: NDArray[np.float64], tol: float) -> bool:
    return bool(a.shape == b.shape and np.max(np.abs(a - b), initial=0.0) <= tol)


def rounded_to(decimals: int) -> float:
    """The tolerance of an answer worked by hand and rounded to ``decimals`` decimals.

    One unit of the last decimal asked: half of it for the rounding of the answer, the rest for
    the rounding of the steps before it.

    Examples
    --------
    >>> rounded_to(3)
    0.001
    """
    return float(10.0**-decimals)


#: Degrees of the coarse band of a wrong set of angles or a wrong quaternion that is "close".
CLOSE_DEGREES = 1.0
#: The coarse band of a wrong number or array entry that is "close", relative to its size.
CLOSE_RELATIVE = 0.01

_CLOSE = "close, but not within the tolerance: check your rounding, or give more digits"
_GENERIC_HINT = "work it through again from the data the question gives"


def _are(what: str) -> str:
    """``is`` or ``are``, as ``what`` asks ("your coordinates are", "your axis is")."""
    plural = "," in what or (what.endswith("s") and not what.endswith(("is", "ss", "us")))
    return "are" if plural else "is"


def _not_it(what: str, hint: str) -> str:
    return f"{what} {_are(what)} not it; {hint or _GENERIC_HINT}"


class Judge:
    """Base of the judges: ``judge(answer) -> Verdict``; ``kind`` names the kind of answer."""

    kind = "answer"

    def judge(self, answer: object) -> Verdict:  # pragma: no cover - every judge overrides
        raise NotImplementedError


# --- numbers ------------------------------------------------------------------------------------


@dataclass(frozen=True)
class NumberJudge(Judge):
    """A single number; with ``unit`` it is an angle and degrees/radians mix-ups are named.

    ``modulo`` (for angles: 360 or 2π) accepts answers equal up to whole turns.
    """

    reference: float
    what: str = "your number"
    tol: float = ROTATION_ATOL
    unit: str | None = None  # "deg" or "rad"
    modulo: float | None = None
    mistakes: Sequence[Mistake] = ()
    hint: str = ""
    kind = "number"

    def __post_init__(self) -> None:
        check_tolerance(self.tol, "tol")
        if self.unit not in (None, "deg", "rad"):
            raise ValueError(f"unit must be None, 'deg' or 'rad', got {self.unit!r}")

    def _distance(self, value: float, target: float) -> float:
        if self.modulo is None:
            return abs(value - target)
        m = self.modulo
        return abs((value - target + m / 2) % m - m / 2)

    def judge(self, answer: object) -> Verdict:
        value = float(read_numbers(answer, (), self.what))
        if self._distance(value, self.reference) <= self.tol:
            return correct(f"{self.what} {_are(self.what)} right ({value:.10g})")
        for mistake in self.mistakes:
            if self._distance(value, float(mistake.value)) <= self.tol:
                return off(mistake.message)
        if self.unit is not None:
            # the same angle in the other unit, and the tolerance and turn in that unit
            to_other = math.pi / 180 if self.unit == "deg" else 180 / math.pi
            other = self.reference * to_other
            tol = self.tol * to_other
            gap = abs(value - other)
            if self.modulo is not None:
                turn = self.modulo * to_other
                gap = abs((value - other + turn / 2) % turn - turn / 2)
            if gap <= tol:
                said, asked = (
                    ("radians", "degrees") if self.unit == "deg" else ("degrees", "radians")
                )
                return off(f"{self.what} looks like {said}; the question asks for {asked}")
        if self.reference != 0 and self._distance(-value, self.reference) <= self.tol:
            return off(f"{self.what} has the right size but the wrong sign")
        if self._distance(value, self.reference) <= self._band():
            return off(f"{self.what} {_are(self.what)} {_CLOSE}")
        return off(_not_it(self.what, self.hint))

    def _band(self) -> float:
        """The coarse band of "close" (a degree, or a hundredth of the size)."""
        if self.unit == "deg":
            band = CLOSE_DEGREES
        elif self.unit == "rad":
            band = math.radians(CLOSE_DEGREES)
        else:
            band = CLOSE_RELATIVE * max(abs(self.reference), 1.0)
        return max(band, 10 * self.tol)


# --- arrays: vectors and matrices ---------------------------------------------------------------


@dataclass(frozen=True)
class ArrayJudge(Judge):
    """A vector or a matrix, compared entry by entry.

    With ``rotation=True`` the answer is a rotation matrix, or a point turned by one: a wrong
    matrix is also checked for being the transpose (the inverse rotation), a reflection, or not
    orthogonal at all, and a wrong point for having another length than the answer (a rotation
    keeps lengths). Any vector is checked for pointing the opposite way.
    """

    reference: ArrayLike
    what: str = "your answer"
    tol: float = ROTATION_ATOL
    rotation: bool = False
    mistakes: Sequence[Mistake] = ()
    hint: str = ""
    kind = "array"

    def __post_init__(self) -> None:
        check_tolerance(self.tol, "tol")

    @property
    def _reference(self) -> NDArray[np.float64]:
        return np.asarray(self.reference, dtype=np.float64)

    def judge(self, answer: object) -> Verdict:
        ref = self._reference
        value = read_numbers(answer, ref.shape, self.what)
        if _close(value, ref, self.tol):
            return correct(f"{self.what} {_are(self.what)} right")
        for mistake in self.mistakes:
            if _close(value, np.asarray(mistake.value, dtype=np.float64), self.tol):
                return off(mistake.message)
        if ref.ndim == 2 and ref.shape[0] == ref.shape[1] and _close(value.T, ref, self.tol):
            return off(
                f"{self.what} is the transpose of the answer, that is the inverse rotation: "
                "check the order of the product, or active versus passive"
            )
        if ref.ndim == 1 and _close(-value, ref, self.tol):
            return off(f"{self.what} points the opposite way: a sign is off")
        if (
            self.rotation
            and ref.ndim == 1
            and not math.isclose(
                float(np.linalg.norm(value)),
                float(np.linalg.norm(ref)),
                rel_tol=1e-6,
                abs_tol=self.tol,
            )
        ):
            return off(
                f"{self.what} has another length than the point it comes from: a rotation never "
                "changes a length"
            )
        if self.rotation and ref.shape == (3, 3):
            det = float(np.linalg.det(value))
            if det < 0:
                return off(
                    f"{self.what} has determinant {det:.3g}: a reflection, not a rotation (a sign "
                    "or two columns are swapped)"
                )
            gram = float(np.max(np.abs(value @ value.T - np.eye(3))))
            if gram > 1e-6:
                return off(
                    f"{self.what} is not a rotation: its columns are not orthonormal "
                    f"(max |R Rᵀ − I| = {gram:.3g}); check each entry"
                )
        band = CLOSE_RELATIVE * max(float(np.max(np.abs(ref), initial=0.0)), 1.0)
        if _close(value, ref, max(band, 10 * self.tol)):
            return off(f"{self.what} {_are(self.what)} {_CLOSE}")
        return off(_not_it(self.what, self.hint))


# --- angles --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class AnglesJudge(Judge):
    """Three Euler angles, judged by the rotation they give.

    Any triple that gives the reference rotation is right (angles modulo a turn, the other
    branch of eq 3, any split of the free outer angle at lock) unless a :class:`Constraint` of the
    question fails. A wrong answer is first compared with the exercise's own :class:`Mistake`
    list, by rotation (so a mistake written modulo a turn is recognised too), then checked for
    the typical mistakes, in this order: the other unit, the reversed order, the
    intrinsic/extrinsic swap, one angle with the wrong sign, one angle off by 180° (``atan`` for
    ``atan2``).
    """

    reference: ArrayLike
    seq: str
    degrees: bool = True
    what: str = "your angles"
    tol: float = ROTATION_ATOL
    constraints: Sequence[Constraint] = ()
    mistakes: Sequence[Mistake] = ()
    hint: str = ""
    kind = "angles"

    def __post_init__(self) -> None:
        check_tolerance(self.tol, "tol")

    def _matrix(
        self, angles: ArrayLike, seq: str | None = None, degrees: bool | None = None
    ) -> Any:
        from eulerlib import euler_to_matrix

        return euler_to_matrix(
            angles,
            self.seq if seq is None else seq,
            degrees=self.degrees if degrees is None else degrees,
        )

    def judge(self, answer: object) -> Verdict:
        from eulerlib import get_convention

        convention = get_convention(self.seq)
        names, seq = convention.angle_names, convention.seq
        value = read_numbers(answer, (3,), self.what)
        target = self._matrix(self.reference)
        if _close(self._matrix(value), target, self.tol):
            for constraint in self.constraints:
                if not constraint.holds(value):
                    return off(f"these angles give the right rotation, but {constraint.message}")
            return correct("these angles give the rotation asked for")
        got = self._matrix(value)
        for mistake in self.mistakes:
            if _close(got, self._matrix(np.asarray(mistake.value, dtype=np.float64)), self.tol):
                return off(mistake.message)
        half = 180.0 if self.degrees else math.pi
        # (angles, sequence, in degrees, what it means if they give the target rotation)
        candidates: list[tuple[NDArray[np.float64], str, bool, str]] = []
        said, asked = ("radians", "degrees") if self.degrees else ("degrees", "radians")
        candidates.append(
            (value, seq, not self.degrees, f"these look like {said}; the question asks for {asked}")
        )
        candidates.append(
            (
                value[::-1],
                seq,
                self.degrees,
                f"the angles are in reverse order: angle i goes with letter i of {seq!r} "
                f"({', '.join(names)})",
            )
        )
        fixed_for_moving = (
            "fixed axes (extrinsic) instead of moving axes (intrinsic)"
            if seq.isupper()
            else "moving axes (intrinsic) instead of fixed axes (extrinsic)"
        )
        candidates.append(
            (
                value,
                seq.swapcase(),
                self.degrees,
                f"these are the angles of {seq.swapcase()!r}: {fixed_for_moving}",
            )
        )
        for i, name in enumerate(names):
            flipped = value.copy()
            flipped[i] = -flipped[i]
            candidates.append((flipped, seq, self.degrees, f"{name} has the wrong sign"))
        for i, name in enumerate(names):
            turned = value.copy()
            turned[i] += half
            candidates.append(
                (
                    turned,
                    seq,
                    self.degrees,
                    f"{name} is off by {'180°' if self.degrees else 'π'}, half a turn: check the "
                    "quadrant of that angle",
                )
            )
        for angles, candidate_seq, degrees, message in candidates:
            if _close(self._matrix(angles, seq=candidate_seq, degrees=degrees), target, self.tol):
                return off(message)
        from eulerlib import angle_between

        if float(angle_between(got, target, degrees=True)) <= CLOSE_DEGREES:
            return off(f"these angles are {_CLOSE}")
        return off(f"these angles give another rotation; {self.hint or _GENERIC_HINT}")


# --- quaternions ----------------------------------------------------------------------------------


@dataclass(frozen=True)
class QuaternionJudge(Judge):
    """A unit quaternion; ``q`` and ``−q`` are the same rotation and both are right.

    ``reference`` is written in the layout the question asks for (``scalar_first`` or not).
    Wrong answers are checked for the other layout, the conjugate (the inverse rotation), and a
    missing normalization.
    """

    reference: ArrayLike
    scalar_first: bool = False
    what: str = "your quaternion"
    tol: float = ROTATION_ATOL
    mistakes: Sequence[Mistake] = ()
    hint: str = ""
    kind = "quaternion"

    def __post_init__(self) -> None:
        check_tolerance(self.tol, "tol")

    def _same(self, q: NDArray[np.float64], r: NDArray[np.float64]) -> bool:
        return _close(q, r, self.tol) or _close(-q, r, self.tol)

    def judge(self, answer: object) -> Verdict:
        ref = np.asarray(self.reference, dtype=np.float64)
        value = read_numbers(answer, (4,), self.what)
        if _close(value, ref, self.tol):
            return correct(f"{self.what} is right")
        if _close(-value, ref, self.tol):
            return correct(
                f"{self.what} is −q of the reference, which is the same rotation (the double cover)"
            )
        for mistake in self.mistakes:
            if self._same(value, np.asarray(mistake.value, dtype=np.float64)):
                return off(mistake.message)
        norm = float(np.linalg.norm(value))
        if (
            norm > 0
            and not math.isclose(norm, 1.0, abs_tol=self.tol)
            and self._same(value / norm, ref)
        ):
            return off(
                f"{self.what} points the right way but is not of length 1; divide it by its "
                "norm to make it a unit quaternion"
            )
        moved = np.roll(value, 1 if self.scalar_first else -1)
        if self._same(moved, ref):
            layout = (
                "scalar-first (w, x, y, z)" if self.scalar_first else "scalar-last (x, y, z, w)"
            )
            return off(f"the components are in the wrong order: the question asks for {layout}")
        scalar = 0 if self.scalar_first else 3
        conjugate = -value
        conjugate[scalar] = value[scalar]
        if self._same(conjugate, ref):
            return off(f"{self.what} is the conjugate of the answer, which is the inverse rotation")
        if norm == 0:
            return off(f"{self.what} is zero, which is no rotation at all")
        dot = abs(float(value @ ref)) / norm
        if 2 * math.degrees(math.acos(min(1.0, dot))) <= CLOSE_DEGREES:
            return off(f"{self.what} {_are(self.what)} {_CLOSE}")
        return off(f"{self.what} is another rotation; {self.hint or _GENERIC_HINT}")


# --- SymPy expressions and matrices --------------------------------------------------------------


def _samples(symbol: Any, rng: np.random.Generator, count: int) -> NDArray[Any]:
    """Random values a symbol may take, by its assumptions (integer, positive, real)."""
    if symbol.is_integer:
        first = 1 if symbol.is_positive else 0 if symbol.is_nonnegative else -5
        return rng.integers(first, 6, count)
    low = 0.1 if (symbol.is_positive or symbol.is_nonnegative) else -3.0
    return rng.uniform(low, 3.0, count)


def _vanishes(expression: Any, seed: int = 7) -> bool:
    """True when ``expression`` (a SymPy expression or matrix) is zero.

    It is evaluated at random values of its symbols: a trigonometric or polynomial expression
    that is not identically zero is nonzero at almost every point, so seven points decide it
    without the cost of ``simplify`` (which can take seconds on a 3×3 matrix of products of
    sines and cosines, and can fail to see an identity that the numbers see at once).
    """
    import sympy as sp

    symbols = sorted(expression.free_symbols, key=str)
    entries = list(expression) if isinstance(expression, sp.MatrixBase) else [expression]
    if not symbols:
        return all(abs(complex(sp.N(entry, 30))) <= 1e-12 for entry in entries)
    rng = np.random.default_rng(seed)
    points = [_samples(symbol, rng, 7) for symbol in symbols]
    try:
        function = sp.lambdify(symbols, entries, modules="numpy")
        with np.errstate(all="ignore"):
            values = np.asarray(function(*points), dtype=np.complex128)
    except (TypeError, ValueError, NameError, ZeroDivisionError):
        values = np.array(
            [
                [
                    complex(entry.subs(dict(zip(symbols, point, strict=True))).evalf())
                    for entry in entries
                ]
                for point in zip(*points, strict=True)
            ]
        )
    return bool(np.all(np.isfinite(values)) and np.max(np.abs(values)) <= 1e-9)


def _same_symbols(value: Any, reference: Any) -> Any:
    """``value`` with each symbol replaced by the reference's symbol of the same name.

    ``Symbol("alpha")`` and ``Symbol("alpha", real=True)`` are different symbols to SymPy; a
    learner who made the notebook's symbols again, with or without assumptions, means the same
    angle.
    """
    by_name = {str(symbol): symbol for symbol in reference.free_symbols}
    swaps = {
        symbol: by_name[str(symbol)]
        for symbol in getattr(value, "free_symbols", set())
        if str(symbol) in by_name and by_name[str(symbol)] != symbol
    }
    return value.xreplace(swaps) if swaps else value


def _as_shape_of(value: Any, reference: Any) -> Any:
    """A row or column vector ``value`` in the shape of the vector ``reference`` (a vector
    written as a row is the same vector as a column); anything else as it is."""
    import sympy as sp

    if (
        isinstance(value, sp.MatrixBase)
        and isinstance(reference, sp.MatrixBase)
        and 1 in reference.shape
        and 1 in value.shape
        and len(value) == len(reference)
    ):
        return value.reshape(*reference.shape)
    return value


@dataclass(frozen=True)
class ExpressionJudge(Judge):
    """A SymPy expression or matrix, judged by its value, so that any equivalent form passes.

    A wrong matrix is answered with the one entry that differs (the learner's entry, never the
    reference's). ``up_to_sign`` accepts the answer with either sign (for a combination of angles
    whose sign convention the question leaves open).
    """

    reference: Any
    what: str = "your expression"
    up_to_sign: bool = False
    mistakes: Sequence[Mistake] = ()
    kind = "expression"

    def judge(self, answer: object) -> Verdict:
        import sympy as sp

        ref = sp.sympify(self.reference)
        value = _same_symbols(read_expression(answer, self.what), ref)
        is_matrix = isinstance(ref, sp.MatrixBase)
        value = _as_shape_of(value, ref)
        if is_matrix != isinstance(value, sp.MatrixBase) or (
            is_matrix and value.shape != ref.shape
        ):
            wanted = f"a {ref.shape[0]}×{ref.shape[1]} matrix" if is_matrix else "an expression"
            return off(f"{self.what} is not {wanted}")
        if _vanishes(value - ref):
            return correct(f"{self.what} equals the answer (written in another form is fine)")
        if self.up_to_sign and _vanishes(value + ref):
            return correct(f"{self.what} is right (with the other sign, which is as good here)")
        for mistake in self.mistakes:
            wrong = _as_shape_of(sp.sympify(mistake.value), ref)
            if getattr(wrong, "shape", None) == getattr(ref, "shape", None) and _vanishes(
                value - wrong
            ):
                return off(mistake.message)
        if _vanishes(value + ref):
            return off(f"{self.what} differs from the answer by its sign")
        if is_matrix:
            if ref.shape[0] == ref.shape[1] and _vanishes(value.T - ref):
                return off(
                    f"{self.what} is the transpose of the answer: check the order of the "
                    "product, or active versus passive"
                )
            for row in range(ref.shape[0]):
                for col in range(ref.shape[1]):
                    if not _vanishes(value[row, col] - ref[row, col]):
                        return off(
                            f"entry ({row}, {col}) of {self.what} is not right: yours is "
                            f"{sp.simplify(value[row, col])}"
                        )
        return off(f"{self.what} simplifies to {sp.simplify(value)}, which is not the answer")


# --- choices -------------------------------------------------------------------------------


@dataclass(frozen=True)
class ChoiceJudge(Judge):
    """One option among several (at least three), and the computation that settles it.

    Each wrong option has its own explanation, which says why that option fails and never names
    the right one. With ``computed`` (a judge of a number, a vector, a matrix) the answer is a
    pair, ``(option, value)``: the option the learner predicts and the value they computed to
    settle it; both must be right, so trying the options one by one passes nothing.
    ``computed_what`` names the value in the feedback ("the yaw you computed").
    """

    options: Mapping[str, str]
    answer: str
    explanations: Mapping[str, str] = field(default_factory=dict)
    computed: Judge | None = None
    computed_what: str = "the value you computed"
    kind = "choice"

    def __post_init__(self) -> None:
        if len(self.options) < 3:
            raise ValueError("a choice needs at least three options, so that a guess rarely passes")
        if self.answer not in self.options:
            raise ValueError(f"the answer {self.answer!r} is not one of the options")
        missing = set(self.options) - {self.answer} - set(self.explanations)
        if missing:
            raise ValueError(f"every wrong option needs an explanation; missing {sorted(missing)}")

    def _option(self, answer: object) -> str | None:
        if isinstance(answer, str) and answer.strip().lower() in self.options:
            return answer.strip().lower()
        return None

    def judge(self, answer: object) -> Verdict:
        labels = ", ".join(repr(label) for label in self.options)
        if self.computed is None:
            label = self._option(answer)
            if label is None:
                return off(f"give one of the options {labels} (as text, in quotes)")
            if label == self.answer:
                return correct(self.explanations.get(label, "that is the one"))
            return off(self.explanations[label])
        pair = isinstance(answer, (tuple, list)) and len(answer) == 2 and self._option(answer[0])
        if not pair:
            return off(
                f"give a pair: one of the options {labels} (as text, in quotes), then "
                f"{self.computed_what}, for example ('a', value)"
            )
        assert isinstance(answer, (tuple, list))
        label = self._option(answer[0])
        if answer[1] is Ellipsis:
            return Verdict(
                "not yet",
                f"your prediction {label!r} is recorded; now compute {self.computed_what} and "
                "put it in place of the ...",
            )
        if label != self.answer:
            assert label is not None
            return off(self.explanations[label])
        settled = self.computed.judge(answer[1])
        if settled.status != "correct":
            return off(settled.message)
        return correct(self.explanations.get(label, "that is the one"))
