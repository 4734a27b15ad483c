"""Numba kernels of a world's build: the raster's fill, the reachable floor, the skip field.

Each replaces a chain of whole-grid NumPy passes (temporary arrays of 8 bytes per cell) by one
pass that writes the result, with the same values: a new building per episode pays for them.
Private to :mod:`realistic_indoor.sim`; :mod:`realistic_indoor.sim.raster` imports it lazily so
that a map export does not load numba.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from realistic_indoor.sim._edt import column_squares, row_distances
from realistic_indoor.sim.raster import RASTER_FREE, RASTER_OUTSIDE, RASTER_WALL

__all__ = ["fill_cover", "reachable_from", "skip_and_clearance", "skip_and_clearance_of"]


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
    for r in range(h):
        _skip_row(grid[r], dist[r], skip[r], clearance[r], safety, skip_wall, skip_outside, half, res)
    return skip, clearance


@njit(cache=True, nogil=True)
def skip_and_clearance_of(grid, safety, skip_wall, skip_outside, half, res):  # pragma: no cover
    """:func:`skip_and_clearance` straight from the raster, its distance field never stored.

    The distance transform's row pass (:func:`~realistic_indoor.sim._edt.row_distances`)
    fills one row at a time, which becomes that row of both fields at once; the clearance is
    written over the column pass's squares, whose row is no longer needed.

    Args:
        grid: ``(H, W)`` uint8 raster codes; free cells are :data:`RASTER_FREE`, others obstacles.
        safety: As for :func:`skip_and_clearance`.
        skip_wall: As for :func:`skip_and_clearance`.
        skip_outside: As for :func:`skip_and_clearance`.
        half: As for :func:`skip_and_clearance`.
        res: As for :func:`skip_and_clearance`.

    Returns:
        ``(skip uint8, clearance float32 m)``, both ``(H, W)``: the values
        :func:`skip_and_clearance` gives with ``distance_field(grid != RASTER_FREE)``.
    """
    h, w = grid.shape
    squares = column_squares(grid, RASTER_FREE)
    skip = np.empty((h, w), dtype=np.uint8)
    dist = np.empty(w, dtype=np.float32)
    stack_at = np.empty(w, dtype=np.int64)
    stack_height = np.empty(w)
    for r in range(h):
        row_distances(squares[r], dist, stack_at, stack_height)
        _skip_row(grid[r], dist, skip[r], squares[r], safety, skip_wall, skip_outside, half, res)
    return skip, squares


@njit(cache=True, nogil=True, inline="always")
def _skip_row(codes, dist, skip, clearance, safety, skip_wall, skip_outside, half, res):  # pragma: no cover
    """One row of :func:`skip_and_clearance`: ``skip`` and ``clearance`` overwritten."""
    top = np.float32(skip_wall - 1)
    zero = np.float32(0.0)
    for c in range(codes.shape[0]):
        d = dist[c]
        code = codes[c]
        if code == RASTER_WALL:
            skip[c] = skip_wall
        elif code == RASTER_OUTSIDE:
            skip[c] = skip_outside
        else:
            skip[c] = np.uint8(min(max(np.floor(d - safety), zero), top))
        clearance[c] = max(d - half, zero) * res
