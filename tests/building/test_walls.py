"""Wall segments against the one-shapely-object-per-room-and-door pipeline they replaced."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from shapely.ops import unary_union

from realistic_indoor.building import Building
from realistic_indoor.building.walls import DOOR_GAP_DEPTH_M, door_gap, wall_segments
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


@pytest.mark.parametrize("building_type", ["office", "school", "house", "random"])
@pytest.mark.parametrize("seed", range(3))
def test_wall_segments__equal_the_per_object_pipeline_in_order(building_type, seed):
    building = generate(building_type, seed=seed)
    got = wall_segments(building)
    assert got.dtype == np.float64 and not got.flags.writeable
    assert np.array_equal(got, _reference_walls(building))  # same segments, order and direction


@pytest.mark.filterwarnings("ignore")  # the plans' repair warnings
def test_wall_segments__of_real_plans_equal_the_per_object_pipeline(real_plans_dir):
    from realistic_indoor.io import load

    for path in sorted(real_plans_dir.glob("*/*.xml"))[::6]:
        building = load(path)
        assert np.array_equal(wall_segments(building), _reference_walls(building)), path.name


def test_door_cuts__cuts_that_meet_are_merged_and_the_others_kept(tiny_office):
    from realistic_indoor.building.walls import _door_cuts

    cuts = shapely.get_parts(_door_cuts(tiny_office, DOOR_GAP_DEPTH_M))
    assert len(cuts) == len(tiny_office.doors)  # apart: one polygon per door, as made
    corner = Building("office", tiny_office.rooms, (*tiny_office.doors, _door_beside(tiny_office.doors[0])))
    merged = shapely.get_parts(_door_cuts(corner, DOOR_GAP_DEPTH_M))
    assert len(merged) == len(tiny_office.doors)  # the new door's cut overlaps the first one's
    union = shapely.union_all([door_gap(d) for d in corner.doors])
    assert shapely.equals(shapely.union_all(merged), union)
    assert np.array_equal(wall_segments(corner), _reference_walls(corner))


def _door_beside(door):
    """A door on the same wall, 0.2 m along from ``door``: their cuts overlap."""
    from dataclasses import replace

    dx, dy = door.direction
    return replace(door, id=door.id + "-beside", x=door.x + 0.2 * dx, y=door.y + 0.2 * dy)
