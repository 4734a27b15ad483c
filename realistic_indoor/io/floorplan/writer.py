"""Write a ``Building`` as floor-plan XML, the format of the shared real plans (1 px = 1 cm)."""

from __future__ import annotations

import itertools
import math
import xml.etree.ElementTree as ET
from pathlib import Path

from realistic_indoor.building import CIRCULATION_LABELS, Building, Door, Room
from realistic_indoor.errors import ConfigError
from realistic_indoor.files import atomic_path

__all__ = ["PX_PER_M", "write"]

PX_PER_M = 100.0
"""Pixels per metre of written files: ``<scale>`` says 100 px represent 100 cm."""

ENTRY_FUNCTIONS = frozenset({"entrance", "stairs", "elevator"})
"""Functions written with ``<type>E</type>`` (ways in and out of the floor), as the real plans do."""


def write(building: Building, path: str | Path) -> list[Path]:
    """Write ``building`` to ``path`` as floor-plan XML.

    The plan is drawn with y growing downwards, its bounding box starting at pixel (0, 0). Each
    room is a ``<space>`` with its labels (``<semantic_label>`` is this project's extension,
    which other readers ignore), centroid, bounding box, outline, walls and portals; each door
    is a PORTAL line segment of its real width, listed by both rooms, and an exterior door is a
    portal whose ``<target>`` names only its room.

    Returns:
        ``[path]``.

    Raises:
        ConfigError: If the building has no rooms.
    """
    if not building.rooms:
        raise ConfigError("cannot write a building without rooms")
    path = Path(path)
    name = str(building.metadata.get("name") or path.name.removesuffix(".xml"))
    root = ET.Element("building", id=str(building.metadata.get("building_id") or name))
    ET.SubElement(root, "name").text = name
    root.append(_scale())
    ET.SubElement(
        ET.SubElement(root, "building_type"), "main_type"
    ).text = building.building_type.value.upper()
    spaces = ET.SubElement(ET.SubElement(root, "floor"), "spaces")
    x0, _, _, y1 = building.bounds

    def px(p: tuple[float, float]) -> dict[str, str]:
        return {"x": _fmt((p[0] - x0) * PX_PER_M), "y": _fmt((y1 - p[1]) * PX_PER_M)}

    used = {r.id for r in building.rooms} | {d.id for d in building.doors}
    for room in building.rooms:
        spaces.append(_space(room, building.doors_of[room.id], px, used))
    ET.indent(root, space="  ")
    with atomic_path(path) as tmp:
        ET.ElementTree(root).write(tmp, encoding="UTF-8", xml_declaration=True)
    return [path]


def _fmt(v: float) -> str:
    text = f"{v:.6f}".rstrip("0").rstrip(".")
    return "0" if text in ("", "-0") else text


def _scale() -> ET.Element:
    scale = ET.Element("scale")
    for tag, unit in (("represented_distance", "pixel"), ("real_distance", "cm")):
        el = ET.SubElement(scale, tag)
        ET.SubElement(el, "value").text = "100"
        ET.SubElement(el, "um").text = unit
    return scale


def _type_letter(room: Room) -> str:
    if room.function in ENTRY_FUNCTIONS:
        return "E"
    return "C" if room.label in CIRCULATION_LABELS else "R"


def _space(room: Room, doors: tuple[Door, ...], px, used: set[str]) -> ET.Element:
    space = ET.Element("space", id=room.id)
    labels = ET.SubElement(space, "labels")
    ET.SubElement(labels, "type").text = _type_letter(room)
    ET.SubElement(labels, "label").text = room.function.upper()
    ET.SubElement(labels, "semantic_label").text = room.label.value
    c = room.polygon.centroid
    ET.SubElement(ET.SubElement(space, "centroid"), "point", px((c.x, c.y)))
    xmin, ymin, xmax, ymax = room.bounds
    box = ET.SubElement(space, "bounding_box")
    for tag, corner in (
        ("maxx", (xmax, ymax)),
        ("maxy", (xmax, ymax)),
        ("minx", (xmin, ymin)),
        ("miny", (xmin, ymin)),
    ):
        ET.SubElement(ET.SubElement(box, tag), "point", px(corner))
    ring = ET.SubElement(space, "bounding_polygon")
    for p in (*room.outline, room.outline[0]):
        ET.SubElement(ring, "point", px(p))
    space.append(_representation(room, doors, px, used))
    portals = ET.SubElement(space, "portals")
    for d in doors:
        portals.append(_portal(d))
    return space


def _representation(room: Room, doors: tuple[Door, ...], px, used: set[str]) -> ET.Element:
    """The outline as WALL segments, broken where each door's PORTAL segment sits on it."""
    rep = ET.Element("space_representation")
    cuts = _door_cuts(room, doors)
    pts = room.outline
    walls = itertools.count()
    for i, a in enumerate(pts):
        b = pts[(i + 1) % len(pts)]
        cursor = 0.0
        for t0, t1, door in sorted(cuts.get(i, []), key=lambda c: c[0]):
            if t0 > cursor:
                _segment(
                    rep, _wall_id(room, next(walls), used), _lerp(a, b, cursor), _lerp(a, b, t0), "WALL", px
                )
            _segment(rep, door.id, *_along(door.segment, a, b), "PORTAL", px)
            cursor = max(cursor, t1)
        if cursor < 1.0:
            _segment(rep, _wall_id(room, next(walls), used), _lerp(a, b, cursor), b, "WALL", px)
    return rep


def _door_cuts(room: Room, doors: tuple[Door, ...]) -> dict[int, list[tuple[float, float, Door]]]:
    """For each outline edge, the stretches ``(t0, t1)`` (fractions of the edge) its doors take."""
    pts = room.outline
    cuts: dict[int, list[tuple[float, float, Door]]] = {}
    for d in doors:
        best = None
        for i, a in enumerate(pts):
            b = pts[(i + 1) % len(pts)]
            length = math.hypot(b[0] - a[0], b[1] - a[1])
            t = ((d.x - a[0]) * (b[0] - a[0]) + (d.y - a[1]) * (b[1] - a[1])) / length**2
            t = min(1.0, max(0.0, t))
            dist = math.hypot(a[0] + t * (b[0] - a[0]) - d.x, a[1] + t * (b[1] - a[1]) - d.y)
            if best is None or dist < best[0]:
                best = (dist, i, t, d.width_m / 2 / length)
        _, i, t, half = best
        cuts.setdefault(i, []).append((max(0.0, t - half), min(1.0, t + half), d))
    return cuts


def _along(seg, a, b):
    """The segment's end points ordered in the direction ``a`` -> ``b`` of the wall it sits on."""
    p, q = seg
    forward = (q[0] - p[0]) * (b[0] - a[0]) + (q[1] - p[1]) * (b[1] - a[1]) >= 0
    return (p, q) if forward else (q, p)


def _lerp(a, b, t: float) -> tuple[float, float]:
    return (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))


def _wall_id(room: Room, k: int, used: set[str]) -> str:
    wall_id = f"{room.id}-wall-{k}"
    while wall_id in used:
        wall_id += "'"
    used.add(wall_id)
    return wall_id


def _segment(rep: ET.Element, seg_id: str, p, q, cls: str, px) -> None:
    seg = ET.SubElement(rep, "linesegment", id=seg_id)
    ET.SubElement(seg, "point", px(p))
    ET.SubElement(seg, "point", px(q))
    ET.SubElement(seg, "class").text = cls
    ET.SubElement(seg, "type").text = "EXPLICIT"


def _portal(door: Door) -> ET.Element:
    portal = ET.Element("portal")
    ET.SubElement(portal, "linesegment").text = door.id
    ET.SubElement(portal, "class").text = "HORIZONTAL"
    ET.SubElement(portal, "type").text = "EXPLICIT"
    ET.SubElement(portal, "direction").text = "BOTH"
    target = ET.SubElement(portal, "target")
    for rid in door.rooms:
        ET.SubElement(target, "id").text = rid
    return portal
