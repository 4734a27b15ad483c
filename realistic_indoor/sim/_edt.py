"""Exact Euclidean distance transform in numba (Meijster et al. 2000; Felzenszwalb & Huttenlocher).

Several times faster than ``scipy.ndimage.distance_transform_edt``, which also builds the
feature transform: the world's distance field is rebuilt with every new building. Private: use
:func:`realistic_indoor.sim.fields.distance_field`; :mod:`realistic_indoor.sim._world_kernels`
runs the same two passes and turns each row straight into the raycaster's skip field and the
world's clearance.
"""

from __future__ import annotations

import numpy as np
from numba import njit

__all__ = ["MAX_WIDTH", "column_squares", "distance_to_mask", "row_distances", "row_scratch"]

_INF = 1e20
_FAR = np.float32(1e10)
"""Distance (cells) of a cell with no obstacle cell in reach: the square root of ``_INF``."""
_MAX_STRETCHES = 32
"""Most stretches of equal column distance a run is solved by stretch; beyond, point by point."""
MAX_WIDTH = 2_000_000
"""Widest grid (cells) whose row pass stays exact: its integer products then fit in an int64."""


def distance_to_mask(obstacle: np.ndarray) -> np.ndarray:
    """Distance (in cells, centre to centre) from every cell to the nearest ``True`` cell.

    Args:
        obstacle: ``(H, W)`` bool array.

    Returns:
        ``(H, W)`` float32 array, 0 on obstacle cells; where there is no obstacle at all, 1e10.
    """
    return _edt(np.ascontiguousarray(obstacle, dtype=np.bool_))


@njit(cache=True, nogil=True)
def _edt(obstacle):  # pragma: no cover - compiled
    h, w = obstacle.shape
    squares = column_squares(obstacle, False)
    out = np.empty((h, w), dtype=np.float32)
    stack_at, stack_height = row_scratch(w)
    for r in range(h):
        row_distances(squares[r], out[r], stack_at, stack_height)
    return out


@njit(cache=True, nogil=True)
def column_squares(cells, free_value):  # pragma: no cover - compiled
    """Squared distance (cells²) from each cell to the nearest obstacle cell of its column.

    Args:
        cells: ``(H, W)`` array; a cell is an obstacle unless it holds ``free_value``.
        free_value: The value of free cells.

    Returns:
        ``(H, W)`` float32: 0 on obstacle cells, the square of the distance along the column
        to the nearest obstacle cell elsewhere (float32 arithmetic), 1e20 in a column without one.

    Raises:
        ValueError: If the grid is more than :data:`MAX_WIDTH` cells wide.
    """
    h, w = cells.shape
    if w > MAX_WIDTH:
        raise ValueError("the distance transform takes grids at most 2,000,000 cells wide")
    g = np.empty((h, w), dtype=np.float32)
    for c in range(w):
        g[0, c] = _INF if cells[0, c] == free_value else 0.0
    for r in range(1, h):  # sweeps row by row: contiguous memory
        for c in range(w):
            g[r, c] = g[r - 1, c] + 1.0 if cells[r, c] == free_value else 0.0
    for r in range(h - 2, -1, -1):  # upwards, squaring each row once the one below is final
        for c in range(w):
            g[r, c] = min(g[r, c], g[r + 1, c] + 1.0)
            g[r + 1, c] = _square(g[r + 1, c])
    for c in range(w):
        g[0, c] = _square(g[0, c])
    return g


@njit(cache=True, nogil=True, inline="always")
def _square(x):  # pragma: no cover - compiled
    return x * x if x < _INF else _INF


@njit(cache=True, nogil=True)
def row_scratch(w):  # pragma: no cover - compiled
    """The scratch arrays :func:`row_distances` takes for rows of ``w`` cells."""
    stack_at = np.empty(max(w, 4 * _MAX_STRETCHES), dtype=np.int64)
    stack_height = np.empty(max(w, _MAX_STRETCHES), dtype=np.int64)
    return stack_at, stack_height


@njit(cache=True, nogil=True)
def row_distances(squares, out, stack_at, stack_height):  # pragma: no cover - compiled
    """One row of the distance transform, from its cells' :func:`column_squares`.

    Each run of free cells is solved on its own, between the obstacle cells that bound it: no
    cell beyond them can be nearer. In a building the column distances along a run take a
    few values in long stretches (a room's middle: one), and the lower envelope of the
    stretches gives each cell its nearest one; runs of more stretches take the lower envelope
    of the parabolas ``(q - p)² + g(p)``. Both are built and read with integer products
    instead of the intersections' divisions: the squared distances are whole numbers, so
    either gives the exact minimum.

    Args:
        squares: ``(W,)`` float32 row of :func:`column_squares` (0 on obstacle cells).
        out: ``(W,)`` float32, overwritten with the distances (cells): 0 on obstacle cells,
            1e10 where no obstacle cell is in reach.
        stack_at: int64 scratch, from :func:`row_scratch`.
        stack_height: int64 scratch, from :func:`row_scratch`.
    """
    w = squares.shape[0]
    q = 0
    while q < w:
        if squares[q] == 0.0:
            out[q] = 0.0
            q += 1
            continue
        first = q
        level = squares[q]
        level_run = True  # every cell of the run at one column distance
        while q < w and squares[q] != 0.0:
            level_run &= squares[q] == level
            q += 1
        if level_run and first > 0 and q < w:
            _walled_level_run(out, first, q - 1, level)
            continue
        lo, hi = max(first - 1, 0), min(q, w - 1)
        if not _stretch_distances(squares, out, first, q - 1, lo, hi, stack_at, stack_height):
            _run_distances(squares, out, first, q - 1, lo, hi, stack_at, stack_height)


@njit(cache=True, nogil=True, inline="always")
def _walled_level_run(out, first, last, level):  # pragma: no cover - compiled
    """Distances of cells ``first..last``, all at column distance² ``level``, between obstacle cells.

    The most common run in a building (a room's row between its side walls): each cell is
    nearest to one of the two obstacle cells beside the run or to its own column's, which is
    what :func:`_stretch_distances` finds for these three stretches, without the envelope.
    """
    inner = _FAR if level >= _INF else np.float32(np.sqrt(np.float64(level)))
    for q in range(first, last + 1):
        out[q] = min(np.float32(min(q - first + 1, last + 1 - q)), inner)


@njit(cache=True, nogil=True, inline="always")
def _stretch_distances(squares, out, first, last, lo, hi, ints, level):  # pragma: no cover
    """Distances of cells ``first..last`` from stretches of equal ``g`` in columns ``lo..hi``.

    A stretch ``[s, e]`` of level ``g`` is at squared distance ``g + (q - clamp(q, s, e))²``
    from cell ``q``. Two stretches' difference falls strictly as ``q`` grows (the derivative is
    ``2 (clamp_left - clamp_right) < 0``), so each stretch is nearest on one interval, in the
    stretches' order: their lower envelope is built as the parabolas' is, each crossing found
    by bisection on whole cells, and every cell is then computed once from its own stretch.
    False, with nothing written, if the columns hold more than :data:`_MAX_STRETCHES`
    stretches of finite ``g``.

    ``ints`` holds the stretches' ends (``2 n`` from index 0) and the envelope's stretch and
    first cell (``2 n`` from index ``2 * _MAX_STRETCHES``); ``level`` the stretches' ``g``.
    """
    n = 0
    p = lo
    while p <= hi:
        g = squares[p]
        s = p
        while p < hi and squares[p + 1] == g:
            p += 1
        if g < _INF:
            if n == _MAX_STRETCHES:
                return False
            ints[2 * n], ints[2 * n + 1], level[n] = s, p, np.int64(g)
            n += 1
        p += 1
    if n == 0:
        out[first : last + 1] = _FAR
        return True
    env = 2 * _MAX_STRETCHES  # the envelope: (stretch, first cell it is nearest to) pairs
    top = -1
    for k in range(n):
        begin = first
        while top >= 0:
            a = ints[env + 2 * top]
            za = ints[env + 2 * top + 1]
            if _level_at(ints, level, k, za) <= _level_at(ints, level, a, za):
                top -= 1  # nearer than the top from where the top begins: the top never is
                continue
            left, right = za + 1, last + 1  # first cell where k is at least as near as a
            while left < right:
                mid = (left + right) >> 1
                if _level_at(ints, level, k, mid) <= _level_at(ints, level, a, mid):
                    right = mid
                else:
                    left = mid + 1
            begin = left
            break
        if begin > last:
            continue
        top += 1
        ints[env + 2 * top] = k
        ints[env + 2 * top + 1] = begin
    for t in range(top + 1):
        k = ints[env + 2 * t]
        z0 = ints[env + 2 * t + 1]
        z1 = ints[env + 2 * t + 3] - 1 if t < top else last
        s, e, g = ints[2 * k], ints[2 * k + 1], level[k]
        if g == 0:  # an obstacle's own column: the distance is the whole offset, no root needed
            for q in range(z0, min(z1, s - 1) + 1):
                out[q] = np.float32(s - q)
            for q in range(max(z0, e + 1), z1 + 1):
                out[q] = np.float32(q - e)
            continue
        for q in range(z0, min(z1, s - 1) + 1):
            out[q] = np.float32(np.sqrt(np.float64(g + (s - q) * (s - q))))
        inner = np.float32(np.sqrt(np.float64(g)))
        for q in range(max(z0, s), min(z1, e) + 1):
            out[q] = inner
        for q in range(max(z0, e + 1), z1 + 1):
            out[q] = np.float32(np.sqrt(np.float64(g + (q - e) * (q - e))))
    return True


@njit(cache=True, nogil=True, inline="always")
def _level_at(ints, level, k, q):  # pragma: no cover - compiled
    """Squared distance (cells², an integer) from cell ``q`` to stretch ``k``."""
    off = max(ints[2 * k] - q, q - ints[2 * k + 1], 0)
    return level[k] + off * off


@njit(cache=True, nogil=True, inline="always")
def _run_distances(squares, out, first, last, lo, hi, at, height):  # pragma: no cover - compiled
    """Distances of cells ``first..last`` from the parabolas of columns ``lo..hi``.

    Integer arithmetic is exact while ``(g + p²) * W`` fits in an int64: up to grids
    :data:`MAX_WIDTH` cells wide, which :func:`column_squares` checks.
    """
    k = -1
    below_at, below_h, top_at, top_h = 0, 0, 0, 0
    for p in range(lo, hi + 1):
        g = squares[p]
        if g >= _INF:
            continue
        h = np.int64(g) + p * p
        # pop the top while the new parabola meets it before the top meets the one below it
        while k >= 1 and (h - top_h) * (top_at - below_at) <= (top_h - below_h) * (p - top_at):
            k -= 1
            top_at, top_h = below_at, below_h
            if k >= 1:
                below_at, below_h = at[k - 1], height[k - 1]
        k += 1
        at[k] = p
        height[k] = h
        below_at, below_h, top_at, top_h = top_at, top_h, p, h
    if k < 0:
        out[first : last + 1] = _FAR
        return
    j = 0
    for q in range(first, last + 1):
        best = height[j] + q * (q - 2 * at[j])
        while j < k:
            after = height[j + 1] + q * (q - 2 * at[j + 1])
            if after > best:
                break
            best = after
            j += 1
        out[q] = np.float32(np.sqrt(np.float64(best)))
