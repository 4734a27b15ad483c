"""Numba kernels of the robot's map: which cells a scan swept, marking them, the local view.

Geometry is in cell units: cell ``(r, c)`` spans ``[c, c + 1) x [r, r + 1)``, centre at
``(c + 0.5, r + 0.5)``. The fan's cells are marked row by row between the outline's crossings,
each beam's cells as it is walked; bits of 64 cells (:data:`WORD`) say which free cells are
still unknown, so that a row with none between its ends is passed over. The marking of a cell
is written out in the span loop and the walk: as a numba function of the arrays that is not
inlined, it made the map update four times slower.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from realistic_indoor.sim.cells import RASTER_FREE, RASTER_WALL

MAPPED_UNKNOWN, MAPPED_FREE, MAPPED_OCCUPIED = 0, 1, 2
"""States of a cell of the robot's map (uint8); a higher state wins when cells are pooled."""
TRUTH_WALL, TRUTH_OUTSIDE, TRUTH_FREE, TRUTH_REACHABLE = 0, 1, 2, 3
"""What the ground truth lets a beam mark in a cell: free only if ``>= TRUTH_FREE``."""
WORD = 64
"""Cells per word of the to-do bits: bit ``j`` of ``todo[r, w]`` is set while cell
``(r, WORD * w + j)`` is free in the ground truth and still unknown. A span tests a whole word
of cells at once and visits only the cells it marks (most of a scan covers known floor), and a
beam tests a bit of an array an eighth of the map's size."""
_DE_BRUIJN = 0x03F79D71B4CB0A89
"""A de Bruijn sequence of order 6: the top 6 bits of it times a power of two name the power."""
_LOWEST_BIT = np.zeros(64, dtype=np.int64)
_LOWEST_BIT[[((_DE_BRUIJN << j) & 0xFFFFFFFFFFFFFFFF) >> 58 for j in range(64)]] = np.arange(64)
"""Which bit a power of two is, by the top 6 bits of it times :data:`_DE_BRUIJN`."""
_NUDGE = 1e-3
"""Distance (cells) past a beam's end at which the wall cell it hit is looked up."""


def coverage_share(observed_cells: float, reachable_cells: float) -> float:
    """Observed share of the reachable floor, in ``[0, 1]``; 1 for a building with no reachable cell.

    The coverage rule of every environment (single, vector, team): cells observed over cells
    reachable from the start (both counts of map cells). Plain Python, for the single env's
    and the team's calls from Python (a compiled call costs half a microsecond more);
    :data:`coverage_share_compiled` is the same function for kernels.
    """
    return observed_cells / reachable_cells if reachable_cells > 0 else 1.0


coverage_share_compiled = njit(cache=True, nogil=True)(coverage_share)
""":func:`coverage_share`, compiled for the kernels."""


@njit(cache=True, nogil=True)
def integrate_scan(
    grid,
    pooled,
    k,
    targets,
    todo,
    walls,
    px,
    py,
    cos_h,
    sin_h,
    cos_off,
    sin_off,
    range_m,
    kind,
    scale,
    closed,
):  # pragma: no cover - compiled
    """Mark what one scan saw; return the number of reachable cells observed for the first time.

    Free: the cells whose centre lies in the fan the beams swept (between each two neighbouring
    beams, up to the shorter of their ranges) plus the cells each beam crosses. Occupied: the
    wall cell each returned beam ends in. Ranges are in metres, ``scale`` is cells per metre;
    ``todo`` holds the map's to-do bits (:func:`todo_bits` of ``targets`` for an empty map),
    which every cell marked free clears; ``walls`` the same for the wall cells not yet marked
    (:func:`wall_bits`), so a beam ending on a known wall reads one bit, not the map.
    """
    n = cos_off.shape[0]
    dxs = np.empty(n)
    dys = np.empty(n)
    ts = np.empty(n)
    for i in range(n):
        dxs[i] = cos_h * cos_off[i] - sin_h * sin_off[i]
        dys[i] = sin_h * cos_off[i] + cos_h * sin_off[i]
        ts[i] = range_m[i] * scale
    h, w = grid.shape
    if n > 1:
        vx, vy = _fan_outline(px, py, dxs, dys, ts, closed)
        new = _mark_fan(grid, pooled, k, targets, todo, vx, vy)
    else:
        new = 0
    new += _mark_beams(grid, pooled, k, targets, todo, px, py, dxs, dys, ts, closed)
    for i in range(n):
        if kind[i] == RASTER_WALL:
            c = math.floor(px + (ts[i] + _NUDGE) * dxs[i])
            r = math.floor(py + (ts[i] + _NUDGE) * dys[i])
            if not (0 <= r < h and 0 <= c < w):
                continue
            bit = np.int64(1) << (c % WORD)
            if walls[r, c // WORD] & bit:
                walls[r, c // WORD] ^= bit
                grid[r, c] = MAPPED_OCCUPIED
                pooled[r // k, c // k] = MAPPED_OCCUPIED
    return new


@njit(cache=True, nogil=True, inline="always")
def _mark_span(grid, pooled, k, targets, todo, r, c, end):  # pragma: no cover - compiled
    """Mark free the cells still to do in columns ``[c, end)`` of row ``r``; the new reachable ones."""
    new = 0
    while c < end:  # word by word: only the cells still to mark are visited
        word = c // WORD
        stop = min(end, (word + 1) * WORD)
        bits = todo[r, word] & _bit_range(c - word * WORD, stop - word * WORD)
        if bits != 0:
            todo[r, word] ^= bits
            base = word * WORD
            while bits != 0:
                low = bits & -bits  # the lowest set bit; the product wraps, ">>" keeps the sign
                cc = base + _LOWEST_BIT[((low * _DE_BRUIJN) >> 58) & 63]
                bits ^= low
                grid[r, cc] = MAPPED_FREE
                if pooled[r // k, cc // k] == MAPPED_UNKNOWN:
                    pooled[r // k, cc // k] = MAPPED_FREE
                if targets[r, cc] == TRUTH_REACHABLE:
                    new += 1
        c = stop
    return new


@njit(cache=True, nogil=True, inline="always")
def _any_to_do(todo, r, c, end):  # pragma: no cover - compiled
    """Whether any cell of columns ``[c, end)`` of row ``r`` is still to do (``c < end``)."""
    last = (end - 1) // WORD
    for word in range(c // WORD, last + 1):
        lo = max(c - word * WORD, 0)
        hi = min(end - word * WORD, WORD)
        if todo[r, word] & _bit_range(lo, hi):
            return True
    return False


@njit(cache=True, nogil=True, inline="always")
def _bit_range(lo, hi):  # pragma: no cover - compiled
    """An int64 whose bits ``lo <= j < hi`` are set (``0 <= lo < hi <= WORD``)."""
    upper = np.int64(-1) if hi == WORD else (np.int64(1) << hi) - 1
    return upper & (np.int64(-1) << lo)


@njit(cache=True, nogil=True)
def map_targets(grid, reachable):  # pragma: no cover - compiled
    """What a beam may mark in each cell (``TRUTH_*``) from the raster codes and reachable cells."""
    h, w = grid.shape
    out = np.empty((h, w), dtype=np.uint8)
    for r in range(h):
        for c in range(w):
            if reachable[r, c]:
                out[r, c] = TRUTH_REACHABLE
            elif grid[r, c] == RASTER_FREE:
                out[r, c] = TRUTH_FREE
            elif grid[r, c] == RASTER_WALL:
                out[r, c] = TRUTH_WALL
            else:
                out[r, c] = TRUTH_OUTSIDE
    return out


def todo_bits(targets: np.ndarray) -> np.ndarray:
    """The to-do bits of an empty map: a bit set for each free cell (``targets >= TRUTH_FREE``).

    Returns:
        ``(H, ceil(W / WORD))`` int64, bit ``j`` of word ``w`` for column ``WORD * w + j``.
    """
    return start_bits(targets)[0]


def wall_bits(targets: np.ndarray) -> np.ndarray:
    """The wall bits of an empty map: a bit set for each wall cell (``targets == TRUTH_WALL``).

    Returns:
        ``(H, ceil(W / WORD))`` int64, as :func:`todo_bits`.
    """
    return start_bits(targets)[1]


@njit(cache=True, nogil=True)
def start_bits(targets):  # pragma: no cover - compiled
    """An empty map's to-do and wall bits (:func:`todo_bits`, :func:`wall_bits`) in one pass.

    Each word is gathered in a register and stored once (an ``|=`` into the array for every
    cell made the loop wait on its own stores: six times slower).

    Returns:
        ``(todo, walls)``: ``(H, ceil(W / WORD))`` int64 each.
    """
    h, w = targets.shape
    n_words = (w + WORD - 1) // WORD
    todo = np.empty((h, n_words), dtype=np.int64)
    walls = np.empty((h, n_words), dtype=np.int64)
    for r in range(h):
        row = targets[r]
        for word in range(n_words):
            base = word * WORD
            free = np.int64(0)
            wall = np.int64(0)
            for j in range(min(WORD, w - base)):
                v = row[base + j]
                free |= np.int64(v >= TRUTH_FREE) << j
                wall |= np.int64(v == TRUTH_WALL) << j
            todo[r, word] = free
            walls[r, word] = wall
    return todo, walls


@njit(cache=True, nogil=True)
def unknown_bits(cells, out):  # pragma: no cover - compiled
    """Write into ``out`` the to-do bits of the cells of a map still unknown.

    Args:
        cells: ``(H, W)`` uint8 ``MAPPED_*`` cells (any memory layout: a window of a larger map).
        out: ``(H, ceil(W / WORD))`` int64, written: bit ``j`` of word ``w`` of row ``r`` set
            where ``cells[r, WORD * w + j]`` is :data:`MAPPED_UNKNOWN`.
    """
    h, w = cells.shape
    n_words = out.shape[1]
    for r in range(h):
        for word in range(n_words):
            base = word * WORD
            bits = np.int64(0)
            for j in range(min(WORD, w - base)):
                bits |= np.int64(cells[r, base + j] == MAPPED_UNKNOWN) << j
            out[r, word] = bits


@njit(cache=True, nogil=True)
def _fan_outline(px, py, dxs, dys, ts, closed):  # pragma: no cover - compiled
    """Outline of the fan: for each two neighbouring beams, both at the shorter range.

    Cutting each wedge at the shorter range keeps what hides behind a corner between two
    beams from counting as seen. An open fan (less than a full turn) starts at the sensor.
    """
    n = dxs.shape[0]
    pairs = n if closed else n - 1
    first = 0 if closed else 1
    vx = np.empty(2 * pairs + first)
    vy = np.empty(2 * pairs + first)
    vx[0] = px
    vy[0] = py
    for i in range(pairs):
        j = (i + 1) % n
        t = min(ts[i], ts[j])
        o = first + 2 * i
        vx[o] = px + t * dxs[i]
        vy[o] = py + t * dys[i]
        vx[o + 1] = px + t * dxs[j]
        vy[o + 1] = py + t * dys[j]
    return vx, vy


@njit(cache=True, nogil=True)
def _mark_fan(grid, pooled, k, targets, todo, vx, vy):  # pragma: no cover - compiled
    """Mark free the cells still to do whose centre lies in the fan's outline; the new reachable ones.

    A scanline fill that looks only at the rows it may mark: along a drive about 3 of some 300
    rows of a scan hold a cell still to do. One pass over the outline keeps each row's leftmost
    and rightmost crossing; a row's crossings are gathered, sorted and paired into spans only
    when a cell between those two is still to do: edge by edge for each such row when they are
    few, by one counting sort of every row's crossings (:func:`_row_crossings`) when many are
    (a scan into unexplored floor).

    Args:
        grid: ``(H, W)`` uint8 map, marked :data:`MAPPED_FREE` where a cell is marked.
        pooled: The pooled map (``k x k`` cells to a pixel), kept up to date.
        k: Cells per side of a pooled cell.
        targets: ``(H, W)`` uint8 ``TRUTH_*`` of each cell.
        todo: The map's to-do bits, cleared for the cells marked.
        vx: ``(N,)`` outline x (cells), in order around the fan.
        vy: ``(N,)`` outline y (cells).

    Returns:
        The number of reachable cells marked.
    """
    h, w = grid.shape
    nv = vx.shape[0]
    rc, r_lo, n_rows = _outline_rows(vy, h)
    left = np.full(n_rows, np.inf)
    right = np.full(n_rows, -np.inf)
    crossings = 0
    for e in range(nv):
        f, ra, rb = _edge_rows(rc, e, r_lo, r_lo + n_rows)
        if rb > ra:
            slope = _slope(vx, vy, e, f)
            for r in range(ra, rb):
                x = _crossing(vx, vy, e, slope, r)
                left[r - r_lo] = min(left[r - r_lo], x)
                right[r - r_lo] = max(right[r - r_lo], x)
            crossings += rb - ra
    rows = np.empty(n_rows, dtype=np.int64)  # the rows with a cell still to do between their ends
    n = 0
    for i in range(n_rows):
        if left[i] > right[i]:  # no crossing
            continue
        c0 = max(_ceil(left[i] - 0.5), 0)
        c1 = min(_ceil(right[i] - 0.5), w)
        if c1 > c0 and _any_to_do(todo, r_lo + i, c0, c1):
            rows[n] = r_lo + i
            n += 1
    new = 0
    # edge by edge costs a row nv tests, the counting sort every row about 4 operations per
    # crossing (count, prefix, place, read): gather row by row while that is the cheaper
    if n * nv > 4 * crossings:
        _, start, xs = _row_crossings(vx, vy, h)
        for q in range(n):
            i = rows[q] - r_lo
            new += _mark_row(grid, pooled, k, targets, todo, rows[q], xs, start[i], start[i + 1])
        return new
    xs = np.empty(nv)  # a row crosses each edge at most once
    for q in range(n):
        r = rows[q]
        m = 0
        for e in range(nv):
            f, ra, rb = _edge_rows(rc, e, r_lo, r_lo + n_rows)
            if ra <= r < rb:
                xs[m] = _crossing(vx, vy, e, _slope(vx, vy, e, f), r)
                m += 1
        new += _mark_row(grid, pooled, k, targets, todo, r, xs, 0, m)
    return new


@njit(cache=True, nogil=True, inline="always")
def _mark_row(grid, pooled, k, targets, todo, r, xs, a, b):  # pragma: no cover - compiled
    """Mark the spans of row ``r`` between its crossings ``xs[a:b]`` (sorted in place); the new ones."""
    w = grid.shape[1]
    _sort_small(xs, a, b)
    new = 0
    for j in range(a, b - 1, 2):
        c0 = max(_ceil(xs[j] - 0.5), 0)
        c1 = min(_ceil(xs[j + 1] - 0.5), w)
        new += _mark_span(grid, pooled, k, targets, todo, r, c0, c1)
    return new


@njit(cache=True, nogil=True, inline="always")
def _edge_rows(rc, e, r_lo, r_hi):  # pragma: no cover - compiled
    """The outline's edge from vertex ``e``: its end vertex and the rows ``[ra, rb)`` it crosses.

    ``rc`` are the vertices' rows (:func:`_outline_rows`); rows are clipped to ``[r_lo, r_hi)``.
    """
    f = e + 1 if e + 1 < rc.shape[0] else 0
    return f, max(min(rc[e], rc[f]), r_lo), min(max(rc[e], rc[f]), r_hi)


@njit(cache=True, nogil=True, inline="always")
def _slope(vx, vy, e, f):  # pragma: no cover - compiled
    """Columns per row along the outline's edge from vertex ``e`` to vertex ``f``."""
    return (vx[f] - vx[e]) / (vy[f] - vy[e])


@njit(cache=True, nogil=True, inline="always")
def _crossing(vx, vy, e, slope, r):  # pragma: no cover - compiled
    """Where the edge from vertex ``e`` (of ``slope``) crosses row ``r``'s centre line (column).

    The one formula of every crossing, so that the row tests and the spans agree to the bit.
    """
    return vx[e] + (r + 0.5 - vy[e]) * slope


@njit(cache=True, nogil=True, inline="always")
def _outline_rows(vy, h):  # pragma: no cover - compiled
    """Each vertex's first row whose centre is not below it, and the rows the outline spans.

    Returns:
        ``(rc, r_lo, n_rows)``: ``(N,)`` int64 rows of the vertices; the first row and the
        number of rows between the lowest and highest vertex, clipped to an ``h``-row grid.
    """
    nv = vy.shape[0]
    rc = np.empty(nv, dtype=np.int64)
    lo, hi = h, 0
    for v in range(nv):
        rc[v] = _ceil(vy[v] - 0.5)
        lo = min(lo, rc[v])
        hi = max(hi, rc[v])
    r_lo = max(lo, 0)
    return rc, r_lo, max(min(hi, h) - r_lo, 0)


@njit(cache=True, nogil=True)
def _row_crossings(vx, vy, h):  # pragma: no cover - compiled
    """Where a polygon's outline crosses the centre line of each row of an ``h``-row grid.

    Each edge drops its crossings into per-row buckets (a counting sort): the cost grows with
    the perimeter (in rows) plus the rows, not with edges times rows.

    Returns:
        ``(r_lo, start, xs)``: the crossings of row ``r_lo + i`` are ``xs[start[i]:start[i + 1]]``
        (columns, in edge order), for the rows between the outline's lowest and highest.
    """
    nv = vx.shape[0]
    rc, r_lo, n_rows = _outline_rows(vy, h)
    r_hi = r_lo + n_rows
    start = np.zeros(n_rows + 1, dtype=np.int64)
    for e in range(nv):
        _, ra, rb = _edge_rows(rc, e, r_lo, r_hi)
        for r in range(ra, rb):
            start[r - r_lo + 1] += 1
    for i in range(n_rows):
        start[i + 1] += start[i]
    nxt = start[:-1].copy()
    xs = np.empty(start[n_rows])
    for e in range(nv):
        f, ra, rb = _edge_rows(rc, e, r_lo, r_hi)
        if rb > ra:
            slope = _slope(vx, vy, e, f)
            for r in range(ra, rb):
                xs[nxt[r - r_lo]] = _crossing(vx, vy, e, slope, r)
                nxt[r - r_lo] += 1
    return r_lo, start, xs


@njit(cache=True, nogil=True, inline="always")
def _ceil(x):  # pragma: no cover - compiled
    """``math.ceil`` of a finite float as an int64, without calling the C library's ``ceil``."""
    c = np.int64(x)  # truncation: the ceiling of a negative x, the floor of a positive one
    return c + 1 if c < x else c


@njit(cache=True, nogil=True)
def _sort_small(xs, a, b):  # pragma: no cover - compiled
    """Insertion sort of ``xs[a:b]`` in place (a row holds a handful of crossings)."""
    for j in range(a + 1, b):
        x = xs[j]
        m = j - 1
        while m >= a and xs[m] > x:
            xs[m + 1] = xs[m]
            m -= 1
        xs[m + 1] = x


@njit(cache=True, nogil=True)
def _mark_beams(grid, pooled, k, targets, todo, px, py, dxs, dys, ts, closed):  # pragma: no cover - compiled
    """Mark the cells each beam crosses beyond the fan (where the fan stops); return the new ones.

    A beam is walked from one cell short of the shorter of its neighbours' ranges (a lone beam,
    with no fan beside it, from the sensor) to its own end. (Testing first whether any cell
    near the stretch is still to do was slower: two thirds of the walks are under three cells,
    and a long one's box spans many rows.)
    """
    n = dxs.shape[0]
    h, w = grid.shape
    new = 0
    for i in range(n):
        t0 = 0.0
        if n > 1:
            t0 = ts[i]
            if i > 0 or closed:
                t0 = min(t0, ts[i - 1])
            if i < n - 1 or closed:
                t0 = min(t0, ts[(i + 1) % n])
            t0 = max(t0 - 1.0, 0.0)
        new += _walk_and_mark(grid, pooled, k, targets, todo, px, py, dxs[i], dys[i], t0, ts[i], h, w)
    return new


@njit(cache=True, nogil=True)
def _walk_and_mark(grid, pooled, k, targets, todo, px, py, dx, dy, t0, t1, h, w):  # pragma: no cover
    """Mark the cells a ray crosses between ``t0`` and ``t1`` (exact grid traversal)."""
    x = px + t0 * dx
    y = py + t0 * dy
    c = math.floor(x)
    r = math.floor(y)
    step_c = 1 if dx > 0 else -1
    step_r = 1 if dy > 0 else -1
    t_dc = abs(1.0 / dx) if dx != 0.0 else 1e30
    t_dr = abs(1.0 / dy) if dy != 0.0 else 1e30
    t_c = t0 + ((c + 1 - x) if dx > 0 else (x - c)) * t_dc if dx != 0.0 else 1e30
    t_r = t0 + ((r + 1 - y) if dy > 0 else (y - r)) * t_dr if dy != 0.0 else 1e30
    new = 0
    while 0 <= r < h and 0 <= c < w:
        bit = np.int64(1) << (c % WORD)
        if todo[r, c // WORD] & bit:
            grid[r, c] = MAPPED_FREE
            todo[r, c // WORD] ^= bit
            if pooled[r // k, c // k] == MAPPED_UNKNOWN:
                pooled[r // k, c // k] = MAPPED_FREE
            if targets[r, c] == TRUTH_REACHABLE:
                new += 1
        if min(t_c, t_r) >= t1:
            break
        if t_c < t_r:
            c += step_c
            t_c += t_dc
        else:
            r += step_r
            t_r += t_dr
    return new


@njit(cache=True, nogil=True)
def render_local(pooled, lut, px, py, cos_h, sin_h, step, out):  # pragma: no cover - compiled
    """Sample the pooled map on a square grid turned to the heading (pooled-cell units).

    Pixel ``(0, 0)`` is ahead and to the left; pixels off the map show ``lut[MAPPED_UNKNOWN]``.
    Rows are sampled two at a time, so that the two rows' running sums overlap instead of each
    pixel waiting on the previous one's.
    """
    s = out.shape[0]
    half = (s - 1) / 2.0
    unknown = lut[MAPPED_UNKNOWN]
    col_dx = step * sin_h  # one pixel to the right: the heading turned clockwise
    col_dy = -step * cos_h
    for i in range(0, s - 1, 2):
        xa, ya = _row_start(px, py, cos_h, sin_h, step, half, i, col_dx, col_dy)
        xb, yb = _row_start(px, py, cos_h, sin_h, step, half, i + 1, col_dx, col_dy)
        for j in range(s):
            out[i, j] = _pixel(pooled, lut, xa, ya, unknown)
            out[i + 1, j] = _pixel(pooled, lut, xb, yb, unknown)
            xa += col_dx
            ya += col_dy
            xb += col_dx
            yb += col_dy
    if s % 2:
        x, y = _row_start(px, py, cos_h, sin_h, step, half, s - 1, col_dx, col_dy)
        for j in range(s):
            out[s - 1, j] = _pixel(pooled, lut, x, y, unknown)
            x += col_dx
            y += col_dy


@njit(cache=True, nogil=True, inline="always")
def _row_start(px, py, cos_h, sin_h, step, half, i, col_dx, col_dy):  # pragma: no cover - compiled
    """Where row ``i`` of the local view starts (its left pixel), in pooled-cell units."""
    ahead = (half - i) * step
    return px + ahead * cos_h - half * col_dx, py + ahead * sin_h - half * col_dy


@njit(cache=True, nogil=True, inline="always")
def _pixel(pooled, lut, x, y, unknown):  # pragma: no cover - compiled
    """The grey level at ``(x, y)`` (pooled-cell units): ``unknown`` off the map.

    The cell's indices as unsigned integers: a negative one wraps to a huge one, so one
    comparison per axis tests both ends, and indexing needs no check for negative indices.
    Coordinates must be finite (a pose's always are): the integer of a NaN or of a float beyond
    the int64 range is the processor's choice.
    """
    c = np.uint64(np.int64(math.floor(x)))
    r = np.uint64(np.int64(math.floor(y)))
    if c < np.uint64(pooled.shape[1]) and r < np.uint64(pooled.shape[0]):
        return lut[pooled[r, c]]
    return unknown


@njit(cache=True, nogil=True)
def scatter_global(pooled, rx, ry, cos0, sin0, scale, free, wall):  # pragma: no cover - compiled
    """Mark the pixels of a fixed-orientation image that hold known free and wall cells.

    The image is centred on ``(rx, ry)`` (pooled-cell units) with the direction ``(cos0, sin0)``
    up; ``scale`` is pixels per pooled cell. Each known pooled cell sets ``wall`` (occupied) or
    ``free`` (free) to 255 at the pixel its centre falls in; pixels are not cleared first.
    """
    h, w = pooled.shape
    s = free.shape[0]
    half = s / 2.0
    for i in range(h):
        dy = i + 0.5 - ry
        for j in range(w):
            state = pooled[i, j]
            if state == MAPPED_UNKNOWN:
                continue
            dx = j + 0.5 - rx
            ahead = (dx * cos0 + dy * sin0) * scale
            left = (dy * cos0 - dx * sin0) * scale
            r = math.floor(half - ahead)
            c = math.floor(half - left)
            if 0 <= r < s and 0 <= c < s:
                if state == MAPPED_OCCUPIED:
                    wall[r, c] = 255
                else:
                    free[r, c] = 255


@njit(cache=True, nogil=True)
def merge_maps(grid, pooled, k, targets, todo, walls, src_todo, src_walls):  # pragma: no cover - compiled
    """Mark in a map what another map of the same world knows and it does not (a map merge).

    The cells the other map marked free (its to-do bit cleared, this map's still set) become
    free here, and its marked walls occupied, by the rules the scans follow (pooled cells
    included), with this map's bits cleared for them. Word by word: only the cells that differ
    are visited.

    Returns:
        The reachable floor cells newly marked free here (what :attr:`Batch.observed` counts).
    """
    h, n_words = todo.shape
    reachable = 0
    for r in range(h):
        for word in range(n_words):
            bits = todo[r, word] & ~src_todo[r, word]
            todo[r, word] ^= bits
            reachable += _mark_bits(grid, pooled, k, targets, r, word * WORD, bits, MAPPED_FREE)
            bits = walls[r, word] & ~src_walls[r, word]
            walls[r, word] ^= bits
            _mark_bits(grid, pooled, k, targets, r, word * WORD, bits, MAPPED_OCCUPIED)
    return reachable


@njit(cache=True, nogil=True, inline="always")
def _mark_bits(grid, pooled, k, targets, r, base, bits, state):  # pragma: no cover - compiled
    """Mark ``state`` on the cells of row ``r`` whose bits are set (column ``base`` + bit); the reachable free ones."""
    reachable = 0
    while bits != 0:
        low = bits & -bits  # the lowest set bit; the product wraps, ">>" keeps the sign
        c = base + _LOWEST_BIT[((low * _DE_BRUIJN) >> 58) & 63]
        bits ^= low
        grid[r, c] = state
        if state == MAPPED_OCCUPIED or pooled[r // k, c // k] == MAPPED_UNKNOWN:
            pooled[r // k, c // k] = state
        if state == MAPPED_FREE and targets[r, c] == TRUTH_REACHABLE:
            reachable += 1
    return reachable
