"""The argument rules of eulerlib.symbolic: every public function, every bad argument.

The functions are found by introspecting ``eulerlib.symbolic.__all__``, so a function added
later must get a valid call here and is then held to the same rules. Every bad argument gives a
``TypeError`` or ``ValueError`` whose message starts with the argument's name; never an
``AttributeError``, and never SymPy's own ``SympifyError`` (text is not evaluated at all).
"""

from __future__ import annotations

import inspect
import subprocess
import sys
from fractions import Fraction
from typing import Any

import numpy as np
import pytest
import sympy as sp

import eulerlib
from eulerlib import symbolic

T = sp.Symbol("t", real=True)
W, V, U = sp.symbols("w v u", real=True)
THETA = sp.Function("theta", real=True)(T)

PUBLIC = {name: getattr(symbolic, name) for name in symbolic.__all__}
FUNCTIONS = {name: f for name, f in PUBLIC.items() if inspect.isfunction(f)}

#: One valid call of every public function, as keyword arguments.
VALID_CALLS: dict[str, dict[str, Any]] = {
    "angular_velocity_from_matrix": {"R": symbolic.elementary_matrix("z", THETA), "t": T},
    "angular_velocity_jacobian": {"angles": (W, V, U), "seq": "ZYX"},
    "axis_angle_matrix": {"axis": (0, 0, 1), "angle": T},
    "elementary_matrix": {"axis": "x", "angle": T},
    "euler_matrix": {"angles": (W, V, U), "seq": "ZYX"},
    "euler_symbols": {"seq": "ZYX"},
    "extraction_relations": {"angles": (W, V, U), "seq": "ZYX"},
    "gimbal_lock_matrix": {"angles": (W, U), "seq": "ZYX", "pole": 90},
    "jacobian_determinant": {"angles": (W, V, U), "seq": "ZYX"},
    "quaternion_conjugate": {"q": (1, 0, 0, 0)},
    "quaternion_from_axis_angle": {"axis": (0, 0, 1), "angle": T},
    "quaternion_product": {"p": (1, 0, 0, 0), "q": (0, 1, 0, 0)},
    "quaternion_to_matrix": {"q": (1, 0, 0, 0)},
    "rodrigues_matrix": {"axis": (0, 0, 1), "angle": T},
    "skew": {"v": (1, 2, 3)},
}

NOT_AN_EXPRESSION = [None, "1/", "import os", "x y", "t", b"t", [T], True, 1j, sp.I]
NOT_FINITE = [float("nan"), float("inf"), sp.oo, sp.nan, sp.zoo]
BAD_SEQ = [None, 123, "ZZX", "ZyX", "roses", ""]

#: Bad values for each kind of argument: (value, exception).
BAD: dict[str, list[Any]] = {
    "expression": NOT_AN_EXPRESSION + NOT_FINITE,
    "seq": BAD_SEQ,
    "frame": [None, "world", 1, True],
    "pole": [None, True, "90", 45, 1, sp.pi / 2],
    "axis name": [None, True, 1.0, "w", 3, "xy", [0]],
    "matrix": [None, "R", sp.eye(2), [[1, 0], [0, 1]], sp.Matrix(3, 3, [T] * 8 + ["x"])],
    "symbol": [None, "t", 1, W + 1, THETA],
}


def sequence_of(count: int) -> list[Any]:
    """Bad values for an argument that holds ``count`` expressions."""
    good = [T] * count
    return [
        None,
        "1/",
        "x y",
        T,
        1.5,
        {"a": 1},
        good[:-1],
        [*good, T],
        [*good[:-1], "import os"],
        [*good[:-1], [T]],
        [*good[:-1], None],
        [*good[:-1], float("nan")],
        sp.ones(2, 2),
        np.zeros((count, 1)),
    ]


KINDS: dict[tuple[str, str], list[Any]] = {}
for _name, _function in FUNCTIONS.items():
    for _parameter in inspect.signature(_function).parameters:
        if _parameter in ("angle",):
            KINDS[_name, _parameter] = BAD["expression"]
        elif _parameter == "axis":
            KINDS[_name, _parameter] = (
                BAD["axis name"] if _name == "elementary_matrix" else sequence_of(3)
            )
        elif _parameter == "angles":
            KINDS[_name, _parameter] = sequence_of(2 if _name == "gimbal_lock_matrix" else 3)
        elif _parameter in ("p", "q"):
            KINDS[_name, _parameter] = sequence_of(4)
        elif _parameter == "v":
            KINDS[_name, _parameter] = sequence_of(3)
        elif _parameter == "R":
            KINDS[_name, _parameter] = BAD["matrix"]
        elif _parameter == "t":
            KINDS[_name, _parameter] = BAD["symbol"]
        else:
            KINDS[_name, _parameter] = BAD.get(_parameter, [])
CASES = [
    pytest.param(name, parameter, index, id=f"{name}-{parameter}-{index}")
    for (name, parameter), values in KINDS.items()
    for index, value in enumerate(values)
    # None is the documented default of euler_symbols' seq
    if not (
        value is None and inspect.signature(FUNCTIONS[name]).parameters[parameter].default is None
    )
]


def test_every_public_function_has_a_valid_call_here() -> None:
    assert set(VALID_CALLS) == set(FUNCTIONS)
    for name, kwargs in VALID_CALLS.items():
        FUNCTIONS[name](**kwargs)
        assert set(kwargs) | {"frame"} >= set(inspect.signature(FUNCTIONS[name]).parameters)
    unknown = [key for key, values in KINDS.items() if not values]
    assert not unknown, f"no bad values listed for {unknown}"


def test_everything_public_is_documented_with_an_example() -> None:
    for name, value in PUBLIC.items():
        doc = inspect.getdoc(value) or ""
        assert "Examples" in doc, f"{name} has no Examples section"
        if inspect.isfunction(value):
            assert "Raises" in doc or name == "euler_symbols", f"{name} does not say what it raises"


@pytest.mark.parametrize(("name", "parameter", "index"), CASES)
def test_bad_arguments_name_the_argument(
    name: str, parameter: str, index: int, capsys: pytest.CaptureFixture[str]
) -> None:
    bad = KINDS[name, parameter][index]
    kwargs = {**VALID_CALLS[name], parameter: bad}
    with pytest.raises((TypeError, ValueError)) as caught:
        FUNCTIONS[name](**kwargs)
    assert not isinstance(caught.value, sp.SympifyError)
    message = str(caught.value)
    assert message.startswith((f"{parameter} ", f"{parameter}[")), message
    assert capsys.readouterr() == ("", "")


@pytest.mark.parametrize("frame", ["body", "space"])
def test_frame_is_checked_by_every_function_that_takes_it(frame: str) -> None:
    for name, function in FUNCTIONS.items():
        if "frame" in inspect.signature(function).parameters:
            function(**VALID_CALLS[name], frame=frame.upper())
            with pytest.raises(ValueError, match=r"^frame must be 'body' or 'space'"):
                function(**VALID_CALLS[name], frame="world")


def test_text_is_never_evaluated() -> None:
    with pytest.raises(TypeError, match=r"not text .* never evaluated.*sp\.Symbol\('t'\)"):
        symbolic.elementary_matrix("x", "__import__('os').getcwd()")
    with pytest.raises(TypeError, match=r"^angles\[1\] must be .* not text"):
        symbolic.euler_matrix((W, "v", U))


def test_numbers_of_every_kind_are_expressions() -> None:
    expected = symbolic.elementary_matrix("z", sp.Rational(1, 2))
    for half in (Fraction(1, 2), sp.Rational(1, 2)):
        assert symbolic.elementary_matrix("z", half) == expected
    for half in (0.5, np.float64(0.5), np.float32(0.5)):
        floats = np.array(symbolic.elementary_matrix("z", half), dtype=float)
        assert np.allclose(floats, eulerlib.rot_z(0.5), atol=1e-15)
    assert symbolic.elementary_matrix("z", np.int64(0)) == sp.eye(3)


# --- one axis parser for the symbolic and the numeric elementary rotation ---------------------

GOOD_AXES = ["x", "y", "z", "X", "Y", "Z", 0, 1, 2, np.int64(2), np.int8(0), np.uint16(1)]
BAD_AXES = [True, False, np.bool_(True), 1.0, np.float64(0.0), None, [0], (1,), "w", "xy", ""]
BAD_AXES += [3, -1, np.int64(3), "x ", b"x", np.array(1)]


@pytest.mark.parametrize("axis", GOOD_AXES, ids=repr)
def test_good_axes_side_by_side(axis: object) -> None:
    symbolic_matrix = np.array(symbolic.elementary_matrix(axis, 0.3), dtype=float)
    assert np.allclose(symbolic_matrix, eulerlib.elementary_rotation(axis, 0.3), atol=1e-15)


@pytest.mark.parametrize("axis", BAD_AXES, ids=repr)
def test_bad_axes_side_by_side(axis: object) -> None:
    with pytest.raises((TypeError, ValueError)) as numeric_error:
        eulerlib.elementary_rotation(axis, 0.3)
    with pytest.raises((TypeError, ValueError)) as symbolic_error:
        symbolic.elementary_matrix(axis, 0.3)
    assert type(symbolic_error.value) is type(numeric_error.value)
    assert str(symbolic_error.value) == str(numeric_error.value)
    assert str(symbolic_error.value).startswith("axis must be 'x', 'y', 'z' (either case)")
    expected = (
        ValueError
        if isinstance(axis, (str, int, np.integer)) and not isinstance(axis, (bool, np.bool_))
        else TypeError
    )
    assert type(symbolic_error.value) is expected


# --- light import -----------------------------------------------------------------------------


def test_import_eulerlib_does_not_load_sympy() -> None:
    code = "import sys, eulerlib; sys.exit('sympy' in sys.modules)"
    assert subprocess.run([sys.executable, "-c", code], check=False).returncode == 0
