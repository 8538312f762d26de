"""The exercise self-checks: right answers pass, wrong ones say what is off and by how much.

The references are written out by hand (elementary matrices with exact entries, angle triples
related by the identities of the convention), never produced by the checker itself.
"""

import re

import numpy as np
import pytest
import sympy as sp

from eulerlib.checks import (
    CheckResult,
    check_angles,
    check_matrix,
    check_number,
    check_symbolic,
    check_true,
)

# A quarter turn about z, typed in: x goes to y.
QUARTER_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])

NOT_YET = "not yet"


def numbers_in(message: str) -> list[float]:
    """Every number written in a message, in order."""
    return [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?(?:e[+-]?\d+)?", message)]


# --- CheckResult -------------------------------------------------------------------------------


def test_result_repr_is_the_message_and_truth_is_passed() -> None:
    passed = CheckResult(True, "correct: fine")
    off = CheckResult(False, "off: no")
    pending = CheckResult(None, "not yet: later")
    assert repr(passed) == str(passed) == "correct: fine"
    assert bool(passed) is True
    assert bool(off) is False
    assert bool(pending) is False


@pytest.mark.parametrize(
    "call",
    [
        lambda a: check_matrix(a, np.eye(3)),
        lambda a: check_number(a, 0.5),
        lambda a: check_angles(a, [0.1, 0.2, 0.3]),
        lambda a: check_symbolic(a, sp.Symbol("x")),
        lambda a: check_true(a, correct="yes", wrong="no"),
    ],
    ids=["matrix", "number", "angles", "symbolic", "true"],
)
@pytest.mark.parametrize("placeholder", [..., None], ids=["ellipsis", "none"])
def test_unanswered_exercise_says_not_yet(call, placeholder) -> None:
    result = call(placeholder)
    assert result.passed is None
    assert repr(result).startswith(NOT_YET)
    assert "..." in result.message  # tells the learner what to replace


# --- check_matrix ------------------------------------------------------------------------------


def test_matrix_correct() -> None:
    result = check_matrix([[0, -1, 0], [1, 0, 0], [0, 0, 1]], QUARTER_Z)
    assert result.passed is True
    assert result.message.startswith("correct")


def test_matrix_within_tolerance_is_correct_and_reports_the_difference() -> None:
    answer = QUARTER_Z + 1e-12
    result = check_matrix(answer, QUARTER_Z)
    assert result.passed is True
    assert numbers_in(result.message)[-1] == pytest.approx(1e-12, rel=0.1)


def test_matrix_off_names_the_entry_and_the_numbers() -> None:
    answer = QUARTER_Z.copy()
    answer[2, 1] = 0.25
    result = check_matrix(answer, QUARTER_Z, name="R")
    assert result.passed is False
    assert result.message.startswith("off: R")
    assert "(2, 1)" in result.message
    assert "0.25" in result.message  # by how much, and what the learner has
    assert "expected 0" in result.message
    assert "transpose" not in result.message


def test_matrix_tolerance_is_respected() -> None:
    answer = QUARTER_Z + 1e-6
    assert check_matrix(answer, QUARTER_Z).passed is False
    assert check_matrix(answer, QUARTER_Z, atol=1e-5).passed is True


def test_matrix_transpose_gets_a_hint() -> None:
    result = check_matrix(QUARTER_Z.T, QUARTER_Z)
    assert result.passed is False
    assert "transpose" in result.message
    assert "2" in result.message  # the largest difference, -1 against 1


def test_matrix_transpose_hint_works_on_stacks() -> None:
    stack = np.stack([QUARTER_Z, np.eye(3)])
    result = check_matrix(np.swapaxes(stack, -1, -2), stack)
    assert result.passed is False
    assert "transpose" in result.message


def test_matrix_wrong_shape() -> None:
    result = check_matrix(np.eye(2), np.eye(3))
    assert result.passed is False
    assert "(2, 2)" in result.message
    assert "(3, 3)" in result.message


@pytest.mark.parametrize("answer", ["a rotation", {"a": 1}, [[1, 2], [3]], object()])
def test_matrix_wrong_type(answer) -> None:
    result = check_matrix(answer, np.eye(2))
    assert result.passed is False
    assert result.message.startswith("off")
    assert type(answer).__name__ in result.message


def test_matrix_with_nan_is_off_not_an_error() -> None:
    answer = QUARTER_Z.copy()
    answer[0, 0] = np.nan
    result = check_matrix(answer, QUARTER_Z)
    assert result.passed is False
    assert "nan" in result.message


# --- check_number ------------------------------------------------------------------------------


def test_number_correct() -> None:
    result = check_number(np.sqrt(2.0) / 2, 0.7071067811865476)
    assert result.passed is True
    assert result.message.startswith("correct")
    assert "0.707107" in result.message


def test_number_accepts_numpy_scalars_and_zero_dim_arrays() -> None:
    assert check_number(np.float32(0.5), 0.5).passed is True
    assert check_number(np.array(0.5), 0.5).passed is True


def test_number_off_gives_both_values_and_the_difference() -> None:
    result = check_number(86.4, 90.0, name="the attitude")
    assert result.passed is False
    assert result.message.startswith("off: the attitude")
    assert numbers_in(result.message) == pytest.approx([86.4, 90.0, 3.6])


def test_number_tolerance() -> None:
    assert check_number(1.0 + 1e-8, 1.0).passed is False
    assert check_number(1.0 + 1e-8, 1.0, atol=1e-7).passed is True


def test_number_wrong_shape() -> None:
    result = check_number([1.0, 2.0], 1.0)
    assert result.passed is False
    assert "(2,)" in result.message


@pytest.mark.parametrize("answer", ["ninety", [1, [2]], object()])
def test_number_wrong_type(answer) -> None:
    result = check_number(answer, 1.0)
    assert result.passed is False
    assert type(answer).__name__ in result.message


def test_number_nan_is_off() -> None:
    result = check_number(float("nan"), 1.0)
    assert result.passed is False
    assert "nan" in result.message


# --- check_angles ------------------------------------------------------------------------------


def test_angles_identical_triple() -> None:
    result = check_angles([0.3, -0.2, 1.1], [0.3, -0.2, 1.1])
    assert result.passed is True
    assert result.message == "correct: these angles give the reference rotation"


@pytest.mark.parametrize(
    ("answer", "reference", "seq"),
    [
        # Tait–Bryan: (a, b, c) and (a + 180°, 180° − b, c + 180°) are the same rotation.
        ([210.0, 160.0, 190.0], [30.0, 20.0, 10.0], "ZYX"),
        ([-150.0, -110.0, 100.0], [30.0, -70.0, -80.0], "xyz"),
        # Proper Euler: (a, b, c) and (a + 180°, −b, c + 180°).
        ([220.0, -50.0, 190.0], [40.0, 50.0, 10.0], "ZXZ"),
        # Gimbal lock at pitch +90° (Rose, eq 4b): only roll − yaw matters.
        ([0.0, 90.0, -20.0], [30.0, 90.0, 10.0], "ZYX"),
        # Gimbal lock at pitch −90° (Rose, eq 4a): only roll + yaw matters.
        ([40.0, -90.0, 0.0], [30.0, -90.0, 10.0], "ZYX"),
        # A full turn added to an outer angle.
        ([390.0, 20.0, -350.0], [30.0, 20.0, 10.0], "YZX"),
    ],
)
def test_angles_equivalent_triples_are_accepted(answer, reference, seq) -> None:
    result = check_angles(answer, reference, seq=seq, degrees=True)
    assert result.passed is True, result.message
    assert result.message.startswith("correct")
    assert "differ from the reference angles" in result.message


def test_angles_in_radians() -> None:
    reference = np.radians([30.0, 20.0, 10.0])
    equivalent = np.radians([210.0, 160.0, 190.0])
    assert check_angles(equivalent, reference).passed is True
    assert check_angles([30.0, 20.0, 10.0], reference).passed is False  # degrees given as radians


def test_angles_off_names_the_sequence_and_the_unit() -> None:
    result = check_angles([10.0, 20.0, 30.0], [30.0, 20.0, 10.0], seq="ZYX", degrees=True)
    assert result.passed is False
    assert result.message.startswith("off")
    assert "'ZYX'" in result.message
    assert "°" in result.message
    radians = check_angles([0.1, 0.2, 0.3], [0.3, 0.2, 0.1])
    assert "rad" in radians.message


def test_angles_off_reports_how_far_the_matrices_are() -> None:
    # Yaw 0 against yaw 180°: the first two rows flip sign, a difference of 2.
    result = check_angles([0.0, 0.0, 0.0], [180.0, 0.0, 0.0], degrees=True)
    assert result.passed is False
    assert "up to 2" in result.message


def test_angles_depend_on_the_sequence() -> None:
    # The same numbers in two conventions are two different rotations.
    same = check_angles([30.0, 20.0, 10.0], [30.0, 20.0, 10.0], seq="xyz", degrees=True)
    reversed_order = check_angles([10.0, 20.0, 30.0], [30.0, 20.0, 10.0], seq="xyz", degrees=True)
    assert same.passed is True
    assert reversed_order.passed is False


def test_angles_batch() -> None:
    reference = [[30.0, 20.0, 10.0], [0.0, 90.0, 0.0]]
    assert check_angles([[210.0, 160.0, 190.0], [45.0, 90.0, 45.0]], reference, degrees=True)
    result = check_angles([[30.0, 20.0, 10.0], [0.0, 80.0, 0.0]], reference, degrees=True)
    assert result.passed is False


def test_angles_wrong_shape() -> None:
    result = check_angles([0.1, 0.2], [0.1, 0.2, 0.3])
    assert result.passed is False
    assert "(2,)" in result.message
    assert "(3,)" in result.message


@pytest.mark.parametrize("answer", ["thirty", [0.1, [0.2], 0.3]])
def test_angles_wrong_type(answer) -> None:
    result = check_angles(answer, [0.1, 0.2, 0.3])
    assert result.passed is False
    assert type(answer).__name__ in result.message


@pytest.mark.parametrize("bad", [np.nan, np.inf])
def test_angles_not_finite_is_off_not_an_error(bad) -> None:
    # asin of a number just above 1 gives NaN: the learner gets feedback, not a traceback.
    result = check_angles([0.1, bad, 0.3], [0.1, 0.2, 0.3])
    assert result.passed is False
    assert "NaN" in result.message


# --- check_symbolic ----------------------------------------------------------------------------

u, v, w = sp.symbols("u v w", real=True)


def test_symbolic_expressions() -> None:
    result = check_symbolic(sp.cos(v) ** 2, 1 - sp.sin(v) ** 2)
    assert result.passed is True
    assert result.message.startswith("correct")


def test_symbolic_accepts_strings() -> None:
    assert check_symbolic("2*sin(x)*cos(x)", sp.sin(2 * sp.Symbol("x"))).passed is True


def test_symbolic_off_shows_the_difference() -> None:
    result = check_symbolic(sp.sin(u) + 1, sp.sin(u), name="r32")
    assert result.passed is False
    assert result.message.startswith("off: r32")
    assert result.message.endswith("by 1")


def _rz(a):
    return sp.Matrix([[sp.cos(a), -sp.sin(a), 0], [sp.sin(a), sp.cos(a), 0], [0, 0, 1]])


def _rx(a):
    return sp.Matrix([[1, 0, 0], [0, sp.cos(a), -sp.sin(a)], [0, sp.sin(a), sp.cos(a)]])


def test_symbolic_matrices_equal() -> None:
    # Two turns about z add up: Rz(w) Rz(u) = Rz(w + u), entry by entry after simplification.
    result = check_symbolic(_rz(w) * _rz(u), _rz(w + u))
    assert result.passed is True
    assert result.message.startswith("correct")


def test_symbolic_matrices_differ() -> None:
    # The product order matters: Rz Rx is not Rx Rz.
    result = check_symbolic(_rx(u) * _rz(w), _rz(w) * _rx(u), name="your product")
    assert result.passed is False
    assert result.message.startswith("off: your product differs")
    assert "Matrix" in result.message


def test_symbolic_matrix_shape_mismatch() -> None:
    result = check_symbolic(sp.eye(2), sp.eye(3))
    assert result.passed is False
    assert "could not be compared" in result.message


def test_symbolic_unparsable() -> None:
    result = check_symbolic("sin(u", sp.sin(u))
    assert result.passed is False
    assert "could not be compared" in result.message


def test_symbolic_matrix_against_expression() -> None:
    result = check_symbolic(sp.eye(3), sp.Integer(1))
    assert result.passed is False
    assert result.message.startswith("off")


# --- check_true --------------------------------------------------------------------------------


@pytest.mark.parametrize("answer", [True, np.True_, np.bool_(True)])
def test_true_accepts_true(answer) -> None:
    result = check_true(answer, correct="the determinant is 1", wrong="look at the determinant")
    assert result.passed is True
    assert result.message == "correct: the determinant is 1"


@pytest.mark.parametrize("answer", [False, np.False_, 1, "True", [True]])
def test_true_rejects_anything_else(answer) -> None:
    result = check_true(answer, correct="the determinant is 1", wrong="look at the determinant")
    assert result.passed is False
    assert result.message == "off: look at the determinant"
