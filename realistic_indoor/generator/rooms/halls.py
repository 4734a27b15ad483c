"""Rooms set into halls: a strip of rooms along one side of a large hall, opening onto it."""

from __future__ import annotations

from typing import TYPE_CHECKING

from realistic_indoor.generator.geometry import Rect, contact, to_units
from realistic_indoor.generator.rooms.regions import Bay, FloorRegions

if TYPE_CHECKING:
    import numpy as np

__all__ = ["carve_hall_bays"]

MIN_HALL = to_units(3.5)
"""Least depth of hall left in front of a strip of rooms (units)."""
PASSAGE = to_units(2.5)
"""Width of hall kept free at each end of a strip that does not take a whole side (units)."""

_ACROSS = {"S": "N", "N": "S", "W": "E", "E": "W"}


def _split(hall: Rect, side: str, depth: int, a: int, b: int) -> tuple[list[Rect], Bay]:
    """The hall minus a strip ``depth`` deep along ``side`` between ``a`` and ``b``, and the strip."""
    x0, y0, x1, y1 = hall
    if side in "SN":
        strip = (a, y0, b, y0 + depth) if side == "S" else (a, y1 - depth, b, y1)
        front = (a, y0 + depth, b, y1) if side == "S" else (a, y0, b, y1 - depth)
        rest = [front, (x0, y0, a, y1), (b, y0, x1, y1)]
        bay = Bay(strip, "x", _ACROSS[side])
    else:
        strip = (x0, a, x0 + depth, b) if side == "W" else (x1 - depth, a, x1, b)
        front = (x0 + depth, a, x1, b) if side == "W" else (x0, a, x1 - depth, b)
        rest = [front, (x0, y0, x1, a), (x0, b, x1, y1)]
        bay = Bay(strip, "y", _ACROSS[side])
    return [r for r in rest if r[0] < r[2] and r[1] < r[3]], bay


def _options(hall: Rect, corridors: list[Rect], depth: int) -> list[tuple[list[Rect], Bay]]:
    """Strips the hall can give up without losing a corridor opening or its own passage."""
    x0, y0, x1, y1 = hall
    touching = [c for c in (contact(hall, r) for r in corridors) if c is not None]
    out = []
    for side in "SNWE":
        across = (y1 - y0) if side in "SN" else (x1 - x0)
        lo, hi = (x0, x1) if side in "SN" else (y0, y1)
        coord = {"S": y0, "N": y1, "W": x0, "E": x1}[side]
        if across - depth < MIN_HALL:
            continue
        on_side = [c for c in touching if c.axis == ("h" if side in "SN" else "v") and c.coord == coord]
        ends = [c for c in touching if c not in on_side]
        if not on_side and not ends and hi - lo >= 2 * depth:
            out.append(_split(hall, side, depth, lo, hi))
            continue
        a, b = lo + PASSAGE, hi - PASSAGE
        if b - a >= 2 * depth and not any(c.lo < b and c.hi > a for c in on_side):
            out.append(_split(hall, side, depth, a, b))
    return out


def carve_hall_bays(regions: FloorRegions, rng: np.random.Generator, depth: int, p: float) -> None:
    """Set a strip of rooms (reception, cloakroom, meeting rooms) into large halls.

    With probability ``p`` per hall, a strip ``depth`` deep is taken along one side of the hall:
    the whole side if no corridor enters the hall elsewhere across the strip, else the middle of
    the side with a passage of hall left at both ends (the hall becomes U-shaped). Every corridor
    opening stays whole and at least :data:`MIN_HALL` of hall remains in front of the strip. The
    strip becomes a bay whose rooms open onto the hall.
    """
    halls = []
    for node, rects in regions.halls:
        options = _options(rects[0], regions.corridors, depth) if len(rects) == 1 else []
        if options and rng.random() < p:
            rest, bay = options[int(rng.integers(len(options)))]
            halls.append((node, rest))
            regions.bays.append(bay)
        else:
            halls.append((node, rects))
    regions.halls = halls
