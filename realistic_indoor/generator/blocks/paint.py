"""From a block's section and length to rectangles: corridors, halls, strips of rooms, courts."""

from __future__ import annotations

import functools
import itertools
from dataclasses import dataclass

from realistic_indoor.generator.blocks.section import Hall, Section
from realistic_indoor.generator.geometry import Rect, subtract_intervals, to_units
from realistic_indoor.generator.rooms.regions import Bay, FloorRegions

__all__ = ["length_for_area", "paint_block"]

MIN_HALL_M = 3.0
"""Narrowest hall along the block (m)."""

MIN_PIECE_M = 2.4
"""Shortest stretch of strip left between a hall and its neighbour (m); a hall closer than this
to a crossing, a court or another hall grows to meet it."""


@dataclass(frozen=True)
class _Frame:
    """Coordinates of a block at one length (units): bar bottoms, corridor lines, run."""

    length: int
    bottoms: tuple[int, ...]
    lines: tuple[int, ...]
    run: tuple[int, int]
    crossings: tuple[tuple[int, int], ...]

    def core(self, j: int, c: int) -> tuple[int, int]:
        """South and north edge of core ``j`` (between corridors ``j`` and ``j + 1``)."""
        return self.lines[j] + c, self.lines[j + 1]


def _frame(s: Section, length: int) -> _Frame:
    bottoms, lines, y = [], [], 0
    for south, north in s.depths:
        bottoms.append(y)
        lines.append(y + south)
        y += south + s.corridor + north
    x0, x1 = s.run(length)
    half = s.corridor // 2
    crossings = tuple(
        (x0 + round(f * (x1 - x0)) - half, x0 + round(f * (x1 - x0)) - half + s.corridor) for f in s.crossings
    )
    return _Frame(length, tuple(bottoms), tuple(lines), (x0, x1), crossings)


def paint_block(s: Section, length: int) -> FloorRegions:
    """The regions of a block of ``length`` (units): what the room toolkit turns into rooms."""
    f = _frame(s, length)
    regions = FloorRegions()
    regions.corridors = _corridors(s, f)
    courts = _courts(s, f)
    deep = _deep(s, f)
    regions.holes = [rect for rects in courts.values() for rect in rects]
    taken: dict = {"S": [], "N": []}
    for j in range(s.bars - 1):
        blocked = list(f.crossings) + [
            (r[0], r[2]) for r in courts.get(j, []) + [b.rect for b in deep.get(j, [])]
        ]
        taken[(j, "lo")], taken[(j, "hi")] = blocked, list(blocked)
    apart: dict = {}
    for i, hall in enumerate(s.halls):
        rect = _place_hall(s, f, hall, taken, apart)
        if rect is not None:
            regions.halls.append((("hall", i), [rect]))
    deep_bays = [bay for bays in deep.values() for bay in bays]
    regions.bays = _facade_bays(s, f, taken) + _core_bays(s, f, taken) + deep_bays + _end_bays(s, f)
    shapes = (
        regions.corridors + [r for _, rects in regions.halls for r in rects] + [b.rect for b in regions.bays]
    )
    regions.area = sum((r[2] - r[0]) * (r[3] - r[1]) for r in shapes)
    return regions


def _corridors(s: Section, f: _Frame) -> list[Rect]:
    """Long corridors, and the ring's ends and the crossings as pieces between two of them.

    The long corridors of a ring run from one end corridor's outer side to the other's, so an
    end strip meets every corridor piece whole (a service core's stub never straddles two).
    """
    c, (x0, x1) = s.corridor, f.run
    if s.bars == 1:
        return [(x0, y, x1, y + c) for y in f.lines]
    e = s.end_depth
    out = [(e, y, f.length - e, y + c) for y in f.lines]
    ends = ((e, e + c), (f.length - e - c, f.length - e))
    for j in range(s.bars - 1):
        y0, y1 = f.core(j, c)
        out += [(a, y0, b, y1) for a, b in (*ends, *f.crossings)]
    return out


def _sections(f: _Frame) -> list[tuple[int, int]]:
    """Stretches of a core between the crossings (units along the block)."""
    return subtract_intervals(*f.run, list(f.crossings))


def _core_sections(s: Section, f: _Frame, picks: list[tuple[int, int]]) -> list[tuple[int, Rect]]:
    """The full-depth rectangle of each picked ``(core, section)``, with the pick's index.

    A pick past the block's last section (a block shorter than its section was drawn for) is
    left out.
    """
    stretches = _sections(f)
    out = []
    for k, (j, i) in enumerate(picks):
        if i < len(stretches):
            y0, y1 = f.core(j, s.corridor)
            a, b = stretches[i]
            out.append((k, (a, y0, b, y1)))
    return out


def _courts(s: Section, f: _Frame) -> dict[int, list[Rect]]:
    out: dict[int, list[Rect]] = {}
    for k, rect in _core_sections(s, f, list(s.courts)):
        out.setdefault(s.courts[k][0], []).append(rect)
    return out


def _deep(s: Section, f: _Frame) -> dict[int, list[Bay]]:
    """The deep strips of each core: one bay across the core's depth per deep section."""
    out: dict[int, list[Bay]] = {}
    for k, rect in _core_sections(s, f, [(j, i) for j, i, _ in s.deep]):
        j, _, side = s.deep[k]
        out.setdefault(j, []).append(Bay(rect, "x", side))
    return out


def _span(s: Section, f: _Frame, hall: Hall) -> tuple[tuple[int, int], tuple[int, int], list]:
    """Where a hall may go: its range along the block, its extent across, and the strips it takes."""
    c = s.corridor
    if hall.where == "S":
        return _facade_range(s, f), (0, f.lines[0]), ["S"]
    if hall.where == "N":
        return _facade_range(s, f), (f.lines[-1] + c, f.lines[-1] + c + s.depths[-1][1]), ["N"]
    j = int(hall.where)
    y0, y1 = f.core(j, c)
    if hall.through:
        return f.run, (y0, y1), [(j, "lo"), (j, "hi")]
    mid = y0 + s.depths[j][1]
    return f.run, ((y0, mid) if hall.half == "lo" else (mid, y1)), [(j, hall.half)]


def _facade_range(s: Section, f: _Frame) -> tuple[int, int]:
    return (s.end_depth, f.length - s.end_depth) if s.bars > 1 else (0, f.length)


def _place_hall(s: Section, f: _Frame, hall: Hall, taken: dict, halls: dict) -> Rect | None:
    """The hall's rectangle in the free stretch nearest its place (``None``: no room for it).

    Halls keep a room's width (:data:`MIN_PIECE_M`) from each other: two halls side by side
    would be one hall with a door in the middle.
    """
    (lo, hi), (y0, y1), keys = _span(s, f, hall)
    width = max(round(hall.area / max(y1 - y0, 1)), to_units(MIN_HALL_M), 2 * s.corridor)
    used = sorted({iv for key in keys for iv in taken[key] + halls.setdefault(key, [])})
    want = lo + round(hall.at * (hi - lo))
    best = None
    for a, b in subtract_intervals(lo, hi, used):
        w = min(width, (b - a) // 2)
        if w < to_units(MIN_HALL_M):
            continue
        x = min(max(want - w // 2, a), b - w)
        if best is None or abs(x + w // 2 - want) < abs(best[0] + best[1] // 2 - want):
            best = (x, w)
    if best is None:
        return None
    x, w = best
    x, w = _snapped(x, w, subtract_intervals(lo, hi, used))
    gap = to_units(MIN_PIECE_M)
    for key in keys:
        taken[key].append((x, x + w))
        halls[key].append((x - gap, x + w + gap))
    return (x, y0, x + w, y1)


def _snapped(x: int, w: int, free: list[tuple[int, int]]) -> tuple[int, int]:
    """The hall ``x..x + w`` grown to the ends of its free stretch where it would leave slivers."""
    a, b = next((a, b) for a, b in free if a <= x and x + w <= b)
    gap = to_units(MIN_PIECE_M)
    x0 = a if x - a < gap else x
    x1 = b if b - (x + w) < gap else x + w
    return x0, x1 - x0


def _pieces(lo: int, hi: int, cuts: list[tuple[int, int]]) -> list[tuple[int, int]]:
    return [(a, b) for a, b in subtract_intervals(lo, hi, cuts) if b - a >= to_units(1.0)]


def _facade_bays(s: Section, f: _Frame, taken: dict) -> list[Bay]:
    lo, hi = _facade_range(s, f)
    c, top = s.corridor, f.lines[-1] + s.corridor + s.depths[-1][1]
    out = []
    for side, (y0, y1), access in (("S", (0, f.lines[0]), "N"), ("N", (f.lines[-1] + c, top), "S")):
        steps = [
            (lo + round(a * (hi - lo)), lo + round(b * (hi - lo)), d) for sd, a, b, d in s.steps if sd == side
        ]
        for a, b in _pieces(lo, hi, taken.get(side, [])):
            for p0, p1, inset in _stepped(a, b, steps):
                if inset >= y1 - y0:
                    continue
                rect = (p0, y0 + inset, p1, y1) if side == "S" else (p0, y0, p1, y1 - inset)
                out.append(Bay(rect, "x", access))
    return out


def _stepped(a: int, b: int, steps: list[tuple[int, int, int]]) -> list[tuple[int, int, int]]:
    """``(start, end, inset)`` pieces of ``a..b``: inset where a step covers it, else 0.

    Step ends closer than a metre to another cut are dropped, so no piece is a sliver.
    """
    inner = sorted({x for s0, s1, _ in steps for x in (s0, s1) if a < x < b})
    cuts = [a]
    for x in inner:
        if x - cuts[-1] >= to_units(1.0) and b - x >= to_units(1.0):
            cuts.append(x)
    cuts.append(b)
    out = []
    for p0, p1 in itertools.pairwise(cuts):
        inset = max((d for s0, s1, d in steps if s0 <= p0 and p1 <= s1), default=0)
        out.append((p0, p1, inset))
    return out


def _core_bays(s: Section, f: _Frame, taken: dict) -> list[Bay]:
    out = []
    for j in range(s.bars - 1):
        y0, y1 = f.core(j, s.corridor)
        mid = y0 + s.depths[j][1]
        out += [Bay((a, y0, b, mid), "x", "S") for a, b in _pieces(*f.run, taken[(j, "lo")])]
        out += [Bay((a, mid, b, y1), "x", "N") for a, b in _pieces(*f.run, taken[(j, "hi")])]
    return out


def _end_bays(s: Section, f: _Frame) -> list[Bay]:
    if s.bars == 1:
        return []
    e, depth = s.end_depth, f.lines[-1] + s.corridor + s.depths[-1][1]
    return [Bay((0, 0, e, depth), "y", "E"), Bay((f.length - e, 0, f.length, depth), "y", "W")]


def length_for_area(section: Section, guess: int, area: int) -> int:
    """The block length whose painted floor area is nearest ``area`` (units).

    The area grows with the length (in steps, where a hall or a strip's piece appears), so the
    length is bracketed from the guess and then found by bisection. Each length is painted once.
    """

    @functools.cache
    def painted(length: int) -> int:
        return paint_block(section, length).area

    lo, hi = max(guess // 2, 2 * section.corridor), max(guess, 2 * section.corridor + 1)
    while painted(hi) < area:
        lo, hi = hi, hi * 2
    while lo > 2 * section.corridor and painted(lo) > area:
        lo = max(lo // 2, 2 * section.corridor)
    while hi - lo > 1:
        mid = (lo + hi) // 2
        lo, hi = (mid, hi) if painted(mid) < area else (lo, mid)
    return min((lo, hi), key=lambda n: abs(painted(n) - area))
