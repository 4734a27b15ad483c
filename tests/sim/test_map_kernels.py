"""The map kernels: to-do bits (which free cells are still unknown, 64 cells to a word), the local view."""

import math

import numpy as np
import pytest

from realistic_indoor.sim._map_kernels import (
    MAPPED_FREE,
    MAPPED_OCCUPIED,
    MAPPED_UNKNOWN,
    TRUTH_FREE,
    TRUTH_OUTSIDE,
    TRUTH_REACHABLE,
    TRUTH_WALL,
    _fan_outline,
    _mark_fan,
    _mark_span,
    _walk_and_mark,
    render_local,
    todo_bits,
    wall_bits,
)
from realistic_indoor.sim.lidar import Lidar, LidarConfig
from realistic_indoor.sim.mapping import RobotMap
from realistic_indoor.sim.world import World


def _word(columns):
    """The int64 whose bits ``columns`` are set, by Python's integers."""
    value = sum(1 << c for c in columns)
    return np.int64(value - (1 << 64) if value >= 1 << 63 else value)


def test_todo_bits__one_bit_per_free_cell_64_to_a_word():
    targets = np.full((2, 130), TRUTH_WALL, dtype=np.uint8)
    targets[0, [0, 5, 63]] = TRUTH_FREE
    targets[0, [64, 127]] = TRUTH_REACHABLE
    targets[0, 129] = TRUTH_FREE
    targets[1, 10] = TRUTH_OUTSIDE
    bits = todo_bits(targets)
    assert bits.shape == (2, 3)
    assert bits.dtype == np.int64
    assert bits[0].tolist() == [_word([0, 5, 63]), _word([0, 63]), _word([1])]
    assert bits[1].tolist() == [0, 0, 0]
    walls = wall_bits(targets)
    assert walls[0].tolist() == [~_word([0, 5, 63]), ~_word([0, 63]), _word([0])]
    assert walls[1].tolist() == [~_word([10]), -1, _word(range(2))]


@pytest.mark.parametrize(
    ("c0", "c1"),
    [(60, 70), (0, 64), (64, 128), (63, 64), (0, 200), (130, 131), (127, 129), (10, 63), (65, 127)],
)
def test_mark_span__marks_exactly_the_free_unknown_cells_of_a_span(c0, c1):
    rng = np.random.default_rng(c0 * 1000 + c1)
    targets = rng.choice(
        np.array([TRUTH_WALL, TRUTH_OUTSIDE, TRUTH_FREE, TRUTH_REACHABLE], dtype=np.uint8), size=(3, 200)
    )
    targets[1, [c0 - 1, c1 % 200]] = TRUTH_FREE  # beside the span (in it when it reaches an end)
    grid = np.zeros((3, 200), dtype=np.uint8)
    grid[1, 3::7] = MAPPED_FREE  # already seen: neither marked again nor counted
    seen = grid[1] == MAPPED_FREE
    todo = todo_bits(targets)
    for c in np.flatnonzero(seen & (targets[1] >= TRUTH_FREE)):
        todo[1, c // 64] ^= np.int64(1) << np.int64(c % 64)
    pooled = np.zeros((1, 50), dtype=np.uint8)
    new = _mark_span(grid, pooled, 4, targets, todo, 1, c0, c1)
    in_span = (np.arange(200) >= c0) & (np.arange(200) < c1)
    marked = in_span & ~seen & (targets[1] >= TRUTH_FREE)
    assert np.array_equal(grid[1] == MAPPED_FREE, seen | marked)
    assert new == np.count_nonzero(marked & (targets[1] == TRUTH_REACHABLE))
    assert np.array_equal(grid[[0, 2]], np.zeros((2, 200)))
    still = (grid == MAPPED_UNKNOWN) & (targets >= TRUTH_FREE)
    assert np.array_equal(todo, todo_bits(np.where(still, TRUTH_FREE, TRUTH_WALL).astype(np.uint8)))
    assert np.array_equal(pooled[0] > 0, [marked[4 * p : 4 * p + 4].any() for p in range(50)])


def test_robot_map__todo_and_wall_bits_follow_the_map_along_a_drive(office):
    world = World(office)
    robot_map = RobotMap(world)
    lidar = Lidar(LidarConfig(noise_std_m=0.0))
    x, y, theta = world.start_pose
    total = 0.0
    for k in range(40):
        pose = (x + 0.1 * k * math.cos(theta), y + 0.1 * k * math.sin(theta), theta + 0.2 * k)
        total += robot_map.update(lidar.scan(world.raycaster, pose))
        still = (robot_map.grid == MAPPED_UNKNOWN) & (robot_map._targets >= TRUTH_FREE)
        expected = todo_bits(np.where(still, TRUTH_FREE, TRUTH_WALL).astype(np.uint8))
        assert np.array_equal(robot_map._bits.todo, expected)
        unmarked = (robot_map.grid != MAPPED_OCCUPIED) & (robot_map._targets == TRUTH_WALL)
        assert np.array_equal(
            robot_map._bits.walls, wall_bits(np.where(unmarked, TRUTH_WALL, TRUTH_FREE).astype(np.uint8))
        )
    assert np.count_nonzero(robot_map.grid == MAPPED_OCCUPIED) > 100
    free_seen = (robot_map.grid == MAPPED_FREE) & world.reachable
    assert total == pytest.approx(np.count_nonzero(free_seen) * world.raster.resolution_m**2)


def _fan_cells(vx, vy, h, w):
    """The cells whose centre lies in a polygon, by the even-odd rule on each row's centre line.

    A cell is in when an odd number of the row's crossings lie at or left of it (a crossing at
    ``x`` is left of cell ``c`` when ``ceil(x - 0.5) <= c``), each crossing computed as the map
    kernels compute it, so that the two agree to the bit also on cell boundaries.
    """
    rc = np.ceil(vy - 0.5).astype(np.int64)  # each vertex's first row whose centre is not below it
    inside = np.zeros((h, w), dtype=bool)
    columns = np.arange(w)
    for e in range(len(vx)):
        f = (e + 1) % len(vx)
        rows = np.arange(max(min(rc[e], rc[f]), 0), min(max(rc[e], rc[f]), h))
        if rows.size:
            x = vx[e] + (rows + 0.5 - vy[e]) * ((vx[f] - vx[e]) / (vy[f] - vy[e]))
            inside[rows] ^= np.ceil(x - 0.5)[:, None] <= columns[None, :]
    return inside


def _to_do(todo, w):
    """The to-do bits as a bool ``(H, W)`` array."""
    return np.unpackbits(todo.view(np.uint8), bitorder="little").reshape(len(todo), -1)[:, :w].astype(bool)


def _mark_by_hand(grid, pooled, k, targets, todo, cells):
    """Mark free the cells of ``cells`` still to do, as the kernels do; the new reachable ones."""
    w = grid.shape[1]
    marked = cells & _to_do(todo, w)
    rows, cols = np.nonzero(marked)
    grid[rows, cols] = MAPPED_FREE
    unknown = pooled[rows // k, cols // k] == MAPPED_UNKNOWN
    pooled[rows[unknown] // k, cols[unknown] // k] = MAPPED_FREE
    todo[...] = todo_bits(np.where(_to_do(todo, w) & ~marked, TRUTH_FREE, TRUTH_WALL).astype(np.uint8))
    return int(np.count_nonzero(marked & (targets == TRUTH_REACHABLE)))


@pytest.mark.parametrize("fov_deg", [270.0, 360.0])
def test_robot_map__marks_the_fan_by_the_even_odd_rule_and_every_beam_walk(office, fov_deg):
    # the map update looks only at the rows that may hold a cell still to do; the reference
    # tests every cell of the map against the fan and walks every beam, over a copy of the map
    world = World(office)
    robot_map = RobotMap(world)
    lidar = Lidar(LidarConfig(fov_rad=math.radians(fov_deg), noise_std_m=0.0))
    grid = robot_map._grid.copy()
    pooled = robot_map._pooled.copy()
    todo = robot_map._bits.todo.copy()
    targets, k, res = robot_map._targets, robot_map._pool, world.raster.resolution_m
    x, y, theta = world.start_pose
    for step in range(60):
        pose = (x + 0.05 * step * math.cos(theta), y + 0.05 * step * math.sin(theta), theta + 0.15 * step)
        scan = lidar.scan(world.raycaster, pose)
        new = round(robot_map.update(scan) / res**2)
        px, py = (pose[0] - world.raster.origin[0]) / res, (pose[1] - world.raster.origin[1]) / res
        dxs = math.cos(pose[2]) * robot_map._cos - math.sin(pose[2]) * robot_map._sin
        dys = math.sin(pose[2]) * robot_map._cos + math.cos(pose[2]) * robot_map._sin
        ts = scan.true.range_m.astype(np.float64) * (1.0 / res)  # as the kernel: float64 products
        vx, vy = _fan_outline(px, py, dxs, dys, ts, robot_map._closed)
        want = _mark_by_hand(grid, pooled, k, targets, todo, _fan_cells(vx, vy, *grid.shape))
        n = len(ts)
        for i in range(n):
            neighbours = (
                [ts[(i - 1) % n], ts[(i + 1) % n]] if robot_map._closed else ts[max(i - 1, 0) : i + 2]
            )
            t0 = max(min(ts[i], *neighbours) - 1.0, 0.0)
            want += _walk_and_mark(
                grid, pooled, k, targets, todo, px, py, dxs[i], dys[i], t0, ts[i], *grid.shape
            )
        assert new == want
        assert np.array_equal(robot_map._bits.todo, todo)
        assert np.array_equal(robot_map.grid == MAPPED_FREE, grid == MAPPED_FREE)
        assert np.array_equal(robot_map._pooled > MAPPED_UNKNOWN, pooled > MAPPED_UNKNOWN)
    assert np.count_nonzero(grid == MAPPED_FREE) > 10_000


@pytest.mark.parametrize("to_do_share", [0.002, 0.05, 1.0])
def test_mark_fan__marks_the_cells_still_to_do_inside_by_the_even_odd_rule(to_do_share):
    # random fan outlines (a sensor and two ends per wedge) over cells still to do here and
    # there: few rows qualify (each gathered on its own), many, or all (every row sorted at once)
    rng = np.random.default_rng(7)
    h, w = 90, 150
    targets = np.where(rng.random((h, w)) < 0.7, TRUTH_REACHABLE, TRUTH_FREE).astype(np.uint8)
    for trial in range(60):
        n = int(rng.integers(3, 40))
        angles = np.sort(rng.uniform(0, 1.5 * math.pi, n)) + rng.uniform(0, 2 * math.pi)
        ranges = rng.uniform(2, 70, n)
        px, py = rng.uniform(-10, w + 10), rng.uniform(-10, h + 10)
        t = np.minimum(ranges[:-1], ranges[1:])
        ends_x = np.stack([px + t * np.cos(angles[:-1]), px + t * np.cos(angles[1:])], axis=1).ravel()
        ends_y = np.stack([py + t * np.sin(angles[:-1]), py + t * np.sin(angles[1:])], axis=1).ravel()
        vx, vy = np.concatenate([[px], ends_x]), np.concatenate([[py], ends_y])
        if trial % 3 == 0:  # vertices on row centres and cell edges
            vx, vy = np.round(vx * 2) / 2, np.floor(vy) + 0.5
        still = rng.random((h, w)) < to_do_share
        todo = todo_bits(np.where(still, targets, TRUTH_WALL).astype(np.uint8))
        maps = [
            (np.zeros((h, w), np.uint8), np.zeros((h // 2, w // 2), np.uint8), todo.copy()) for _ in range(2)
        ]
        got = _mark_fan(*maps[0][:2], 2, targets, maps[0][2], vx, vy)
        want = _mark_by_hand(*maps[1][:2], 2, targets, maps[1][2], _fan_cells(vx, vy, h, w))
        assert got == want, trial
        for a, b in zip(maps[0], maps[1], strict=True):
            assert np.array_equal(a, b), trial
        assert want > 0 or to_do_share < 0.01 or not _fan_cells(vx, vy, h, w).any()


def _cells_walked(px, py, dx, dy, t0, t1, h, w):
    """The cells a ray crosses from ``t0`` to ``t1``, one boundary at a time (a row's on a tie)."""
    x, y = px + t0 * dx, py + t0 * dy
    c, r = math.floor(x), math.floor(y)
    step_c, step_r = (1 if dx > 0 else -1), (1 if dy > 0 else -1)
    t_dc = abs(1.0 / dx) if dx != 0.0 else 1e30
    t_dr = abs(1.0 / dy) if dy != 0.0 else 1e30
    t_c = t0 + ((c + 1 - x) if dx > 0 else (x - c)) * t_dc if dx != 0.0 else 1e30
    t_r = t0 + ((r + 1 - y) if dy > 0 else (y - r)) * t_dr if dy != 0.0 else 1e30
    cells = []
    while 0 <= r < h and 0 <= c < w:
        cells.append((r, c))
        if min(t_c, t_r) >= t1:
            break
        if t_c < t_r:
            c, t_c = c + step_c, t_c + t_dc
        else:
            r, t_r = r + step_r, t_r + t_dr
    return cells


def test_walk_and_mark__marks_the_cells_still_to_do_that_a_ray_crosses():
    rng = np.random.default_rng(3)
    h, w = 40, 150
    targets = np.where(rng.random((h, w)) < 0.8, TRUTH_REACHABLE, TRUTH_FREE).astype(np.uint8)
    directions = [0.0, math.pi / 2, math.pi, -math.pi / 2, math.pi / 4]  # along axes and diagonals too
    for trial in range(400):
        angle = directions[trial] if trial < len(directions) else rng.uniform(-math.pi, math.pi)
        dx, dy = math.cos(angle), math.sin(angle)
        px, py = rng.uniform(-5, w + 5), rng.uniform(-5, h + 5)
        if trial % 3 == 0:  # on cell boundaries
            px, py = float(round(px)), float(round(py))
        t0 = rng.uniform(0, 20)
        t1 = t0 + rng.choice([rng.uniform(0, 3), rng.uniform(0, 200)])
        still = rng.random((h, w)) < 0.5
        todo = todo_bits(np.where(still, targets, TRUTH_WALL).astype(np.uint8))
        grid = np.zeros((h, w), np.uint8)
        pooled = np.zeros((-(-h // 3), -(-w // 3)), np.uint8)
        new = _walk_and_mark(grid, pooled, 3, targets, todo, px, py, dx, dy, t0, t1, h, w)
        marked = [(r, c) for r, c in _cells_walked(px, py, dx, dy, t0, t1, h, w) if still[r, c]]
        want = np.zeros((h, w), bool)
        want[tuple(np.array(marked, dtype=int).reshape(-1, 2).T)] = True
        assert np.array_equal(grid == MAPPED_FREE, want), trial
        assert new == sum(targets[r, c] == TRUTH_REACHABLE for r, c in marked), trial
        assert np.array_equal(todo, todo_bits(np.where(still & ~want, targets, TRUTH_WALL).astype(np.uint8)))
        assert np.array_equal(
            pooled > 0, np.add.reduceat(np.add.reduceat(want, range(0, h, 3), 0), range(0, w, 3), 1) > 0
        )


def test_batch__a_robot_reset_in_the_same_building_maps_as_on_its_first_episode(office):
    from realistic_indoor.envs.vector import BatchedExploreEnv

    env = BatchedExploreEnv(num_envs=1, source=office, max_steps=5)
    first, _ = env.reset(seed=0)
    first_grid = env._batch.grids[0].copy()
    for _ in range(5):
        env.step(np.array([[1.0, 0.5]]))
    again = env.step(np.array([[0.0, 0.0]]))[0]  # the autoreset: the same building, a new map
    assert np.array_equal(env._batch.grids[0], first_grid)
    assert (first_grid == MAPPED_OCCUPIED).any()
    assert np.array_equal(again["local_map"], first["local_map"])


_GREY = np.array([128, 255, 0], dtype=np.uint8)  # unknown, free, occupied
_POOLED = np.array(
    [[MAPPED_UNKNOWN, MAPPED_FREE, MAPPED_OCCUPIED], [MAPPED_FREE, MAPPED_FREE, MAPPED_UNKNOWN]], np.uint8
)


@pytest.mark.parametrize(
    ("px", "py", "cos_h", "sin_h", "expected"),
    [
        # heading +x from cell (0, 1)'s centre: row i is 1 - i cells ahead, column j 1 - j cells
        # to the left (+y); the right column falls off the map (y < 0)
        (1.5, 0.5, 1.0, 0.0, [[128, 0, 128], [255, 255, 128], [255, 128, 128]]),
        # heading -x from cell (0, 0)'s centre: the top row (x < 0) and the left column (y < 0) are off
        (0.5, 0.5, -1.0, 0.0, [[128, 128, 128], [128, 128, 255], [128, 255, 255]]),
    ],
)
def test_render_local__an_odd_view_samples_the_cells_by_hand(px, py, cos_h, sin_h, expected):
    out = np.full((3, 3), 7, dtype=np.uint8)
    render_local(_POOLED, _GREY, px, py, cos_h, sin_h, 1.0, out)
    assert out.tolist() == expected


def test_render_local__a_pixel_on_the_far_edge_of_the_map_is_off_it():
    out = np.zeros((1, 1), dtype=np.uint8)
    render_local(_POOLED, _GREY, 3.0, 0.5, 1.0, 0.0, 1.0, out)  # x == width: past the last cell
    assert out[0, 0] == 128
    render_local(_POOLED, _GREY, 2.999, 0.5, 1.0, 0.0, 1.0, out)
    assert out[0, 0] == 0
    render_local(_POOLED, _GREY, -0.001, 0.5, 1.0, 0.0, 1.0, out)  # just before the first cell
    assert out[0, 0] == 128


def _view_by_hand(pooled, px, py, cos_h, sin_h, step, size):
    """The local view pixel by pixel: each row's start, then one pixel's step at a time."""
    h, w = pooled.shape
    half = (size - 1) / 2.0
    col_dx, col_dy = step * sin_h, -step * cos_h
    out = np.empty((size, size), dtype=np.uint8)
    for i in range(size):
        ahead = (half - i) * step
        x = px + ahead * cos_h - half * col_dx
        y = py + ahead * sin_h - half * col_dy
        for j in range(size):
            on_map = 0.0 <= x < w and 0.0 <= y < h
            out[i, j] = _GREY[pooled[math.floor(y), math.floor(x)]] if on_map else _GREY[MAPPED_UNKNOWN]
            x += col_dx
            y += col_dy
    return out


def test_render_local__equals_the_view_sampled_pixel_by_pixel():
    rng = np.random.default_rng(11)
    pooled = rng.integers(0, 3, (13, 17)).astype(np.uint8)
    for trial in range(300):
        size = int(rng.integers(1, 10))
        step = float(rng.choice([1.0, 0.5, rng.uniform(0.2, 3.0)]))
        px, py = rng.uniform(-6, 23), rng.uniform(-6, 19)
        if trial % 4 == 0:  # on cell edges, heading along an axis
            px, py = float(round(px)), float(round(py))
        theta = rng.choice([0.0, math.pi / 2, math.pi, rng.uniform(-math.pi, math.pi)])
        out = np.empty((size, size), dtype=np.uint8)
        render_local(pooled, _GREY, px, py, math.cos(theta), math.sin(theta), step, out)
        want = _view_by_hand(pooled, px, py, math.cos(theta), math.sin(theta), step, size)
        assert np.array_equal(out, want), trial
