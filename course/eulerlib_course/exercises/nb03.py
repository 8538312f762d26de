"""Answer key of notebook 03, Euler angles: Rose's eq 2, Baker's matrix, the 24 conventions."""

from __future__ import annotations

from collections.abc import Callable
from functools import cached_property
from typing import Any

import numpy as np
from numpy.typing import NDArray

from eulerlib import elementary_rotation, euler_to_matrix

from .judges import ArrayJudge, ChoiceJudge, ExpressionJudge, Mistake, rounded_to
from .key import Example, Exercise
from .seeds import signed_degrees


class _Later:
    """A SymPy expression built when a judge first needs it.

    The judges pass references through ``sympify``, which calls ``_sympy_``; so loading the
    answer key (which ``check`` does for every exercise) does not import SymPy.
    """

    def __init__(self, build: Callable[[], Any]) -> None:
        self._build = build

    @cached_property
    def _value(self) -> Any:
        return self._build()

    def _sympy_(self) -> Any:
        return self._value


def _product(*turns: tuple[str, str]) -> _Later:
    """The elementary matrices of ``turns`` (axis, angle symbol) multiplied from left to right.

    The symbols are real, as the exercise cells define them, so that they compare equal.
    """

    def build() -> Any:
        import sympy as sp

        from eulerlib.symbolic import elementary_matrix

        result = sp.eye(3)
        for axis, name in turns:
            result = result * elementary_matrix(axis, sp.Symbol(name, real=True))
        return result

    return _Later(build)


def _column(matrix: _Later, column: int) -> _Later:
    return _Later(lambda: matrix._sympy_()[:, column])


def _row_as_column(matrix: _Later, row: int) -> _Later:
    return _Later(lambda: matrix._sympy_()[row, :].T)


# 03.1: Baker's heading h about y (up), attitude a about the new z, bank b about the newest x:
# W_R_B = R_y(h) R_z(a) R_x(b), for the learner's own angles
_HAB = [120.0, 25.0, -40.0]  # h, a, b of the teacher's edition, degrees


def _hab() -> NDArray[np.float64]:
    return np.array(_HAB)


def _some_hab(rng: np.random.Generator) -> NDArray[np.float64]:
    """A student's h, a, b in whole degrees: heading and bank at least 20° from 0 and 10° apart
    (so that swapping them is another matrix), attitude 15° to 70° either way (away from the
    poles)."""
    while True:
        heading, bank = (signed_degrees(rng, 20, 170) for _ in range(2))
        if abs(heading - bank) >= 10.0:
            break
    attitude = signed_degrees(rng, 15, 70)
    return np.array([heading, attitude, bank])


def _judge_hab(angles: NDArray[np.float64]) -> ArrayJudge:
    h, a, b = (float(x) for x in angles)

    def product(*turns: tuple[str, float], degrees: bool = True) -> NDArray[np.float64]:
        result = np.eye(3)
        for axis, angle in turns:
            result = result @ elementary_rotation(axis, angle, degrees=degrees)
        return result

    return ArrayJudge(
        product(("y", h), ("z", a), ("x", b)),
        what="your matrix",
        rotation=True,
        mistakes=(
            Mistake(
                product(("z", h), ("y", a), ("x", b)),
                "this is Rose's z-up product with Baker's numbers: in Baker's frame y is up, so "
                "the heading turns about y and the attitude about the new z",
            ),
            Mistake(
                product(("x", b), ("z", a), ("y", h)),
                "the matrices stand in the reverse order of the turns, which reads them about "
                "the fixed axes; Baker's turns are about the moving axes, so they stand in the "
                "order they happen",
            ),
            Mistake(
                product(("y", b), ("z", a), ("x", h)),
                "heading and bank are swapped: the heading turns about the vertical y, the bank "
                "about the nose x",
            ),
            Mistake(
                product(("y", h), ("x", a), ("z", b)),
                "the attitude turns about z, not x: with y up and the nose along x, the wing "
                "lies along z, and the attitude (the pitch) turns about the wing",
            ),
            Mistake(
                product(("y", h), ("z", a), ("x", b), degrees=False),
                "these are turns by radians: pass degrees=True",
            ),
        ),
    )


# 03.3: Rose's numbers read about the fixed axes, "zyx": R_x(u) R_y(v) R_z(w); the nose is column 1
_ZYX_FIXED = _product(("x", "u"), ("y", "v"), ("z", "w"))

_WVU = (30.0, -20.0, 50.0)  # 03.2: yaw w, pitch v, roll u of the matrix asked for, degrees

EXERCISES = [
    Exercise(
        id="03.1",
        level="apply",
        judge=_judge_hab(_hab()),
        per_student=_some_hab,
        judged=_judge_hab,
        given=_hab,
        examples=(
            Example(
                'elementary_rotation("y", hab_ex[0], degrees=True)'
                ' @ elementary_rotation("z", hab_ex[1], degrees=True)'
                ' @ elementary_rotation("x", hab_ex[2], degrees=True)',
                "correct",
            ),
            Example("heading_attitude_bank_to_matrix(*hab_ex, degrees=True)", "correct"),
            Example('euler_to_matrix(hab_ex[::-1], "xzy", degrees=True)', "correct"),
            Example('euler_to_matrix(hab_ex, "ZYX", degrees=True)', "off", "z-up product"),
            Example('euler_to_matrix(hab_ex, "yzx", degrees=True)', "off", "reverse order"),
            Example('euler_to_matrix(hab_ex[::-1], "YZX", degrees=True)', "off", "swapped"),
            Example('euler_to_matrix(hab_ex, "YXZ", degrees=True)', "off", "wing lies along z"),
            Example('euler_to_matrix(hab_ex, "YZX")', "off", "radians"),
            Example('euler_to_matrix(hab_ex, "YZX", degrees=True).T', "off", "transpose"),
        ),
        forbidden=("W_R_1 @ one_R_2 @ two_R_B", 'elementary_rotation("y", heading'),
    ),
    Exercise(
        id="03.2",
        level="predict",
        judge=ChoiceJudge(
            options={
                "a": 'Rotation.from_euler("XYZ", [u, v, w])',
                "b": 'Rotation.from_euler("xyz", [u, v, w])',
                "c": 'Rotation.from_euler("zyx", [w, v, u])',
                "d": 'Rotation.from_euler("ZYX", [u, v, w])',
            },
            answer="b",
            computed=ArrayJudge(
                euler_to_matrix(np.array(_WVU), "ZYX", degrees=True),
                what="your matrix",
                tol=rounded_to(3),
                rotation=True,
                hint="make the matrix of the call you chose for w, v, u = 30°, −20°, 50°",
            ),
            computed_what="the matrix of your call",
            explanations={
                "b": "right: x, then y, then z about the fixed axes is R_z(w) R_y(v) R_x(u), "
                "Rose's product read from the right",
                "a": "'XYZ' turns about the moving axes x, then y, then z: that is "
                "R_x(u) R_y(v) R_z(w), Rose's product in the reverse order, another rotation",
                "c": "'zyx' turns about the fixed axes z, then y, then x; each later turn "
                "multiplies from the left, so that is R_x(u) R_y(v) R_z(w), another rotation",
                "d": "the letters are Rose's, but angle i goes with letter i: this call reads the "
                "roll u as the yaw about z and the yaw w as the roll about x",
            },
        ),
        examples=(
            Example(
                "('b', Rotation.from_euler('xyz', [50, -20, 30], degrees=True).as_matrix())",
                "correct",
            ),
            Example(
                "(' B ', Rotation.from_euler('ZYX', [30, -20, 50], degrees=True).as_matrix())",
                "correct",
                "read from the right",
            ),
            Example(
                "('b', Rotation.from_euler('XYZ', [50, -20, 30], degrees=True).as_matrix())",
                "off",
                "your matrix is not it",
            ),
            Example("('a', np.eye(3))", "off", "reverse order"),
            Example("('c', np.eye(3))", "off", "fixed axes z, then y, then x"),
            Example("('d', np.eye(3))", "off", "angle i goes with letter i"),
            Example("'b'", "off", "give a pair"),
        ),
        forbidden=('answer_2 = "b"', "answer_2 = 'b'"),
    ),
    Exercise(
        id="03.3",
        level="extend",
        judge=ExpressionJudge(
            _column(_ZYX_FIXED, 0),
            what="your nose direction",
            mistakes=(
                Mistake(
                    _column(_product(("z", "w"), ("y", "v"), ("x", "u")), 0),
                    "that is the nose of Rose's moving-axes reading 'ZYX', where the roll leaves "
                    "the nose alone; about the fixed axes each later turn multiplies from the "
                    "left, so the matrix is R_x(u) R_y(v) R_z(w)",
                ),
                Mistake(
                    _row_as_column(_ZYX_FIXED, 0),
                    "this is the first row of the matrix written as a column; the nose is where "
                    "e_x goes, R e_x, which is the first column",
                ),
            ),
        ),
        examples=(
            Example('euler_matrix((w, v, u), "zyx")[:, 0]', "correct"),
            Example(
                'elementary_matrix("x", u) * elementary_matrix("y", v)'
                ' * elementary_matrix("z", w) * sp.Matrix([1, 0, 0])',
                "correct",
            ),
            Example('euler_matrix((w, v, u), "ZYX")[:, 0]', "off", "moving-axes reading"),
            Example('euler_matrix((w, v, u), "zyx")[0, :].T', "off", "first row"),
            Example('euler_matrix((w, v, u), "zyx")[0, :]', "off", "first row"),
            Example("'cos(v)*cos(w)'", "off", "is text"),
        ),
        forbidden=('euler_matrix((w, v, u), "zyx")', "fixed_reading[:, 0]"),
    ),
]
