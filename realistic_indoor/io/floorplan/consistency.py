"""Portals that contradict each other or the plan's outlines, repaired by fixed rules.

Each space lists the portals on its walls, naming the one or two spaces each portal joins
(``<target>``) and the ``<linesegment>`` where it is. Three contradictions are repaired here,
each reported through a :class:`~realistic_indoor.io.floorplan.repairs.RepairLog`:

- ``targets_differ``: the spaces listing a portal name different targets. The door joins the
  named spaces whose outlines the segment touches (the two nearest if more do); with fewer
  than two it is dropped.
- ``one_sided_portal``: a space the portal joins does not list it. The door is kept if it lies
  on both spaces' walls, else dropped.
- ``door_off_wall``: the door lies farther than :data:`REACH_M` from a room it joins. It is
  placed on the wall the two rooms share, or dropped if they are too far apart for one door.

"On a wall" allows for real plans' thick walls: a door's cut through its wall reaches
:data:`REACH_M` either side, so a door within that distance of a room's outline opens into it.
"""

from __future__ import annotations

import numpy as np

from realistic_indoor.building.walls import DOOR_GAP_DEPTH_M
from realistic_indoor.io.floorplan.portals import DoorGeometry, door_between
from realistic_indoor.io.floorplan.repairs import RepairLog

__all__ = ["REACH_M", "Listing", "agreed_targets", "distance_to_outline", "door_on_walls", "one_sided_door"]

Point = tuple[float, float]
Segment = tuple[Point, Point]
Listing = tuple[str, tuple[str, ...]]
"""One space's listing of a portal: ``(space id, target ids)``."""

REACH_M = DOOR_GAP_DEPTH_M
"""A door or segment this close to a room's outline is on its wall (m): the depth a door cuts
through its wall on either side, so that doors in real plans' thick walls still join both rooms."""


def _quoted(ids) -> str:
    return ", ".join(f'"{i}"' for i in ids)


def _spaces(ids) -> str:
    return f"space{'s' if len(ids) > 1 else ''} {_quoted(ids)}"


def distance_to_outline(polygon, copies: list[Segment]) -> float:
    """Least distance (m) from ``polygon``'s outline to any copy of a segment (inf if none)."""
    from shapely.geometry import LineString, Point

    shapes = [Point(p) if p == q else LineString([p, q]) for p, q in copies]
    return min((polygon.exterior.distance(s) for s in shapes), default=float("inf"))


def agreed_targets(
    seg_id: str, listings: list[Listing], copies: list[Segment], polygons: dict, log: RepairLog
) -> tuple[str, ...] | None:
    """The spaces a portal joins, when the spaces listing it may disagree.

    Args:
        seg_id: The portal's segment id.
        listings: Every space's listing of it, in file order (targets distinct, 1 or 2).
        copies: The segment as the spaces give it (metres), possibly none.
        polygons: Room id -> shapely polygon (metres), for every target.
        log: Where a disagreement is reported.

    Returns:
        The target ids (the first listing's order when all agree), or ``None`` to drop the door.
    """
    first = listings[0][1]
    if all(set(ids) == set(first) for _, ids in listings):
        return first
    named = list(dict.fromkeys(t for _, ids in listings for t in ids))
    given = "; ".join(f'space "{sid}" names [{_quoted(ids)}]' for sid, ids in listings)
    element = f'portal linesegment="{seg_id}"'
    problem = f"the spaces listing it name different targets ({given})"
    if copies:
        dist = {t: distance_to_outline(polygons[t], copies) for t in named}
        near = [t for t in named if dist[t] <= REACH_M]
        nearest = sorted(near, key=lambda t: dist[t])[:2]
        kept = [t for t in near if t in nearest]
        rule = f"the segment is within {REACH_M} m of the outlines of {_quoted(near) or 'none of them'}"
        rule += ", the two nearest kept" if len(near) > 2 else ""
    else:
        kept = [t for t in named if all(t in ids for _, ids in listings)]
        rule = f"no space gives the segment, and every listing names {_quoted(kept) or 'none of them'}"
    if len(kept) < 2:
        log.defect("targets_differ", element, problem, f"dropped the door: {rule}")
        return None
    log.defect("targets_differ", element, problem, f"the door joins {_quoted(kept)}: {rule}")
    return tuple(kept)


def one_sided_door(
    seg_id: str,
    ids: tuple[str, ...],
    listers: list[str],
    geo: DoorGeometry | None,
    polygons: dict,
    log: RepairLog,
) -> DoorGeometry | None:
    """A door between two rooms that not both list: kept only if it lies on both rooms' walls.

    Args:
        seg_id: The portal's segment id (the door's id).
        ids: The two rooms it joins.
        listers: Ids of the spaces that list the portal (some of ``ids`` are missing).
        geo: Where the file's segment puts the door; ``None`` if no space gives the segment.
        polygons: Room id -> shapely polygon (metres).
        log: Where the defect is reported.

    Returns:
        ``geo``, or ``None`` to drop the door.
    """
    missing = [t for t in ids if t not in listers]
    element = f'portal linesegment="{seg_id}" of spaces {_quoted(ids)}'
    problem = (
        f"only {_spaces(listers)} {'lists' if len(listers) == 1 else 'list'} it; "
        f"{_spaces(missing)}, which it joins, {'does' if len(missing) == 1 else 'do'} not"
    )
    if geo is None:
        log.defect("one_sided_portal", element, problem, "dropped the door: no space gives its segment")
        return None
    far = _distances(geo, ids, polygons)
    worst = max(far, key=far.get)
    if far[worst] > REACH_M:
        action = f'dropped the door: it is {far[worst]:.2f} m from the outline of space "{worst}"'
        log.defect("one_sided_portal", element, problem, action)
        return None
    log.defect("one_sided_portal", element, problem, "kept the door: it lies on the walls of both spaces")
    return geo


def door_on_walls(
    seg_id: str, ids: tuple[str, ...], geo: DoorGeometry, polygons: dict, log: RepairLog
) -> DoorGeometry | None:
    """The door, once it lies within :data:`REACH_M` of the outline of each room it joins.

    A door farther than that from a room is moved to the wall the two rooms share (the middle
    of its longest stretch, or between the nearest points of the two outlines), keeping its
    width; if the rooms are more than ``2 * REACH_M`` apart, no door can join them and it is
    dropped.

    Args:
        seg_id: The portal's segment id (the door's id).
        ids: The rooms it joins (one for an exterior door, which is returned as it is).
        geo: Where the file puts the door.
        polygons: Room id -> shapely polygon (metres).
        log: Where the defect is reported.

    Returns:
        The door's geometry, or ``None`` to drop it.
    """
    if len(ids) < 2:
        return geo
    far = _distances(geo, ids, polygons)
    worst = max(far, key=far.get)
    if far[worst] <= REACH_M:
        return geo
    element = f'portal linesegment="{seg_id}" of spaces {_quoted(ids)}'
    problem = f'the door is {far[worst]:.2f} m from the outline of space "{worst}" (more than {REACH_M} m)'
    gap = polygons[ids[0]].distance(polygons[ids[1]])
    if gap > 2 * REACH_M:
        log.defect(
            "door_off_wall", element, problem, f"dropped the door: the two spaces are {gap:.2f} m apart"
        )
        return None
    outlines = [np.asarray(polygons[t].exterior.coords[:-1]) for t in ids]
    placed = door_between(outlines[0], outlines[1], geo.width_m)
    action = f"moved it to the wall the two spaces share, at ({placed.x:.2f}, {placed.y:.2f}) m"
    log.defect("door_off_wall", element, problem, action)
    return placed


def _distances(geo: DoorGeometry, ids: tuple[str, ...], polygons: dict) -> dict[str, float]:
    """Distance (m) from the door's centre to the outline of each room it joins."""
    from shapely.geometry import Point

    centre = Point(geo.x, geo.y)
    return {t: polygons[t].exterior.distance(centre) for t in ids}
