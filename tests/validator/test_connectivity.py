import math

import pytest

from realistic_indoor.building import Building, Room, check_building
from realistic_indoor.validator.connectivity import (
    Connectivity,
    connectivity,
    core_rooms,
    corridors_only_to_corridors,
    dead_end_corridors,
    indirect_rooms,
    path_lengths,
    room_mazes,
    rooms_only_to_corridors,
    rooms_touching_corridor,
    set_connectivity,
)


def test_fixture__maze_office_is_a_valid_building(maze_office):
    assert check_building(maze_office) == []


def test_core_rooms__offices_of_an_office(maze_office):
    assert core_rooms(maze_office) == ["o1", "o2", "o3", "o4", "o5"]
    assert rooms_touching_corridor(maze_office, core_rooms(maze_office)) == ["o1", "o2", "o3"]


def test_rooms_only_to_corridors__a_door_to_another_room_disqualifies(maze_office):
    assert rooms_only_to_corridors(maze_office) == ["o1", "o2", "s1"]


def test_corridors__dead_end_and_corridor_only(maze_office):
    assert dead_end_corridors(maze_office) == ["C2"]
    assert corridors_only_to_corridors(maze_office) == ["C2"]


def test_indirect_rooms__rooms_reached_only_through_rooms(maze_office):
    assert indirect_rooms(maze_office) == ["o4", "o5"]


def test_room_mazes__chain_behind_one_gateway(maze_office):
    assert room_mazes(maze_office) == [frozenset({"o3", "o4", "o5"})]


def test_room_mazes__chain_with_two_gateways_is_not_a_maze(two_gateway_chain):
    assert room_mazes(two_gateway_chain) == []
    assert indirect_rooms(two_gateway_chain) == ["b"]


def test_room_mazes__the_outside_counts_as_a_gateway(room_chain_house):
    assert room_mazes(room_chain_house) == [frozenset({"r0", "r1", "r2", "r3"})]
    assert room_mazes(room_chain_house, min_rooms=5) == []


def test_path_lengths__mean_and_longest_in_doors(maze_office, tiny_office):
    mean, longest = path_lengths(maze_office)
    assert mean == pytest.approx(62 / 28)
    assert longest == 4
    assert path_lengths(tiny_office) == (pytest.approx(4 / 3), 2)


def test_path_lengths__no_interior_door_gives_nan():
    b = Building("office", (Room.rectangle("a", "medium", "office", (0, 0, 4, 4)),))
    mean, longest = path_lengths(b)
    assert math.isnan(mean)
    assert longest == 0


def test_connectivity__shares_of_the_maze_office(maze_office):
    c = connectivity(maze_office)
    assert c.core_touching_corridor_pct == pytest.approx(60.0)
    assert c.only_to_corridors_pct == pytest.approx(50.0)
    assert c.indirect_rooms_pct == pytest.approx(100 * 2 / 6)
    assert c.maze_rooms_pct == pytest.approx(50.0)
    assert (c.mazes, c.maze_rooms) == (1, 3)
    assert c.dead_end_corridors_pct == pytest.approx(50.0)
    assert c.corridor_only_corridors_pct == pytest.approx(50.0)
    assert c.longest_path_doors == 4


def test_set_connectivity__pools_rooms_not_buildings(maze_office, tiny_office):
    c = set_connectivity([maze_office, tiny_office])
    assert (c.core_rooms, c.core_touching_corridor) == (7, 5)
    assert c.core_touching_corridor_pct == pytest.approx(100 * 5 / 7)
    assert c.mean_path_doors == pytest.approx((62 / 28 + 4 / 3) / 2)
    assert c.longest_path_doors == pytest.approx(3.0)
    assert c.max_path_doors == 4


def test_connectivity__no_core_rooms_gives_nan_share(room_chain_house):
    c = connectivity(room_chain_house)
    assert c.core_touching_corridor_pct == 0.0
    assert math.isnan(Connectivity.combine([]).core_touching_corridor_pct)
    assert math.isnan(connectivity(room_chain_house).dead_end_corridors_pct)
