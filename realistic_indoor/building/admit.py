"""The gate every building from outside passes before anything else sees it.

Plans read from files (JSON, floor-plan XML, World Generator XML) and buildings handed to an
environment go through :func:`admit_building` once. It refuses what no part of the package can
work with, with one line naming the source and the element, and repairs the one defect that has a
safe repair (an outline that crosses itself where dropping slivers of under 1% of its area leaves
one polygon), with a :class:`~realistic_indoor.errors.PlanRepairWarning`.

It does not judge realism or even validity in the sense of :func:`check_building` (overlapping
rooms, doors off walls, unreachable rooms): ``realistic-indoor validate`` reports those, and the
simulator runs such plans as they are drawn. Generated buildings are not re-checked.
"""

from __future__ import annotations

import math
import warnings
from collections import Counter
from dataclasses import replace
from typing import TYPE_CHECKING, Any

from realistic_indoor.errors import PlanFormatError, PlanRepairWarning

if TYPE_CHECKING:
    from realistic_indoor.building.building import Building
    from realistic_indoor.building.room import Room

__all__ = [
    "MAX_COORDINATE_M",
    "MAX_REPAIR_AREA_SHARE",
    "MAX_ROOMS",
    "MAX_SPAN_M",
    "MAX_VERTICES",
    "admit_building",
]

MAX_COORDINATE_M = 1e7
"""Largest absolute coordinate of a vertex or door (m): room for projected map coordinates."""

MAX_SPAN_M = 2000.0
"""Largest side of a building's bounding box (m); generated buildings stay well below it."""

MAX_ROOMS = 100_000
"""Most rooms a building may have."""

MAX_VERTICES = 1_000_000
"""Most outline vertices a building may have, all rooms together."""

MAX_REPAIR_AREA_SHARE = 0.01
"""Largest share of a self-crossing outline's area that a repair may drop."""


def admit_building(building: Building, source: object = "<building>", *, strict: bool = False) -> Building:
    """Check a building from outside the package; repair a self-crossing outline where it is safe.

    Refused: no rooms; more than :data:`MAX_ROOMS` rooms or :data:`MAX_VERTICES` vertices; a room
    or door id that is not a non-empty string, or repeated; an outline with fewer than 3 vertices,
    a coordinate that is not finite or beyond :data:`MAX_COORDINATE_M`, or no area; a footprint
    wider or deeper than :data:`MAX_SPAN_M`; a door whose position, width or angle is not finite,
    whose width is not in (0, :data:`MAX_SPAN_M`] m, or that names a room the building lacks; an
    invalid outline without a safe repair.

    Repaired (with a ``PlanRepairWarning``, recorded in ``metadata["repairs"]``): an outline that
    crosses or touches itself, where shapely's ``make_valid`` leaves one polygon holding all but
    under :data:`MAX_REPAIR_AREA_SHARE` of its area; the room takes that polygon's outline.

    Args:
        building: The building, read from a file or given to an environment.
        source: What to name in messages: the file, or e.g. ``"EnvConfig.building"``.
        strict: Refuse a building that needs a repair instead of repairing it.

    Returns:
        ``building`` itself when nothing needed a repair, else a repaired copy.

    Raises:
        PlanFormatError: One line naming ``source``, the element and what is wrong.
    """
    rooms = building.rooms
    if not rooms:
        raise PlanFormatError(source, "the plan has no rooms")
    _check_counts(building, source)
    _check_ids([r.id for r in rooms], "room", source)
    _check_ids([d.id for d in building.doors], "door", source)
    for room in rooms:
        _check_outline(room, source)
    _check_span(rooms, source)
    _check_doors(building, source)
    repaired, notes = _repair_outlines(rooms, source, strict)
    if not notes:
        return building
    for note in notes:
        warnings.warn(
            PlanRepairWarning(f"{source}: {note['element']}: {note['problem']}; {note['action']}"),
            stacklevel=2,
        )
    metadata = dict(building.metadata)
    metadata["repairs"] = [*metadata.get("repairs", []), *notes]
    return replace(building, rooms=repaired, metadata=metadata)


def _check_counts(building: Building, source: object) -> None:
    vertices = sum(len(r.outline) for r in building.rooms)
    if len(building.rooms) > MAX_ROOMS:
        raise PlanFormatError(
            source, f"{len(building.rooms):,} rooms; at most {MAX_ROOMS:,} are read", "rooms"
        )
    if vertices > MAX_VERTICES:
        raise PlanFormatError(
            source, f"{vertices:,} outline vertices; at most {MAX_VERTICES:,} are read", "rooms"
        )


def _check_ids(ids: list[Any], what: str, source: object) -> None:
    for i, given in enumerate(ids):
        if not isinstance(given, str) or not given:
            raise PlanFormatError(
                source, f"the id must be a non-empty string, got {given!r}", f"{what} {i + 1}"
            )
    repeated = [k for k, n in Counter(ids).items() if n > 1]
    if repeated:
        raise PlanFormatError(
            source,
            f"{Counter(ids)[repeated[0]]} {what}s have this id; ids must be unique",
            f"{what} {repeated[0]!r}",
        )


def _finite(value: float, limit: float = MAX_COORDINATE_M) -> bool:
    return math.isfinite(value) and abs(value) <= limit


def _check_outline(room: Room, source: object) -> None:
    where = f"room {room.id!r}"
    if not isinstance(room.function, str):
        raise PlanFormatError(source, f"the function must be a string, got {room.function!r}", where)
    if len(room.outline) < 3:
        raise PlanFormatError(
            source, f"the outline has {len(room.outline)} vertices; a room needs at least 3", where
        )
    for x, y in room.outline:
        if not (_finite(x) and _finite(y)):
            raise PlanFormatError(
                source,
                f"vertex ({x!r}, {y!r}) is not a finite coordinate within +-{MAX_COORDINATE_M:g} m",
                where,
            )


def _check_span(rooms: tuple[Room, ...], source: object) -> None:
    xs = [x for r in rooms for x, _ in r.outline]
    ys = [y for r in rooms for _, y in r.outline]
    width, depth = max(xs) - min(xs), max(ys) - min(ys)
    if max(width, depth) > MAX_SPAN_M:
        raise PlanFormatError(
            source,
            f"the footprint is {width:.6g} m x {depth:.6g} m; at most {MAX_SPAN_M:g} m a side is read "
            "(are the coordinates in metres?)",
            "rooms",
        )


def _check_doors(building: Building, source: object) -> None:
    known = building.room_by_id
    for d in building.doors:
        where = f"door {d.id!r}"
        if not (_finite(d.x) and _finite(d.y) and math.isfinite(d.angle_rad)):
            raise PlanFormatError(
                source, f"position ({d.x!r}, {d.y!r}) or angle {d.angle_rad!r} is not a finite number", where
            )
        if not (d.width_m > 0 and _finite(d.width_m, MAX_SPAN_M)):
            raise PlanFormatError(source, f"width {d.width_m!r} m is not in (0, {MAX_SPAN_M:g}] m", where)
        for rid in d.rooms:
            if not isinstance(rid, str) or rid not in known:
                raise PlanFormatError(source, f"names room {rid!r}, which the plan does not have", where)


def _repair_outlines(
    rooms: tuple[Room, ...], source: object, strict: bool
) -> tuple[tuple[Room, ...], list[dict]]:
    import shapely

    polygons = [r.polygon for r in rooms]
    valid = shapely.is_valid(polygons)
    if valid.all():
        return rooms, []
    out, notes = list(rooms), []
    for i in (k for k, ok in enumerate(valid) if not ok):
        out[i], note = _repaired_room(rooms[i], source, strict)
        notes.append(note)
    return tuple(out), notes


def _repaired_room(room: Room, source: object, strict: bool) -> tuple[Room, dict[str, str]]:
    """The room with its largest valid part as outline, if that keeps over 99% of the area."""
    import shapely
    from shapely.validation import explain_validity

    where = f"room {room.id!r}"
    why = explain_validity(room.polygon)
    parts = [g for g in shapely.get_parts(shapely.make_valid(room.polygon)) if g.geom_type == "Polygon"]
    total = sum(p.area for p in parts)
    if total <= 0:
        raise PlanFormatError(source, f"the outline encloses no area ({why})", where)
    largest = max(parts, key=lambda p: p.area)
    kept = shapely.Polygon(largest.exterior)
    dropped = abs(kept.area - total) / total
    if dropped >= MAX_REPAIR_AREA_SHARE:
        raise PlanFormatError(
            source,
            f"the outline is invalid ({why}) and making it one valid polygon would change its area by "
            f"{dropped:.1%}; redraw the room",
            where,
        )
    action = f"kept its largest valid part ({dropped:.2%} of the area changed)"
    if strict:
        raise PlanFormatError(
            source,
            f"the outline is invalid ({why}); fix the file, or read it without strict (repair: {action})",
            where,
        )
    fixed = type(room).from_polygon(room.id, room.label, room.function, kept)
    return fixed, {
        "element": where,
        "problem": f"invalid outline ({why})",
        "action": action,
        "defect": "invalid_outline",
    }
