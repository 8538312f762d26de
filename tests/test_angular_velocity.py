"""Euler-angle rates ⇄ angular velocity, for all 24 sequences, both frames, and at gimbal lock.

Oracles, none of them the code under test: the Jacobian that ``eulerlib.symbolic`` derives in
SymPy from the moved axes; ``ω`` read off ``Ṙ Rᵀ`` (or ``Rᵀ Ṙ``) by central differences of SciPy's
matrices; ``ω`` read off the derivative of the symbolic matrix; a 50-digit evaluation of the
symbolic Jacobian with mpmath; NumPy's pseudo-inverse at lock; hypothesis properties. SciPy has
no Euler-rate conversion of its own.
"""

from __future__ import annotations

import functools
import math
import warnings
from collections.abc import Callable

import mpmath
import numpy as np
import pytest
import sympy as sp
from budget import examples
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp
from mp_reference import EPS, radians_of
from numpy.testing import assert_allclose, assert_array_equal
from scipy.spatial.transform import Rotation
from symbolic_oracles import numeric

import eulerlib
from eulerlib import (
    ALL_SEQUENCES,
    GIMBAL_LOCK_TOLERANCE,
    GimbalLockWarning,
    angular_velocity_to_euler_rates,
    euler_rates_to_angular_velocity,
    get_convention,
)
from eulerlib.symbolic import angular_velocity_from_matrix, angular_velocity_jacobian, euler_matrix

FRAMES = ("body", "space")
SYMBOLS = sp.symbols("alpha beta gamma", real=True)
PRESETS = ("rose", "baker", "ros")


@functools.cache
def jacobian(seq: str, frame: str) -> Callable[..., np.ndarray]:
    """The symbolic Jacobian of ``seq`` as a NumPy function of three angles in radians."""
    return numeric(angular_velocity_jacobian(SYMBOLS, seq, frame=frame), SYMBOLS)


@functools.cache
def mp_jacobian(seq: str, frame: str) -> Callable[..., object]:
    """The same Jacobian, evaluated with mpmath (at the working precision)."""
    return sp.lambdify(SYMBOLS, angular_velocity_jacobian(SYMBOLS, seq, frame=frame), "mpmath")


def oracle_omega(angles: np.ndarray, rates: np.ndarray, seq: str, frame: str) -> np.ndarray:
    J = jacobian(seq, frame)
    return np.array([J(*a) @ r for a, r in zip(angles, rates, strict=True)])


def is_proper(seq: str) -> bool:
    return seq[0].lower() == seq[2].lower()


def poles(seq: str) -> tuple[float, float]:
    return (0.0, 180.0) if is_proper(seq) else (90.0, -90.0)


def vee(skew: np.ndarray) -> np.ndarray:
    return np.array([skew[2, 1], skew[0, 2], skew[1, 0]])


# --- rates → ω ------------------------------------------------------------------------------------


@pytest.mark.parametrize("frame", FRAMES)
@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_rates_to_omega_is_the_symbolic_jacobian(seq: str, frame: str, rng) -> None:
    angles = rng.uniform(-4.0, 4.0, (25, 3))
    rates = rng.normal(size=(25, 3))
    expected = oracle_omega(angles, rates, seq, frame)
    got = euler_rates_to_angular_velocity(angles, rates, seq, frame=frame)
    assert_allclose(got, expected, rtol=0, atol=8 * EPS * np.abs(rates).max())
    in_degrees = euler_rates_to_angular_velocity(
        np.degrees(angles), np.degrees(rates), seq, frame=frame, degrees=True
    )
    assert_allclose(in_degrees, np.degrees(expected), rtol=0, atol=1e-12)


@pytest.mark.parametrize("frame", FRAMES)
@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_omega_is_read_off_scipys_matrices(seq: str, frame: str, rng) -> None:
    """``Rᵀ Ṙ`` (body) or ``Ṙ Rᵀ`` (space) by central differences of ``Rotation.from_euler``."""
    step = 1e-5
    for angles, rates in zip(rng.uniform(-3, 3, (4, 3)), rng.normal(size=(4, 3)), strict=True):
        R = Rotation.from_euler(seq, angles).as_matrix()
        ahead = Rotation.from_euler(seq, angles + step * rates).as_matrix()
        behind = Rotation.from_euler(seq, angles - step * rates).as_matrix()
        R_dot = (ahead - behind) / (2 * step)
        skew = R.T @ R_dot if frame == "body" else R_dot @ R.T
        got = euler_rates_to_angular_velocity(angles, rates, seq, frame=frame)
        assert_allclose(got, vee(skew), rtol=0, atol=1e-9)


@pytest.mark.parametrize("seq", ["ZYX", "xyz", "YZX", "ZXZ", "yxy"])
@pytest.mark.parametrize("frame", FRAMES)
def test_omega_is_read_off_the_derivative_of_the_symbolic_matrix(seq: str, frame: str) -> None:
    t = sp.Symbol("t", real=True)
    functions = [sp.Function(name, real=True)(t) for name in ("a", "b", "c")]
    speeds = sp.symbols("da db dc", real=True)
    omega = angular_velocity_from_matrix(euler_matrix(functions, seq), t, frame=frame)
    values = sp.symbols("A B C", real=True)
    omega = omega.subs({f.diff(t): d for f, d in zip(functions, speeds, strict=True)}).subs(
        dict(zip(functions, values, strict=True))
    )
    evaluate = numeric(omega, (*values, *speeds))
    rng = np.random.default_rng(7)
    for angles, rates in zip(rng.uniform(-3, 3, (5, 3)), rng.normal(size=(5, 3)), strict=True):
        expected = evaluate(*angles, *rates).reshape(3)
        got = euler_rates_to_angular_velocity(angles, rates, seq, frame=frame)
        assert_allclose(got, expected, rtol=0, atol=1e-14)


def test_rose_body_rates_as_typed_in() -> None:
    """The aircraft's p, q, r in Rose's yaw w, pitch v, roll u, typed in from the kinematics."""
    w, v, u = 0.7, -1.1, 2.3
    dw, dv, du = 0.3, -0.8, 1.9
    p = du - dw * math.sin(v)
    q = dv * math.cos(u) + dw * math.sin(u) * math.cos(v)
    r = -dv * math.sin(u) + dw * math.cos(u) * math.cos(v)
    got = euler_rates_to_angular_velocity([w, v, u], [dw, dv, du], "rose")
    assert_allclose(got, [p, q, r], rtol=0, atol=4 * EPS)


def test_extrinsic_is_the_reversed_intrinsic_and_presets_are_their_sequences(rng) -> None:
    angles, rates = rng.uniform(-3, 3, (50, 3)), rng.normal(size=(50, 3))
    for intrinsic in (s for s in ALL_SEQUENCES if s.isupper()):
        extrinsic = intrinsic[::-1].lower()
        for frame in FRAMES:
            assert_array_equal(
                euler_rates_to_angular_velocity(angles, rates, extrinsic, frame=frame),
                euler_rates_to_angular_velocity(
                    angles[:, ::-1], rates[:, ::-1], intrinsic, frame=frame
                ),
            )
            omega = euler_rates_to_angular_velocity(angles, rates, intrinsic, frame=frame)
            assert_array_equal(
                angular_velocity_to_euler_rates(angles[:, ::-1], omega, extrinsic, frame=frame),
                angular_velocity_to_euler_rates(angles, omega, intrinsic, frame=frame)[:, ::-1],
            )
    for preset in PRESETS:
        seq = get_convention(preset).seq
        assert_array_equal(
            euler_rates_to_angular_velocity(angles, rates, preset),
            euler_rates_to_angular_velocity(angles, rates, seq),
        )


def test_huge_angles_in_degrees_are_reduced_exactly() -> None:
    # 1e20° is 280° exactly (Python's integers say so)
    assert int(1e20) % 360 == 280
    rates = [3.0, -2.0, 5.0]
    for seq in ("ZYX", "zxz"):
        assert_allclose(
            euler_rates_to_angular_velocity([1e20, 1e20, 1e20], rates, seq, degrees=True),
            euler_rates_to_angular_velocity([280, 280, 280], rates, seq, degrees=True),
            rtol=0,
            atol=1e-14,
        )


def test_shapes_broadcast_and_one_attitude_gives_one_vector(rng) -> None:
    angles = rng.uniform(-1, 1, (4, 1, 3))
    rates = rng.normal(size=(5, 3))
    omega = euler_rates_to_angular_velocity(angles, rates)
    assert omega.shape == (4, 5, 3)
    assert_array_equal(omega[2, 3], euler_rates_to_angular_velocity(angles[2, 0], rates[3]))
    assert euler_rates_to_angular_velocity([0.1, 0.2, 0.3], [1, 2, 3]).shape == (3,)
    assert angular_velocity_to_euler_rates(angles, rates).shape == (4, 5, 3)
    assert euler_rates_to_angular_velocity(np.zeros((0, 3)), [1, 2, 3]).shape == (0, 3)


def test_blocks_of_a_long_input_give_the_same_numbers(rng) -> None:
    n = 40_000  # three blocks
    angles, rates = rng.uniform(-3, 3, (n, 3)), rng.normal(size=(n, 3))
    omega = euler_rates_to_angular_velocity(angles, rates, "XZY", frame="space")
    assert_array_equal(
        omega[-7:], euler_rates_to_angular_velocity(angles[-7:], rates[-7:], "XZY", frame="space")
    )
    back = angular_velocity_to_euler_rates(angles, omega, "XZY", frame="space")
    assert_array_equal(
        back[-7:], angular_velocity_to_euler_rates(angles[-7:], omega[-7:], "XZY", frame="space")
    )


# --- ω → rates ------------------------------------------------------------------------------------


@pytest.mark.parametrize("frame", FRAMES)
@pytest.mark.parametrize("seq", ALL_SEQUENCES)
def test_omega_to_rates_solves_the_symbolic_jacobian(seq: str, frame: str, rng) -> None:
    angles = rng.uniform(-4.0, 4.0, (25, 3))
    omega = rng.normal(size=(25, 3))
    J = jacobian(seq, frame)
    expected = np.array([np.linalg.solve(J(*a), w) for a, w in zip(angles, omega, strict=True)])
    got = angular_velocity_to_euler_rates(angles, omega, seq, frame=frame)
    scale = np.abs(expected).max(axis=1, keepdims=True)
    assert np.all(np.abs(got - expected) <= 1e-12 * scale)


PITCH_DISTANCES = [10.0**-k for k in (1, 3, 6, 9, 12, 14)]


@pytest.mark.parametrize("seq", ["ZYX", "xzy", "ZXZ", "yzy"])
@pytest.mark.parametrize("frame", FRAMES)
@pytest.mark.parametrize("degrees", [False, True])
def test_both_directions_against_fifty_digits_at_the_hard_places(
    seq: str, frame: str, degrees: bool, rng
) -> None:
    """Near the pole the rates grow like 1/cos β; the error stays a few ulp of that size."""
    unit = 180 / math.pi if degrees else 1.0
    cases = []
    for pole in poles(seq):
        pole_value = pole if degrees else math.radians(pole)
        for distance in PITCH_DISTANCES:
            for side in (-1.0, 1.0):
                middle = pole_value + side * distance * unit
                outer = rng.uniform(-3, 3, 2) * unit
                cases.append([outer[0], middle, outer[1]])
    cases += [[1e20, 1e20 + 0.5, -3e17]] if degrees else [[1e-300, 0.3, -1e-20]]
    cases += list(rng.uniform(-3, 3, (6, 3)) * unit)
    mp_J = mp_jacobian(seq, frame)
    for angles in np.array(cases):
        with mpmath.workdps(50):
            radians = [radians_of(a, degrees) for a in angles]
            middle = mpmath.sin(radians[1]) if is_proper(seq) else mpmath.cos(radians[1])
        distance = abs(float(middle))  # |det J|
        if distance <= GIMBAL_LOCK_TOLERANCE:
            continue  # a locked attitude: its own test
        rates = rng.normal(size=3)
        with mpmath.workdps(50):
            J = mpmath.matrix(mp_J(*radians))
            exact_omega = J * mpmath.matrix([mpmath.mpf(float(r)) for r in rates])
            omega = rng.normal(size=3)
            exact_rates = mpmath.lu_solve(J, mpmath.matrix([mpmath.mpf(float(w)) for w in omega]))
        got_omega = euler_rates_to_angular_velocity(
            angles, rates, seq, frame=frame, degrees=degrees
        )
        error = max(abs(float(exact_omega[i]) - got_omega[i]) for i in range(3))
        assert error <= 6 * EPS * np.abs(rates).max(), (angles, error)
        got_rates = angular_velocity_to_euler_rates(
            angles, omega, seq, frame=frame, degrees=degrees
        )
        error = max(abs(mpmath.mpf(float(got_rates[i])) - exact_rates[i]) for i in range(3))
        assert float(error) <= 6 * EPS * np.abs(omega).max() / distance, (angles, float(error))


angle = st.one_of(
    st.floats(-4.0, 4.0, allow_nan=False),
    st.builds(
        lambda base, sign, exponent: base + sign * 10.0**exponent,
        st.sampled_from((0.0, np.pi / 2, -np.pi / 2, np.pi)),
        st.sampled_from([-1.0, 1.0]),
        st.integers(-8, -1),
    ),
)
triples = hnp.arrays(np.float64, (3,), elements=angle)
vectors = hnp.arrays(np.float64, (3,), elements=st.floats(-10.0, 10.0, allow_nan=False))
checked = settings(max_examples=examples(200), deadline=None)


@checked
@given(triples, vectors, st.sampled_from(ALL_SEQUENCES), st.sampled_from(FRAMES))
def test_the_two_are_inverses_away_from_lock(angles, rates, seq, frame) -> None:
    middle = angles[1]
    distance = abs(math.sin(middle)) if is_proper(seq) else abs(math.cos(middle))
    assume(distance > 1e-12)  # locked attitudes have their own tests below
    omega = euler_rates_to_angular_velocity(angles, rates, seq, frame=frame)
    back = angular_velocity_to_euler_rates(angles, omega, seq, frame=frame)
    # the outer rates come back to a few ulp of |ω| / |det J|
    assert_allclose(back, rates, rtol=0, atol=16 * EPS * (np.abs(rates).max() + 1) / distance)
    again = euler_rates_to_angular_velocity(angles, back, seq, frame=frame)
    assert_allclose(again, omega, rtol=0, atol=16 * EPS * (np.abs(back).max() + 1))


@checked
@given(triples, vectors, st.sampled_from(ALL_SEQUENCES))
def test_body_omega_is_R_transposed_times_space_omega(angles, rates, seq) -> None:
    R = Rotation.from_euler(seq, angles).as_matrix()  # SciPy's matrix: an independent R
    body = euler_rates_to_angular_velocity(angles, rates, seq, frame="body")
    space = euler_rates_to_angular_velocity(angles, rates, seq, frame="space")
    scale = np.abs(rates).max() + 1
    assert_allclose(body, R.T @ space, rtol=0, atol=16 * EPS * scale)
    assert_allclose(R @ body, space, rtol=0, atol=16 * EPS * scale)


# --- at gimbal lock ----------------------------------------------------------------------------


def locked_cases(rng) -> list[tuple[str, float, np.ndarray]]:
    """(seq or preset, pole, angles in degrees) with the middle angle exactly at the pole."""
    cases = []
    for seq in (*ALL_SEQUENCES, *PRESETS):
        for pole in poles(get_convention(seq).seq):
            outer = rng.uniform(-180, 180, 2)
            cases.append((seq, pole, np.array([outer[0], pole, outer[1]])))
    return cases


def test_at_lock_the_rates_follow_the_lock_policy_and_fit_omega_by_least_squares(rng) -> None:
    for seq, pole, angles in locked_cases(rng):
        convention = get_convention(seq)
        zeroed = 0 if convention.lock_zeroes == "first" else 2
        for frame in FRAMES:
            omega = rng.normal(size=3)
            with pytest.warns(GimbalLockWarning) as record:
                rates = angular_velocity_to_euler_rates(
                    angles, omega, seq, frame=frame, degrees=True
                )
            assert len(record) == 1 and record[0].filename == __file__
            facts = record[0].message
            assert isinstance(facts, GimbalLockWarning)
            assert facts.rates and (facts.count, facts.total) == (1, 1)
            assert facts.zeroed == convention.angle_names[zeroed]
            assert list(facts.combinations) == [int(pole)]
            assert "the rate of" in str(facts) and "was left out" in str(facts)
            assert rates[zeroed] == 0.0
            # what the rates produce is the projection of ω onto what any rates can produce
            J = jacobian(convention.seq, frame)(*np.radians(angles))
            projection = J @ np.linalg.pinv(J) @ omega
            assert_allclose(J @ rates, projection, rtol=0, atol=1e-14)
            assert_allclose(
                euler_rates_to_angular_velocity(angles, rates, seq, frame=frame, degrees=True),
                projection,
                rtol=0,
                atol=1e-14,
            )
            # and ω beyond that projection is the direction the lock lost
            lost = omega - projection
            assert np.linalg.norm(lost) > 1e-3
            assert_allclose(J.T @ lost, 0.0, atol=1e-14)


def test_at_lock_rates_with_the_zeroed_rate_zero_come_back_exactly(rng) -> None:
    for seq, _, angles in locked_cases(rng):
        zeroed = 0 if get_convention(seq).lock_zeroes == "first" else 2
        for frame in FRAMES:
            rates = rng.normal(size=3)
            rates[zeroed] = 0.0
            omega = euler_rates_to_angular_velocity(angles, rates, seq, frame=frame, degrees=True)
            with pytest.warns(GimbalLockWarning):
                back = angular_velocity_to_euler_rates(
                    angles, omega, seq, frame=frame, degrees=True
                )
            assert_allclose(back, rates, rtol=0, atol=4 * EPS * np.abs(rates).max())


def test_at_lock_the_rates_are_those_of_the_angles_matrix_to_euler_reports() -> None:
    """Turning about the locked axis: matrix_to_euler keeps yaw at 0 and moves roll only."""
    step = 1e-6
    for frame in FRAMES:
        angles = np.array([0.0, math.pi / 2, 0.4])  # pitch π/2 in radians: within the tolerance
        rates = np.array([0.0, 0.0, 0.7])
        omega = euler_rates_to_angular_velocity(angles, rates, "rose", frame=frame)
        with pytest.warns(GimbalLockWarning):
            back = angular_velocity_to_euler_rates(angles, omega, "rose", frame=frame)
        path = np.array([angles - step * rates, angles + step * rates])
        with pytest.warns(GimbalLockWarning):
            reported = eulerlib.matrix_to_euler(eulerlib.euler_to_matrix(path, "rose"), "rose")
        assert_allclose(back, (reported[1] - reported[0]) / (2 * step), rtol=0, atol=1e-9)


def test_the_lock_tolerance_is_the_librarys() -> None:
    omega = [0.3, -0.2, 0.5]
    inside = [0.2, math.pi / 2 - GIMBAL_LOCK_TOLERANCE / 2, 0.1]
    outside = [0.2, math.pi / 2 - 8 * GIMBAL_LOCK_TOLERANCE, 0.1]
    assert bool(eulerlib.gimbal_lock_status(eulerlib.euler_to_matrix(inside)).locked)
    with pytest.warns(GimbalLockWarning):
        finite = angular_velocity_to_euler_rates(inside, omega)
    assert np.abs(finite).max() < 1.0
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        huge = angular_velocity_to_euler_rates(outside, omega)
    assert np.abs(huge).max() > 1e12  # 1 / cos β, as it should be
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        angular_velocity_to_euler_rates(inside, omega, warn=False)


def test_one_warning_per_call_counts_every_locked_attitude() -> None:
    angles = [[10, 90, 20], [0, 0, 0], [5, -90, 5], [1, 90, 2]]
    with pytest.warns(GimbalLockWarning) as record:
        angular_velocity_to_euler_rates(angles, [1.0, 2.0, 3.0], "rose", degrees=True)
    assert len(record) == 1
    facts = record[0].message
    assert (facts.count, facts.total, facts.zeroed, facts.carrier) == (3, 4, "yaw", "roll")
    assert facts.combinations == {90: "roll - yaw", -90: "yaw + roll"}
    import pickle

    again = pickle.loads(pickle.dumps(facts))
    assert again.rates and str(again) == str(facts)


def test_angles_warning_is_unchanged_by_the_rates_wording() -> None:
    R = eulerlib.euler_to_matrix([30, 90, 10], "rose", degrees=True)
    with pytest.warns(GimbalLockWarning) as record:
        eulerlib.matrix_to_euler(R, "rose")
    facts = record[0].message
    assert not facts.rates
    assert str(facts).endswith("yaw (angle 1) was set to 0 and roll carries the whole turn")
