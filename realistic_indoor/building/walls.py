"""Wall segments of a building, with gaps where the doors are."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from realistic_indoor.building.rect_walls import rectilinear_walls

if TYPE_CHECKING:
    from realistic_indoor.building.building import Building
    from realistic_indoor.building.door import Door

__all__ = ["door_gap", "overlay_walls", "wall_segments"]

DOOR_GAP_DEPTH_M = 0.3
"""How far either side of its wall a door cuts walls away (m): covers the thickness of walls
in real plans, where two rooms' outlines can lie a few centimetres apart."""
_LINE_TYPES = (1, 2)
"""shapely's type ids of the lines a merge yields: LineString, LinearRing."""


def door_gap(door: Door, depth_m: float = DOOR_GAP_DEPTH_M):
    """The rectangle a door cuts out of the walls (shapely polygon, metres)."""
    from shapely.geometry import Polygon

    return Polygon(_gap_corners(door, depth_m))


def wall_segments(building: Building, depth_m: float = DOOR_GAP_DEPTH_M) -> np.ndarray:
    """Merge the room outlines into walls and cut the doors out of them.

    Walls shared by two rooms appear once; collinear pieces are merged, so the count stays
    small (raycasting cost grows with it). A building whose outlines and door cuts are all
    axis-parallel (every generated one) is done on intervals
    (:func:`~realistic_indoor.building.rect_walls.rectilinear_walls`: about 0.4 ms for a default
    office); others go to shapely, outlines and door cuts as arrays, one call each, and only
    door cuts that meet merged (about 2.3 ms for a default office). The path goes by the
    geometry, not by where the plan came from. On generated buildings both give the same
    segments (to 1e-12 m), in orders of their own; on hand-made plans they can differ where
    shapely follows floating-point noise (see :mod:`~realistic_indoor.building.rect_walls`).

    Args:
        building: The building.
        depth_m: Half the depth of the cut each door makes across its wall (m).

    Returns:
        A read-only float64 array of shape ``(N, 2, 2)``: ``N`` segments, two end points each.
    """
    if not building.rooms:
        return np.zeros((0, 2, 2))
    corners = np.array([_gap_corners(d, depth_m) for d in building.doors], dtype=float).reshape(-1, 4, 2)
    out = rectilinear_walls(building, corners)
    if out is None:
        out = overlay_walls(building, corners)
    out.setflags(write=False)
    return out


def overlay_walls(building: Building, corners: np.ndarray) -> np.ndarray:
    """:func:`wall_segments` by shapely's overlay, for any building with rooms.

    Args:
        building: The building (at least one room).
        corners: ``(G, 4, 2)`` corners of the doors' cuts (m).

    Returns:
        ``(N, 2, 2)`` float64 segments, in the order shapely's merge leaves them.
    """
    import shapely

    lines = shapely.union_all(_outline_rings(building))
    if len(corners):
        lines = lines.difference(_door_cuts(corners))
    merged = shapely.line_merge(lines) if not lines.is_empty else lines
    out = _segments_of(merged.simplify(1e-9, preserve_topology=False))
    return out[np.hypot(*(out[:, 1] - out[:, 0]).T) > 1e-9]


def _outline_rings(building: Building) -> np.ndarray:
    """The rooms' outlines as closed shapely rings (metres), made in one call."""
    import shapely

    coords = [np.array(r.outline, dtype=float) for r in building.rooms]
    index = np.repeat(np.arange(len(coords)), [len(c) for c in coords])
    return shapely.linearrings(np.concatenate(coords), indices=index)


def _door_cuts(corners: np.ndarray):
    """The area the doors cut out of the walls: a shapely multipolygon (metres).

    Args:
        corners: ``(G, 4, 2)`` corners of the cuts, ``G >= 1``.

    Cuts that meet another are merged with it (a union per group); the others, most of them,
    are taken as they are, which gives the same area as a union of all of them for a fraction
    of its cost, and the same walls once subtracted (tested on thousands of buildings).
    """
    import shapely

    gaps = shapely.polygons(corners)
    a, b = shapely.STRtree(gaps).query(gaps, predicate="intersects")
    groups = _groups(len(gaps), a[a != b], b[a != b])
    parts = [gaps[g[0]] if len(g) == 1 else shapely.union_all(gaps[g]) for g in groups]
    return shapely.multipolygons(shapely.get_parts(np.array(parts, dtype=object)))


def _groups(n: int, a: np.ndarray, b: np.ndarray) -> list[list[int]]:
    """The connected groups of items ``0..n-1`` joined by pairs ``(a[k], b[k])``, by first item."""
    parent = list(range(n))

    def root(i: int) -> int:
        while parent[i] != i:
            i = parent[i]
        return i

    for i, j in zip(a.tolist(), b.tolist(), strict=True):
        ri, rj = root(i), root(j)
        parent[max(ri, rj)] = min(ri, rj)
    groups: dict[int, list[int]] = {}
    for i in range(n):
        groups.setdefault(root(i), []).append(i)
    return list(groups.values())


def _gap_corners(door: Door, depth_m: float) -> list[tuple[float, float]]:
    """Corners of the rectangle :func:`door_gap` makes (metres), with the same arithmetic."""
    (ax, ay), (bx, by) = door.segment
    dx, dy = door.direction
    nx_, ny_ = -dy * depth_m, dx * depth_m
    return [(ax - nx_, ay - ny_), (bx - nx_, by - ny_), (bx + nx_, by + ny_), (ax + nx_, ay + ny_)]


def _segments_of(lines) -> np.ndarray:
    """The consecutive vertex pairs of every non-empty line of ``lines``, ``(N, 2, 2)`` (metres)."""
    import shapely

    parts = shapely.get_parts(lines)
    parts = parts[~shapely.is_empty(parts) & np.isin(shapely.get_type_id(parts), _LINE_TYPES)]
    coords, part = shapely.get_coordinates(parts, return_index=True)
    same = part[:-1] == part[1:]
    return np.stack([coords[:-1][same], coords[1:][same]], axis=1)
