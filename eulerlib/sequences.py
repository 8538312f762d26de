"""Axis sequences: the 24 ways to name an Euler-angle convention with three letters.

A sequence is three letters from ``x``, ``y``, ``z`` with no two neighbours alike, read exactly
as SciPy's :meth:`scipy.spatial.transform.Rotation.from_euler` reads them:

* **uppercase** (``"ZYX"``) means *intrinsic* rotations: each one turns about an axis of the
  body, which has already been moved by the rotations before it;
* **lowercase** (``"xyz"``) means *extrinsic* rotations: each one turns about an axis of the
  fixed reference frame;
* angle ``i`` goes with letter ``i``.

Six sequences use three different axes (Tait–Bryan: ``XYZ``, ``XZY``, ``YXZ``, ``YZX``,
``ZXY``, ``ZYX``), six repeat the first axis at the end (proper Euler: ``XYX``, ``XZX``,
``YXY``, ``YZY``, ``ZXZ``, ``ZYZ``), and each comes in both cases: 24 conventions.

An intrinsic sequence and the reversed extrinsic sequence with the angles reversed describe
the same rotation: ``"ZYX"`` with ``(yaw, pitch, roll)`` equals ``"xyz"`` with
``(roll, pitch, yaw)``. eulerlib uses that fact everywhere, so that both spellings of a
convention give identical numbers.
"""

from eulerlib._sequences import (
    ALL_SEQUENCES,
    PROPER_EULER,
    TAIT_BRYAN,
    Sequence,
    parse_axis,
    parse_sequence,
    sequence_problem,
)

__all__ = [
    "ALL_SEQUENCES",
    "PROPER_EULER",
    "TAIT_BRYAN",
    "Sequence",
    "parse_axis",
    "parse_sequence",
    "sequence_problem",
]
