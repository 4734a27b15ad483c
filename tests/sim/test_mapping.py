import math

import numpy as np
import pytest
from sim_buildings import corridor_office

from realistic_indoor.building import Building
from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.lidar import Lidar, LidarConfig
from realistic_indoor.sim.mapping import (
    MAPPED_FREE,
    MAPPED_OCCUPIED,
    MAPPED_UNKNOWN,
    PIXEL_FREE,
    PIXEL_OCCUPIED,
    PIXEL_UNKNOWN,
    FreeSpaceMarker,
    LocalMapConfig,
    RobotMap,
)
from realistic_indoor.sim.raster import RASTER_FREE, RASTER_WALL
from realistic_indoor.sim.world import World

RING = LidarConfig(fov_rad=2 * math.pi, n_beams=360, noise_std_m=0.0)


@pytest.fixture
def tiny_world(tiny_office):
    return World(tiny_office)


def _scan_from(world, pose, config=RING):
    return Lidar(config).scan(world.raycaster, pose)


def _room_cells(world, room):
    centres = world.raster.cell_to_world(*np.indices(world.raster.shape))
    import shapely

    inside = shapely.contains_xy(room.polygon, centres[..., 0], centres[..., 1])
    return inside & (world.raster.grid == RASTER_FREE)


def test_robot_map__a_full_turn_in_a_closed_room_sees_the_whole_room(tiny_office):
    closed = Building("office", tiny_office.rooms, ())
    world = World(closed, start_pose=(2.5, 4.0, 0.0))
    m = RobotMap(world)
    new = m.update(_scan_from(world, (2.5, 4.0, 0.0)))
    room = _room_cells(world, closed.room("a"))
    seen = m.grid == MAPPED_FREE
    assert seen[room].mean() > 0.995
    assert not seen[~room].any()  # nothing behind the walls
    assert m.coverage == pytest.approx(seen[room].mean(), abs=1e-9)
    assert new == pytest.approx(m.observed_area_m2)


def test_robot_map__marks_walls_where_beams_return_and_free_only_on_free_floor(office):
    world = World(office)
    m = RobotMap(world)
    for pose in [(1.25, 3.0, 1.5), (6.0, 6.25, 0.0), (12.0, 6.25, math.pi), (4.5, 2.5, 2.0)]:
        m.update(_scan_from(world, pose))
    truth = world.raster.grid
    assert (truth[m.grid == MAPPED_OCCUPIED] == RASTER_WALL).all()
    assert (truth[m.grid == MAPPED_FREE] == RASTER_FREE).all()
    assert (m.grid == MAPPED_OCCUPIED).sum() > 500


def test_robot_map__update_returns_the_newly_observed_area(office):
    world = World(office)
    m = RobotMap(world)
    scan = _scan_from(world, world.start_pose, LidarConfig())
    first = m.update(scan)
    assert first > 5.0
    assert m.update(scan) == 0.0
    second = m.update(_scan_from(world, (6.0, 6.25, 0.0), LidarConfig()))
    assert first + second == pytest.approx(m.observed_area_m2)


def test_robot_map__free_floor_marked_is_in_line_of_sight(office, rng):
    world = World(office)
    m = RobotMap(world)
    pose = (6.0, 6.25, 0.3)  # in the corridor, looking into offices through their doors
    m.update(_scan_from(world, pose, LidarConfig(n_beams=109)))
    cells = np.argwhere(m.grid == MAPPED_FREE)
    sample = cells[rng.choice(len(cells), 2000, replace=False)]
    visible = world.raycaster.visible(pose[:2], world.raster.cell_to_world(*sample.T))
    assert visible.mean() > 0.98


def test_robot_map__scanning_every_room_covers_the_building(office):
    world = World(office)
    m = RobotMap(world)
    for room in office.rooms:
        c = room.polygon.centroid
        m.update(_scan_from(world, (c.x, c.y, 0.0)))
    for y in np.arange(1.0, 25.0, 1.0):  # the spine corridor, every metre
        m.update(_scan_from(world, (1.25, y, 0.0)))
    assert m.coverage > 0.99
    assert m.observed_area_m2 == pytest.approx(m.coverage * world.reachable_area_m2)


def test_robot_map__reset_forgets_everything(tiny_world):
    m = RobotMap(tiny_world)
    m.update(_scan_from(tiny_world, tiny_world.start_pose))
    m.reset()
    assert m.coverage == 0.0 and (m.grid == MAPPED_UNKNOWN).all()
    assert (m.local_view(tiny_world.start_pose) == PIXEL_UNKNOWN).all()


def test_robot_map__after_a_reset_maps_a_scan_as_a_new_map_does(tiny_world):
    scan = _scan_from(tiny_world, tiny_world.start_pose)
    used, fresh = RobotMap(tiny_world), RobotMap(tiny_world)
    used.update(scan)
    used.reset()
    assert used.update(scan) == fresh.update(scan) > 0
    assert np.array_equal(used.grid, fresh.grid)
    assert (used.grid == MAPPED_OCCUPIED).any()  # walls marked again after the reset


def test_robot_map__grid_is_read_only(tiny_world):
    with pytest.raises(ValueError):
        RobotMap(tiny_world).grid[0, 0] = 1


def test_local_view__robot_at_the_centre_heading_up(tiny_world):
    m = RobotMap(tiny_world, LocalMapConfig(size_px=64, resolution_m=0.1))
    pose = (2.5, 4.0, math.pi / 2)  # room a, facing north: wall 2 m ahead, 2.5 m either side
    m.update(_scan_from(tiny_world, pose))
    img = m.local_view(pose)
    assert img.shape == (64, 64) and img.dtype == np.uint8
    column = img[:, 31]
    # pixel i lies (31.5 - i) * 0.1 m ahead: the north wall's face (1.95 m ahead) is in row 12
    assert column[12] == PIXEL_OCCUPIED and (column[13:32] == PIXEL_FREE).all()
    assert (column[:12] == PIXEL_UNKNOWN).all()  # behind the wall
    row = img[32]  # west wall on the left, east wall on the right, both 2.45 m away
    assert row[7] == PIXEL_OCCUPIED and row[56] == PIXEL_OCCUPIED
    assert (row[8:56] == PIXEL_FREE).all()


def test_local_view__turns_with_the_robot(tiny_world):
    m = RobotMap(tiny_world)
    m.update(_scan_from(tiny_world, (2.5, 4.0, 0.0)))
    north = m.local_view((2.5, 4.0, math.pi / 2))
    east = m.local_view((2.5, 4.0, 0.0))
    # facing east, north is on the left: a quarter turn clockwise gives the view facing north
    assert (np.rot90(east, k=-1) == north).mean() > 0.99


def test_local_view__coarse_pixels_keep_thin_walls(tiny_world):
    m = RobotMap(tiny_world, LocalMapConfig(size_px=32, resolution_m=0.4))
    pose = (2.5, 4.0, 0.0)
    m.update(_scan_from(tiny_world, pose))
    img = m.local_view(pose)
    # the east wall (x = 5, 0.1 m thick) is 2.5 m ahead: a full row of black pixels
    ahead = 15.5 - 2.5 / 0.4
    assert (img[math.floor(ahead) - 1 : math.ceil(ahead) + 1, 12:20] == PIXEL_OCCUPIED).any(axis=0).all()


def test_local_view__fills_a_given_buffer(tiny_world):
    m = RobotMap(tiny_world, LocalMapConfig(size_px=16, resolution_m=0.2))
    buffer = np.zeros((1, 16, 16), dtype=np.uint8)
    out = m.local_view((2.5, 4.0, 0.0), out=buffer[0])
    assert np.shares_memory(out, buffer) and (buffer[0] == PIXEL_UNKNOWN).all()
    with pytest.raises(ConfigError, match="local_view"):
        m.local_view((2.5, 4.0, 0.0), out=np.zeros((16, 16), dtype=np.float32))
    with pytest.raises(ConfigError, match="local_view"):
        m.local_view((2.5, 4.0, 0.0), out=np.zeros((16, 32), dtype=np.uint8)[:, ::2])


def test_robot_map__coverage_counts_only_reachable_floor(tiny_office):
    # room b cut off: no door to it, it does not count
    b = Building("office", tiny_office.rooms, tiny_office.doors[:1] + tiny_office.doors[2:])
    world = World(b)
    m = RobotMap(world)
    for pose in [(2.5, 4.0, 0.0), (2.5, 1.0, 0.0), (7.5, 1.0, 0.0), (7.5, 4.0, 0.0)]:
        m.update(_scan_from(world, pose))
    assert m.coverage > 0.99
    assert m.observed_area_m2 == pytest.approx(world.reachable_area_m2, rel=0.01)


def test_robot_map__works_with_a_single_beam(office):
    world = World(office)
    m = RobotMap(world)
    new = m.update(_scan_from(world, (6.0, 6.25, 0.0), LidarConfig(fov_rad=0.1, n_beams=1)))
    assert new == pytest.approx(10.0 * 0.05, rel=0.1)  # a 10 m line of 5 cm cells


@pytest.mark.parametrize("kwargs", [{"size_px": 0}, {"resolution_m": 0.0}, {"size_px": 8.5}])
def test_local_map_config__bad_values_raise_config_error(kwargs):
    with pytest.raises(ConfigError, match="LocalMapConfig"):
        LocalMapConfig(**kwargs)


def test_robot_map__in_a_large_building(rng):
    world = World(corridor_office(8, 3))
    m = RobotMap(world)
    lidar = Lidar()
    total = sum(m.update(lidar.scan(world.raycaster, (1.25, y, 0.0), rng)) for y in np.arange(1, 37, 0.5))
    assert total == pytest.approx(m.observed_area_m2) and 0.05 < m.coverage < 0.5


@pytest.mark.parametrize("config", [RING, LidarConfig(noise_std_m=0.0)], ids=["ring", "default"])
def test_free_space_marker__is_the_robot_maps_fan_without_ground_truth(office, config):
    world = World(office)
    res, (x0, y0) = world.raster.resolution_m, world.raster.origin
    marker = FreeSpaceMarker(world.raster.shape, res, Lidar(config).offsets_rad)
    for pose in [(1.25, 3.0, 1.5), (6.0, 6.25, 0.0), (4.5, 2.5, 2.0)]:
        scan = _scan_from(world, pose, config)
        m = RobotMap(world)
        m.update(scan)
        swept = marker.free((pose[0] - x0, pose[1] - y0, pose[2]), scan.true.range_m)
        assert np.array_equal(m.grid == MAPPED_FREE, swept & (world.raster.grid == RASTER_FREE))
        assert (swept & (world.raster.grid != RASTER_FREE)).any()  # no ground truth: beams end in walls


def test_free_space_marker__checks_its_grid():
    with pytest.raises(ConfigError, match="resolution_m"):
        FreeSpaceMarker((10, 10), 0.0, np.zeros(3))
    with pytest.raises(ConfigError, match="beam offsets"):
        FreeSpaceMarker((10, 10), 0.1, np.zeros(0))


def test_free_space_marker__mark_unknown_marks_only_the_unknown_cells_it_sweeps():
    # a full circle of 1 m readings on 0.1 m cells, in the middle of a window of a larger map
    marker = FreeSpaceMarker((40, 40), 0.1, Lidar(RING).offsets_rad)
    pose = (2.05, 2.05, 0.3)
    ranges = np.full(RING.n_beams, 1.0, dtype=np.float32)
    swept = marker.free(pose, ranges)
    big = np.full((60, 70), MAPPED_UNKNOWN, dtype=np.uint8)
    window = big[10:50, 20:60]  # a view, not contiguous
    window[20, 20:25] = MAPPED_OCCUPIED  # known cells inside the swept disc stay as they are
    window[18:20, 15:18] = MAPPED_FREE
    before = big.copy()
    new = marker.mark_unknown(pose, ranges, window)
    expected = swept & (before[10:50, 20:60] == MAPPED_UNKNOWN)
    assert new == expected.sum()
    # cells whose centre lies within 1 m, plus those the beams cross at its edge: between the
    # discs of radius 10 -/+ 0.71 cells (pi * 9.29**2 = 271, pi * 10.71**2 = 360), less 11 known
    assert 260 < new < 360
    assert np.array_equal(window == MAPPED_FREE, expected | (before[10:50, 20:60] == MAPPED_FREE))
    assert (window[20, 20:25] == MAPPED_OCCUPIED).all()
    outside = np.ones(big.shape, dtype=bool)
    outside[10:50, 20:60] = False
    assert np.array_equal(big[outside], before[outside])
    assert marker.mark_unknown(pose, ranges, window) == 0  # nothing left to mark
    with pytest.raises(ConfigError, match="uint8 cells of that shape"):
        marker.mark_unknown(pose, ranges, np.zeros((40, 41), dtype=np.uint8))


def test_coverage_share__observed_over_reachable_and_full_where_nothing_is_reachable():
    from realistic_indoor.sim.mapping import coverage_share

    assert coverage_share(3, 4) == 0.75
    assert coverage_share(0.0, 8.0) == 0.0
    assert coverage_share(0, 0) == 1.0  # nothing to observe: done
