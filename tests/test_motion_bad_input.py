"""Every bad input of the Euler-rate conversions and of the integration step: type and message.

The same rules as everywhere (``tests/test_bad_input.py``): numbers are real and finite, shapes
are named, rotation matrices are rotations (or ``repair=True`` is asked for), a frame is one of
two words. Flags and tolerances are held to the rules by ``tests/test_api.py`` for every public
function. Inputs are never modified, nothing is printed, and no warning is left over.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
import pytest
from bad_numbers import bad_values
from numpy.testing import assert_array_equal
from scipy.spatial.transform import Rotation

from eulerlib import (
    angular_velocity_to_euler_rates,
    euler_rates_to_angular_velocity,
    integrate_angular_velocity,
)

R0 = Rotation.from_euler("ZYX", [0.3, 0.2, 0.1]).as_matrix()
ANGLES, RATES = [0.1, 0.2, 0.3], [1.0, -2.0, 0.5]

#: name → (call with one argument replaced, the argument's name, a valid value of it)
ARGUMENTS: dict[str, tuple[Callable[[Any], object], str, Any]] = {
    "rates to omega, angles": (
        lambda x: euler_rates_to_angular_velocity(x, RATES),
        "angles",
        ANGLES,
    ),
    "rates to omega, rates": (lambda x: euler_rates_to_angular_velocity(ANGLES, x), "rates", RATES),
    "omega to rates, angles": (
        lambda x: angular_velocity_to_euler_rates(x, RATES),
        "angles",
        ANGLES,
    ),
    "omega to rates, omega": (lambda x: angular_velocity_to_euler_rates(ANGLES, x), "omega", RATES),
    "integrate, R": (lambda x: integrate_angular_velocity(x, RATES, 0.1), "R", R0),
    "integrate, omega": (lambda x: integrate_angular_velocity(R0, x, 0.1), "omega", RATES),
    "integrate, dt": (lambda x: integrate_angular_velocity(R0, RATES, x), "dt", 0.1),
}


@pytest.mark.parametrize("key", sorted(ARGUMENTS))
def test_numbers_are_real_and_finite(key: str) -> None:
    call, name, valid = ARGUMENTS[key]
    call(valid)
    for bad, error, words in bad_values(valid):
        with pytest.raises(error, match=rf"^{name} {words}"):
            call(bad)


@pytest.mark.parametrize("key", sorted(ARGUMENTS))
def test_wrong_shapes_are_named(key: str) -> None:
    call, name, _ = ARGUMENTS[key]
    if name == "dt":
        return  # any shape that broadcasts
    if name == "R":
        bad, words = np.eye(4), r"R must have shape \(\.\.\., 3, 3\), got shape \(4, 4\)"
    else:
        bad, words = [1.0, 2.0], rf"{name} must have shape \(\.\.\., 3\), got shape \(2,\)"
    with pytest.raises(ValueError, match=rf"^{words}$"):
        call(bad)


def test_shapes_that_do_not_broadcast() -> None:
    with pytest.raises(ValueError, match=r"leading shapes of angles \(2,\) and rates \(3,\) do"):
        euler_rates_to_angular_velocity(np.zeros((2, 3)), np.zeros((3, 3)))
    with pytest.raises(ValueError, match=r"leading shapes of angles \(2,\) and omega \(3,\) do"):
        angular_velocity_to_euler_rates(np.zeros((2, 3)), np.zeros((3, 3)))
    with pytest.raises(ValueError, match=r"leading shapes of R \(2,\), omega \(\) and dt \(3,\)"):
        integrate_angular_velocity(np.stack([R0, R0]), RATES, np.zeros(3))


CALLS_WITH_FRAME: list[Callable[..., object]] = [
    lambda **k: euler_rates_to_angular_velocity(ANGLES, RATES, **k),
    lambda **k: angular_velocity_to_euler_rates(ANGLES, RATES, **k),
    lambda **k: integrate_angular_velocity(R0, RATES, 0.1, **k),
]


@pytest.mark.parametrize("call", CALLS_WITH_FRAME)
def test_frame_is_body_or_space_in_any_case(call: Callable[..., Any]) -> None:
    assert_array_equal(call(frame="Body"), call(frame="body"))
    assert_array_equal(call(frame=" SPACE "), call(frame="space"))
    with pytest.raises(ValueError, match=r"^frame must be 'body' or 'space', got 'world'$"):
        call(frame="world")
    for bad, kind in ((None, "NoneType"), (1, "int"), (True, "bool"), (["body"], "list")):
        with pytest.raises(
            TypeError, match=rf"^frame must be 'body' or 'space' \(a string\), got {kind}$"
        ):
            call(frame=bad)


def test_seq_is_a_sequence_or_a_preset() -> None:
    for function in (euler_rates_to_angular_velocity, angular_velocity_to_euler_rates):
        with pytest.raises(ValueError, match=r"^seq 'ZZX' is neither a preset"):
            function(ANGLES, RATES, "ZZX")
        with pytest.raises(TypeError, match=r"^seq must be a convention"):
            function(ANGLES, RATES, 3)


REFLECTION = np.diag([1.0, 1.0, -1.0])
SHEARED = np.array([[1.0, 0.1, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])


def test_the_attitude_must_be_a_rotation() -> None:
    with pytest.raises(ValueError, match=r"^R has determinant -1: a reflection"):
        integrate_angular_velocity(REFLECTION, RATES, 0.1)
    with pytest.raises(ValueError, match=r"^R is not a rotation matrix: .*pass repair=True"):
        integrate_angular_velocity(SHEARED, RATES, 0.1)
    with pytest.raises(ValueError, match=r"^R at index \(2,\) is not a rotation matrix"):
        integrate_angular_velocity(np.stack([R0, R0, 1.01 * R0]), RATES, 0.1)
    with pytest.raises(ValueError, match=r"^R is singular \(rank 0"):
        integrate_angular_velocity(np.zeros((3, 3)), RATES, 0.1, repair=True)


def test_inputs_are_never_modified_and_nothing_is_printed(capsys, rng) -> None:
    R = Rotation.random(5, rng=rng).as_matrix()
    angles = rng.uniform(-3, 3, (5, 3))
    angles[0, 1] = np.pi / 2  # one locked attitude
    rates = rng.normal(size=(5, 3))
    dt = rng.uniform(0, 1, 5)
    before = [a.copy() for a in (R, angles, rates, dt)]
    euler_rates_to_angular_velocity(angles, rates, "rose", frame="space")
    angular_velocity_to_euler_rates(angles, rates, "baker", warn=False)
    angular_velocity_to_euler_rates(angles, rates, "zxz", degrees=True)
    integrate_angular_velocity(R, rates, dt)
    integrate_angular_velocity(R, rates, dt, frame="space", repair=True)
    for original, now in zip(before, (R, angles, rates, dt), strict=True):
        assert_array_equal(now, original)
    assert capsys.readouterr() == ("", "")
