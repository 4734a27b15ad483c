"""Fixtures shared by every test folder."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared"
REAL_PLANS = SHARED / "data" / "real_floorplans"
REQUIRE_SHARED = os.environ.get("REALISTIC_INDOOR_REQUIRE_SHARED") == "1"
"""Set by ``.ci/run``: a test that needs ``../shared`` fails where it is missing instead of skipping."""


def missing_shared(reason: str) -> None:
    """Skip the test for want of the shared data, or fail it where CI requires the data."""
    if REQUIRE_SHARED:
        pytest.fail(f"{reason}; REALISTIC_INDOOR_REQUIRE_SHARED=1 requires it", pytrace=False)
    pytest.skip(reason)


@pytest.fixture(scope="session")
def shared_dir() -> Path:
    """``../shared`` beside the project; tests that need it skip where it is absent (fail in CI)."""
    if not SHARED.is_dir():
        missing_shared(f"shared data not found at {SHARED} (tests of real plans need ../shared)")
    return SHARED


@pytest.fixture(scope="session")
def real_plans_dir(shared_dir: Path) -> Path:
    """The folder of real floor plans (``office/`` and ``school/`` XML files)."""
    path = shared_dir / "data" / "real_floorplans"
    if not path.is_dir():
        missing_shared(f"real floor plans not found at {path}")
    return path


@pytest.fixture
def tiny_office():
    """A hand-made office: a corridor with two offices and an entrance; statistics known exactly."""
    import math

    from realistic_indoor.building import Building, Door, Room

    rooms = (
        Room.rectangle("c", "corridor", "corridor", (0, 0, 10, 2)),
        Room.rectangle("a", "medium", "office", (0, 2, 5, 6)),
        Room.rectangle("b", "medium", "office", (5, 2, 10, 6)),
    )
    doors = (
        Door("d1", "a", "c", 2.5, 2.0, 0.9, 0.0),
        Door("d2", "b", "c", 7.5, 2.0, 0.9, 0.0),
        Door("e1", "c", None, 0.0, 1.0, 1.2, math.pi / 2),
    )
    return Building("office", rooms, doors, {"generator": "hand-made"})
