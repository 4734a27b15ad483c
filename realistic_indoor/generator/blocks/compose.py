"""Footprints of several blocks: a main bar with wings at right angles (L, T, U and E shapes).

Real schools, and some offices, are double-loaded bars joined at right angles rather than one
deep block. A composed footprint is a main bar (one corridor, rooms on both sides; for an L, T
or U, a ring with the style's ``ring_main_p``, as offices with a wing are) with one wing (an L
at an end, a T in between), two (a U, one at each end) or more (an E or comb, evenly spaced:
large schools without a ring corridor) standing on its north facade. Each wing is a bar
too, turned a quarter: its corridor meets the main corridor through a short corridor cut across
the main bar's north strip, and runs on to the wing's far end.
"""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from realistic_indoor.generator.blocks.paint import length_for_area, paint_block
from realistic_indoor.generator.blocks.section import Section, draw_section, mean_block_depth
from realistic_indoor.generator.geometry import Rect, to_units
from realistic_indoor.generator.rooms.regions import Bay, FloorRegions

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.blocks.style import BlockStyle
    from realistic_indoor.generator.rooms.dims import Dims

__all__ = ["WINGS", "compose"]

WINGS = {"L": 1, "T": 1, "U": 2, "E": 3}
"""Wings of each composed shape (an E may be given more)."""

MIN_COURT_M = 9.0
"""Narrowest open space between the two wings of a U (m)."""

_TURNED = {"N": "E", "S": "W", "E": "N", "W": "S"}
"""A bay's corridor side after the wing's quarter turn (x and y swapped)."""


def compose(
    rng: np.random.Generator,
    shape: str,
    area: int,
    dims: Dims,
    style: BlockStyle,
    n_halls: int,
    hall_area: float,
    wings: int | None = None,
) -> FloorRegions | None:
    """The regions of a main bar with wings for ``area`` (square units).

    Returns ``None`` if the wings do not fit along the main bar or a bar would be longer than
    the style's ``max_bar_m`` (the caller then lays out one block).

    Args:
        rng: Random generator.
        shape: ``"L"``, ``"T"``, ``"U"`` or ``"E"`` (see :data:`WINGS`).
        area: Floor area wanted (square units).
        dims: Corridor width and strip depths.
        style: The type's block conventions.
        n_halls: Halls wanted in all, the lobby (in the main bar) first.
        hall_area: Mean hall area (square units).
        wings: Wings of an E (default :data:`WINGS`).
    """
    n_wings = wings if shape == "E" and wings else WINGS[shape]
    main_area = round(area * _main_share(rng, n_wings, area, dims, style))
    bars = 2 if n_wings < 3 and rng.random() < style.ring_main_p else 1
    main, guess = draw_section(rng, main_area, dims, style, max(n_halls - n_wings, 1), hall_area, bars=bars)
    main = _north_free(main)
    length = length_for_area(main, guess, main_area)
    if length > to_units(style.max_bar_m):
        return None
    regions = paint_block(main, length)
    wing_area = (area - regions.area) // n_wings
    for k in range(n_wings):
        wing, guess = draw_section(rng, wing_area, dims, style, 1, hall_area, bars=1)
        wing_length = length_for_area(wing, guess, wing_area)
        x = _wing_x(rng, shape, k, length, wing.depth, n_wings)
        if x is not None and main.bars > 1:
            x = _on_the_run(x, main, length, wing)
        if x is None or wing_length > to_units(style.max_bar_m):
            return None
        _attach(regions, main, wing, paint_block(wing, wing_length), x, k)
    return regions


def _main_share(rng: np.random.Generator, n_wings: int, area: int, dims: Dims, style: BlockStyle) -> float:
    """The main bar's share of the area.

    Drawn for an L or T (the style's ``main_share``) or a U; for an E, what makes the main bar just long enough for its wings
    and the courts between them.
    """
    if n_wings == 1:
        return rng.uniform(*style.main_share)
    if n_wings == 2:
        return rng.uniform(0.45, 0.6)
    bar = mean_block_depth(dims, style, 1)
    length = n_wings * bar + (n_wings - 1) * to_units(MIN_COURT_M * rng.uniform(1.1, 2.0))
    length = min(length, 0.9 * to_units(style.max_bar_m))  # the drawn section may come out deeper
    return min(max(length * bar / area, 0.15), 0.6)


def _north_free(s: Section) -> Section:
    """The section with its north facade kept whole for the wings: halls moved south, no steps."""
    halls = tuple(replace(h, where="S") if h.where == "N" else h for h in s.halls)
    steps = tuple(st for st in s.steps if st[0] != "N")
    return replace(s, halls=halls, steps=steps)


def _wing_x(rng: np.random.Generator, shape: str, k: int, length: int, depth: int, n: int) -> int | None:
    """Where a wing's west side stands along the main bar (units), or ``None`` if it does not fit."""
    if shape == "E":
        if (length - n * depth) / (n - 1) < to_units(MIN_COURT_M):
            return None
        return round(k * (length - depth) / (n - 1))
    if shape == "U":
        if length - 2 * depth < to_units(MIN_COURT_M):
            return None
        return 0 if k == 0 else length - depth
    if length - depth < to_units(MIN_COURT_M):
        return None
    if shape == "L":
        return 0 if rng.random() < 0.5 else length - depth
    return round((length - depth) * rng.uniform(0.3, 0.7))


def _on_the_run(x: int, main: Section, length: int, wing: Section) -> int | None:
    """``x`` moved so the wing's corridor meets the ring's north corridor, not an end strip.

    A ring's long corridors run between its end strips; the short corridor joining a wing
    crosses the north facade strip there. ``None`` where the run is too short for it.
    """
    lo, hi = main.end_depth, length - main.end_depth - wing.corridor
    if hi < lo:
        return None
    corridor_x = min(max(x + wing.depths[0][0], lo), hi)
    return corridor_x - wing.depths[0][0]


def _attach(
    regions: FloorRegions, main: Section, wing: Section, painted: FloorRegions, x: int, k: int
) -> None:
    """Turn wing ``k`` a quarter, stand it on the main block's north facade at ``x``, join the corridors.

    The main block is one bar or a ring; the wing's corridor meets its northmost corridor.
    """
    top = main.depth
    corridor_x = x + wing.depths[0][0]
    line_top = top - main.depths[-1][1]
    connector = (corridor_x, line_top, corridor_x + wing.corridor, top)
    regions.bays = _cut_bays(regions.bays, connector)
    regions.corridors.append(connector)

    def turn(r: Rect) -> Rect:
        return (x + r[1], top + r[0], x + r[3], top + r[2])

    regions.corridors += [turn(r) for r in painted.corridors]
    regions.halls += [(("wing", k, *node), [turn(r) for r in rects]) for node, rects in painted.halls]
    regions.bays += [
        Bay(turn(b.rect), "y" if b.axis == "x" else "x", _TURNED[b.access]) for b in painted.bays
    ]
    regions.holes += [turn(r) for r in painted.holes]
    regions.area += painted.area


def _cut_bays(bays: list[Bay], cut: Rect) -> list[Bay]:
    """The bays with the stretch under ``cut`` taken out (bays running along x only)."""
    out = []
    for bay in bays:
        x0, y0, x1, y1 = bay.rect
        if bay.axis != "x" or min(x1, cut[2]) <= max(x0, cut[0]) or min(y1, cut[3]) <= max(y0, cut[1]):
            out.append(bay)
            continue
        out += [Bay((a, y0, b, y1), "x", bay.access) for a, b in ((x0, cut[0]), (cut[2], x1)) if b > a]
    return out
