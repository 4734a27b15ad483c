"""Read a floor-plan XML file (the format of the shared real plans) into a ``Building``."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections import Counter
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path, PureWindowsPath
from typing import Any, NamedTuple

import numpy as np

from realistic_indoor.building import Building, BuildingType, Door, Room, SemanticLabel, parse_label
from realistic_indoor.building.check import WALL_TOLERANCE_M
from realistic_indoor.building.door import DEFAULT_DOOR_WIDTH_M
from realistic_indoor.building.labels import normalise_function
from realistic_indoor.checks import require_between
from realistic_indoor.errors import ConfigError, PlanFormatError
from realistic_indoor.io.floorplan.consistency import (
    REACH_M,
    Listing,
    agreed_targets,
    door_on_walls,
    one_sided_door,
)
from realistic_indoor.io.floorplan.entrances import infer_entrances as _infer_entrances
from realistic_indoor.io.floorplan.outline import MAX_SLIVER_FRACTION, OutlineError, repair_outline
from realistic_indoor.io.floorplan.overlaps import cut_overlaps
from realistic_indoor.io.floorplan.portals import DoorGeometry, door_between, door_from_copies
from realistic_indoor.io.floorplan.repairs import RepairLog
from realistic_indoor.io.floorplan.xmlfile import parse_root, points, read_scale
from realistic_indoor.io.function_labels import load_label_map, semantic_label_for

__all__ = ["read"]

Point = tuple[float, float]


@dataclass
class _Space:
    """One ``floor/spaces/space`` element, parsed (coordinates in pixels, y down)."""

    id: str
    function: str
    label: SemanticLabel
    ring: list[Point]
    portals: list[tuple[str, tuple[str, ...]]] = field(default_factory=list)
    segments: dict[str, tuple[Point, Point]] = field(default_factory=dict)


class _Shapes(NamedTuple):
    """The rooms' geometry (metres), by room id: shapely polygons and ``(n, 2)`` outlines."""

    polygons: dict[str, Any]
    outlines: dict[str, np.ndarray]


def read(
    path: str | Path,
    label_map: Mapping[str, Any] | str | Path | None = None,
    *,
    door_width_m: float = DEFAULT_DOOR_WIDTH_M,
    infer_entrances: bool = False,
    max_sliver_fraction: float = MAX_SLIVER_FRACTION,
    strict: bool = False,
) -> Building:
    """Read a floor-plan XML file.

    Coordinates are scaled to metres with the file's ``<scale>``, y is flipped to grow upwards,
    and the plan is moved so that its bounding box starts at (0, 0). Rooms come from
    ``floor/spaces/space`` (id, functional label, ``<bounding_polygon>``); doors from the
    portals, one per portal segment (its id is the door's id).

    Defects where the file contradicts itself are repaired by the rules of ``docs/formats.md``
    and each reported as a :class:`~realistic_indoor.io.floorplan.repairs.PlanRepairWarning`:
    spaces naming different targets for one portal, a portal that a space it joins does not
    list, a door farther than 0.3 m from a room it joins, overlapping outlines (the overlap is
    cut out of the larger room).

    Args:
        path: The file.
        label_map: Changes to the functional -> semantic label table (a mapping or a JSON file,
            see :func:`realistic_indoor.io.function_labels.load_label_map`).
        door_width_m: Width of a door whose portal segment has no length (m), in [0.6, 3]
            (0.6 m is the narrowest door :func:`~realistic_indoor.building.check_building`
            accepts).
        infer_entrances: Add exterior doors (the files have none): one per ``entrance`` space on
            the building's outer wall, else one for the largest hall or lobby, else for the
            largest corridor, else for the largest room. Recorded in
            ``metadata["inferred_entrances"]``.
        max_sliver_fraction: Largest share of a self-crossing outline's area that may be dropped
            as slivers when repairing it.
        strict: Refuse a file with any of the defects above (raise :class:`PlanFormatError`)
            instead of repairing it. Clean-ups of single outlines (spikes, slivers, empty spaces)
            and doors placed for portals without a segment are still made.

    Returns:
        The building. ``metadata`` holds ``source`` (the path as given), ``name``,
        ``building_id``, ``scale_m_per_px``, ``door_geometry`` (how many doors came from a
        segment, from two jambs, from a point, or were placed), ``repairs`` (every change made
        to the file's content, if any; a defect's entry has a ``"defect"`` key naming its kind),
        ``wall_tolerance_m`` (0.3, when a door lies more than 0.05 m from the outline of a room
        it joins: the plan draws walls as gaps between rooms, see
        :func:`~realistic_indoor.building.check_building`) and ``groups`` (the file's groups of
        spaces, if any).

    Raises:
        PlanFormatError: If the file is missing or malformed, has no usable scale, a space has an
            unknown functional label, an invalid outline or non-numeric coordinates, or a portal
            names an unknown space or more than two; under ``strict``, if it has a defect. The
            message names the file and the element.
        ConfigError: If ``label_map`` or ``door_width_m`` is invalid.
    """
    source, path = str(path), Path(path)
    require_between("floorplan.read", "door_width_m", door_width_m, 0.6, 3.0, "m")
    labels = load_label_map(label_map)
    root = parse_root(path)
    if root.tag != "building":
        raise PlanFormatError(
            path, f"root element is <{root.tag}>, not <building>; World Generator files end in .wg.xml"
        )
    rep_px, real_m = read_scale(root, path)
    log = RepairLog(path, strict)
    spaces = _read_spaces(root, path, labels, real_m / rep_px, max_sliver_fraction, log)
    rings = cut_overlaps([s.id for s in spaces], [s.ring for s in spaces], real_m / rep_px, log)
    for space, ring in zip(spaces, rings, strict=True):
        space.ring = ring
    to_m = _transform(spaces, rep_px, real_m)
    rooms = [Room(s.id, s.label, s.function, tuple(map(tuple, to_m(s.ring)))) for s in spaces]
    doors, sources = _read_doors(spaces, rooms, to_m, path, door_width_m, log, _dropped_ids(root, spaces))
    metadata = _metadata(root, source, path, real_m / rep_px, sources, log.entries)
    if _off_wall(doors, rooms):
        metadata["wall_tolerance_m"] = REACH_M
    if infer_entrances:
        extra, note = _infer_entrances(rooms, {d.id for d in doors}, door_width_m)
        doors += extra
        metadata["inferred_entrances"] = note
    return Building(_building_type(root), tuple(rooms), tuple(doors), metadata)


def _read_spaces(
    root: ET.Element,
    path: Path,
    labels: Mapping[str, SemanticLabel],
    m_per_px: float,
    max_sliver: float,
    log: RepairLog,
) -> list[_Space]:
    elements = root.findall("floor/spaces/space")
    if not elements:
        raise PlanFormatError(path, "no rooms: the file has no floor/spaces/space element", "floor/spaces")
    spaces: list[_Space] = []
    seen: set[str] = set()
    for i, el in enumerate(elements):
        sid = el.get("id")
        if not sid:
            raise PlanFormatError(path, "has no id attribute", f"floor/spaces/space[{i + 1}]")
        where = f'space id="{sid}"'
        if sid in seen:
            raise PlanFormatError(path, "another space has the same id; space ids must be unique", where)
        seen.add(sid)
        space = _read_space(el, sid, path, labels)
        try:
            space.ring, note = repair_outline(
                points(el.find("bounding_polygon"), path, where), m_per_px, max_sliver
            )
        except OutlineError as e:
            if e.degenerate and not space.portals:
                log.note(where, str(e), "dropped the space (no portals)")
                continue
            raise PlanFormatError(path, f"invalid <bounding_polygon>: {e}", where) from None
        if note:
            log.note(where, "invalid <bounding_polygon>", note)
        spaces.append(space)
    return spaces


def _read_space(el: ET.Element, sid: str, path: Path, labels: Mapping[str, SemanticLabel]) -> _Space:
    where = f'space id="{sid}"'
    text = el.findtext("labels/label")
    if not text or not text.strip():
        raise PlanFormatError(path, "has no <labels><label>: add the room's functional label", where)
    function = normalise_function(text)
    explicit = el.findtext("labels/semantic_label")
    try:
        label = parse_label(explicit) if explicit else semantic_label_for(function, labels)
    except ConfigError as e:
        raise PlanFormatError(path, str(e), where) from None
    space = _Space(sid, function, label, [])
    for ls in el.findall("space_representation/linesegment"):
        seg_id = ls.get("id")
        pts = points(ls, path, f'{where} linesegment id="{seg_id}"')
        if seg_id and len(pts) >= 2:
            space.segments[seg_id] = (pts[0], pts[1])
    for k, portal in enumerate(el.findall("portals/portal")):
        seg_id = (portal.findtext("linesegment") or "").strip()
        if not seg_id:
            raise PlanFormatError(path, "has no <linesegment> naming its segment", f"{where} portal {k + 1}")
        targets = tuple(t.text.strip() for t in portal.findall("target/id") if t.text and t.text.strip())
        space.portals.append((seg_id, targets))
    return space


def _transform(spaces: list[_Space], rep_px: float, real_m: float):
    """Pixels (y down) -> metres (y up), the plan's bounding box starting at (0, 0)."""
    allpts = np.array([p for s in spaces for p in s.ring], dtype=float)
    xs = allpts[:, 0] * real_m / rep_px
    ys = -allpts[:, 1] * real_m / rep_px
    x0, y0 = xs.min(), ys.min()

    def to_m(pts) -> np.ndarray:
        a = np.asarray(pts, dtype=float).reshape(-1, 2)
        return np.column_stack([a[:, 0] * real_m / rep_px - x0, -a[:, 1] * real_m / rep_px - y0])

    return to_m


def _dropped_ids(root: ET.Element, spaces: list[_Space]) -> set[str]:
    kept = {s.id for s in spaces}
    return {el.get("id", "") for el in root.findall("floor/spaces/space")} - kept


def _read_doors(spaces, rooms, to_m, path, width_m, log: RepairLog, dropped) -> tuple[list[Door], Counter]:
    listings = _portal_listings(spaces, path)
    copies: dict[str, list[tuple[Point, Point]]] = {}
    for s in spaces:
        for seg_id, (p, q) in s.segments.items():
            if seg_id in listings:
                copies.setdefault(seg_id, []).append(tuple(map(tuple, to_m([p, q]))))
    shapes = _Shapes({r.id: r.polygon for r in rooms}, {r.id: np.asarray(r.outline) for r in rooms})
    doors, sources = [], Counter()
    for seg_id, listed in listings.items():
        where = f'portal linesegment="{seg_id}"'
        named = list(dict.fromkeys(t for _, ids in listed for t in ids))
        if any(t in dropped for t in named):
            log.note(where, "joins a dropped space", "dropped the door")
            continue
        unknown = [t for t in named if t not in shapes.polygons]
        if unknown:
            raise PlanFormatError(path, f"target id {unknown[0]!r} names no space of floor/spaces", where)
        found = _door(seg_id, listed, copies.get(seg_id, []), shapes, width_m, path, log)
        if found is None:
            continue
        ids, geo = found
        sources[geo.source] += 1
        doors.append(
            Door(seg_id, ids[0], ids[1] if len(ids) > 1 else None, geo.x, geo.y, geo.width_m, geo.angle_rad)
        )
    return doors, sources


def _door(
    seg_id: str, listed: list[Listing], copies, shapes: _Shapes, width_m: float, path: Path, log: RepairLog
) -> tuple[tuple[str, ...], DoorGeometry] | None:
    """The rooms a portal joins and where its door is, or ``None`` if the door is dropped."""
    polygons = shapes.polygons
    ids = agreed_targets(seg_id, listed, copies, polygons, log)
    if ids is None:
        return None
    outlines = [shapes.outlines[t] for t in ids]
    geo = door_from_copies(copies, outlines, width_m) if copies else None
    listers = [sid for sid, _ in listed]
    agreed = len({frozenset(targets) for _, targets in listed}) == 1  # else checked by agreed_targets
    if agreed and len(ids) == 2 and any(t not in listers for t in ids):
        geo = one_sided_door(seg_id, ids, listers, geo, polygons, log)
        return None if geo is None else (ids, geo)
    if geo is None:
        geo = _placed(seg_id, ids, outlines, width_m, path, log)
    geo = door_on_walls(seg_id, ids, geo, polygons, log)
    return None if geo is None else (ids, geo)


def _portal_listings(spaces: list[_Space], path: Path) -> dict[str, list[Listing]]:
    """Every space's listing of each portal segment (distinct targets, 1 or 2), in file order."""
    out: dict[str, list[Listing]] = {}
    for s in spaces:
        for seg_id, targets in s.portals:
            ids = tuple(dict.fromkeys(targets))
            if not 1 <= len(ids) <= 2:
                where = f'space id="{s.id}" portal linesegment="{seg_id}"'
                raise PlanFormatError(path, f"<target> must name 1 or 2 spaces, not {len(ids)}", where)
            out.setdefault(seg_id, []).append((s.id, ids))
    return out


def _placed(seg_id, ids, outlines, width_m, path, log: RepairLog) -> DoorGeometry:
    """A door for a portal whose segment no space gives: on the wall its two rooms share."""
    where = f'portal linesegment="{seg_id}"'
    if len(ids) == 1:
        raise PlanFormatError(path, "names no <linesegment> of any space; an exterior door needs one", where)
    geo = door_between(outlines[0], outlines[1], width_m)
    log.note(
        where,
        "names no <linesegment> of any space",
        f"placed the door on the wall the two spaces share, at ({geo.x:.2f}, {geo.y:.2f}) m",
    )
    return geo


def _off_wall(doors: list[Door], rooms: list[Room]) -> bool:
    """Whether a door between two rooms lies farther than the usual tolerance from one's outline."""
    import shapely

    outline = {r.id: r.polygon.exterior for r in rooms}
    pairs = [(outline[rid], (d.x, d.y)) for d in doors if not d.is_exterior for rid in d.rooms]
    if not pairs:
        return False
    lines, centres = zip(*pairs, strict=True)
    far = shapely.distance(np.asarray(lines, dtype=object), shapely.points(centres))
    return bool((far > WALL_TOLERANCE_M).any())


def _building_type(root: ET.Element) -> BuildingType:
    text = (root.findtext("building_type/main_type") or "").strip().lower()
    return BuildingType(text) if text in {t.value for t in BuildingType} else BuildingType.UNKNOWN


def _metadata(
    root: ET.Element, source: str, path: Path, m_per_px: float, sources: Counter, repairs
) -> dict[str, Any]:
    name = (root.findtext("name") or "").strip()
    meta: dict[str, Any] = {
        "source": source,
        "name": PureWindowsPath(name).name if name else path.stem,
        "scale_m_per_px": m_per_px,
        "door_geometry": {k: sources.get(k, 0) for k in ("segment", "jambs", "point", "placed")},
    }
    if root.get("id"):
        meta["building_id"] = root.get("id")
    if repairs:
        meta["repairs"] = repairs
    groups = [
        {
            "name": g.findtext("name") or "",
            "type": g.findtext("type") or "",
            "rooms": [s.text for s in g.findall("space")],
        }
        for g in root.iter("group_features")
    ]
    if groups:
        meta["groups"] = groups
    return meta
