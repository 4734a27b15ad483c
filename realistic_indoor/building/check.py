"""Invariants of a valid building, and a check that lists every violation."""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass
from typing import TYPE_CHECKING

import networkx as nx

from realistic_indoor.errors import RealisticIndoorError

if TYPE_CHECKING:
    from realistic_indoor.building.building import Building
    from realistic_indoor.building.door import Door

__all__ = [
    "MIN_DOOR_WIDTH_M",
    "OVERLAP_TOLERANCE_M2",
    "WALL_TOLERANCE_M",
    "Finding",
    "InvalidBuildingError",
    "check_building",
]

MIN_DOOR_WIDTH_M = 0.6
"""Narrowest doorway a person or a small robot passes through (m)."""

WALL_TOLERANCE_M = 0.05
"""How far a door centre may lie from a room's outline unless the building says otherwise (m)."""

OVERLAP_TOLERANCE_M2 = 0.01
"""Overlap area below which two rooms count as touching (m2)."""


@dataclass(frozen=True)
class Finding:
    """One violated invariant.

    Attributes:
        code: Short machine-readable name (``"overlap"``, ``"unreachable"``, ...).
        message: What is wrong, in words.
        ids: Ids of the rooms or doors concerned.
    """

    code: str
    message: str
    ids: tuple[str, ...] = ()

    def __str__(self) -> str:
        return f"{self.code}: {self.message}"


class InvalidBuildingError(RealisticIndoorError):
    """Raised by :func:`check_building` with ``raise_on_error=True``; carries the findings."""

    def __init__(self, findings: list[Finding]) -> None:
        self.findings = findings
        more = f" (and {len(findings) - 1} more)" if len(findings) > 1 else ""
        super().__init__(f"invalid building: {findings[0]}{more}")


def check_building(
    building: Building,
    *,
    min_door_width_m: float = MIN_DOOR_WIDTH_M,
    wall_tolerance_m: float | None = None,
    overlap_tolerance_m2: float = OVERLAP_TOLERANCE_M2,
    require_entrance: bool = True,
    raise_on_error: bool = False,
) -> list[Finding]:
    """List every invariant ``building`` violates.

    Checked: room ids unique and outlines valid simple polygons; no two rooms overlapping;
    every door joins known rooms, lies on a wall the two rooms share (an exterior door: on
    its room's wall facing outside) and is at least ``min_door_width_m`` wide; the topology is
    connected and every room is reachable from an entrance.

    Args:
        building: The building to check.
        min_door_width_m: Narrowest allowed door (m).
        wall_tolerance_m: How far a door centre may lie from a room's outline (m). ``None``:
            the building's ``metadata["wall_tolerance_m"]`` when it has one, else
            :data:`WALL_TOLERANCE_M` (0.05 m). The floor-plan XML reader records 0.3 m for real
            plans that draw walls as gaps between rooms' outlines: a door's cut through its wall
            reaches that far on either side (``realistic_indoor.building.walls.DOOR_GAP_DEPTH_M``),
            so such a door still joins its two rooms.
        overlap_tolerance_m2: Overlap area below which two rooms count as touching (m2).
        require_entrance: Report a building with no exterior door.
        raise_on_error: Raise :class:`InvalidBuildingError` when anything is found.

    Returns:
        The findings, empty for a valid building.

    Raises:
        InvalidBuildingError: If ``raise_on_error`` and the building is invalid.
    """
    if wall_tolerance_m is None:
        wall_tolerance_m = float(building.metadata.get("wall_tolerance_m", WALL_TOLERANCE_M))
    findings: list[Finding] = []
    findings += _check_ids(building)
    findings += _check_polygons(building)
    findings += _check_overlaps(building, overlap_tolerance_m2)
    for door in building.doors:
        findings += _check_door(building, door, min_door_width_m, wall_tolerance_m)
    findings += _check_connectivity(building, require_entrance)
    if findings and raise_on_error:
        raise InvalidBuildingError(findings)
    return findings


def _check_ids(b: Building) -> list[Finding]:
    out = []
    for what, ids in (("room", [r.id for r in b.rooms]), ("door", [d.id for d in b.doors])):
        for dup, n in Counter(ids).items():
            if n > 1:
                out.append(Finding("duplicate_id", f"{n} {what}s have the id {dup!r}", (dup,)))
    return out


def _check_polygons(b: Building) -> list[Finding]:
    from shapely.validation import explain_validity

    out = []
    for r in b.rooms:
        if len(r.outline) < 3 or not r.polygon.is_valid or r.area <= 0:
            why = explain_validity(r.polygon) if len(r.outline) >= 3 else "fewer than 3 vertices"
            out.append(Finding("invalid_polygon", f"room {r.id!r} has an invalid outline: {why}", (r.id,)))
    return out


def _check_overlaps(b: Building, tol_m2: float) -> list[Finding]:
    from shapely import STRtree

    rooms = [r for r in b.rooms if len(r.outline) >= 3 and r.polygon.is_valid]
    tree = STRtree([r.polygon for r in rooms])
    out = []
    for i, j in zip(*tree.query([r.polygon for r in rooms], predicate="intersects"), strict=True):
        if i < j:
            shared = rooms[i].polygon.intersection(rooms[j].polygon).area
            if shared > tol_m2:
                a, c = rooms[i].id, rooms[j].id
                out.append(Finding("overlap", f"rooms {a!r} and {c!r} overlap by {shared:.2f} m2", (a, c)))
    return out


def _check_door(b: Building, d: Door, min_width: float, tol: float) -> list[Finding]:
    from shapely.geometry import Point

    unknown = [rid for rid in d.rooms if rid not in b.room_by_id]
    if unknown:
        return [Finding("unknown_room", f"door {d.id!r} names unknown room {unknown[0]!r}", (d.id,))]
    out = []
    if d.width_m < min_width:
        out.append(
            Finding(
                "narrow_door", f"door {d.id!r} is {d.width_m:.2f} m wide (minimum {min_width} m)", (d.id,)
            )
        )
    centre = Point(d.x, d.y)
    far = [rid for rid in d.rooms if b.room(rid).polygon.exterior.distance(centre) > tol]
    if far:
        out.append(Finding("door_off_wall", f"door {d.id!r} is not on a wall of room {far[0]!r}", (d.id,)))
    elif d.is_exterior:
        inside = [r.id for r in b.rooms if r.id != d.room_a and r.polygon.distance(centre) <= tol]
        if inside:
            msg = f"exterior door {d.id!r} of room {d.room_a!r} opens into room {inside[0]!r}"
            out.append(Finding("door_off_wall", msg, (d.id,)))
    return out


def _check_connectivity(b: Building, require_entrance: bool) -> list[Finding]:
    g = b.graph()
    out = []
    if g.number_of_nodes() and not nx.is_connected(g):
        parts = sorted(nx.connected_components(g), key=len, reverse=True)
        out.append(
            Finding("disconnected", f"the rooms form {len(parts)} groups without doors between them", ())
        )
    entrances = [d.room_a for d in b.entrances if d.room_a in g]
    if not entrances:
        if require_entrance:
            out.append(Finding("no_entrance", "the building has no exterior door", ()))
        return out
    reached = set().union(*(nx.node_connected_component(g, r) for r in entrances))
    lost = [r.id for r in b.rooms if r.id not in reached]
    if lost:
        out.append(
            Finding(
                "unreachable",
                f"{len(lost)} rooms cannot be reached from an entrance, e.g. {lost[0]!r}",
                tuple(lost),
            )
        )
    return out
