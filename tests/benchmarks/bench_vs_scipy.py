"""eulerlib against SciPy's ``Rotation``, side by side in one process.

Run::

    python tests/benchmarks/bench_vs_scipy.py [--n 1000000] [--repeats 7] [--seq ZYX] [--only TEXT]

Each operation is timed on the same data for both libraries, best of ``--repeats`` runs with
``time.perf_counter``, and the table shows the ratio SciPy time / eulerlib time (above 1 means
eulerlib is faster). Both sides validate their input where the operation does so by default:
``matrix_to_euler`` checks that every matrix is a rotation, and ``Rotation.from_matrix``
orthogonalizes every matrix; ``quaternion_to_matrix`` and ``Rotation.from_quat`` both
normalize every quaternion; ``slerp`` checks both ends, as ``Rotation.from_matrix`` does before
SciPy's ``Slerp`` interpolates; one step of ``integrate_angular_velocity`` checks the attitudes,
as ``Rotation.from_matrix`` does before the product with ``Rotation.from_rotvec``.

The quaternion algebra is timed against SciPy's ``Rotation`` doing the same: ``*`` for the
product, ``inv`` for the conjugate and the inverse, ``from_rotvec`` for the exponential of half a
rotation vector, ``as_rotvec`` for the logarithm and ``**`` for the power; ``random_rotations``
against ``Rotation.random`` and ``mean_rotation`` against ``Rotation.mean`` (both checking the
matrices). ``align_vectors`` solves one problem per call, as SciPy's does, and is timed per call
on typical sizes, as ``mean_rotation`` is on small sets; a last table times one call on one
rotation for each of the new functions.

SciPy has no conversion between Euler-angle rates and angular velocity. Those rows are timed
against a plain NumPy baseline written here, loop-free: the Jacobian built with ``np.stack``
from the three elementary rotations, applied with ``np.einsum`` and inverted with
``np.linalg.solve``. This file is a script, not a test: nothing here asserts a time.
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


def per_call_time(function: Callable[[], object], repeats: int, calls: int = 300) -> float:
    """Shortest mean time of one call, over ``repeats`` runs of ``calls`` calls, in seconds."""
    function()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        for _ in range(calls):
            function()
        times.append((time.perf_counter() - start) / calls)
    return min(times)


def elementary(axis: int, angle: np.ndarray) -> np.ndarray:
    """Rotations by ``angle`` (shape (n,)) about axis 0, 1 or 2, shape (n, 3, 3), by np.stack."""
    c, s = np.cos(angle), np.sin(angle)
    one, zero = np.ones_like(angle), np.zeros_like(angle)
    rows = {
        0: ((one, zero, zero), (zero, c, -s), (zero, s, c)),
        1: ((c, zero, s), (zero, one, zero), (-s, zero, c)),
        2: ((c, -s, zero), (s, c, zero), (zero, zero, one)),
    }[axis]
    return np.stack([np.stack(row, axis=-1) for row in rows], axis=-2)


def baseline_jacobian(angles: np.ndarray, seq: str, frame: str) -> np.ndarray:
    """The Euler-rate Jacobian, shape (n, 3, 3), as plain NumPy would build it.

    Column ``i`` is the axis of rotation ``i`` as it lies when that rotation happens: for the
    intrinsic form ``A B C``, ``(e_A, A e_B, A B e_C)`` in space, ``(Cᵀ Bᵀ e_A, Cᵀ e_B, e_C)`` in
    the body. An extrinsic sequence is the intrinsic one reversed.
    """
    axes = ["xyz".index(letter) for letter in seq.lower()]
    values = angles
    if seq.islower():
        axes, values = axes[::-1], angles[:, ::-1]
    A, B, C = (elementary(axis, values[:, k]) for k, axis in enumerate(axes))
    if frame == "space":
        AB = np.einsum("nij,njk->nik", A, B)
        first = np.broadcast_to(np.eye(3)[axes[0]], (len(angles), 3))
        columns = [first, A[:, :, axes[1]], AB[:, :, axes[2]]]
    else:
        CtBt = np.einsum("nji,nkj->nik", C, B)  # Cᵀ Bᵀ
        last = np.broadcast_to(np.eye(3)[axes[2]], (len(angles), 3))
        columns = [CtBt[:, :, axes[0]], C[:, axes[1], :], last]
    if seq.islower():
        columns.reverse()
    return np.stack(columns, axis=-1)


def baseline_rates_to_omega(angles: np.ndarray, rates: np.ndarray, seq: str) -> np.ndarray:
    return np.einsum("nij,nj->ni", baseline_jacobian(angles, seq, "body"), rates)


def baseline_omega_to_rates(angles: np.ndarray, omega: np.ndarray, seq: str) -> np.ndarray:
    J = baseline_jacobian(angles, seq, "body")
    return np.linalg.solve(J, omega[..., np.newaxis])[..., 0]


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
    rates = rng.normal(size=(n, 3))  # angle rates, and angular velocities in the body
    dt = 1 / 256
    others = Rotation.random(n, rng=rng).as_quat()
    half_rotvecs = rotvecs / 2

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

    assert np.allclose(
        eulerlib.integrate_angular_velocity(R, rates, dt),
        (Rotation.from_matrix(R) * Rotation.from_rotvec(rates * dt)).as_matrix(),
        atol=1e-12,
    )
    scipy_product = (Rotation.from_quat(quaternions) * Rotation.from_quat(others)).as_quat()
    assert np.allclose(eulerlib.quaternion_multiply(quaternions, others), scipy_product)
    assert np.allclose(eulerlib.quaternion_inverse(quaternions), rotation.inv().as_quat())
    assert np.allclose(eulerlib.quaternion_exp(half_rotvecs), rotation.as_quat(canonical=True))
    canonical = rotation.as_quat(canonical=True)  # w ≥ 0: the log and power take the short way
    assert np.allclose(eulerlib.quaternion_log(canonical)[:, :3], rotvecs / 2)
    assert np.allclose(
        eulerlib.quaternion_power(canonical, 0.3), (Rotation.from_quat(canonical) ** 0.3).as_quat()
    )
    assert np.allclose(
        eulerlib.random_rotations(1000, rng=5), Rotation.random(1000, rng=5).as_matrix()
    )
    assert np.allclose(eulerlib.mean_rotation(R), rotation.mean().as_matrix())

    omega = eulerlib.euler_rates_to_angular_velocity(angles, rates, seq)
    assert np.allclose(omega, baseline_rates_to_omega(angles, rates, seq), atol=1e-12)
    away = np.abs(eulerlib.gimbal_lock_status(R, seq).distance) > 1e-3  # well-conditioned
    assert np.allclose(
        eulerlib.angular_velocity_to_euler_rates(angles, rates, seq)[away],
        baseline_omega_to_rates(angles, rates, seq)[away],
        rtol=1e-9,
        atol=1e-9,
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
        (
            "integrate one step, body",
            lambda: eulerlib.integrate_angular_velocity(R, rates, dt),
            lambda: (Rotation.from_matrix(R) * Rotation.from_rotvec(rates * dt)).as_matrix(),
        ),
        (
            "quaternion multiply",
            lambda: eulerlib.quaternion_multiply(quaternions, others),
            lambda: (Rotation.from_quat(quaternions) * Rotation.from_quat(others)).as_quat(),
        ),
        (
            "quaternion conjugate",
            lambda: eulerlib.quaternion_conjugate(quaternions),
            lambda: Rotation.from_quat(quaternions).inv().as_quat(),
        ),
        (
            "quaternion inverse",
            lambda: eulerlib.quaternion_inverse(quaternions),
            lambda: Rotation.from_quat(quaternions).inv().as_quat(),
        ),
        (
            "quaternion exp",
            lambda: eulerlib.quaternion_exp(half_rotvecs),
            lambda: Rotation.from_rotvec(rotvecs).as_quat(),
        ),
        (
            "quaternion log",
            lambda: eulerlib.quaternion_log(quaternions),
            lambda: Rotation.from_quat(quaternions).as_rotvec() / 2,
        ),
        (
            "quaternion power",
            lambda: eulerlib.quaternion_power(quaternions, 0.3),
            lambda: (Rotation.from_quat(quaternions) ** 0.3).as_quat(),
        ),
        (
            "random rotations",
            lambda: eulerlib.random_rotations(n, rng=1),
            lambda: Rotation.random(n, rng=1).as_matrix(),
        ),
        (
            "mean rotation, n rotations",
            lambda: eulerlib.mean_rotation(R),
            lambda: Rotation.from_matrix(R).mean().as_matrix(),
        ),
    ]
    # per call, on the sizes these are called with
    pairs = {count: rng.normal(size=(2, count, 3)) for count in (2, 10, 1000)}
    sets = {count: R[:count] for count in (10, 1000)}
    one_q, other_q, one_v = quaternions[0], others[0], half_rotvecs[0]
    per_call: list[tuple[str, Callable[[], object], Callable[[], object]]] = [
        *(
            (
                f"align_vectors, {count} pairs",
                lambda a=a, b=b: eulerlib.align_vectors(a, b),
                lambda a=a, b=b: Rotation.align_vectors(a, b),
            )
            for count, (a, b) in pairs.items()
        ),
        (
            "align_vectors, TRIAD (inf)",
            lambda: eulerlib.align_vectors(*pairs[2], [np.inf, 1.0]),
            lambda: Rotation.align_vectors(*pairs[2], [np.inf, 1.0]),
        ),
        *(
            (
                f"mean_rotation, {count}",
                lambda M=M: eulerlib.mean_rotation(M),
                lambda M=M: Rotation.from_matrix(M).mean().as_matrix(),
            )
            for count, M in sets.items()
        ),
        (
            "multiply, 1 pair",
            lambda: eulerlib.quaternion_multiply(one_q, other_q),
            lambda: (Rotation.from_quat(one_q) * Rotation.from_quat(other_q)).as_quat(),
        ),
        (
            "conjugate, 1",
            lambda: eulerlib.quaternion_conjugate(one_q),
            lambda: Rotation.from_quat(one_q).inv().as_quat(),
        ),
        (
            "inverse, 1",
            lambda: eulerlib.quaternion_inverse(one_q),
            lambda: Rotation.from_quat(one_q).inv().as_quat(),
        ),
        (
            "exp, 1",
            lambda: eulerlib.quaternion_exp(one_v),
            lambda: Rotation.from_rotvec(2 * one_v).as_quat(),
        ),
        (
            "log, 1",
            lambda: eulerlib.quaternion_log(one_q),
            lambda: Rotation.from_quat(one_q).as_rotvec() / 2,
        ),
        (
            "power, 1",
            lambda: eulerlib.quaternion_power(one_q, 0.3),
            lambda: (Rotation.from_quat(one_q) ** 0.3).as_quat(),
        ),
        (
            "random rotations, 1",
            lambda: eulerlib.random_rotations((), rng=rng),
            lambda: Rotation.random(rng=rng).as_matrix(),
        ),
    ]
    # no SciPy equivalent: eulerlib against the plain NumPy baseline of this script
    baseline_cases: list[tuple[str, Callable[[], object], Callable[[], object]]] = [
        (
            "euler rates -> omega, body",
            lambda: eulerlib.euler_rates_to_angular_velocity(angles, rates, seq),
            lambda: baseline_rates_to_omega(angles, rates, seq),
        ),
        (
            "omega -> euler rates, body",
            lambda: eulerlib.angular_velocity_to_euler_rates(angles, rates, seq),
            lambda: baseline_omega_to_rates(angles, rates, seq),
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
    if any(args.only in name for name, _, _ in per_call):
        print()
        print("Per call, on typical sizes:")
        header = f"{'operation':<32}{'eulerlib':>12}{'scipy':>12}{'scipy/eulerlib':>16}"
        print(header)
        print("-" * len(header))
        for name, ours, theirs in per_call:
            if args.only not in name:
                continue
            t_ours = per_call_time(ours, args.repeats)
            t_theirs = per_call_time(theirs, args.repeats)
            print(
                f"{name:<32}{t_ours * 1e6:>9.1f} µs{t_theirs * 1e6:>9.1f} µs"
                f"{t_theirs / t_ours:>15.2f}x"
            )
    if not any(args.only in name for name, _, _ in baseline_cases):
        return
    print()
    print("SciPy has no Euler-rate conversion; against plain NumPy (np.stack, np.einsum, solve):")
    header = f"{'operation':<32}{'eulerlib':>12}{'numpy':>12}{'numpy/eulerlib':>16}"
    print(header)
    print("-" * len(header))
    for name, ours, theirs in baseline_cases:
        if args.only not in name:
            continue
        t_ours = best_time(ours, args.repeats)
        t_theirs = best_time(theirs, args.repeats)
        print(
            f"{name:<32}{t_ours * 1e3:>9.1f} ms{t_theirs * 1e3:>9.1f} ms{t_theirs / t_ours:>15.2f}x"
        )


if __name__ == "__main__":
    main()
