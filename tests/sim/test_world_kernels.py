"""The compiled passes of a world's build against what they replace: scipy and NumPy expressions."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import ndimage

from realistic_indoor.sim._world_kernels import (
    fill_cover,
    reachable_from,
    ring_spans,
    skip_and_clearance,
    skip_and_clearance_of,
)
from realistic_indoor.sim.fields import distance_field
from realistic_indoor.sim.raster import RASTER_FREE, RASTER_OUTSIDE, RASTER_WALL
from realistic_indoor.sim.raycast import _SAFETY, _SKIP_OUTSIDE, _SKIP_WALL


def _random_grid(seed: int, shape=(60, 80), free_share=0.62) -> np.ndarray:
    rng = np.random.default_rng(seed)
    codes = rng.choice([RASTER_WALL, RASTER_OUTSIDE], size=shape).astype(np.uint8)
    codes[rng.random(shape) < free_share] = RASTER_FREE
    return codes


@pytest.mark.parametrize("seed", range(6))
def test_reachable_from__is_the_start_cells_4_connected_component(seed):
    grid = _random_grid(seed)  # near the percolation threshold: many winding components
    labels, n = ndimage.label(grid == RASTER_FREE)  # 4-connected by default
    sizes = np.bincount(labels.ravel())[1:]
    start = np.argwhere(labels == 1 + int(np.argmax(sizes)))[0]
    got = reachable_from(grid, int(start[0]), int(start[1]))
    assert np.array_equal(got, labels == labels[tuple(start)])
    assert n > 10 and got.sum() > 100


def test_reachable_from__a_serpentine_corridor_is_followed_to_its_end_and_no_further():
    grid = np.full((41, 43), RASTER_WALL, dtype=np.uint8)
    for r in range(1, 40, 2):  # one-cell corridors joined at alternate ends
        grid[r, 1:41] = RASTER_FREE
        if r + 2 < 40:
            grid[r + 1, 40 if r % 4 == 1 else 1] = RASTER_FREE
    grid[5:9, 42] = RASTER_FREE  # a pocket behind the wall
    got = reachable_from(grid, 1, 1)
    want = grid == RASTER_FREE
    want[5:9, 42] = False
    assert np.array_equal(got, want)
    assert got[39, 1 if 39 % 4 == 3 else 40]  # the far end of the last corridor


@pytest.mark.parametrize("res", [0.05, 0.1, 0.037])
def test_skip_and_clearance__equal_the_numpy_expressions(res):
    grid = _random_grid(3, (50, 70), free_share=0.9)
    dist = distance_field(grid != RASTER_FREE)
    skip, clearance = skip_and_clearance(
        grid, dist, np.float32(_SAFETY), _SKIP_WALL, _SKIP_OUTSIDE, np.float32(0.5), np.float32(res)
    )
    want_skip = np.clip(np.floor(dist - _SAFETY), 0, _SKIP_WALL - 1).astype(np.uint8)
    want_skip[grid == RASTER_WALL] = _SKIP_WALL
    want_skip[grid == RASTER_OUTSIDE] = _SKIP_OUTSIDE
    want_clearance = np.maximum(dist - np.float32(0.5), np.float32(0.0)) * np.float32(res)
    assert np.array_equal(skip, want_skip)
    assert clearance.dtype == np.float32 and np.array_equal(clearance, want_clearance)
    assert want_skip[grid == RASTER_FREE].max() > 0  # the field has jumps to check


def test_reachable_from__a_comb_with_more_teeth_than_the_first_seed_stack_holds():
    grid = np.full((4, 20_001), RASTER_WALL, dtype=np.uint8)
    grid[0] = RASTER_FREE  # the back of the comb
    grid[1:3, ::2] = RASTER_FREE  # 10,001 teeth: one pending seed each, more than 4,096
    grid[3, 1] = RASTER_FREE  # a cell no tooth reaches
    got = reachable_from(grid, 0, 0)
    want = grid == RASTER_FREE
    want[3, 1] = False
    assert np.array_equal(got, want)


@pytest.mark.parametrize(("seed", "free_share"), [(0, 0.9), (1, 0.62), (2, 0.99), (3, 1.0), (4, 0.0)])
def test_skip_and_clearance_of__equals_skip_and_clearance_of_the_distance_field(seed, free_share):
    grid = _random_grid(seed, (57, 91), free_share)
    constants = (np.float32(_SAFETY), _SKIP_WALL, _SKIP_OUTSIDE, np.float32(0.5), np.float32(0.05))
    want_skip, want_clearance = skip_and_clearance(grid, distance_field(grid != RASTER_FREE), *constants)
    skip, clearance = skip_and_clearance_of(grid, *constants)
    assert np.array_equal(skip, want_skip) and np.array_equal(clearance, want_clearance)
    assert clearance.dtype == np.float32 and skip.dtype == np.uint8


def test_skip_and_clearance_of__a_generated_office_equals_scipys_distances():
    from realistic_indoor.generator import generate
    from realistic_indoor.sim.raster import rasterize

    grid = rasterize(generate("office", area_m2=600.0, seed=4)).grid
    dist = ndimage.distance_transform_edt(grid == RASTER_FREE).astype(np.float32)
    constants = (np.float32(_SAFETY), _SKIP_WALL, _SKIP_OUTSIDE, np.float32(0.5), np.float32(0.05))
    want_skip, want_clearance = skip_and_clearance(grid, dist, *constants)
    skip, clearance = skip_and_clearance_of(grid, *constants)
    assert np.array_equal(skip, want_skip) and np.array_equal(clearance, want_clearance)
    assert skip[grid == RASTER_FREE].max() >= 20  # long jumps: distances of many cells


@pytest.mark.parametrize("seed", range(3))
def test_reachable_from__components_of_a_generated_office_with_rubble_are_scipys(seed):
    from realistic_indoor.generator import generate
    from realistic_indoor.sim.raster import rasterize

    grid = rasterize(generate("office", area_m2=600.0, seed=seed), resolution_m=0.1).grid.copy()
    rng = np.random.default_rng(seed)
    grid[(rng.random(grid.shape) < 0.3) & (np.arange(grid.shape[1]) < grid.shape[1] // 2)] = RASTER_WALL
    labels, n = ndimage.label(grid == RASTER_FREE)
    sizes = np.bincount(labels.ravel())
    for label in [*range(1, 40), *np.argsort(sizes[1:])[-5:] + 1]:  # pockets, and the largest parts
        start = np.argwhere(labels == label)[0]
        assert np.array_equal(reachable_from(grid, int(start[0]), int(start[1])), labels == label)
    assert n > 100 and sizes[1:].max() > 10_000


def _numpy_spans(start, end, first, sizes, h, w):
    """The spans as commit ada2453 found them: every crossing with NumPy, then one lexsort."""
    r0 = np.clip(np.ceil(np.minimum(start[:, 1], end[:, 1])), 0, h).astype(np.int64)
    r1 = np.clip(np.ceil(np.maximum(start[:, 1], end[:, 1])), 0, h).astype(np.int64)
    count = r1 - r0
    edge = np.flatnonzero(count > 0)
    count = count[edge]
    e = np.repeat(edge, count)
    rows = np.repeat(r0[edge], count) + (np.arange(count.sum()) - np.repeat(np.cumsum(count) - count, count))
    sx, sy, ex, ey = start[e, 0], start[e, 1], end[e, 0], end[e, 1]
    x = sx + (rows - sy) * (ex - sx) / (ey - sy)
    ring = np.repeat(np.arange(len(sizes)), sizes)[e]
    order = np.lexsort((x, rows, ring))
    x, rows, ring = x[order], rows[order], ring[order]
    col_a = np.clip(np.ceil(x[0::2]), 0, w).astype(np.int64)
    col_b = np.clip(np.ceil(x[1::2]), 0, w).astype(np.int64)
    return rows[0::2], col_a, col_b, ring[0::2]


@pytest.mark.parametrize("seed", range(5))
def test_ring_spans__equal_numpys_crossings_of_random_rings(seed):
    rng = np.random.default_rng(seed)
    rings = []
    for _ in range(40):  # star-shaped rings of 3 to 12 vertices, some reaching off the grid
        n = int(rng.integers(3, 13))
        angles = np.sort(rng.uniform(0, 2 * np.pi, n))
        radius = rng.uniform(1, 15, n)
        centre = rng.uniform(-5, 65, 2)
        rings.append(centre + np.stack([np.cos(angles), np.sin(angles)], axis=1) * radius[:, None])
    rings.append(np.array([[2.0, 3.0], [20.0, 3.0], [20.0, 9.0], [2.0, 9.0]]))  # on the centre lines
    sizes = np.array([len(r) for r in rings])
    first = np.cumsum(sizes) - sizes
    start = np.concatenate(rings)
    nxt = np.arange(1, len(start) + 1)
    nxt[first + sizes - 1] = first
    end = np.ascontiguousarray(start[nxt])
    got = ring_spans(start, end, first, sizes, 50, 60)
    want = _numpy_spans(start, end, first, sizes, 50, 60)
    assert all(np.array_equal(a, b) for a, b in zip(got, want, strict=True))
    assert len(got[0]) > 300


@pytest.mark.parametrize("seed", range(4))
def test_fill_cover__equals_summing_the_spans_cell_by_cell(seed):
    rng = np.random.default_rng(seed)
    h, w, wall = 40, 70, 1 << 16
    n = 600
    rows = rng.integers(0, h, n)
    col_a = rng.integers(0, w + 1, n)
    col_b = np.minimum(col_a + rng.integers(0, 25, n), w)  # some empty, some to the last column
    weight = np.where(rng.random(n) < 0.2, wall, 1).astype(np.int64)
    cover = np.zeros((h, w + 1), dtype=np.int64)
    np.add.at(cover, (rows, col_a), weight)
    np.add.at(cover, (rows, col_b), -weight)
    cover = np.cumsum(cover, axis=1)[:, :w]
    want = np.where(cover >= wall, RASTER_WALL, np.where(cover > 0, RASTER_FREE, RASTER_OUTSIDE))
    got = fill_cover(rows, col_a, col_b, weight, h, w, wall)
    assert got.dtype == np.uint8 and np.array_equal(got, want)
    assert {RASTER_WALL, RASTER_FREE, RASTER_OUTSIDE} <= set(np.unique(got))


def test_reachable_from__rows_of_more_runs_than_the_first_read_holds():
    grid = np.full((5, 200), RASTER_WALL, dtype=np.uint8)
    grid[:, ::2] = RASTER_FREE  # 100 runs in every row: more than 16 per row
    grid[0, :] = RASTER_FREE  # a top row joining the columns
    got = reachable_from(grid, 4, 10)
    want = grid == RASTER_FREE
    assert np.array_equal(got, want)
