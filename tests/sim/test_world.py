import math

import numpy as np
import pytest
import shapely
from sim_buildings import corridor_office

from realistic_indoor.building import Building, Room
from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.raster import RASTER_FREE
from realistic_indoor.sim.world import World, WorldConfig


def test_world__starts_just_inside_the_entrance_facing_in(tiny_office):
    w = World(tiny_office)
    x, y, theta = w.start_pose
    # entrance e1 is on the corridor's west wall (x = 0) at y = 1
    assert y == pytest.approx(1.0) and 0.3 <= x <= 1.0
    assert theta == pytest.approx(0.0)
    assert w.clearance_at((x, y)) >= w.config.start_clearance_m


def test_world__entrance_on_a_south_wall_faces_north(office):
    x, y, theta = World(office).start_pose
    assert x == pytest.approx(1.25) and 0.3 <= y <= 1.0 and theta == pytest.approx(math.pi / 2)


def test_world__without_entrance_starts_in_the_middle_of_the_largest_hall():
    rooms = (
        Room.rectangle("h", "hall", "hall", (0, 0, 6, 4)),
        Room.rectangle("big", "big", "office", (6, 0, 20, 10)),
    )
    w = World(Building("office", rooms, ()))
    assert w.start_pose == pytest.approx((3.0, 2.0, 0.0), abs=0.06)


def test_world__without_hall_starts_in_the_largest_room():
    b = corridor_office(5, 2)
    no_entrance = Building("office", b.rooms, tuple(d for d in b.doors if not d.is_exterior))
    largest = max(b.rooms, key=lambda r: r.area)
    assert largest.id == "spine"
    assert World(no_entrance).start_pose == pytest.approx((*largest.polygon.centroid.coords[0], 0.0))


def test_world__reachable_floor_is_the_free_floor_joined_to_the_start(tiny_office):
    w = World(tiny_office)
    assert w.reachable.sum() == (w.raster.grid == RASTER_FREE).sum()
    cut_off = Building("office", tiny_office.rooms, tiny_office.doors[:1] + tiny_office.doors[2:])
    w2 = World(cut_off)
    assert w2.reachable_area_m2 == pytest.approx(w.reachable_area_m2 - 20.0, abs=1.0)
    assert not w2.reachable[w2.raster.world_to_cell((7.5, 4.0))]


def test_world__collision_segments_close_the_entrances(tiny_office):
    w = World(tiny_office)
    lines = shapely.MultiLineString([list(map(tuple, s)) for s in w.collision_segments])
    outline = shapely.union_all([r.polygon for r in tiny_office.rooms]).exterior
    assert outline.difference(lines.buffer(1e-6)).length == pytest.approx(0.0, abs=1e-6)


def test_world__explicit_start_pose_is_checked(tiny_office):
    assert World(tiny_office, start_pose=(2.5, 4.0, 1.0)).start_pose == (2.5, 4.0, 1.0)
    with pytest.raises(ConfigError, match="start pose"):
        World(tiny_office, start_pose=(5.0, 4.0, 0.0))  # on the wall between a and b
    with pytest.raises(ConfigError, match="start pose"):
        World(tiny_office, start_pose=(-3.0, 4.0, 0.0))  # outside


def test_world__clearance_is_the_distance_to_the_nearest_wall(office):
    w = World(office)
    # middle of a 4 m x 5 m office: 2 m to the side walls, less half a wall (0.05 m)
    assert float(w.clearance_at((4.5, 2.5))) == pytest.approx(1.95, abs=0.05)
    assert float(w.clearance_at((-10.0, 0.0))) == 0.0


def test_world__memory_is_reported_and_the_clearance_kept_only_once_read(office):
    w = World(office)
    cells = w.raster.grid.size
    segments = w.collision_segments.nbytes
    assert w.nbytes == 3 * cells + segments  # raster, skip field and reachable floor: a byte each
    w.clearance_at((4.5, 2.5))
    assert w.nbytes == 7 * cells + segments  # and the clearance, float32


# 0.475 m at 0.05 m cells and 0.35 m at 0.1 m cells: float32(least) rounds onto a clearance the
# grid makes, so a float64 comparison would answer otherwise than clearance_at(xy) >= least
@pytest.mark.parametrize(
    ("resolution_m", "least"),
    [
        (0.05, 0.0),
        (0.05, 0.26),
        (0.05, 0.4),
        (0.05, 0.475),
        (0.05, 1.0),
        (0.05, 1.5),
        (0.1, 0.35),
        (0.1, 0.95),
    ],
)
def test_world__is_clear_is_the_clearance_at_least(office, rng, resolution_m, least):
    config = WorldConfig(resolution_m=resolution_m, start_clearance_m=0.3)
    looked = World(office, config)
    read = World(office, config)
    xmin, ymin, xmax, ymax = office.bounds
    points = rng.uniform((xmin - 1, ymin - 1), (xmax + 1, ymax + 1), size=(3000, 2))
    points = np.concatenate([points, np.round(points / resolution_m) * resolution_m])  # cell corners
    got = looked.is_clear(points, least)
    assert "clearance_m" not in looked.__dict__  # answered without the whole floor's clearance
    assert np.array_equal(got, read.clearance_at(points) >= least)
    assert np.array_equal(read.is_clear(points, least), got)  # the same once the field is read
    assert got.all() if least == 0.0 else got.any() and not got.all()  # 0 m: every point, walls too
    assert looked.is_clear(tuple(points[0]), least).shape == ()
    assert read.is_clear(tuple(points[0]), least).shape == ()


def test_world__is_clear_of_any_clearance_at_most_zero_is_everywhere(office):
    w = World(office)
    points = np.array([[4.5, 2.5], [-10.0, 0.0], [0.0, 0.0]])  # on the floor, off the grid, on a wall
    assert w.is_clear(points, -1e20).all() and w.is_clear(points, 0.0).all()


def test_world__is_clear_refuses_a_clearance_that_is_not_a_number(office):
    with pytest.raises(ConfigError, match="min_m"):
        World(office).is_clear((4.5, 2.5), float("nan"))


@pytest.mark.parametrize(
    "kwargs", [{"resolution_m": 0}, {"start_clearance_m": -1}, {"wall_thickness_m": -0.1}]
)
def test_world_config__bad_values_raise_config_error(kwargs):
    with pytest.raises(ConfigError, match="WorldConfig"):
        WorldConfig(**kwargs)


def test_world__real_plan_gets_a_start_and_reachable_floor(real_plans_dir):
    from realistic_indoor.io import load

    path = sorted((real_plans_dir / "office").glob("*.xml"))[0]
    w = World(load(path))
    assert w.reachable_area_m2 > 0.5 * w.building.area
    assert w.clearance_at(w.start_pose[:2]) >= w.config.start_clearance_m
    assert np.isfinite(w.start_pose).all()


def _largest_door_component(building) -> set[str]:
    import networkx as nx

    parts = nx.connected_components(building.graph())
    return max(parts, key=lambda part: sum(building.room_by_id[r].area for r in part))


@pytest.mark.parametrize("building_type", ["office", "school", "house", "random"])
def test_world__main_part_is_the_door_graphs_largest_component(building_type):
    from realistic_indoor.generator import generate

    building = generate(building_type, seed=5)
    assert World(building).main_part() == _largest_door_component(building)


def test_world__main_part_of_two_unjoined_flats_is_the_larger(tiny_office):
    flat = Room.rectangle("far", "big", "office", (30, 0, 50, 20))  # 400 m2, no door reaches it
    building = Building("office", (*tiny_office.rooms, flat), tiny_office.doors)
    assert World(building).main_part() == {"far"} == _largest_door_component(building)
