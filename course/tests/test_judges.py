"""The judges of the exercises: equally right answers pass, typical mistakes get their diagnosis.

References are written out here or built by SciPy, never by the judge under test. The messages
must never contain the reference (the check cell a student sees names the exercise and the answer
only, so a wrong answer must not be answered with the right one).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from scipy.spatial.transform import Rotation

from eulerlib_course.exercises import (
    AnglesJudge,
    ArrayJudge,
    ChoiceJudge,
    Constraint,
    ExpressionJudge,
    Feedback,
    Mistake,
    NumberJudge,
    QuaternionJudge,
    check,
    exercises,
    given,
)
from eulerlib_course.exercises.judges import rounded_to
from eulerlib_course.exercises.reading import Unreadable, read_numbers

QUARTER_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])  # typed in


def verdict(judge, answer):
    try:
        return judge.judge(answer)
    except Unreadable as reason:
        return type("V", (), {"status": "off", "message": str(reason)})()


# --- reading answers -------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("answer", "words"),
    [
        ("0.5", "is text"),
        (b"0.5", "is text"),
        (True, "yes/no"),
        (np.True_, "yes/no"),
        (None, "is None"),
        (1 + 2j, "imaginary part"),
        ([1.0, "2", 3.0], "not a number"),
        ([1.0, None, 3.0], "not a number"),
        (np.ma.masked_array([1.0]), "masked"),
        (float("nan"), "NaN"),
        ([1.0, 2.0], "shape (2,)"),
        (sp.Symbol("x") + 1, "symbol(s) x"),
    ],
)
def test_unreadable_answers_say_why(answer, words) -> None:
    shape = (2,) if isinstance(answer, np.ma.MaskedArray) else ()
    shape = (3,) if isinstance(answer, list) else shape
    with pytest.raises(Unreadable, match=words.replace("(", r"\(").replace(")", r"\)")):
        read_numbers(answer, shape, "your answer")


def test_sympy_numbers_and_real_complex_numbers_are_read() -> None:
    assert read_numbers(sp.Rational(1, 2), (), "x") == 0.5
    assert read_numbers(sp.Matrix([[1, 0], [0, 1]]), (2, 2), "x").tolist() == [[1, 0], [0, 1]]
    assert read_numbers(2 + 0j, (), "x") == 2.0


# --- numbers ---------------------------------------------------------------------------------


def test_number_modulo_a_turn_and_units() -> None:
    judge = NumberJudge(30.0, unit="deg", modulo=360.0, what="the angle")
    for right in (30, 390, -330, 30 + 1e-12):
        assert judge.judge(right).status == "correct"
    assert "radians" in judge.judge(math.radians(30)).message
    assert "wrong sign" in judge.judge(-30).message
    assert judge.judge(31).status == "off"
    in_radians = NumberJudge(math.pi / 6, unit="rad", modulo=2 * math.pi)
    assert "degrees" in in_radians.judge(30).message
    assert in_radians.judge(math.pi / 6 + 2 * math.pi).status == "correct"


def test_number_without_modulo_refuses_a_turn_more() -> None:
    assert NumberJudge(13.0).judge(13.0 + 360).status == "off"


def test_number_mistakes_come_with_their_message() -> None:
    judge = NumberJudge(13.0, mistakes=(Mistake(19.0, "you added the coordinates"),))
    assert judge.judge(19).message == "you added the coordinates"


def test_a_wrong_number_is_not_answered_with_the_reference() -> None:
    message = NumberJudge(13.0).judge(12.0).message
    assert "13" not in message


@pytest.mark.parametrize("tol", [float("nan"), -1.0, "1e-9", None])
def test_tolerances_are_checked(tol) -> None:
    with pytest.raises((TypeError, ValueError), match="tol"):
        NumberJudge(1.0, tol=tol)


# --- arrays ----------------------------------------------------------------------------------


def test_matrix_diagnoses() -> None:
    judge = ArrayJudge(QUARTER_Z, what="your R", rotation=True)
    assert judge.judge(QUARTER_Z.tolist()).status == "correct"
    assert "transpose" in judge.judge(QUARTER_Z.T).message
    assert "reflection" in judge.judge(QUARTER_Z @ np.diag([1.0, 1.0, -1.0])).message
    assert "not orthonormal" in judge.judge(2 * QUARTER_Z).message
    other = Rotation.from_euler("x", 30, degrees=True).as_matrix()
    message = judge.judge(other).message
    assert "is not it" in message and "-1" not in message and "entr" not in message


def test_complex_matrix_is_refused_not_accepted() -> None:
    message = verdict(ArrayJudge(QUARTER_Z), QUARTER_Z + 1j).message
    assert "imaginary" in message


def test_vector_diagnoses() -> None:
    judge = ArrayJudge([0.0, 2.0, 1.0], what="the point", rotation=True)
    assert judge.judge([0, 2, 1]).status == "correct"
    assert "opposite way" in judge.judge([0, -2, -1]).message
    assert "never changes a length" in judge.judge([0, 2, 2]).message
    rates = ArrayJudge([0.0, 2.0, 1.0], what="the rates")  # not a turned point: no length rule
    assert "length" not in rates.judge([0, 2, 2]).message


# --- angles ----------------------------------------------------------------------------------


def scipy_matrix(seq: str, angles) -> np.ndarray:
    return Rotation.from_euler(seq, angles, degrees=True).as_matrix()


def test_angles_equal_modulo_a_turn_and_the_other_branch_pass() -> None:
    judge = AnglesJudge([-100.0, 35.0, 160.0], "ZYX")
    for right in ([-100, 35, 160], [260, 35, -200], [80, 145, -20], [80, 145, 340]):
        assert np.allclose(scipy_matrix("ZYX", right), scipy_matrix("ZYX", [-100, 35, 160]))
        assert judge.judge(right).status == "correct", right


@pytest.mark.parametrize(
    ("answer", "words"),
    [
        (np.radians([-100, 35, 160]), "look like radians"),
        ([160, 35, -100], "reverse order"),
        ([-100, -35, 160], "pitch has the wrong sign"),
        ([80, 35, 160], "yaw is off by 180°"),
    ],
)
def test_angle_mistakes_are_diagnosed(answer, words) -> None:
    judge = AnglesJudge([-100.0, 35.0, 160.0], "rose")
    result = judge.judge(answer)
    assert result.status == "off"
    assert words in result.message


def test_an_exercises_own_angle_mistake_is_recognised_by_its_rotation() -> None:
    # atan for both outer angles: yaw and roll each off by 180°, which no one-angle check sees
    atan_both = [80.0, 35.0, -20.0]
    judge = AnglesJudge(
        [-100.0, 35.0, 160.0],
        "rose",
        mistakes=(Mistake(atan_both, "yaw and roll are both off by 180°"),),
    )
    assert judge.judge(atan_both).message == "yaw and roll are both off by 180°"
    same_mistake = [-280.0, 35.0, 340.0]  # written with other turns
    assert np.allclose(scipy_matrix("ZYX", same_mistake), scipy_matrix("ZYX", atan_both))
    assert judge.judge(same_mistake).message == "yaw and roll are both off by 180°"
    # other wrong answers keep their own diagnosis, and right ones pass
    assert "pitch has the wrong sign" in judge.judge([-100, -35, 160]).message
    assert "another rotation" in judge.judge([10, 20, 30]).message
    assert judge.judge([80, 145, -20]).status == "correct"


def test_intrinsic_read_as_extrinsic_is_diagnosed() -> None:
    angles = [30.0, 20.0, 10.0]
    extrinsic = Rotation.from_matrix(scipy_matrix("ZYX", angles)).as_euler("zyx", degrees=True)
    result = AnglesJudge(angles, "ZYX").judge(extrinsic)
    assert "'zyx'" in result.message and "fixed axes" in result.message


def test_constraints_are_enforced_and_named() -> None:
    at_lock = [0.0, 90.0, 45.0]  # yaw 0, roll − yaw = 45
    judge = AnglesJudge(
        at_lock,
        "ZYX",
        constraints=(Constraint(lambda a: abs(a[0]) < 1e-9, "the question asks for yaw = 0"),),
    )
    assert judge.judge([0, 90, 45]).status == "correct"
    result = judge.judge([20, 90, 65])  # the same rotation, yaw not 0
    assert np.allclose(scipy_matrix("ZYX", [20, 90, 65]), scipy_matrix("ZYX", at_lock))
    assert result.status == "off" and "yaw = 0" in result.message


def test_an_exercise_mistake_is_named_when_the_answer_gives_its_rotation() -> None:
    # At pitch +90° only roll − yaw is defined; adding instead of subtracting is the mistake.
    sum_not_difference = Mistake([0.0, 90.0, 95.0], "roll + yaw belongs to pitch −90°")
    judge = AnglesJudge([25.0, 90.0, 70.0], "ZYX", mistakes=(sum_not_difference,))
    same_as_mistake = [15.0, 90.0, 110.0]  # another split of roll − yaw = 95°
    assert np.allclose(scipy_matrix("ZYX", same_as_mistake), scipy_matrix("ZYX", [0, 90, 95]))
    assert not np.allclose(scipy_matrix("ZYX", [0, 90, 95]), scipy_matrix("ZYX", [25, 90, 70]))
    result = judge.judge(same_as_mistake)
    assert result.status == "off" and "roll + yaw" in result.message
    # an answer that is neither right nor the mistake does not get the mistake's message
    other = judge.judge([0.0, 90.0, 10.0])
    assert other.status == "off" and "roll + yaw" not in other.message
    assert judge.judge([0.0, 90.0, 45.0]).status == "correct"


def test_a_far_rotation_gets_no_distance_that_a_search_could_follow() -> None:
    judge = AnglesJudge([10.0, 20.0, 30.0], "ZYX", hint="read each angle off its entries")
    far = [judge.judge(angles).message for angles in ([50, -40, 100], [12, 25, 20])]
    assert far[0] == far[1] and "read each angle off its entries" in far[0]
    assert not any(ch.isdigit() for ch in far[0])


def test_close_is_a_coarse_band_without_a_side() -> None:
    # within a degree of the rotation (SciPy measures it), but not within the tolerance
    judge = AnglesJudge([10.0, 20.0, 30.0], "ZYX")
    near = [[10.3, 20.0, 30.0], [9.7, 20.0, 30.0], [10.0, 20.0, 30.4]]
    for angles in near:
        gap = Rotation.from_euler("ZYX", [[10, 20, 30], angles], degrees=True)
        assert np.degrees((gap[0].inv() * gap[1]).magnitude()) < 1.0
    messages = {judge.judge(angles).message for angles in near}
    assert len(messages) == 1 and "close" in messages.pop()
    number = NumberJudge(30.0, unit="deg", what="your angle")
    assert number.judge(30.4).message == number.judge(29.6).message
    assert "large" not in number.judge(40).message and "small" not in number.judge(20).message
    assert number.judge(40).message == number.judge(20).message


def test_rounded_hand_worked_answers_pass() -> None:
    judge = ArrayJudge([0.5, 0.0, math.sqrt(3) / 2], tol=rounded_to(3))
    assert judge.judge([0.5, 0, 0.866]).status == "correct"
    assert "close" in judge.judge([0.5, 0, 0.86]).message


def test_sympy_symbols_made_again_with_or_without_assumptions() -> None:
    a, b = sp.symbols("a b", real=True)
    judge = ExpressionJudge(sp.cos(a) * sp.sin(b))
    for plain in (sp.symbols("a b"), sp.symbols("a b", positive=True), (a, b)):
        assert judge.judge(sp.cos(plain[0]) * sp.sin(plain[1])).status == "correct"
        assert judge.judge(sp.sin(plain[0]) * sp.sin(plain[1])).status == "off"
    matrix = ExpressionJudge(sp.Matrix([[sp.cos(a), -sp.sin(a)], [sp.sin(a), sp.cos(a)]]))
    x = sp.Symbol("a")
    assert matrix.judge(sp.Matrix([[sp.cos(x), -sp.sin(x)], [sp.sin(x), sp.cos(x)]]))


@pytest.mark.parametrize(
    "answer", [np.float32(0.5), np.float64(0.5), np.array(0.5), 0.5, sp.Rational(1, 2)]
)
def test_numbers_in_any_reasonable_form_are_read(answer) -> None:
    assert NumberJudge(0.5).judge(answer).status == "correct"
    vector = ArrayJudge([0.5, 1.0])
    for form in ([answer, 1], (answer, 1), np.array([answer, 1], dtype=object)):
        assert vector.judge(form).status == "correct"


@pytest.mark.parametrize(
    ("answer", "words"), [("x", "is text"), (None, "is None"), (2j, "imaginary")]
)
def test_text_none_and_complex_get_one_line(answer, words) -> None:
    feedback = check("09.1", answer)
    assert feedback.status == "off" and words in feedback.message and "\n" not in str(feedback)


@pytest.mark.parametrize("blank", [..., "", "   "])
def test_a_blank_answer_is_no_answer_yet(blank) -> None:
    feedback = check("09.1", blank)
    assert feedback.status == "not yet" and "no answer yet" in feedback.message


# --- quaternions -----------------------------------------------------------------------------


def test_quaternion_double_cover_and_layouts() -> None:
    q = Rotation.from_euler("z", 60, degrees=True).as_quat()  # (x, y, z, w)
    judge = QuaternionJudge(q)
    assert judge.judge(q).status == "correct"
    assert "double cover" in judge.judge(-q).message
    assert "wrong order" in judge.judge(np.roll(q, 1)).message  # (w, x, y, z)
    conjugate = q * [-1, -1, -1, 1]
    assert "conjugate" in judge.judge(conjugate).message
    assert "not of length 1" in judge.judge(2 * q).message
    first = QuaternionJudge(np.roll(q, 1), scalar_first=True)
    assert first.judge(np.roll(q, 1)).status == "correct"
    assert "scalar-first" in first.judge(q).message


# --- expressions -----------------------------------------------------------------------------


def test_expressions_are_simplified_before_judging() -> None:
    a, b = sp.symbols("a b", real=True)
    rx = lambda t: sp.Matrix(  # noqa: E731 - typed in, the oracle
        [[1, 0, 0], [0, sp.cos(t), -sp.sin(t)], [0, sp.sin(t), sp.cos(t)]]
    )
    judge = ExpressionJudge(rx(a + b), what="your product")
    assert judge.judge(rx(a) * rx(b)).status == "correct"  # unsimplified product
    assert "transpose" in judge.judge((rx(a) * rx(b)).T).message
    wrong = judge.judge(rx(a) * rx(-b))
    assert wrong.status == "off" and "entry (1, 1)" in wrong.message
    assert "cos(a + b)" not in wrong.message  # the learner's entry, not the reference's


def test_numeric_matrix_against_an_exact_sympy_matrix() -> None:
    judge = ExpressionJudge(sp.Matrix(QUARTER_Z.astype(int)))
    assert judge.judge(QUARTER_Z).status == "correct"
    assert judge.judge(QUARTER_Z.T).status == "off"


def test_either_sign_when_the_question_allows_it() -> None:
    a, c = sp.symbols("alpha gamma", real=True)
    assert ExpressionJudge(a + c, up_to_sign=True).judge(-a - c).status == "correct"
    assert "sign" in ExpressionJudge(a + c).judge(-a - c).message
    assert "text" in verdict(ExpressionJudge(a + c), "alpha + gamma").message


# --- choices ---------------------------------------------------------------------------------


def test_choices_need_three_options_and_an_explanation_for_each_wrong_one() -> None:
    with pytest.raises(ValueError, match="at least three"):
        ChoiceJudge({"a": "yes", "b": "no"}, "a", {"b": "why"})
    with pytest.raises(ValueError, match="explanation"):
        ChoiceJudge({"a": "1", "b": "2", "c": "3"}, "a", {"b": "why"})
    judge = ChoiceJudge({"a": "1", "b": "2", "c": "3"}, "b", {"a": "too few", "c": "too many"})
    assert judge.judge(" B ").status == "correct"
    assert judge.judge("c").message == "too many"
    assert "one of the options" in judge.judge(True).message


# --- check and given -------------------------------------------------------------------------


def test_check_says_not_yet_for_the_placeholder_and_never_raises_for_an_answer() -> None:
    some = next(iter(exercises()))
    assert check(some, ...).status == "not yet"
    for answer in (None, "text", True, 1j, object(), [[1, 2], [3]], {"a": 1}):
        result = check(some, answer)
        assert isinstance(result, Feedback) and result.status == "off"


def test_check_names_a_wrong_exercise_id() -> None:
    with pytest.raises(ValueError, match=r"no exercise '99\.9'"):
        check("99.9", 1)
    with pytest.raises(TypeError, match="exercise must be an id"):
        check(5.1, 1)  # type: ignore[arg-type]


def test_feedback_reads_as_a_sentence() -> None:
    text = str(Feedback("05.1", "off", "yaw is off by 180°"))
    assert text == "Exercise 05.1 — off: yaw is off by 180°"


def test_given_returns_a_fresh_copy() -> None:
    # An exercise's data is one array or a tuple of arrays; a learner who changes them in place
    # must not change what the next call of given (or the check) sees.
    with_data = [key for key, ex in exercises().items() if ex.given is not None]
    assert with_data
    for key in with_data:
        first = given(key)
        for array in first if isinstance(first, tuple) else (first,):
            array[...] = 0
        again = given(key)
        assert all(
            np.any(array != 0) for array in (again if isinstance(again, tuple) else (again,))
        )


# --- the course's own exercises with SymPy symbols made again ---------------------------------


@pytest.mark.parametrize("assumptions", [{}, {"real": True}, {"positive": True}])
def test_symbolic_exercises_take_symbols_with_or_without_assumptions(assumptions) -> None:
    from eulerlib.symbolic import euler_matrix

    alpha, gamma = sp.symbols("alpha gamma", **assumptions)
    w, v, u = sp.symbols("w v u", **assumptions)
    assert check("03.3", euler_matrix((w, v, u), "zyx")[:, 0]).status == "correct"
    wrong = check("03.3", euler_matrix((w, v, u), "ZYX")[:, 0])
    assert wrong.status == "off" and "moving-axes reading" in wrong.message
    assert check("06.2", alpha + gamma).status == "correct"
    assert check("06.2", alpha - gamma).status == "off"


# --- predictions -------------------------------------------------------------------------------


def test_a_prediction_is_recorded_before_the_computation_that_settles_it() -> None:
    from eulerlib_course.exercises.predictions import forget, prediction, settle

    forget()
    computed = []
    refused = settle("07.2", lambda: computed.append("yaw") or "the yaw")
    assert refused.startswith("predict first") and computed == []
    assert check("07.2", ("a", ...)).status == "not yet"  # the option alone is recorded
    assert prediction("07.2") == ("a", ...)
    assert settle("07.2", lambda: "the yaw") == "the yaw"
    # after the computation the recorded option counts, whatever the cell says now
    late = check("07.2", ("c", 160.0))
    assert late.status == "off" and "made before the computation" in late.message
    assert check("07.2", ("a", 160.0)).status == "off"
    forget()
    assert check("07.2", ("c", 160.0)).status == "correct"
    forget()


def test_predict_refuses_an_exercise_that_is_not_a_prediction() -> None:
    from eulerlib_course.exercises import predict

    with pytest.raises(ValueError, match="not a prediction"):
        predict("05.1", [1, 2, 3])


def test_a_vector_as_a_row_or_a_column_is_the_same_vector() -> None:
    a = sp.Symbol("a", real=True)
    judge = ExpressionJudge(
        sp.Matrix([sp.cos(a), sp.sin(a), 0]),
        mistakes=(Mistake(sp.Matrix([[sp.sin(a), sp.cos(a), 0]]), "sine and cosine swapped"),),
    )
    assert judge.judge(sp.Matrix([[sp.cos(a), sp.sin(a), 0]])).status == "correct"
    assert "swapped" in judge.judge(sp.Matrix([sp.sin(a), sp.cos(a), 0])).message
    assert "not a 3×1 matrix" in judge.judge(sp.eye(3)).message
    assert judge.judge(sp.Matrix([1, 0, 0])).status == "off"
