"""The arithmetic of the kernels for one rotation, in Python floats.

A call on a single rotation spends most of its time in numpy's set-up of many small array
operations, not in arithmetic. These functions compute the same formulas as the array kernels
(:mod:`eulerlib._euler_kernels`, :mod:`eulerlib._quaternion_kernels`, :mod:`eulerlib._trig`)
on Python floats, operation for operation in the same order, so that both give the same
result to the last bit. The transcendental functions are numpy's, called once on the few
values of a rotation (numpy's vectorized ``sin``, ``cos``, ``tan`` and ``arctan2`` may differ
from :mod:`math`'s by a unit in the last place, and an angle solved from another would carry
that on); everything else is Python arithmetic, which rounds exactly as numpy's element-wise
operations do.

Nothing here checks its input; :mod:`eulerlib._scalar` reads and checks a single rotation and
returns ``None`` for anything the array path must handle (a lock, a zero quaternion, an input
of unusual scale), so that every refusal and every warning comes from one place.
"""

from __future__ import annotations

import math

import numpy as np

from eulerlib._euler_kernels import frame
from eulerlib._quaternion_kernels import _OFF_DIAGONAL
from eulerlib._sequences import Sequence

Three = tuple[float, float, float]
Four = tuple[float, float, float, float]
Nine = tuple[float, float, float, float, float, float, float, float, float]

# squared lengths of quaternions between these bounds need no rescaling (as _length_kernels)
_SMALL, _LARGE = 2.0**-1000, 2.0**1000
_HALF_QUARTER = ((1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (-1.0, 1.0))  # as _trig's, by k mod 4


def quarter_turns(angle: float) -> tuple[float, float]:
    """``angle`` in degrees as ``k · 90° + r`` exactly, ``r`` in radians
    (:func:`eulerlib._trig.quarter_turns`)."""
    reduced = math.fmod(angle, 360.0)
    quarter = float(round(reduced / 90.0))  # round half to even, as np.round
    return quarter, math.radians(reduced - 90.0 * quarter)


def sin_cos(angles: Three, degrees: bool) -> tuple[list[float], list[float]]:
    """``(sin, cos)`` of three angles, as :func:`eulerlib._trig.sin_cos`."""
    if not degrees:
        return np.sin(angles).tolist(), np.cos(angles).tolist()
    split = [quarter_turns(angle) for angle in angles]
    rests = [rest for _, rest in split]
    sines, cosines = np.sin(rests).tolist(), np.cos(rests).tolist()
    for n, (quarter, _) in enumerate(split):
        s, c = sines[n], cosines[n]
        turn = quarter % 4.0
        if turn == 0.0:
            sine, cosine = s, c
        elif turn == 1.0:
            sine, cosine = c, -s
        elif turn == 2.0:
            sine, cosine = -s, -c
        else:
            sine, cosine = -c, s
        sines[n], cosines[n] = sine + 0.0, cosine + 0.0
    return sines, cosines


def half_angle_pairs(angles: Three, degrees: bool) -> tuple[list[float], list[float]]:
    """Positive multiples ``(a, b)`` of ``(cos(θ/2), sin(θ/2))`` for three angles, as
    :func:`eulerlib._trig.half_angle_pair`."""
    if not degrees:
        return [1.0, 1.0, 1.0], np.tan([0.5 * angle for angle in angles]).tolist()
    split = [quarter_turns(angle) for angle in angles]
    tangents = np.tan([0.5 * rest for _, rest in split]).tolist()
    a, b = [0.0] * 3, [0.0] * 3
    for n, (quarter, _) in enumerate(split):
        c, s = _HALF_QUARTER[int(quarter % 4.0)]
        t = tangents[n]
        a[n], b[n] = c - s * t + 0.0, s + c * t + 0.0
    return a, b


def angles_to_entries(values: Three, parsed: Sequence, degrees: bool) -> Nine:
    """Entries of the matrix of intrinsic angles ``values``, as
    :func:`eulerlib._euler_kernels.fill_matrices` writes them."""
    (i, j, k), sign = frame(parsed)
    (s1, s2, s3), (c1, c2, c3) = sin_cos(values, degrees)
    if parsed.proper:
        M = (
            (c2, s2 * s3, s2 * c3),
            (s1 * s2, c1 * c3 - s1 * c2 * s3, -c1 * s3 - s1 * c2 * c3),
            (-c1 * s2, s1 * c3 + c1 * c2 * s3, c1 * c2 * c3 - s1 * s3),
        )
    else:
        s3 = s3 * sign[2]
        M = (
            (c2 * c3, -c2 * s3, s2),
            (c1 * s3 + s1 * s2 * c3, c1 * c3 - s1 * s2 * s3, -s1 * c2),
            (s1 * s3 - c1 * s2 * c3, s1 * c3 + c1 * s2 * s3, c1 * c2),
        )
    index = (i, j, k)
    out = [0.0] * 9
    for r in range(3):
        for col in range(3):
            value = M[r][col] if sign[r] * sign[col] > 0 else -M[r][col]
            out[3 * index[r] + index[col]] = value + 0.0
    return tuple(out)  # type: ignore[return-value]


def intrinsic_angles(
    entries: Nine, parsed: Sequence, zero_first: bool, tolerance: float
) -> Three | None:
    """Intrinsic angles of a rotation matrix, as :func:`eulerlib._euler_kernels.intrinsic_angles`;
    ``None`` when it is in gimbal lock (the array path applies the policy and warns)."""
    index, sign = frame(parsed)

    def m(r: int, c: int) -> float:
        entry = entries[3 * index[r] + index[c]]
        return entry if sign[r] * sign[c] > 0 else -entry

    if parsed.proper:
        a, b = m(0, 1), m(0, 2)
        sine = math.sqrt(a * a + b * b)
        cosine = m(0, 0)
        y, x = (sine, sine), (cosine, abs(cosine))
    else:
        sine = m(0, 2)
        a, b = m(0, 0), m(0, 1)
        cosine = math.sqrt(a * a + b * b)
        y, x = (sine, cosine), (cosine, abs(sine))
    # the middle angle, its distance from lock, and the outer angle read from its own ratio
    if parsed.proper:
        outer = (m(1, 0), -m(2, 0)) if zero_first else (m(0, 1), m(0, 2))
    else:
        outer = (-m(1, 2), m(2, 2)) if zero_first else (-m(0, 1), m(0, 0))
    middle, distance, read = np.arctan2((*y, outer[0]), (*x, outer[1])).tolist()
    if distance <= tolerance:
        return None
    # its sine and cosine from the ratio, as eulerlib._euler_kernels.direction
    length = math.sqrt(outer[0] * outer[0] + outer[1] * outer[1])
    if length == 0.0:
        sine_read, cosine_read = 0.0, 1.0
    else:
        sine_read, cosine_read = outer[0] / length, outer[1] / length
    if parsed.proper:
        if zero_first:
            first, s1, c1 = read, sine_read, cosine_read
            solved = (-(c1 * m(1, 2) + s1 * m(2, 2)), c1 * m(1, 1) + s1 * m(2, 1))
        else:
            third, s3, c3 = read, sine_read, cosine_read
            solved = (c3 * m(2, 1) - s3 * m(2, 2), c3 * m(1, 1) - s3 * m(1, 2))
    else:
        if zero_first:
            first, s1, c1 = read, sine_read, cosine_read
            solved = (c1 * m(1, 0) + s1 * m(2, 0), c1 * m(1, 1) + s1 * m(2, 1))
        else:
            third, s3, c3 = read, sine_read, cosine_read
            solved = (s3 * m(2, 0) + c3 * m(2, 1), s3 * m(1, 0) + c3 * m(1, 1))
    if zero_first:
        third = np.arctan2(*solved).item()
    else:
        first = np.arctan2(*solved).item()
    if not parsed.proper:
        third = third * sign[2]
    angles = [first + 0.0, middle + 0.0, third + 0.0]
    return tuple(math.pi if a == -math.pi else a for a in angles)  # type: ignore[return-value]


def quaternion_to_entries(w: float, x: float, y: float, z: float) -> Nine | None:
    """Entries of the matrix of a quaternion of any length, as
    :func:`eulerlib._quaternion_kernels.quaternions_to_entries`; ``None`` when its squared
    length leaves the range where no rescaling is needed."""
    ww, xx, yy, zz = w * w, x * x, y * y, z * z
    a, b = ww - zz, xx - yy
    ww += zz
    xx += yy
    squared = ww + xx
    if not _SMALL <= squared <= _LARGE:
        return None
    r = 1.0 / squared
    e0, e4, e8 = (a + b) * r, (a - b) * r, (ww - xx) * r
    r += r
    xs, ys, zs = x * r, y * r, z * r
    wx, wy, wz = w * xs, w * ys, w * zs
    t01, t02, t12 = xs * y + 0.0, xs * z + 0.0, ys * z + 0.0
    return (e0, t01 - wz, t02 + wy, t01 + wz, e4, t12 - wx, t02 - wy, t12 + wx, e8)


def make_canonical(q: Four) -> Four:
    """The one of ``q`` and ``-q`` that :func:`eulerlib._quaternion_kernels.make_canonical`
    chooses, with no ``-0.0``."""
    w, x, y, z = q
    sign = math.copysign(1.0, w)
    w, x, y, z = w * sign, x * sign, y * sign, z * sign
    if w == 0.0:
        first = x if x != 0.0 else (y if y != 0.0 else z)
        sign = math.copysign(1.0, first)
        w, x, y, z = w * sign, x * sign, y * sign, z * sign
    return w + 0.0, x + 0.0, y + 0.0, z + 0.0


def entries_to_quaternion(e: Nine) -> Four:
    """Canonical quaternion ``(w, x, y, z)`` of a rotation matrix, by Shepperd's method, as
    :func:`eulerlib._quaternion_kernels.entries_to_quaternions` (not normalized)."""
    r00, r11, r22 = e[0], e[4], e[8]
    d = (
        (1.0 + r00) + (r11 + r22),
        (1.0 + r00) - (r11 + r22),
        (1.0 + r11) - (r00 + r22),
        (1.0 + r22) - (r00 + r11),
    )
    second, fourth = int(d[1] > d[0]), int(d[3] > d[2])
    upper = int(max(d[2], d[3]) > max(d[0], d[1]))
    k = second + upper * (2 + fourth - second)
    row = [0.0] * 4
    row[k] = d[k]
    for other in range(4):
        if other != k:
            p, r, sign = _OFF_DIAGONAL[min(k, other), max(k, other)]
            row[other] = e[r] * sign + e[p]
    factor = math.sqrt(row[k]) / (2.0 * row[k])
    return make_canonical((row[0] * factor, row[1] * factor, row[2] * factor, row[3] * factor))


def normalized(q: Four) -> Four | None:
    """``q`` divided by its length, as :func:`eulerlib._quaternion_kernels.normalize`; None when
    the length is zero or overflows (only an unchecked matrix far from a rotation gives such a
    quaternion: the array path handles it)."""
    w, x, y, z = q
    length = math.sqrt(w * w + x * x + y * y + z * z)
    if not 0.0 < length < math.inf:
        return None
    return w / length, x / length, y / length, z / length


def euler_to_quaternion(values: Three, parsed: Sequence, degrees: bool) -> Four:
    """Canonical quaternion of intrinsic angles, as
    :func:`eulerlib._quaternion_kernels.euler_to_quaternions`."""
    (i, j, k), sign = frame(parsed)
    (c1, c2, c3), (s1, s2, s3) = half_angle_pairs(values, degrees)
    q = [0.0] * 4
    if parsed.proper:
        q[0] = c2 * (c1 * c3 - s1 * s3)
        q[1 + i] = c2 * (c1 * s3 + s1 * c3)
        q[1 + j] = s2 * (c1 * c3 + s1 * s3)
        q[1 + k] = s2 * (s1 * c3 - c1 * s3)
    else:
        s3 = s3 * sign[2]
        c1c2, s1s2, s1c2, c1s2 = c1 * c2, s1 * s2, s1 * c2, c1 * s2
        q[0] = c1c2 * c3 - s1s2 * s3
        q[1 + i] = s1c2 * c3 + c1s2 * s3
        q[1 + j] = c1s2 * c3 - s1c2 * s3
        q[1 + k] = c1c2 * s3 + s1s2 * c3
    if sign[2] < 0:
        q[1 + k] *= -1.0
    factor = math.sqrt(1.0 / ((c1 * c1 + s1 * s1) * (c2 * c2 + s2 * s2) * (c3 * c3 + s3 * s3)))
    return make_canonical((q[0] * factor, q[1] * factor, q[2] * factor, q[3] * factor))


def squared_length(values: tuple[float, ...]) -> float | None:
    """``x² + y² + …`` in order, as :func:`eulerlib._length_kernels.squared_lengths`; None
    when it leaves the range where :func:`eulerlib._length_kernels.lengths` needs no rescaling
    (a zero vector included)."""
    total = values[0] * values[0]
    for value in values[1:]:
        total += value * value
    return total if _SMALL <= total <= _LARGE else None


def rotation_angle(e: Nine) -> float | None:
    """Angle of a rotation matrix, as :func:`eulerlib._quaternion_kernels.rotation_angles`;
    None for a turn so small that the length of its skew part needs rescaling."""
    r00, r01, r02, r10, r11, r12, r20, r21, r22 = e
    squared = squared_length((r21 - r12, r02 - r20, r10 - r01))
    if squared is None:
        return None
    trace = r00 + r11
    trace += r22
    return float(np.arctan2(math.sqrt(squared), trace - 1.0))


def relative_angle(a: Nine, b: Nine) -> float | None:
    """Angle of ``Aᵀ B``, as :func:`eulerlib._quaternion_kernels.relative_angles`; None when
    the length of the skew part needs rescaling."""
    trace = a[0] * b[0]
    for i in range(1, 9):
        trace += a[i] * b[i]
    skew = [0.0, 0.0, 0.0]
    for k in range(3):
        a0, a1, a2 = a[3 * k : 3 * k + 3]
        b0, b1, b2 = b[3 * k : 3 * k + 3]
        skew[0] += b1 * a2 - b2 * a1
        skew[1] += b2 * a0 - b0 * a2
        skew[2] += b0 * a1 - b1 * a0
    squared = squared_length(tuple(skew))
    if squared is None:
        return None
    return float(np.arctan2(math.sqrt(squared), trace - 1.0))


def vector_part(q: Four) -> tuple[Three, float] | None:
    """The vector part of a quaternion and its length, or None when the length needs
    rescaling (the identity's zero vector part included)."""
    vector = (q[1], q[2], q[3])
    squared = squared_length(vector)
    return None if squared is None else (vector, math.sqrt(squared))


def half_angle_pair(angle: float, degrees: bool) -> tuple[float, float]:
    """:func:`half_angle_pairs` for one angle."""
    if not degrees:
        return 1.0, float(np.tan(0.5 * angle))
    quarter, rest = quarter_turns(angle)
    c, s = _HALF_QUARTER[int(quarter % 4.0)]
    t = float(np.tan(0.5 * rest))
    return c - s * t + 0.0, s + c * t + 0.0


def rotvec_to_entries(v: Three, degrees: bool) -> Nine | None:
    """Matrix entries of a rotation vector, as
    :func:`eulerlib._quaternion_kernels.rotvecs_to_entries`; None for a vector whose length
    needs rescaling (the zero vector included)."""
    squared = squared_length(v)
    if squared is None:
        return None
    length = math.sqrt(squared)
    a, b = half_angle_pair(length, degrees)
    factor = b / length
    return quaternion_to_entries(a, v[0] * factor, v[1] * factor, v[2] * factor)


def axis_angle_to_entries(axis: Three, angle: float, degrees: bool) -> Nine | None:
    """Matrix entries of a turn about an axis of any length, as the body of
    :func:`eulerlib.axis_angle_to_matrix`; None for a zero axis (refused by the array path)."""
    largest = max(abs(axis[0]), abs(axis[1]), abs(axis[2]))
    if largest == 0.0:
        return None
    exponent = math.frexp(largest)[1]  # scaled exactly, as _unit.scaled_to_unit_size
    x, y, z = (math.ldexp(value, -exponent) for value in axis)
    squared = x * x
    squared += y * y
    squared += z * z
    a, b = half_angle_pair(angle, degrees)
    return quaternion_to_entries(a * math.sqrt(squared), x * b, y * b, z * b)


def transposed_product(a: Nine, b: Nine) -> Nine:
    """Entries of ``Aᵀ B``, as :func:`eulerlib._quaternion_kernels.transposed_product`."""
    e = [0.0] * 9
    for i in range(3):
        for j in range(3):
            total = a[i] * b[j]
            total += a[3 + i] * b[3 + j]
            total += a[6 + i] * b[6 + j]
            e[3 * i + j] = total
    return tuple(e)  # type: ignore[return-value]


def product(a: Nine, b: Nine) -> Nine:
    """Entries of ``A B`` without negative zeros, as :func:`eulerlib._quaternion_kernels.product`
    followed by ``+= 0.0``."""
    e = [0.0] * 9
    for i in range(3):
        for j in range(3):
            total = a[3 * i] * b[j]
            total += a[3 * i + 1] * b[3 + j]
            e[3 * i + j] = (total + a[3 * i + 2] * b[6 + j]) + 0.0
    return tuple(e)  # type: ignore[return-value]


def slerp_entries(start: Nine, end: Nine, t: float) -> Nine | None:
    """Entries of the rotation a fraction ``t`` of the way from ``start`` to ``end``, as the
    body of :func:`eulerlib.slerp`; None for ends so close that a length needs rescaling, and
    for a turn that overflows (the array path refuses it)."""
    relative = entries_to_quaternion(transposed_product(start, end))
    part = vector_part(relative)
    if part is None:
        return None
    vector, sine = part
    with np.errstate(over="ignore"):
        half_turn = float(np.arctan2(sine, relative[0])) * t
    if half_turn - half_turn != 0.0:
        return None
    factor = float(np.tan(half_turn)) / sine
    turn = quaternion_to_entries(1.0, vector[0] * factor, vector[1] * factor, vector[2] * factor)
    return None if turn is None else product(start, turn)
