"""The layout template: the steps in which every realistic generator lays out a building.

1. **Draw the annexes**: large rooms to stand beside the building (a school's gym, an
   auditorium, a canteen; none in offices and houses).
2. **Lay out regions**: the layout's own step. It turns a footprint of the floor area less the
   annexes' into regions: corridors, halls and strips of rooms (the block and wing layouts,
   :class:`~realistic_indoor.generator.rooms.region_layout.RegionLayout`), or a house's day
   zone, entrance, hallway and bands (:class:`~realistic_indoor.generator.house.steps.HouseLayout`).
3. **Rooms from regions**.
4. **Add the annexes** beside the rooms. Where one finds no place, the building is laid out
   again (from step 2) with fewer or smaller annexes, so it keeps its floor area.
5. **Connect and name**: doors, then functions and labels.

:func:`lay_out` runs them; a :class:`Layout` says how each is done.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol, TypeVar

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.plan import Plan
    from realistic_indoor.generator.rooms.annex import Annex

__all__ = ["Layout", "lay_out"]

R = TypeVar("R")
"""What a layout's regions are (painted regions, a house's zones)."""


class Layout(Protocol[R]):
    """How each step of the layout template is done, for one building type and layout."""

    def draw_annexes(self, rng: np.random.Generator, area_m2: float) -> tuple[Layout[R], list[Annex]]:
        """Step 1: the annexes of a building of ``area_m2`` (m2), and the layout to lay it out with.

        The type's own annex comes first. The layout returned may differ from this one: a
        building drawn without its type's annex does not ask for its function of another room.
        """
        ...

    def regions(self, rng: np.random.Generator, area_m2: float) -> R:
        """Step 2: a footprint of about ``area_m2`` (m2) turned into regions."""
        ...

    def rooms(self, regions: R, rng: np.random.Generator, annexes: list[Annex]) -> Plan:
        """Step 3: the rooms of the regions, with ``annexes`` to stand beside them."""
        ...

    def add_annexes(self, plan: Plan, rng: np.random.Generator, annexes: list[Annex]) -> list[Annex] | None:
        """Step 4: stand ``annexes`` beside the rooms.

        Returns ``None`` if all stand, else the annexes to lay the building out again with
        (fewer or smaller ones; an empty list at the last, which always stands).
        """
        ...

    def connect_and_name(self, plan: Plan, regions: R, rng: np.random.Generator) -> None:
        """Step 5: doors, then functions and labels."""
        ...


def lay_out(layout: Layout[R], rng: np.random.Generator, area_m2: float) -> tuple[Plan, R]:
    """Lay out a building of about ``area_m2`` (m2) in the template's steps.

    Args:
        layout: How each step is done.
        rng: The building's random generator; the steps draw from it in their order, so the
            same state gives the same plan.
        area_m2: Floor area wanted (m2), annexes included.

    Returns:
        The plan (rooms, doors, functions) and the regions it was made from.
    """
    layout, annexes = layout.draw_annexes(rng, area_m2)
    while True:  # ends: a layout places an empty list of annexes
        regions = layout.regions(rng, area_m2 - sum(annex.area_m2 for annex in annexes))
        plan = layout.rooms(regions, rng, annexes)
        fewer = layout.add_annexes(plan, rng, annexes)
        if fewer is None:
            break
        annexes = fewer
    layout.connect_and_name(plan, regions, rng)
    return plan, regions
