"""Hand-made buildings whose statistics are known exactly."""

from __future__ import annotations

import math

import pytest

from realistic_indoor.building import Building, Door, Room

V = math.pi / 2  # a door on a vertical wall


def maze_office_building() -> Building:
    """An office with a main corridor, a dead-end stub corridor and a maze of three offices.

    ::

        y=10          +----+
                      | o5 |
        y=6  +--+--+  +-d6-+
             |o1|o2|s1| o3 d5 o4 |
        y=2  +d1+d2+d3+-d4-+-----+
        e1   C1 (0..20 x 0..2)
        y=0  ------+d7+------------
                   |C2| (8..10 x -6..0)

    Known facts: offices o1..o5 (5), of which o1, o2, o3 touch the corridor (60%); ordinary
    rooms o1, o2, s1, o3, o4, o5 (6), of which o1, o2, s1 connect only to corridors (50%);
    o4 and o5 are reached only through rooms; {o3, o4, o5} is one room maze (gateway o3); C2
    is a dead end joined only to a corridor; paths between rooms: mean 62/28 doors, longest 4.
    """
    rooms = (
        Room.rectangle("C1", "corridor", "corridor", (0, 0, 20, 2)),
        Room.rectangle("o1", "medium", "office", (0, 2, 5, 6)),
        Room.rectangle("o2", "medium", "office", (5, 2, 10, 6)),
        Room.rectangle("s1", "small", "toilet", (10, 2, 12, 4)),
        Room.rectangle("o3", "medium", "office", (12, 2, 16, 6)),
        Room.rectangle("o4", "medium", "office", (16, 2, 20, 6)),
        Room.rectangle("o5", "medium", "office", (16, 6, 20, 10)),
        Room.rectangle("C2", "corridor", "corridor", (8, -6, 10, 0)),
    )
    doors = (
        Door("d1", "o1", "C1", 2.5, 2.0),
        Door("d2", "o2", "C1", 7.5, 2.0),
        Door("d3", "s1", "C1", 11.0, 2.0),
        Door("d4", "o3", "C1", 14.0, 2.0),
        Door("d5", "o3", "o4", 16.0, 4.0, 0.9, V),
        Door("d6", "o4", "o5", 18.0, 6.0),
        Door("d7", "C2", "C1", 9.0, 0.0),
        Door("e1", "C1", None, 0.0, 1.0, 1.2, V),
    )
    return Building("office", rooms, doors, {"source": "maze_office"})


@pytest.fixture
def maze_office() -> Building:
    """See :func:`maze_office_building`."""
    return maze_office_building()


@pytest.fixture
def room_chain_house() -> Building:
    """A house of four rooms in a row, no corridor, entrance in the first: one maze of four."""
    rooms = tuple(
        Room.rectangle(f"r{i}", "medium", "bedroom" if i else "living room", (4 * i, 0, 4 * i + 4, 4))
        for i in range(4)
    )
    doors = tuple(Door(f"d{i}", f"r{i}", f"r{i + 1}", 4 * i + 4, 2, 0.9, V) for i in range(3))
    doors += (Door("e", "r0", None, 0, 2, 1.0, V),)
    return Building("house", rooms, doors, {"source": "room_chain_house"})


@pytest.fixture
def two_gateway_chain() -> Building:
    """Three offices in a row along a corridor, the outer two opening onto it: not a maze."""
    rooms = (
        Room.rectangle("C", "corridor", "corridor", (0, 0, 12, 2)),
        Room.rectangle("a", "medium", "office", (0, 2, 4, 6)),
        Room.rectangle("b", "medium", "office", (4, 2, 8, 6)),
        Room.rectangle("c", "medium", "office", (8, 2, 12, 6)),
    )
    doors = (
        Door("da", "a", "C", 2, 2),
        Door("dab", "a", "b", 4, 4, 0.9, V),
        Door("dbc", "b", "c", 8, 4, 0.9, V),
        Door("dc", "c", "C", 10, 2),
        Door("e", "C", None, 0, 1, 1.2, V),
    )
    return Building("office", rooms, doors)


def _strip_labels(b: Building) -> Building:
    rooms = tuple(Room(r.id, "medium", "unknown", r.outline) for r in b.rooms)
    return Building(b.building_type, rooms, b.doors, dict(b.metadata))


@pytest.fixture
def strip_labels():
    """A function that gives a plan without labels (every room "medium", function "unknown")."""
    return _strip_labels


def _scaled(b: Building, factor: float) -> Building:
    rooms = tuple(
        Room(r.id, r.label, r.function, [(x * factor, y * factor) for x, y in r.outline]) for r in b.rooms
    )
    doors = tuple(
        Door(d.id, d.room_a, d.room_b, d.x * factor, d.y * factor, d.width_m, d.angle_rad) for d in b.doors
    )
    return Building(b.building_type, rooms, doors, dict(b.metadata))


@pytest.fixture
def scaled():
    """A function that gives a plan with every length multiplied by a factor."""
    return _scaled


@pytest.fixture
def plan_folders(tmp_path, maze_office, tiny_office, scaled):
    """Two folders of JSON plans: ``mazes/`` (4 maze offices) and ``tidy/`` (4 tiny offices), plus a README."""
    from realistic_indoor.io import save

    for name, b in (("mazes", maze_office), ("tidy", tiny_office)):
        for i, f in enumerate((0.9, 1.0, 1.1, 1.2)):
            save(scaled(b, f), tmp_path / name / f"{name}_{i}.json")
    (tmp_path / "mazes" / "README.md").write_text("not a plan\n")
    return tmp_path
