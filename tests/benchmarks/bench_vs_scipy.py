"""eulerlib against SciPy's ``Rotation``, side by side in one process.

Run::

    python tests/benchmarks/bench_vs_scipy.py [--n 1000000] [--repeats 7] [--seq ZYX] [--only TEXT]

Each operation is timed on the same data for both libraries, best of ``--repeats`` runs with
``time.perf_counter``, and the table shows the ratio SciPy time / eulerlib time (above 1 means
eulerlib is faster). Both sides validate their input where the operation does so by default:
``matrix_to_euler`` checks that every matrix is a rotation, and ``Rotation.from_matrix``
orthogonalizes every matrix; ``quaternion_to_matrix`` and ``Rotation.from_quat`` both
normalize every quaternion; ``slerp`` checks both ends, as ``Rotation.from_matrix`` does before
SciPy's ``Slerp`` interpolates. This file is a script, not a test: nothing here asserts a time.
"""

from __future__ import annotations

import argparse
import platform
import time
from collections.abc import Callable

import numpy as np
import scipy
from scipy.spatial.transform import Rotation, Slerp

import eulerlib


def best_time(function: Callable[[], object], repeats: int) -> float:
    """Shortest wall-clock time of ``repeats`` calls, in seconds."""
    function()  # warm up: first-call allocations, lazy imports
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times)


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=1_000_000, help="rotations per call")
    parser.add_argument("--repeats", type=int, default=7, help="timed runs per operation")
    parser.add_argument("--seq", default="ZYX", help="axis sequence, as in Rotation.from_euler")
    parser.add_argument(
        "--only", default="", help="time only the operations whose name contains this text"
    )
    args = parser.parse_args(argv)
    n, seq = args.n, args.seq

    rng = np.random.default_rng(0)
    angles = Rotation.random(n, rng=rng).as_euler(seq)
    R = eulerlib.euler_to_matrix(angles, seq)
    points = rng.normal(size=(n, 3))
    rotation = Rotation.from_matrix(R)
    one_R, one_rotation = R[0], rotation[0]
    quaternions = rotation.as_quat()
    rotvecs = rotation.as_rotvec()
    ends = Rotation.random(n, rng=rng).as_matrix()
    # n pairs (R[i], ends[i]): SciPy's Slerp takes them as 2n key rotations at times 0, 1, …,
    # and the fraction t of pair i is the time 2 i + t; fractions on a grid of 2⁻²⁰ keep those
    # times exact, so that both sides interpolate at the same fractions
    fractions = np.round(rng.uniform(0.0, 1.0, n) * 2**20) / 2**20
    keys = np.stack([R, ends], axis=1).reshape(-1, 3, 3)
    key_times, pair_times = np.arange(2 * n), 2 * np.arange(n) + fractions

    # the two libraries must agree on what they compute before their speed means anything
    assert np.allclose(eulerlib.euler_to_matrix(angles, seq), rotation.as_matrix(), atol=1e-12)
    assert np.allclose(eulerlib.matrix_to_euler(R, seq), angles, atol=1e-9)
    assert np.allclose(eulerlib.rotate_points(R, points), rotation.apply(points), atol=1e-12)
    assert np.allclose(eulerlib.matrix_to_quaternion(R), rotation.as_quat(canonical=True))
    assert np.allclose(eulerlib.quaternion_to_matrix(quaternions), R, atol=1e-12)
    assert np.allclose(eulerlib.matrix_to_rotvec(R), rotvecs, atol=1e-12)
    assert np.allclose(eulerlib.rotvec_to_matrix(rotvecs), R, atol=1e-12)
    assert np.allclose(
        eulerlib.euler_to_quaternion(angles, seq),
        Rotation.from_euler(seq, angles).as_quat(canonical=True),
        atol=1e-12,
    )
    assert np.allclose(eulerlib.quaternion_to_euler(quaternions, seq), angles, atol=1e-9)
    assert np.allclose(
        eulerlib.slerp(R, ends, fractions),
        Slerp(key_times, Rotation.from_matrix(keys))(pair_times).as_matrix(),
        atol=1e-12,
    )
    assert np.allclose(
        eulerlib.slerp(R[0], ends[0], fractions),
        Slerp([0, 1], Rotation.from_matrix([R[0], ends[0]]))(fractions).as_matrix(),
        atol=1e-12,
    )

    cases: list[tuple[str, Callable[[], object], Callable[[], object]]] = [
        (
            "euler -> matrix",
            lambda: eulerlib.euler_to_matrix(angles, seq),
            lambda: Rotation.from_euler(seq, angles).as_matrix(),
        ),
        (
            "matrix -> euler, validating",
            lambda: eulerlib.matrix_to_euler(R, seq),
            lambda: Rotation.from_matrix(R).as_euler(seq),
        ),
        (
            "matrix -> euler, no check",
            lambda: eulerlib.matrix_to_euler(R, seq, validate=False),
            lambda: Rotation.from_matrix(R, assume_valid=True).as_euler(seq),
        ),
        (
            "rotate points, from matrices",  # both check the n matrices
            lambda: eulerlib.rotate_points(R, points),
            lambda: Rotation.from_matrix(R).apply(points),
        ),
        (
            "rotate points, no check",
            lambda: eulerlib.rotate_points(R, points, validate=False),
            lambda: Rotation.from_matrix(R, assume_valid=True).apply(points),
        ),
        (
            # SciPy's object was checked when it was built; eulerlib's matrices were checked
            # by an earlier call, so neither side checks them again
            "rotate points, checked before",
            lambda: eulerlib.rotate_points(R, points, validate=False),
            lambda: rotation.apply(points),
        ),
        (
            # memory-bound; eulerlib also checks that every point is finite, SciPy does not
            "rotate points, 1 rotation",
            lambda: eulerlib.rotate_points(one_R, points),
            lambda: one_rotation.apply(points),
        ),
        (
            "matrix -> quaternion",
            lambda: eulerlib.matrix_to_quaternion(R),
            lambda: Rotation.from_matrix(R).as_quat(),
        ),
        (
            "quaternion -> matrix",
            lambda: eulerlib.quaternion_to_matrix(quaternions),
            lambda: Rotation.from_quat(quaternions).as_matrix(),
        ),
        (
            "matrix -> rotvec",
            lambda: eulerlib.matrix_to_rotvec(R),
            lambda: Rotation.from_matrix(R).as_rotvec(),
        ),
        (
            "rotvec -> matrix",
            lambda: eulerlib.rotvec_to_matrix(rotvecs),
            lambda: Rotation.from_rotvec(rotvecs).as_matrix(),
        ),
        (
            "euler -> quaternion",
            lambda: eulerlib.euler_to_quaternion(angles, seq),
            lambda: Rotation.from_euler(seq, angles).as_quat(),
        ),
        (
            "quaternion -> euler",
            lambda: eulerlib.quaternion_to_euler(quaternions, seq),
            lambda: Rotation.from_quat(quaternions).as_euler(seq),
        ),
        (
            "slerp, n pairs",
            lambda: eulerlib.slerp(R, ends, fractions),
            lambda: Slerp(key_times, Rotation.from_matrix(keys))(pair_times).as_matrix(),
        ),
        (
            "slerp, 1 pair, n fractions",
            lambda: eulerlib.slerp(one_R, ends[0], fractions),
            lambda: Slerp([0, 1], Rotation.from_matrix([one_R, ends[0]]))(fractions).as_matrix(),
        ),
    ]

    print(
        f"n = {n:,} rotations, seq = {seq!r}, best of {args.repeats}; "
        f"numpy {np.__version__}, scipy {scipy.__version__}, "
        f"Python {platform.python_version()} on {platform.machine()}"
    )
    header = f"{'operation':<32}{'eulerlib':>12}{'scipy':>12}{'scipy/eulerlib':>16}"
    print(header)
    print("-" * len(header))
    for name, ours, theirs in cases:
        if args.only not in name:
            continue
        t_ours = best_time(ours, args.repeats)
        t_theirs = best_time(theirs, args.repeats)
        print(
            f"{name:<32}{t_ours * 1e3:>9.1f} ms{t_theirs * 1e3:>9.1f} ms{t_theirs / t_ours:>15.2f}x"
        )


if __name__ == "__main__":
    main()
