"""Buildings and helpers shared by the tests of the 3D world exports."""

from __future__ import annotations

import math

import numpy as np
import pytest

import realistic_indoor as ri
from realistic_indoor.building import Building, Door, Room

THICKNESS_M = 0.1


@pytest.fixture(scope="session")
def office() -> Building:
    """A generated office, small enough for a fine raster."""
    return ri.generate("office", area_m2=800, seed=7)


@pytest.fixture(scope="session")
def slanted() -> Building:
    """Two rooms split by a slanted wall with a door in it, and an entrance on the left."""
    a = Room("a", "medium", "office", ((0, 0), (4, 0), (6, 4), (0, 4)))
    b = Room("b", "big", "lab", ((4, 0), (10, 0), (10, 4), (6, 4)))
    doors = (
        Door("d1", "a", "b", 5.0, 2.0, 0.9, math.atan2(4, 2)),
        Door("e1", "a", None, 0.0, 2.0, 1.2, math.pi / 2),
    )
    return Building("office", (a, b), doors, {"generator": "hand-made", "name": "slanted"})


def _box_segments(centres, lengths, yaws, thickness: float) -> np.ndarray:
    """The plan segments of wall boxes, ``(N, 2, 2)``: each box's centre line less its square caps."""
    half = (np.asarray(lengths) - thickness) / 2
    u = np.column_stack([np.cos(yaws), np.sin(yaws)]) * half[:, None]
    c = np.asarray(centres)[:, :2]
    return np.stack([c - u, c + u], axis=1)


@pytest.fixture(scope="session")
def box_segments():
    """``box_segments(centres, lengths, yaws, thickness)``: wall boxes back to plan segments."""
    return _box_segments
