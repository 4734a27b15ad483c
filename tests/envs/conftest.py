"""Fixtures of the environment tests: toy buildings that are small, exact and fast."""

from __future__ import annotations

import numpy as np
import pytest
from env_helpers import ToyOffice

from realistic_indoor.building import Building


@pytest.fixture
def toy_building() -> Building:
    """One fixed small office."""
    return ToyOffice(jitter_m=0.0)(np.random.default_rng(0))
