"""Attitude from vector observations: Wahba's problem, and TRIAD as its two-vector case.

A sensor that sees known directions tells the attitude: an accelerometer at rest measures
gravity, a magnetometer the Earth's field, a star tracker the stars. Each gives a vector ``a_i``
in the body's axes whose direction ``b_i`` in the reference axes is known, and the attitude is
the rotation ``C`` with ``a_i ≈ C b_i``. Measured vectors are never exact, so G. Wahba (1965)
asked for the rotation that fits them best in the weighted least-squares sense,

.. math::

    C = \\arg\\min_{C ∈ SO(3)} \\tfrac12 \\sum_i w_i \\lVert a_i - C b_i \\rVert^2
      = \\arg\\max_{C ∈ SO(3)} \\operatorname{tr}(C^T B), \\qquad B = \\sum_i w_i a_i b_i^T,

whose solution by the singular value decomposition ``B = U S Vᵀ`` is ``C = U diag(1, 1, d)
Vᵀ`` with ``d = det U det V`` (F. L. Markley, 1988). It is unique when ``B`` has rank 2 or 3
(and, when ``d = −1``, ``s2 > s3``): at least two of the weighted vectors must point in
different directions. One direction alone fixes no turn about itself.

With two vectors the answer depends on both; the older TRIAD method (H. D. Black, 1964) instead
aligns the first pair exactly and uses the second only to fix the turn about the first. That is
the limit of an infinite weight on the first pair, which :func:`align_vectors` accepts as
SciPy's ``Rotation.align_vectors`` does: trust gravity completely and the magnetic field for
the heading only.

Examples
--------
>>> import numpy as np
>>> from eulerlib import rot_z
>>> b = np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0]])        # up and north, in the world
>>> a = b @ rot_z(30, degrees=True).T                        # as seen by a body turned 30°
>>> found = align_vectors(a, b)
>>> np.allclose(found.matrix, rot_z(30, degrees=True)), float(found.rssd) < 1e-15
(True, True)
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._length_kernels import lengths
from eulerlib._procrustes_kernels import (
    procrustes_one,
    special_procrustes,
    turn_about_primary,
    turn_about_primary_one,
)
from eulerlib._validation import _index_text, as_float_array

__all__ = ["Alignment", "align_vectors"]

Array = NDArray[np.float64]

#: A problem whose margin ``s2 + d s3`` is at most this fraction of ``s1`` (or, with an infinite
#: weight, whose secondary pairs pull on the turn about the primary one by at most this fraction
#: of their size) does not determine one rotation. Two unit vectors at the angle φ give the
#: fraction ``(1 − cos φ) / (1 + cos φ) ≈ φ² / 4``, so the limit is φ ≈ 2⁻¹⁹ ≈ 2e-6 rad, where
#: the rounding of the input alone would turn the answer by about 2⁻¹² ≈ 2e-4 rad.
DEGENERATE = 2.0**-40


class Alignment(NamedTuple):
    """What :func:`align_vectors` returns: the rotation and how well it fits."""

    #: The rotation matrices ``C``, shape ``(..., 3, 3)``, with ``a ≈ C b``.
    matrix: NDArray[np.float64]
    #: ``sqrt(Σ w |a − C b|²)``, the root of the weighted sum of squared residuals, shape
    #: ``(...)``; pairs with an infinite weight are fitted exactly and left out.
    rssd: NDArray[np.float64]


def _as_vector_sets(value: ArrayLike, name: str) -> Array:
    array = as_float_array(value, name)
    if array.ndim < 2 or array.shape[-1] != 3:
        raise ValueError(f"{name} must have shape (..., N, 3), got shape {array.shape}")
    nonzero = array.any(axis=-1)
    if not nonzero.all():
        zero = np.flatnonzero(~nonzero)
        where = _index_text(array.shape[:-1], int(zero[0]))
        raise ValueError(f"{name}{where} is zero: a vector with no direction cannot be aligned")
    return array


def _as_weights(value: ArrayLike | None, count: int) -> Array:
    if value is None:
        return np.ones(count)
    weights = as_float_array(value, "weights", finite=False)
    if weights.ndim == 0 or weights.shape[-1] != count:
        raise ValueError(
            f"weights must have shape (..., {count}), one per vector, got shape {weights.shape}"
        )
    bad = np.flatnonzero(~(weights >= 0.0))
    if bad.size:
        first = int(bad[0])
        raise ValueError(
            f"weights must be ≥ 0 (or +inf for one primary vector), got "
            f"{weights.reshape(-1)[first]}{_index_text(weights.shape, first)}"
        )
    return weights


def _exponents(values: Array, axes: tuple[int, ...]) -> NDArray[np.int32]:
    """Binary exponent of the largest ``|value|`` over ``axes`` (0 where all are zero)."""
    exponent: NDArray[np.int32] = np.frexp(np.max(np.abs(values), axis=axes, initial=0.0))[1]
    return exponent


def align_vectors(a: ArrayLike, b: ArrayLike, weights: ArrayLike | None = None) -> Alignment:
    """The rotation that best turns the vectors ``b`` into the vectors ``a`` (Wahba's problem).

    Parameters
    ----------
    a : array_like, shape (..., N, 3)
        The vectors as observed, in the body's axes, say; none of them zero.
    b : array_like, shape (..., N, 3)
        The same vectors in the reference axes; none zero. The leading axes of ``a``, ``b`` and
        ``weights`` broadcast: each leading index is one problem, so ``a`` of shape
        ``(T, 2, 3)`` and ``b`` of shape ``(2, 3)`` solve ``T`` problems with one reference.
    weights : array_like, shape (..., N), optional
        The weight of each pair, ≥ 0; default all 1. One weight per problem may be ``inf``:
        that pair is then aligned exactly and the others only fix the turn about it (TRIAD,
        for two pairs).

    Returns
    -------
    Alignment
        ``(matrix, rssd)``: the rotations ``C`` ``(..., 3, 3)`` minimizing ``Σ w |a − C b|²``
        and the root of that sum ``(...)``, as SciPy's ``Rotation.align_vectors`` returns
        them. One problem in gives a ``(3, 3)`` matrix and a 0-d ``rssd``.

    Raises
    ------
    TypeError
        If an argument is not real numbers.
    ValueError
        If a shape is wrong or the shapes do not broadcast, a vector is not finite or is zero,
        a weight is negative or NaN, a problem has more than one infinite weight, or a problem
        does not determine one rotation: every weight zero, or all the weighted vectors
        parallel (one pair alone, say), so that any turn about their direction fits equally
        well. The message gives the index of the problem.

    Notes
    -----
    ``C = U diag(1, 1, det U det V) Vᵀ`` from the SVD of ``B = Σ w a bᵀ`` (see the module
    docstring). The vectors are not normalized: a longer vector counts as much as a larger
    weight, as in SciPy. Each problem's vectors and weights are first scaled by powers of two,
    which changes neither the answer nor any digit, so vectors as long as 1e200 or as short as
    1e-200 are aligned as well as unit ones. A problem counts as degenerate when ``s2 + d s3``
    is at most ``2⁻⁴⁰ s1``: for two vectors, when they are parallel to within about 2e-6 rad,
    where the rounding of the input alone would turn the answer by about 2e-4 rad. Closer to
    parallel the answer is mostly rounding, and SciPy only warns.

    Examples
    --------
    >>> import numpy as np
    >>> from eulerlib import rot_x
    >>> b = np.array([[0.0, 0.0, -1.0], [0.5, 0.0, 0.8]])      # gravity and field, world axes
    >>> a = b @ rot_x(10, degrees=True).T                       # seen by a body rolled 10°
    >>> noisy = a + [[0.0, 0.01, 0.0], [0.0, 0.0, 0.0]]
    >>> triad = align_vectors(noisy, b, weights=[np.inf, 1.0])   # trust gravity fully
    >>> np.round(np.degrees(np.arctan2(triad.matrix[2, 1], triad.matrix[2, 2])), 3)  # roll
    np.float64(10.562)
    >>> align_vectors([[1.0, 0.0, 0.0], [2.0, 0.0, 0.0]], [[0.0, 1.0, 0.0], [0.0, 2.0, 0.0]])
    Traceback (most recent call last):
    ...
    ValueError: a and b do not determine one rotation: the weighted vectors are all parallel \
(or only one has a weight), so any turn about their direction fits as well
    """
    first = _as_vector_sets(a, "a")
    second = _as_vector_sets(b, "b")
    count = first.shape[-2]
    if second.shape[-2] != count:
        raise ValueError(
            f"a and b must hold as many vectors each, got {count} and {second.shape[-2]} "
            f"(shapes {first.shape} and {second.shape})"
        )
    w = None if weights is None else _as_weights(weights, count)
    if first.ndim == second.ndim == 2 and (w is None or w.ndim == 1):
        sizes = [max(float(x.max()), -float(x.min())) for x in (first, second)]
        if w is not None:
            sizes.append(float(np.max(w, where=w < math.inf, initial=0.0)))
        if all(_ORDINARY[0] <= size <= _ORDINARY[1] for size in sizes):
            return _one_problem(first, second, w)  # one problem of ordinary size: the short way
    if w is None:
        w = np.ones(count)
    lead = _problems_shape(first.shape[:-2], second.shape[:-2], w.shape[:-1])
    total = math.prod(lead)
    A = _problems(first, lead, total, 2)
    Bv = _problems(second, lead, total, 2)
    W = np.ones((total, count)) if weights is None else _problems(w, lead, total, 1)

    primaries = np.zeros(total, dtype=np.intp)
    if weights is not None:
        infinite = np.isinf(W)
        if infinite.any():
            primaries = np.count_nonzero(infinite, axis=1)
            several = np.flatnonzero(primaries > 1)
            if several.size:
                raise ValueError(
                    f"weights{_index_text(lead, int(several[0]))} has "
                    f"{primaries[several[0]]} infinite weights: only one vector can be aligned "
                    "exactly"
                )
            W = np.where(infinite, 0.0, W)
    # Scale every problem by powers of two, so that M = Σ w a bᵀ and the residuals can neither
    # overflow nor underflow: exact, and the rotation does not change. Inputs of ordinary size
    # (everything between 2⁻²⁰⁰ and 2²⁰⁰) need none of it.
    scaled = not all(
        _ORDINARY[0] <= max(float(x.max()), -float(x.min())) <= _ORDINARY[1] for x in (A, Bv, W)
    )
    e_a = e_b = e_w = np.zeros(total, dtype=np.int32)
    if scaled:
        e_a, e_b = _exponents(A, (1, 2)), _exponents(Bv, (1, 2))
        e_w = _exponents(W, (1,))
        e_w += e_w % 2  # even, so that its square root is a power of two too
        A = np.ldexp(A, -e_a[:, None, None])
        Bv = np.ldexp(Bv, -e_b[:, None, None])
        W = np.ldexp(W, -e_w[:, None])
    M = np.einsum("kn,kni,knj->kij", W, A, Bv)

    if not primaries.any():
        C, singular, margin = special_procrustes(M)
        _check_margins(lead, np.arange(total), singular, margin)
    else:
        C = np.empty((total, 3, 3))
        plain = np.flatnonzero(primaries == 0)
        if plain.size:
            C[plain], singular, margin = special_procrustes(M[plain])
            _check_margins(lead, plain, singular, margin)
        with_primary = np.flatnonzero(primaries == 1)
        C[with_primary] = _with_primary(lead, with_primary, A, Bv, W, M, infinite)
    C += 0.0  # no negative zeros
    with np.errstate(over="ignore", under="ignore"):
        # the residuals in units of 2**e_a, the weights in units of 2**e_w
        turned = np.einsum("kij,knj->kni", C, Bv)
        if scaled:
            turned = np.ldexp(turned, (e_b - e_a)[:, None, None])
        residual = A - turned
        rssd = np.sqrt(np.einsum("kn,kni,kni->k", W, residual, residual))
        if scaled:
            rssd = np.ldexp(rssd, e_a + e_w // 2)
    return Alignment(C.reshape(*lead, 3, 3), rssd.reshape(lead))


def _one_problem(a: Array, b: Array, w: Array | None) -> Alignment:
    """One problem of ordinary size, as the general path solves it, in fewer numpy calls."""
    problem = np.zeros(1, dtype=np.intp)
    if w is None or not (infinite := np.isinf(w)).any():
        M = (a.T if w is None else a.T * w) @ b
        C, singular, margin = procrustes_one(M)
        if not margin > DEGENERATE * singular[0]:
            _check_margins((), problem, np.array([singular]), np.array([margin]))
    else:
        if np.count_nonzero(infinite) > 1:
            raise ValueError(
                f"weights has {np.count_nonzero(infinite)} infinite weights: only one vector "
                "can be aligned exactly"
            )
        w = np.where(infinite, 0.0, w)
        primary = int(np.argmax(infinite))
        pa, pb = a[primary].tolist(), b[primary].tolist()
        size_a, size_b = math.sqrt(sum(v * v for v in pa)), math.sqrt(sum(v * v for v in pb))
        M = (a.T * w) @ b
        C, turning = turn_about_primary_one(
            [v / size_a for v in pa], [v / size_b for v in pb], M.tolist()
        )
        size = float(w @ np.sqrt(np.einsum("ij,ij->i", a, a) * np.einsum("ij,ij->i", b, b)))
        if not turning > DEGENERATE * size:
            raise ValueError(f"a and b do not determine one rotation: {_NOT_ABOUT_PRIMARY}")
    C += 0.0  # no negative zeros
    residual = a - b @ C.T
    if w is None:
        return Alignment(C, np.sqrt(np.vdot(residual, residual)))
    return Alignment(C, np.sqrt(w @ np.einsum("ij,ij->i", residual, residual)))


_NOT_ABOUT_PRIMARY = (
    "the vectors with finite weights are parallel to the one with the infinite weight (or "
    "there are none, or their weights are zero), so any turn about it fits as well"
)


#: The range of sizes in which one problem is solved without scaling.
_ORDINARY = (2.0**-200, 2.0**200)


def _check_margins(
    lead: tuple[int, ...], problems: NDArray[np.intp], singular: Array, margin: Array
) -> None:
    """Refuse the first problem whose margin says that it determines no single rotation."""
    largest = singular[:, 0]
    flat = np.flatnonzero(~(margin > DEGENERATE * largest))
    if not flat.size:
        return
    where = _index_text(lead, int(problems[flat[0]]))
    values = singular[flat[0]]
    if values[0] == 0.0:
        reason = "every weight is zero"
    elif values[1] <= DEGENERATE * values[0]:
        reason = (
            "the weighted vectors are all parallel (or only one has a weight), so any turn "
            "about their direction fits as well"
        )
    else:
        reason = (
            "two rotations fit equally well (the vectors of a are turned like a mirror image "
            "of those of b)"
        )
    raise ValueError(f"a and b do not determine one rotation{where}: {reason}")


def _with_primary(
    lead: tuple[int, ...],
    problems: NDArray[np.intp],
    A: Array,
    Bv: Array,
    W: Array,
    M: Array,
    infinite: NDArray[np.bool_],
) -> Array:
    """The rotations of the problems with one infinite weight (TRIAD and its generalization)."""
    count = A.shape[1]
    index = np.argmax(infinite[problems], axis=1)
    pa = A[problems, index]
    pb = Bv[problems, index]
    pa /= lengths(pa.T)[:, None]
    pb /= lengths(pb.T)[:, None]
    C, turning = turn_about_primary(pa, pb, M[problems])
    # the secondary pairs' own size, Σ w |a| |b|, scaled as M is
    size = np.einsum(
        "kn,kn,kn->k",
        W[problems],
        lengths(A[problems].reshape(-1, 3).T).reshape(-1, count),
        lengths(Bv[problems].reshape(-1, 3).T).reshape(-1, count),
    )
    flat = np.flatnonzero(~(turning > DEGENERATE * size))
    if flat.size:
        where = _index_text(lead, int(problems[flat[0]]))
        raise ValueError(f"a and b do not determine one rotation{where}: {_NOT_ABOUT_PRIMARY}")
    return C


def _problems(values: Array, lead: tuple[int, ...], total: int, axes: int) -> Array:
    """``values`` with its leading axes (all but the last ``axes``) broadcast to ``lead`` and
    flattened into one."""
    tail = values.shape[values.ndim - axes :]
    if values.shape[: values.ndim - axes] == lead:
        return values.reshape(total, *tail)
    return np.broadcast_to(values, (*lead, *tail)).reshape(total, *tail)


def _problems_shape(*shapes: tuple[int, ...]) -> tuple[int, ...]:
    try:
        return tuple(np.broadcast_shapes(*shapes))
    except ValueError:
        words = f"a {shapes[0]}, b {shapes[1]} and weights {shapes[2]}"
        raise ValueError(
            f"the leading shapes of {words} do not broadcast together (each is (..., N))"
        ) from None
