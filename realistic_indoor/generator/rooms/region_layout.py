"""The layout template's steps for layouts that paint regions: all but the painting.

The block and wing layouts differ in how they paint a footprint (a :class:`Painter`); the
rest (annexes, rooms from the regions, doors and functions) is the room toolkit's, with each
layout's conventions (:class:`~realistic_indoor.generator.rooms.from_regions.RoomRules`,
:class:`~realistic_indoor.generator.rooms.annex.AnnexRules`,
:class:`~realistic_indoor.generator.rooms.connect_and_name.DoorRules`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, NamedTuple, Protocol

from realistic_indoor.generator.rooms.annex import (
    draw_annexes,
    expected_service_rooms,
    fewer_annexes,
    place_annexes,
)
from realistic_indoor.generator.rooms.connect_and_name import connect_and_name
from realistic_indoor.generator.rooms.dims import layout_dims
from realistic_indoor.generator.rooms.from_regions import rooms_from_regions

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.plan import Plan
    from realistic_indoor.generator.rooms.annex import Annex, AnnexRules
    from realistic_indoor.generator.rooms.connect_and_name import DoorRules
    from realistic_indoor.generator.rooms.dims import Dims
    from realistic_indoor.generator.rooms.from_regions import RoomRules
    from realistic_indoor.generator.rooms.regions import FloorRegions
    from realistic_indoor.generator.rooms.style import TypeStyle
    from realistic_indoor.models.building_model import BuildingTypeModel

__all__ = ["Painted", "Painter", "RegionLayout"]


class Painted(NamedTuple):
    """A footprint painted into regions.

    Attributes:
        regions: The regions (units).
        dims: The building-wide sizes they were painted with (units).
        shape: The footprint's shape name, for the building's metadata.
    """

    regions: FloorRegions
    dims: Dims
    shape: str


class Painter(Protocol):
    """A layout's own step: a footprint of ``area_m2`` painted into regions."""

    def __call__(
        self, rng: np.random.Generator, area_m2: float, model: BuildingTypeModel, dims: Dims
    ) -> Painted:
        """The regions of a footprint of about ``area_m2`` (m2), with sizes ``dims`` (units)."""
        ...


@dataclass(frozen=True)
class RegionLayout:
    """A layout that paints regions, as the layout template's :class:`~realistic_indoor.generator.template.Layout`.

    Attributes:
        model: The building-type model, set to the building's size.
        style: The type's conventions.
        painter: How the footprint is painted into regions (the layout's own step).
        room_rules: How the regions are cut into rooms.
        annex_rules: Which annexes stand beside the rooms, and how.
        door_rules: How the rooms get their doors.
    """

    model: BuildingTypeModel
    style: TypeStyle
    painter: Painter
    room_rules: RoomRules
    annex_rules: AnnexRules
    door_rules: DoorRules

    def draw_annexes(self, rng: np.random.Generator, area_m2: float) -> tuple[RegionLayout, list[Annex]]:
        """The annexes of a building of ``area_m2`` (m2), and the layout with the style to lay it out with."""
        style, annexes = draw_annexes(rng, area_m2, self.style, self.annex_rules)
        return replace(self, style=style), annexes

    def regions(self, rng: np.random.Generator, area_m2: float) -> Painted:
        """Building-wide sizes drawn from the model, and the footprint of ``area_m2`` (m2) painted with them."""
        return self.painter(rng, area_m2, self.model, layout_dims(rng, self.model, self.style))

    def rooms(self, painted: Painted, rng: np.random.Generator, annexes: list[Annex]) -> Plan:
        """The rooms of the painted regions (see :func:`~realistic_indoor.generator.rooms.from_regions.rooms_from_regions`)."""
        rules = self.annex_rules
        count = annexes and rules.count_service_rooms
        placed = expected_service_rooms(annexes[0].area_m2, rules.room_m) if count else 0.0
        return rooms_from_regions(
            painted.regions, rng, self.model, self.style, painted.dims, self.room_rules, placed_small=placed
        )

    def add_annexes(self, plan: Plan, rng: np.random.Generator, annexes: list[Annex]) -> list[Annex] | None:
        """Stand the annexes beside the rooms; ``None`` if all stand, else the annexes to lay out again with."""
        failed = place_annexes(plan, rng, self.style, annexes, self.annex_rules)
        return None if failed < 0 else fewer_annexes(annexes, failed, self.annex_rules)

    def connect_and_name(self, plan: Plan, painted: Painted, rng: np.random.Generator) -> None:
        """Doors, then functions (see :func:`~realistic_indoor.generator.rooms.connect_and_name.connect_and_name`)."""
        connect_and_name(plan, rng, self.model, self.style, self.door_rules)
