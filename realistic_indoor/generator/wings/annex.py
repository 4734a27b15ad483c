"""A large hall beside the wings (a school's gym), reached from a corridor end or a hall."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from realistic_indoor.building.labels import SemanticLabel
from realistic_indoor.generator.doors import RULES, exterior_walls
from realistic_indoor.generator.geometry import Contact, Rect, to_units
from realistic_indoor.generator.plan import Plan, PlanRoom

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.wings.style import WingStyle

__all__ = ["add_annex"]


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


def add_annex(plan: Plan, rng: np.random.Generator, style: WingStyle, area_m2: float) -> int:
    """Attach a hall of about ``area_m2`` outside a corridor end or a hall's facade.

    Its far side holds a strip of small rooms that open onto it (changing rooms, storage).

    Tries the facades of corridors and halls in random order, each with the annex's long side
    along or across the facade, and keeps the first that overlaps nothing.

    Returns:
        The annex's room index, or -1 if there was no free place (the building keeps its area).
    """
    ratio = rng.uniform(1.3, 1.9)
    long_side = math.sqrt(area_m2 * ratio) * 10
    short_side = area_m2 * 100 / long_side
    spots = [
        (i, w)
        for i, r in enumerate(plan.rooms)
        if r.is_circulation and r.role != "stub"
        for w in exterior_walls(plan, i)
        if w.length >= RULES.needed(RULES.hall)
    ]
    for k in rng.permutation(len(spots)):
        i, w = spots[int(k)]
        sign = _outward(plan, i, w)
        for along, depth in ((long_side, short_side), (short_side, long_side)):
            mid = (w.lo + w.hi) / 2 + rng.uniform(-0.3, 0.3) * along
            a = round(mid - along / 2)
            b = a + round(along)
            c0, c1 = (w.coord, w.coord + round(depth)) if sign > 0 else (w.coord - round(depth), w.coord)
            box = (c0, a, c1, b) if w.axis == "v" else (a, c0, b, c1)
            if min(b, w.hi) - max(a, w.lo) >= RULES.needed(RULES.hall) and _free(plan, box):
                return _place(plan, rng, style, box, w.axis, sign)
    return -1


def _place(plan: Plan, rng: np.random.Generator, style: WingStyle, box: Rect, axis: str, sign: int) -> int:
    """The annex hall, with a strip of small service rooms along its far side opening onto it."""
    x0, y0, x1, y1 = box
    depth = to_units(rng.uniform(2.6, 3.4))
    if axis == "v":
        hall = (x0, y0, x1 - depth, y1) if sign > 0 else (x0 + depth, y0, x1, y1)
        strip, along = ((x1 - depth, x1) if sign > 0 else (x0, x0 + depth)), (y0, y1)
    else:
        hall = (x0, y0, x1, y1 - depth) if sign > 0 else (x0, y0 + depth, x1, y1)
        strip, along = ((y1 - depth, y1) if sign > 0 else (y0, y0 + depth)), (x0, x1)
    annex = plan.add(PlanRoom([hall], SemanticLabel.HALL, function=style.annex, role="annex"))
    n = max(2, (along[1] - along[0]) // to_units(3.5))
    cuts = [along[0] + (along[1] - along[0]) * k // n for k in range(n + 1)]
    for k in range(n):
        a, b = cuts[k], cuts[k + 1]
        rect = (strip[0], a, strip[1], b) if axis == "v" else (a, strip[0], b, strip[1])
        function = style.annex_functions[k % len(style.annex_functions)]
        plan.add(PlanRoom([rect], SemanticLabel.SMALL, function=function, role="closet", host=annex))
    return annex
