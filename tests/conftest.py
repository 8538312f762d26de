"""Shared fixtures of the unit tests."""

import numpy as np
import pytest


@pytest.fixture
def rng() -> np.random.Generator:
    """A seeded generator, so every failure can be replayed."""
    return np.random.default_rng(20150214)
