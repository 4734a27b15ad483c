"""The house's rooms on the plan: the day rooms, the entrance, the hallway and the rooms of each band."""

from __future__ import annotations

import itertools
import math
from typing import TYPE_CHECKING

from realistic_indoor.generator.house.bands import split, tuck
from realistic_indoor.generator.house.layout import MIN_DAY_ROOM
from realistic_indoor.generator.plan import B, C, H, M, PlanRoom, S

if TYPE_CHECKING:
    from realistic_indoor.generator.geometry import Rect
    from realistic_indoor.generator.house.layout import Frame
    from realistic_indoor.generator.house.programme import ProgrammeRoom
    from realistic_indoor.generator.plan import Plan

__all__ = ["ENTRANCE", "HALLWAY", "add_rooms"]

ENTRANCE = "entrance"
"""Functional label of the entrance (a hall, see ``data/function_labels.json``)."""
HALLWAY = "hallway"
"""Functional label of the hallways (a corridor)."""


def add_rooms(plan: Plan, frame: Frame, day: tuple[ProgrammeRoom, ...]) -> None:
    """Add every room of the frame to the plan: day rooms, entrance, hallway, the bands' rooms.

    Roles: ``"living"`` for the day rooms (``"kitchen"`` for the kitchen), ``"lobby"`` for the
    entrance, ``"corridor"`` for the hallway, ``"room"`` for the rooms along it. The semantic
    labels are placeholders (small for service rooms, medium else) until the rooms have their
    final size.

    Args:
        plan: The plan (empty).
        frame: The zones, the rooms of each band in order and their widths.
        day: The day rooms, the living room first.
    """
    for room, rect in zip(day, day_rects(frame.day, [r.area_m2 for r in day]), strict=True):
        role = "kitchen" if room.function == "kitchen" else "living"
        plan.add(PlanRoom(rect, B, function=room.function, role=role))
    plan.add(PlanRoom([frame.entrance], H, function=ENTRANCE, role="lobby"))
    plan.add(PlanRoom(list(frame.hallway), C, function=HALLWAY, role="corridor"))
    for band, rooms, ws in zip(frame.bands, frame.rooms, frame.widths, strict=True):
        x = band.x0
        rects: list[list[Rect]] = []
        for w in ws:
            rects.append([(x, band.y0, x + w, band.y1)])
            x += w
        tuck(rects, rooms, band)
        for room, shape in zip(rooms, rects, strict=True):
            plan.add(PlanRoom(shape, S if room.small else M, function=room.function, role="room"))


def day_rects(box: Rect, areas: list[float]) -> list[list[Rect]]:
    """The day rooms in ``box`` (units), in proportion to ``areas``, each beside the one before.

    The rooms fill columns side by side, from the east (the entrance's) side, one above the
    other within a column: up the first column from its south-east corner (the first room
    meets the entrance there), down the next, and so on, so that consecutive rooms share a
    wall. Of the ways to cut the rooms, in order, into columns whose rooms keep
    :data:`MIN_DAY_ROOM`, the one whose most elongated room is least elongated is taken.
    """
    x0, y0, x1, y1 = box
    groups = _columns(areas, x1 - x0, y1 - y0)
    rects, right = [], x1
    widths_ = split(x1 - x0, [sum(g) for g in groups], [MIN_DAY_ROOM] * len(groups))
    for k, (w, group) in enumerate(zip(widths_, groups, strict=True)):
        column = _stack((right - w, y0, right, y1), group)
        rects += column if k % 2 == 0 else column[::-1]
        right -= w
    return [[r] for r in rects]


def _columns(areas: list[float], width: int, depth: int) -> list[list[float]]:
    """``areas`` cut, in order, into the columns of :func:`day_rects` (a ``width`` by ``depth`` box)."""
    total = sum(areas)
    best, best_cost = [list(areas)], math.inf
    for n in range(1, len(areas) + 1):
        for cuts in itertools.combinations(range(1, len(areas)), n - 1):
            edges = (0, *cuts, len(areas))
            groups = [areas[edges[j] : edges[j + 1]] for j in range(n)]
            cost = 0.0
            for g in groups:
                w = width * sum(g) / total
                if w < MIN_DAY_ROOM or len(g) * MIN_DAY_ROOM > depth:
                    cost = math.inf
                    break
                for a in g:
                    h = depth * a / sum(g)
                    cost = max(cost, w / h, h / w)
            if cost < best_cost:
                best, best_cost = groups, cost
    return best


def _stack(box: Rect, areas: list[float]) -> list[Rect]:
    """Rectangles filling ``box`` one above the other from its south side, in proportion to ``areas``.

    Where the box is too short for every room at :data:`MIN_DAY_ROOM`, they are in proportion.
    """
    x0, y0, x1, y1 = box
    out, y = [], y0
    for h in split(y1 - y0, areas, [MIN_DAY_ROOM] * len(areas)):
        out.append((x0, y, x1, y + h))
        y += h
    return out
