"""Building-level measures on small buildings whose values are worked out by hand."""

from __future__ import annotations

import math

import pytest

from realistic_indoor.building import Building, Door, Room
from realistic_indoor.validator.building_measures import BUILDING_MEASURES, building_measures, footprint

V = math.pi / 2  # a door on a vertical wall
H = 0.0  # a door on a horizontal wall


def square_office() -> Building:
    """One 10 m x 10 m office with its entrance."""
    rooms = (Room.rectangle("o", "medium", "office", (0, 0, 10, 10)),)
    return Building("office", rooms, (Door("e", "o", None, 5.0, 0.0),))


def l_office() -> Building:
    """An L of three 10 m squares: a corridor square at the corner, an office east and north of it.

    Convex hull: the 20 m square minus the triangle (10,10)-(20,10)-(10,20) = 400 - 50 = 350 m2.
    Perimeter of the L: 20 + 10 + 10 + 10 + 10 + 20 = 80 m. Doors: corridor-east, corridor-north,
    so the two offices are 2 doors apart and each is 1 door from the corridor.
    """
    rooms = (
        Room.rectangle("c", "corridor", "corridor", (0, 0, 10, 10)),
        Room.rectangle("east", "medium", "office", (10, 0, 20, 10)),
        Room.rectangle("north", "medium", "office", (0, 10, 10, 20)),
    )
    doors = (Door("d1", "c", "east", 10.0, 5.0, 0.9, V), Door("d2", "c", "north", 5.0, 10.0))
    return Building("office", rooms, doors)


def ring_office(core: bool, parallel_door: bool = False) -> Building:
    """A 30 m square ring of four 3 m wide corridors, with or without a 24 m square core room.

    Corridor area 2 * 90 + 2 * 72 = 324 m2. Without the core the 576 m2 court is a hole of the
    footprint: perimeter 4 * 30 + 4 * 24 = 216 m.
    """
    rooms = [
        Room.rectangle("S", "corridor", "corridor", (0, 0, 30, 3)),
        Room.rectangle("N", "corridor", "corridor", (0, 27, 30, 30)),
        Room.rectangle("W", "corridor", "corridor", (0, 3, 3, 27)),
        Room.rectangle("E", "corridor", "corridor", (27, 3, 30, 27)),
    ]
    doors = [
        Door("sw", "S", "W", 1.5, 3.0),
        Door("se", "S", "E", 28.5, 3.0),
        Door("nw", "N", "W", 1.5, 27.0),
        Door("ne", "N", "E", 28.5, 27.0),
    ]
    if parallel_door:
        doors.append(Door("sw2", "S", "W", 2.5, 3.0, 0.8))
    if core:
        rooms.append(Room.rectangle("core", "big", "storage", (3, 3, 27, 27)))
        doors.append(Door("dc", "core", "S", 15.0, 3.0))
    return Building("office", tuple(rooms), tuple(doors))


def test_building_measures__square():
    m = building_measures(square_office())
    assert m.footprint_fill == pytest.approx(1.0)
    assert m.isoperimetric_quotient == pytest.approx(4 * math.pi * 100 / 40**2)  # pi / 4
    assert m.aspect_ratio == pytest.approx(1.0)
    assert m.circulation_share == 0.0
    assert m.rooms_per_hectare == pytest.approx(100.0)  # 1 room on 0.01 ha
    assert m.door_depth == 0.0 and m.door_depth_norm == 0.0
    assert m.one_door_share == 1.0  # its one door is the entrance
    assert m.circulation_loops == 0
    assert m.core_facade_share == 1.0


def test_building_measures__l_shape():
    m = building_measures(l_office())
    assert m.footprint_fill == pytest.approx(300 / 350)
    assert m.isoperimetric_quotient == pytest.approx(4 * math.pi * 300 / 80**2)
    assert m.aspect_ratio == pytest.approx(1.0)  # the smallest enclosing rectangle is 20 m x 20 m
    assert m.circulation_share == pytest.approx(1 / 3)
    assert m.rooms_per_hectare == pytest.approx(100.0)  # 3 rooms on 0.03 ha
    assert m.door_depth == pytest.approx(4 / 3)  # pairs at 1, 1 and 2 doors
    assert m.door_depth_norm == pytest.approx(4 / 3 / math.sqrt(3))
    assert m.one_door_share == 1.0
    assert m.circulation_loops == 0
    assert m.core_facade_share == 1.0


def test_building_measures__ring_corridor_around_a_court():
    m = building_measures(ring_office(core=False))
    assert m.footprint_fill == pytest.approx(324 / 900)
    assert m.isoperimetric_quotient == pytest.approx(4 * math.pi * 324 / 216**2)
    assert m.circulation_share == 1.0
    assert m.circulation_loops == 1
    assert m.door_depth == pytest.approx(4 / 3)  # on a cycle of 4: 1, 1 and 2 doors from each
    assert math.isnan(m.one_door_share)  # no ordinary room
    assert math.isnan(m.core_facade_share)  # no office


def test_building_measures__ring_corridor_around_a_core_room():
    m = building_measures(ring_office(core=True))
    assert m.footprint_fill == pytest.approx(1.0)
    assert m.isoperimetric_quotient == pytest.approx(math.pi / 4)
    assert m.circulation_share == pytest.approx(324 / 900)
    assert m.circulation_loops == 1
    assert m.one_door_share == 1.0


def test_building_measures__parallel_doors_make_no_loop():
    assert building_measures(ring_office(core=False, parallel_door=True)).circulation_loops == 1


def test_building_measures__long_thin_building():
    rooms = tuple(Room.rectangle(f"o{i}", "medium", "office", (5 * i, 0, 5 * i + 5, 5)) for i in range(8))
    doors = tuple(Door(f"d{i}", f"o{i}", f"o{i + 1}", 5 * i + 5, 2.5, 0.9, V) for i in range(7))
    m = building_measures(Building("office", rooms, doors))
    assert m.aspect_ratio == pytest.approx(8.0)
    # a chain of 8: sum over ordered pairs of |i - j| is 2 * 84 = 168, over 56 pairs
    assert m.door_depth == pytest.approx(3.0)
    assert m.one_door_share == pytest.approx(2 / 8)  # the two ends
    assert m.leaf_share == pytest.approx(2 / 8)  # only the ends have one neighbour


def test_building_measures__leaf_share_counts_neighbours_not_doors():
    # a corridor with three offices on it; the first office has two doors to the corridor and
    # a door to the second: neighbours corridor 3, o0 2, o1 2, o2 1 -> one leaf of four rooms
    rooms = (
        Room.rectangle("c", "corridor", "corridor", (0, 0, 15, 2)),
        *(Room.rectangle(f"o{i}", "medium", "office", (5 * i, 2, 5 * i + 5, 7)) for i in range(3)),
    )
    doors = (
        Door("d0", "c", "o0", 1.5, 2, 0.9, H),
        Door("d0b", "c", "o0", 3.5, 2, 0.9, H),
        Door("d1", "c", "o1", 7.5, 2, 0.9, H),
        Door("d2", "c", "o2", 12.5, 2, 0.9, H),
        Door("d01", "o0", "o1", 5, 4.5, 0.9, V),
    )
    assert building_measures(Building("office", rooms, doors)).leaf_share == pytest.approx(1 / 4)


def test_building_measures__interior_office_has_no_facade():
    rooms = (
        Room.rectangle("west", "medium", "office", (0, 0, 5, 5)),
        Room.rectangle("mid", "medium", "office", (5, 0, 10, 5)),
        Room.rectangle("east", "medium", "office", (10, 0, 15, 5)),
        Room.rectangle("top", "corridor", "corridor", (0, 5, 15, 7)),
        Room.rectangle("bottom", "corridor", "corridor", (0, -2, 15, 0)),
    )
    m = building_measures(Building("office", rooms, ()))
    assert m.core_facade_share == pytest.approx(2 / 3)  # mid is between corridors and offices


def test_footprint__fills_shafts_and_keeps_courts():
    # a 12 m square ring of rooms around a 2 m square shaft (4 m2, filled) ...
    ring = [(0, 0, 12, 5), (0, 7, 12, 12), (0, 5, 5, 7), (7, 5, 12, 7)]
    rooms = tuple(Room.rectangle(f"r{i}", "big", "office", box) for i, box in enumerate(ring))
    assert footprint(Building("office", rooms, ())).area == pytest.approx(144.0)
    # ... and around a 6 m square court (36 m2, kept)
    ring = [(0, 0, 12, 3), (0, 9, 12, 12), (0, 3, 3, 9), (9, 3, 12, 9)]
    rooms = tuple(Room.rectangle(f"r{i}", "big", "office", box) for i, box in enumerate(ring))
    assert footprint(Building("office", rooms, ())).area == pytest.approx(108.0)


def test_footprint__closes_wall_gaps_between_rooms():
    rooms = (
        Room.rectangle("a", "medium", "office", (0, 0, 5, 5)),
        Room.rectangle("b", "medium", "office", (5.2, 0, 10.2, 5)),  # a 0.2 m wall between them
    )
    shape = footprint(Building("office", rooms, ()))
    assert shape.geom_type == "Polygon"
    assert shape.area == pytest.approx(51.0)


def test_building_measures__every_measure_is_described():
    assert list(BUILDING_MEASURES) == list(building_measures(square_office()).as_dict())
