"""The compiled kernels of operations on rotation matrices against the numpy-only path, on the
same inputs: the same bits, the same shapes, the same errors and warnings.

The oracle is the numpy-only path, which tests/test_operations.py holds against SciPy and
typed-in formulas; these tests show that the optional kernels change nothing but the time.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from budget import examples
from compiled import assert_same_bits, both, needs_compiled
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from scipy.spatial.transform import Rotation

import eulerlib

pytestmark = needs_compiled

# numbers of every scale: huge points overflow (declined by the kernels, rescaled by the array path)
scaled = st.one_of(
    st.floats(-2.0, 2.0),
    st.floats(-1e-160, 1e-160),
    st.floats(-1e300, 1e300),
    st.sampled_from([0.0, -0.0, 1.0, -1.0, 5e-324, 1.7e308, -1.7e308]),
)
# leading axes of one operand, and of the other one, that the kernels take or decline
lead_pairs = st.sampled_from(
    [
        ((), ()),
        ((1,), ()),
        ((), (1,)),
        ((3,), ()),
        ((), (3,)),
        ((3,), (3,)),
        ((2, 3), (3,)),
        ((2, 3), (2, 3)),
        ((2, 1), (3,)),  # a true broadcast: the array path
        ((17,), (17,)),
        ((4,), (3,)),  # no broadcast: the array path's error
        ((1, 5), (5,)),
        ((0,), ()),
    ]
)
tolerances = st.sampled_from([1e-6, 0.0, 1e-3, 0.5])


def rotations(data, lead, exact: bool = True) -> np.ndarray:
    """Rotations of shape ``(*lead, 3, 3)``, some of them spoiled unless ``exact``: rounded,
    scaled, mirrored, with a NaN or an infinity, or any numbers at all."""
    count = int(np.prod(lead, dtype=int))
    seed = data.draw(st.integers(0, 2**32 - 1))
    R = Rotation.random(count, rng=seed).as_matrix() if count else np.empty((0, 3, 3))
    if data.draw(st.booleans()):  # quarter and half turns: many exact zeros and ones
        R = np.round(R)
        R[np.abs(np.linalg.det(R) - 1.0) > 0.5] = np.eye(3)
    if not exact and count:
        kind = data.draw(
            st.sampled_from(
                ["none", "none", "none", "noise", "scaled", "mirror", "nan", "inf", "any"]
            )
        )
        where = data.draw(st.integers(0, count - 1))
        if kind == "noise":
            R = R + data.draw(st.sampled_from([1e-7, 4e-7, 1e-6, 1e-3]))
        elif kind == "scaled":
            R[where] *= data.draw(st.sampled_from([2.0, 1e200, -1.0]))
        elif kind == "mirror":
            R[where, 0] *= -1.0
        elif kind in ("nan", "inf"):
            R[where, 1, 2] = np.nan if kind == "nan" else -np.inf
        elif kind == "any":
            R[where] = data.draw(arrays(np.float64, (3, 3), elements=scaled))
    return R.reshape(*lead, 3, 3)


def outcome(function, *args, **kwargs):
    """The result of a call, or the type and message of what it raised, with the categories
    and messages of the warnings it gave."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            result = function(*args, **kwargs)
        except Exception as error:  # any error: both paths must raise it alike
            result = (type(error), str(error))
    return result, [(w.category, str(w.message)) for w in caught]


def assert_same_outcome(function, *args, **kwargs) -> None:
    (compiled, compiled_warnings), (pure, pure_warnings) = both(outcome, function, *args, **kwargs)
    assert compiled_warnings == pure_warnings
    if isinstance(pure, tuple) and isinstance(pure[0], type):
        assert compiled == pure
    else:
        assert_same_bits(compiled, pure)


def flags(data) -> dict:
    """validate/repair/atol keywords, or none."""
    return data.draw(
        st.sampled_from(
            [
                {},
                {},
                {"validate": False},
                {"repair": True},
                {"validate": False, "repair": True},
                {"atol": data.draw(tolerances)},
            ]
        )
    )


@settings(max_examples=examples(300))
@given(lead=st.sampled_from([(), (1,), (3,), (2, 3), (17,), (0,)]), data=st.data())
def test_invert(lead, data) -> None:
    R = rotations(data, lead, exact=False)
    assert_same_outcome(eulerlib.invert, R, **flags(data))


@settings(max_examples=examples(300))
@given(leads=lead_pairs, data=st.data(), third=st.sampled_from([None, (), "same"]))
def test_compose(leads, data, third) -> None:
    first, second = rotations(data, leads[0], exact=False), rotations(data, leads[1], False)
    factors = [first, second]
    if third is not None:
        factors.append(rotations(data, leads[0] if third == "same" else (), exact=False))
    assert_same_outcome(eulerlib.compose, *factors, **flags(data))


@settings(max_examples=examples(100))
@given(lead=st.sampled_from([(), (1,), (3,), (2, 3), (17,)]), data=st.data())
def test_compose_of_one_and_of_many(lead, data) -> None:
    R = rotations(data, lead, exact=False)
    assert_same_outcome(eulerlib.compose, R, **flags(data))
    count = data.draw(st.integers(3, 40))  # more factors than the kernel takes at once, too
    assert_same_outcome(eulerlib.compose, *([R] * count), **flags(data))


@settings(max_examples=examples(300))
@given(leads=lead_pairs, data=st.data())
def test_rotate_points(leads, data) -> None:
    R = rotations(data, leads[0], exact=False)
    points = data.draw(arrays(np.float64, (*leads[1], 3), elements=scaled))
    if data.draw(st.booleans()):  # points of one scale, with every digit
        scale = data.draw(st.sampled_from([1.0, 1e-300, 1e-10, 1e10, 1e300, 1e308]))
        rng = np.random.default_rng(data.draw(st.integers(0, 2**32 - 1)))
        with np.errstate(over="ignore"):  # some overflow to infinity: refused alike
            points = rng.normal(size=points.shape) * scale
    assert_same_outcome(eulerlib.rotate_points, R, points, **flags(data))
    assert_same_outcome(eulerlib.rotate_points, R, points[..., ::-1], **flags(data))  # a view


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_operations_refuse_alike(bad) -> None:
    R = np.stack([np.eye(3), np.eye(3)])
    R[1, 2, 0] = bad
    points = np.ones((2, 3))
    for validate in (True, False):
        assert_same_outcome(eulerlib.invert, R, validate=validate)
        assert_same_outcome(eulerlib.compose, R, R[::-1].copy(), validate=validate)
        assert_same_outcome(eulerlib.rotate_points, R, points, validate=validate)
        assert_same_outcome(eulerlib.rotate_points, R[0], np.full((4, 3), bad), validate=validate)


def test_huge_points_are_rescaled_alike() -> None:
    R = Rotation.random(5, rng=3).as_matrix()
    points = np.full((5, 3), 1.5e308)
    points[:, 1] *= -1.0
    assert_same_outcome(eulerlib.rotate_points, R, points)
    assert_same_outcome(eulerlib.rotate_points, R[0], points)
    assert_same_outcome(eulerlib.rotate_points, R, points[0])
    turn = eulerlib.rot_z(np.stack([np.pi / 4, -np.pi / 4, 0.1]))  # x of the first is 2.4e308
    huge = np.array([[1.7e308, -1.7e308, 0.0], [1e308, 1e308, 1e308], [1.0, 2.0, 3.0]])
    assert_same_outcome(eulerlib.rotate_points, turn, huge)
    assert_same_outcome(eulerlib.rotate_points, turn[0], huge)


def test_the_kernels_take_plain_batches() -> None:
    """The comparisons above compare the kernels, not the array path twice."""
    from eulerlib import _compiled

    kernels = _compiled.operations
    R = Rotation.random(6, rng=5).as_matrix()
    out = np.empty((6, 3, 3))
    assert kernels.invert(out, R, True, 1e-6)
    assert kernels.compose(out, True, 1e-6, R, R[0], R)
    assert kernels.rotate_points(np.empty((6, 3)), R, np.ones(3), True, 1e-6)
    huge = np.array([1.7e308, -1.7e308, 0.0])  # turned by 45° about z, x is 2.4e308
    assert not kernels.rotate_points(np.empty(3), eulerlib.rot_z(np.pi / 4), huge, True, 1e-6)
    assert not kernels.rotate_points(np.empty((6, 3)), R, np.array([0.0, np.inf, 0.0]), False, 0.0)
    assert not kernels.invert(out, 2.0 * R, True, 1e-6)
    assert kernels.invert(out, 2.0 * R, False, 1e-6)


@pytest.mark.parametrize("atol", [1e-6, 1e-9, 0.01])
@pytest.mark.parametrize("fraction", [0.2, 0.32, 0.34, 0.5, 0.66, 0.7, 1.2])
def test_matrices_at_the_edge_of_the_tolerance(atol, fraction) -> None:
    """Scaled by 1 + ε, a rotation's determinant is 1 + 3ε to first order: around ε = atol / 3
    it is accepted or refused, by both paths alike."""
    R = Rotation.random(4, rng=7).as_matrix() * (1.0 + fraction * atol)
    R[0] = Rotation.random(1, rng=8).as_matrix()[0]
    points = np.array([1.0, -2.0, 0.5])
    for function, args in [
        (eulerlib.invert, (R,)),
        (eulerlib.compose, (R, R[0])),
        (eulerlib.compose, (R[0], R, R)),
        (eulerlib.rotate_points, (R, points)),
    ]:
        assert_same_outcome(function, *args, atol=atol)


fractions = st.one_of(
    st.floats(-0.5, 1.5),
    st.floats(-1e6, 1e6),
    st.sampled_from([0.0, -0.0, 0.5, 1.0, 2.0, -1.0, 1e300, -1e308, 1.7e308, 5e-324]),
)


def slerp_ends(data, leads):
    """Start and end rotations: random, or the end a half turn from the start, the start itself,
    or a tiny turn away (lengths that need rescaling), some spoiled."""
    start = rotations(data, leads[0], exact=False)
    end = rotations(data, leads[1], exact=False)
    kind = data.draw(st.sampled_from(["random", "random", "half", "same", "tiny", "near half"]))
    try:
        np.broadcast_shapes(start.shape, end.shape)
    except ValueError:
        kind = "random"  # ends that do not broadcast: the array path's refusal
    if kind != "random" and start.size and end.size:
        axis = data.draw(st.sampled_from([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [1.0, -2.0, 2.0]]))
        angle = {"half": np.pi, "same": 0.0, "tiny": 1e-160, "near half": np.pi - 1e-9}[kind]
        turn = Rotation.from_rotvec(np.array(axis) / np.linalg.norm(axis) * angle).as_matrix()
        with np.errstate(over="ignore", invalid="ignore"):  # a spoiled start: refused alike
            turned = start @ turn
        end = np.broadcast_to(turned, np.broadcast_shapes(start.shape, end.shape)).copy()
    return start, end


@settings(max_examples=examples(300))
@given(
    leads=lead_pairs,
    data=st.data(),
    t_lead=st.sampled_from([None, None, "same", (), (1,), (3,), (17,)]),
)
def test_slerp(leads, data, t_lead) -> None:
    start, end = slerp_ends(data, leads)
    t_lead = leads[0] if t_lead == "same" else t_lead
    if t_lead is None:
        t = data.draw(fractions)
        if data.draw(st.booleans()):
            t = data.draw(st.sampled_from([int(t) if abs(t) < 1e9 else 3, np.float64(t)]))
    else:
        t = data.draw(arrays(np.float64, t_lead, elements=fractions))
    assert_same_outcome(eulerlib.slerp, start, end, t, **flags(data))


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_slerp_refuses_alike(bad) -> None:
    R = Rotation.random(3, rng=4).as_matrix()
    assert_same_outcome(eulerlib.slerp, R, R[::-1].copy(), np.array([0.5, bad, 0.2]))
    assert_same_outcome(eulerlib.slerp, R, R[0], bad)
    # one pair: numpy's tangent of one number warns of an infinity, of several it does not
    assert_same_outcome(eulerlib.slerp, R[0], R[1], np.array([bad]))
    assert_same_outcome(eulerlib.slerp, R[0], R[1], np.array([1e308]))
    spoiled = R.copy()
    spoiled[1, 0, 0] = bad
    assert_same_outcome(eulerlib.slerp, spoiled, R, 0.5)
    assert_same_outcome(eulerlib.slerp, R, spoiled, 0.5, validate=False)
    assert_same_outcome(eulerlib.slerp, R, R[::-1].copy(), 1e308)  # t θ / 2 above the largest float
    for scale in (2.0, 1.0 + 1e-7, 1.0 + 4e-7):  # refused, or accepted within atol, alike
        for validate in (True, False):
            assert_same_outcome(eulerlib.slerp, scale * R, R, 0.5, validate=validate)
            assert_same_outcome(eulerlib.slerp, R, scale * R, 0.5, validate=validate)


rates = st.one_of(
    st.floats(-10.0, 10.0),
    st.floats(-1e-160, 1e-160),
    st.floats(-1e200, 1e200),
    st.sampled_from([0.0, -0.0, 90.0, -180.0, 270.0, 360.0, 45.0, 1e-300, 1.7e308]),
)
step_lengths = st.one_of(
    st.floats(-2.0, 2.0),
    st.sampled_from([0.0, 1.0, -1.0, 0.5, 1e-10, 1e10, 1e300, -1e308, 5e-324]),
)


@settings(max_examples=examples(300))
@given(
    leads=lead_pairs,
    data=st.data(),
    dt_lead=st.sampled_from([None, None, "same", (), (1,), (3,), (17,)]),
    frame=st.sampled_from(["body", "space", "Space"]),
    degrees=st.booleans(),
)
def test_integrate_angular_velocity(leads, data, dt_lead, frame, degrees) -> None:
    R = rotations(data, leads[0], exact=False)
    omega = data.draw(arrays(np.float64, (*leads[1], 3), elements=rates))
    if data.draw(st.booleans()):  # rates of one scale, with every digit
        scale = data.draw(st.sampled_from([1.0, 1e-200, 1e-3, 100.0, 1e200]))
        rng = np.random.default_rng(data.draw(st.integers(0, 2**32 - 1)))
        omega = rng.normal(size=omega.shape) * scale
    if dt_lead is None:
        dt = data.draw(step_lengths)
        if data.draw(st.booleans()):
            dt = data.draw(st.sampled_from([1, 2, np.float64(dt)]))
    else:
        dt_lead = leads[0] if dt_lead == "same" else dt_lead
        dt = data.draw(arrays(np.float64, dt_lead, elements=step_lengths))
    assert_same_outcome(
        eulerlib.integrate_angular_velocity,
        R,
        omega,
        dt,
        frame=frame,
        degrees=degrees,
        **flags(data),
    )


@pytest.mark.parametrize("degrees", [False, True])
def test_integration_of_quarter_turns_and_overflow_alike(degrees) -> None:
    R = Rotation.random(4, rng=9).as_matrix()
    omega = np.array([[90.0, 0.0, 0.0], [0.0, -180.0, 0.0], [0.0, 0.0, 45.0], [45.0, 45.0, 0.0]])
    for dt in (1.0, 3.0, 5.0, -1.0, np.array([1.0, 2.0, 3.0, 4.0]), 1e300, 1e306, 1e308):
        for frame in ("body", "space"):
            assert_same_outcome(
                eulerlib.integrate_angular_velocity, R, omega, dt, frame=frame, degrees=degrees
            )
            assert_same_outcome(
                eulerlib.integrate_angular_velocity, R[0], omega, dt, frame=frame, degrees=degrees
            )
    huge = np.full((4, 3), 1e200)  # ω dt overflows, or its length does
    for dt in (1e200, 1e108, 1.0):
        assert_same_outcome(eulerlib.integrate_angular_velocity, R, huge, dt, degrees=degrees)
    for spoiled in (2.0 * R, R + 1e-6, R[::-1] * [1.0, 1.0, -1.0]):
        for validate in (True, False):
            assert_same_outcome(
                eulerlib.integrate_angular_velocity, spoiled, omega, 0.5, validate=validate
            )
    nan = omega.copy()
    nan[2, 1] = np.nan
    assert_same_outcome(eulerlib.integrate_angular_velocity, R, nan, 1.0, degrees=degrees)
    assert_same_outcome(eulerlib.integrate_angular_velocity, R, omega, np.inf, degrees=degrees)
