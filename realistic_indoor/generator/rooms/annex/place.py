"""Where an annex stands: outside a corridor end or a hall's facade, its service rooms along its far side."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from realistic_indoor.building.labels import SemanticLabel
from realistic_indoor.generator.doors import RULES, exterior_walls
from realistic_indoor.generator.geometry import UNITS_PER_M, Contact, Rect, area_to_units, to_units
from realistic_indoor.generator.plan import Plan, PlanRoom

if TYPE_CHECKING:
    from collections.abc import Sequence

    import numpy as np

    from realistic_indoor.generator.rooms.style import TypeStyle

__all__ = ["ANNEX_RATIO", "ANNEX_SCALES", "add_annex", "expected_service_rooms"]

ANNEX_SCALES = (1.0, 0.8, 0.65)
"""Shares of its area an annex is tried at, in turn, while it finds no free place."""
ANNEX_RATIO = (1.3, 1.9)
"""Range of an annex's long side over its short side, drawn uniformly."""


def _outward(plan: Plan, i: int, w: Contact) -> int:
    """+1 if outside lies towards growing coordinates from wall ``w`` of room ``i``, else -1."""
    for r in plan.rooms[i].rects:
        if (w.axis == "v" and r[2] == w.coord) or (w.axis == "h" and r[3] == w.coord):
            return 1
    return -1


def _free(plan: Plan, box: Rect) -> bool:
    return not any(
        min(box[2], r[2]) > max(box[0], r[0]) and min(box[3], r[3]) > max(box[1], r[1])
        for room in plan.rooms
        for r in room.rects
    )


def _built(plan: Plan, strip: Rect) -> bool:
    """Whether rooms cover all of ``strip`` (the annex's back leaves no pocket of void behind it)."""
    covered = sum(
        max(0, min(strip[2], r[2]) - max(strip[0], r[0])) * max(0, min(strip[3], r[3]) - max(strip[1], r[1]))
        for room in plan.rooms
        for r in room.rects
    )
    return covered >= (strip[2] - strip[0]) * (strip[3] - strip[1])


def add_annex(
    plan: Plan,
    rng: np.random.Generator,
    style: TypeStyle,
    area_m2: float,
    label: SemanticLabel = SemanticLabel.HALL,
    keep_clear: Sequence[Contact] = (),
    room_m: tuple[tuple[float, float], float] = ((2.6, 3.4), 3.5),
    function: str | None = None,
    service_rooms: bool = True,
    scales: tuple[float, ...] = ANNEX_SCALES,
) -> int:
    """Attach a hall of about ``area_m2`` outside a corridor end or a hall's facade.

    Its far side holds a strip of small rooms that open onto it (changing rooms, storage),
    unless ``service_rooms`` is false.

    Tries the facades of corridors and halls in random order, each with the annex's long side
    along or across the facade and centred on it or flush with either end, and keeps the first
    that overlaps nothing and whose back lies against the building all along (no pocket of void
    enclosed behind it); where nothing fits, a smaller annex is tried (``scales`` of the area in
    turn: 80%, then 65%, by default).

    ``label`` is the annex's semantic label: a hall (the paper's convention) or a big room (as
    the real school plans label their gyms). The annex never stands against a wall of
    ``keep_clear`` (the lobby's facade, kept for the main entrance). ``room_m`` is the range of
    the depth of the rooms on its far side and the length along it each takes (m).
    ``function`` names the annex (default: the style's ``annex``).

    Returns:
        The annex's room index, or -1 if there was no free place (the building is then smaller
        by the annex's area).
    """
    ratio = rng.uniform(*ANNEX_RATIO)
    spots = [
        (i, w)
        for i, r in enumerate(plan.rooms)
        if r.is_circulation and r.role != "stub"
        for w in exterior_walls(plan, i)
        if w.length >= RULES.needed(RULES.hall)
    ]
    order = [spots[int(k)] for k in rng.permutation(len(spots))]
    for scale in scales:
        long_side = math.sqrt(area_m2 * scale * ratio) * UNITS_PER_M
        short_side = area_to_units(area_m2 * scale) / long_side
        for i, w in order:
            box = _fit(plan, w, _outward(plan, i, w), long_side, short_side)
            if box is not None and not any(_against(box, c) for c in keep_clear):
                room = PlanRoom([box], label, function=function or style.annex, role="annex")
                if not service_rooms:
                    return plan.add(room)
                return _place(plan, rng, style, room, w.axis, _outward(plan, i, w), room_m)
    return -1


def expected_service_rooms(area_m2: float, room_m: tuple[tuple[float, float], float]) -> float:
    """About how many small rooms :func:`add_annex` puts along an annex of ``area_m2``.

    The mean over the annex's two orientations, at the middle of :data:`ANNEX_RATIO`, of the
    rooms of ``room_m``'s length along one side (at least two), as :func:`_place` cuts them.
    """
    ratio = sum(ANNEX_RATIO) / 2
    sides_m = (math.sqrt(area_m2 * ratio), math.sqrt(area_m2 / ratio))
    return sum(max(2, int(side / room_m[1])) for side in sides_m) / 2


def _against(box: Rect, wall: Contact) -> bool:
    """Whether a side of ``box`` lies along part of ``wall``."""
    if wall.axis == "v":
        return wall.coord in (box[0], box[2]) and min(box[3], wall.hi) > max(box[1], wall.lo)
    return wall.coord in (box[1], box[3]) and min(box[2], wall.hi) > max(box[0], wall.lo)


def _fit(plan: Plan, w: Contact, sign: int, long_side: float, short_side: float) -> Rect | None:
    """A free box against wall ``w``: either side along it, centred or flush with either end."""
    need = RULES.needed(RULES.hall)
    for along, depth in ((long_side, short_side), (short_side, long_side)):
        size = round(along)
        starts = ((w.lo + w.hi - size) // 2, w.hi - size, w.lo, w.lo + need - size, w.hi - need)
        c0, c1 = (w.coord, w.coord + round(depth)) if sign > 0 else (w.coord - round(depth), w.coord)
        for a in starts:
            box = (c0, a, c1, a + size) if w.axis == "v" else (a, c0, a + size, c1)
            back = w.coord - 1 if sign > 0 else w.coord
            behind = (back, a, back + 1, a + size) if w.axis == "v" else (a, back, a + size, back + 1)
            if min(a + size, w.hi) - max(a, w.lo) >= need and _free(plan, box) and _built(plan, behind):
                return box
    return None


def _place(
    plan: Plan,
    rng: np.random.Generator,
    style: TypeStyle,
    room: PlanRoom,
    axis: str,
    sign: int,
    room_m: tuple[tuple[float, float], float],
) -> int:
    """The annex ``room`` (one rect: its box), with small service rooms along its far side opening onto it."""
    x0, y0, x1, y1 = room.rects[0]
    depths, length = room_m
    depth = to_units(rng.uniform(*depths))
    if axis == "v":
        hall = (x0, y0, x1 - depth, y1) if sign > 0 else (x0 + depth, y0, x1, y1)
        strip, along = ((x1 - depth, x1) if sign > 0 else (x0, x0 + depth)), (y0, y1)
    else:
        hall = (x0, y0, x1, y1 - depth) if sign > 0 else (x0, y0 + depth, x1, y1)
        strip, along = ((y1 - depth, y1) if sign > 0 else (y0, y0 + depth)), (x0, x1)
    room.rects[0] = hall
    annex = plan.add(room)
    n = max(2, (along[1] - along[0]) // to_units(length))
    cuts = [along[0] + (along[1] - along[0]) * k // n for k in range(n + 1)]
    for k in range(n):
        a, b = cuts[k], cuts[k + 1]
        rect = (strip[0], a, strip[1], b) if axis == "v" else (a, strip[0], b, strip[1])
        function = style.annex_functions[k % len(style.annex_functions)]
        plan.add(PlanRoom([rect], SemanticLabel.SMALL, function=function, role="closet", host=annex))
    return annex
