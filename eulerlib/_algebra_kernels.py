"""The algebra of quaternions on one block of checked values: product, inverse, exp, log, power.

Nothing here checks its input: :mod:`eulerlib.quaternion_algebra` did that once. Quaternions are
held as four rows ``(w, x, y, z)`` of a block, shape ``(4, n)``, so that every step is an
element-wise operation on a few thousand quaternions at once. The quaternions may have any
length; lengths and directions are taken after scaling by a power of two
(:mod:`eulerlib._length_kernels`), which is exact, so that neither huge nor tiny quaternions
overflow or lose digits on the way.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from eulerlib._length_kernels import (
    TINY,
    binary_exponents,
    lengths,
    out_of_range,
    squared_lengths,
)

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
    0, or documents the choice (the logarithm of a negative real number). Where every squared
    length lies well inside float64's range, the columns are divided by their lengths at once;
    otherwise each is first scaled by a power of two, exactly, so that nothing overflows or
    underflows.
    """
    squared = squared_lengths(v)
    if not out_of_range(squared).size:  # the usual case: every length far from 0 and overflow
        length: Array = np.sqrt(squared)
        return v / length, length
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


#: Veltkamp's splitter for float64: ``t = hi + lo`` with ``hi`` of 26 significant bits.
_SPLITTER = 2.0**27 + 1.0


def powers_of_two(exponent: NDArray[np.int32], t: Array) -> Array:
    """``2**(e t)`` for integers ``|e| < 2**11``, without rounding the product ``e t`` first.

    Rounding ``e t`` would cost up to ``|e t| ln 2`` units in the last place (a hundred for
    ``|q| = 1e300``, ``t = 0.3``). ``t`` is split into ``hi + lo`` of 26 and 27 bits (Veltkamp),
    so that ``e hi`` and ``e lo`` are exact; ``e hi = n + f`` with ``n`` an integer, and
    ``2**(e t) = 2**n · 2**(f + e lo)`` is one ``exp2`` of a number below 1 and an exact
    scaling.
    """
    with np.errstate(over="ignore", invalid="ignore"):
        big = _SPLITTER * t
        high = big - (big - t)
        high = np.where(np.isfinite(high), high, t)  # |t| beyond 1e300: |q|^t is 0 or inf
        product = exponent * high
        whole = np.round(product)
        fraction = (product - whole) + exponent * (t - high)
        whole = np.clip(whole, -4096, 4096)  # beyond float64's range either way
        result: Array = np.ldexp(np.exp2(fraction), whole.astype(np.int32))
    return result


def powers(q: Array, t: Array) -> Array:
    """``q^t = exp(t log q) = |q|^t (cos tθ, sin tθ v / |v|)`` of nonzero quaternions."""
    mantissa, exponent, angle, unit = polar_forms(q)
    turn = angle * t
    out = np.empty_like(q)
    np.cos(turn, out=out[0])
    np.multiply(unit, np.sin(turn), out=out[1:])
    with np.errstate(over="ignore", under="ignore"):  # |q|^t beyond float64's range
        out *= np.power(mantissa, t) * powers_of_two(exponent, t)
    return out


# --- one quaternion at a time ---------------------------------------------------------------------
#
# A call on one quaternion spends most of its time in numpy's per-call overhead, a few
# microseconds for each of the thirty-odd operations above. The functions below compute the same
# formulas, in the same order, on four Python floats (``(w, x, y, z)``), so that one quaternion
# costs a few microseconds. The arithmetic is bit for bit that of the block functions; the sines,
# cosines and logarithms come from the C library instead of numpy's loops and may differ from
# them in the last bit. The caller uses them only where no intermediate can overflow:
# :func:`moderate` says when.

Quad = tuple[float, float, float, float]

#: Components below 2**-500 or above 2**500 take the block functions, which handle the edges of
#: float64's range as numpy does; between them no square and no inverse overflows.
_LIMIT = 2.0**500
_SMALL, _LARGE = 2.0**-1000, 2.0**1000  # as in eulerlib._length_kernels


def moderate(values: list[float]) -> bool:
    """True when every nonzero ``|value|`` lies within [2**-500, 2**500]."""
    return all(value == 0.0 or 1.0 / _LIMIT <= abs(value) <= _LIMIT for value in values)


def product_one(p: Quad, q: Quad) -> Quad:
    """:func:`hamilton_product` of one pair."""
    pw, px, py, pz = p
    qw, qx, qy, qz = q
    w = pw * qw
    w -= px * qx
    w -= py * qy
    w -= pz * qz
    x = pw * qx
    x += px * qw
    x += py * qz
    x -= pz * qy
    y = pw * qy
    y -= px * qz
    y += py * qw
    y += pz * qx
    z = pw * qz
    z += px * qy
    z -= py * qx
    z += pz * qw
    return w, x, y, z


def _scaled_one(values: tuple[float, ...]) -> tuple[list[float], int]:
    exponent = math.frexp(max(abs(value) for value in values))[1]
    return [math.ldexp(value, -exponent) for value in values], exponent


def _squared_one(values: list[float]) -> float:
    total = values[0] * values[0]
    for value in values[1:]:
        total += value * value
    return total


def _length_one(values: list[float]) -> float:
    """:func:`eulerlib._length_kernels.lengths` of one vector, step by step."""
    squared = _squared_one(values)
    if _SMALL <= squared <= _LARGE:
        return math.sqrt(squared)
    part, exponent = _scaled_one(tuple(values))
    return math.ldexp(math.sqrt(_squared_one(part)), exponent)


def inverse_one(q: Quad) -> Quad:
    """:func:`inverses` of one nonzero quaternion."""
    part, exponent = _scaled_one(q)
    factor = 1.0 / _squared_one(part)
    w, x, y, z = (math.ldexp(value * factor, -exponent) for value in part)
    return w, -x, -y, -z


def _direction_one(v: list[float]) -> tuple[list[float], float]:
    """:func:`directions` of one vector: its unit vector (``(1, 0, 0)`` for 0) and length."""
    length = _length_one(v)
    if length == 0.0:
        return [1.0, 0.0, 0.0], 0.0
    part, _ = _scaled_one(tuple(v))
    size = math.sqrt(_squared_one(part))
    return [value / size for value in part], length


def exp_one(scalar: float, v: list[float]) -> Quad:
    """:func:`exponentials` of one quaternion ``scalar + v``."""
    unit, angle = _direction_one(v)
    sine = math.sin(angle)
    factor = math.exp(scalar)
    return (
        math.cos(angle) * factor,
        unit[0] * sine * factor,
        unit[1] * sine * factor,
        unit[2] * sine * factor,
    )


def _polar_one(q: Quad) -> tuple[float, int, float, list[float]]:
    part, exponent = _scaled_one(q)
    unit, sine = _direction_one(part[1:])
    return _length_one(part), exponent, math.atan2(sine, part[0]), unit


def log_one(q: Quad) -> Quad:
    """:func:`logarithms` of one nonzero quaternion."""
    mantissa, exponent, angle, unit = _polar_one(q)
    scalar = math.log(mantissa)
    scalar += exponent * _LN2
    return scalar, unit[0] * angle, unit[1] * angle, unit[2] * angle


def power_one(q: Quad, t: float) -> Quad:
    """:func:`powers` of one nonzero quaternion; ``|t|`` and ``|t e|`` at most 500."""
    mantissa, exponent, angle, unit = _polar_one(q)
    turn = angle * t
    sine = math.sin(turn)
    big = _SPLITTER * t
    high = big - (big - t)
    product = exponent * high
    whole = round(product)
    fraction = (product - whole) + exponent * (t - high)
    factor = mantissa**t * math.ldexp(2.0**fraction, whole)
    return (
        math.cos(turn) * factor,
        unit[0] * sine * factor,
        unit[1] * sine * factor,
        unit[2] * sine * factor,
    )


def matrix_one(q: Quad) -> list[float]:
    """The nine entries of the rotation matrix of one quaternion of moderate size, row by row:
    the formulas of :func:`eulerlib._quaternion_kernels.quaternions_to_entries`, in its order."""
    w, x, y, z = q
    ww, xx, yy, zz = w * w, x * x, y * y, z * z
    a, b = ww - zz, xx - yy
    ww += zz
    xx += yy
    r = 1.0 / (ww + xx)
    e = [0.0] * 9
    e[0], e[4], e[8] = (a + b) * r, (a - b) * r, (ww - xx) * r
    r += r
    xs, ys, zs = x * r, y * r, z * r
    wx, wy, wz = w * xs, w * ys, w * zs
    for first, second, with_w, minus, plus in (
        (xs, y, wz, 1, 3),
        (xs, z, wy, 6, 2),
        (ys, z, wx, 5, 7),
    ):
        t = first * second + 0.0
        e[minus] = t - with_w
        e[plus] = t + with_w
    return e
