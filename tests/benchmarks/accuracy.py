"""How accurate eulerlib's conversions are, measured at the easy and the hard places.

Run::

    python tests/benchmarks/accuracy.py [--n 20000] [--seed 0]

For every one of the 24 Euler conventions the script builds rotation matrices with SciPy (not
with the code under test) in four groups — random rotations, exactly at gimbal lock, 1e-16 … 1e-3
rad from lock, and lock matrices that carry ordinary rounding noise (``Q Qᵀ R``) — and prints

* the **round trip**: the largest entry of ``|euler_to_matrix(matrix_to_euler(R)) − R|``;
* the **middle angle** against a 50-digit reference: the exact middle angle of the float64
  matrix, computed with mpmath from the same entries, in units in the last place (ulp) of the
  result.

This file is a script that prints measurements; the tests assert the bounds the README states
(``tests/test_gimbal_lock.py``). The README quotes the numbers printed here.
"""

from __future__ import annotations

import argparse
import warnings

import mpmath
import numpy as np
from scipy.spatial.transform import Rotation

import eulerlib
from eulerlib import ALL_SEQUENCES

mpmath.mp.dps = 50


def groups(seq: str, n: int, rng: np.random.Generator) -> dict[str, np.ndarray]:
    """The four groups of test matrices for ``seq``, built by SciPy."""
    proper = seq[0].lower() == seq[2].lower()
    poles = np.array([0.0, np.pi]) if proper else np.array([np.pi / 2, -np.pi / 2])
    outer = rng.uniform(-np.pi, np.pi, (n, 2))

    def with_middle(middle: np.ndarray) -> np.ndarray:
        angles = np.column_stack([outer[:, 0], middle, outer[:, 1]])
        return Rotation.from_euler(seq, angles).as_matrix()

    at_lock = with_middle(rng.choice(poles, n))
    pole = rng.choice(poles, n)
    inwards = np.where(pole > 0.1, -1.0, 1.0) if proper else -np.sign(pole)  # into the range
    near = with_middle(pole + inwards * 10.0 ** rng.uniform(-16, -3, n))
    Q = Rotation.random(n, rng=rng).as_matrix()
    noisy = np.einsum("nij,nkj,nkl->nil", Q, Q, at_lock)
    return {
        "random": Rotation.random(n, rng=rng).as_matrix(),
        "at lock": at_lock,
        "1e-16..1e-3 from lock": near,
        "lock + rounding noise": noisy,
    }


def exact_middle(R: np.ndarray, seq: str) -> float:
    """The middle angle of the float64 matrix ``R``, to 50 digits (mpmath), as a float."""
    intrinsic = seq if seq.isupper() else seq[::-1].upper()
    i, j, k = ("XYZ".index(letter) for letter in intrinsic)
    m = [[mpmath.mpf(float(x)) for x in row] for row in R]
    if i == k:  # proper Euler: cos β = R[i][i], sin β = |(R[i][j], R[i][l])|
        other = 3 - i - j
        return float(mpmath.atan2(mpmath.sqrt(m[i][j] ** 2 + m[i][other] ** 2), m[i][i]))
    sign = 1 if (j - i) % 3 == 1 else -1
    return float(mpmath.atan2(sign * m[i][k], mpmath.sqrt(m[i][i] ** 2 + m[i][j] ** 2)))


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=20000, help="matrices per group and sequence")
    parser.add_argument("--mp", type=int, default=200, help="of which compared with mpmath")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    rng = np.random.default_rng(args.seed)

    worst_trip: dict[str, float] = {}
    worst_ulp: dict[str, float] = {}
    for seq in ALL_SEQUENCES:
        for name, R in groups(seq, args.n, rng).items():
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", eulerlib.GimbalLockWarning)
                angles = eulerlib.matrix_to_euler(R, seq)
            trip = float(np.abs(eulerlib.euler_to_matrix(angles, seq) - R).max())
            worst_trip[name] = max(worst_trip.get(name, 0.0), trip)
            for index in range(min(args.mp, len(R))):
                middle = angles[index, 1]
                exact = exact_middle(R[index], seq)
                ulp = abs(middle - exact) / np.spacing(abs(exact) or 1.0)
                worst_ulp[name] = max(worst_ulp.get(name, 0.0), float(ulp))

    print(f"eulerlib {eulerlib.__version__}: 24 sequences × {args.n:,} matrices per group")
    header = f"{'group':<26}{'round trip (max entry)':>24}{'middle angle vs mpmath':>26}"
    print(header)
    print("-" * len(header))
    for name in worst_trip:
        print(f"{name:<26}{worst_trip[name]:>24.2g}{worst_ulp[name]:>21.1f} ulp")


if __name__ == "__main__":
    main()
