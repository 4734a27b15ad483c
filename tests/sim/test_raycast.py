import math

import numpy as np
import pytest
import shapely
from shapely.geometry import LineString, Point, box
from shapely.ops import unary_union
from sim_buildings import corridor_office, rotated

from realistic_indoor.building.walls import door_gap
from realistic_indoor.sim.raster import RASTER_FREE, RASTER_OUTSIDE, RASTER_WALL, rasterize
from realistic_indoor.sim.raycast import Raycaster

RES, THICKNESS, MAX_RANGE = 0.05, 0.1, 10.0


class Reference:
    """Exact rays against the building's wall segments and outline (shapely)."""

    def __init__(self, building):
        self.centre_lines = shapely.MultiLineString([list(map(tuple, s)) for s in building.walls])
        self.walls = self.centre_lines.buffer(THICKNESS / 2, cap_style="square")
        inside = [r.polygon for r in building.rooms] + [
            door_gap(d) for d in building.doors if not d.is_exterior
        ]
        inside = unary_union(inside).buffer(1e-6)  # closes float slivers between rotated rooms
        self.outside = box(*inside.buffer(MAX_RANGE + 1).bounds).difference(inside)

    @staticmethod
    def first(origin, end, geom):
        """Distance from ``origin`` to the first point of ``geom`` on the segment, or inf."""
        cut = LineString([origin, end]).intersection(geom)
        if cut.is_empty:
            return math.inf
        return shapely.distance(Point(origin), cut)


def _free_poses(raster, reference, rng, n, clearance=0.2):
    free = np.argwhere(raster.grid == RASTER_FREE)
    out = []
    while len(out) < n:
        p = raster.cell_to_world(*free[rng.integers(len(free))])
        if reference.walls.distance(Point(p)) >= clearance:
            out.append(p)
    return out


BUILDINGS = {
    "tiny office": None,
    "real office ED21 (slanted walls)": "office/ED21.xml",
    "axis-aligned": lambda: corridor_office(3, 1),
    "rotated 30 deg": lambda: rotated(corridor_office(3, 1), math.radians(30), (0.31, -0.17)),
    "rotated 7 deg": lambda: rotated(corridor_office(2, 2), math.radians(7), (0.0, 0.0)),
}


def _building(source, request):
    if source is None:
        return request.getfixturevalue("tiny_office")
    if isinstance(source, str):
        from realistic_indoor.io import load

        return load(request.getfixturevalue("real_plans_dir") / source)
    return source()


@pytest.mark.parametrize("name", BUILDINGS)
def test_raycaster__agrees_with_exact_geometry_within_one_cell(name, rng, request):
    building = _building(BUILDINGS[name], request)
    raster = rasterize(building, RES, THICKNESS)
    rc = Raycaster(raster)
    ref = Reference(building)
    n_wall = 0
    for origin in _free_poses(raster, ref, rng, 25):
        angles = rng.uniform(-math.pi, math.pi, 40)
        hits = rc.cast(origin, angles, MAX_RANGE)
        for a, r, kind in zip(angles, hits.range_m.astype(float), hits.kind, strict=True):
            d = np.array([math.cos(a), math.sin(a)])
            end = origin + MAX_RANGE * d
            point = Point(origin + r * d)
            # never through a wall: the beam stops before crossing a wall's centre line
            assert r <= ref.first(origin, end, ref.centre_lines) + 1e-6
            if kind == RASTER_WALL:
                n_wall += 1
                assert ref.walls.distance(point) <= RES  # it stopped at a real wall
            elif kind == RASTER_OUTSIDE:
                assert ref.outside.distance(point) <= RES  # it left through an entrance
            else:
                assert r == pytest.approx(MAX_RANGE)
                assert ref.first(origin, end, ref.walls) > MAX_RANGE - RES * 2
    assert n_wall > 500


def test_raycaster__ranges_are_exact_for_head_on_walls(tiny_office):
    rc = Raycaster(rasterize(tiny_office, RES, THICKNESS))
    hits = rc.cast((2.0, 4.0), np.array([0.0, math.pi / 2, math.pi, -math.pi / 2]), MAX_RANGE)
    # walls are 0.1 m thick, centred on the room outline (x = 0 and 5, y = 2 and 6)
    assert hits.range_m == pytest.approx([2.95, 1.95, 1.95, 1.95], abs=1e-4)
    assert (hits.kind == RASTER_WALL).all()


def test_raycaster__beam_through_an_entrance_reports_the_outside(tiny_office):
    rc = Raycaster(rasterize(tiny_office, RES, THICKNESS))
    hits = rc.cast((3.0, 1.0), np.array([math.pi]), MAX_RANGE)  # west, through the entrance e1
    assert hits.kind[0] == RASTER_OUTSIDE
    assert hits.range_m[0] == pytest.approx(3.0, abs=RES)


def test_raycaster__nothing_within_range_reads_max_range(office):
    rc = Raycaster(rasterize(office))
    hits = rc.cast((3.0, 6.25), np.array([0.0]), 2.0)  # along the corridor
    assert hits.kind[0] == RASTER_FREE and hits.range_m[0] == pytest.approx(2.0)


def test_raycaster__origin_off_the_grid_sees_outside(tiny_office):
    hits = Raycaster(rasterize(tiny_office)).cast((-100.0, 0.0), np.zeros(3), MAX_RANGE)
    assert (hits.kind == RASTER_OUTSIDE).all() and (hits.range_m == 0).all()


def test_raycaster__line_of_sight_is_blocked_by_walls_not_by_doorways(tiny_office):
    rc = Raycaster(rasterize(tiny_office))
    targets = np.array([(2.5, 4.0), (4.0, 4.0), (7.0, 4.0), (2.5, 1.0)])
    assert list(rc.visible((2.5, 3.0), targets)) == [True, True, False, True]
    assert list(rc.visible((1.0, 4.0), targets[3:])) == [False]


def test_raycaster__rejects_a_non_positive_range(tiny_office):
    from realistic_indoor.errors import ConfigError

    with pytest.raises(ConfigError, match="max_range_m"):
        Raycaster(rasterize(tiny_office)).cast((1.0, 1.0), np.zeros(1), 0.0)


def test_free_distance_cells__is_the_exact_euclidean_distance_transform(office, rng):
    from scipy.ndimage import distance_transform_edt

    from realistic_indoor.sim.raycast import free_distance_cells

    raster = rasterize(office)
    expected = distance_transform_edt(raster.grid == RASTER_FREE)
    assert np.abs(free_distance_cells(raster) - expected).max() < 1e-4


def test_raycaster__a_fan_marched_in_lockstep_equals_its_rays_marched_one_by_one(office, rng):
    from realistic_indoor.sim.raycast import _march

    raycaster = Raycaster(rasterize(office, RES, THICKNESS))
    free = np.argwhere(raycaster.raster.grid == RASTER_FREE)
    offsets = np.linspace(-3 * math.pi / 4, 3 * math.pi / 4, 109)
    t_max = MAX_RANGE / RES
    for k in range(60):
        r, c = free[rng.integers(len(free))]
        x, y = raycaster.raster.cell_to_world(r, c)
        heading = (math.pi / 2) * (k % 4) if k % 3 == 0 else rng.uniform(-math.pi, math.pi)  # axes too
        angles = heading + offsets
        hits = raycaster.cast((x, y), angles, MAX_RANGE)
        px = (x - raycaster._x0) * raycaster._scale
        py = (y - raycaster._y0) * raycaster._scale
        dx, dy = np.cos(angles), np.sin(angles)  # the directions cast() gives the fan
        for i in range(len(angles)):
            t, kind = _march(raycaster._skip, px, py, dx[i], dy[i], t_max)
            assert hits.kind[i] == kind
            assert hits.range_m[i] == np.float32(min(t, t_max) * RES)


@pytest.mark.parametrize("n_rays", [1, 2, 3, 4, 5, 9])
def test_raycaster__fans_of_fewer_rays_than_lanes_and_a_few_more_equal_their_rays_marched_alone(
    office, rng, n_rays
):
    from realistic_indoor.sim.raycast import _march

    raycaster = Raycaster(rasterize(office, RES, THICKNESS))
    free = np.argwhere(raycaster.raster.grid == RASTER_FREE)
    for _ in range(20):
        r, c = free[rng.integers(len(free))]
        x, y = raycaster.raster.cell_to_world(r, c)
        angles = rng.uniform(-math.pi, math.pi, n_rays)
        max_range = float(rng.choice([MAX_RANGE, 0.3]))  # the short range ends rays in free floor
        hits = raycaster.cast((x, y), angles, max_range)
        px = (x - raycaster._x0) * raycaster._scale
        py = (y - raycaster._y0) * raycaster._scale
        t_max = max_range / RES
        dx, dy = np.cos(angles), np.sin(angles)  # the directions cast() gives the fan
        for i in range(n_rays):
            t, kind = _march(raycaster._skip, px, py, dx[i], dy[i], t_max)
            assert hits.kind[i] == kind
            assert hits.range_m[i] == np.float32(min(t, t_max) * RES)
