"""Fixtures of the evaluation tests: a small hand-made office saved as a plan file."""

from __future__ import annotations

import math

import pytest

from realistic_indoor.building import Building, Door, Room


def corridor_with_rooms() -> Building:
    """A 12 m corridor with an entrance and three 4 x 4 m offices on one side (about 70 m2)."""
    rooms = [Room.rectangle("c", "corridor", "corridor", (0.0, 0.0, 12.0, 2.0))]
    doors = [Door("entrance", "c", None, 0.0, 1.0, 1.2, math.pi / 2)]
    for i in range(3):
        rid = f"r{i}"
        rooms.append(Room.rectangle(rid, "medium", "office", (4.0 * i, 2.0, 4.0 * i + 4.0, 6.0)))
        doors.append(Door(f"d{i}", rid, "c", 4.0 * i + 2.0, 2.0, 0.9, 0.0))
    return Building("office", tuple(rooms), tuple(doors), {"generator": "hand-made"})


@pytest.fixture(scope="session")
def small_office() -> Building:
    return corridor_with_rooms()


@pytest.fixture(scope="session")
def plan_dir(tmp_path_factory, small_office):
    """A folder with the small office as two JSON plans."""
    from realistic_indoor.io import save

    folder = tmp_path_factory.mktemp("plans")
    save(small_office, folder / "a.json")
    save(small_office, folder / "b.json")
    return folder
