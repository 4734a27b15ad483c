"""Numba kernels of a world's build: the raster's fill, the reachable floor, the skip field.

Each replaces a chain of whole-grid NumPy passes (temporary arrays of 8 bytes per cell) by one
pass that writes the result, with the same values: a new building per episode pays for them.
Private to :mod:`realistic_indoor.sim`; :mod:`realistic_indoor.sim.raster` imports it lazily so
that a map export does not load numba.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from realistic_indoor.sim._edt import column_squares, row_distances, row_scratch
from realistic_indoor.sim.cells import RASTER_FREE, RASTER_OUTSIDE, RASTER_WALL

__all__ = [
    "clear_at_least",
    "fill_cover",
    "reachable_from",
    "ring_spans",
    "skip_and_clearance",
    "skip_and_clearance_of",
]


@njit(cache=True, nogil=True)
def ring_spans(start, end, ring_first, ring_size, h, w):  # pragma: no cover - compiled
    """The spans of cells whose centres lie inside each ring, row by row (a scanline fill).

    A ring covers row ``r`` where its edges cross the line through the row's cell centres;
    an edge from ``y0`` to ``y1`` crosses the rows ``ceil(min) <= r < ceil(max)``. The
    crossings of one ring on one row, in increasing ``x``, pair up into spans (even-odd).

    Args:
        start: ``(E, 2)`` float64 first vertex of each edge, in cell-centre units (cell
            ``(r, c)``'s centre is ``(c, r)``).
        end: ``(E, 2)`` float64 second vertex of each edge.
        ring_first: ``(R,)`` int64 index of each ring's first edge; a ring's edges are
            consecutive.
        ring_size: ``(R,)`` int64 number of edges of each ring.
        h: Rows of the grid.
        w: Columns of the grid.

    Returns:
        ``(row, col_a, col_b, ring)`` int64 arrays, one entry per span: its row, its first
        column and the column after its last (both in ``[0, w]``) and its ring, ordered by
        ring, then row, then column.
    """
    n_edges = start.shape[0]
    r0 = np.empty(n_edges, dtype=np.int64)
    r1 = np.empty(n_edges, dtype=np.int64)
    crossings = 0
    for e in range(n_edges):
        lo, hi = min(start[e, 1], end[e, 1]), max(start[e, 1], end[e, 1])
        r0[e] = min(max(np.ceil(lo), 0.0), h)
        r1[e] = min(max(np.ceil(hi), 0.0), h)
        crossings += r1[e] - r0[e]
    n = crossings // 2
    rows = np.empty(n, dtype=np.int64)
    col_a = np.empty(n, dtype=np.int64)
    col_b = np.empty(n, dtype=np.int64)
    ring = np.empty(n, dtype=np.int64)
    xs = np.empty(max(ring_size.max(), 1) if ring_size.shape[0] else 1)
    k = 0
    for i in range(ring_first.shape[0]):
        first, last = ring_first[i], ring_first[i] + ring_size[i]
        for row in range(r0[first:last].min(), r1[first:last].max()):
            m = _row_crossings(start, end, r0, r1, first, last, row, xs)
            for j in range(0, m - 1, 2):
                rows[k], ring[k] = row, i
                col_a[k] = min(max(np.ceil(xs[j]), 0.0), w)
                col_b[k] = min(max(np.ceil(xs[j + 1]), 0.0), w)
                k += 1
    return rows[:k], col_a[:k], col_b[:k], ring[:k]


@njit(cache=True, nogil=True, inline="always")
def _row_crossings(start, end, r0, r1, first, last, row, xs):  # pragma: no cover - compiled
    """The ``x`` where edges ``first..last-1`` cross ``row``, sorted into ``xs``; their number."""
    m = 0
    for e in range(first, last):
        if r0[e] <= row < r1[e]:
            sx, sy, ex, ey = start[e, 0], start[e, 1], end[e, 0], end[e, 1]
            x = sx + (row - sy) * (ex - sx) / (ey - sy)
            j = m
            while j > 0 and xs[j - 1] > x:  # insertion sort: a few crossings per row
                xs[j] = xs[j - 1]
                j -= 1
            xs[j] = x
            m += 1
    return m


@njit(cache=True, nogil=True)
def fill_cover(rows, col_a, col_b, weight, h, w, wall_weight):  # pragma: no cover - compiled
    """The raster's cells from the spans of its rings: outside, free (covered) or wall.

    Row by row: the row's span ends, sorted by column, split it into stretches of equal
    cover, each filled with its code at once.

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
    row_start, order = _by_row(rows, h)
    widest = 0
    for r in range(h):
        widest = max(widest, row_start[r + 1] - row_start[r])
    at = np.empty(2 * widest, dtype=np.int64)
    change = np.empty(2 * widest, dtype=np.int64)
    grid = np.empty((h, w), dtype=np.uint8)
    for r in range(h):
        m = 0
        for i in range(row_start[r], row_start[r + 1]):
            s = order[i]
            m = _insert_event(at, change, m, col_a[s], weight[s])
            m = _insert_event(at, change, m, col_b[s], -weight[s])
        cover = 0
        c = 0
        for i in range(m):
            if at[i] > c:
                grid[r, c : at[i]] = _code(cover, wall_weight)
                c = at[i]
            cover += change[i]
        grid[r, c:w] = _code(cover, wall_weight)
    return grid


@njit(cache=True, nogil=True)
def _by_row(rows, h):  # pragma: no cover - compiled
    """Spans grouped by row (a counting sort): ``order[row_start[r]:row_start[r + 1]]`` are row ``r``'s."""
    row_start = np.zeros(h + 1, dtype=np.int64)
    for s in range(rows.shape[0]):
        row_start[rows[s] + 1] += 1
    for r in range(h):
        row_start[r + 1] += row_start[r]
    fill = row_start[:h].copy()
    order = np.empty(rows.shape[0], dtype=np.int64)
    for s in range(rows.shape[0]):
        order[fill[rows[s]]] = s
        fill[rows[s]] += 1
    return row_start, order


@njit(cache=True, nogil=True, inline="always")
def _insert_event(at, change, m, col, delta):  # pragma: no cover - compiled
    """Insert a change of cover at column ``col`` into the ``m`` sorted events; their new number."""
    j = m
    while j > 0 and at[j - 1] > col:
        at[j] = at[j - 1]
        change[j] = change[j - 1]
        j -= 1
    at[j] = col
    change[j] = delta
    return m + 1


@njit(cache=True, nogil=True, inline="always")
def _code(cover, wall_weight):  # pragma: no cover - compiled
    """The raster code of a cell under ``cover``."""
    if cover >= wall_weight:
        return RASTER_WALL
    return RASTER_FREE if cover > 0 else RASTER_OUTSIDE


@njit(cache=True, nogil=True)
def reachable_from(grid, row, col):  # pragma: no cover - compiled
    """The free cells joined to free cell ``(row, col)`` through free 4-neighbours.

    Works on runs of free cells along the rows rather than on cells: two runs of neighbouring
    rows that share a column are joined (union-find), and the runs of the start's component
    are written out. One read of the grid (usually) and one write of the result; the runs are
    few (a default office has about 6,000 for 870,000 cells).

    Args:
        grid: ``(H, W)`` uint8 raster codes.
        row: Row of the start cell (a free cell).
        col: Column of the start cell.

    Returns:
        ``(H, W)`` bool, ``True`` on the start's component.
    """
    run_row, first, last, row_start = _free_runs(grid)
    parent = np.arange(first.shape[0])
    for r in range(1, grid.shape[0]):
        _join_rows(first, last, row_start[r - 1], row_start[r], row_start[r + 1], parent)
    out = np.zeros(grid.shape, dtype=np.bool_)
    start = _run_at(first, last, row_start[row], row_start[row + 1], col)
    if start < 0:
        return out
    root = _root(parent, start)
    for i in range(first.shape[0]):
        if _root(parent, i) == root:
            out[run_row[i], first[i] : last[i] + 1] = True
    return out


@njit(cache=True, nogil=True)
def _free_runs(grid):  # pragma: no cover - compiled
    """Runs of free cells, row by row: ``(row, first column, last column, row_start)``.

    ``row_start[r]:row_start[r + 1]`` are the runs of row ``r``, in column order. One read of
    the grid into room for 16 runs per row (a default office has about 6); a grid with more
    is read again into arrays of the size the first read counted.
    """
    h = grid.shape[0]
    row_start = np.empty(h + 1, dtype=np.int64)
    first = np.empty(16 * h, dtype=np.int64)
    last = np.empty(16 * h, dtype=np.int64)
    row_start[0] = 0
    for r in range(h):
        row_start[r + 1] = row_start[r] + _runs_of_row(grid[r], first, last, row_start[r])
    n = row_start[h]
    if n > first.shape[0]:
        first = np.empty(n, dtype=np.int64)
        last = np.empty(n, dtype=np.int64)
        for r in range(h):
            _runs_of_row(grid[r], first, last, row_start[r])
    run_row = np.empty(n, dtype=np.int64)
    for r in range(h):
        run_row[row_start[r] : row_start[r + 1]] = r
    return run_row, first[:n], last[:n], row_start


@njit(cache=True, nogil=True, inline="always")
def _runs_of_row(codes, first, last, at):  # pragma: no cover - compiled
    """The number of runs of free cells in one row, stored from index ``at`` while they fit."""
    w = codes.shape[0]
    count = 0
    c = 0
    while c < w:
        if codes[c] != RASTER_FREE:
            c += 1
            continue
        a = c
        while c < w and codes[c] == RASTER_FREE:
            c += 1
        if at + count < first.shape[0]:
            first[at + count] = a
            last[at + count] = c - 1
        count += 1
    return count


@njit(cache=True, nogil=True)
def _join_rows(first, last, below, here, end, parent):  # pragma: no cover - compiled
    """Join each run ``below..here-1`` (a row) to the runs ``here..end-1`` (the next) it touches."""
    i, j = below, here
    while i < here and j < end:
        if first[i] <= last[j] and first[j] <= last[i]:
            _union(parent, i, j)
        if last[i] < last[j]:
            i += 1
        else:
            j += 1


@njit(cache=True, nogil=True)
def _run_at(first, last, lo, hi, col):  # pragma: no cover - compiled
    """Index of the run among ``lo..hi-1`` that holds column ``col``; -1 if none does."""
    for i in range(lo, hi):
        if first[i] <= col <= last[i]:
            return i
    return -1


@njit(cache=True, nogil=True, inline="always")
def _root(parent, i):  # pragma: no cover - compiled
    while parent[i] != i:
        parent[i] = parent[parent[i]]
        i = parent[i]
    return i


@njit(cache=True, nogil=True, inline="always")
def _union(parent, i, j):  # pragma: no cover - compiled
    a, b = _root(parent, i), _root(parent, j)
    if a != b:
        parent[max(a, b)] = min(a, b)


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
    stack_at, stack_height = row_scratch(w)
    for r in range(h):
        row_distances(squares[r], dist, stack_at, stack_height)
        _skip_row(grid[r], dist, skip[r], squares[r], safety, skip_wall, skip_outside, half, res)
    return skip, squares


@njit(cache=True, nogil=True)
def clear_at_least(grid, rows, cols, reach, half, res, least, out):  # pragma: no cover - compiled
    """Whether the clearance of each cell is at least ``least``, without the whole field.

    The clearance is the one :func:`skip_and_clearance_of` gives a free cell (:func:`_clearance`
    of the distance from its centre to the nearest non-free cell's centre; 0 off the free floor
    and off the grid), found among the cells at most ``reach`` rows and columns away, and
    compared with ``least`` in float32, as NumPy compares a float32 array with a Python float.
    A cell with no non-free cell within ``reach`` (so farther than ``reach`` cells) counts as
    clear: the caller picks ``reach`` so that such a cell's clearance is certainly at least
    ``least``.

    Args:
        grid: ``(H, W)`` uint8 raster codes.
        rows: ``(N,)`` int64 rows of the cells asked about (any value: off the grid is not clear).
        cols: ``(N,)`` int64 columns.
        reach: Search half-width (cells).
        half: float32 0.5 (cells).
        res: float32 side of a cell (m).
        least: float32 clearance asked for (m).
        out: ``(N,)`` bool, written.
    """
    h, w = grid.shape
    for i in range(rows.shape[0]):
        r, c = rows[i], cols[i]
        if r < 0 or c < 0 or r >= h or c >= w or grid[r, c] != RASTER_FREE:
            out[i] = least <= 0.0
            continue
        best = reach * reach + 1
        for rr in range(max(r - reach, 0), min(r + reach, h - 1) + 1):
            dr2 = (rr - r) * (rr - r)
            if dr2 >= best:
                continue
            row = grid[rr]
            for cc in range(max(c - reach, 0), min(c + reach, w - 1) + 1):
                if row[cc] != RASTER_FREE:
                    d2 = dr2 + (cc - c) * (cc - c)
                    if d2 < best:
                        best = d2
        if best > reach * reach:
            out[i] = True
            continue
        out[i] = _clearance(np.float32(np.sqrt(np.float64(best))), half, res) >= least


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
        clearance[c] = _clearance(d, half, res)


@njit(cache=True, nogil=True, inline="always")
def _clearance(d, half, res):  # pragma: no cover - compiled
    """A free cell's clearance (m, float32): ``d`` less half a cell, at least 0, times the side.

    ``d`` is the float32 distance (cells) from the cell's centre to the nearest non-free cell's.
    """
    return max(d - half, np.float32(0.0)) * res
