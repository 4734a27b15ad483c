"""Exterior doors for plans that have none: one per entrance space, on its outer wall."""

from __future__ import annotations

import math
from typing import Any

from realistic_indoor.building import Door, Room, SemanticLabel

__all__ = ["infer_entrances"]

WALL_GAP_M = 0.3
"""Gaps between rooms up to this width count as walls when finding the building's outline (m)."""


def infer_entrances(
    rooms: list[Room], taken_ids: set[str], width_m: float
) -> tuple[list[Door], dict[str, Any]]:
    """Add exterior doors where a real plan's entrance must be.

    One door for each space whose function is ``entrance`` and which has a wall on the building's
    outer boundary; when there is none, one door for the largest hall or lobby on the boundary,
    then for the largest corridor, then for the largest room (an upper floor, whose way in is a
    staircase inside, still gets a door to the outside). Each door sits in the middle of the
    room's longest stretch of outer wall.

    Args:
        rooms: The plan's rooms (metres).
        taken_ids: Door ids already used (new ids avoid them).
        width_m: Width of the new doors (m).

    Returns:
        The new doors, and a note for the building's metadata saying which rooms got them (or
        why none could be added).
    """
    if not rooms:
        return [], {"rule": "none", "doors": [], "note": "the plan has no rooms"}
    boundary = _outer_boundary(rooms)
    tiers = (
        ("entrance spaces", [r for r in rooms if r.function == "entrance"], False),
        ("largest hall or lobby", [r for r in rooms if r.label is SemanticLabel.HALL], True),
        ("largest corridor", [r for r in rooms if r.label is SemanticLabel.CORRIDOR], True),
        ("largest room", list(rooms), True),
    )
    for rule, candidates, only_largest in tiers:
        placed = []
        for room in sorted(candidates, key=lambda r: -r.area) if only_largest else candidates:
            door = _door_on_outer_wall(room, boundary, width_m, _new_id(room.id, taken_ids))
            if door is not None:
                placed.append(door)
                taken_ids.add(door.id)
                if only_largest:
                    break
        if placed:
            return placed, {"rule": rule, "doors": [{"door": d.id, "room": d.room_a} for d in placed]}
    return [], {"rule": "none", "doors": [], "note": "no room has an outer wall as wide as a door"}


def _outer_boundary(rooms: list[Room]):
    from shapely.ops import unary_union

    footprint = unary_union([r.polygon for r in rooms]).buffer(WALL_GAP_M).buffer(-WALL_GAP_M)
    parts = getattr(footprint, "geoms", [footprint])
    return unary_union([p.exterior for p in parts if not p.is_empty]).buffer(WALL_GAP_M)


def _door_on_outer_wall(room: Room, near_boundary, width_m: float, door_id: str) -> Door | None:
    from shapely.geometry import LineString

    best = None
    pts = room.outline
    for a, b in zip(pts, pts[1:] + pts[:1], strict=True):
        on = LineString([a, b]).intersection(near_boundary)
        pieces = [g for g in getattr(on, "geoms", [on]) if g.geom_type == "LineString" and not g.is_empty]
        for piece in pieces:
            if piece.length >= width_m and (best is None or piece.length > best[0].length):
                best = (piece, a, b)
    if best is None:
        return None
    piece, a, b = best
    mid = piece.interpolate(0.5, normalized=True)
    angle = math.atan2(b[1] - a[1], b[0] - a[0])
    return Door(door_id, room.id, None, mid.x, mid.y, width_m, angle)


def _new_id(room_id: str, taken: set[str]) -> str:
    base = f"entrance-{room_id}"
    door_id, k = base, 1
    while door_id in taken:
        k += 1
        door_id = f"{base}-{k}"
    return door_id
