"""Wall segments of a rectilinear building, without shapely's overlay.

Generated buildings have axis-parallel room outlines and door cuts. Their walls are then lines
on a few coordinates, and what shapely's union, difference and merge make of them can be
computed on intervals: the outlines' sides merged per line, the door cuts taken out of them
(closed rectangles: a side lying on a cut's edge goes too), and each piece split where another
piece meets it (a T or a crossing), as the noded overlay leaves it. On generated buildings the
result is the set of segments :func:`realistic_indoor.building.walls.overlay_walls` gets from
shapely (tested on thousands), in an order of its own, for about a fifth of the time: the
interval passes are compiled (:mod:`realistic_indoor.building._rect_kernels`, numba, loaded on
first use).

Hand-made plans can tell the two apart where shapely follows floating-point noise rather than
the plan. A door along y (angle pi/2) has a direction of (6e-17, 1), so near a coordinate of 0
shapely's cut is tilted by that much: where the cut's edge lies on a wall across it, shapely
keeps that wall under the edge and the interval path takes it away, as both do for the same
door along x. An isolated room whose outline starts in the middle of a side gets that side
split by shapely (a ring's start), not by the interval path.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from realistic_indoor.building.building import Building

__all__ = ["rectilinear_walls"]

_SLANT_M = 1e-12
"""Most two corners of a door's cut may differ on an axis and the cut still count as axis-parallel
(m): a door on a wall at x = 0 has corners 0.3 +- 5e-17 m, from the cosine of pi / 2."""

Pieces = tuple[np.ndarray, np.ndarray, np.ndarray]
"""Pieces of wall on lines of one direction: their line's coordinate, low and high end (m)."""


def rectilinear_walls(building: Building, gaps: np.ndarray) -> np.ndarray | None:
    """The building's wall segments, if its outlines and door cuts are all axis-parallel.

    Args:
        building: The building (at least one room).
        gaps: ``(G, 4, 2)`` corners of the doors' cuts (m).

    Returns:
        ``(N, 2, 2)`` float64 segments: horizontal ones (west to east), then vertical ones
        (south to north); ``None`` if a side or a cut is slanted.
    """
    from realistic_indoor.building._rect_kernels import cut_pieces, split_pieces  # numba: only here

    cuts = _boxes(gaps)
    if cuts is None:
        return None
    start, end = _sides(building)
    flat = start[:, 1] == end[:, 1]
    upright = start[:, 0] == end[:, 0]
    kept = ~(flat & upright)  # a repeated vertex makes a side of no length: no wall
    start, end, flat, upright = start[kept], end[kept], flat[kept], upright[kept]
    if not np.all(flat | upright):
        return None
    horizontal = _merged(start[flat, 1], start[flat, 0], end[flat, 0])
    vertical = _merged(start[upright, 0], start[upright, 1], end[upright, 1])
    horizontal = cut_pieces(*horizontal, np.ascontiguousarray(cuts[:, [1, 3, 0, 2]]))
    vertical = cut_pieces(*vertical, np.ascontiguousarray(cuts[:, [0, 2, 1, 3]]))
    h = split_pieces(*horizontal, *vertical)
    v = split_pieces(*vertical, *horizontal)
    segments = np.concatenate(
        [np.stack([h[1], h[0], h[2], h[0]], axis=1), np.stack([v[0], v[1], v[0], v[2]], axis=1)]
    ).reshape(-1, 2, 2)
    return segments[np.hypot(*(segments[:, 1] - segments[:, 0]).T) > 1e-9]


def _sides(building: Building) -> tuple[np.ndarray, np.ndarray]:
    """Start and end point of every side of every room's outline, ``(S, 2)`` each."""
    rings = [room.outline for room in building.rooms]
    sizes = np.array([len(r) for r in rings])
    start = np.array([p for r in rings for p in r], dtype=float)
    first = np.cumsum(sizes) - sizes
    after = np.arange(1, len(start) + 1)
    after[first + sizes - 1] = first  # each ring's last vertex closes on its first
    return start, start[after]


def _boxes(gaps: np.ndarray) -> np.ndarray | None:
    """``(G, 4)`` x and y bounds of each cut (xmin, ymin, xmax, ymax); ``None`` if one is slanted."""
    if not len(gaps):
        return np.zeros((0, 4))
    xs, ys = np.sort(gaps[:, :, 0], axis=1), np.sort(gaps[:, :, 1], axis=1)
    if max(np.abs(xs[:, 1] - xs[:, 0]).max(), np.abs(xs[:, 3] - xs[:, 2]).max()) > _SLANT_M:
        return None
    if max(np.abs(ys[:, 1] - ys[:, 0]).max(), np.abs(ys[:, 3] - ys[:, 2]).max()) > _SLANT_M:
        return None
    return np.stack([xs[:, 0], ys[:, 0], xs[:, 3], ys[:, 3]], axis=1)


def _merged(line: np.ndarray, a: np.ndarray, b: np.ndarray) -> Pieces:
    """Collinear sides that overlap or touch joined into one piece per stretch of wall."""
    from realistic_indoor.building._rect_kernels import merge_sides

    lo, hi = np.minimum(a, b), np.maximum(a, b)
    order = np.lexsort((lo, line))
    return merge_sides(line[order], lo[order], hi[order])
