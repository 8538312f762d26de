"""How much the README's test command tries: a quick share of examples and cases; CI runs all.

Each property test states the number of examples it is meant to draw, ``examples(200)``. Under
Hypothesis' usual settings (the ``thorough`` profile, 100 examples for a test that states none)
that is what it draws. The README's test command loads the ``quick`` profile instead (see
``conftest.py``): a quarter of each number, and never fewer than :data:`FLOOR`, so that the
command stays within its time budget on two cores. CI runs every property test again with
``--hypothesis-profile=thorough`` in a step of its own, so no example is dropped from what
lands; only the quick local run is lighter.

The same holds for the slowest sweeps over every Euler sequence (SymPy derivations, one per
sequence): under the quick profile :func:`sweep` keeps a fixed spread of the sequences, Tait–Bryan
and proper Euler, intrinsic and extrinsic, even and odd orders among them; CI runs them all.

The share follows the loaded profile: ``max_examples`` of the active settings over Hypothesis'
default of 100. Test modules call :func:`examples` when they are imported, which is after
pytest has loaded the profile.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TypeVar

from hypothesis import settings

T = TypeVar("T")

#: Hypothesis' own default number of examples, the scale the stated numbers are written in.
USUAL = 100
#: The fewest examples a property test draws in the quick profile.
FLOOR = 10


def examples(stated: int) -> int:
    """The examples to draw for a test written for ``stated`` examples under the active profile."""
    share = stated * settings.default.max_examples // USUAL
    return max(FLOOR, share) if share < stated else stated


def thorough() -> bool:
    """True under Hypothesis' usual settings (CI's run), False under the README's quick profile."""
    return settings.default.max_examples >= USUAL


def sweep(items: Sequence[T]) -> list[T]:
    """All ``items`` in a thorough run; in a quick one every fifth, from the first and the third.

    Over :data:`eulerlib.ALL_SEQUENCES` the quick share is XYZ, YXZ, ZYX, XZX, ZXZ, xyz, yzx,
    zyx, yxy and zxz.
    """
    if thorough():
        return list(items)
    keep = set(range(0, len(items), 5)) | set(range(2, len(items), 5))
    return [item for index, item in enumerate(items) if index in keep]
