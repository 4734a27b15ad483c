"""Wall segments against the one-shapely-object-per-room-and-door pipeline they replaced."""

from __future__ import annotations

import math

import numpy as np
import pytest
import shapely
from shapely.ops import unary_union

from realistic_indoor.building import Building, Door, Room
from realistic_indoor.building.walls import DOOR_GAP_DEPTH_M, _gap_corners, door_gap, wall_segments
from realistic_indoor.generator import generate


def _reference_walls(building) -> np.ndarray:
    """The walls as commit ada2453 computed them: a shapely object per room and per door."""
    lines = unary_union([r.polygon.exterior for r in building.rooms])
    lines = lines.difference(unary_union([door_gap(d, DOOR_GAP_DEPTH_M) for d in building.doors]))
    merged = shapely.line_merge(lines).simplify(1e-9, preserve_topology=False)
    segs = []
    for part in getattr(merged, "geoms", [merged]):
        c = np.asarray(part.coords, dtype=float)
        segs.append(np.stack([c[:-1], c[1:]], axis=1))
    out = np.concatenate(segs)
    return out[np.hypot(*(out[:, 1] - out[:, 0]).T) > 1e-9]


def _canonical(segments: np.ndarray) -> np.ndarray:
    """Segments as ``(N, 4)`` rows, each from its lower to its higher end point, rows sorted."""
    rows = np.asarray(segments, dtype=float).reshape(-1, 4).copy()
    flip = (rows[:, 0] > rows[:, 2]) | ((rows[:, 0] == rows[:, 2]) & (rows[:, 1] > rows[:, 3]))
    rows[flip] = rows[flip][:, [2, 3, 0, 1]]
    return rows[np.lexsort(rows.T[::-1])]


def _same_segments(a: np.ndarray, b: np.ndarray) -> bool:
    a, b = _canonical(a), _canonical(b)
    return a.shape == b.shape and np.allclose(a, b, rtol=0.0, atol=1e-12)


@pytest.mark.parametrize("building_type", ["office", "school", "house", "random"])
@pytest.mark.parametrize("seed", range(3))
def test_wall_segments__of_generated_buildings_are_the_per_object_pipelines(building_type, seed):
    building = generate(building_type, seed=seed)
    got = wall_segments(building)
    assert got.dtype == np.float64 and not got.flags.writeable
    assert _same_segments(got, _reference_walls(building))  # the same segments, in another order


@pytest.mark.parametrize("building_type", ["office", "school", "house", "random"])
def test_wall_segments__of_generated_buildings_take_the_interval_path(building_type):
    from realistic_indoor.building.rect_walls import rectilinear_walls

    building = generate(building_type, seed=11)
    corners = np.array([_gap_corners(d, DOOR_GAP_DEPTH_M) for d in building.doors]).reshape(-1, 4, 2)
    fast = rectilinear_walls(building, corners)
    assert fast is not None and np.array_equal(wall_segments(building), fast)


def _room(id_: str, box: tuple[float, float, float, float]) -> Room:
    return Room.rectangle(id_, "medium", "office", box)


def _expect(*segments: tuple[float, float, float, float]) -> np.ndarray:
    return np.array(segments, dtype=float).reshape(-1, 2, 2)


def test_wall_segments__a_shared_wall_is_drawn_once_cut_at_its_door_and_splits_the_walls_it_meets():
    rooms = (_room("a", (0, 0, 4, 3)), _room("b", (4, 0, 8, 3)))
    building = Building("office", rooms, (Door("d", "a", "b", 4.0, 1.5, 0.9, math.pi / 2),))
    want = _expect(
        (0, 0, 4, 0), (4, 0, 8, 0), (0, 3, 4, 3), (4, 3, 8, 3),  # the T at x = 4 splits them
        (0, 0, 0, 3), (8, 0, 8, 3),
        (4, 0, 4, 1.05), (4, 1.95, 4, 3),  # the door: 0.9 m around y = 1.5
    )  # fmt: skip
    assert _same_segments(wall_segments(building), want)
    assert _same_segments(_reference_walls(building), want)


def test_wall_segments__four_rooms_meeting_at_a_point_split_both_walls_there():
    rooms = (
        _room("a", (0, 0, 4, 3)),
        _room("b", (4, 0, 8, 3)),
        _room("c", (0, 3, 4, 6)),
        _room("d", (4, 3, 8, 6)),
    )
    building = Building("office", rooms, ())
    outer = [
        (0, 0, 4, 0),
        (4, 0, 8, 0),
        (0, 6, 4, 6),
        (4, 6, 8, 6),
        (0, 0, 0, 3),
        (0, 3, 0, 6),
        (8, 0, 8, 3),
        (8, 3, 8, 6),
    ]
    inner = [(0, 3, 4, 3), (4, 3, 8, 3), (4, 0, 4, 3), (4, 3, 4, 6)]
    assert _same_segments(wall_segments(building), _expect(*outer, *inner))


def test_wall_segments__a_doors_cut_takes_a_wall_lying_on_its_edge():
    # rooms b and c stand 0.3 m above and below room a: the cuts of a's doors (0.3 m either side
    # of the wall) reach their walls and open them too, as in real plans with thick walls
    rooms = (_room("a", (0, 0, 4, 3)), _room("b", (0, 3.3, 4, 6)), _room("c", (0, -3, 4, -0.3)))
    doors = (Door("d", "a", "b", 2.0, 3.0, 1.0, 0.0), Door("e", "a", "c", 2.0, 0.0, 1.0, 0.0))
    building = Building("office", rooms, doors)
    want = _expect(
        (0, 0, 1.5, 0), (2.5, 0, 4, 0), (0, 0, 0, 3), (4, 0, 4, 3), (0, 3, 1.5, 3), (2.5, 3, 4, 3),
        (0, 3.3, 1.5, 3.3), (2.5, 3.3, 4, 3.3), (0, 3.3, 0, 6), (4, 3.3, 4, 6), (0, 6, 4, 6),
        (0, -0.3, 1.5, -0.3), (2.5, -0.3, 4, -0.3), (0, -3, 0, -0.3), (4, -3, 4, -0.3), (0, -3, 4, -3),
    )  # fmt: skip
    assert _same_segments(wall_segments(building), want)
    assert _same_segments(_reference_walls(building), want)


def test_wall_segments__a_slanted_room_goes_to_shapely():
    from realistic_indoor.building.rect_walls import rectilinear_walls

    slanted = Room("s", "medium", "office", ((4, 0), (7, 0), (8, 3), (4, 3)))
    building = Building(
        "office", (_room("a", (0, 0, 4, 3)), slanted), (Door("d", "a", "s", 4.0, 1.5, 0.9, math.pi / 2),)
    )
    corners = np.array([_gap_corners(d, DOOR_GAP_DEPTH_M) for d in building.doors])
    assert rectilinear_walls(building, corners) is None
    assert np.array_equal(wall_segments(building), _reference_walls(building))


@pytest.mark.filterwarnings("ignore")  # the plans' repair warnings
def test_wall_segments__of_real_plans_equal_the_per_object_pipeline(real_plans_dir):
    from realistic_indoor.io import load

    for path in sorted(real_plans_dir.glob("*/*.xml"))[::6]:
        building = load(path)
        assert np.array_equal(wall_segments(building), _reference_walls(building)), path.name


def test_door_cuts__cuts_that_meet_are_merged_and_the_others_kept(tiny_office):
    from realistic_indoor.building.walls import _door_cuts

    cuts = shapely.get_parts(_door_cuts(_corners(tiny_office)))
    assert len(cuts) == len(tiny_office.doors)  # apart: one polygon per door, as made
    corner = Building("office", tiny_office.rooms, (*tiny_office.doors, _door_beside(tiny_office.doors[0])))
    merged = shapely.get_parts(_door_cuts(_corners(corner)))
    assert len(merged) == len(tiny_office.doors)  # the new door's cut overlaps the first one's
    union = shapely.union_all([door_gap(d) for d in corner.doors])
    assert shapely.equals(shapely.union_all(merged), union)
    assert _same_segments(wall_segments(corner), _reference_walls(corner))


def _corners(building) -> np.ndarray:
    return np.array([_gap_corners(d, DOOR_GAP_DEPTH_M) for d in building.doors])


def _door_beside(door):
    """A door on the same wall, 0.2 m along from ``door``: their cuts overlap."""
    from dataclasses import replace

    dx, dy = door.direction
    return replace(door, id=door.id + "-beside", x=door.x + 0.2 * dx, y=door.y + 0.2 * dy)


def test_wall_segments__a_repeated_vertex_and_a_door_of_no_width_change_no_wall():
    # a vertex given twice makes a side of no length, which must not split the wall it lies on;
    # a door of no width cuts nothing (shapely's overlay agrees on both)
    room = Room("a", "medium", "office", ((0, 0), (2, 0), (2, 1), (2, 1), (2, 2), (0, 2)))
    building = Building("office", (room,), (Door("d", "a", None, 1.0, 0.0, 0.0, 0.0),))
    want = _expect((0, 0, 2, 0), (2, 0, 2, 2), (0, 2, 2, 2), (0, 0, 0, 2))
    assert _same_segments(wall_segments(building), want)
    assert _same_segments(_reference_walls(building), want)
