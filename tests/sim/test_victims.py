import math

import numpy as np
import pytest
import shapely

from realistic_indoor.building import ROOM_LABELS, Building, Room
from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.victims import VictimConfig, VictimSensor, place_victims, relative_polar
from realistic_indoor.sim.world import World


@pytest.fixture
def office_world(office):
    return World(office)


def _room_of(building, p):
    return next(r for r in building.rooms if r.polygon.contains(shapely.Point(p)))


def test_place_victims__in_ordinary_rooms_clear_of_walls(office_world, rng):
    victims = place_victims(office_world, rng, VictimConfig(n_victims=50, min_clearance_m=0.4))
    assert victims.shape == (50, 2)
    assert all(_room_of(office_world.building, p).label in ROOM_LABELS for p in victims)
    assert office_world.clearance_at(victims).min() >= 0.4
    row, col = office_world.raster.world_to_cell(victims)
    assert office_world.reachable[row, col].all()


def test_place_victims__same_seed_same_places(office_world):
    a = place_victims(office_world, np.random.default_rng(5))
    b = place_victims(office_world, np.random.default_rng(5))
    c = place_victims(office_world, np.random.default_rng(6))
    assert a.tobytes() == b.tobytes() and a.tobytes() != c.tobytes()


def test_place_victims__rooms_are_chosen_by_area(rng):
    rooms = (
        Room.rectangle("small", "small", "storage", (0, 0, 3, 3)),
        Room.rectangle("big", "big", "office", (3, 0, 12, 9)),
    )
    world = World(Building("office", rooms, ()), start_pose=(7.5, 4.5, 0.0))
    # the small room is cut off from the start: it is not reachable, no victim goes there
    victims = place_victims(world, rng, VictimConfig(n_victims=200))
    assert all(_room_of(world.building, p).id == "big" for p in victims)
    spread = np.ptp(victims, axis=0)
    assert spread.min() > 7.0  # spread over the room


def test_place_victims__functional_filter(rng):
    rooms = (
        Room.rectangle("c", "corridor", "corridor", (0, 0, 12, 2)),
        Room.rectangle("o", "medium", "office", (0, 2, 6, 6)),
        Room.rectangle("t", "small", "toilet", (6, 2, 12, 6)),
    )
    from realistic_indoor.building import Door

    doors = (Door("d1", "o", "c", 3.0, 2.0), Door("d2", "t", "c", 9.0, 2.0))
    world = World(Building("office", rooms, doors), start_pose=(1.0, 1.0, 0.0))
    victims = place_victims(world, rng, VictimConfig(n_victims=30, functions=("Toilet",)))
    assert all(_room_of(world.building, p).id == "t" for p in victims)
    with pytest.raises(ConfigError, match="no room can hold victims"):
        place_victims(world, rng, VictimConfig(functions=("classroom",)))
    corridor_only = VictimConfig(n_victims=5, labels=("corridor",))
    assert all(_room_of(world.building, p).id == "c" for p in place_victims(world, rng, corridor_only))


def test_place_victims__no_room_clear_enough_raises(office_world, rng):
    with pytest.raises(ConfigError, match="min_clearance_m"):
        place_victims(office_world, rng, VictimConfig(min_clearance_m=3.0))


def test_victim_sensor__sees_within_range_field_of_view_and_line_of_sight(tiny_office):
    world = World(tiny_office)
    sensor = VictimSensor(VictimConfig(sensor_range_m=3.0, sensor_fov_rad=math.radians(90)))
    victims = np.array(
        [
            (2.5, 4.5),  # 1.5 m ahead
            (2.5, 5.8),  # 2.8 m ahead
            (4.0, 4.0),  # 1.8 m away, 56 degrees right: outside the 90-degree field
            (7.5, 4.0),  # behind the wall between rooms a and b
            (2.5, 1.0),  # behind the robot, in the corridor
        ]
    )
    pose = (2.5, 3.0, math.pi / 2)
    assert list(sensor.in_view(world.raycaster, pose, victims)) == [True, True, False, False, False]
    turned = (2.5, 3.0, -math.pi / 2)  # facing the corridor through the door
    assert list(sensor.in_view(world.raycaster, turned, victims)) == [False, False, False, False, True]
    far = VictimSensor(VictimConfig(sensor_range_m=2.0, sensor_fov_rad=math.radians(90)))
    assert list(far.in_view(world.raycaster, pose, victims[:2])) == [True, False]


def test_relative_polar__ranges_and_bearings():
    r, b = relative_polar((1.0, 1.0, math.pi / 2), np.array([(1.0, 3.0), (0.0, 1.0), (2.0, 1.0)]))
    assert r == pytest.approx([2.0, 1.0, 1.0])
    assert b == pytest.approx([0.0, math.pi / 2, -math.pi / 2])


@pytest.mark.parametrize(
    "kwargs",
    [
        {"n_victims": 0},
        {"sensor_range_m": -3.0},
        {"sensor_fov_rad": 0.0},
        {"labels": ("kitchen",)},
        {"labels": ()},
        {"min_clearance_m": -1},
    ],
)
def test_victim_config__bad_values_raise_config_error(kwargs):
    with pytest.raises(ConfigError):
        VictimConfig(**kwargs)


def test_victims__counts_and_the_end_of_a_search_follow_the_found_flags():
    from realistic_indoor.sim.victims import Victims

    victims = Victims()
    victims.found = np.array([True, False, True])
    assert victims.counts() == {"victims_found": 2, "victims_total": 3}
    assert not victims.all_found
    victims.found[1] = True
    assert victims.all_found and victims.counts()["victims_found"] == 3
