"""A 50-digit reference for rotations, written here with mpmath and nothing from eulerlib.

The reference answer is the exact answer for the float64 input: every float is converted to
mpmath exactly, and the arithmetic is done with 50 significant digits. A float64 matrix is
never exactly orthogonal, so the rotation it stands for is taken to be its orthogonal polar
factor (the nearest rotation), found by Newton's iteration ``X ← (X + X⁻ᵀ) / 2``. The formulas
are the textbook ones, which are exact in exact arithmetic; with 50 digits their cancellations
cost nothing that shows at float64's 16.

Results are returned as mpmath numbers; :func:`to_float` rounds them to float64 once, at the end.
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction

import mpmath
import numpy as np

DIGITS = 50
EPS = float(np.finfo(np.float64).eps)

MP = mpmath.mpf
Vector = list[mpmath.mpf]
Matrix = list[list[mpmath.mpf]]


def mp_vector(values: Sequence[float]) -> Vector:
    """Floats to mpmath numbers, exactly."""
    return [MP(float(v)) for v in values]


def mp_matrix(R: np.ndarray) -> Matrix:
    """A float 3×3 matrix to mpmath numbers, exactly."""
    return [[MP(float(R[i, j])) for j in range(3)] for i in range(3)]


def to_float(values: object) -> np.ndarray:
    """mpmath numbers (nested lists) rounded to float64."""
    return np.array(values, dtype=object).astype(np.float64)


def _transpose(A: Matrix) -> Matrix:
    return [[A[j][i] for j in range(3)] for i in range(3)]


def _multiply(A: Matrix, B: Matrix) -> Matrix:
    return [[sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def _inverse_transpose(A: Matrix) -> Matrix:
    """``A⁻ᵀ``: the cofactor matrix divided by the determinant."""

    def cofactor(i: int, j: int) -> mpmath.mpf:
        r = [k for k in range(3) if k != i]
        c = [k for k in range(3) if k != j]
        minor = A[r[0]][c[0]] * A[r[1]][c[1]] - A[r[0]][c[1]] * A[r[1]][c[0]]
        return minor if (i + j) % 2 == 0 else -minor

    C = [[cofactor(i, j) for j in range(3)] for i in range(3)]
    det = sum(A[0][j] * C[0][j] for j in range(3))
    return [[C[i][j] / det for j in range(3)] for i in range(3)]


def polar(R: np.ndarray) -> Matrix:
    """The rotation a float matrix stands for: its orthogonal polar factor, to 50 digits."""
    with mpmath.workdps(DIGITS + 10):
        X = mp_matrix(R)
        for _ in range(60):
            Y = _inverse_transpose(X)
            new = [[(X[i][j] + Y[i][j]) / 2 for j in range(3)] for i in range(3)]
            change = max(abs(new[i][j] - X[i][j]) for i in range(3) for j in range(3))
            X = new
            if change < MP(10) ** (-(DIGITS + 5)):
                return X
    raise AssertionError("the polar iteration did not converge")


def canonical(q: Vector) -> Vector:
    """The one of ``q``, ``-q`` with w > 0, or at w = 0 the first nonzero of x, y, z > 0."""
    for component in q:
        if component != 0:
            return q if component > 0 else [-c for c in q]
    raise AssertionError("zero quaternion")


def quaternion_of(Q: Matrix) -> Vector:
    """Canonical unit quaternion ``[w, x, y, z]`` of an exact rotation matrix."""
    with mpmath.workdps(DIGITS + 10):
        t = Q[0][0] + Q[1][1] + Q[2][2]
        squares = [1 + t, 1 + 2 * Q[0][0] - t, 1 + 2 * Q[1][1] - t, 1 + 2 * Q[2][2] - t]
        k = max(range(4), key=lambda i: squares[i])
        big = mpmath.sqrt(squares[k]) / 2
        four = 4 * big
        w_x = (Q[2][1] - Q[1][2]) / four
        w_y = (Q[0][2] - Q[2][0]) / four
        w_z = (Q[1][0] - Q[0][1]) / four
        x_y = (Q[0][1] + Q[1][0]) / four
        x_z = (Q[0][2] + Q[2][0]) / four
        y_z = (Q[1][2] + Q[2][1]) / four
        q = [
            [big, w_x, w_y, w_z],
            [w_x, big, x_y, x_z],
            [w_y, x_y, big, y_z],
            [w_z, x_z, y_z, big],
        ][k]
        return canonical(q)


def unit(v: Vector) -> Vector:
    with mpmath.workdps(DIGITS + 10):
        length = mpmath.sqrt(sum(c * c for c in v))
        return [c / length for c in v]


def matrix_of_quaternion(q: Vector) -> Matrix:
    """Rotation matrix of ``[w, x, y, z]``, normalized exactly first."""
    with mpmath.workdps(DIGITS + 10):
        w, x, y, z = unit(q)
        return [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]


def multiply(p: Vector, q: Vector) -> Vector:
    """Hamilton product of ``[w, x, y, z]`` quaternions."""
    a, b, c, d = p
    e, f, g, h = q
    return [
        a * e - b * f - c * g - d * h,
        a * f + b * e + c * h - d * g,
        a * g - b * h + c * e + d * f,
        a * h + b * g - c * f + d * e,
    ]


def axis_angle_of(Q: Matrix) -> tuple[Vector, mpmath.mpf]:
    """Unit axis and angle in [0, π] of an exact rotation; the axis of the canonical quaternion."""
    with mpmath.workdps(DIGITS + 10):
        w, *v = quaternion_of(Q)
        length = mpmath.sqrt(sum(c * c for c in v))
        angle = 2 * mpmath.atan2(length, w)
        if length == 0:
            return [MP(1), MP(0), MP(0)], angle
        return [c / length for c in v], angle


def radians_of(angle: float, degrees: bool) -> mpmath.mpf:
    """A float angle in radians, exactly; in degrees reduced modulo 360 with exact rationals."""
    if not degrees:
        return MP(float(angle))
    reduced = Fraction(float(angle)) % 360
    return mpmath.pi * MP(reduced.numerator) / MP(reduced.denominator) / 180


def quaternion_of_axis_angle(axis: Vector, angle: mpmath.mpf) -> Vector:
    with mpmath.workdps(DIGITS + 10):
        n = unit(axis)
        half = angle / 2
        return [mpmath.cos(half)] + [mpmath.sin(half) * c for c in n]


def matrix_of_axis_angle(axis: Vector, angle: mpmath.mpf) -> Matrix:
    """Rodrigues: ``cos θ I + sin θ [n]× + (1 − cos θ) n nᵀ``, typed as such."""
    with mpmath.workdps(DIGITS + 10):
        n = unit(axis)
        c, s = mpmath.cos(angle), mpmath.sin(angle)
        cross = [[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]]
        return [
            [(c if i == j else 0) + s * cross[i][j] + (1 - c) * n[i] * n[j] for j in range(3)]
            for i in range(3)
        ]


def matrix_of_rotvec(v: Sequence[float], degrees: bool) -> Matrix:
    """Rotation matrix of a float rotation vector (length in degrees if asked)."""
    with mpmath.workdps(DIGITS + 10):
        components = mp_vector(v)
        length = mpmath.sqrt(sum(c * c for c in components))
        if length == 0:
            return [[MP(1 if i == j else 0) for j in range(3)] for i in range(3)]
        angle = length * mpmath.pi / 180 if degrees else length
        return matrix_of_axis_angle(components, angle)


def elementary_quaternion(axis: str, angle: mpmath.mpf) -> Vector:
    half = angle / 2
    q = [mpmath.cos(half), MP(0), MP(0), MP(0)]
    q[1 + "xyz".index(axis.lower())] = mpmath.sin(half)
    return q


def quaternion_of_euler(angles: Sequence[float], seq: str, degrees: bool) -> Vector:
    """Canonical quaternion of Euler angles as SciPy reads ``seq``: the product of three
    elementary quaternions, in written order for intrinsic (uppercase) sequences and in
    reverse for extrinsic (lowercase) ones."""
    with mpmath.workdps(DIGITS + 10):
        factors = [
            elementary_quaternion(axis, radians_of(angle, degrees))
            for axis, angle in zip(seq, angles, strict=True)
        ]
        if seq.islower():
            factors = factors[::-1]
        q = multiply(multiply(factors[0], factors[1]), factors[2])
        return canonical(q)


def rotation_angle_of(Q: Matrix) -> mpmath.mpf:
    return axis_angle_of(Q)[1]


def slerp_of(Q0: Matrix, Q1: Matrix, t: float) -> Matrix:
    """``Q0 Exp(t log(Q0ᵀ Q1))`` with the axis of the canonical quaternion of ``Q0ᵀ Q1``."""
    with mpmath.workdps(DIGITS + 10):
        axis, angle = axis_angle_of(_multiply(_transpose(Q0), Q1))
        return _multiply(Q0, matrix_of_axis_angle(axis, angle * MP(float(t))))


def slerp_other_way_of(Q0: Matrix, Q1: Matrix, t: float) -> Matrix:
    """The geodesic the long way round: ``Q0 Rot(n, −t (2π − θ))``, the other answer when
    ``Q0ᵀ Q1`` is a half turn (θ = π), and nearly one within rounding of it."""
    with mpmath.workdps(DIGITS + 10):
        axis, angle = axis_angle_of(_multiply(_transpose(Q0), Q1))
        turn = -(2 * mpmath.pi - angle) * MP(float(t))
        return _multiply(Q0, matrix_of_axis_angle(axis, turn))


def transpose_product(Q0: Matrix, Q1: Matrix) -> Matrix:
    return _multiply(_transpose(Q0), Q1)


def random_axis(rng: np.random.Generator) -> Vector:
    """A random direction as mpmath numbers (not rounded to float64 on purpose)."""
    return unit(mp_vector(rng.normal(size=3)))


# --- the hard places, built exactly and rounded to float64 once ---------------------------------

#: Angles near 0, as exact mpmath numbers: where sin θ / θ and (1 − cos θ) / θ² lose digits.
SMALL_ANGLES = tuple(MP(10) ** -k for k in (300, 200, 100, 50, 20, 16, 12, 10, 8, 6, 4))
#: Distances from π, as exact mpmath numbers (and 0: exactly a half turn).
BELOW_PI = (0, *(MP(10) ** -k for k in (16, 15, 14, 12, 10, 8, 6, 4)))


def coordinate_and_random_axes(rng: np.random.Generator, count: int) -> list[Vector]:
    """The three coordinate axes, one diagonal, and ``count`` random directions (exact)."""
    axes = [mp_vector(a) for a in ([1, 0, 0], [0, 1, 0], [0, 0, 1], [1, -1, 1])]
    return axes + [random_axis(rng) for _ in range(count)]


def hard_rotations(rng: np.random.Generator, axes: int = 3) -> list[tuple[str, np.ndarray]]:
    """``(label, R)``: rotation matrices rounded once from exact ones, at the hard places.

    Angles from 1e-300 to 1e-4, and from π − 1e-4 to exactly π, about coordinate and random
    axes, plus random rotations.
    """
    cases = []
    with mpmath.workdps(DIGITS + 10):
        for axis in coordinate_and_random_axes(rng, axes):
            for angle in SMALL_ANGLES:
                cases.append((f"angle {float(angle):.0e}", matrix_of_axis_angle(axis, angle)))
            for below in BELOW_PI:
                label = "angle pi" if below == 0 else f"angle pi - {float(below):.0e}"
                cases.append((label, matrix_of_axis_angle(axis, mpmath.pi - below)))
        for _ in range(4 * axes):
            angle = mpmath.pi * MP(float(rng.uniform(0.0, 1.0)))
            cases.append(("random", matrix_of_axis_angle(random_axis(rng), angle)))
    return [(label, to_float(R)) for label, R in cases]


def ulps(value: float, exact: mpmath.mpf) -> float:
    """``|value − exact|`` in units in the last place of ``exact`` (as np.spacing counts them)."""
    return float(abs(MP(float(value)) - exact)) / float(np.spacing(abs(float(exact)) or 1.0))


def absolute_ulps(values: np.ndarray, exact: object) -> float:
    """Largest ``|value − exact|`` of arrays of numbers of size up to 1, in units of 2⁻⁵²."""
    exact_array = np.array(exact, dtype=object).reshape(-1)
    worst = max(abs(MP(float(v)) - e) for v, e in zip(np.ravel(values), exact_array, strict=True))
    return float(worst) / EPS


def quaternion_ulps(q: np.ndarray, exact: Vector) -> float:
    """:func:`absolute_ulps` of a ``[w, x, y, z]`` quaternion; when the exact scalar part is
    within a few units of 0, either sign of the quaternion is accepted, since the canonical
    choice between ``q`` and ``-q`` then depends on the last bits."""
    error = absolute_ulps(q, exact)
    if abs(exact[0]) <= 8 * EPS:
        error = min(error, absolute_ulps(-q, exact))
    return error
