"""The algebra of quaternions on one block of checked values: product, inverse, exp, log, power.

Nothing here checks its input: :mod:`eulerlib.quaternion_algebra` did that once. Quaternions are
held as four rows ``(w, x, y, z)`` of a block, shape ``(4, n)``, so that every step is an
element-wise operation on a few thousand quaternions at once. The quaternions may have any
length; lengths and directions are taken after scaling by a power of two
(:mod:`eulerlib._length_kernels`), which is exact, so that neither huge nor tiny quaternions
overflow or lose digits on the way.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from eulerlib._length_kernels import TINY, binary_exponents, lengths, squared_lengths

Array = NDArray[np.float64]

_LN2 = float(np.log(2.0))


def hamilton_product(p: Array, q: Array, out: Array) -> None:
    """Write into ``out`` (shape ``(4, n)``) the Hamilton products ``p q``, term by term.

    With ``i² = j² = k² = ijk = −1`` (so ``ij = k``, ``jk = i``, ``ki = j``)::

        w = pw qw − px qx − py qy − pz qz
        x = pw qx + px qw + py qz − pz qy
        y = pw qy − px qz + py qw + pz qx
        z = pw qz + px qy − py qx + pz qw
    """
    pw, px, py, pz = p
    qw, qx, qy, qz = q
    np.multiply(pw, qw, out=out[0])
    out[0] -= px * qx
    out[0] -= py * qy
    out[0] -= pz * qz
    np.multiply(pw, qx, out=out[1])
    out[1] += px * qw
    out[1] += py * qz
    out[1] -= pz * qy
    np.multiply(pw, qy, out=out[2])
    out[2] -= px * qz
    out[2] += py * qw
    out[2] += pz * qx
    np.multiply(pw, qz, out=out[3])
    out[3] += px * qy
    out[3] -= py * qx
    out[3] += pz * qw


def scaled(q: Array) -> tuple[Array, NDArray[np.int32]]:
    """Each column times the power of two ``2**-e`` that puts its largest entry in [0.5, 1),
    and ``e`` (0 for a zero column): ``q = scaled · 2**e`` exactly."""
    exponent = binary_exponents(q)
    return np.ldexp(q, -exponent), exponent


def inverses(q: Array) -> Array:
    """``q⁻¹ = q* / |q|²`` of nonzero quaternions, computed on ``q / 2**e`` and scaled back, so
    that ``|q|²`` neither overflows nor underflows."""
    part, exponent = scaled(q)
    factor = 1.0 / squared_lengths(part)
    result = part * factor
    result[1:] *= -1.0
    with np.errstate(over="ignore", under="ignore"):  # an inverse beyond float64's range
        inverse: Array = np.ldexp(result, -exponent)
    return inverse


def directions(v: Array) -> tuple[Array, Array]:
    """Unit vectors of the columns of ``v`` (shape ``(3, n)``) and their lengths, at any scale.

    The direction of a zero column is ``(1, 0, 0)``; whoever uses it multiplies it by a sine of
    0, or documents the choice (the logarithm of a negative real number).
    """
    part, _ = scaled(v)
    unit: Array = part / np.maximum(np.sqrt(squared_lengths(part)), TINY)
    length = lengths(v)
    unit[0, length == 0.0] = 1.0
    return unit, length


def exponentials(scalar: Array | None, v: Array) -> Array:
    """``exp(a + v) = e^a (cos |v|, sin |v| v / |v|)`` of each column, shape ``(4, n)``.

    ``scalar`` holds the scalar parts ``a`` (``None`` for pure quaternions, ``a = 0``), ``v`` the
    vector parts, shape ``(3, n)``.
    """
    unit, angle = directions(v)
    out = np.empty((4, v.shape[1]))
    np.cos(angle, out=out[0])
    np.multiply(unit, np.sin(angle), out=out[1:])
    if scalar is not None:
        with np.errstate(over="ignore"):  # e^a beyond float64's range is infinite
            out *= np.exp(scalar)
    return out


def polar_forms(q: Array) -> tuple[Array, NDArray[np.int32], Array, Array]:
    """The polar form ``q = |q| (cos θ, sin θ v / |v|)`` of nonzero quaternions: ``|q|`` as
    ``m 2**e`` (``m`` in [0.5, 2), ``e`` an integer, so that no length is subnormal or
    infinite), the angle ``θ = atan2(|v|, w)`` in [0, π] and the unit vector ``v / |v|``.

    The whole quaternion is scaled by ``2**-e`` first, which is exact, so ``|v|`` and ``w`` keep
    all their digits even when the quaternion is tiny; the angle comes from ``atan2`` of the two
    parts, never from ``acos(w / |q|)``, so it is accurate to a few units in the last place near
    0 and near π alike.
    """
    part, exponent = scaled(q)
    unit, sine = directions(part[1:])
    angle: Array = np.arctan2(sine, part[0])
    return lengths(part), exponent, angle, unit


def logarithms(q: Array) -> Array:
    """``log q = (ln |q|, θ v / |v|)`` of nonzero quaternions, shape ``(4, n)``."""
    mantissa, exponent, angle, unit = polar_forms(q)
    out = np.empty_like(q)
    np.log(mantissa, out=out[0])
    out[0] += exponent * _LN2
    np.multiply(unit, angle, out=out[1:])
    return out


def powers(q: Array, t: Array) -> Array:
    """``q^t = exp(t log q) = |q|^t (cos tθ, sin tθ v / |v|)`` of nonzero quaternions."""
    mantissa, exponent, angle, unit = polar_forms(q)
    turn = angle * t
    out = np.empty_like(q)
    np.cos(turn, out=out[0])
    np.multiply(unit, np.sin(turn), out=out[1:])
    with np.errstate(over="ignore", under="ignore"):  # |q|^t beyond float64's range
        out *= np.power(mantissa, t) * np.exp2(exponent * t)
    return out
