"""What a house of a given floor area holds: the programme table, room sizes, and a draw from them.

The table gives, per band of floor area, how many rooms of each kind a single-storey house has;
the sizes give each kind's range of areas. Every figure comes from published statistics or
norms (no plan data), or is marked as this project's choice:

- [NDSS] DCLG (2015), *Technical housing standards: nationally described space standard*,
  Table 1 and its notes: least gross internal area of a one-storey dwelling by bedrooms
  (1 bedroom 39-50 m2, 2 bedrooms 61-70, 3 bedrooms 74-95, 4 bedrooms 90-117, 5 bedrooms
  103-121, 6 bedrooms 116-125); a single bedroom at least 7.5 m2 and 2.15 m wide, a double
  at least 11.5 m2 and the first double 2.75 m wide; built-in storage 1.0-4.0 m2.
- [SOC] US Census Bureau, Survey of Construction (*Characteristics of New Housing*), as
  tabulated by NAHB (*Eye on Housing*, 2021-2022): bedrooms of new single-family homes by
  finished floor area: under 1,200 sq ft (111 m2) 83% two or fewer; 1,200-1,599 sq ft
  (111-149 m2) 31% two or fewer, 67% three, 2% four; 1,600-1,999 sq ft (149-186 m2) 85% three
  or fewer, 15% four or more; 2,000-2,399 sq ft (186-223 m2) 59% three or fewer, 41% four or
  more. Bathrooms (2019 starts, median about 210 m2): 4% one, 64% two, 25% three, 8% four or
  more; of homes with four or more bedrooms, 57% have three or more bathrooms (2011).
- [LHDG] Mayor of London (2010), *London Housing Design Guide*, interim edition, standard
  4.4.1: living, dining and kitchen space together at least 23 m2 (2 persons) to 31 m2
  (6 persons); single bedroom 8 m2, double 12 m2.
- [LABC] LABC Warranty (2018) survey of UK homes, as reported in the press: living rooms of
  homes built since 2010 average 17.1 m2 (24.9 m2 in the 1970s).
- [T1] The paper's Table 1, houses: small rooms (bathrooms, toilets, stores) 6.0 +- 2.6 m2,
  big rooms 33.7 +- 7.8 m2.
- [ADM] *Approved Document M*, volume 1 (2015), M4(1) Table 1.1: hallways at least 900 mm
  wide. [DIN] DIN 18040-2 (2011): hallways of barrier-free dwellings at least 1.20 m wide,
  1.50 m by 1.50 m to turn a wheelchair.

The counts are drawn uniformly within their range; a house is always given one kitchen, one
entrance and the hallways its layout needs. Room areas are drawn uniformly within their range
of :data:`SIZES` times the band's room scale; they set the rooms' proportions, and the layout
then fills the floor area with them (see docs/generator.md, "Houses").
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING, NamedTuple

from realistic_indoor.generator.geometry import to_units

if TYPE_CHECKING:
    import numpy as np

__all__ = [
    "ENTRANCE_WIDTH_M",
    "HALLWAY_WIDTH_M",
    "LIVING_SPACE_M2",
    "PROGRAMME",
    "SERVICE_KINDS",
    "SIZES",
    "STORE_FUNCTIONS",
    "Programme",
    "ProgrammeRoom",
    "ProgrammeRow",
    "RoomSize",
    "Span",
    "draw_programme",
    "programme_markdown",
    "row_for",
]


@dataclass(frozen=True)
class Span:
    """A whole-number range, both ends included.

    Attributes:
        low: Least count.
        high: Greatest count.
    """

    low: int
    high: int

    def __str__(self) -> str:
        return str(self.low) if self.low == self.high else f"{self.low}-{self.high}"


@dataclass(frozen=True)
class ProgrammeRow:
    """The rooms of a house whose floor area lies in ``[min_area_m2, max_area_m2)``.

    Attributes:
        min_area_m2: Smallest floor area of the band (m2).
        max_area_m2: Floor area where the next band starts (m2); the last band includes it.
        bedrooms: Bedrooms (the first is the main, double bedroom).
        bathrooms: Bathrooms (basin, toilet and bath or shower).
        toilets: Separate toilets (a US half bath, a UK cloakroom WC).
        living_rooms: Living rooms (a second one is a family room).
        dining_rooms: Separate dining rooms.
        studies: Studies.
        stores: Storage rooms, laundries and walk-in closets.
        room_scale: Factor on every room size of :data:`SIZES` (larger houses have larger rooms).
    """

    min_area_m2: float
    max_area_m2: float
    bedrooms: Span
    bathrooms: Span
    toilets: Span
    living_rooms: Span
    dining_rooms: Span
    studies: Span
    stores: Span
    room_scale: float


def _row(low: float, high: float, *counts: tuple[int, int], scale: float) -> ProgrammeRow:
    return ProgrammeRow(low, high, *(Span(a, b) for a, b in counts), room_scale=scale)


# Bedrooms: at most what [NDSS] allows in the band's floor area, about what [SOC] finds (three
# from 111 m2, four in two of five homes from 186 m2). Bathrooms: one per one to two bedrooms,
# two in most homes of 150-250 m2 [SOC]. Toilets, dining rooms, studies, stores and the room
# scale: this project's choice, so that the rooms drawn fill about the floor area less its
# circulation (about 13%); a US home of the median 210 m2 has three or four bedrooms [SOC], so
# its rooms are larger than the [NDSS] minimums by about the scale given here. The bands stop
# at the generator's limits.
PROGRAMME: tuple[ProgrammeRow, ...] = (
    #     area (m2)   bedrooms  baths    toilets  living   dining   studies  stores
    _row(50, 65, (1, 1), (1, 1), (0, 0), (1, 1), (0, 0), (0, 0), (0, 1), scale=0.85),
    _row(65, 90, (1, 2), (1, 1), (0, 0), (1, 1), (0, 1), (0, 0), (1, 1), scale=0.9),
    _row(90, 120, (2, 3), (1, 1), (0, 1), (1, 1), (0, 1), (0, 0), (1, 1), scale=1.0),
    _row(120, 150, (3, 3), (1, 2), (0, 1), (1, 1), (0, 1), (0, 1), (1, 1), scale=1.1),
    _row(150, 190, (3, 4), (1, 2), (0, 1), (1, 1), (1, 1), (0, 1), (1, 2), scale=1.2),
    _row(190, 250, (3, 4), (2, 2), (1, 1), (1, 2), (1, 1), (1, 1), (2, 2), scale=1.3),
    _row(250, 350, (4, 5), (2, 3), (1, 1), (2, 2), (1, 1), (1, 2), (3, 3), scale=1.45),
    _row(350, 500, (5, 6), (3, 4), (1, 2), (2, 3), (1, 1), (2, 2), (4, 5), scale=1.7),
    _row(500, 700, (6, 7), (4, 6), (2, 2), (3, 3), (1, 2), (2, 3), (5, 6), scale=2.0),
    _row(700, 1000, (7, 8), (6, 8), (2, 3), (3, 4), (2, 2), (3, 4), (6, 8), scale=2.5),
)
"""The programme by floor area, smallest band first (see the module doc for the sources)."""


@dataclass(frozen=True)
class RoomSize:
    """The range of areas of one kind of room, and its narrowest width.

    Attributes:
        function: Functional label the room gets.
        min_m2: Least area drawn (m2).
        max_m2: Greatest area drawn (m2).
        min_width_m: Narrowest the layout makes it (m): a bed's or a sofa's width, else a door's.
        source: Where the figures come from (see the module doc).
    """

    function: str
    min_m2: float
    max_m2: float
    min_width_m: float
    source: str


SIZES: dict[str, RoomSize] = {
    "main bedroom": RoomSize("bedroom", 11.5, 18.0, 2.75, "NDSS double >= 11.5 m2, 2.75 m wide; LHDG 12"),
    "bedroom": RoomSize("bedroom", 7.5, 13.0, 2.2, "NDSS single >= 7.5 m2, 2.15 m wide; LHDG 8"),
    "bathroom": RoomSize("bathroom", 3.5, 8.5, 1.6, "T1 small rooms 6.0 +- 2.6 m2"),
    "toilet": RoomSize("toilet", 1.5, 2.5, 1.6, "project's choice; width for a door"),
    "kitchen": RoomSize("kitchen", 8.0, 16.0, 2.6, "project's choice; day rooms together >= LHDG"),
    "living room": RoomSize("living room", 17.0, 34.0, 2.6, "LABC mean 17.1 m2; T1 big rooms 33.7 m2"),
    "dining room": RoomSize("dining room", 9.0, 16.0, 2.6, "project's choice"),
    "study": RoomSize("study", 7.5, 12.0, 2.2, "NDSS single bedroom"),
    "store": RoomSize("storage", 2.0, 5.0, 1.6, "NDSS built-in storage 1.0-4.0 m2"),
}
"""Room sizes by kind; a store's function is drawn among :data:`STORE_FUNCTIONS`."""

LIVING_SPACE_M2 = {2: 23.0, 3: 25.0, 4: 27.0, 5: 29.0, 6: 31.0}
"""Least floor area of living, dining and kitchen space together by persons [LHDG]; two more
square metres per further person (project's extrapolation)."""

STORE_FUNCTIONS = ("storage", "laundry", "closet")
"""Functions a store is given, each as likely."""

HALLWAY_WIDTH_M = (0.9, 1.0, 1.5)
"""Least, most likely and greatest hallway width (m), drawn from a triangular distribution:
at least [ADM]'s 0.9 m, at most [DIN]'s 1.5 m turning space, most often about 1 m."""

ENTRANCE_WIDTH_M = (1.6, 2.4)
"""Range of the entrance's width (m), drawn uniformly, times the square root of the band's room
scale where that is above 1 (project's choice: wide enough for the front door with its
clearances and a coat rack); it is as deep as the band of rooms beside it."""

SERVICE_KINDS = ("bathroom", "toilet", "store")
"""Kinds of service room: as wide as their door needs, tucked in next to the hallway."""


class ProgrammeRoom(NamedTuple):
    """One room a house is to have.

    Attributes:
        kind: Key of its size in :data:`SIZES` (``"main bedroom"``, ``"store"``, ...).
        function: Functional label.
        area_m2: Area drawn (m2): sets the room's share of its zone.
        least: Narrowest the layout makes it (grid units, see
            :mod:`realistic_indoor.generator.geometry`).
        small: Whether it is a service room (:data:`SERVICE_KINDS`).
        key: A uniform number in [0, 1) that sets its place among the rooms of its band.
    """

    kind: str
    function: str
    area_m2: float
    least: int
    small: bool
    key: float = 0.0


@dataclass(frozen=True)
class Programme:
    """The rooms a house is to have, and the widths of its circulation.

    Attributes:
        area_m2: Floor area of the house (m2).
        row: The table's band it was drawn from.
        day: Living rooms, dining rooms and the kitchen, in the order they are laid out from the entrance.
        night: Bedrooms (main first), bathrooms, toilets, studies and stores.
        hallway_width_m: Width of the hallways (m).
        entrance_width_m: Width of the entrance (m).
    """

    area_m2: float
    row: ProgrammeRow
    day: tuple[ProgrammeRoom, ...]
    night: tuple[ProgrammeRoom, ...]
    hallway_width_m: float
    entrance_width_m: float

    @cached_property
    def day_m2(self) -> float:
        """Summed area of the day rooms (m2)."""
        return sum(r.area_m2 for r in self.day)

    @cached_property
    def night_m2(self) -> float:
        """Summed area of the night rooms (m2)."""
        return sum(r.area_m2 for r in self.night)

    @cached_property
    def living_space_m2(self) -> float:
        """Least area of the day zone (m2): [LHDG]'s living space for as many persons as bedspaces.

        The main bedroom sleeps two, every other bedroom one (as [NDSS] counts a 3b4p home).
        """
        persons = 1 + self.count("bedroom")
        top = max(LIVING_SPACE_M2)
        return LIVING_SPACE_M2[min(persons, top)] + 2.0 * max(persons - top, 0)

    def count(self, function: str) -> int:
        """How many of its rooms have ``function``."""
        return sum(r.function == function for r in self.day + self.night)


def row_for(area_m2: float) -> ProgrammeRow:
    """The band of :data:`PROGRAMME` a floor area falls in (the nearest end band outside them)."""
    for row in PROGRAMME:
        if area_m2 < row.max_area_m2:
            return row
    return PROGRAMME[-1]


COUNT_COLUMNS = (
    ("bedrooms", "bedrooms"),
    ("bathrooms", "bathrooms"),
    ("toilets", "toilets"),
    ("living_rooms", "living rooms"),
    ("dining_rooms", "dining rooms"),
    ("studies", "studies"),
    ("stores", "stores"),
)
"""The count columns of :data:`PROGRAMME` and their headings in the docs."""


def draw_programme(rng: np.random.Generator, area_m2: float) -> Programme:
    """The rooms of a house of ``area_m2``: counts from its band of :data:`PROGRAMME`, areas from :data:`SIZES`.

    Counts and areas are drawn uniformly within their ranges (areas times the band's room
    scale), a store's function uniformly among :data:`STORE_FUNCTIONS`, the hallway's width
    from :data:`HALLWAY_WIDTH_M` and the entrance's from :data:`ENTRANCE_WIDTH_M` (in a few
    vector draws: the generator runs once per episode).

    Args:
        rng: Random source.
        area_m2: Floor area of the house (m2).
    """
    row = row_for(area_m2)
    spans = [getattr(row, name) for name, _ in COUNT_COLUMNS]
    u = rng.random(len(spans) + 2)
    n = dict(
        zip(
            (name for name, _ in COUNT_COLUMNS),
            (s.low + int(x * (s.high - s.low + 1)) for s, x in zip(spans, u, strict=False)),
            strict=True,
        )
    )
    day_kinds = ["living room"] * n["living_rooms"] + ["dining room"] * n["dining_rooms"] + ["kitchen"]
    night_kinds = (
        ["main bedroom"]
        + ["bedroom"] * (n["bedrooms"] - 1)
        + ["bathroom"] * n["bathrooms"]
        + ["toilet"] * n["toilets"]
        + ["study"] * n["studies"]
        + ["store"] * n["stores"]
    )
    kinds = day_kinds + night_kinds
    v = rng.random(3 * len(kinds)).tolist()
    rooms = tuple(_room(kind, *v[3 * k : 3 * k + 3], row.room_scale) for k, kind in enumerate(kinds))
    a, mode, b = HALLWAY_WIDTH_M
    hallway = _triangular(a, mode, b, float(u[-2]))
    entrance = ENTRANCE_WIDTH_M[0] + float(u[-1]) * (ENTRANCE_WIDTH_M[1] - ENTRANCE_WIDTH_M[0])
    entrance *= math.sqrt(max(row.room_scale, 1.0))
    return Programme(area_m2, row, rooms[: len(day_kinds)], rooms[len(day_kinds) :], hallway, entrance)


def _room(kind: str, u_area: float, u_function: float, key: float, scale: float) -> ProgrammeRoom:
    """A room of ``kind`` from three uniform numbers in [0, 1): its area (times ``scale``), a store's function, its key."""
    size = SIZES[kind]
    function = STORE_FUNCTIONS[int(u_function * len(STORE_FUNCTIONS))] if kind == "store" else size.function
    area = scale * (size.min_m2 + u_area * (size.max_m2 - size.min_m2))
    return ProgrammeRoom(kind, function, area, to_units(size.min_width_m), kind in SERVICE_KINDS, key)


def _triangular(a: float, mode: float, b: float, u: float) -> float:
    """The value of the triangular distribution on ``[a, b]`` peaking at ``mode`` at quantile ``u``."""
    if u < (mode - a) / (b - a):
        return a + math.sqrt(u * (b - a) * (mode - a))
    return b - math.sqrt((1 - u) * (b - a) * (b - mode))


def programme_markdown() -> str:
    """The programme and the room sizes as the two Markdown tables of docs/generator.md.

    A band of floor area includes its lower end, not its upper one (but for the last).
    """
    head = "| floor area (m2) | " + " | ".join(h for _, h in COUNT_COLUMNS) + " | room scale |"
    lines = [head, "|" + "---|" * (len(COUNT_COLUMNS) + 2)]
    for row in PROGRAMME:
        counts = " | ".join(str(getattr(row, name)) for name, _ in COUNT_COLUMNS)
        lines.append(f"| {row.min_area_m2:g}-{row.max_area_m2:g} | {counts} | {row.room_scale:.2f} |")
    lines += ["", "| room | function | area (m2) | narrowest (m) | source |", "|---|---|---|---|---|"]
    for kind, s in SIZES.items():
        function = ", ".join(STORE_FUNCTIONS) if kind == "store" else s.function
        lines.append(f"| {kind} | {function} | {s.min_m2:g}-{s.max_m2:g} | {s.min_width_m:g} | {s.source} |")
    return "\n".join(lines) + "\n"
