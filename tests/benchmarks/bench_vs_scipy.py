"""eulerlib against SciPy's ``Rotation``, side by side in one process.

Run::

    python tests/benchmarks/bench_vs_scipy.py [--n 1000000] [--repeats 7] [--seq ZYX] [--only TEXT]
                                              [--table batch|calls|both] [--numpy-only]

It prints two tables. The **batch table** times ``--n`` rotations per call. The **one-call
table** times calls on 1, 10, 100 and 10⁴ rotations (one rotation as a single ``(3,)``,
``(3, 3)`` or ``(4,)`` argument), for every public function with a SciPy counterpart, and for
one rotation also against transforms3d (plain Python and NumPy per rotation, no checks), when it
is installed (the course's ``dev`` extra installs it).

The batch table has a third column where C gives the floor: a small C file of plain loops over
the same arrays, with the same formulas and the same checks (finiteness, ``|R Rᵀ − I| ≤ atol``,
``det R > 0``), written to a temporary folder, compiled with the system's ``cc -O3`` and called
through :mod:`ctypes`. Without a C compiler the column is left out, with a note.

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

eulerlib is timed as installed: with its optional compiled kernels when they were built (the
first line says which), or, with ``--numpy-only``, as if they had not been: run it both ways
to see what the kernels buy.
"""

from __future__ import annotations

import argparse
import ctypes
import platform
import shutil
import subprocess
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np
import scipy
from scipy.spatial.transform import Rotation, Slerp

import eulerlib
from eulerlib import _compiled

try:  # the one-rotation baseline; the course's dev extra installs it
    import transforms3d
    import transforms3d.axangles
    import transforms3d.euler
    import transforms3d.quaternions
except ImportError:
    transforms3d = None


# The C loops of the batch table: the formulas of eulerlib's kernels for "ZYX" in plain C, one
# pass per call; each returns 0, or 1 + the index of the first rotation it refuses.
C_SOURCE = r"""
#include <math.h>
#include <stddef.h>

static int finite9(const double *m) {
    double s = 0.0;
    for (int k = 0; k < 9; k++) s += m[k] - m[k];
    return s == 0.0;
}

static int is_rotation(const double *m, double atol) {
    if (!finite9(m)) return 0;
    double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6])
               + m[2] * (m[3] * m[7] - m[4] * m[6]);
    if (!(det > 0.0) || !(fabs(det - 1.0) <= atol)) return 0;
    for (int r = 0; r < 3; r++)
        for (int c = r; c < 3; c++) {
            double d = m[3 * r] * m[3 * c] + m[3 * r + 1] * m[3 * c + 1]
                     + m[3 * r + 2] * m[3 * c + 2] - (r == c ? 1.0 : 0.0);
            if (!(fabs(d) <= atol)) return 0;
        }
    return 1;
}

long euler_to_matrix(const double *a, double *R, long n) {
    for (long i = 0; i < n; i++, a += 3, R += 9) {
        if (!isfinite(a[0]) || !isfinite(a[1]) || !isfinite(a[2])) return i + 1;
        double s1 = sin(a[0]), c1 = cos(a[0]), s2 = sin(a[1]), c2 = cos(a[1]);
        double s3 = sin(a[2]), c3 = cos(a[2]);
        R[0] = c1 * c2; R[1] = c1 * s2 * s3 - s1 * c3; R[2] = c1 * s2 * c3 + s1 * s3;
        R[3] = s1 * c2; R[4] = s1 * s2 * s3 + c1 * c3; R[5] = s1 * s2 * c3 - c1 * s3;
        R[6] = -s2; R[7] = c2 * s3; R[8] = c2 * c3;
    }
    return 0;
}

long matrix_to_euler(const double *R, double *a, long n, double atol, int check) {
    for (long i = 0; i < n; i++, R += 9, a += 3) {
        if (check ? !is_rotation(R, atol) : !finite9(R)) return i + 1;
        double r = sqrt(R[0] * R[0] + R[3] * R[3]), s = R[3] / r, c = R[0] / r;
        a[0] = atan2(R[3], R[0]);
        a[1] = atan2(-R[6], r);
        a[2] = atan2(s * R[2] - c * R[5], c * R[4] - s * R[1]);
    }
    return 0;
}

long rotate_points(const double *R, long step, const double *p, double *out, long n,
                   double atol, int check) {
    if (step == 0 && check && !is_rotation(R, atol)) return 1;
    for (long i = 0; i < n; i++, R += step, p += 3, out += 3) {
        if (step && (check ? !is_rotation(R, atol) : !finite9(R))) return i + 1;
        if (!isfinite(p[0] + p[1] + p[2])) return i + 1;
        out[0] = R[0] * p[0] + R[1] * p[1] + R[2] * p[2];
        out[1] = R[3] * p[0] + R[4] * p[1] + R[5] * p[2];
        out[2] = R[6] * p[0] + R[7] * p[1] + R[8] * p[2];
    }
    return 0;
}

long matrix_to_quaternion(const double *R, double *q, long n, double atol) {
    for (long i = 0; i < n; i++, R += 9, q += 4) {  /* q as (x, y, z, w) */
        if (!is_rotation(R, atol)) return i + 1;
        double d[4] = {1.0 + R[0] + R[4] + R[8], 1.0 + R[0] - R[4] - R[8],
                       1.0 - R[0] + R[4] - R[8], 1.0 - R[0] - R[4] + R[8]};
        int k = 0;
        for (int j = 1; j < 4; j++) if (d[j] > d[k]) k = j;
        double w, x, y, z, h = 0.5 / sqrt(d[k]);
        if (k == 0) { w = d[0]; x = R[7] - R[5]; y = R[2] - R[6]; z = R[3] - R[1]; }
        else if (k == 1) { w = R[7] - R[5]; x = d[1]; y = R[1] + R[3]; z = R[2] + R[6]; }
        else if (k == 2) { w = R[2] - R[6]; x = R[1] + R[3]; y = d[2]; z = R[5] + R[7]; }
        else { w = R[3] - R[1]; x = R[2] + R[6]; y = R[5] + R[7]; z = d[3]; }
        double sign = w < 0.0 ? -h : h;
        q[0] = x * sign; q[1] = y * sign; q[2] = z * sign; q[3] = w * sign;
    }
    return 0;
}

long quaternion_to_matrix(const double *q, double *R, long n) {
    for (long i = 0; i < n; i++, q += 4, R += 9) {
        double x = q[0], y = q[1], z = q[2], w = q[3];
        double nn = x * x + y * y + z * z + w * w;
        if (!isfinite(nn) || !(nn > 0.0)) return i + 1;
        double s = 2.0 / nn;
        R[0] = 1.0 - s * (y * y + z * z); R[1] = s * (x * y - z * w); R[2] = s * (x * z + y * w);
        R[3] = s * (x * y + z * w); R[4] = 1.0 - s * (x * x + z * z); R[5] = s * (y * z - x * w);
        R[6] = s * (x * z - y * w); R[7] = s * (y * z + x * w); R[8] = 1.0 - s * (x * x + y * y);
    }
    return 0;
}

long matrix_to_rotvec(const double *R, double *v, long n, double atol) {
    double q[4];
    for (long i = 0; i < n; i++, R += 9, v += 3) {
        if (matrix_to_quaternion(R, q, 1, atol)) return i + 1;
        double s = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
        double angle = 2.0 * atan2(s, q[3]);
        double f = s > 0.0 ? angle / s : 2.0;
        v[0] = f * q[0]; v[1] = f * q[1]; v[2] = f * q[2];
    }
    return 0;
}

long rotvec_to_matrix(const double *v, double *R, long n) {
    for (long i = 0; i < n; i++, v += 3, R += 9) {
        double x = v[0], y = v[1], z = v[2];
        double t = sqrt(x * x + y * y + z * z);
        if (!isfinite(t)) return i + 1;
        double s = t > 1e-8 ? sin(t) / t : 1.0 - t * t / 6.0;
        double k = t > 1e-8 ? (1.0 - cos(t)) / (t * t) : 0.5 - t * t / 24.0;
        R[0] = 1.0 - k * (y * y + z * z); R[1] = k * x * y - s * z; R[2] = k * x * z + s * y;
        R[3] = k * x * y + s * z; R[4] = 1.0 - k * (x * x + z * z); R[5] = k * y * z - s * x;
        R[6] = k * x * z - s * y; R[7] = k * y * z + s * x; R[8] = 1.0 - k * (x * x + y * y);
    }
    return 0;
}

long euler_to_quaternion(const double *a, double *q, long n) {
    for (long i = 0; i < n; i++, a += 3, q += 4) {
        if (!isfinite(a[0]) || !isfinite(a[1]) || !isfinite(a[2])) return i + 1;
        double c1 = cos(0.5 * a[0]), s1 = sin(0.5 * a[0]), c2 = cos(0.5 * a[1]);
        double s2 = sin(0.5 * a[1]), c3 = cos(0.5 * a[2]), s3 = sin(0.5 * a[2]);
        q[0] = c1 * c2 * s3 - s1 * s2 * c3; q[1] = c1 * s2 * c3 + s1 * c2 * s3;
        q[2] = s1 * c2 * c3 - c1 * s2 * s3; q[3] = c1 * c2 * c3 + s1 * s2 * s3;
    }
    return 0;
}

long quaternion_to_euler(const double *q, double *a, long n) {
    double R[9];
    for (long i = 0; i < n; i++, q += 4, a += 3) {
        if (quaternion_to_matrix(q, R, 1)) return i + 1;
        matrix_to_euler(R, a, 1, 0.0, 0);
    }
    return 0;
}
"""


def compile_c_loops() -> tuple[ctypes.CDLL | None, str]:
    """The C loops above, compiled with ``cc -O3`` into a temporary folder, or None and why."""
    compiler = shutil.which("cc")
    if compiler is None:
        return None, "no C compiler (cc) on this machine: the C column is left out"
    folder = Path(tempfile.mkdtemp(prefix="eulerlib-bench-"))
    (folder / "loops.c").write_text(C_SOURCE)
    library = folder / "loops.so"
    command = [compiler, "-O3", "-shared", "-fPIC", "-o", str(library), str(folder / "loops.c")]
    done = subprocess.run([*command, "-lm"], capture_output=True, text=True, check=False)
    if done.returncode:
        return None, f"cc -O3 failed, the C column is left out: {done.stderr.strip()[:200]}"
    return ctypes.CDLL(str(library)), f"C: {compiler} -O3, plain loops, one pass per call"


def c_call(
    loops: ctypes.CDLL, name: str, *arrays: np.ndarray, extra: tuple = ()
) -> Callable[[], object]:
    """A call of C loop ``name`` on ``arrays`` (the last one is written), then the count."""
    function = getattr(loops, name)
    function.restype = ctypes.c_long
    pointers = [a.ctypes.data_as(ctypes.POINTER(ctypes.c_double)) for a in arrays]
    count = ctypes.c_long(len(arrays[-1]))

    def call() -> object:
        refused = function(*pointers, count, *extra)
        assert refused == 0, f"{name} refused rotation {refused - 1}"
        return arrays[-1]

    return call


def best_time(function: Callable[[], object], repeats: int) -> float:
    """Shortest wall-clock time of ``repeats`` calls, in seconds."""
    function()  # warm up: first-call allocations, lazy imports
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times)


def call_times(functions: list[Callable[[], object]], repeats: int) -> list[float]:
    """The shortest time of one call of each function, in seconds: best of ``repeats`` runs of
    enough calls to fill about 20 ms each, the functions' runs taken in turn (one run of each,
    then the next round), so that a burst of other work on the machine falls on all of them
    alike rather than on one side of a ratio."""
    calls = []
    for function in functions:  # warm up, and find how many calls fill about 20 ms
        function()
        count = 1
        while True:
            start = time.perf_counter()
            for _ in range(count):
                function()
            if time.perf_counter() - start > 0.02:
                break
            count *= 10
        calls.append(count)
    best = [float("inf")] * len(functions)
    for _ in range(repeats):
        for n, (function, count) in enumerate(zip(functions, calls, strict=True)):
            start = time.perf_counter()
            for _ in range(count):
                function()
            best[n] = min(best[n], (time.perf_counter() - start) / count)
    return best


ONE_CALL_SIZES = (1, 10, 100, 10_000)

Case = tuple[str, Callable[[], object], Callable[[], object], "Callable[[], object] | None"]


def one_call_cases(k: int, seq: str) -> list[Case]:
    """Every public function with a SciPy counterpart, on ``k`` rotations (a single one for 1):
    (name, eulerlib, SciPy, transforms3d or None)."""
    rng = np.random.default_rng(k)
    count = None if k == 1 else k
    rotation = Rotation.random(count, rng=rng)
    other = Rotation.random(count, rng=rng)
    angles = rotation.as_euler(seq)
    R, R1 = rotation.as_matrix(), other.as_matrix()
    q = rotation.as_quat()
    v = rotation.as_rotvec()
    angle = np.linalg.norm(v, axis=-1)
    axis = v / angle[..., np.newaxis]
    points = rng.normal(size=(3,) if k == 1 else (k, 3))
    omega = rng.normal(size=(3,) if k == 1 else (k, 3))
    t = rng.uniform(0.0, 1.0, size=count)
    single = rng.uniform(-np.pi, np.pi, size=count)
    noisy = R + 1e-9 * rng.normal(size=R.shape)
    ypr = eulerlib.matrix_to_euler(R, "ZYX")
    hab = eulerlib.matrix_to_euler(R, "YZX")
    if k == 1:
        pair_keys, pair_times = Rotation.from_matrix(np.stack([R, R1])), [0.0, 1.0]
        at = float(t)
    else:
        pair_keys = Rotation.from_matrix(np.stack([R, R1], axis=1).reshape(-1, 3, 3))
        pair_times = np.arange(2 * k)
        at = 2 * np.arange(k) + t
    cases: list[Case] = [
        (
            "euler_to_matrix",
            lambda: eulerlib.euler_to_matrix(angles, seq),
            lambda: Rotation.from_euler(seq, angles).as_matrix(),
            None,
        ),
        (
            "matrix_to_euler",
            lambda: eulerlib.matrix_to_euler(R, seq),
            lambda: Rotation.from_matrix(R).as_euler(seq),
            None,
        ),
        (
            "convert_angles",
            lambda: eulerlib.convert_angles(angles, seq, seq.lower()),
            lambda: Rotation.from_euler(seq, angles).as_euler(seq.lower()),
            None,
        ),
        (
            "yaw_pitch_roll_to_matrix",
            lambda: eulerlib.yaw_pitch_roll_to_matrix(*ypr.T),
            lambda: Rotation.from_euler("ZYX", ypr).as_matrix(),
            None,
        ),
        (
            "matrix_to_yaw_pitch_roll",
            lambda: eulerlib.matrix_to_yaw_pitch_roll(R),
            lambda: Rotation.from_matrix(R).as_euler("ZYX"),
            None,
        ),
        (
            "heading_attitude_bank_to_matrix",
            lambda: eulerlib.heading_attitude_bank_to_matrix(*hab.T),
            lambda: Rotation.from_euler("YZX", hab).as_matrix(),
            None,
        ),
        (
            "matrix_to_heading_attitude_bank",
            lambda: eulerlib.matrix_to_heading_attitude_bank(R),
            lambda: Rotation.from_matrix(R).as_euler("YZX"),
            None,
        ),
        (
            "rot_x",
            lambda: eulerlib.rot_x(single),
            lambda: Rotation.from_euler(
                "x", single if k == 1 else single[:, np.newaxis]
            ).as_matrix(),
            None,
        ),
        (
            "euler_to_quaternion",
            lambda: eulerlib.euler_to_quaternion(angles, seq),
            lambda: Rotation.from_euler(seq, angles).as_quat(),
            None,
        ),
        (
            "quaternion_to_euler",
            lambda: eulerlib.quaternion_to_euler(q, seq),
            lambda: Rotation.from_quat(q).as_euler(seq),
            None,
        ),
        (
            "quaternion_to_matrix",
            lambda: eulerlib.quaternion_to_matrix(q),
            lambda: Rotation.from_quat(q).as_matrix(),
            None,
        ),
        (
            "matrix_to_quaternion",
            lambda: eulerlib.matrix_to_quaternion(R),
            lambda: Rotation.from_matrix(R).as_quat(),
            None,
        ),
        (
            "rotvec_to_matrix",
            lambda: eulerlib.rotvec_to_matrix(v),
            lambda: Rotation.from_rotvec(v).as_matrix(),
            None,
        ),
        (
            "matrix_to_rotvec",
            lambda: eulerlib.matrix_to_rotvec(R),
            lambda: Rotation.from_matrix(R).as_rotvec(),
            None,
        ),
        (
            "axis_angle_to_matrix",
            lambda: eulerlib.axis_angle_to_matrix(axis, angle),
            lambda: Rotation.from_rotvec(axis * angle[..., np.newaxis]).as_matrix(),
            None,
        ),
        (
            "matrix_to_axis_angle",
            lambda: eulerlib.matrix_to_axis_angle(R),
            lambda: np.linalg.norm(Rotation.from_matrix(R).as_rotvec(), axis=-1),
            None,
        ),
        (
            "rotation_angle",
            lambda: eulerlib.rotation_angle(R),
            lambda: Rotation.from_matrix(R).magnitude(),
            None,
        ),
        (
            "angle_between",
            lambda: eulerlib.angle_between(R, R1),
            lambda: (Rotation.from_matrix(R).inv() * Rotation.from_matrix(R1)).magnitude(),
            None,
        ),
        (
            "rotate_points",
            lambda: eulerlib.rotate_points(R, points),
            lambda: Rotation.from_matrix(R).apply(points),
            None,
        ),
        (
            "invert",
            lambda: eulerlib.invert(R),
            lambda: Rotation.from_matrix(R).inv().as_matrix(),
            None,
        ),
        (
            "compose",
            lambda: eulerlib.compose(R, R1),
            lambda: (Rotation.from_matrix(R) * Rotation.from_matrix(R1)).as_matrix(),
            None,
        ),
        (
            "nearest_rotation",
            lambda: eulerlib.nearest_rotation(noisy),
            lambda: Rotation.from_matrix(noisy).as_matrix(),
            None,
        ),
        (
            "slerp",
            lambda: eulerlib.slerp(R, R1, t),
            lambda: Slerp(pair_times, pair_keys)(at).as_matrix(),
            None,
        ),
        (
            "integrate_angular_velocity",
            lambda: eulerlib.integrate_angular_velocity(R, omega, 0.01),
            lambda: (Rotation.from_matrix(R) * Rotation.from_rotvec(omega * 0.01)).as_matrix(),
            None,
        ),
    ]
    if k == 1 and transforms3d is not None:
        t3d = transforms3d
        axes = ("r" if seq.isupper() else "s") + seq.lower()
        if seq.islower():
            axes = "s" + seq
        wxyz = np.roll(q, 1)
        baseline: dict[str, Callable[[], object]] = {
            "euler_to_matrix": lambda: t3d.euler.euler2mat(*angles, axes),
            "matrix_to_euler": lambda: t3d.euler.mat2euler(R, axes),
            "euler_to_quaternion": lambda: t3d.euler.euler2quat(*angles, axes),
            "quaternion_to_euler": lambda: t3d.euler.quat2euler(wxyz, axes),
            "quaternion_to_matrix": lambda: t3d.quaternions.quat2mat(wxyz),
            "matrix_to_quaternion": lambda: t3d.quaternions.mat2quat(R),
            "rotvec_to_matrix": lambda: t3d.axangles.axangle2mat(v, np.linalg.norm(v)),
            "matrix_to_rotvec": lambda: np.multiply(*t3d.axangles.mat2axangle(R)),
            "axis_angle_to_matrix": lambda: t3d.axangles.axangle2mat(axis, angle),
            "matrix_to_axis_angle": lambda: t3d.axangles.mat2axangle(R),
            "rotate_points": lambda: R @ points,
            "invert": lambda: R.T,
            "compose": lambda: R @ R1,
            "rot_x": lambda: t3d.euler.euler2mat(single, 0.0, 0.0, "sxyz"),
        }
        cases = [(name, ours, theirs, baseline.get(name)) for name, ours, theirs, _ in cases]
    return cases


def one_call_table(seq: str, repeats: int, only: str) -> None:
    """The one-call table: SciPy's time over eulerlib's at each size, and at one rotation
    eulerlib's time and transforms3d's time over eulerlib's."""
    by_size = {k: one_call_cases(k, seq) for k in ONE_CALL_SIZES}
    print()
    print(
        "One call on k rotations: scipy/eulerlib time at each k, eulerlib's time for one "
        "rotation, and transforms3d/eulerlib for one rotation"
        + ("" if transforms3d is not None else " (transforms3d is not installed)")
    )
    header = (
        f"{'function':<34}{'1 rotation':>11}"
        + "".join(f"{'k=' + str(k):>9}" for k in ONE_CALL_SIZES)
        + f"{'t3d':>8}"
    )
    print(header)
    print("-" * len(header))
    for row, (name, *_rest) in enumerate(by_size[1]):
        if only not in name:
            continue
        line, single, t3d = "", 0.0, f"{'':>8}"
        for k in ONE_CALL_SIZES:
            _, ours, theirs, baseline = by_size[k][row]
            timed = [ours, theirs] + ([baseline] if baseline is not None else [])
            t_ours, t_theirs, *t_baseline = call_times(timed, repeats)
            if k == 1:
                single = t_ours
                if t_baseline:
                    t3d = f"{t_baseline[0] / t_ours:>7.2f}x"
            line += f"{t_theirs / t_ours:>8.2f}x"
        print(f"{name:<34}{single * 1e6:>8.1f} µs{line}{t3d}")


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
    parser.add_argument(
        "--table",
        choices=("batch", "calls", "both"),
        default="both",
        help="the batch table (--n rotations), the one-call table (1 to 10⁴), or both",
    )
    parser.add_argument(
        "--numpy-only",
        action="store_true",
        help="time eulerlib as if its optional compiled kernels had not been built",
    )
    args = parser.parse_args(argv)
    n, seq = args.n, args.seq
    if args.numpy_only:
        _compiled.euler = _compiled.rotations = _compiled.operations = None
    built = all(kernels is not None for kernels in (_compiled.euler, _compiled.rotations))
    print(
        f"seq = {seq!r}, best of {args.repeats}; numpy {np.__version__}, "
        f"scipy {scipy.__version__}, Python {platform.python_version()} on {platform.machine()}; "
        + ("eulerlib with its compiled kernels" if built else "eulerlib on numpy only")
    )
    if args.table in ("calls", "both"):
        one_call_table(seq, args.repeats, args.only)
    if args.table in ("batch", "both"):
        batch_table(n, seq, args.repeats, args.only)


def batch_table(n: int, seq: str, repeats: int, only: str) -> None:
    """The batch table: ``n`` rotations per call, SciPy and C loops beside eulerlib."""

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

    loops, note = compile_c_loops() if seq == "ZYX" else (None, "C loops are written for 'ZYX'")
    c_cases: dict[str, Callable[[], object]] = {}
    if loops is not None:
        atol = ctypes.c_double(eulerlib.ROTATION_ATOL)
        yes, no = ctypes.c_int(1), ctypes.c_int(0)
        out3, out4, out9 = np.empty((n, 3)), np.empty((n, 4)), np.empty((n, 3, 3))
        c_cases = {
            "euler -> matrix": c_call(loops, "euler_to_matrix", angles, out9),
            "matrix -> euler, validating": c_call(
                loops, "matrix_to_euler", R, out3, extra=(atol, yes)
            ),
            "matrix -> euler, no check": c_call(
                loops, "matrix_to_euler", R, out3, extra=(atol, no)
            ),
            "matrix -> quaternion": c_call(loops, "matrix_to_quaternion", R, out4, extra=(atol,)),
            "quaternion -> matrix": c_call(loops, "quaternion_to_matrix", quaternions, out9),
            "matrix -> rotvec": c_call(loops, "matrix_to_rotvec", R, out3, extra=(atol,)),
            "rotvec -> matrix": c_call(loops, "rotvec_to_matrix", rotvecs, out9),
            "euler -> quaternion": c_call(loops, "euler_to_quaternion", angles, out4),
            "quaternion -> euler": c_call(loops, "quaternion_to_euler", quaternions, out3),
        }
        rotate = loops.rotate_points
        rotate.restype = ctypes.c_long
        for name, step, check in (
            ("rotate points, from matrices", 9, yes),
            ("rotate points, no check", 9, no),
            ("rotate points, checked before", 9, no),
            ("rotate points, 1 rotation", 0, yes),
        ):
            source = R if step else one_R
            pointers = [
                a.ctypes.data_as(ctypes.POINTER(ctypes.c_double)) for a in (source, points, out3)
            ]

            def call(
                pointers: list[object] = pointers, step: int = step, check: object = check
            ) -> object:
                refused = rotate(
                    pointers[0],
                    ctypes.c_long(step),
                    pointers[1],
                    pointers[2],
                    ctypes.c_long(n),
                    atol,
                    check,
                )
                assert refused == 0
                return out3

            c_cases[name] = call
        # the C loops compute what eulerlib computes
        for name, expected in (
            ("euler -> matrix", R.reshape(n, 3, 3)),
            ("matrix -> euler, validating", angles),
            ("matrix -> quaternion", eulerlib.matrix_to_quaternion(R)),
            ("quaternion -> matrix", R),
            ("matrix -> rotvec", rotvecs),
            ("rotvec -> matrix", R),
            ("euler -> quaternion", eulerlib.euler_to_quaternion(angles, seq)),
            ("quaternion -> euler", angles),
            ("rotate points, from matrices", rotation.apply(points)),
            ("rotate points, 1 rotation", one_rotation.apply(points)),
        ):
            computed = np.asarray(c_cases[name]())
            if "-> quaternion" in name:  # q and -q are one rotation
                computed = computed * np.sign(computed[:, 3:] * expected[:, 3:])
            assert np.allclose(computed, expected, atol=1e-9), name
    print()
    print(f"Batch: n = {n:,} rotations per call; {note}")
    header = (
        f"{'operation':<32}{'eulerlib':>12}{'scipy':>12}{'scipy/eulerlib':>16}"
        f"{'C':>10}{'eulerlib/C':>12}"
    )
    print(header)
    print("-" * len(header))
    for name, ours, theirs in cases:
        if only not in name:
            continue
        t_ours = best_time(ours, repeats)
        t_theirs = best_time(theirs, repeats)
        line = (
            f"{name:<32}{t_ours * 1e3:>9.1f} ms{t_theirs * 1e3:>9.1f} ms{t_theirs / t_ours:>15.2f}x"
        )
        if name in c_cases:
            t_c = best_time(c_cases[name], repeats)
            line += f"{t_c * 1e3:>7.1f} ms{t_ours / t_c:>11.2f}x"
        print(line)
    if any(only in name for name, _, _ in per_call):
        print()
        print("Per call, on typical sizes:")
        header = f"{'operation':<32}{'eulerlib':>12}{'scipy':>12}{'scipy/eulerlib':>16}"
        print(header)
        print("-" * len(header))
        for name, ours, theirs in per_call:
            if only not in name:
                continue
            t_ours = per_call_time(ours, repeats)
            t_theirs = per_call_time(theirs, repeats)
            print(
                f"{name:<32}{t_ours * 1e6:>9.1f} µs{t_theirs * 1e6:>9.1f} µs"
                f"{t_theirs / t_ours:>15.2f}x"
            )
    if not any(only in name for name, _, _ in baseline_cases):
        return
    print()
    print("SciPy has no Euler-rate conversion; against plain NumPy (np.stack, np.einsum, solve):")
    header = f"{'operation':<32}{'eulerlib':>12}{'numpy':>12}{'numpy/eulerlib':>16}"
    print(header)
    print("-" * len(header))
    for name, ours, theirs in baseline_cases:
        if only not in name:
            continue
        t_ours = best_time(ours, repeats)
        t_theirs = best_time(theirs, repeats)
        print(
            f"{name:<32}{t_ours * 1e3:>9.1f} ms{t_theirs * 1e3:>9.1f} ms{t_theirs / t_ours:>15.2f}x"
        )


if __name__ == "__main__":
    main()
