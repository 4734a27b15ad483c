"""What a house of a given floor area holds: the programme table, room sizes and hallway widths.

The table gives, per band of floor area, how many rooms of each kind a single-storey house has;
the sizes give each kind's range of areas. Every figure comes from published statistics or
norms (no plan data), listed in :data:`SOURCES` and cited by their keys below, or is marked as
this project's choice. The generator draws houses from these tables
(:mod:`realistic_indoor.generator.house.programme`) and the validator judges house plans against
them (:mod:`realistic_indoor.validator.house_programme`); docs/generator.md ("Houses") prints them.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = [
    "CORRIDOR_SHARE_MAX",
    "COUNT_COLUMNS",
    "HALLWAY_WIDTH_M",
    "LIVING_SPACE_M2",
    "PROGRAMME",
    "SIZES",
    "SOURCES",
    "STORE_FUNCTIONS",
    "ProgrammeRow",
    "RoomSize",
    "Source",
    "Span",
    "programme_markdown",
    "row_for",
]


@dataclass(frozen=True)
class Source:
    """A published statistic or norm the programme is built from.

    Attributes:
        title: Author, year and title.
        finding: What of it the programme uses.
    """

    title: str
    finding: str


SOURCES: dict[str, Source] = {
    "NDSS": Source(
        "DCLG (2015), Technical housing standards: nationally described space standard",
        "Table 1 and its notes: least gross internal area of a one-storey dwelling by bedrooms "
        "(1 bedroom 39-50 m2, 2 bedrooms 61-70, 3 bedrooms 74-95, 4 bedrooms 90-117, 5 bedrooms "
        "103-121, 6 bedrooms 116-125); a single bedroom at least 7.5 m2 and 2.15 m wide, a double "
        "at least 11.5 m2 and the first double 2.75 m wide; built-in storage 1.0-4.0 m2",
    ),
    "SOC": Source(
        "US Census Bureau, Survey of Construction (Characteristics of New Housing), as tabulated "
        "by NAHB (Eye on Housing, 2021-2022)",
        "bedrooms of new single-family homes by finished floor area: under 1,200 sq ft (111 m2) "
        "83% two or fewer; 1,200-1,599 sq ft (111-149 m2) 31% two or fewer, 67% three, 2% four; "
        "1,600-1,999 sq ft (149-186 m2) 85% three or fewer, 15% four or more; 2,000-2,399 sq ft "
        "(186-223 m2) 59% three or fewer, 41% four or more. Bathrooms (2019 starts, median about "
        "210 m2): 4% one, 64% two, 25% three, 8% four or more; of homes with four or more "
        "bedrooms, 57% have three or more bathrooms (2011)",
    ),
    "LHDG": Source(
        "Mayor of London (2010), London Housing Design Guide, interim edition",
        "standard 4.4.1: living, dining and kitchen space together at least 23 m2 (2 persons) to "
        "31 m2 (6 persons); single bedroom 8 m2, double 12 m2",
    ),
    "LABC": Source(
        "LABC Warranty (2018) survey of UK homes, as reported in the press",
        "living rooms of homes built since 2010 average 17.1 m2 (24.9 m2 in the 1970s)",
    ),
    "T1": Source(
        "Amigoni, Luperto, Quattrini Li (2014), Table 1, houses",
        "small rooms (bathrooms, toilets, stores) 6.0 +- 2.6 m2, big rooms 33.7 +- 7.8 m2",
    ),
    "ADM": Source(
        "HM Government (2015), Approved Document M, volume 1",
        "M4(1) Table 1.1: hallways at least 900 mm wide",
    ),
    "DIN": Source(
        "DIN 18040-2 (2011), barrier-free dwellings",
        "hallways at least 1.20 m wide, 1.50 m by 1.50 m to turn a wheelchair",
    ),
}
"""The programme's sources by the key that cites them."""


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

    @property
    def band(self) -> str:
        """The band of floor area in words (``"150-190 m2"``)."""
        return f"{self.min_area_m2:g}-{self.max_area_m2:g} m2"


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
"""The programme by floor area, smallest band first (see :data:`SOURCES`). A house always has
one kitchen and one entrance besides, and the hallways its layout needs."""

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


def row_for(area_m2: float) -> ProgrammeRow:
    """The band of :data:`PROGRAMME` a floor area (m2) falls in (the nearest end band outside them)."""
    for row in PROGRAMME:
        if area_m2 < row.max_area_m2:
            return row
    return PROGRAMME[-1]


@dataclass(frozen=True)
class RoomSize:
    """The range of areas of one kind of room, and its narrowest width.

    Attributes:
        function: Functional label the room gets.
        min_m2: Least area drawn (m2).
        max_m2: Greatest area drawn (m2).
        min_width_m: Narrowest the layout makes it (m): a bed's or a sofa's width, else a door's.
        source: Where the figures come from (keys of :data:`SOURCES`).
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
"""Room sizes by kind; a store's function is one of :data:`STORE_FUNCTIONS`."""

LIVING_SPACE_M2 = {2: 23.0, 3: 25.0, 4: 27.0, 5: 29.0, 6: 31.0}
"""Least floor area of living, dining and kitchen space together by persons [LHDG]; two more
square metres per further person (project's extrapolation)."""

STORE_FUNCTIONS = ("storage", "laundry", "closet")
"""Functions of a store."""

HALLWAY_WIDTH_M = (0.9, 1.0, 1.5)
"""Least, most likely and greatest hallway width (m): at least [ADM]'s 0.9 m, at most [DIN]'s
1.5 m turning space, most often about 1 m (project's choice)."""

CORRIDOR_SHARE_MAX = 0.15
"""Greatest share of a house's floor in hallways (corridor-labelled rooms): project's choice,
issue 34's bound for houses of 150 m2; the programme leaves about 13% of the floor to
circulation, entrance included."""


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
