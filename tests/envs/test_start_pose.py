"""info["start_pose"] at reset: where the robot starts, by the documented rule."""

from __future__ import annotations

import math

import numpy as np
import pytest
from env_helpers import make_env
from shapely.geometry import Point

from realistic_indoor.building import Building, Door, Room
from realistic_indoor.envs import ExploreEnv
from realistic_indoor.envs.search import SearchEnv


def _inside(building: Building, pose: tuple[float, float, float]) -> bool:
    return any(room.polygon.contains(Point(pose[0], pose[1])) for room in building.rooms)


def test_start_pose__is_just_inside_the_entrance_facing_inward(toy_building):
    env = ExploreEnv(building=toy_building)
    _, info = env.reset(seed=0)
    x, y, heading = info["start_pose"]
    assert info["start_pose"] == env.simulation.robot.pose  # where the robot stands after reset
    # The entrance is in the west wall at (0, 5): the start is on its centre line, 0.3 m or more
    # inward (0.4 m clear of walls), in the corridor, facing +x.
    assert y == pytest.approx(5.0) and 0.3 <= x < 1.0 and heading == pytest.approx(0.0)
    assert toy_building.room_by_id["c"].polygon.contains(Point(x, y))
    assert all(isinstance(v, float) for v in info["start_pose"])


def test_start_pose__is_the_same_after_every_reset_of_a_fixed_building(toy_building):
    env = SearchEnv(building=toy_building)
    _, first = env.reset(seed=0)
    for _ in range(5):
        env.step(np.array([1.0, 0.5], np.float32))
    _, again = env.reset(seed=1)
    assert again["start_pose"] == first["start_pose"] == env.simulation.robot.pose


def _no_entrance(hall_box: tuple[float, float, float, float], room_label: str = "hall") -> Building:
    """A hall (or a room) west of a bigger office, one door between them, no exterior door."""
    rooms = (
        Room.rectangle("h", room_label, room_label, hall_box),
        Room.rectangle("o", "big", "office", (4.0, 0.0, 12.0, 4.0)),
    )
    return Building("office", rooms, (Door("d", "h", "o", 4.0, 2.0, 0.9, math.pi / 2),))


def test_start_pose__without_an_entrance_is_the_centre_of_the_largest_hall():
    building = _no_entrance((0.0, 0.0, 4.0, 4.0))  # the 16 m2 hall, though the office has 32 m2
    env = ExploreEnv(building=building)
    _, info = env.reset(seed=0)
    assert info["start_pose"] == pytest.approx((2.0, 2.0, 0.0))
    assert info["start_pose"] == env.simulation.robot.pose


def test_start_pose__without_an_entrance_or_hall_is_the_centre_of_the_largest_room():
    building = _no_entrance((0.0, 0.0, 4.0, 4.0), room_label="medium")
    _, info = ExploreEnv(building=building).reset(seed=0)
    assert info["start_pose"] == pytest.approx((8.0, 2.0, 0.0))  # the office's centroid


def test_start_pose__off_centre_hall_is_its_point_farthest_from_walls():
    # An L-shaped hall, arms 2 m wide: its centroid (2.2, 2.2) lies outside it. The point
    # farthest from its walls is on the diagonal at a = 2 sqrt(2) / (1 + sqrt(2)) = 1.17 m,
    # as far from the outer walls (a) as from the inner corner (sqrt(2) (2 - a)).
    outline = ((0.0, 0.0), (6.0, 0.0), (6.0, 2.0), (2.0, 2.0), (2.0, 6.0), (0.0, 6.0))
    building = Building("office", (Room("h", "hall", "hall", outline),), ())
    _, info = ExploreEnv(building=building).reset(seed=0)
    a = 2 * math.sqrt(2) / (1 + math.sqrt(2))
    x, y, heading = info["start_pose"]
    assert x == pytest.approx(a, abs=0.06) and y == pytest.approx(a, abs=0.06) and heading == 0.0


def _two_parts(entrances: bool) -> Building:
    """A 5 m square hall alone (25 m2), and a 4 m square hall with a 7 m x 4 m office beyond it
    (44 m2), no door between the two parts; with ``entrances``, one in each, the lone hall's
    listed first (at (0, 2.5); the other at (8, 0))."""
    rooms = (
        Room.rectangle("a", "hall", "lobby", (0.0, 0.0, 5.0, 5.0)),
        Room.rectangle("h", "hall", "lobby", (6.0, 0.0, 10.0, 4.0)),
        Room.rectangle("o", "big", "office", (10.0, 0.0, 17.0, 4.0)),
    )
    doors = [Door("ho", "h", "o", 10.0, 2.0, 0.9, math.pi / 2)]
    if entrances:
        doors = [
            Door("ea", "a", None, 0.0, 2.5, 1.2, math.pi / 2),
            Door("eh", "h", None, 8.0, 0.0, 1.2, 0.0),
            *doors,
        ]
    return Building("office", rooms, tuple(doors))


def test_start_pose__is_at_an_entrance_of_the_part_holding_the_most_floor():
    building = _two_parts(entrances=True)
    x, y, heading = ExploreEnv(building=building).reset(seed=0)[1]["start_pose"]
    # not at the first entrance, into the lone hall: at the other, on its centre line x = 8,
    # just inside the south wall, facing north
    assert x == pytest.approx(8.0) and 0.3 <= y < 1.0 and heading == pytest.approx(math.pi / 2)


def test_start_pose__without_an_entrance_is_in_the_largest_hall_of_the_part_holding_the_most_floor():
    # not the centre of the largest hall (the lone one, 25 m2): of the 16 m2 hall by the office
    _, info = ExploreEnv(building=_two_parts(entrances=False)).reset(seed=0)
    assert info["start_pose"] == pytest.approx((8.0, 2.0, 0.0))


@pytest.mark.parametrize("env_id", ["OfficeExplore-v0", "HouseSearch-v0"])
def test_start_pose__of_generated_buildings_is_inside_and_where_the_robot_is(env_id):
    env = make_env(env_id)
    for seed in (0, 1):
        _, info = env.reset(seed=seed)
        sim = env.unwrapped.simulation
        assert _inside(env.unwrapped.building, info["start_pose"])
        assert info["start_pose"] == sim.robot.pose
        assert sim.world.clearance_at(info["start_pose"][:2]) >= env.unwrapped.config.world.start_clearance_m
    env.close()
