"""Openings in a laser scan: doorways are found, walls seen at a grazing angle are not."""

from __future__ import annotations

import math

import numpy as np
import pytest
from agent_helpers import empty_room, vestibule

from realistic_indoor.agents.openings import find_openings
from realistic_indoor.sim import Lidar, World

MIN_WIDTH_M = 0.6


def _scan(building, pose: tuple[float, float, float]) -> tuple[np.ndarray, np.ndarray, float]:
    """Ranges (with the simulator's noise), beam directions and range of a scan taken at ``pose``."""
    lidar = Lidar()
    scan = lidar.scan(World(building).raycaster, pose, np.random.default_rng(0))
    return scan.ranges_m.astype(float), lidar.offsets_rad, lidar.config.max_range_m


def test_find_openings__sees_the_door_of_a_small_room_and_nothing_else():
    # just inside the vestibule's entrance, facing north: the 0.9 m door centred at (3.35, 4.0)
    # lies 4.0 - 0.45 = 3.55 m ahead and 3.35 - 2.0 = 1.35 m to the right
    openings = find_openings(*_scan(vestibule(), (2.0, 0.45, math.pi / 2)), MIN_WIDTH_M)
    assert len(openings) == 1
    door = openings[0]
    assert np.allclose(door.middle, (3.55, -1.35), atol=0.1)
    assert door.width_m == pytest.approx(0.9, abs=0.1)
    assert np.allclose(door.normal, (1.0, 0.0), atol=0.1)  # across the door, away from the robot
    assert not door.seen_beyond  # the room behind reaches 11.55 m away: beyond the 10 m laser


@pytest.mark.parametrize(
    "pose",
    [(0.7, 0.7, 0.0), (19.3, 19.2, 2.5), (10.0, 0.7, math.pi / 4), (3.0, 1.0, -0.1)],
    ids=["corner, along a wall", "corner, diagonal", "wall, 45 degrees", "near a wall, along it"],
)
def test_find_openings__a_wall_seen_at_a_grazing_angle_is_no_opening(pose):
    # in a closed 20 m room far walls are seen at grazing angles (ranges growing fast from
    # beam to beam) and beyond the laser's range (no return): no gap between two wall ends
    assert find_openings(*_scan(empty_room(20.0), pose), MIN_WIDTH_M) == []
