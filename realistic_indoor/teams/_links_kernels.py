"""Compiled walls crossed by straight lines on a world's raster (for radio links)."""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from realistic_indoor.sim.cells import RASTER_WALL


@njit(cache=True, nogil=True)
def walls_between(grid, points):  # pragma: no cover - compiled
    """The walls each straight line between two points crosses, for every pair of points.

    A line crosses a wall each time it enters a run of wall cells: the cells it passes through
    are visited in order (Amanatides and Woo's traversal), and each wall cell entered from a
    cell that is not a wall counts one. Two rooms' shared wall is one, however thick; a line
    along a wall counts it once.

    Args:
        grid: ``(H, W)`` uint8 raster codes (``RASTER_*``).
        points: ``(k, 2)`` float64 points in cell units (column, row: x and y over the cell size
            from the raster's origin).

    Returns:
        ``(k, k)`` int64, symmetric, 0 on the diagonal.
    """
    k = points.shape[0]
    out = np.zeros((k, k), dtype=np.int64)
    for a in range(k):
        for b in range(a + 1, k):
            n = _walls_on_line(grid, points[a, 0], points[a, 1], points[b, 0], points[b, 1])
            out[a, b] = n
            out[b, a] = n
    return out


@njit(cache=True, nogil=True)
def _walls_on_line(grid, x0, y0, x1, y1):  # pragma: no cover - compiled
    """Wall runs entered along the segment from ``(x0, y0)`` to ``(x1, y1)`` (cell units)."""
    h, w = grid.shape
    c, r = math.floor(x0), math.floor(y0)
    c_end, r_end = math.floor(x1), math.floor(y1)
    dx, dy = x1 - x0, y1 - y0
    step_c = 1 if dx > 0 else -1
    step_r = 1 if dy > 0 else -1
    t_dc = abs(1.0 / dx) if dx != 0.0 else math.inf
    t_dr = abs(1.0 / dy) if dy != 0.0 else math.inf
    t_c = ((c + 1 - x0) if dx > 0 else (x0 - c)) * t_dc if dx != 0.0 else math.inf
    t_r = ((r + 1 - y0) if dy > 0 else (y0 - r)) * t_dr if dy != 0.0 else math.inf
    count = 0
    in_wall = False
    for _ in range(abs(c_end - c) + abs(r_end - r) + 1):
        wall = 0 <= r < h and 0 <= c < w and grid[r, c] == RASTER_WALL
        if wall and not in_wall:
            count += 1
        in_wall = wall
        if c == c_end and r == r_end:
            break
        if t_c < t_r:
            t_c += t_dc
            c += step_c
        else:
            t_r += t_dr
            r += step_r
    return count


@njit(cache=True, nogil=True)
def components(links):  # pragma: no cover - compiled
    """The component of each node of a symmetric link matrix, numbered by their lowest node in order.

    Args:
        links: ``(k, k)`` bool direct links.

    Returns:
        ``(k,)`` int64: nodes joined by a chain of links share a number; the component holding
        node 0 is 0, the next lowest node not in it starts component 1, and so on.
    """
    k = links.shape[0]
    label = np.full(k, -1, dtype=np.int64)
    stack = np.empty(k, dtype=np.int64)
    count = 0
    for start in range(k):
        if label[start] >= 0:
            continue
        label[start] = count
        top = 0
        stack[top] = start
        top += 1
        while top > 0:
            top -= 1
            a = stack[top]
            for b in range(k):
                if links[a, b] and label[b] < 0:
                    label[b] = count
                    stack[top] = b
                    top += 1
        count += 1
    return label
