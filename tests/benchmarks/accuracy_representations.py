"""How accurate quaternions, axis–angle, rotation vectors and slerp are, at the hard places.

Run::

    python tests/benchmarks/accuracy_representations.py [--axes 12] [--n 100000] [--seed 0]

Every conversion is compared with the 50-digit mpmath reference of ``tests/mp_reference.py``,
the exact answer for the float64 input, on matrices rounded once from exact rotations by
angles from 1e-300 to 1e-4, by π − 1e-4 to exactly π, and by random angles, about coordinate
and random axes. Errors are printed in units of 2⁻⁵² ≈ 2.2e-16 for results of size about 1
(quaternions, matrices, axes) and in units in the last place of the result for angles and
rotation vectors. Then the round trips ``R → q → R``, ``R → (axis, angle) → R`` and
``R → rotvec → R`` over ``--n`` random rotations and the hard places: the largest entry of the
difference.

This file is a script that prints measurements; the tests (``tests/test_quaternion.py``,
``tests/test_axis_angle.py``, ``tests/test_slerp.py``) assert the bounds.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import mpmath
import numpy as np
from scipy.spatial.transform import Rotation

import eulerlib

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # tests/, for mp_reference
import mp_reference as mp


def group_of(label: str) -> str:
    if label.startswith("angle pi"):
        return "angle pi - 1e-4 ... pi"
    if label.startswith("angle"):
        return "angle 1e-300 ... 1e-4"
    return "random"


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--axes", type=int, default=12, help="random axes per hard place")
    parser.add_argument("--n", type=int, default=100_000, help="random rotations, round trips")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    rng = np.random.default_rng(args.seed)
    cases = mp.hard_rotations(rng, axes=args.axes)

    worst: dict[tuple[str, str], float] = {}

    def record(what: str, group: str, error: float) -> None:
        worst[what, group] = max(worst.get((what, group), 0.0), error)

    for label, R in cases:
        group = group_of(label)
        Q = mp.polar(R)
        exact_q = mp.quaternion_of(Q)
        record(
            "matrix -> quaternion",
            group,
            mp.quaternion_ulps(eulerlib.matrix_to_quaternion(R, scalar_first=True), exact_q),
        )
        exact_axis, exact_angle = mp.axis_angle_of(Q)
        axis, angle = eulerlib.matrix_to_axis_angle(R)
        record("matrix -> angle (ulp of the angle)", group, mp.ulps(angle, exact_angle))
        half_turn = exact_angle > mpmath.pi - 8 * mp.EPS  # both axes are answers there
        error = mp.absolute_ulps(axis, exact_axis)
        if half_turn:
            error = min(error, mp.absolute_ulps(-axis, exact_axis))
        record("matrix -> axis", group, error)
        v = eulerlib.matrix_to_rotvec(R)
        exact_v = [exact_angle * c for c in exact_axis]
        spacing = float(np.spacing(float(exact_angle)))
        error = max(float(abs(mp.MP(float(a)) - b)) for a, b in zip(v, exact_v, strict=True))
        if half_turn:
            error = min(error, max(float(abs(mp.MP(float(-a)) - b))
                                   for a, b in zip(v, exact_v, strict=True)))  # fmt: skip
        record("matrix -> rotvec (ulp of |v|)", group, error / spacing)
        # back: the float axis and angle, and the float rotation vector, exactly
        exact_R = mp.matrix_of_axis_angle(mp.mp_vector(axis), mp.MP(float(angle)))
        record(
            "axis, angle -> matrix",
            group,
            mp.absolute_ulps(eulerlib.axis_angle_to_matrix(axis, angle), exact_R),
        )
        record(
            "rotvec -> matrix",
            group,
            mp.absolute_ulps(eulerlib.rotvec_to_matrix(v), mp.matrix_of_rotvec(v, False)),
        )
        q = rng.normal(size=4) if group == "random" else eulerlib.matrix_to_quaternion(R)
        record(
            "quaternion -> matrix",
            group,
            mp.absolute_ulps(
                eulerlib.quaternion_to_matrix(q),
                mp.matrix_of_quaternion(mp.mp_vector(np.roll(q, 1))),
            ),
        )
        # slerp from a random rotation by this turn, at a few fractions inside and outside
        start = Rotation.random(rng=rng).as_matrix()
        end = start @ R
        Q0, Q1 = mp.polar(start), mp.polar(end)
        # within rounding of a half turn (π and π − 1e-16 here), the last bits of the two
        # float matrices decide which way round is shorter: compare with the nearer geodesic
        undecided = label in ("angle pi", "angle pi - 1e-16")
        for t in (-0.5, 0.3, 0.5, 1.0, 1.5):
            path = eulerlib.slerp(start, end, t)
            error = mp.absolute_ulps(path, mp.slerp_of(Q0, Q1, t))
            if undecided:
                error = min(error, mp.absolute_ulps(path, mp.slerp_other_way_of(Q0, Q1, t)))
            record("slerp (either way at pi)" if undecided else "slerp", group, error)
        exact_distance = mp.rotation_angle_of(mp.transpose_product(Q0, Q1))
        record("angle_between (absolute)", group,
               float(abs(mp.MP(float(eulerlib.angle_between(start, end))) - exact_distance))
               / mp.EPS)  # fmt: skip

    for seq in eulerlib.ALL_SEQUENCES:
        for degrees in (False, True):
            for _ in range(20):
                if degrees:
                    angles = rng.choice([0.0, 90.0, -90.0, 180.0, 1e20, 2.0**60 + 45], 3)
                    angles = angles + rng.choice([0.0, 1e-9, 33.3], 3)
                else:
                    angles = rng.uniform(-4.0, 4.0, 3)
                q = eulerlib.euler_to_quaternion(angles, seq, degrees=degrees, scalar_first=True)
                exact = mp.quaternion_of_euler(angles, seq, degrees)
                record("euler -> quaternion", "degrees" if degrees else "radians",
                       mp.quaternion_ulps(q, exact))  # fmt: skip

    print(f"eulerlib {eulerlib.__version__}: {len(cases)} matrices at the hard places, "
          f"against mpmath with {mp.DIGITS} digits")  # fmt: skip
    header = f"{'conversion':<36}{'group':<26}{'worst':>10}"
    print(header)
    print("-" * len(header))
    conversions = list(dict.fromkeys(what for what, _ in worst))  # in the order first met
    for (what, group), error in sorted(worst.items(), key=lambda k: conversions.index(k[0][0])):
        print(f"{what:<36}{group:<26}{error:>10.2f}")

    R = np.concatenate([Rotation.random(args.n, rng=rng).as_matrix(),
                        np.stack([R for _, R in cases])])  # fmt: skip
    trips = {
        "R -> q -> R": eulerlib.quaternion_to_matrix(eulerlib.matrix_to_quaternion(R)),
        "R -> (axis, angle) -> R": eulerlib.axis_angle_to_matrix(*eulerlib.matrix_to_axis_angle(R)),
        "R -> rotvec -> R": eulerlib.rotvec_to_matrix(eulerlib.matrix_to_rotvec(R)),
    }
    print()
    print(f"round trips over {len(R):,} rotations: largest entry of the difference")
    for name, back in trips.items():
        print(f"{name:<36}{float(np.abs(back - R).max()):>10.2g}")


if __name__ == "__main__":
    main()
