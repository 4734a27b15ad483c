"""The house's steps of the layout template: zones from the programme, rooms, doors and labels.

A house has no annex. Its regions are the zones of a frame (day zone, entrance, hallways, bands
of rooms) fitted to a programme drawn for its floor area; its rooms are the programme's, put
in the zones; its doors and labels follow a house's rules.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import lru_cache
from typing import TYPE_CHECKING, NamedTuple

from realistic_indoor.errors import RealisticIndoorError
from realistic_indoor.generator.geometry import area_to_units
from realistic_indoor.generator.house.doors import add_doors
from realistic_indoor.generator.house.layout import ASPECT, NEAR_COST, choose_frame
from realistic_indoor.generator.house.programme import draw_programme
from realistic_indoor.generator.house.rooms import add_rooms
from realistic_indoor.generator.plan import B, M, Plan, S
from realistic_indoor.models.reference import reference_table

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.house.layout import Frame
    from realistic_indoor.generator.house.programme import Programme
    from realistic_indoor.generator.rooms.annex import Annex
    from realistic_indoor.models.building_model import BuildingTypeModel

__all__ = ["OPTIONAL_KINDS", "HouseLayout", "HouseZones", "fit_frame", "label_by_size"]


class HouseZones(NamedTuple):
    """A house's regions: its programme and the frame that holds it.

    Attributes:
        programme: The rooms drawn for the floor area (less any left out to fit).
        frame: The footprint's zones, the rooms of each band in order and their widths (units).
    """

    programme: Programme
    frame: Frame


@dataclass(frozen=True)
class HouseLayout:
    """The house's steps, as the layout template's :class:`~realistic_indoor.generator.template.Layout`.

    Attributes:
        model: The building-type model whose door habits are used (en suites, garden doors).
    """

    model: BuildingTypeModel

    def draw_annexes(self, rng: np.random.Generator, area_m2: float) -> tuple[HouseLayout, list[Annex]]:
        """No annexes (nothing drawn)."""
        return self, []

    def regions(self, rng: np.random.Generator, area_m2: float) -> HouseZones:
        """A programme drawn for ``area_m2`` (m2) and the frame nearest a drawn length-to-width ratio."""
        prog = draw_programme(rng, area_m2)
        return HouseZones(*fit_frame(prog, float(rng.uniform(*ASPECT))))

    def rooms(self, zones: HouseZones, rng: np.random.Generator, annexes: list[Annex]) -> Plan:
        """The programme's rooms in the frame's zones (nothing drawn)."""
        plan = Plan()
        add_rooms(plan, zones.frame, zones.programme.day)
        return plan

    def add_annexes(self, plan: Plan, rng: np.random.Generator, annexes: list[Annex]) -> list[Annex] | None:
        """Nothing to add."""
        return None

    def connect_and_name(self, plan: Plan, zones: HouseZones, rng: np.random.Generator) -> None:
        """Doors by a house's rules, then every room's size label by its area."""
        add_doors(plan, rng, self.model, (zones.frame.width, zones.frame.depth))
        label_by_size(plan)


OPTIONAL_KINDS = ("store", "study", "toilet", "dining room", "living room", "bathroom", "bedroom")
"""Kinds of room left out, in this order, where a house's rooms do not fit its floor area with
their least areas, down to the least count of the programme table."""


def _drop_one(prog: Programme) -> Programme | None:
    """The programme with its least needed room left out, the table's least counts kept (``None``: none left)."""
    rooms = prog.day + prog.night
    row = prog.row
    least = {
        "store": row.stores.low,
        "study": row.studies.low,
        "toilet": row.toilets.low,
        "dining room": row.dining_rooms.low,
        "living room": row.living_rooms.low,
        "bathroom": row.bathrooms.low,
        "bedroom": row.bedrooms.low - 1,
    }
    for kind in OPTIONAL_KINDS:
        pick = [r for r in rooms if r.kind == kind]
        if len(pick) > least[kind]:
            gone = min(pick, key=lambda r: r.area_m2)
            return replace(
                prog,
                day=tuple(r for r in prog.day if r is not gone),
                night=tuple(r for r in prog.night if r is not gone),
            )
    return None


def fit_frame(prog: Programme, target: float) -> tuple[Programme, Frame]:
    """The programme's frame, leaving out rooms (see :data:`OPTIONAL_KINDS`) until one fits.

    A frame near the wanted proportions (see :data:`~realistic_indoor.generator.house.layout.NEAR_COST`)
    is preferred to all the programme's rooms: an over-full house of one strip loses a store
    rather than get a second hallway. Where even the least programme does not fit so, any
    proportions are taken, and in the smallest houses rooms below their least areas.

    Raises:
        RealisticIndoorError: If the least programme does not fit at all (a layout bug).
    """
    while True:
        frame = choose_frame(prog, target, allowance=NEAR_COST)
        if frame is not None:
            return prog, frame
        smaller = _drop_one(prog)
        if smaller is None:
            break
        prog = smaller
    frame = choose_frame(prog, target) or choose_frame(prog, target, strict=False)
    if frame is None:
        raise RealisticIndoorError(
            f"house of {prog.area_m2:g} m2 without a layout (a bug: please report the seed)"
        )
    return prog, frame


@lru_cache(maxsize=1)
def _size_limits() -> tuple[float, float]:
    """Largest small and largest medium room of a house (m2): geometric means of Table 1's mean areas.

    The rule of :func:`realistic_indoor.validator.label_inference.size_thresholds`, so that a
    generated room has the label its area would be given.
    """
    t = reference_table("house")
    s, m, b = (t[lab]["area_mean"] for lab in (S, M, B))
    return math.sqrt(s * m), math.sqrt(m * b)


def label_by_size(plan: Plan) -> None:
    """Give every room but the entrance and the hallway the size label of its area."""
    small, medium = (area_to_units(a) for a in _size_limits())
    for r in plan.rooms:
        if not r.is_circulation:
            area = r.area
            r.label = S if area < small else M if area < medium else B
