"""Answer key of notebook 05, from the matrix back to the angles (Rose eq 3, Baker's formulas)."""

from __future__ import annotations

from eulerlib import euler_to_matrix

from .judges import AnglesJudge, Constraint, Mistake
from .key import Example, Exercise

_YPR = [-100.0, 35.0, 160.0]  # yaw, pitch, roll of the matrix the learner is given


def _wrapped(angle: float) -> float:
    return (angle + 180.0) % 360.0 - 180.0


EXERCISES = [
    Exercise(
        id="05.1",
        level="apply",
        judge=AnglesJudge(_YPR, "rose", degrees=True, what="your yaw, pitch, roll"),
        given=lambda: euler_to_matrix(_YPR, "rose", degrees=True),
        examples=(
            Example(
                "np.degrees([np.arctan2(R_ex[1, 0], R_ex[0, 0]), -np.arcsin(R_ex[2, 0]),"
                " np.arctan2(R_ex[2, 1], R_ex[2, 2])])",
                "correct",
            ),
            Example("[260, 35, -200]", "correct", "rotation asked for"),
            Example(
                "np.degrees([np.arctan(R_ex[1, 0] / R_ex[0, 0]), -np.arcsin(R_ex[2, 0]),"
                " np.arctan2(R_ex[2, 1], R_ex[2, 2])])",
                "off",
                "yaw is off by 180°",
            ),
            Example(
                "[np.arctan2(R_ex[1, 0], R_ex[0, 0]), -np.arcsin(R_ex[2, 0]),"
                " np.arctan2(R_ex[2, 1], R_ex[2, 2])]",
                "off",
                "radians",
            ),
            Example("[160, 35, -100]", "off", "reverse order"),
            Example("[-100, -35, 160]", "off", "pitch has the wrong sign"),
            Example("'-100, 35, 160'", "off", "text"),
        ),
        forbidden=("-100", "160"),
    ),
    Exercise(
        id="05.2",
        level="predict",
        judge=AnglesJudge(
            [_wrapped(_YPR[0] + 180), 180 - _YPR[1], _wrapped(_YPR[2] + 180)],
            "rose",
            degrees=True,
            what="your second triple",
            mistakes=(
                Mistake(
                    [_wrapped(_YPR[0] + 180), 180 - _YPR[1], _YPR[2]],
                    "the second triple turns both outer angles by 180°: yaw and roll",
                ),
            ),
            constraints=(
                Constraint(
                    lambda a: abs(_wrapped(float(a[1]))) > 90.0 + 1e-9,
                    "the question asks for the other triple, the one with pitch outside "
                    "[-90°, 90°]",
                ),
            ),
        ),
        examples=(
            Example("[80, 145, -20]", "correct"),
            Example("[80, 145, 340]", "correct"),
            Example("[-280, -215, -20]", "correct"),
            Example("[-100, 35, 160]", "off", "pitch outside"),
            Example("[80, -145, -20]", "off", "pitch has the wrong sign"),
            Example("[80, 145, 160]", "off", "both outer angles"),
        ),
        forbidden=("80, 145", "145"),
    ),
    Exercise(
        id="05.3",
        level="extend",
        judge=AnglesJudge(
            [50.0, -25.0, 110.0],
            "XYZ",
            degrees=True,
            what="your angles for 'XYZ'",
        ),
        given=lambda: euler_to_matrix([50.0, -25.0, 110.0], "XYZ", degrees=True),
        examples=(
            Example(
                "np.degrees([np.arctan2(-M_ex[1, 2], M_ex[2, 2]), np.arcsin(M_ex[0, 2]),"
                " np.arctan2(-M_ex[0, 1], M_ex[0, 0])])",
                "correct",
            ),
            Example("[50 - 360, -25, 110]", "correct"),
            Example("[50, -25, 110][::-1]", "off", "reverse order"),
            Example("np.degrees(matrix_to_euler(M_ex, 'xyz'))", "off", "fixed axes (extrinsic)"),
        ),
        forbidden=("-25", "110"),
    ),
]
