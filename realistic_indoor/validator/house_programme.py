"""House plans judged against the house programme: rooms counted by function, hallway widths, access.

The programme (:mod:`realistic_indoor.models.house_programme`, built from published housing
statistics and norms, the table of docs/generator.md "Houses") says how many bedrooms, bathrooms
and living rooms a single-storey house of a floor area has; a house has one kitchen, one
entrance and at least one hallway besides; hallways are 0.9-1.5 m wide; at most 15% of the floor
is corridor-labelled; a bathroom is reachable without crossing a bedroom (en-suites aside) and bedrooms
open off a hallway or the living area. :func:`house_check` measures one plan against each of
these items, :func:`house_summary` gives the share of a set's plans inside the programme per item.
"""

from __future__ import annotations

import math
import statistics
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import networkx as nx

from realistic_indoor.building.labels import (
    CIRCULATION_LABELS,
    CORE_FUNCTIONS,
    OUTSIDE,
    BuildingType,
    SemanticLabel,
    normalise_function,
)
from realistic_indoor.models.house_programme import (
    CORRIDOR_SHARE_MAX,
    HALLWAY_WIDTH_M,
    PROGRAMME,
    SOURCES,
    row_for,
)

if TYPE_CHECKING:
    from collections.abc import Sequence

    from shapely.geometry import Polygon

    from realistic_indoor.building.building import Building
    from realistic_indoor.models.house_programme import ProgrammeRow

__all__ = [
    "AREA_TOLERANCE",
    "COUNTED_FUNCTIONS",
    "FIXED_COUNTS",
    "HOUSE_ITEMS",
    "HOUSE_REFERENCE",
    "HOUSE_RULES",
    "WIDTH_TOLERANCE_M",
    "CountRange",
    "HouseCheck",
    "HouseSummary",
    "allowed_counts",
    "bands_near",
    "hallway_width",
    "house_check",
    "house_reference",
    "house_summary",
]

COUNTED_FUNCTIONS: dict[str, frozenset[str]] = {
    "bedrooms": CORE_FUNCTIONS[BuildingType.HOUSE],
    "bathrooms": frozenset({"bathroom", "bath room", "shower room", "en suite", "ensuite"}),
    "kitchens": frozenset({"kitchen"}),
    "living_rooms": frozenset({"living room", "lounge", "sitting room", "family room"}),
    "entrances": frozenset({"entrance", "entrance hall", "foyer", "hall", "lobby"}),
    "hallways": frozenset({"hallway", "corridor", "passage", "landing"}),
}
"""The functions (normalised, see :func:`~realistic_indoor.building.labels.normalise_function`)
counted as each kind of room. The house generator writes ``bedroom``, ``bathroom``, ``kitchen``,
``living room``, ``entrance`` and ``hallway``; the others are common names in house plans."""

LIVING_AREA = COUNTED_FUNCTIONS["living_rooms"] | {"dining room", "kitchen"}
"""Functions of the living area, which bedrooms may open off besides hallways and entrances."""

HOUSE_ITEMS: dict[str, str] = {
    "bedrooms": "bedrooms",
    "bathrooms": "bathrooms",
    "kitchens": "kitchens",
    "living_rooms": "living rooms",
    "entrances": "entrances",
    "hallways": "hallways",
    "hallway_width": "hallway width (m)",
    "corridor_share": "corridor-labelled floor",
    "bathroom_access": "a bathroom reached without crossing a bedroom",
    "bedroom_access": "bedrooms open off a hallway or the living area",
}
"""What a house is judged on, in the order of the report, and its words there."""

HOUSE_REFERENCE = (
    f"the house programme of docs/generator.md (sources: {', '.join(SOURCES)}; see docs/validator.md)"
)
"""The reference in words, as the report names it."""

AREA_TOLERANCE = 0.02
"""A plan is held to every band of the programme within this share of its floor area: a plan's
summed room areas differ from the floor area it was designed for (generated houses by up to
1%), so a house of 149 m2 may have the rooms of one of 150 m2."""

WIDTH_TOLERANCE_M = 0.05
"""How far a hallway's measured width may lie outside 0.9-1.5 m (m): half the 0.1 m grid plans
are drawn on."""


@dataclass(frozen=True)
class CountRange:
    """The counts of a kind of room a house may have, both ends included.

    Attributes:
        low: Least count.
        high: Greatest count (``None``: no upper bound).
    """

    low: int
    high: int | None

    def admits(self, n: int) -> bool:
        """Whether ``n`` lies in the range."""
        return self.low <= n and (self.high is None or n <= self.high)

    def __str__(self) -> str:
        if self.high is None:
            return f"{self.low} or more"
        return str(self.low) if self.low == self.high else f"{self.low}-{self.high}"


FIXED_COUNTS = {"kitchens": CountRange(1, 1), "entrances": CountRange(1, 1), "hallways": CountRange(1, None)}
"""Counts the programme gives every house whatever its floor area."""


HOUSE_RULES: dict[str, str] = {
    **dict.fromkeys(("bedrooms", "bathrooms", "living_rooms"), "by floor area (docs/generator.md)"),
    **{key: str(span) for key, span in FIXED_COUNTS.items()},
    "hallway_width": f"{HALLWAY_WIDTH_M[0]}-{HALLWAY_WIDTH_M[2]} (ADM, DIN)",
    "corridor_share": f"at most {CORRIDOR_SHARE_MAX:.0%}",
    "bathroom_access": "yes",
    "bedroom_access": "yes",
}
"""What the programme asks of each item of :data:`HOUSE_ITEMS`, in words."""


def house_reference() -> dict[str, Any]:
    """The house programme as the validator uses it, as JSON-ready data: rules, table, tolerances, sources."""
    return {
        "name": HOUSE_REFERENCE,
        "rules": HOUSE_RULES,
        "table": [
            {
                "min_area_m2": r.min_area_m2,
                "max_area_m2": r.max_area_m2,
                **{
                    key: [getattr(r, key).low, getattr(r, key).high]
                    for key in ("bedrooms", "bathrooms", "living_rooms")
                },
            }
            for r in PROGRAMME
        ],
        "hallway_width_m": [HALLWAY_WIDTH_M[0], HALLWAY_WIDTH_M[2]],
        "corridor_share_max": CORRIDOR_SHARE_MAX,
        "area_tolerance": AREA_TOLERANCE,
        "width_tolerance_m": WIDTH_TOLERANCE_M,
        "sources": {key: {"title": src.title, "finding": src.finding} for key, src in SOURCES.items()},
    }


def bands_near(area_m2: float) -> tuple[ProgrammeRow, ...]:
    """The bands of the programme holding a floor area within :data:`AREA_TOLERANCE` of ``area_m2`` (m2).

    Outside the table's floor areas, the nearest end band.
    """
    low, high = area_m2 / (1 + AREA_TOLERANCE), area_m2 * (1 + AREA_TOLERANCE)
    rows = tuple(r for r in PROGRAMME if r.min_area_m2 <= high and low < r.max_area_m2)
    return rows or (row_for(area_m2),)


def allowed_counts(area_m2: float) -> dict[str, CountRange]:
    """The counts of each kind of room (keys of :data:`COUNTED_FUNCTIONS`) a house of ``area_m2`` (m2) may have.

    Bedrooms, bathrooms and living rooms from the programme's bands near the floor area (see
    :func:`bands_near`: the least of their lows to the greatest of their highs); one kitchen, one
    entrance and at least one hallway.
    """
    rows = bands_near(area_m2)

    def spanned(key: str) -> CountRange:
        return CountRange(min(getattr(r, key).low for r in rows), max(getattr(r, key).high for r in rows))

    return {key: FIXED_COUNTS[key] if key in FIXED_COUNTS else spanned(key) for key in COUNTED_FUNCTIONS}


def hallway_width(polygon: Polygon) -> float:
    """A hallway's width (m): the short side of the rectangle with its area and perimeter.

    Exact for a straight hallway and for an L, T, comb or cross of one width (each arm adds its
    length to both the area over the width and the half perimeter), where the short side of the
    smallest enclosing rectangle would be the span of the arms.
    """
    area, half = polygon.area, polygon.length / 2
    long_side = half / 2 + math.sqrt(max((half / 2) ** 2 - area, 0.0))
    return area / long_side if long_side > 0 else 0.0


@dataclass(frozen=True)
class HouseCheck:
    """One house plan measured against the programme.

    Attributes:
        floor_area_m2: Summed area of its rooms (m2).
        bands: The programme's bands its counts are judged by (``"150-190 m2"``; two near a
            band's edge, see :data:`AREA_TOLERANCE`).
        counts: Rooms of each kind (keys of :data:`COUNTED_FUNCTIONS`), by function.
        allowed: The counts the programme allows, for the same keys.
        hallway_widths_m: Width of each hallway (m, see :func:`hallway_width`).
        corridor_share: Share of the floor in corridor-labelled rooms (0-1).
        bathroom_reachable: Whether a bathroom is reached from outside without crossing a
            bedroom (``None``: no bathroom, or no way in).
        bedrooms_open_off_living: Whether every bedroom has a door to a hallway, an entrance, a
            corridor, a hall or a room of the living area (``None``: no bedroom).
    """

    floor_area_m2: float
    bands: tuple[str, ...]
    counts: dict[str, int]
    allowed: dict[str, CountRange]
    hallway_widths_m: tuple[float, ...]
    corridor_share: float
    bathroom_reachable: bool | None
    bedrooms_open_off_living: bool | None

    @property
    def items(self) -> dict[str, bool | None]:
        """Whether the plan is inside the programme on each item of :data:`HOUSE_ITEMS` (``None``: not judged)."""
        out: dict[str, bool | None] = {k: self.allowed[k].admits(n) for k, n in self.counts.items()}
        low, _mode, high = HALLWAY_WIDTH_M
        widths = self.hallway_widths_m
        out["hallway_width"] = (
            all(low - WIDTH_TOLERANCE_M <= w <= high + WIDTH_TOLERANCE_M for w in widths) if widths else None
        )
        out["corridor_share"] = self.corridor_share <= CORRIDOR_SHARE_MAX
        out["bathroom_access"] = self.bathroom_reachable
        out["bedroom_access"] = self.bedrooms_open_off_living
        return out

    @property
    def inside(self) -> bool:
        """Whether no item is outside the programme."""
        return all(ok is not False for ok in self.items.values())

    def to_dict(self) -> dict[str, Any]:
        """The check as JSON-ready data: its fields (allowed ranges as text), items, verdict and problems."""
        return {
            **{k: getattr(self, k) for k in self.__dataclass_fields__},
            "allowed": {k: str(v) for k, v in self.allowed.items()},
            "items": self.items,
            "inside": self.inside,
            "problems": list(self.problems()),
        }

    def problems(self) -> tuple[str, ...]:
        """The items outside the programme, in words (``"0 bedrooms; the programme has 3-4 at 150-190 m2"``)."""
        items, out = self.items, []
        bands = " or ".join(self.bands)
        for key, n in self.counts.items():
            if not items[key]:
                out.append(f"{n} {HOUSE_ITEMS[key]}; the programme has {self.allowed[key]} at {bands}")
        if items["hallway_width"] is False:
            widths = ", ".join(f"{w:.2f}" for w in self.hallway_widths_m)
            out.append(
                f"hallways {widths} m wide; the programme has {HALLWAY_WIDTH_M[0]}-{HALLWAY_WIDTH_M[2]} m"
            )
        if not items["corridor_share"]:
            out.append(
                f"{100 * self.corridor_share:.1f}% of the floor corridor-labelled; "
                f"the programme has at most {100 * CORRIDOR_SHARE_MAX:g}%"
            )
        if items["bathroom_access"] is False:
            out.append("every bathroom is reached only through a bedroom")
        if items["bedroom_access"] is False:
            out.append("a bedroom opens off neither a hallway nor the living area")
        return tuple(out)


def house_check(building: Building) -> HouseCheck:
    """Measure a house plan against the programme (see :class:`HouseCheck`).

    Rooms are counted by their function (:data:`COUNTED_FUNCTIONS`); the corridor share is by
    semantic label; the floor area is the summed area of the rooms.
    """
    kind = {r.id: _kind(r.function) for r in building.rooms}
    counts = {key: sum(k == key for k in kind.values()) for key in COUNTED_FUNCTIONS}
    area = building.area
    widths = tuple(hallway_width(r.polygon) for r in building.rooms if kind[r.id] == "hallways")
    corridor = sum(r.area for r in building.rooms if r.label is SemanticLabel.CORRIDOR)
    return HouseCheck(
        floor_area_m2=area,
        bands=tuple(r.band for r in bands_near(area)),
        counts=counts,
        allowed=allowed_counts(area),
        hallway_widths_m=widths,
        corridor_share=corridor / area if area > 0 else math.nan,
        bathroom_reachable=_bathroom_reachable(building, kind),
        bedrooms_open_off_living=_bedrooms_open_off_living(building, kind),
    )


def _kind(function: str) -> str | None:
    """The key of :data:`COUNTED_FUNCTIONS` a function is counted as, if any."""
    name = normalise_function(function)
    return next((key for key, names in COUNTED_FUNCTIONS.items() if name in names), None)


def _bathroom_reachable(building: Building, kind: dict[str, str | None]) -> bool | None:
    """Whether a bathroom is reached without crossing a bedroom, from outside (or an entrance where no door leads out)."""
    bathrooms = {rid for rid, k in kind.items() if k == "bathrooms"}
    starts = [OUTSIDE] if building.entrances else [rid for rid, k in kind.items() if k == "entrances"]
    if not bathrooms or not starts:
        return None
    g = building.graph(include_outside=True)
    g.remove_nodes_from([rid for rid, k in kind.items() if k == "bedrooms"])
    reached = set().union(*(nx.node_connected_component(g, s) for s in starts))
    return bool(bathrooms & reached)


def _bedrooms_open_off_living(building: Building, kind: dict[str, str | None]) -> bool | None:
    """Whether every bedroom has a door to circulation (by function or label) or the living area."""
    bedrooms = [rid for rid, k in kind.items() if k == "bedrooms"]
    if not bedrooms:
        return None

    def open_off(rid: str) -> bool:
        for door in building.doors_of[rid]:
            other = door.other(rid)
            room = building.room_by_id.get(other) if other is not None else None
            if room is not None and (
                kind[room.id] in ("hallways", "entrances")
                or room.label in CIRCULATION_LABELS
                or normalise_function(room.function) in LIVING_AREA
            ):
                return True
        return False

    return all(open_off(rid) for rid in bedrooms)


@dataclass(frozen=True)
class HouseSummary:
    """A set of house plans against the programme.

    Attributes:
        plans: Plans judged.
        inside: Per item of :data:`HOUSE_ITEMS`, the share of the plans judged on it that are
            inside the programme (0-1; ``nan`` where no plan was judged on it).
        all_inside: Share of the plans inside the programme on every item (0-1).
        medians: Median count per kind of room over the plans; ``hallway_width`` the median
            over all hallways (m); ``corridor_share`` the median over the plans (0-1).
    """

    plans: int
    inside: dict[str, float]
    all_inside: float
    medians: dict[str, float]


def house_summary(checks: Sequence[HouseCheck]) -> HouseSummary:
    """Summarise the checks of a set of house plans (see :class:`HouseSummary`)."""
    inside = {}
    for key in HOUSE_ITEMS:
        judged = [c.items[key] for c in checks if c.items[key] is not None]
        inside[key] = sum(judged) / len(judged) if judged else math.nan
    medians = {key: _median([c.counts[key] for c in checks]) for key in COUNTED_FUNCTIONS}
    medians["hallway_width"] = _median([w for c in checks for w in c.hallway_widths_m])
    medians["corridor_share"] = _median([c.corridor_share for c in checks])
    all_inside = sum(c.inside for c in checks) / len(checks) if checks else math.nan
    return HouseSummary(len(checks), inside, all_inside, medians)


def _median(values: Sequence[float]) -> float:
    return float(statistics.median(values)) if values else math.nan
