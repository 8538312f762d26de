"""The arithmetic of quaternions and rotation angles, on one block of checked values.

Nothing here checks its input: the public functions (:mod:`eulerlib.quaternion`,
:mod:`eulerlib.axis_angle`, :mod:`eulerlib.interpolation`) did that once. Quaternions are held
as four rows ``(w, x, y, z)`` of a block, matrices as nine rows of entries (row ``3 i + j`` is
``R[i, j]``, as :func:`eulerlib._validation.matrix_entries` lays them out), so that every step
is an element-wise operation on a few thousand rotations at once.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from eulerlib._euler_kernels import frame
from eulerlib._length_kernels import TINY, lengths, squared_lengths
from eulerlib._sequences import Sequence
from eulerlib._trig import half_angle_pair

Array = NDArray[np.float64]

# Off the diagonal, 4 q qᵀ is made of sums and differences of two entries of R (entry 3 i + j
# is R[i, j]): for each pair of components of q = (w, x, y, z), the two entries and the sign,
# 4 q_a q_b = R[p] + sign · R[q].
_OFF_DIAGONAL = {
    (0, 1): (7, 5, -1.0),  # 4wx = r21 − r12
    (0, 2): (2, 6, -1.0),  # 4wy = r02 − r20
    (0, 3): (3, 1, -1.0),  # 4wz = r10 − r01
    (1, 2): (1, 3, 1.0),  # 4xy = r01 + r10
    (1, 3): (2, 6, 1.0),  # 4xz = r02 + r20
    (2, 3): (5, 7, 1.0),  # 4yz = r12 + r21
}


def make_canonical(q: Array) -> None:
    """Choose, in place, the one of ``q`` and ``-q`` with ``w > 0``, or at ``w = 0`` the one
    whose first nonzero component of ``(x, y, z)`` is positive; and turn ``-0.0`` into ``0.0``.
    """
    np.multiply(q, np.copysign(1.0, q[0]), out=q)
    zero = np.flatnonzero(q[0] == 0.0)
    if zero.size:  # half turns: the sign of w says nothing
        part = q[:, zero]
        x, y, z = part[1:]
        first = np.where(x != 0.0, x, np.where(y != 0.0, y, z))
        part *= np.copysign(1.0, first)
        q[:, zero] = part
    q += 0.0


def entries_to_quaternions(e: Array) -> Array:
    """Canonical unit quaternions ``(4, n)`` of rotation matrices given by their entries.

    Shepperd's method: the entries of ``R`` give the matrix ``4 q qᵀ`` by sums and differences:
    its diagonal is ``4w² = 1 + r00 + r11 + r22``, ``4x² = 1 + r00 − r11 − r22``, ``4y²``,
    ``4z²`` alike, and off it ``4wx = r21 − r12``, ``4xy = r01 + r10``, and so on. Of the four
    diagonal entries, which add up to 4, the largest is at least 1; dividing its row by twice
    its square root gives ``q`` with no division by a small number and no cancellation under
    the square root. Each rotation needs only the row of its own largest entry, so the rows
    are computed for the rotations that use them.
    """
    r00, r11, r22 = e[0], e[4], e[8]
    n = e.shape[1]
    diagonal = np.empty((4, n))  # 4w², 4x², 4y², 4z²
    diagonal[0] = (1.0 + r00) + (r11 + r22)
    diagonal[1] = (1.0 + r00) - (r11 + r22)
    diagonal[2] = (1.0 + r11) - (r00 + r22)
    diagonal[3] = (1.0 + r22) - (r00 + r11)
    # index of the largest, the first one at a tie
    d = diagonal
    second = (d[1] > d[0]).view(np.int8)
    fourth = (d[3] > d[2]).view(np.int8)
    upper = (np.maximum(d[2], d[3]) > np.maximum(d[0], d[1])).view(np.int8)
    largest = second + upper * (2 + fourth - second)
    q = np.empty((4, n))
    for k in range(4):
        chosen = np.flatnonzero(largest == k)
        if not chosen.size:
            continue
        part = e[:, chosen]
        row = np.empty((4, chosen.size))
        row[k] = diagonal[k, chosen]
        for other in range(4):
            if other != k:
                p, r, sign = _OFF_DIAGONAL[min(k, other), max(k, other)]
                np.multiply(part[r], sign, out=row[other])
                row[other] += part[p]
        # divide by 2 √d as √d / (2 d): the largest component is then √d / 2, correctly rounded
        row *= np.sqrt(row[k]) / (2.0 * row[k])
        q[:, chosen] = row
    make_canonical(q)
    return q


def normalize(q: Array) -> None:
    """Divide, in place, each quaternion (column of ``q``, shape ``(4, n)``) by its length.

    For quaternions near unit length, such as those of matrices that are rotations within a
    tolerance, the length is ``sqrt`` of a sum of four squares without overflow or underflow,
    and each component is divided once, so the result has length 1 to a unit or two in the last
    place; a quaternion whose length rounds to 1 is left as it is. The squares are summed in
    order, ``((w² + x²) + y²) + z²``, for any number of quaternions (``einsum`` sums a single
    column in another order), so that one quaternion gets the same bits as many.
    """
    q /= np.sqrt(squared_lengths(q))


def quaternions_to_entries(q: Array | tuple[Array, Array, Array, Array], out: Array) -> Array:
    """Write into ``out`` (shape ``(9, n)``) the rotation matrices of quaternions of any length.

    ``q`` holds the rows w, x, y, z (shape ``(4, n)``, or four rows). Row ``3 i + j`` of ``out``
    receives ``R[i, j]``. Returns ``|q|²``; where it is 0, infinite or subnormal, the entries are
    not meaningful and the caller must redo those columns, scaled by
    :func:`eulerlib._unit.scaled_to_unit_size`.

    ``R = I + 2 w [v]× + 2 [v]×²`` for a unit quaternion is evaluated in the form that holds for
    any length: on the diagonal ``R[0, 0] = (w² − z² + x² − y²) / |q|²``, ``R[1, 1] = (w² − z² −
    x² + y²) / |q|²``, ``R[2, 2] = (w² + z² − x² − y²) / |q|²``, off it ``R[0, 1] = 2(xy − wz) /
    |q|²`` and so on, each a short sum of products times ``1 / |q|²``. Nothing is subtracted
    from 1 and ``q`` is never rounded by a normalization, so every entry is accurate to about
    one unit in the last place, and a quaternion such as ``(1, 0, 0, 1)``, whose squared length
    is a power of two, gives its matrix exactly.

    The arithmetic runs in eight scratch rows, reused step by step, so that a block's working
    set stays in the processor's cache.
    """
    w, x, y, z = q
    scratch = np.empty((8, w.shape[0]))
    ww, xx, yy, zz, a, b, r, t = scratch
    np.multiply(w, w, out=ww)
    np.multiply(x, x, out=xx)
    np.multiply(y, y, out=yy)
    np.multiply(z, z, out=zz)
    np.subtract(ww, zz, out=a)
    np.subtract(xx, yy, out=b)
    ww += zz  # w² + z²
    xx += yy  # x² + y²
    squared: Array = ww + xx
    np.divide(1.0, squared, out=r)
    np.add(a, b, out=t)
    np.multiply(t, r, out=out[0])
    np.subtract(a, b, out=t)
    np.multiply(t, r, out=out[4])
    np.subtract(ww, xx, out=t)
    np.multiply(t, r, out=out[8])
    r += r  # 2 / |q|²
    xs, ys, zs, wx, wy, wz = ww, xx, yy, zz, a, b  # the rows are free again
    np.multiply(x, r, out=xs)
    np.multiply(y, r, out=ys)
    np.multiply(z, r, out=zs)
    np.multiply(w, xs, out=wx)
    np.multiply(w, ys, out=wy)
    np.multiply(w, zs, out=wz)
    for first, second, with_w, minus, plus in (
        (xs, y, wz, 1, 3),  # R[0, 1] = 2(xy − wz) / |q|², R[1, 0] = 2(xy + wz) / |q|²
        (xs, z, wy, 6, 2),  # R[2, 0] = 2(xz − wy) / |q|², R[0, 2] = 2(xz + wy) / |q|²
        (ys, z, wx, 5, 7),  # R[1, 2] = 2(yz − wx) / |q|², R[2, 1] = 2(yz + wx) / |q|²
    ):
        np.multiply(first, second, out=t)
        t += 0.0  # so that no entry comes out as -0.0
        np.subtract(t, with_w, out=out[minus])
        np.add(t, with_w, out=out[plus])
    return squared


def unit_axes(q: Array) -> Array:
    """Unit axes ``(3, n)`` of canonical quaternions; ``(1, 0, 0)`` for the identity."""
    vector = q[1:]
    length = lengths(vector)
    axes: Array = vector / np.maximum(length, TINY)
    axes[0, length == 0.0] = 1.0
    return axes


def rotation_vectors(q: Array, angle: Array) -> Array:
    """Rotation vectors ``(3, n)``: ``angle`` times the unit axis of canonical quaternions."""
    vector = q[1:]
    result: Array = vector * (angle / np.maximum(lengths(vector), TINY))
    return result


def rotation_angles(e: Array) -> Array:
    """Angle of each rotation, in [0, π], from its matrix entries ``(9, n)``.

    ``θ = atan2(|s|, trace − 1)`` with ``s = (r21 − r12, r02 − r20, r10 − r01) = 2 sin θ n`` and
    ``trace − 1 = 2 cos θ``: a sine and a cosine that are both accurate, so θ is accurate to a
    few units in the last place near 0 and near π alike, where ``acos((trace − 1) / 2)`` loses
    half the digits.
    """
    r00, r01, r02, r10, r11, r12, r20, r21, r22 = e
    skew = np.empty((3, e.shape[1]))
    np.subtract(r21, r12, out=skew[0])
    np.subtract(r02, r20, out=skew[1])
    np.subtract(r10, r01, out=skew[2])
    trace = r00 + r11
    trace += r22  # summed in the order of relative_angles, which then agrees to the last bit
    angle: Array = np.arctan2(lengths(skew), trace - 1.0)
    return angle


def relative_angles(a: Array, b: Array) -> Array:
    """Angle of ``Aᵀ B`` for matrices given by their entries, without forming ``Aᵀ B``.

    With ``A_k`` and ``B_k`` the rows of the two matrices, ``trace(Aᵀ B) = Σ A_k · B_k`` and the
    skew part of ``Aᵀ B`` is ``s = Σ B_k × A_k``; then as :func:`rotation_angles`.
    """
    skew = np.zeros((3, a.shape[1]))
    trace = a[0] * b[0]
    for i in range(1, 9):
        trace += a[i] * b[i]
    for k in range(3):
        a0, a1, a2 = a[3 * k : 3 * k + 3]
        b0, b1, b2 = b[3 * k : 3 * k + 3]
        skew[0] += b1 * a2 - b2 * a1
        skew[1] += b2 * a0 - b0 * a2
        skew[2] += b0 * a1 - b1 * a0
    angle: Array = np.arctan2(lengths(skew), trace - 1.0)
    return angle


def transposed_product(a: Array, b: Array) -> Array:
    """Entries ``(9, n)`` of ``Aᵀ B``: ``(Aᵀ B)[i, j] = Σ_k A[k, i] B[k, j]``."""
    e = np.empty_like(a)
    for i in range(3):
        for j in range(3):
            row = e[3 * i + j]
            np.multiply(a[i], b[j], out=row)
            row += a[3 + i] * b[3 + j]
            row += a[6 + i] * b[6 + j]
    return e


def product(a: Array, b: Array, out: Array) -> None:
    """Write into ``out`` (shape ``(9, n)``, possibly strided) the entries of ``A B``:
    ``(A B)[i, j] = Σ_k A[i, k] B[k, j]``."""
    for i in range(3):
        for j in range(3):
            total = a[3 * i] * b[j]
            total += a[3 * i + 1] * b[3 + j]
            np.add(total, a[3 * i + 2] * b[6 + j], out=out[3 * i + j])


def euler_to_quaternions(values: Array, parsed: Sequence, degrees: bool) -> Array:
    """Canonical quaternions ``(4, n)`` of intrinsic Euler angles ``values`` ``(n, 3)``.

    As for the matrices (:func:`eulerlib._euler_kernels.fill_matrices`), the sequence is
    relabelled as x-y-z or x-y-x by the signed permutation ``P``; the quaternion of
    ``R = P M Pᵀ`` is that of ``M`` with its vector part turned by ``P``. The quaternion of ``M``
    is the product of three elementary ones, ``(cos(a/2), sin(a/2) e)``, written out. Each is
    taken as the multiple ``(c, s)`` of it that :func:`eulerlib._trig.half_angle_pair` gives
    (``(1, tan(a/2))``, or small integers for the quarter turns of degrees), and the product is
    normalized once at the end, so that quarter turns give their quaternions correctly rounded.
    """
    (i, j, k), sign = frame(parsed)
    c, s = half_angle_pair(np.ascontiguousarray(values.T), degrees)
    c1, c2, c3 = c
    s1, s2, s3 = s
    q = np.empty((4, values.shape[0]))
    if parsed.proper:  # q_x(a) q_y(b) q_x(c)
        q[0] = c2 * (c1 * c3 - s1 * s3)
        q[1 + i] = c2 * (c1 * s3 + s1 * c3)
        q[1 + j] = s2 * (c1 * c3 + s1 * s3)
        q[1 + k] = s2 * (s1 * c3 - c1 * s3)
    else:  # q_x(a) q_y(b) q_z(±c)
        s3 = s3 * sign[2]
        c1c2, s1s2, s1c2, c1s2 = c1 * c2, s1 * s2, s1 * c2, c1 * s2
        q[0] = c1c2 * c3 - s1s2 * s3
        q[1 + i] = s1c2 * c3 + c1s2 * s3
        q[1 + j] = c1s2 * c3 - s1c2 * s3
        q[1 + k] = c1c2 * s3 + s1s2 * c3
    if sign[2] < 0:
        q[1 + k] *= -1.0
    squared = c * c
    squared += s * s
    q *= np.sqrt(1.0 / (squared[0] * squared[1] * squared[2]))  # |q|² is the product
    make_canonical(q)
    return q


def rotvecs_to_entries(rows: Array, degrees: bool, length: Array) -> Array:
    """Body of :func:`rotvec_to_matrix` for one block of checked rotation vectors.

    ``rows`` holds the vectors as columns, shape ``(3, n)``, and ``length`` their lengths from
    :func:`eulerlib._length_kernels.lengths`, each a float: the caller refuses a vector longer
    than the largest float (:func:`eulerlib._unit.refuse_overlong`), since its turn has no
    angle. Returns the entries of their matrices laid out as
    :func:`eulerlib._validation.matrix_entries` does, shape ``(9, n)``.
    """
    a, b = half_angle_pair(length, degrees)
    # (a, b v / |v|) is a multiple of (cos(θ/2), sin(θ/2) v / |v|); the zero vector gives
    # b / TINY = 0 and so the identity
    q = np.empty((4, rows.shape[1]))
    q[0] = a
    np.multiply(rows, b / np.maximum(length, TINY), out=q[1:])
    entries = np.empty((9, q.shape[1]))
    quaternions_to_entries(q, entries)
    return entries
