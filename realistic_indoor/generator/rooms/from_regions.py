"""Rooms from painted regions: halls, rooms cut from the strips, end rooms and corridor segments."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from realistic_indoor.generator.geometry import Rect, to_units
from realistic_indoor.generator.plan import C, H, Plan, PlanRoom, S
from realistic_indoor.generator.rooms.bays import DOOR_NEED, BayContext, subdivide
from realistic_indoor.generator.rooms.budget import building_budget
from realistic_indoor.generator.rooms.corridors import corridor_fronts, segment_corridors
from realistic_indoor.generator.rooms.halls import carve_hall_bays

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.rooms.dims import Dims
    from realistic_indoor.generator.rooms.regions import FloorRegions
    from realistic_indoor.generator.rooms.style import TypeStyle
    from realistic_indoor.models.building_model import BuildingTypeModel

__all__ = ["RoomRules", "rooms_from_regions"]


@dataclass(frozen=True)
class RoomRules:
    """A layout's conventions for cutting its regions into rooms.

    Attributes:
        corridor_cuts: How many corridor segments to cut, as a share of the number the model's
            corridor share asks for.
        hall_rooms_p: Probability that a large hall gets a strip of rooms along a side (see
            :func:`~realistic_indoor.generator.rooms.halls.carve_hall_bays`); ``None``: halls
            keep their floor (and nothing is drawn).
        max_axes_ratio: Rooms are at least a strip's depth over this wide (see
            :class:`~realistic_indoor.generator.rooms.bays.BayContext`).
        widen_last_room: See :class:`~realistic_indoor.generator.rooms.bays.BayContext`.
    """

    corridor_cuts: float = 1.0
    hall_rooms_p: float | None = None
    max_axes_ratio: float = math.inf
    widen_last_room: bool = False


def rooms_from_regions(
    regions: FloorRegions,
    rng: np.random.Generator,
    model: BuildingTypeModel,
    style: TypeStyle,
    dims: Dims,
    rules: RoomRules,
    placed_small: float = 0.0,
) -> Plan:
    """Halls, rooms cut from the strips, end rooms and corridor segments of painted regions.

    Args:
        regions: The painted footprint (its halls may give up a strip of rooms).
        rng: The building's random generator.
        model: The building-type model (label shares, areas, structures).
        style: The type's conventions (rooms per service core).
        dims: Corridor width and strip depths (units).
        rules: The layout's conventions.
        placed_small: Small rooms the building gets besides these (see
            :func:`~realistic_indoor.generator.rooms.budget.building_budget`).

    Returns:
        The plan: rooms without doors.
    """
    if rules.hall_rooms_p is not None:
        carve_hall_bays(regions, rng, round(dims.depth * rng.uniform(0.8, 1.0)), rules.hall_rooms_p)
    plan = Plan(exterior_holes=regions.holes)
    for _, rects in regions.halls:
        plan.add(PlanRoom(rects, H, role="hall"))
    circulation = regions.corridors + [r for _, rects in regions.halls for r in rects]
    stub = to_units(rng.uniform(1.3, 1.6))
    limit = (dims.depth + dims.shallow) // 2
    budget = building_budget(regions, model, stub, style.core_rooms, limit, placed_small)
    ctx = BayContext(
        model, budget, circulation, stub, style.core_rooms, limit, rules.max_axes_ratio, rules.widen_last_room
    )
    for k in rng.permutation(len(regions.bays)):
        subdivide(plan, regions.bays[int(k)], rng, ctx)
    for rect in regions.ends:
        plan.add(PlanRoom([rect], S, role="end"))
    _corridors(plan, regions, model, rng, dims, rules.corridor_cuts)
    return plan


def _corridors(
    plan: Plan,
    regions: FloorRegions,
    model: BuildingTypeModel,
    rng: np.random.Generator,
    dims: Dims,
    corridor_cuts: float,
) -> None:
    """Cut the corridor lines into segments, as many as the model's corridor share asks for.

    The count is scaled by ``corridor_cuts``; stubs of service cores count as corridors.
    """
    p = model.shares()
    others = sum(1 for r in plan.rooms if r.label is not C)
    stubs = sum(1 for r in plan.rooms if r.label is C)
    want = round(corridor_cuts * p[C] / max(1 - p[C], 1e-6) * others) - stubs
    junctions: list[Rect] = [r for _, rects in regions.halls for r in rects] + regions.corridors
    min_len = max(4 * dims.corridor, to_units(6.0))
    fronts = corridor_fronts(plan, regions.corridors)
    for seg in segment_corridors(regions.corridors, want, rng, min_len, junctions, fronts, DOOR_NEED):
        plan.add(PlanRoom([seg], C, role="corridor"))
