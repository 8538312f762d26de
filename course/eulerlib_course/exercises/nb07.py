"""Answer key of notebook 07, gimbal lock seen (Rose eq 3a and eq 4; a proper Euler sequence)."""

from __future__ import annotations

from typing import Any

import numpy as np

from eulerlib import euler_to_matrix, matrix_to_euler, rot_y

from .judges import AnglesJudge, ChoiceJudge, Constraint, Mistake, NumberJudge, rounded_to
from .key import Example, Exercise

# 07.1: the matrix ᵂR_B built from this yaw, pitch, roll (degrees), at pitch −90°, where only
# yaw + roll is defined (Rose eq 4a); eulerlib reports yaw 0, SciPy roll 0.
_LOCKED = (25.0, -90.0, 40.0)
_ZXZ = (30.0, 180.0, 10.0)  # z, x', z'' of the matrix of 07.3, degrees
# 07.2: the locked attitude of section 4 nudged by 1e-9 rad about the world +y axis
_NUDGED = rot_y(1e-9) @ euler_to_matrix([0.0, 90.0, -20.0], "ZYX", degrees=True)
_NUDGED_ROLL = float(matrix_to_euler(_NUDGED, "ZYX", degrees=True)[2])


def _some_yaw_roll(rng: np.random.Generator) -> tuple[float, float]:
    """A student's yaw and roll, whole degrees: their sum and difference at least 10° from
    every multiple of 45° (where two of the typical mistakes would coincide with the answer)."""
    while True:
        yaw, roll = (float(a) for a in rng.integers(-80, 81, 2))
        if all(10.0 <= abs(x) % 45.0 <= 35.0 for x in (roll + yaw, roll - yaw)) and abs(yaw) >= 10:
            return yaw, roll


def _some_locked(rng: np.random.Generator) -> Any:
    """A student's matrix ᵂR_B at pitch −90° (yaw + roll other than in the teacher's edition,
    whose stored outputs show its answer)."""
    while True:
        yaw, roll = _some_yaw_roll(rng)
        if yaw + roll != _LOCKED[0] + _LOCKED[2]:
            return euler_to_matrix([yaw, -90.0, roll], "rose", degrees=True)


def _some_zxz(rng: np.random.Generator) -> Any:
    """A student's z, x', z'' at x' = 180°, picked like :func:`_some_locked`'s yaw and roll."""
    z, z2 = _some_yaw_roll(rng)
    return np.array([z, 180.0, z2])


def _is_zero_degrees(angle: float) -> bool:
    """Whether an angle in degrees is 0 up to whole turns."""
    return abs((angle + 180.0) % 360.0 - 180.0) <= 1e-9


def _judge_locked(W_R_B: Any) -> AnglesJudge:
    """The judge of 07.1: any yaw, pitch, roll that rebuild the matrix at pitch −90°.

    The reference is the library's reading (yaw 0, the roll carries yaw + roll); every other
    split of yaw + roll rebuilds the matrix too and is right, SciPy's (roll 0) among them.
    """
    yaw, _, roll = matrix_to_euler(np.asarray(W_R_B, dtype=float), "rose", degrees=True, warn=False)
    total = float(yaw + roll)  # yaw + roll, the one combination the matrix keeps at −90°
    return AnglesJudge(
        [0.0, -90.0, total],
        "rose",
        degrees=True,
        what="your yaw, pitch, roll",
        hint="read the pitch off r31 first; at that pitch, write out which entries hold the "
        "sine and the cosine of the one combination of yaw and roll that is left",
        mistakes=(
            Mistake(
                [-total, -90.0, 0.0],
                "yaw + roll has the wrong sign: whichever angle you set to 0 (SciPy sets the "
                "roll, eulerlib the yaw), the other carries the whole sum at pitch −90°, sign "
                "included; it is at +90° that roll − yaw survives",
            ),
            Mistake(
                [total + 180.0, -90.0, 0.0],
                "that angle comes from eq 4b, atan2(r12, r13), which belongs to pitch +90° "
                "(r31 = −1); here r31 = +1: use the formula of the other pole",
            ),
            Mistake(
                [90.0 - total, -90.0, 0.0],
                "the arguments of atan2 are swapped: atan2(y, x) takes the sine entry first",
            ),
        ),
    )


def _judge_zxz(zxz: Any) -> AnglesJudge:
    return AnglesJudge(
        zxz,
        "ZXZ",
        degrees=True,
        what="your z, x', z''",
        constraints=(
            Constraint(
                lambda a: _is_zero_degrees(float(a[0])),
                "the question asks for the triple with the first angle z = 0°",
            ),
        ),
        mistakes=(
            Mistake(
                [0.0, 180.0, zxz[2] + zxz[0]],
                "you added z and z'': that is what survives at x' = 0°; at x' = 180° the "
                "middle turn points the z axis the other way: work out how the two outer turns "
                "about z combine then",
            ),
            Mistake(
                [0.0, 180.0, zxz[0] - zxz[2]],
                "you took z − z'': the combination is right up to its sign; check the sign "
                "each outer angle carries in the locked matrix",
            ),
        ),
    )


EXERCISES = [
    Exercise(
        id="07.1",
        level="apply",
        judge=_judge_locked(euler_to_matrix(_LOCKED, "rose", degrees=True)),
        per_student=_some_locked,
        judged=_judge_locked,
        given=lambda: euler_to_matrix(_LOCKED, "rose", degrees=True),
        examples=(
            Example(
                "[np.degrees(np.arctan2(-W_R_B_ex[0, 1], -W_R_B_ex[0, 2])), -90, 0]", "correct"
            ),
            Example(
                "[0, -90, np.degrees(np.arctan2(-W_R_B_ex[0, 1], -W_R_B_ex[0, 2]))]", "correct"
            ),
            Example("[25, -90, 40]", "correct", "rotation asked for"),
            Example("[-335, 270, 400]", "correct", "rotation asked for"),
            Example("[-65, -90, 0]", "off", "sign included"),
            Example("[0, -90, -65]", "off", "sign included"),
            Example(
                "[np.degrees(np.arctan2(W_R_B_ex[0, 1], W_R_B_ex[0, 2])), -90, 0]", "off", "eq 4b"
            ),
            Example(
                "[np.degrees(np.arctan2(-W_R_B_ex[0, 2], -W_R_B_ex[0, 1])), -90, 0]",
                "off",
                "swapped",
            ),
            Example("[65, 90, 0]", "off", "pitch has the wrong sign"),
            Example("np.radians([65, -90, 0])", "off", "radians"),
            Example("[10, -90, 10]", "off", "combination of yaw and roll"),
        ),
        forbidden=("65",),
    ),
    Exercise(
        id="07.2",
        level="predict",
        judge=ChoiceJudge(
            options={
                "a": "the yaw stays close to 0°",
                "b": "the yaw jumps to about +90° or −90°",
                "c": "the yaw jumps to about 180°",
                "d": "the yaw comes out as NaN",
            },
            answer="c",
            computed=NumberJudge(
                _NUDGED_ROLL,
                what="your roll",
                tol=rounded_to(2),
                unit="deg",
                modulo=360.0,
                hint="read it from matrix_to_euler of the nudged matrix, in degrees; at the "
                "lock only roll − yaw is pinned down",
            ),
            computed_what="the roll that comes with that yaw",
            explanations={
                "a": "the yaw is the direction of the nose's shadow on the horizontal plane, "
                "atan2(r21, r11); it stays near 0° only if the nudge tips the nose toward +x: "
                "work out from column 1 of rot_y(ε) R_lock which way it tips",
                "b": "±90° would mean the nose tips toward ±y; a turn about the y axis moves the "
                "nose within the x–z plane and leaves its y component alone",
                "c": "about +y the nose tips toward −x, and the yaw is the direction of "
                "the nose's shadow, atan2(r21, r11): 180°",
                "d": "atan2 of two tiny numbers is a perfectly good angle: the direction in which "
                "the nose has tipped, however little",
            },
        ),
        examples=(
            Example("('c', 160.0)", "correct", "shadow"),
            Example("('c', ...)", "not yet", "recorded"),
            Example("(' C ', -200.0)", "correct", "180°"),
            Example("('c', -20.0)", "off", "your roll is not it"),
            Example("('a', -20.0)", "off", "which way it tips"),
            Example("('b', 70.0)", "off", "x–z plane"),
            Example("('d', float('nan'))", "off", "atan2"),
            Example("'c'", "off", "give a pair"),
            Example("180", "off", "give a pair"),
        ),
    ),
    Exercise(
        id="07.3",
        level="extend",
        judge=_judge_zxz(_ZXZ),
        per_student=_some_zxz,
        judged=_judge_zxz,
        given=lambda: np.array(_ZXZ),
        examples=(
            Example("[0.0, zxz_ex[1], zxz_ex[2] - zxz_ex[0]]", "correct"),
            Example("[0, -180, 340]", "correct", "rotation asked for"),
            Example("[30, 180, 10]", "off", "z = 0°"),
            Example("[0, 180, 40]", "off", "you added z and z''"),
            Example("[0, 180, 20]", "off", "right up to its sign"),
            Example("np.radians([0, 180, -20])", "off", "radians"),
        ),
        forbidden=("180, -20", "180.0, -20.0"),
    ),
]
