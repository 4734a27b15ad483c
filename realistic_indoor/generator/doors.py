"""Placing doors on shared walls: widths, clearance from wall corners, exterior walls."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from realistic_indoor.generator.geometry import Contact, Rect, contact, subtract_intervals, to_units
from realistic_indoor.generator.plan import Plan, PlanDoor

if TYPE_CHECKING:
    import numpy as np

__all__ = ["DoorRules", "add_door", "add_exterior_door", "door_fits", "exterior_walls", "open_between"]


@dataclass(frozen=True)
class DoorRules:
    """Widths and clearances of doors (grid units, see :mod:`realistic_indoor.generator.geometry`).

    Attributes:
        room: Width of an ordinary room's door (0.9 m).
        hall: Width of a hall's doors to rooms and of a corridor's side openings (1.2 m).
        entrance: Width of a main entrance (1.8 m).
        exit: Width of a secondary exterior door at a corridor end (1.1 m).
        margin: Clearance between a door and the end of its wall piece (0.3 m), so the door is
            away from the corner and a 0.5 m robot can turn through it.
        open_margin: Clearance of an open passage between two circulation spaces (0.15 m).
        spacing: Smallest wall between two doors on one wall (0.5 m).
    """

    room: int = to_units(0.9)
    hall: int = to_units(1.2)
    entrance: int = to_units(1.8)
    exit: int = to_units(1.1)
    margin: int = to_units(0.3)
    open_margin: int = to_units(0.15)
    spacing: int = to_units(0.5)

    def needed(self, width: int) -> int:
        """Length of wall a door of ``width`` needs, clearances included (units)."""
        return width + 2 * self.margin


RULES = DoorRules()


def door_fits(c: Contact, width: int, rules: DoorRules = RULES) -> bool:
    """Whether a door of ``width`` fits on the wall piece ``c`` with its clearances."""
    return c.length >= rules.needed(width)


def _free_spans(plan: Plan, c: Contact, rules: DoorRules, margin: int) -> list[tuple[int, int]]:
    lo, hi = c.lo + margin, c.hi - margin
    taken = []
    for d in plan.doors_on(c.axis, c.coord):
        if c.lo < d.centre2 / 2 < c.hi:
            half = d.width / 2 + rules.spacing
            taken.append((int(d.centre2 / 2 - half), int(d.centre2 / 2 + half + 1)))
    return subtract_intervals(lo, hi, taken) if taken else ([(lo, hi)] if hi > lo else [])


def add_door(
    plan: Plan,
    a: int,
    b: int | None,
    c: Contact,
    width: int,
    rng: np.random.Generator | None = None,
    *,
    where: str = "random",
    rules: DoorRules = RULES,
    margin: int | None = None,
) -> bool:
    """Put a door between rooms ``a`` and ``b`` on wall piece ``c``, clear of other doors.

    Args:
        plan: The plan (the door is appended to ``plan.doors``).
        a: One room.
        b: The other room, or ``None`` for an exterior door.
        c: The shared wall piece.
        width: Door width (units); shrunk to fit an open passage, never below 0.6 m.
        rng: Random source for ``where="random"`` and ``"end"``.
        where: ``"centre"`` of the free wall, ``"end"`` (near one end, as office doors are) or
            ``"random"``.
        rules: Clearances.
        margin: Clearance at the wall's ends (default ``rules.margin``).

    Returns:
        Whether a door was placed.
    """
    margin = rules.margin if margin is None else margin
    spans = [s for s in _free_spans(plan, c, rules, margin) if s[1] - s[0] >= width]
    if not spans:
        return False
    if where == "centre" or rng is None:
        lo, hi = max(spans, key=lambda s: s[1] - s[0])
        centre2 = lo + hi
    else:
        lo, hi = spans[int(rng.integers(len(spans)))]
        first, last = 2 * lo + width, 2 * hi - width
        if where == "end":
            slack = min(last - first, to_units(0.6) * 2)
            centre2 = (
                first + int(rng.integers(slack + 1))
                if rng.random() < 0.5
                else last - int(rng.integers(slack + 1))
            )
        else:
            centre2 = int(rng.integers(first, last + 1))
    plan.doors.append(PlanDoor(a, b, c.axis, c.coord, centre2, width))
    return True


def open_between(
    plan: Plan, a: int, b: int, rules: DoorRules = RULES, max_width: int = to_units(3.0)
) -> bool:
    """Join two circulation spaces by an opening as wide as their longest shared wall allows.

    The opening keeps ``rules.open_margin`` of wall at both ends, so the side walls of a
    corridor stay whole, keeps clear of doors already on that wall, and is at most
    ``max_width`` wide.

    Returns:
        Whether they share enough free wall for a 0.6 m opening.
    """
    best, best_span = None, 0
    for c in plan.shared(a, b):
        spans = _free_spans(plan, c, rules, rules.open_margin)
        span = max((hi - lo for lo, hi in spans), default=0)
        if span > best_span:
            best, best_span = c, span
    width = min(best_span, max_width)
    if best is None or width < to_units(0.6):
        return False
    return add_door(plan, a, b, best, width, where="centre", rules=rules, margin=rules.open_margin)


def add_exterior_door(
    plan: Plan,
    i: int,
    width: int,
    *,
    axis: str | None = None,
    rules: DoorRules = RULES,
    margin: int | None = None,
) -> bool:
    """Put a door from room ``i`` to the outside on its longest facade that takes one.

    The door is ``width`` wide, or narrower down to a room door's width where the facade is
    short; facades that cannot hold a room door are passed over.

    Args:
        plan: The plan.
        i: The room.
        width: Width wanted (units).
        axis: Only facades along this axis (``"v"`` or ``"h"``), e.g. the end of a corridor.
        rules: Widths and clearances.
        margin: Clearance at the facade's ends (default ``rules.margin``).

    Returns:
        Whether a door was placed.
    """
    margin = rules.margin if margin is None else margin
    for w in exterior_walls(plan, i):
        fits = min(width, w.length - 2 * margin)
        usable = (axis is None or w.axis == axis) and fits >= min(width, rules.room)
        if usable and add_door(plan, i, None, w, fits, where="centre", rules=rules, margin=margin):
            return True
    return False


def exterior_walls(plan: Plan, i: int) -> list[Contact]:
    """Pieces of room ``i``'s outline that face the outside (not a courtyard), longest first."""
    rects = plan.rooms[i].rects
    covered: dict[tuple[str, int], list[tuple[int, int]]] = {}
    for w in plan.walls_of(i):
        covered.setdefault((w.axis, w.coord), []).append((w.lo, w.hi))
    for k, r in enumerate(rects):
        for s in rects[k + 1 :]:
            w = contact(r, s)
            if w is not None:
                covered.setdefault((w.axis, w.coord), []).append((w.lo, w.hi))
    out = []
    for r in rects:
        for axis, coord, outward, lo, hi in _sides(r):
            for a, b in subtract_intervals(lo, hi, covered.get((axis, coord), [])):
                if not _in_hole(plan.exterior_holes, axis, coord + outward, (a + b) / 2):
                    out.append(Contact(axis, coord, a, b))
    return sorted(out, key=lambda w: (-w.length, w))


def _sides(r: Rect) -> list[tuple[str, int, int, int, int]]:
    """``(axis, coord, outward step, lo, hi)`` of the four sides of a rectangle."""
    x0, y0, x1, y1 = r
    return [("h", y0, -1, x0, x1), ("h", y1, 1, x0, x1), ("v", x0, -1, y0, y1), ("v", x1, 1, y0, y1)]


def _in_hole(holes: list[Rect], axis: str, coord: float, along: float) -> bool:
    x, y = (coord, along) if axis == "v" else (along, coord)
    return any(h[0] <= x <= h[2] and h[1] <= y <= h[3] for h in holes)
