"""A house's footprint cut into zones: the day zone, the entrance, the hallways and the bands of rooms.

The footprint is a rectangle. Its west part is the day zone (living rooms, dining rooms and the
kitchen), as deep as the house; east of it lie one or more strips, each a hallway between two
bands of rooms (bedrooms, bathrooms, toilets, studies, stores). The entrance takes the west end
of the first strip's south band, between the living room and the rooms along the first
hallway, which runs over it; with several strips, a hallway along the day zone (the spine)
joins the hallways into one. So every night room opens onto a hallway, the living room onto
the entrance, and the entrance onto the hallway along its whole width::

    +---------+----------------------------+
    | kitchen | bedroom | bath |  bedroom  |   north band
    |         +----------------------------+
    | living  |     hallway                |
    |         +-------+--------------------+
    |         | entr. | bedroom | WC | ... |   south band
    +---------+-------+--------------------+

The number of strips and the bands' depth are chosen so that the footprint is nearest a drawn
length-to-width ratio, a strip more costing a little (each adds a hallway).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from realistic_indoor.generator.geometry import area_to_units, to_units
from realistic_indoor.generator.house.bands import Band, band_order, deal, widths
from realistic_indoor.models.house_programme import SIZES

if TYPE_CHECKING:
    from realistic_indoor.generator.geometry import Rect
    from realistic_indoor.generator.house.programme import Programme, ProgrammeRoom

__all__ = ["ASPECT", "BAND_DEPTH_M", "NEAR_COST", "Frame", "choose_frame", "frame"]

ASPECT = (1.0, 1.8)
"""Range of the drawn length-to-width ratio of the footprint."""
BAND_DEPTH_M = (3.0, 4.8)
"""Shallowest and deepest band of rooms along a hallway (m); the deepest grows with the square
root of the programme's room scale above 1, up to :data:`MAX_BAND_DEPTH_M`."""
MAX_BAND_DEPTH_M = 6.0
"""Deepest band of rooms in the largest houses (m)."""
MAX_STRIPS = 5
"""Most strips (hallways with their two bands) a house is laid out in."""
STRIP_COST = 0.35
"""Cost of one more strip, against ``|log(aspect / target)|`` of the footprint."""
NARROW_COST = 0.1
"""Cost of a day zone narrowed for the night rooms to fit (see :func:`frame`)."""
NEAR_COST = 0.3
"""How much more than the cheapest a frame may cost before rooms are left out instead (see
:func:`realistic_indoor.generator.house.steps.fit_frame`)."""
LEAST_AREA = {kind: area_to_units(size.min_m2) for kind, size in SIZES.items()}
"""Least area of each kind of room (square units): the low end of its range in :data:`SIZES`."""
MIN_DAY_ROOM = to_units(2.6)
"""Shortest side of a day room (units)."""
DAY_KEPT = 0.67
"""Least share of the width its rooms ask that a narrowed day zone keeps (where the fit is strict)."""
DAY_STEPS = 3
"""Steps in which the day zone is narrowed, down to its narrowest, where the night rooms do not fit."""


@dataclass(frozen=True)
class Frame:
    """The zones of a house (units, the house's south-west corner at the origin).

    Attributes:
        width: West-east extent.
        depth: South-north extent.
        day: The day zone.
        entrance: The entrance.
        hallway: The hallway's rectangles (the strips' hallways and the spine between them).
        bands: The bands of rooms, south first.
        rooms: The night rooms of each band, in order along it (:func:`band_order`).
        widths: Their widths (units, :func:`widths`).
    """

    width: int
    depth: int
    day: Rect
    entrance: Rect
    hallway: list[Rect]
    bands: list[Band]
    rooms: list[list[ProgrammeRoom]]
    widths: list[list[int]]

    @property
    def aspect(self) -> float:
        """Length over width of the footprint (>= 1)."""
        return max(self.width, self.depth) / min(self.width, self.depth)


def _offsets(strips: int, hallway: int, entrance: int) -> list[tuple[int, bool]]:
    """Each band's distance from the day zone (units) and whether its hallway is above it, south first.

    The first south band starts after the entrance, bands beside the spine after the spine,
    the last north band at the day zone.
    """
    out = []
    for k in range(strips):
        out.append((entrance if k == 0 else hallway, True))
        out.append((0 if k == strips - 1 else hallway, False))
    return out


def _day_width(day_m2: float, night_m2: float, width: int, depth: int, band: int, offsets: list[int]) -> int:
    """Width of the day zone that gives the day and the night rooms their shares of the room area.

    Solves ``x * depth / (x * depth + band * sum(width - x - offset)) = day / (day + night)``
    for ``x``: the hallways and the entrance take what is left.
    """
    share = day_m2 / (day_m2 + night_m2)
    n = len(offsets)
    x = share * band * (n * width - sum(offsets)) / (depth * (1 - share) + share * band * n)
    return round(x)


def frame(prog: Programme, strips: int, band: int, narrow: bool = False, strict: bool = True) -> Frame | None:
    """The zones of ``prog`` in ``strips`` strips of bands ``band`` deep, or ``None`` where they do not fit.

    The day zone is as wide as the day rooms' share of the room area asks, or as leaves the bands
    room for the night rooms at their narrowest (:func:`_widest_day`). The night rooms fit
    where each band holds its rooms at their narrowest; strictly, where moreover every
    bedroom and study keeps its least area and the day zone :data:`DAY_KEPT` of its width and
    the least living space for the house's occupancy (:attr:`~realistic_indoor.generator.house.programme.Programme.living_space_m2`).

    Args:
        prog: The programme.
        strips: Number of strips.
        band: Depth of every band (units).
        narrow: Where the night rooms do not fit, narrow the day zone step by step
            (:data:`DAY_STEPS`) down to the narrowest its rooms allow.
        strict: Check the least areas.
    """
    hall_w, entry_w = to_units(prog.hallway_width_m), to_units(prog.entrance_width_m)
    strip = 2 * band + hall_w
    depth = strips * strip
    width = round(area_to_units(prog.area_m2) / depth)
    offsets = _offsets(strips, hall_w, entry_w)
    share = _day_width(prog.day_m2, prog.night_m2, width, depth, band, [o for o, _ in offsets])
    least = _least_day(prog, depth)
    if strict:
        least = max(least, math.ceil(area_to_units(prog.living_space_m2) / depth), round(DAY_KEPT * share))
    x_day = max(min(share, _widest_day(prog, width, [o for o, _ in offsets])), least)
    steps = range(1, DAY_STEPS + 1) if narrow else range(1)
    for x in sorted({x_day - (x_day - least) * k // DAY_STEPS for k in steps}, reverse=True):
        bands = [
            Band(x + offset, width, y0, y0 + band, above)
            for (offset, above), y0 in zip(offsets, _band_bottoms(strips, band, hall_w), strict=True)
        ]
        dealt = deal(prog.night, bands) if all(b.length > 0 for b in bands) else None
        if dealt is None:
            continue
        rooms = [band_order(rs) for rs in dealt]
        ws = [widths(rs, b.length, b.depth) for b, rs in zip(bands, rooms, strict=True)]
        if not strict or all(_roomy(b, rs, w) for b, rs, w in zip(bands, rooms, ws, strict=True)):
            hallway = _hallway(strips, band, hall_w, x, width)
            entrance = (x, 0, x + entry_w, band)
            return Frame(width, depth, (0, 0, x, depth), entrance, hallway, bands, rooms, ws)
    return None


def _widest_day(prog: Programme, width: int, offsets: list[int]) -> int:
    """Widest day zone that leaves the bands room for the night rooms at their narrowest (units).

    The bands together must hold every night room at its least width, with one widest room's
    width to spare for dealing whole rooms to bands.
    """
    need = sum(r.least for r in prog.night) + max(r.least for r in prog.night)
    return (len(offsets) * width - sum(offsets) - need) // len(offsets)


def _roomy(band: Band, rooms: list[ProgrammeRoom], ws: list[int]) -> bool:
    """Whether every ordinary room of the band, ``ws`` wide, gets its least area (:data:`SIZES` ``min_m2``)."""
    return all(r.small or w * band.depth >= LEAST_AREA[r.kind] for r, w in zip(rooms, ws, strict=True))


def _band_bottoms(strips: int, band: int, hall_w: int) -> list[int]:
    """South side of each band (units), in the order of :func:`_offsets`."""
    strip = 2 * band + hall_w
    return [k * strip + (0 if north == 0 else band + hall_w) for k in range(strips) for north in (0, 1)]


def _hallway(strips: int, band: int, hall_w: int, x_day: int, width: int) -> list[Rect]:
    """The hallway's rectangles: each strip's, and the spine along the day zone that joins them (units)."""
    strip = 2 * band + hall_w
    out = [(x_day, band, width, band + hall_w)]
    if strips > 1:
        top = (strips - 1) * strip + band
        out.append((x_day, band + hall_w, x_day + hall_w, top))
        out += [
            (x_day + hall_w, k * strip + band, width, k * strip + band + hall_w) for k in range(1, strips - 1)
        ]
        out.append((x_day, top, width, top + hall_w))
    return out


def _least_day(prog: Programme, depth: int) -> int:
    """Narrowest day zone: one column of day rooms where they fit one above the other, else two."""
    return MIN_DAY_ROOM if len(prog.day) * MIN_DAY_ROOM <= depth else 2 * MIN_DAY_ROOM


def choose_frame(
    prog: Programme, target: float, strict: bool = True, allowance: float = math.inf
) -> Frame | None:
    """The frame nearest the ``target`` length-to-width ratio among those that fit.

    For each number of strips up to :data:`MAX_STRIPS`, the bands are as deep as the target
    asks, within :data:`BAND_DEPTH_M` (see there for the largest houses), or as shallow as
    allowed (longer bands hold more rooms); each strip after the first costs
    :data:`STRIP_COST`, and narrowing the day zone for the night rooms :data:`NARROW_COST`. The
    candidates are tried cheapest first; the first that fits (see :func:`frame`) is taken.

    Args:
        prog: The programme.
        target: Length-to-width ratio wanted.
        strict: Whether the rooms must keep their least areas (see :func:`frame`).
        allowance: Try only candidates that cost at most this much more than the cheapest.

    Returns:
        The best frame, or ``None`` where none fits.
    """
    lo = to_units(BAND_DEPTH_M[0])
    hi = to_units(min(BAND_DEPTH_M[1] * math.sqrt(max(prog.row.room_scale, 1.0)), MAX_BAND_DEPTH_M))
    hall_w = to_units(prog.hallway_width_m)
    area_u = area_to_units(prog.area_m2)
    candidates = []
    for strips in range(1, MAX_STRIPS + 1):
        wanted = (math.sqrt(area_u / target) / strips - hall_w) / 2
        for band in {min(max(round(wanted), lo), hi), lo}:
            depth = strips * (2 * band + hall_w)
            width = area_u / depth
            aspect = max(width, depth) / min(width, depth)
            cost = abs(math.log(aspect / target)) + STRIP_COST * (strips - 1)
            candidates += [(cost, strips, band, False), (cost + NARROW_COST, strips, band, True)]
    candidates.sort()
    for cost, strips, band, narrow in candidates:
        if cost > candidates[0][0] + allowance:
            break
        f = frame(prog, strips, band, narrow, strict)
        if f is not None:
            return f
    return None
