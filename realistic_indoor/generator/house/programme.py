"""A house's programme drawn for its floor area: which rooms it has, how large, and its hallway's width.

The table and the room sizes, with their sources, are data of the building-type models
(:mod:`realistic_indoor.models.house_programme`), which the validator judges houses against too.
The counts are drawn uniformly within their range; a house is always given one kitchen, one
entrance and the hallways its layout needs. Room areas are drawn uniformly within their range
of :data:`~realistic_indoor.models.house_programme.SIZES` times the band's room scale; they set
the rooms' proportions, and the layout then fills the floor area with them (see
docs/generator.md, "Houses").
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING, NamedTuple

from realistic_indoor.generator.geometry import to_units
from realistic_indoor.models.house_programme import (
    COUNT_COLUMNS,
    HALLWAY_WIDTH_M,
    LIVING_SPACE_M2,
    SIZES,
    STORE_FUNCTIONS,
    ProgrammeRow,
    row_for,
)

if TYPE_CHECKING:
    import numpy as np

__all__ = [
    "ENTRANCE_WIDTH_M",
    "SERVICE_KINDS",
    "Programme",
    "ProgrammeRoom",
    "draw_programme",
]


ENTRANCE_WIDTH_M = (1.6, 2.4)
"""Range of the entrance's width (m), drawn uniformly, times the square root of the band's room
scale where that is above 1 (project's choice: wide enough for the front door with its
clearances and a coat rack); it is as deep as the band of rooms beside it."""

SERVICE_KINDS = ("bathroom", "toilet", "store")
"""Kinds of service room: as wide as their door needs, tucked in next to the hallway."""


class ProgrammeRoom(NamedTuple):
    """One room a house is to have.

    Attributes:
        kind: Key of its size in :data:`~realistic_indoor.models.house_programme.SIZES`
            (``"main bedroom"``, ``"store"``, ...).
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
        """Least area of the day zone (m2): LHDG's living space for as many persons as bedspaces.

        The main bedroom sleeps two, every other bedroom one (as NDSS counts a 3b4p home).
        """
        persons = 1 + self.count("bedroom")
        top = max(LIVING_SPACE_M2)
        return LIVING_SPACE_M2[min(persons, top)] + 2.0 * max(persons - top, 0)

    def count(self, function: str) -> int:
        """How many of its rooms have ``function``."""
        return sum(r.function == function for r in self.day + self.night)


def draw_programme(rng: np.random.Generator, area_m2: float) -> Programme:
    """The rooms of a house of ``area_m2``: counts from its band of the programme, areas from its room sizes.

    Counts and areas are drawn uniformly within their ranges (areas times the band's room
    scale), a store's function uniformly among the store functions, the hallway's width from the
    triangular distribution with the least, most likely and greatest width of
    :data:`~realistic_indoor.models.house_programme.HALLWAY_WIDTH_M` and the entrance's from
    :data:`ENTRANCE_WIDTH_M` (in a few vector draws: the generator runs once per episode). The
    tables are those of :mod:`realistic_indoor.models.house_programme`.

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
