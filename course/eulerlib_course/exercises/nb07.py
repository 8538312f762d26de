"""Answer key of notebook 07, gimbal lock seen (Rose eq 3a and eq 4; a proper Euler sequence)."""

from __future__ import annotations

import numpy as np

from .judges import AnglesJudge, ChoiceJudge, Constraint, Mistake
from .key import Example, Exercise

_LOCKED = (25.0, 90.0, 70.0)  # yaw, pitch, roll of the aircraft of 07.1, degrees
_ZXZ = (30.0, 180.0, 10.0)  # z, x', z'' of the matrix of 07.3, degrees


def _is_zero_degrees(angle: float) -> bool:
    """Whether an angle in degrees is 0 up to whole turns."""
    return abs((angle + 180.0) % 360.0 - 180.0) <= 1e-9


EXERCISES = [
    Exercise(
        id="07.1",
        level="apply",
        judge=AnglesJudge(
            _LOCKED,
            "rose",
            degrees=True,
            what="your yaw, pitch, roll",
            constraints=(
                Constraint(
                    lambda a: _is_zero_degrees(float(a[0])),
                    "the question asks for the triple with yaw = 0°",
                ),
            ),
            mistakes=(
                Mistake(
                    [0.0, 90.0, _LOCKED[2] + _LOCKED[0]],
                    "you added yaw and roll: the sum roll + yaw is what survives at pitch −90°; "
                    "at pitch +90° the matrix keeps roll − yaw",
                ),
                Mistake(
                    [0.0, 90.0, _LOCKED[0] - _LOCKED[2]],
                    "you took yaw − roll: at pitch +90° the matrix keeps roll − yaw, the other "
                    "way round",
                ),
            ),
        ),
        given=lambda: np.array(_LOCKED),
        examples=(
            Example("[0.0, ypr_ex[1], ypr_ex[2] - ypr_ex[0]]", "correct"),
            Example("[0, 90, 405]", "correct", "rotation asked for"),
            Example("[360, 90, 45]", "correct", "rotation asked for"),
            Example("[25, 90, 70]", "off", "yaw = 0°"),
            Example("[-45, 90, 0]", "off", "yaw = 0°"),
            Example("[0, 90, 95]", "off", "roll + yaw"),
            Example("[0, 90, -45]", "off", "yaw − roll"),
            Example("np.radians([0, 90, 45])", "off", "radians"),
        ),
        forbidden=("90, 45", "90.0, 45.0"),
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
            explanations={
                "a": "a nudge about −y would leave the yaw near 0°; about +y the nose tips toward "
                "−x, and the yaw follows the nose's shadow there",
                "b": "±90° is what the nudges about ±x give, which tip the nose toward ±y; a "
                "nudge about +y tips it toward −x",
                "c": "about +y the nose tips toward −x, and the yaw is the direction of "
                "the nose's shadow, atan2(r21, r11): 180°",
                "d": "atan2 of two tiny numbers is a perfectly good angle: the direction in which "
                "the nose has tipped, however little",
            },
        ),
        examples=(
            Example("'c'", "correct", "shadow"),
            Example("' C '", "correct", "180°"),
            Example("'a'", "off", "−x"),
            Example("'b'", "off", "±y"),
            Example("'d'", "off", "atan2"),
            Example("180", "off", "as text"),
        ),
    ),
    Exercise(
        id="07.3",
        level="extend",
        judge=AnglesJudge(
            _ZXZ,
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
                    [0.0, 180.0, _ZXZ[2] + _ZXZ[0]],
                    "you added z and z'': that is what survives at x' = 0°; at x' = 180° the "
                    "middle turn points the z axis the other way, so the two outer turns oppose "
                    "each other and the matrix keeps z'' − z",
                ),
                Mistake(
                    [0.0, 180.0, _ZXZ[0] - _ZXZ[2]],
                    "you took z − z'': at x' = 180° the matrix keeps z'' − z, the other way round",
                ),
            ),
        ),
        given=lambda: np.array(_ZXZ),
        examples=(
            Example("[0.0, zxz_ex[1], zxz_ex[2] - zxz_ex[0]]", "correct"),
            Example("[0, -180, 340]", "correct", "rotation asked for"),
            Example("[30, 180, 10]", "off", "z = 0°"),
            Example("[0, 180, 40]", "off", "z'' − z"),
            Example("[0, 180, 20]", "off", "the other way round"),
            Example("np.radians([0, 180, -20])", "off", "radians"),
        ),
        forbidden=("180, -20", "180.0, -20.0"),
    ),
]
