"""Wall segments of a building, with gaps where the doors are."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from realistic_indoor.building.building import Building
    from realistic_indoor.building.door import Door

__all__ = ["door_gap", "wall_segments"]

DOOR_GAP_DEPTH_M = 0.3
"""How far either side of its wall a door cuts walls away (m): covers the thickness of walls
in real plans, where two rooms' outlines can lie a few centimetres apart."""


def door_gap(door: Door, depth_m: float = DOOR_GAP_DEPTH_M):
    """The rectangle a door cuts out of the walls (shapely polygon, metres)."""
    from shapely.geometry import Polygon

    (ax, ay), (bx, by) = door.segment
    dx, dy = door.direction
    nx_, ny_ = -dy * depth_m, dx * depth_m
    return Polygon([(ax - nx_, ay - ny_), (bx - nx_, by - ny_), (bx + nx_, by + ny_), (ax + nx_, ay + ny_)])


def wall_segments(building: Building, depth_m: float = DOOR_GAP_DEPTH_M) -> np.ndarray:
    """Merge the room outlines into walls and cut the doors out of them.

    Walls shared by two rooms appear once; collinear pieces are merged, so the count stays
    small (raycasting cost grows with it).

    Args:
        building: The building.
        depth_m: Half the depth of the cut each door makes across its wall (m).

    Returns:
        A read-only float64 array of shape ``(N, 2, 2)``: ``N`` segments, two end points each.
    """
    import shapely
    from shapely.ops import unary_union

    if not building.rooms:
        return np.zeros((0, 2, 2))
    lines = unary_union([r.polygon.exterior for r in building.rooms])
    if building.doors:
        lines = lines.difference(unary_union([door_gap(d, depth_m) for d in building.doors]))
    merged = shapely.line_merge(lines) if not lines.is_empty else lines
    merged = merged.simplify(1e-9, preserve_topology=False)
    segs: list[np.ndarray] = []
    for part in getattr(merged, "geoms", [merged]):
        if part.is_empty or part.geom_type not in ("LineString", "LinearRing"):
            continue
        c = np.asarray(part.coords, dtype=float)
        segs.append(np.stack([c[:-1], c[1:]], axis=1))
    out = np.concatenate(segs) if segs else np.zeros((0, 2, 2))
    out = out[np.hypot(*(out[:, 1] - out[:, 0]).T) > 1e-9]
    out.setflags(write=False)
    return out
