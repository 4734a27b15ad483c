import math

import numpy as np
import pytest
from scipy import ndimage
from sim_buildings import corridor_office, rotated

from realistic_indoor.building import Building
from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.raster import RASTER_FREE, RASTER_OUTSIDE, RASTER_WALL, rasterize


def _closed(building: Building) -> Building:
    """The same rooms without any door: every room is walled in."""
    return Building(building.building_type, building.rooms, ())


def test_rasterize__cells_inside_rooms_are_free_outside_is_outside(tiny_office):
    r = rasterize(tiny_office)
    points = np.array([(2.0, 4.0), (7.0, 3.0), (5.0, 1.0), (-0.3, 1.0), (11.0, 7.0), (5.0, 6.4)])
    assert list(r.value_at(points)) == [
        RASTER_FREE,
        RASTER_FREE,
        RASTER_FREE,
        RASTER_OUTSIDE,
        RASTER_OUTSIDE,
        RASTER_OUTSIDE,
    ]


def test_rasterize__walls_at_room_boundaries_with_gaps_at_doors(tiny_office):
    r = rasterize(tiny_office)
    walls = np.array([(5.0, 4.0), (1.0, 2.0), (0.0, 0.2), (10.0, 1.0), (4.0, 6.0)])
    assert (r.value_at(walls) == RASTER_WALL).all()
    doorways = np.array([(2.5, 2.0), (7.5, 2.0), (2.2, 1.98), (0.03, 1.0)])
    assert (r.value_at(doorways) == RASTER_FREE).all()


def test_rasterize__wall_is_as_thick_as_asked(tiny_office):
    # y = 2 m lies on a cell boundary: a wall of no thickness still touches the two rows beside it
    for thickness, rows in ((0.1, 2), (0.3, 6), (0.0, 2)):
        r = rasterize(tiny_office, resolution_m=0.05, wall_thickness_m=thickness)
        row, col = r.world_to_cell((4.0, 2.0))
        column = r.grid[:, col]
        assert np.count_nonzero(column[row - 10 : row + 10] == RASTER_WALL) == rows


@pytest.mark.parametrize("thickness", [0.0, 0.1])
@pytest.mark.parametrize("angle_deg", [0.0, 30.0, 45.0, 71.3])
def test_rasterize__walls_do_not_leak_even_diagonally(angle_deg, thickness):
    b = _closed(rotated(corridor_office(3, 1), math.radians(angle_deg), (0.37, -1.1)))
    r = rasterize(b, resolution_m=0.1, wall_thickness_m=thickness)
    labels, n = ndimage.label(r.grid == RASTER_FREE, structure=np.ones((3, 3)))
    assert n == len(b.rooms)
    for room in b.rooms:
        centre = room.polygon.representative_point()
        row, col = r.world_to_cell((centre.x, centre.y))
        cells = labels == labels[row, col]
        assert abs(cells.sum() * r.cell_area_m2 - room.area) < 0.15 * room.area


def test_rasterize__free_area_matches_the_floor_area(office):
    r = rasterize(office, resolution_m=0.05, wall_thickness_m=0.1)
    wall_length = float(np.linalg.norm(office.walls[:, 1] - office.walls[:, 0], axis=1).sum())
    inside = r.area_m2(RASTER_FREE) + r.area_m2(RASTER_WALL)
    assert inside == pytest.approx(office.area + wall_length * 0.05, rel=0.02)


def test_rasterize__grid_covers_the_building_with_a_margin(office):
    r = rasterize(office, margin_m=1.0)
    xmin, xmax, ymin, ymax = r.extent
    bx0, by0, bx1, by1 = office.bounds
    assert xmin <= bx0 - 1.0 and ymin <= by0 - 1.0 and xmax >= bx1 + 1.0 and ymax >= by1 + 1.0
    assert (r.grid[0] == RASTER_OUTSIDE).all() and (r.grid[:, -1] == RASTER_OUTSIDE).all()
    assert not r.grid.flags.writeable


def test_raster__world_to_cell_inverts_cell_to_world(office, rng):
    r = rasterize(office)
    rows = rng.integers(0, r.shape[0], 100)
    cols = rng.integers(0, r.shape[1], 100)
    back = r.world_to_cell(r.cell_to_world(rows, cols))
    assert (back[0] == rows).all() and (back[1] == cols).all()
    assert r.in_bounds(rows, cols).all()
    assert not r.in_bounds(-1, 0) and not r.in_bounds(0, r.shape[1])


def test_raster__row_zero_is_the_lowest_y(tiny_office):
    r = rasterize(tiny_office)
    (x0, y0), res = r.origin, r.resolution_m
    assert r.cell_to_world(0, 0) == pytest.approx((x0 + res / 2, y0 + res / 2))
    assert r.world_to_cell((x0 + 0.01, y0 + 3 * res + 0.01)) == (3, 0)


@pytest.mark.parametrize(
    "kwargs",
    [{"resolution_m": 0.0}, {"resolution_m": -1}, {"wall_thickness_m": -0.1}, {"margin_m": math.nan}],
)
def test_rasterize__bad_sizes_raise_config_error(tiny_office, kwargs):
    with pytest.raises(ConfigError):
        rasterize(tiny_office, **kwargs)


def test_rasterize__building_without_rooms_raises_config_error():
    with pytest.raises(ConfigError, match="without rooms"):
        rasterize(Building("office", ()))
