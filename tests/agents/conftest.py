"""Fixtures of the agents' tests."""

from __future__ import annotations

import pytest
from agent_helpers import hall_and_corridor

import realistic_indoor.envs  # noqa: F401 - registers the ids
from realistic_indoor.building import Building


@pytest.fixture(scope="session")
def hall_office() -> Building:
    """A hall, a corridor and six rooms: about 140 m2."""
    return hall_and_corridor(3)
