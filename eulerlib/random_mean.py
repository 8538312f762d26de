"""Random rotations that are uniform, and the average of several rotations.

Uniform rotations
-----------------
"Uniformly random" for rotations means by the Haar measure, the one that turning every rotation
by a fixed rotation leaves unchanged: no attitude and no axis is preferred. Uniform Euler angles
are not uniform rotations (their density piles up where the middle angle makes the first and
third axes nearly coincide). Four independent standard normal numbers, read as a quaternion and
normalized, are: the normal distribution in four dimensions looks the same in every direction,
so its direction is uniform on the sphere of unit quaternions, and the Haar measure is that
uniform distribution carried to the rotations (K. Shoemake, *Graphics Gems III*, 1992). Under it
the angle θ of a rotation has the density ``(1 − cos θ) / π`` on [0, π]: small turns are rare,
and the mean angle is ``π / 2 + 2 / π`` (about 126°).

Averaging rotations
-------------------
Rotations cannot be averaged entry by entry (the average of rotation matrices is not a rotation)
nor angle by angle (Euler angles jump by 2π at a seam and lose a degree of freedom at gimbal
lock). The **chordal L2 mean** is the rotation nearest, in the Frobenius norm, to the weighted
average of the matrices:

.. math::

    \\bar R = \\arg\\min_{M ∈ SO(3)} \\sum_i w_i \\lVert R_i - M \\rVert_F^2
            = \\arg\\max_{M ∈ SO(3)} \\operatorname{tr}\\left(M^T \\sum_i w_i R_i\\right),

found in closed form from one SVD (R. Hartley et al., "Rotation averaging", 2013). Since
``‖R(p) − R(q)‖²_F = 8 (1 − (p · q)²)`` for unit quaternions, it is also the eigenvector of
``Σ w q qᵀ`` with the largest eigenvalue (F. L. Markley et al., 2007), which is how SciPy's
``Rotation.mean`` computes the same rotation.

The **geodesic** (Karcher) L2 mean instead minimizes ``Σ w θ(R_i, M)²``, the squared angles
between the rotations, and has no closed form: it is found by iterating
``M ← M Exp(Σ w Log(Mᵀ R_i) / Σ w)``. The chordal distance ``2√2 sin(θ/2)`` grows more slowly
than θ, so the chordal mean gives a far-off rotation less pull than the geodesic mean does.
For two equally weighted rotations both are the midpoint; otherwise they differ by a term of
third order in the spread of the rotations: by about a thousandth of the spread for rotations
within a few degrees of each other (measured: 8e-5 rad for ten rotations scattered by 0.05
rad), but by a sizeable part of it for rotations spread over a radian or more. The chordal
mean is the usual starting point of the geodesic iteration.
"""

from __future__ import annotations

import math
import operator
from typing import cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._algebra_kernels import matrix_one
from eulerlib._blocks import block_slices
from eulerlib._procrustes_kernels import procrustes_one, special_procrustes
from eulerlib._quaternion_kernels import quaternions_to_entries
from eulerlib._scalar import rotations
from eulerlib._validation import (
    ROTATION_ATOL,
    _index_text,
    as_float_array,
    as_rotations,
    rotation_check,
)

__all__ = ["mean_rotation", "random_rotations"]

#: A mean whose margin ``s2 + d s3`` is at most this fraction of ``s1`` is not unique: the
#: rotations are spread so that several rotations are nearest to their average (a turn and its
#: half-turned opposite, equally weighted, say).
DEGENERATE = 2.0**-40


def _as_shape(n: object) -> tuple[int, ...]:
    """``n`` (an integer ≥ 0, or a tuple of them) as an output shape."""
    items = n if isinstance(n, tuple) else (n,)
    shape = []
    for item in items:
        if isinstance(item, (bool, np.bool_)):
            raise TypeError(f"n must be an integer ≥ 0 or a tuple of them, got {n!r}")
        try:
            size = operator.index(item)
        except TypeError:
            raise TypeError(
                f"n must be an integer ≥ 0 or a tuple of them, got {n!r} ({type(n).__name__})"
            ) from None
        if size < 0:
            raise ValueError(f"n must be an integer ≥ 0 or a tuple of them, got {n!r}")
        shape.append(size)
    return tuple(shape)


def _as_generator(rng: object) -> np.random.Generator:
    if isinstance(rng, np.random.Generator):
        return rng
    if rng is None or isinstance(rng, (np.random.SeedSequence, np.random.BitGenerator)):
        return np.random.default_rng(rng)
    if isinstance(rng, (int, np.integer)) and not isinstance(rng, (bool, np.bool_)):
        if rng < 0:
            raise ValueError(f"rng must be a seed ≥ 0, got {rng}")
        return np.random.default_rng(int(rng))
    raise TypeError(
        "rng must be None, a seed (an integer ≥ 0) or a numpy.random.Generator, got "
        f"{rng!r} ({type(rng).__name__})"
    )


def random_rotations(
    n: int | tuple[int, ...], *, rng: np.random.Generator | int | None = None
) -> NDArray[np.float64]:
    """Uniformly distributed (Haar) random rotation matrices.

    Parameters
    ----------
    n : int or tuple of int
        How many rotations: ``n`` gives shape ``(n, 3, 3)``, a tuple ``shape`` gives
        ``(*shape, 3, 3)`` and ``()`` one matrix ``(3, 3)``.
    rng : numpy.random.Generator, int or None, optional
        Where the random numbers come from: a Generator (advanced by the call), a seed for
        ``numpy.random.default_rng`` (the same seed gives the same rotations), or ``None``
        for fresh entropy.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        Independent rotations, uniform by the Haar measure: their angles have the density
        ``(1 − cos θ) / π`` on [0, π], and their axes are uniform on the sphere.

    Raises
    ------
    TypeError
        If ``n`` is not an integer or a tuple of integers, or ``rng`` is none of the above.
    ValueError
        If ``n`` is negative or ``rng`` is a negative seed.

    Notes
    -----
    Four standard normal numbers per rotation, ``rng.normal(size=(*shape, 4))``, read as the
    quaternion ``(x, y, z, w)`` and turned into its matrix without rounding the quaternion by
    a normalization (see :func:`eulerlib.quaternion_to_matrix`). SciPy's ``Rotation.random``
    draws the same numbers the same way, so from one seed both give the same rotations, to
    the last few bits.

    Examples
    --------
    >>> import numpy as np
    >>> from eulerlib import is_rotation_matrix
    >>> R = random_rotations(1000, rng=42)
    >>> R.shape, bool(np.all(is_rotation_matrix(R)))
    ((1000, 3, 3), True)
    >>> np.array_equal(random_rotations(3, rng=7), random_rotations(3, rng=7))
    True
    """
    shape = _as_shape(n)
    generator = _as_generator(rng)
    total = math.prod(shape)
    if total == 1:  # one rotation: the same numbers and formulas, without numpy's overheads
        x, y, z, w = generator.normal(size=4).tolist()
        entries = matrix_one((w, x, y, z)) if any((w, x, y, z)) else np.eye(3).reshape(9)
        return np.array(entries).reshape(*shape, 3, 3)
    out = np.empty((total, 9))
    for block in block_slices(total):
        stored = generator.normal(size=(block.stop - block.start, 4))
        rows = stored.T[[3, 0, 1, 2]]  # (w, x, y, z)
        squared = quaternions_to_entries(rows, out[block].T)
        zero = np.flatnonzero(squared == 0.0)  # four zeros at once: probability about 0
        if zero.size:  # pragma: no cover
            out[block][zero] = np.eye(3).reshape(9)
    return out.reshape(*shape, 3, 3)


def mean_rotation(
    R: ArrayLike,
    weights: ArrayLike | None = None,
    *,
    validate: bool = True,
    repair: bool = False,
    atol: float = ROTATION_ATOL,
) -> NDArray[np.float64]:
    """The chordal L2 mean of rotations: the rotation nearest to their weighted average.

    Parameters
    ----------
    R : array_like, shape (..., N, 3, 3)
        The rotations to average, along the axis ``-3``; leading axes before it are separate
        sets, each averaged on its own.
    weights : array_like, shape (..., N), optional
        A weight ≥ 0 for each rotation, not all zero; default all 1. Its leading axes
        broadcast with those of ``R``.
    validate, repair, atol
        As in :func:`eulerlib.matrix_to_euler`: check that ``R`` holds rotations within
        ``atol`` (default), or use the nearest rotations.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        The rotation ``M`` minimizing ``Σ w ‖R_i − M‖²_F``, the same rotation as SciPy's
        ``Rotation.mean``.

    Raises
    ------
    TypeError
        If ``R`` or ``weights`` is not real numbers or a flag is not a bool.
    ValueError
        If a shape is wrong or the shapes do not broadcast, a value is not finite, ``R`` is
        not a rotation within ``atol`` (or cannot be repaired), a weight is negative, every
        weight of a set is zero (or a set is empty), or the mean is not unique: the rotations
        are spread so evenly that several rotations are equally near their average (a
        rotation and the same one turned half a turn, equally weighted). The message gives
        the index of the set.

    Notes
    -----
    With ``S = Σ w R_i = U diag(s) Vᵀ``, ``M = U diag(1, 1, det U det V) Vᵀ``; it is unique when
    ``s2 + d s3 > 0`` and counted as not unique when ``s2 + d s3 ≤ 2⁻⁴⁰ s1``. The weights of a
    set are scaled by a power of two first, so weights of any size give the same mean. Not the
    geodesic mean, which minimizes the sum of squared angles: see the module docstring for the
    difference.

    Examples
    --------
    >>> import numpy as np
    >>> from eulerlib import rot_z, rotation_angle
    >>> R = rot_z([-20.0, 10.0, 40.0], degrees=True)
    >>> np.allclose(mean_rotation(R), rot_z(10, degrees=True))
    True
    >>> M = mean_rotation(R, weights=[0.0, 1.0, 1.0])          # of 10° and 40°
    >>> np.round(rotation_angle(M, degrees=True), 12)
    np.float64(25.0)
    """
    check = rotation_check(validate, repair, atol)
    # A few matrices are checked one by one in Python floats, the same test in the same
    # arithmetic (eulerlib._scalar); anything else, or a matrix that fails, takes the array path,
    # which words the refusal.
    if rotations(R, check) is not None:
        matrices = cast(NDArray[np.float64], R)
    else:
        matrices = as_rotations(R, "R", check)
    if matrices.ndim < 3:
        raise ValueError(f"R must have shape (..., N, 3, 3), got shape {matrices.shape}")
    count = matrices.shape[-3]
    if weights is None:
        w = np.ones(count)
    else:
        w = as_float_array(weights, "weights")
        if w.ndim == 0 or w.shape[-1] != count:
            raise ValueError(
                f"weights must have shape (..., {count}), one per rotation, got shape {w.shape}"
            )
        negative = np.flatnonzero(w < 0.0)
        if negative.size:
            first = int(negative[0])
            raise ValueError(
                f"weights must be ≥ 0, got {w.reshape(-1)[first]}{_index_text(w.shape, first)}"
            )
    try:
        lead = tuple(np.broadcast_shapes(matrices.shape[:-3], w.shape[:-1]))
    except ValueError:
        raise ValueError(
            f"the leading shapes of R {matrices.shape[:-3]} and weights {w.shape[:-1]} do not "
            "broadcast together (R is (..., N, 3, 3), weights (..., N))"
        ) from None
    if weights is not None:  # weights of any size: scaled by a power of two, exactly
        largest_weight = np.max(w, axis=-1, initial=0.0, keepdims=True)
        w = np.ldexp(w, -np.frexp(largest_weight)[1])
    if matrices.ndim == 3 and w.ndim == 1:  # one set: a matrix-vector product
        S = (w @ matrices.reshape(count, 9)).reshape(1, 3, 3)
    else:
        S = np.einsum("...n,...nij->...ij", w, matrices).reshape(-1, 3, 3)
    if S.shape[0] == 1:  # one set: the same computation in fewer numpy calls
        C, values, gap = procrustes_one(S[0])
        M, singular, margin = C[np.newaxis], np.array([values]), np.array([gap])
    else:
        M, singular, margin = special_procrustes(S)
    empty = np.flatnonzero(singular[:, 0] == 0.0)
    if empty.size:
        raise ValueError(
            f"R{_index_text(lead, int(empty[0]))} has no rotation with a weight: every weight is "
            "zero, or there are no rotations, so there is nothing to average"
        )
    spread = np.flatnonzero(~(margin > DEGENERATE * singular[:, 0]))
    if spread.size:
        raise ValueError(
            f"the mean of R{_index_text(lead, int(spread[0]))} is not unique: the rotations are "
            "spread so evenly that several rotations are equally near their average"
        )
    M += 0.0  # no negative zeros
    return M.reshape(*lead, 3, 3)
