"""Rooms side by side along a hallway: which band each room goes to, how wide it is, and tucked service rooms."""

from __future__ import annotations

from typing import TYPE_CHECKING, NamedTuple

from realistic_indoor.generator.geometry import UNITS2_PER_M2, area_to_units, to_units

if TYPE_CHECKING:
    from collections.abc import Sequence

    from realistic_indoor.generator.geometry import Rect
    from realistic_indoor.generator.house.programme import ProgrammeRoom

__all__ = ["Band", "band_order", "deal", "split", "tuck", "widths"]

SMALL_ROOMS_MAX_SHARE = 0.6
"""Largest share of a band's length its service rooms take at the width their area needs; beyond
it every room of the band is as wide as its share of the areas."""
MIN_TUCKED_DEPTH = to_units(1.5)
"""Shallowest a service room tucked in next to the hallway is made (units)."""
MIN_WRAP_DEPTH = to_units(1.2)
"""Least depth of the part of a room that wraps around behind a tucked-in service room (units)."""


class Band(NamedTuple):
    """A row of rooms along one side of a hallway (units).

    Attributes:
        x0: West end.
        x1: East end.
        y0: South side.
        y1: North side.
        hallway_above: Whether the hallway runs along its north side (else its south side).
    """

    x0: int
    x1: int
    y0: int
    y1: int
    hallway_above: bool

    @property
    def length(self) -> int:
        """Length along the hallway (units)."""
        return self.x1 - self.x0

    @property
    def depth(self) -> int:
        """Depth across the hallway (units)."""
        return self.y1 - self.y0


def deal(rooms: Sequence[ProgrammeRoom], bands: Sequence[Band]) -> list[list[ProgrammeRoom]] | None:
    """Deal rooms to bands so that each band's rooms fill it about as much as the others'.

    Ordinary rooms go first, largest first, each to the band with the most room left in
    proportion; service rooms follow, so that no band holds only service rooms where it can
    be helped. A room goes only where the band's rooms, each at its narrowest, still fit.

    Returns:
        The rooms of each band, or ``None`` where some room fits nowhere or some band is left
        empty.
    """
    room_left = [b.length for b in bands]
    if sum(r.least for r in rooms) > sum(room_left):
        return None
    scale = sum(r.area_m2 for r in rooms) / sum(b.length * b.depth for b in bands)
    left = [scale * b.length * b.depth for b in bands]
    out: list[list[ProgrammeRoom]] = [[] for _ in bands]
    for room in sorted(rooms, key=lambda r: (r.small, -r.area_m2)):
        least = room.least
        best = -1
        for k in range(len(bands)):
            if room_left[k] >= least and (best < 0 or left[k] > left[best]):
                best = k
        if best < 0:
            return None
        out[best].append(room)
        left[best] -= room.area_m2
        room_left[best] -= least
    return out if all(out) else None


def band_order(rooms: Sequence[ProgrammeRoom]) -> list[ProgrammeRoom]:
    """The rooms of a band in a random order in which every service room has an ordinary neighbour.

    The ordinary rooms are shuffled by their keys (uniform numbers in [0, 1)); each service room
    goes into a gap between or beside them drawn from its key, the next free gap where that one
    is taken (two to a gap once every gap has one), so that it can be tucked in beside an
    ordinary room (see :func:`tuck`).
    """
    keyed = sorted((r.key, k) for k, r in enumerate(rooms))
    ordinary = [rooms[k] for _, k in keyed if not rooms[k].small]
    n = len(ordinary) + 1
    gaps: list[list[ProgrammeRoom]] = [[] for _ in range(n)]
    cap = 1  # most service rooms a gap takes; raised once every gap has that many
    for key, k in keyed:
        if rooms[k].small:
            if all(len(gap) >= cap for gap in gaps):
                cap += 1
            g = int(key * n)
            while len(gaps[g]) >= cap:
                g = (g + 1) % n
            gaps[g].append(rooms[k])
    out = list(gaps[0])
    for room, gap in zip(ordinary, gaps[1:], strict=True):
        out.append(room)
        out += gap
    return out


def split(total: int, weights: Sequence[float], least: Sequence[int]) -> list[int]:
    """Cut ``total`` units into whole pieces in proportion to ``weights``, each at least its ``least``.

    Pieces whose share falls short of their least are held at it and the rest shared again
    among the others; where the leasts alone exceed the total, the pieces are in proportion.
    """
    n = len(weights)
    shares = [float(w) for w in weights]
    if sum(least) <= total:
        fixed = [False] * n
        free, rest = float(sum(weights)), total
        while free > 0:
            short = [k for k in range(n) if not fixed[k] and weights[k] * rest < least[k] * free]
            if not short:
                break
            for k in short:
                fixed[k] = True
                free -= weights[k]
                rest -= least[k]
        for k in range(n):
            shares[k] = float(least[k]) if fixed[k] else weights[k] * rest / free if free > 0 else 0.0
    out, acc, done, whole = [], 0.0, 0, sum(shares)
    for s in shares:
        acc += s
        edge = round(total * acc / whole)
        out.append(edge - done)
        done = edge
    return out


def widths(rooms: Sequence[ProgrammeRoom], length: int, depth: int) -> list[int]:
    """Widths of a band's rooms: service rooms as their area needs, the others share the rest.

    Where the band holds only service rooms, or none, or its service rooms would take more
    than :data:`SMALL_ROOMS_MAX_SHARE` of its length, every room gets its share of the areas.

    Args:
        rooms: The band's rooms, in order.
        length: Length of the band (units).
        depth: Depth of the band (units).

    Returns:
        Each room's width (units), together ``length``.
    """
    small = sum(r.small for r in rooms)
    if 0 < small < len(rooms):
        per_unit = UNITS2_PER_M2 / max(depth, 1)
        natural = [max(round(r.area_m2 * per_unit), r.least) if r.small else 0 for r in rooms]
        taken = sum(natural)
        if taken <= SMALL_ROOMS_MAX_SHARE * length:
            ordinary = [r for r in rooms if not r.small]
            rest = iter(split(length - taken, [r.area_m2 for r in ordinary], [r.least for r in ordinary]))
            return [w if r.small else next(rest) for r, w in zip(rooms, natural, strict=True)]
    return split(length, [r.area_m2 for r in rooms], [r.least for r in rooms])


def tuck(rects: list[list[Rect]], rooms: Sequence[ProgrammeRoom], band: Band) -> None:
    """Cut each service room of a band to its area's depth next to the hallway, where it can.

    The part behind it goes to an ordinary room beside it (one that wraps around no other, the
    smaller where both could), which wraps around the service room; a service room between two service rooms, or one whose area needs nearly the band's
    depth, keeps the whole depth.

    Args:
        rects: Each room's rectangles, in band order (one each on entry); changed in place.
        rooms: The rooms' programme, in the same order.
        band: The band.
    """
    for k, room in enumerate(rooms):
        if not room.small:
            continue
        mates = [m for m in (k - 1, k + 1) if 0 <= m < len(rooms) and not rooms[m].small]
        mates.sort(key=lambda m: (len(rects[m]), rooms[m].area_m2))
        a, _, b, _ = rects[k][0]
        depth = max(round(area_to_units(room.area_m2) / (b - a)), MIN_TUCKED_DEPTH)
        if not mates or depth > band.depth - MIN_WRAP_DEPTH:
            continue
        if band.hallway_above:
            front, back = (a, band.y1 - depth, b, band.y1), (a, band.y0, b, band.y1 - depth)
        else:
            front, back = (a, band.y0, b, band.y0 + depth), (a, band.y0 + depth, b, band.y1)
        rects[k] = [front]
        rects[mates[0]].append(back)
