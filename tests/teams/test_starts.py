"""Where a team starts: robot 0 at the single robot's start, the others apart, the base outside."""

from __future__ import annotations

import math

import numpy as np
import pytest
from team_buildings import rooms_in_a_row

from realistic_indoor.building import Building, Door, Room
from realistic_indoor.errors import ConfigError
from realistic_indoor.sim import World
from realistic_indoor.teams.starts import base_station, start_poses

RADIUS_M, SPACING_M = 0.25, 0.2


@pytest.mark.parametrize("n", [1, 4, 8])
def test_start_poses__robot_0_at_the_world_start_and_every_robot_apart_clear_and_reachable(n):
    world = World(rooms_in_a_row(4))
    poses = np.array(start_poses(world, n, RADIUS_M, SPACING_M))
    assert tuple(poses[0]) == world.start_pose and len(poses) == n
    gaps = [math.dist(a, b) for i, a in enumerate(poses[:, :2]) for b in poses[i + 1 :, :2]]
    assert min(gaps, default=np.inf) >= 2 * RADIUS_M + SPACING_M - 1e-9
    assert world.is_clear(poses[:, :2], world.config.start_clearance_m).all()
    assert (poses[:, 2] == world.start_pose[2]).all()


def test_start_poses__refused_where_the_building_has_no_room():
    """A 1.4 m x 1 m lobby: one robot fits 0.4 m clear of its walls, two 0.7 m apart do not."""
    lobby = Building(
        "office",
        (Room.rectangle("lobby", "hall", "lobby", (0.0, 0.0, 1.4, 1.0)),),
        (Door("entrance", "lobby", None, 0.0, 0.5, 0.8, math.pi / 2),),
        {"generator": "team tests"},
    )
    world = World(lobby)
    assert len(start_poses(world, 1, RADIUS_M, SPACING_M)) == 1
    with pytest.raises(ConfigError, match="no room for 2 robots"):
        start_poses(world, 2, RADIUS_M, SPACING_M)


def test_base_station__stands_outside_the_entrance():
    world = World(rooms_in_a_row(4))  # entrance at x = 0, y = 5, robot 0 facing +x
    assert base_station(world, 0.5) == pytest.approx((-0.5, 5.0))
