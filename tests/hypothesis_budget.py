"""How many examples a Hypothesis test draws: a quick share in the README's test command, all in CI.

Each property test states the number of examples it is meant to draw, ``examples(200)``. Under
Hypothesis' usual settings (the ``thorough`` profile, 100 examples for a test that states none)
that is what it draws. The README's test command loads the ``quick`` profile instead (see
``conftest.py``): a quarter of each number, and never fewer than :data:`FLOOR`, so that the
command stays within its time budget on two cores. CI runs every property test again with
``--hypothesis-profile=thorough`` in a step of its own, so no example is dropped from what
lands; only the quick local run is lighter.

The share follows the loaded profile: ``max_examples`` of the active settings over Hypothesis'
default of 100. Test modules call :func:`examples` when they are imported, which is after
pytest has loaded the profile.
"""

from __future__ import annotations

from hypothesis import settings

#: Hypothesis' own default number of examples, the scale the stated numbers are written in.
USUAL = 100
#: The fewest examples a property test draws in the quick profile.
FLOOR = 10


def examples(stated: int) -> int:
    """The examples to draw for a test written for ``stated`` examples under the active profile."""
    share = stated * settings.default.max_examples // USUAL
    return max(FLOOR, share) if share < stated else stated
