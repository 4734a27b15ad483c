"""Fixtures of the simulator's tests."""

from __future__ import annotations

import numpy as np
import pytest
from sim_buildings import corridor_office

from realistic_indoor.building import Building


@pytest.fixture(scope="session")
def office() -> Building:
    """A 2-wing corridor office of about 600 m2."""
    return corridor_office(n_rooms=5, n_wings=2)


@pytest.fixture
def rng() -> np.random.Generator:
    return np.random.default_rng(12345)
