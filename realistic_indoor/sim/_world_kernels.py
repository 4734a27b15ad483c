"""Numba kernels of a world's build: the raster's fill, the reachable floor, the skip field.

Each replaces a chain of whole-grid NumPy passes (temporary arrays of 8 bytes per cell) by one
pass that writes the result, with the same values: a new building per episode pays for them.
Private to :mod:`realistic_indoor.sim`; :mod:`realistic_indoor.sim.raster` imports it lazily so
that a map export does not load numba.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from realistic_indoor.sim.raster import RASTER_FREE, RASTER_OUTSIDE, RASTER_WALL

__all__ = ["fill_cover", "reachable_from", "skip_and_clearance"]


@njit(cache=True, nogil=True)
def fill_cover(rows, col_a, col_b, weight, h, w, wall_weight):  # pragma: no cover - compiled
    """The raster's cells from the spans of its rings: outside, free (covered) or wall.

    Args:
        rows: ``(S,)`` int64 row of each span.
        col_a: ``(S,)`` int64 first column of each span, in ``[0, w]``.
        col_b: ``(S,)`` int64 column after each span's last, in ``[0, w]``.
        weight: ``(S,)`` int64 weight of each span's ring.
        h: Rows of the grid.
        w: Columns of the grid.
        wall_weight: Cover at or above which a cell is a wall.

    Returns:
        ``(h, w)`` uint8 raster codes: a cell covered by a total weight above 0 is free, at or
        above ``wall_weight`` a wall, else outside.
    """
    diff = np.zeros((h, w + 1), dtype=np.int32)
    for s in range(rows.shape[0]):
        diff[rows[s], col_a[s]] += weight[s]
        diff[rows[s], col_b[s]] -= weight[s]
    grid = np.empty((h, w), dtype=np.uint8)
    for r in range(h):
        cover = 0
        for c in range(w):
            cover += diff[r, c]
            if cover >= wall_weight:
                grid[r, c] = RASTER_WALL
            elif cover > 0:
                grid[r, c] = RASTER_FREE
            else:
                grid[r, c] = RASTER_OUTSIDE
    return grid


@njit(cache=True, nogil=True)
def reachable_from(grid, row, col):  # pragma: no cover - compiled
    """The free cells joined to free cell ``(row, col)`` through free 4-neighbours.

    A scanline fill: each seed is widened to its whole run of free cells along the row, and
    the rows above and below get one seed per free run that touches it. The pending seeds fit
    in a few thousand entries; a fill that needs more starts again with twice the room.

    Args:
        grid: ``(H, W)`` uint8 raster codes.
        row: Row of the start cell (a free cell).
        col: Column of the start cell.

    Returns:
        ``(H, W)`` bool, ``True`` on the start's component.
    """
    room = 4096
    while True:
        out = np.zeros(grid.shape, dtype=np.bool_)
        if _fill(grid, row, col, out, np.empty(room, dtype=np.int32), np.empty(room, dtype=np.int32)):
            return out
        room *= 2


@njit(cache=True, nogil=True)
def _fill(grid, row, col, out, rows, cols):  # pragma: no cover - compiled
    """:func:`reachable_from` into ``out`` with seed stacks ``rows``, ``cols``; False if they overflow."""
    h, w = grid.shape
    rows[0] = row
    cols[0] = col
    top = 1
    while top > 0:
        top -= 1
        r = rows[top]
        c = cols[top]
        if out[r, c]:
            continue
        a = c
        while a > 0 and grid[r, a - 1] == RASTER_FREE and not out[r, a - 1]:
            a -= 1
        b = c
        while b + 1 < w and grid[r, b + 1] == RASTER_FREE and not out[r, b + 1]:
            b += 1
        for q in range(a, b + 1):
            out[r, q] = True
        for rr in (r - 1, r + 1):
            if rr < 0 or rr >= h:
                continue
            inside = False
            for cc in range(a, b + 1):
                ok = grid[rr, cc] == RASTER_FREE and not out[rr, cc]
                if ok and not inside:
                    if top == rows.shape[0]:
                        return False
                    rows[top] = rr
                    cols[top] = cc
                    top += 1
                inside = ok
    return True


@njit(cache=True, nogil=True)
def skip_and_clearance(grid, dist, safety, skip_wall, skip_outside, half, res):  # pragma: no cover
    """The raycaster's skip field and the world's clearance, from the distance field, in one pass.

    Float32 arithmetic throughout, as the NumPy expressions these replace compute it.

    Args:
        grid: ``(H, W)`` uint8 raster codes.
        dist: ``(H, W)`` float32 distance from each cell's centre to the nearest obstacle
            cell's centre (cells).
        safety: float32 margin (cells) taken off the distance for a safe jump.
        skip_wall: Skip code of a wall cell (free cells hold at most ``skip_wall - 1``).
        skip_outside: Skip code of an outside cell.
        half: float32 0.5: from a cell's centre to the obstacle cell's edge (cells).
        res: float32 side of a cell (m).

    Returns:
        ``(skip uint8, clearance float32 m)``, both ``(H, W)``.
    """
    h, w = grid.shape
    skip = np.empty((h, w), dtype=np.uint8)
    clearance = np.empty((h, w), dtype=np.float32)
    top = np.float32(skip_wall - 1)
    zero = np.float32(0.0)
    for r in range(h):
        for c in range(w):
            d = dist[r, c]
            code = grid[r, c]
            if code == RASTER_WALL:
                skip[r, c] = skip_wall
            elif code == RASTER_OUTSIDE:
                skip[r, c] = skip_outside
            else:
                skip[r, c] = np.uint8(min(max(np.floor(d - safety), zero), top))
            clearance[r, c] = max(d - half, zero) * res
    return skip, clearance
