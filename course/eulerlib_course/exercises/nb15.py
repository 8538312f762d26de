"""Answer key of notebook 15, attitude from two directions (TRIAD, Wahba's problem).

The conventions are notebook 14's: an attitude ``M`` turns sensor coordinates into earth
coordinates, earth z is up, the accelerometer reads the specific force (+1 g up at rest), and a
direction known in earth axes, ``v``, is seen by the sensor as ``Mᵀ v``. ``align_vectors(a, b)``
returns the rotation that turns the references ``b`` into the observations ``a``, that is
``Mᵀ``. The data are made here from stated attitudes, fields and disturbances.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from eulerlib import align_vectors, euler_to_matrix

from .judges import ArrayJudge, ChoiceJudge, Mistake, NumberJudge, rounded_to
from .key import Example, Exercise

_UP = np.array([0.0, 0.0, 1.0])


def _unit(v: NDArray[np.float64]) -> NDArray[np.float64]:
    return np.asarray(v / np.linalg.norm(v, axis=-1, keepdims=True), dtype=np.float64)


def _field(heading: float, dip: float) -> NDArray[np.float64]:
    """A unit field direction in earth axes: its horizontal heading and its dip below, degrees."""
    h, d = math.radians(heading), math.radians(dip)
    return np.array([math.cos(d) * math.cos(h), math.cos(d) * math.sin(h), -math.sin(d)])


def _attitude(
    observed: NDArray[np.float64], weights: list[float], ref: NDArray[np.float64]
) -> NDArray[np.float64]:
    return np.asarray(align_vectors(observed, ref, weights=weights).matrix.T, dtype=np.float64)


# --- 15.1: TRIAD on one sample -----------------------------------------------------------------

_TRUE_1 = euler_to_matrix([70.0, -15.0, 25.0], "rose", degrees=True)
_FIELD_1 = _field(-155.0, 35.0)


def _data_1(
    attitude: NDArray[np.float64],
    field_ref: NDArray[np.float64],
    push: NDArray[np.float64],
    stray: NDArray[np.float64],
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """A reading of each sensor (g, gauss), disturbed, and the field's direction in earth axes."""
    accel = attitude.T @ _UP + push
    field = 0.3 * (attitude.T @ field_ref) + stray
    return accel, field, field_ref.copy()


_GIVEN_1 = _data_1(_TRUE_1, _FIELD_1, np.array([0.06, -0.09, 0.03]), np.array([0.02, 0.01, -0.025]))


def _some_data_1(
    rng: np.random.Generator,
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    angles = [rng.uniform(-170, 170), rng.uniform(-60, 60), rng.uniform(-170, 170)]
    attitude = euler_to_matrix(angles, "rose", degrees=True)
    field_ref = _field(rng.uniform(-180, 180), rng.uniform(20, 60))
    push = rng.choice([-1.0, 1.0], size=3) * rng.uniform(0.04, 0.1, size=3)
    stray = rng.choice([-1.0, 1.0], size=3) * rng.uniform(0.01, 0.03, size=3)
    return _data_1(attitude, field_ref, push, stray)


def _judge_1(
    data: tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]],
) -> ArrayJudge:
    accel, field, field_ref = data
    observed = np.stack([accel, field])
    ref = np.stack([_UP, field_ref])
    return ArrayJudge(
        _attitude(observed, [math.inf, 1.0], ref),
        what="your attitude",
        rotation=True,
        hint="build a triad from each pair, gravity first, and turn one triad into the other",
        mistakes=(
            Mistake(
                _attitude(observed, [1.0, math.inf], ref),
                "this attitude matches the field exactly and gravity only in part: the "
                "question trusts gravity, so gravity is the first vector of each triad",
            ),
            Mistake(
                _attitude(_unit(observed), [1.0, 1.0], ref),
                "this is Wahba's best fit with equal weights, which shares the disagreement "
                "between the two directions; TRIAD matches one of them exactly",
            ),
        ),
    )


# --- 15.2: a level device that accelerates --------------------------------------------------------

_PUSH_2 = 0.4  # g, along the sensor's x axis
_FIELD_2 = _field(0.0, 35.0)
_TILT_2 = math.degrees(math.atan(_PUSH_2))


# --- 15.3: Wahba's problem with three weighted directions ----------------------------------------

_TRUE_3 = euler_to_matrix([-120.0, 40.0, -65.0], "rose", degrees=True)
_REF_3 = np.stack([_UP, _FIELD_1, _unit(np.array([0.3, -0.8, 0.5]))])
_DISTURB_3 = np.array([[0.05, -0.04, 0.02], [-0.03, 0.0, 0.04], [0.004, -0.003, 0.002]])
_SEEN_3 = _unit(_REF_3 @ _TRUE_3 + _DISTURB_3)  # row i: Mᵀ v_i, disturbed, as a unit vector
_WEIGHTS_3 = np.array([1.0, 0.5, 20.0])
_ANSWER_3 = _attitude(_SEEN_3, list(_WEIGHTS_3), _REF_3)


EXERCISES = [
    Exercise(
        id="15.1",
        level="apply",
        judge=_judge_1(_GIVEN_1),
        per_student=_some_data_1,
        judged=_judge_1,
        given=lambda: tuple(v.copy() for v in _GIVEN_1),
        examples=(
            Example(
                "align_vectors([accel_ex, field_ex], [[0, 0, 1], field_ref_ex],"
                " weights=[np.inf, 1]).matrix.T",
                "correct",
            ),
            Example(
                "align_vectors([2 * accel_ex, field_ex / 3], [[0, 0, 5], field_ref_ex],"
                " weights=[np.inf, 0.1]).matrix.T",
                "correct",
            ),
            Example(
                "align_vectors([accel_ex, field_ex], [[0, 0, 1], field_ref_ex],"
                " weights=[np.inf, 1]).matrix",
                "off",
                "transpose",
            ),
            Example(
                "align_vectors([accel_ex, field_ex], [[0, 0, 1], field_ref_ex],"
                " weights=[1, np.inf]).matrix.T",
                "off",
                "trusts gravity",
            ),
            Example(
                "align_vectors([accel_ex / np.linalg.norm(accel_ex), field_ex /"
                " np.linalg.norm(field_ex)], [[0, 0, 1], field_ref_ex]).matrix.T",
                "off",
                "equal weights",
            ),
        ),
        forbidden=tuple(f"{value:.4f}" for value in _judge_1(_GIVEN_1)._reference.ravel()),
    ),
    Exercise(
        id="15.2",
        level="predict",
        judge=ChoiceJudge(
            options={
                "a": "no error: the accelerometer still points up",
                "b": "tilted by the angle between the reading and the true up",
                "c": "tilted by half that angle: the field pulls it halfway back",
                "d": "tilted by a right angle",
            },
            answer="b",
            computed=NumberJudge(
                _TILT_2,
                what="your angle",
                tol=rounded_to(2),
                unit="deg",
                hint="build the TRIAD attitude from the reading and the field, and measure its "
                "angle from the true attitude with angle_between",
                mistakes=(
                    Mistake(
                        90.0 - _TILT_2,
                        "this is the angle of the reading above the horizontal; the question "
                        "asks how far the attitude is from the true one",
                    ),
                    Mistake(
                        0.0,
                        "this attitude matches the field exactly, not gravity: the question's "
                        "TRIAD takes the accelerometer as the exact direction",
                    ),
                ),
            ),
            computed_what="the angle you computed",
            explanations={
                "b": "yes: TRIAD takes the reading as exactly up, so the whole push turns into "
                "a tilt; the field, as the second vector, only fixes the turn about that "
                "false up",
                "a": "the accelerometer measures the specific force, the body's acceleration "
                "minus gravity; a push adds to the reading, and TRIAD cannot tell it from a tilt",
                "c": "the second vector of a TRIAD never moves the first: it only fixes the "
                "turn about it, so the field cannot pull the false up back",
                "d": "a right angle would need the push to swamp gravity entirely; compare the "
                "size of the push with 1 g",
            },
        ),
        given=lambda: (np.array([_PUSH_2, 0.0, 1.0]), _FIELD_2.copy()),
        examples=(
            Example("('b', 21.80)", "correct"),
            Example(
                "('B', angle_between(align_vectors([accel_ex, field_ex], [[0, 0, 1], field_ex],"
                " weights=[np.inf, 1]).matrix, np.eye(3), degrees=True))",
                "correct",
            ),
            Example("('a', 0)", "off", "specific force"),
            Example("('c', 10.9)", "off", "never moves the first"),
            Example("('d', 90)", "off", "swamp gravity"),
            Example("('b', 68.2)", "off", "above the horizontal"),
            Example("('b', 0.0)", "off", "matches the field exactly"),
            Example("('b', 0.3805)", "off", "radians"),
            Example("'b'", "off", "give a pair"),
        ),
        forbidden=("21.8", "answer_2 = 'b'", 'answer_2 = "b"'),
    ),
    Exercise(
        id="15.3",
        level="extend",
        judge=ArrayJudge(
            _ANSWER_3,
            what="your attitude",
            rotation=True,
            hint="Wahba's problem takes all three pairs at once, each with its weight",
            mistakes=(
                Mistake(
                    _attitude(_SEEN_3, [1.0, 1.0, 1.0], _REF_3),
                    "this fits the three directions with equal weights; the question gives each "
                    "its own weight",
                ),
                Mistake(
                    _attitude(_SEEN_3[:2], [math.inf, 1.0], _REF_3[:2]),
                    "this is TRIAD on gravity and the field; the third direction, and the "
                    "weights, are left out",
                ),
                Mistake(
                    _attitude(_SEEN_3, list(1 / _WEIGHTS_3), _REF_3),
                    "each weight was used as its inverse: a larger weight means a direction "
                    "trusted more, not less",
                ),
            ),
        ),
        given=lambda: (_SEEN_3.copy(), _REF_3.copy(), _WEIGHTS_3.copy()),
        examples=(
            Example("align_vectors(seen_ex, ref_ex, weights=w_ex).matrix.T", "correct"),
            Example("align_vectors(seen_ex, ref_ex, weights=3 * w_ex).matrix.T", "correct"),
            Example("align_vectors(seen_ex, ref_ex, weights=w_ex).matrix", "off", "transpose"),
            Example("align_vectors(seen_ex, ref_ex).matrix.T", "off", "equal weights"),
            Example(
                "align_vectors(seen_ex[:2], ref_ex[:2], weights=[np.inf, 1]).matrix.T",
                "off",
                "TRIAD",
            ),
            Example("align_vectors(seen_ex, ref_ex, weights=1 / w_ex).matrix.T", "off", "inverse"),
        ),
        forbidden=tuple(f"{value:.4f}" for value in _ANSWER_3.ravel()),
    ),
]
