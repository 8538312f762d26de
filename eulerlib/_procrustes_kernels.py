"""The rotation nearest a weighted sum: the arithmetic of Wahba's problem and of the chordal mean.

Both :func:`eulerlib.align_vectors` and :func:`eulerlib.mean_rotation` maximize ``tr(Cᵀ M)`` over
rotations ``C`` for one 3×3 matrix ``M`` per problem: ``M = Σ w a bᵀ`` of the vector pairs, or
``M = Σ w R`` of the rotations. With the singular value decomposition ``M = U S Vᵀ`` the answer
is ``C = U diag(1, 1, d) Vᵀ`` with ``d = det U det V`` (F. L. Markley, 1988; the special
orthogonal Procrustes problem). It is unique unless ``s2 + d s3 = 0``. Nothing here checks its
input; the public modules did that once.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

Array = NDArray[np.float64]


def special_procrustes(M: Array) -> tuple[Array, Array, Array]:
    """The rotations ``C`` that maximize ``tr(Cᵀ M)`` for a stack ``M`` ``(n, 3, 3)``.

    Returns ``C`` ``(n, 3, 3)``, the singular values ``(n, 3)`` (largest first) and the margin
    ``s2 + d s3`` ``(n,)``: the maximum is unique exactly when the margin is positive, and a
    margin that is tiny next to ``s1`` means that rounding decides the answer.
    ``d = det U det V = det(U Vᵀ)`` is ±1, and ``U diag(1, 1, −1) Vᵀ = U Vᵀ − 2 u3 v3ᵀ``.
    """
    U, S, Vt = np.linalg.svd(M)
    C: Array = U @ Vt
    d = np.sign(np.linalg.det(C))
    flip = np.flatnonzero(d < 0.0)
    if flip.size:
        C[flip] -= 2.0 * U[flip, :, 2:] @ Vt[flip, 2:, :]
    return C, S, S[:, 1] + d * S[:, 2]


def orthonormal_frames(n: Array) -> Array:
    """Rotations ``F`` ``(k, 3, 3)`` whose first column is the unit vector ``n`` ``(k, 3)``.

    The other two columns complete ``n`` without a division by a small number (T. Duff et al.,
    "Building an orthonormal basis, revisited", 2017): with ``s = ±1`` the sign of ``n_z`` and
    ``c = −1 / (s + n_z)``, ``e1 = (1 + s c n_x², s c n_x n_y, −s n_x)`` and
    ``e2 = (c n_x n_y, s + c n_y², −n_y)``; ``(n, e1, e2)`` is right-handed.
    """
    x, y, z = n[:, 0], n[:, 1], n[:, 2]
    s = np.copysign(1.0, z)
    c = -1.0 / (s + z)
    xy = c * x * y
    F = np.empty((n.shape[0], 3, 3))
    F[:, :, 0] = n
    F[:, 0, 1] = 1.0 + s * c * x * x
    F[:, 1, 1] = s * xy
    F[:, 2, 1] = -s * x
    F[:, 0, 2] = xy
    F[:, 1, 2] = s + c * y * y
    F[:, 2, 2] = -y
    return F


def turn_about_primary(a: Array, b: Array, M: Array) -> tuple[Array, Array]:
    """Rotations that take the unit vectors ``b`` onto the unit vectors ``a`` (both ``(k, 3)``)
    exactly and, among those, maximize ``tr(Cᵀ M)`` for the other pairs' ``M`` ``(k, 3, 3)``.

    Every such rotation is ``C = Fa X(φ) Fbᵀ``, with ``Fa`` and ``Fb`` frames whose first
    columns are ``a`` and ``b`` and ``X(φ)`` the turn by φ about the first axis. With
    ``N = Faᵀ M Fb``, ``tr(Cᵀ M) = N00 + cos φ (N11 + N22) + sin φ (N21 − N12)``, largest at
    ``φ = atan2(N21 − N12, N11 + N22)``. Returns ``C`` and the size of that maximum's varying
    part, ``hypot(N21 − N12, N11 + N22)``: zero when every other pair is parallel to the primary
    one, and then any φ fits as well.
    """
    Fa, Fb = orthonormal_frames(a), orthonormal_frames(b)
    N = np.swapaxes(Fa, -1, -2) @ M @ Fb
    sine = N[:, 2, 1] - N[:, 1, 2]
    cosine = N[:, 1, 1] + N[:, 2, 2]
    phi = np.arctan2(sine, cosine)
    X = np.zeros_like(M)
    X[:, 0, 0] = 1.0
    X[:, 1, 1] = X[:, 2, 2] = np.cos(phi)
    X[:, 2, 1] = np.sin(phi)
    X[:, 1, 2] = -X[:, 2, 1]
    C: Array = Fa @ X @ np.swapaxes(Fb, -1, -2)
    return C, np.hypot(sine, cosine)


# --- one problem at a time ------------------------------------------------------------------------
#
# One small problem spends most of its time in numpy's per-call overhead. These do the same
# computation for one matrix ``M`` (3, 3) with fewer numpy calls, the 3×3 bookkeeping in Python.


def procrustes_one(M: Array) -> tuple[Array, list[float], float]:
    """:func:`special_procrustes` of one matrix: ``C``, the singular values, the margin."""
    U, S, Vt = np.linalg.svd(M)
    C: Array = U @ Vt
    (a, b, c), (d, e, f), (g, h, i) = C.tolist()
    s1, s2, s3 = S.tolist()
    if a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g) < 0.0:
        C -= 2.0 * np.outer(U[:, 2], Vt[2])
        return C, [s1, s2, s3], s2 - s3
    return C, [s1, s2, s3], s2 + s3


def _frame_one(n: list[float]) -> list[list[float]]:
    """:func:`orthonormal_frames` of one unit vector, as rows of the matrix."""
    x, y, z = n
    s = math.copysign(1.0, z)
    c = -1.0 / (s + z)
    xy = c * x * y
    return [[x, 1.0 + s * c * x * x, xy], [y, s * xy, s + c * y * y], [z, -s * x, -y]]


def _times(P: list[list[float]], Q: list[list[float]]) -> list[list[float]]:
    return [[sum(P[i][k] * Q[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def _transposed(P: list[list[float]]) -> list[list[float]]:
    return [[P[j][i] for j in range(3)] for i in range(3)]


def turn_about_primary_one(
    a: list[float], b: list[float], M: list[list[float]]
) -> tuple[Array, float]:
    """:func:`turn_about_primary` of one problem, in Python floats."""
    Fa, Fb = _frame_one(a), _frame_one(b)
    N = _times(_times(_transposed(Fa), M), Fb)
    sine = N[2][1] - N[1][2]
    cosine = N[1][1] + N[2][2]
    phi = math.atan2(sine, cosine)
    co, si = math.cos(phi), math.sin(phi)
    X = [[1.0, 0.0, 0.0], [0.0, co, -si], [0.0, si, co]]
    C = np.array(_times(_times(Fa, X), _transposed(Fb)))
    return C, math.hypot(sine, cosine)
