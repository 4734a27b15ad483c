"""Partial regeneration: resample a portion of a building, keep the rest as it is."""

from __future__ import annotations

import math
from dataclasses import replace
from typing import TYPE_CHECKING, Any

import numpy as np

from realistic_indoor.building import Building, Door, Room, SemanticLabel
from realistic_indoor.building.labels import ROOM_LABELS, BuildingType
from realistic_indoor.errors import ConfigError
from realistic_indoor.generator.connect import (
    break_mazes,
    connect_circulation,
    connect_rooms,
    ensure_reachable,
)
from realistic_indoor.generator.doors import RULES, add_exterior_door
from realistic_indoor.generator.functions import FunctionRoles, assign_functions
from realistic_indoor.generator.geometry import (
    UNITS_PER_M,
    Rect,
    area_to_units,
    contact,
    outline,
    to_metres,
    to_units,
)
from realistic_indoor.generator.plan import C, Plan, PlanDoor, PlanRoom, build_door
from realistic_indoor.generator.rooms.bays import BayContext, Budget, subdivide
from realistic_indoor.generator.rooms.corridors import corridor_fronts, segment_corridors
from realistic_indoor.generator.rooms.regions import Bay

if TYPE_CHECKING:
    from collections.abc import Sequence

    from realistic_indoor.models.building_model import BuildingTypeModel

__all__ = ["regenerate", "select_rooms"]


def select_rooms(
    building: Building,
    rooms: Sequence[str] | None = None,
    region: tuple[float, float, float, float] | None = None,
) -> list[str]:
    """Ids of the rooms named, or of the rooms whose centroid lies in ``region``, in building order.

    Raises:
        ConfigError: If neither or both are given, an id is unknown, the box is malformed, or
            nothing is selected.
    """
    if (rooms is None) == (region is None):
        raise ConfigError("regenerate needs either rooms=[ids] or region=(xmin, ymin, xmax, ymax)")
    if rooms is not None:
        if isinstance(rooms, str):
            rooms = [rooms]
        unknown = [r for r in rooms if r not in building.room_by_id]
        if unknown:
            raise ConfigError(
                f"no room with id {unknown[0]!r} in the building (ids are like {building.rooms[0].id!r})"
            )
        wanted = set(rooms)
    else:
        try:
            x0, y0, x1, y1 = (float(v) for v in region)  # type: ignore[union-attr]
        except (TypeError, ValueError):
            raise ConfigError(f"region must be (xmin, ymin, xmax, ymax) in metres, not {region!r}") from None
        if not (x0 < x1 and y0 < y1):
            raise ConfigError(f"region {region!r} is empty: it needs xmin < xmax and ymin < ymax")
        wanted = {
            r.id
            for r in building.rooms
            if x0 <= r.polygon.centroid.x <= x1 and y0 <= r.polygon.centroid.y <= y1
        }
    picked = [r.id for r in building.rooms if r.id in wanted]
    if not picked:
        raise ConfigError(f"no room has its centre in the region {region!r}")
    return picked


def _units(v: float, what: str) -> int:
    u = v * UNITS_PER_M
    if abs(u - round(u)) > 1e-6:
        raise ConfigError(
            f"{what} is not on the 0.1 m grid; regenerate works on rectilinear plans such as generated ones"
        )
    return round(u)


def _rects(room: Room) -> list[Rect]:
    """A rectilinear room outline as rectangles (units)."""
    pts = [(_units(x, f"room {room.id!r}"), _units(y, f"room {room.id!r}")) for x, y in room.outline]
    for (ax, ay), (bx, by) in zip(pts, pts[1:] + pts[:1], strict=True):
        if ax != bx and ay != by:
            raise ConfigError(f"room {room.id!r} is not rectilinear; regenerate works on rectilinear plans")
    xs, ys = sorted({p[0] for p in pts}), sorted({p[1] for p in pts})
    if len(pts) == 4:
        return [(xs[0], ys[0], xs[-1], ys[-1])]
    rows: list[tuple[int, int, int, int]] = []
    for m in range(len(ys) - 1):
        cy = (ys[m] + ys[m + 1]) / 2
        inside = [k for k in range(len(xs) - 1) if _inside(pts, (xs[k] + xs[k + 1]) / 2, cy)]
        for k in inside:
            rows.append((xs[k], ys[m], xs[k + 1], ys[m + 1]))
    return _merge(rows)


def _inside(pts: list[tuple[int, int]], x: float, y: float) -> bool:
    hit = False
    for (ax, ay), (bx, by) in zip(pts, pts[1:] + pts[:1], strict=True):
        if (ay > y) != (by > y) and x < ax + (y - ay) * (bx - ax) / (by - ay):
            hit = not hit
    return hit


def _merge(cells: list[Rect]) -> list[Rect]:
    """Join cells into rectangles: along rows first, then rows of equal extent upwards."""
    rows: dict[tuple[int, int], list[tuple[int, int]]] = {}
    for x0, y0, x1, y1 in sorted(cells, key=lambda r: (r[1], r[0])):
        runs = rows.setdefault((y0, y1), [])
        if runs and runs[-1][1] == x0:
            runs[-1] = (runs[-1][0], x1)
        else:
            runs.append((x0, x1))
    out: list[Rect] = []
    for (y0, y1), runs in sorted(rows.items()):
        for x0, x1 in runs:
            up = next((k for k, r in enumerate(out) if r[3] == y0 and r[0] == x0 and r[2] == x1), None)
            if up is None:
                out.append((x0, y0, x1, y1))
            else:
                out[up] = (x0, out[up][1], x1, y1)
    return out


def _plan_of(building: Building) -> Plan:
    """The building as a plan in grid units (rooms in order, doors in order)."""
    plan = Plan()
    index = {}
    for r in building.rooms:
        index[r.id] = plan.add(PlanRoom(_rects(r), r.label, r.function, role="kept"))
    for d in building.doors:
        vertical = abs(math.sin(d.angle_rad)) > 0.5
        along, fixed = (d.y, d.x) if vertical else (d.x, d.y)
        plan.doors.append(
            PlanDoor(
                index[d.room_a],
                None if d.room_b is None else index[d.room_b],
                "v" if vertical else "h",
                _units(fixed, f"door {d.id!r}"),
                to_units(2 * along),
                to_units(d.width_m),
            )
        )
    return plan


def _model_for(building: Building) -> BuildingTypeModel:
    from realistic_indoor.models import default_model, fit_model

    if building.building_type in (BuildingType.OFFICE, BuildingType.SCHOOL, BuildingType.HOUSE):
        return default_model(building.building_type)
    return fit_model([building])


def _region_bays(plan: Plan, cells: list[Rect], circulation: set[int]) -> list[Bay]:
    """The region as rectangles, each a bay facing the side with the most circulation."""
    bays = []
    for rect in _merge(cells):
        touch = {"S": 0, "N": 0, "W": 0, "E": 0}
        for j in circulation:
            for r in plan.rooms[j].rects:
                c = contact(rect, r)
                if c is not None:
                    side = (
                        ("S" if c.coord == rect[1] else "N")
                        if c.axis == "h"
                        else ("W" if c.coord == rect[0] else "E")
                    )
                    touch[side] += c.length
        side = max(touch, key=lambda s: (touch[s], s))
        bays.append(Bay(rect, "x" if side in "SN" else "y", side))
    return bays


def _budget(model: BuildingTypeModel, bays: list[Bay]) -> Budget:
    shares = model.shares()
    total = sum(shares[lab] for lab in ROOM_LABELS) or 1.0
    frontage = sum(b.length for b in bays)
    depth = sum(b.depth * b.length for b in bays) / max(frontage, 1)
    width = sum(
        area_to_units(shares[lab] / total * model.stats(lab).area_mean) / max(depth, 1) for lab in ROOM_LABELS
    )
    n = frontage / max(width, 1)
    p = {lab: shares[lab] / total * n for lab in ROOM_LABELS}
    small = p[SemanticLabel.SMALL]
    return Budget(
        {
            "M": p[SemanticLabel.MEDIUM],
            "B": p[SemanticLabel.BIG],
            "S": small,
            "core": model.structures.clustered_small_rooms * small / 4,
            "closet": model.structures.closets_per_room * (p[SemanticLabel.MEDIUM] + p[SemanticLabel.BIG]),
        }
    )


def _recut_corridors(plan: Plan, chosen: list[int], rng: np.random.Generator) -> list[int]:
    """Merge selected corridor segments that line up and cut them again at new places."""
    rects = [plan.rooms[i].rects[0] for i in chosen if len(plan.rooms[i].rects) == 1]
    pieces = _merge_lines(rects)
    for i in chosen:
        plan.rooms[i].rects = []
    fronts = corridor_fronts(plan, pieces)
    segments = segment_corridors(pieces, len(rects), rng, 30, [], fronts, 15)
    plan.invalidate()
    return [plan.add(PlanRoom([s], C, "corridor", role="corridor")) for s in segments]


def _merge_lines(rects: list[Rect]) -> list[Rect]:
    out = list(rects)
    merged = True
    while merged:
        merged = False
        for a in range(len(out)):
            for b in range(a + 1, len(out)):
                r, s = out[a], out[b]
                row = r[1] == s[1] and r[3] == s[3] and (r[2] == s[0] or s[2] == r[0])
                col = r[0] == s[0] and r[2] == s[2] and (r[3] == s[1] or s[3] == r[1])
                if row or col:
                    out[a] = (min(r[0], s[0]), min(r[1], s[1]), max(r[2], s[2]), max(r[3], s[3]))
                    del out[b]
                    merged = True
                    break
            if merged:
                break
    return out


def regenerate(
    building: Building,
    rooms: Sequence[str] | None = None,
    region: tuple[float, float, float, float] | None = None,
    seed: int | None = None,
    *,
    model: BuildingTypeModel | None = None,
) -> Building:
    """Resample a portion of a building and keep everything else.

    The selected small, medium and big rooms are merged into rectangles and cut again into new
    rooms with sizes and labels drawn from the model, facing the corridor or hall they touch
    most; selected corridors keep their place but are cut into segments anew; selected halls
    keep their shape. Every other room, and every door between two other rooms, stays
    identical (same ids, same geometry); doors into the portion are placed anew, and rooms that
    lose their way in get a new door. The result is valid (see
    :func:`realistic_indoor.building.check_building`).

    Args:
        building: A plan on a 0.1 m grid with rectilinear rooms (a generated building).
        rooms: Ids of the rooms to resample.
        region: Or a box ``(xmin, ymin, xmax, ymax)`` in metres: the rooms whose centroid lies in it.
        seed: Seed of the random generator (``None``: a fresh one).
        model: The building-type model to draw rooms from (default: the type's, or for an
            unknown type one fitted to the building itself).

    Returns:
        The new building; its metadata lists the regenerations under ``"regenerated"``.

    Raises:
        ConfigError: For a bad selection, or a plan that is not rectilinear on the 0.1 m grid.

    Examples:
        >>> from realistic_indoor.generator import generate
        >>> b = generate("office", 800, seed=1)
        >>> b2 = regenerate(b, rooms=[b.rooms[-1].id], seed=2)
        >>> all(r in b2.rooms for r in b.rooms[:-1] if r.label.value == "corridor")
        True
    """
    picked = select_rooms(building, rooms, region)
    if seed is not None and (not isinstance(seed, (int, np.integer)) or isinstance(seed, bool) or seed < 0):
        raise ConfigError(f"seed must be a non-negative integer, not {seed!r}")
    rng = np.random.default_rng(seed)
    model = model if model is not None else _model_for(building)
    plan = _plan_of(building)
    index = {r.id: i for i, r in enumerate(building.rooms)}
    chosen = {index[rid] for rid in picked}
    exterior_before = sum(d.b is None for d in plan.doors)
    plan.doors = [d for d in plan.doors if d.a not in chosen and d.b not in chosen]
    kept_doors = len(plan.doors)
    new = _resample(plan, chosen, model, rng)
    _reconnect(plan, new, chosen, model, rng, exterior_before)
    return _rebuild(building, plan, new, kept_doors, picked, seed)


def _resample(plan: Plan, chosen: set[int], model: BuildingTypeModel, rng: np.random.Generator) -> set[int]:
    """Replace the chosen ordinary rooms and corridors by new ones; returns the new rooms."""
    ordinary = sorted(i for i in chosen if plan.rooms[i].label in ROOM_LABELS)
    corridors = sorted(i for i in chosen if plan.rooms[i].label is C)
    cells = [r for i in ordinary for r in plan.rooms[i].rects]
    for i in ordinary:
        plan.rooms[i].rects = []
    plan.invalidate()
    first = len(plan.rooms)
    _recut_corridors(plan, corridors, rng)
    circulation = {i for i, r in enumerate(plan.rooms) if r.is_circulation and r.rects}
    bays = _region_bays(plan, cells, circulation)
    m, s = model.stats(SemanticLabel.MEDIUM), model.stats(SemanticLabel.SMALL)
    limit = to_units((math.sqrt(m.area_mean) + math.sqrt(s.area_mean)) / 2)
    ctx = BayContext(
        model, _budget(model, bays), [r for j in circulation for r in plan.rooms[j].rects], 14, (2, 3), limit
    )
    for bay in bays:
        subdivide(plan, bay, rng, ctx)
    return set(range(first, len(plan.rooms)))


def _reconnect(
    plan: Plan,
    new: set[int],
    chosen: set[int],
    model: BuildingTypeModel,
    rng: np.random.Generator,
    exterior_before: int,
) -> None:
    """Doors for the new rooms, the kept halls of the portion, and any lost entrance."""
    circulation = {i for i in new | chosen if plan.rooms[i].is_circulation and plan.rooms[i].rects}
    connect_circulation(plan, only=circulation)
    lost = exterior_before - sum(d.b is None for d in plan.doors)
    for i in sorted(circulation, key=lambda k: -plan.rooms[k].area):
        if lost <= 0:
            break
        lost -= add_exterior_door(plan, i, RULES.exit)
    if not any(d.b is None for d in plan.doors):
        raise ConfigError("the regenerated portion held the only entrance and has no facade to put one on")
    connect_rooms(
        plan, model, rng, model.structures.connected_room_pairs, only={i for i in new if plan.rooms[i].rects}
    )
    ensure_reachable(plan, rng)
    break_mazes(plan, rng)
    assign_functions(plan, model, rng, FunctionRoles())


def _rebuild(
    building: Building, plan: Plan, new: set[int], kept_doors: int, picked: list[str], seed: int | None
) -> Building:
    """Kept rooms and doors as they were, then the new ones with fresh ids."""
    kept_ids = [r.id for r in building.rooms]
    taken = set(kept_ids) | {d.id for d in building.doors}
    ids: list[str] = []
    counter = len(building.rooms)
    for i in range(len(plan.rooms)):
        if i < len(building.rooms):
            ids.append(kept_ids[i])
            continue
        while f"r{counter}" in taken:
            counter += 1
        ids.append(f"r{counter}")
        taken.add(ids[-1])
    gone = {building.rooms[i].id for i in range(len(building.rooms)) if not plan.rooms[i].rects}
    rooms = [r for r in building.rooms if r.id not in gone]
    rooms += [
        Room(
            ids[i],
            plan.rooms[i].label,
            plan.rooms[i].function,
            [(to_metres(x), to_metres(y)) for x, y in outline(plan.rooms[i].rects)],
        )
        for i in sorted(new)
        if plan.rooms[i].rects
    ]
    doors = [d for d in building.doors if not _touches(d, picked)]
    counter = len(building.doors)
    for d in plan.doors[kept_doors:]:
        door = build_door("", d, ids)
        while f"d{counter}" in taken:
            counter += 1
        taken.add(f"d{counter}")
        doors.append(replace(door, id=f"d{counter}"))
    history = [*building.metadata.get("regenerated", []), {"rooms": picked, "seed": seed}]
    metadata: dict[str, Any] = {**building.metadata, "regenerated": history}
    return Building(building.building_type, tuple(rooms), tuple(doors), metadata)


def _touches(d: Door, picked: list[str]) -> bool:
    return d.room_a in picked or d.room_b in picked
