"""Quaternion algebra: product, conjugate, inverse, exponential, logarithm and power.

A quaternion ``q = w + x i + y j + z k`` has a scalar part ``w`` and a vector part
``v = (x, y, z)``. eulerlib multiplies quaternions by **Hamilton's convention**,

.. math::

    i^2 = j^2 = k^2 = ijk = -1, \\qquad ij = k, \\quad jk = i, \\quad ki = j,

which is SciPy's, Eigen's and Solà's ("Quaternion kinematics for the error-state Kalman
filter", 2017), and in which the product composes rotations as their matrices do:
``R(p q) = R(p) R(q)`` (first ``q``, then ``p``, both about the fixed axes). In terms of the
parts, ``p q = (pw qw − pv · qv, pw qv + qw pv + pv × qv)``. (The other convention in use, JPL's
or Shuster's, has ``ij = −k``, and there the order of every product is reversed.)

The functions here take quaternions of any length, not only unit ones: the conjugate
``q* = (w, −v)``, the inverse ``q⁻¹ = q* / |q|²``, and, with ``θ = atan2(|v|, w)`` in [0, π]
and ``n = v / |v|``, the polar form ``q = |q| (cos θ + n sin θ)`` that gives

.. math::

    \\exp(a + v) = e^a (\\cos |v| + \\hat v \\sin |v|), \\qquad
    \\log q = \\ln |q| + θ n, \\qquad q^t = \\exp(t \\log q) = |q|^t (\\cos tθ + n \\sin tθ).

For a unit quaternion, the rotation by the angle φ about the unit axis ``u``, ``θ = φ / 2``:
``log q`` is ``(0, φ u / 2)``, half the rotation vector; ``exp(ω dt / 2)`` is the turn of a
constant angular velocity ω during ``dt``, and ``q^t`` turns by the fraction ``t`` of the way, so
``q0 (q0⁻¹ q1)^t`` is slerp. ``q`` and ``−q`` are one rotation but two quaternions with
different logarithms and powers: ``q^t`` follows ``q``'s own angle θ, which is the short way
(φ ≤ π) when ``w ≥ 0``; make ``w ≥ 0`` first for the short way.

Component order
---------------
``scalar_first`` means what it means everywhere in eulerlib and in SciPy: ``False`` (the
default) stores ``(x, y, z, w)``, ``True`` stores ``(w, x, y, z)``, for what goes in and what
comes out.

Examples
--------
>>> import numpy as np
>>> i, j = [1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]     # (x, y, z, w)
>>> quaternion_multiply(i, j)                             # ij = k
array([0., 0., 1., 0.])
>>> quaternion_multiply(j, i)                             # ji = −k
array([ 0.,  0., -1.,  0.])
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib import _compiled
from eulerlib._algebra_kernels import (
    Quad,
    exp_one,
    exponentials,
    hamilton_product,
    inverse_one,
    inverses,
    log_one,
    logarithms,
    moderate,
    power_one,
    powers,
    product_one,
)
from eulerlib._blocks import block_slices
from eulerlib._broadcast import Selection, broadcast_blocks, broadcast_shape, selected_index
from eulerlib._validation import _index_text, as_float_array, check_flag

__all__ = [
    "quaternion_conjugate",
    "quaternion_exp",
    "quaternion_inverse",
    "quaternion_log",
    "quaternion_multiply",
    "quaternion_power",
]

Array = NDArray[np.float64]

#: Stored positions of w, x, y, z, by ``scalar_first``.
_ROWS = {False: [3, 0, 1, 2], True: [0, 1, 2, 3]}
#: Rows (w, x, y, z) of each stored position, by ``scalar_first``.
_STORED = {False: [1, 2, 3, 0], True: [0, 1, 2, 3]}


def _as_quaternions(value: ArrayLike, name: str) -> Array:
    array = as_float_array(value, name)
    if array.ndim == 0 or array.shape[-1] != 4:
        raise ValueError(f"{name} must have shape (..., 4), got shape {array.shape}")
    return array


def _rows(stored: Array, first: bool) -> Array:
    """Stored quaternions ``(n, 4)`` as contiguous rows w, x, y, z, shape ``(4, n)``."""
    return np.ascontiguousarray(stored.T[_ROWS[first]])


def _write(out: Array, rows: Array, first: bool) -> None:
    """Rows w, x, y, z ``(4, n)`` into stored quaternions ``out`` ``(n, 4)``, no ``-0.0``."""
    np.add(rows[_STORED[first]].T, 0.0, out=out)


def _one(quaternion: Array, first: bool) -> Quad | None:
    """One stored quaternion ``(4,)`` as Python floats ``(w, x, y, z)``, when it is of moderate
    size (:func:`eulerlib._algebra_kernels.moderate`); else None, for the block functions."""
    values = quaternion.tolist()
    if not moderate(values):
        return None
    w, x, y, z = (values[i] for i in _ROWS[first])
    return w, x, y, z


def _stored_one(result: Quad, first: bool) -> Array:
    """``(w, x, y, z)`` as a stored quaternion, without ``-0.0``."""
    return np.array([result[i] + 0.0 for i in _STORED[first]])


def _refuse_zero(
    rows: Array, name: str, lead: tuple[int, ...], selection: Selection, why: str
) -> None:
    zero = np.flatnonzero(~np.any(rows != 0.0, axis=0))
    if zero.size:
        where = _index_text(lead, selected_index(selection, int(zero[0])))
        raise ValueError(f"{name}{where} is zero: {why}")


def quaternion_multiply(
    p: ArrayLike, q: ArrayLike, *, scalar_first: bool = False
) -> NDArray[np.float64]:
    """Hamilton products ``p q`` of quaternions of any length.

    Parameters
    ----------
    p, q : array_like, shape (..., 4)
        Quaternions, ``(x, y, z, w)`` or with ``scalar_first`` ``(w, x, y, z)``. Their leading
        axes broadcast.
    scalar_first : bool, optional
        Read and return ``(w, x, y, z)``. Default ``False``: ``(x, y, z, w)``, as SciPy.

    Returns
    -------
    ndarray, shape (..., 4)
        ``p q``, not normalized: ``|p q| = |p| |q|``. For unit quaternions it is the rotation
        ``q`` followed by ``p``, ``R(p q) = R(p) R(q)``; it is not made canonical.

    Raises
    ------
    TypeError
        If ``p`` or ``q`` is not real numbers or ``scalar_first`` is not a bool.
    ValueError
        If a shape is wrong or the leading shapes do not broadcast, or a value is not finite.

    Notes
    -----
    Hamilton's convention (``ij = k``), written out term by term: ``w = pw qw − px qx − py qy −
    pz qz``, ``x = pw qx + px qw + py qz − pz qy``, ``y = pw qy − px qz + py qw + pz qx``,
    ``z = pw qz + px qy − py qx + pz qw``. A product beyond float64's range is infinite.

    Examples
    --------
    >>> import numpy as np
    >>> from eulerlib import euler_to_quaternion
    >>> p = euler_to_quaternion([90, 0, 0], degrees=True)   # 90° about z
    >>> q = euler_to_quaternion([0, 0, 90], degrees=True)   # 90° about x
    >>> quaternion_multiply(p, q)                           # first about x, then about z
    array([0.5, 0.5, 0.5, 0.5])
    >>> # (1 + 2i + 3j + 4k) times 1 and times k, broadcast: (1 + 2i + 3j + 4k) k = −4 + 3i − 2j + k
    >>> quaternion_multiply([1, 2, 3, 4], [[1, 0, 0, 0], [0, 0, 0, 1]], scalar_first=True)
    array([[ 1.,  2.,  3.,  4.],
           [-4.,  3., -2.,  1.]])
    """
    first = check_flag(scalar_first, "scalar_first")
    left, right = _as_quaternions(p, "p"), _as_quaternions(q, "q")
    if left.ndim == 1 and right.ndim == 1:
        one_p, one_q = _one(left, first), _one(right, first)
        if one_p is not None and one_q is not None:
            return _stored_one(product_one(one_p, one_q), first)
    lead_p, lead_q = left.shape[:-1], right.shape[:-1]
    shape = broadcast_shape({"p": lead_p, "q": lead_q})
    flat_p, flat_q = left.reshape(-1, 4), right.reshape(-1, 4)
    out = np.empty((math.prod(shape), 4))
    rows = np.empty((4, 0))
    with np.errstate(over="ignore", invalid="ignore"):  # beyond float64's range: infinite
        for block, (on_p, on_q) in broadcast_blocks(shape, (lead_p, lead_q)):
            if rows.shape[1] != block.stop - block.start:
                rows = np.empty((4, block.stop - block.start))
            hamilton_product(_rows(flat_p[on_p], first), _rows(flat_q[on_q], first), rows)
            _write(out[block], rows, first)
    return out.reshape(*shape, 4)


def quaternion_conjugate(q: ArrayLike, *, scalar_first: bool = False) -> NDArray[np.float64]:
    """Conjugates ``q* = (w, −v)``: the vector part negated.

    Parameters
    ----------
    q : array_like, shape (..., 4)
        Quaternions of any length, ``(x, y, z, w)`` or with ``scalar_first`` ``(w, x, y, z)``.
    scalar_first : bool, optional
        Read and return ``(w, x, y, z)``. Default ``False``.

    Returns
    -------
    ndarray, shape (..., 4)
        ``q*``. For a unit quaternion it is the inverse, the opposite rotation; in general
        ``q q* = |q|²``.

    Raises
    ------
    TypeError
        If ``q`` is not real numbers or ``scalar_first`` is not a bool.
    ValueError
        If ``q`` does not have shape ``(..., 4)`` or a value is not finite.

    Examples
    --------
    >>> quaternion_conjugate([1.0, 2.0, 3.0, 4.0])
    array([-1., -2., -3.,  4.])
    >>> quaternion_conjugate([1.0, 2.0, 3.0, 4.0], scalar_first=True)
    array([ 1., -2., -3., -4.])
    """
    first = check_flag(scalar_first, "scalar_first")
    quaternions = _as_quaternions(q, "q")
    out = 0.0 - quaternions  # no -0.0 in the vector part
    scalar = 0 if first else 3
    out[..., scalar] = quaternions[..., scalar]
    return out


def quaternion_inverse(q: ArrayLike, *, scalar_first: bool = False) -> NDArray[np.float64]:
    """Inverses ``q⁻¹ = q* / |q|²`` of nonzero quaternions of any length.

    Parameters
    ----------
    q : array_like, shape (..., 4)
        Nonzero quaternions, ``(x, y, z, w)`` or with ``scalar_first`` ``(w, x, y, z)``.
    scalar_first : bool, optional
        Read and return ``(w, x, y, z)``. Default ``False``.

    Returns
    -------
    ndarray, shape (..., 4)
        ``q⁻¹``, with ``q q⁻¹ = q⁻¹ q = 1``; for a unit quaternion it equals the conjugate.

    Raises
    ------
    TypeError
        If ``q`` is not real numbers or ``scalar_first`` is not a bool.
    ValueError
        If ``q`` does not have shape ``(..., 4)``, a value is not finite, or a quaternion is
        zero (the message gives its index).

    Notes
    -----
    ``q`` is first scaled by the power of two ``2**-e`` that brings its largest component into
    [0.5, 1), which is exact; the inverse of the scaled quaternion is scaled back by ``2**-e``.
    So quaternions as long as 1e300 or as short as 1e-300 are inverted to a few units in the
    last place, where ``|q|²`` itself would overflow or underflow. An inverse beyond float64's
    range (of a quaternion shorter than about 1e-308) is infinite.

    Examples
    --------
    >>> quaternion_inverse([0.0, 0.0, 0.0, 2.0])
    array([0. , 0. , 0. , 0.5])
    >>> quaternion_inverse([0.0, 0.0, 1e300, 1e300])
    array([ 0.e+000,  0.e+000, -5.e-301,  5.e-301])
    """
    first = check_flag(scalar_first, "scalar_first")
    quaternions = _as_quaternions(q, "q")
    if quaternions.ndim == 1 and (one := _one(quaternions, first)) is not None and any(one):
        return _stored_one(inverse_one(one), first)
    lead = quaternions.shape[:-1]
    flat = quaternions.reshape(-1, 4)
    out = np.empty(flat.shape)
    for block in block_slices(flat.shape[0]):
        rows = _rows(flat[block], first)
        _refuse_zero(rows, "q", lead, block, "a zero quaternion has no inverse")
        _write(out[block], inverses(rows), first)
    return out.reshape(quaternions.shape)


def quaternion_exp(v: ArrayLike, *, scalar_first: bool = False) -> NDArray[np.float64]:
    """Exponentials of pure quaternions (vectors) or of quaternions.

    Parameters
    ----------
    v : array_like, shape (..., 3) or (..., 4)
        Vectors ``v``, read as the pure quaternions ``(0, v)``; or quaternions ``a + v``,
        ``(x, y, z, w)`` or with ``scalar_first`` ``(w, x, y, z)``.
    scalar_first : bool, optional
        Read quaternions as, and return, ``(w, x, y, z)``. Default ``False``.

    Returns
    -------
    ndarray, shape (..., 4)
        ``exp(a + v) = e^a (cos |v|, sin |v| v / |v|)``; for a vector a unit quaternion, the
        rotation by ``2 |v|`` about ``v``. ``exp(0) = 1``.

    Raises
    ------
    TypeError
        If ``v`` is not real numbers or ``scalar_first`` is not a bool.
    ValueError
        If ``v`` does not have shape ``(..., 3)`` or ``(..., 4)`` or a value is not finite.

    Notes
    -----
    The direction ``v / |v|`` is taken after scaling ``v`` by a power of two and ``|v|`` is
    computed without overflow or underflow, so the result is accurate to a few units in the
    last place for every length, ``|v|`` of 1e-300 and of 1e300 included. A scalar part
    above about 709 makes ``e^a`` infinite.

    The exponential of the half rotation vector ``ω dt / 2`` is the quaternion of the turn of
    a constant angular velocity ``ω`` during ``dt``: ``q(t + dt) = q(t) exp(ω dt / 2)`` with
    ``ω`` in the body's axes (J. Solà, 2017, eq 4.29 and section 4.6).

    Examples
    --------
    >>> import numpy as np
    >>> q = quaternion_exp([0.0, 0.0, np.pi / 4])     # 90° about z, (x, y, z, w)
    >>> q
    array([0.        , 0.        , 0.70710678, 0.70710678])
    >>> quaternion_exp([0.0, 1.0, 0.0, 0.0], scalar_first=True)     # exp(i) = cos 1 + i sin 1
    array([0.54030231, 0.84147098, 0.        , 0.        ])
    """
    first = check_flag(scalar_first, "scalar_first")
    kernels, given = _compiled.rotations, _compiled.batch(v, (3,))
    if kernels is not None and given is not None and given.ndim > 1:  # one vector: below
        out = _compiled_exponentials(kernels, given, first)
        if out is not None:
            return out
    values = as_float_array(v, "v")
    if values.ndim == 0 or values.shape[-1] not in (3, 4):
        raise ValueError(f"v must have shape (..., 3) or (..., 4), got shape {values.shape}")
    pure = values.shape[-1] == 3
    if values.ndim == 1 and moderate(items := values.tolist()):
        if pure:
            return _stored_one(exp_one(0.0, items), first)
        w, x, y, z = (items[i] for i in _ROWS[first])
        if w < 700.0:  # e^w far from float64's limit
            return _stored_one(exp_one(w, [x, y, z]), first)
    flat = values.reshape(-1, values.shape[-1])
    out = np.empty((flat.shape[0], 4))
    for block in block_slices(flat.shape[0]):
        if pure:
            rows = exponentials(None, np.ascontiguousarray(flat[block].T))
        else:
            parts = _rows(flat[block], first)
            rows = exponentials(parts[0], parts[1:])
        _write(out[block], rows, first)
    return out.reshape(*values.shape[:-1], 4)


def _compiled_exponentials(kernels: Any, v: Array, first: bool) -> Array | None:
    """The exponentials of a float64 batch of vectors in compiled kernels, around numpy's sine
    and cosine, a block at a time; None where they do not take it (a length that needs
    rescaling, a number that is not finite), for the array path."""
    flat = v.reshape(-1, 3)
    out = np.empty((flat.shape[0], 4))
    for block in block_slices(flat.shape[0]):
        part = flat[block]
        unit, length = np.empty(part.shape), np.empty(part.shape[0])
        if not kernels.vector_directions(unit, length, part):
            return None
        kernels.pure_exponentials(out[block], unit, np.sin(length), np.cos(length), first)
    return out.reshape(*v.shape[:-1], 4)


def quaternion_log(q: ArrayLike, *, scalar_first: bool = False) -> NDArray[np.float64]:
    """Logarithms ``log q = (ln |q|, θ v / |v|)`` of nonzero quaternions, ``θ = atan2(|v|, w)``.

    Parameters
    ----------
    q : array_like, shape (..., 4)
        Nonzero quaternions, ``(x, y, z, w)`` or with ``scalar_first`` ``(w, x, y, z)``.
    scalar_first : bool, optional
        Read and return ``(w, x, y, z)``. Default ``False``.

    Returns
    -------
    ndarray, shape (..., 4)
        The principal logarithm, with ``exp(log q) = q``: the scalar part ``ln |q|`` (0 for a
        unit quaternion), the vector part ``θ`` times the unit vector of ``v``, its length ``θ``
        in [0, π]. For a unit quaternion of the rotation by φ about ``u`` (``w ≥ 0``) the
        vector part is ``φ u / 2``, half the rotation vector: ``q[..., :3]`` by default.

    Raises
    ------
    TypeError
        If ``q`` is not real numbers or ``scalar_first`` is not a bool.
    ValueError
        If ``q`` does not have shape ``(..., 4)``, a value is not finite, or a quaternion is
        zero (the message gives its index).

    Notes
    -----
    ``θ = atan2(|v|, w)`` is accurate to a few units in the last place near 0 and near π, where
    ``acos(w / |q|)`` loses half the digits; ``|q|`` and ``v / |v|`` are taken after scaling by
    a power of two, so no length overflows or underflows. The logarithm of a negative real
    number (``v = 0``, ``w < 0``) is any ``(ln |w|, π u)`` with ``|u| = 1``; eulerlib returns
    ``u = (1, 0, 0)``.

    Examples
    --------
    >>> import numpy as np
    >>> s = np.sqrt(0.5)
    >>> quaternion_log([0.0, 0.0, s, s])        # 90° about z: half of (0, 0, π/2)
    array([0.        , 0.        , 0.78539816, 0.        ])
    >>> quaternion_log([np.e, 0.0, 0.0, 0.0], scalar_first=True)
    array([1., 0., 0., 0.])
    """
    first = check_flag(scalar_first, "scalar_first")
    quaternions = _as_quaternions(q, "q")
    if quaternions.ndim == 1 and (one := _one(quaternions, first)) is not None and any(one):
        return _stored_one(log_one(one), first)
    lead = quaternions.shape[:-1]
    flat = quaternions.reshape(-1, 4)
    out = np.empty(flat.shape)
    for block in block_slices(flat.shape[0]):
        rows = _rows(flat[block], first)
        _refuse_zero(rows, "q", lead, block, "the logarithm of 0 is not defined")
        _write(out[block], logarithms(rows), first)
    return out.reshape(quaternions.shape)


def quaternion_power(
    q: ArrayLike, t: ArrayLike, *, scalar_first: bool = False
) -> NDArray[np.float64]:
    """Powers ``q^t = exp(t log q)`` of nonzero quaternions, for real exponents ``t``.

    Parameters
    ----------
    q : array_like, shape (..., 4)
        Nonzero quaternions, ``(x, y, z, w)`` or with ``scalar_first`` ``(w, x, y, z)``.
    t : array_like, shape (...)
        Real exponents. The leading shape of ``q`` and the shape of ``t`` broadcast.
    scalar_first : bool, optional
        Read and return ``(w, x, y, z)``. Default ``False``.

    Returns
    -------
    ndarray, shape (S, 4)
        ``q^t = |q|^t (cos tθ, sin tθ v / |v|)`` with ``θ = atan2(|v|, w)``, ``S`` the broadcast
        of ``q.shape[:-1]`` and ``t.shape``. ``q^0 = 1``, ``q^1 = q``, ``q^-1 = q⁻¹``, and
        ``q^s q^t = q^(s+t)``. For the unit quaternion of the rotation by φ about ``u`` it is
        the rotation by ``t φ`` about ``u`` (the short way when ``w ≥ 0``).

    Raises
    ------
    TypeError
        If ``q`` or ``t`` is not real numbers or ``scalar_first`` is not a bool.
    ValueError
        If ``q`` does not have shape ``(..., 4)``, the shapes do not broadcast, a value is not
        finite, or a quaternion is zero (the message gives its index).

    Notes
    -----
    The principal power, on the logarithm of :func:`quaternion_log` (the same choice for a
    negative real ``q``). SciPy's ``Rotation.__pow__`` computes the same rotation for unit
    quaternions with ``w ≥ 0``.

    Examples
    --------
    >>> import numpy as np
    >>> from eulerlib import euler_to_quaternion, quaternion_to_euler
    >>> q = euler_to_quaternion([90, 0, 0], degrees=True)          # 90° about z
    >>> quaternion_to_euler(quaternion_power(q, [0.5, 2.0]), degrees=True)
    array([[ 45.,   0.,   0.],
           [180.,   0.,   0.]])
    >>> quaternion_power([0.0, 0.0, 0.0, 4.0], 0.5)
    array([0., 0., 0., 2.])
    """
    first = check_flag(scalar_first, "scalar_first")
    quaternions = _as_quaternions(q, "q")
    exponents = as_float_array(t, "t")
    if quaternions.ndim == 1 and exponents.ndim == 0:
        one, power = _one(quaternions, first), float(exponents)
        if one is not None and any(one):
            exponent = math.frexp(max(abs(value) for value in one))[1]
            if abs(power) <= 250.0 and abs(power * exponent) <= 250.0:  # |q|^t is moderate
                return _stored_one(power_one(one, power), first)
    lead = quaternions.shape[:-1]
    shape = broadcast_shape({"q": lead, "t": exponents.shape})
    flat_q, flat_t = quaternions.reshape(-1, 4), exponents.reshape(-1)
    out = np.empty((math.prod(shape), 4))
    for block, (on_q, on_t) in broadcast_blocks(shape, (lead, exponents.shape)):
        rows = _rows(flat_q[on_q], first)
        _refuse_zero(rows, "q", lead, on_q, "0 has no power of every exponent")
        _write(out[block], powers(rows, flat_t[on_t]), first)
    return out.reshape(*shape, 4)
