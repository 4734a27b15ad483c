"""Functional labels of generated rooms, drawn from the model's mix and each room's role."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from realistic_indoor.building.labels import CORE_FUNCTIONS, SemanticLabel
from realistic_indoor.generator.doors import exterior_walls
from realistic_indoor.generator.plan import C
from realistic_indoor.generator.sampling import choice_index

if TYPE_CHECKING:
    from collections.abc import Iterable

    import numpy as np

    from realistic_indoor.generator.plan import Plan
    from realistic_indoor.models.building_model import BuildingTypeModel

__all__ = ["FunctionRoles", "assign_functions", "draw_function"]


def draw_function(
    rng: np.random.Generator,
    weights: dict[str, float],
    prefer: Iterable[str] = (),
    avoid: Iterable[str] = (),
) -> str:
    """A function drawn from ``weights``, restricted to ``prefer`` where the mix has any of them.

    Args:
        rng: Random source.
        weights: Functional labels and their weights.
        prefer: Functions to choose among when the mix holds at least one of them.
        avoid: Functions whose weight is cut to a twentieth.
    """
    prefer = set(prefer)
    avoid = set(avoid)
    pool = {k: v for k, v in weights.items() if k in prefer} or dict(weights)
    names = sorted(pool)
    w = [pool[k] * (0.05 if k in avoid else 1.0) for k in names]
    return names[choice_index(rng, [x / sum(w) for x in w])]


@dataclass(frozen=True)
class FunctionRoles:
    """Which functions suit which roles, for one building type.

    Attributes:
        service: Functions of rooms in service cores.
        storage: Functions of closets and rooms entered through other rooms.
        ends: Functions of small rooms at corridor ends.
        entrance: Functions of the entrance hall.
        core: The type's core functions (offices, classrooms, bedrooms): rooms without a door
            to a corridor rarely get them (default: the validator's core functions of the type).
        grouped: Functions that come only in groups, inside service cores (toilets).
        public: Functions of rooms everyone walks to (a gym, a canteen, a library): rooms
            without a door to a corridor or hall never get them.
        core_on_facade: Also keep the core functions for rooms with an outside wall (windows):
            in deep plans the rooms inside get meeting rooms, storage and services.
    """

    service: tuple[str, ...] = ()
    storage: tuple[str, ...] = ("closet", "storage")
    ends: tuple[str, ...] = ()
    entrance: tuple[str, ...] = ()
    core: tuple[str, ...] = ()
    grouped: tuple[str, ...] = ("toilet", "washroom")
    public: tuple[str, ...] = ("gym", "canteen", "cafeteria", "library", "conference hall", "reception")
    core_on_facade: bool = False


def _core_functions(model: BuildingTypeModel) -> tuple[str, ...]:
    return tuple(sorted(CORE_FUNCTIONS.get(model.building_type, frozenset())))


def assign_functions(
    plan: Plan, model: BuildingTypeModel, rng: np.random.Generator, roles: FunctionRoles
) -> None:
    """Give every room without a function one, by role and label.

    Rooms of a service core get service functions, toilets in pairs; closets storage; the
    entrance hall an entrance function; ordinary rooms their label's mix, with the type's core
    function (office, classroom, bedroom) kept for rooms that open onto a corridor. A function
    an annex holds (a school's gym, auditorium or canteen beside the block) is not given to a
    room inside the building as well, and a public function (``roles.public``: a library, a
    reception) goes to one room of the building: none of the 55 shared real plans holds a gym,
    library, cafeteria, reception or conference hall twice, and one of 13 schools with a
    canteen has two.
    """
    core = roles.core or _core_functions(model)
    held = {r.function for r in plan.rooms if r.role == "annex" and r.function}
    partners = plan.door_partners()
    by_group: dict[int, list[int]] = {}
    for i, r in enumerate(plan.rooms):
        if r.role == "core" and not r.function:
            by_group.setdefault(r.group, []).append(i)
    for rooms in by_group.values():
        _service_core(plan, rooms, model, rng, roles)
    for i, r in enumerate(plan.rooms):
        if r.function:
            continue
        weights = model.function_weights(r.label)
        weights = {k: v for k, v in weights.items() if k not in held} or weights
        if r.role in ("closet", "back") and r.label is SemanticLabel.SMALL:
            r.function = draw_function(rng, weights, roles.storage)
        elif r.role == "end":
            r.function = draw_function(rng, weights, roles.ends, avoid=roles.grouped)
        elif r.role == "lobby":
            r.function = draw_function(rng, weights, roles.entrance)
        elif r.role == "hall":
            r.function = draw_function(rng, weights, avoid=roles.entrance)
        else:
            to_corridor = any(j is not None and plan.rooms[j].label is C for j in partners[i])
            inside = roles.core_on_facade and not exterior_walls(plan, i)
            avoid = roles.grouped + (() if to_corridor and not inside else core)
            if not any(j is not None and plan.rooms[j].is_circulation for j in partners[i]):
                weights = {k: v for k, v in weights.items() if k not in roles.public} or weights
            r.function = draw_function(rng, weights, avoid=avoid)
        if r.function in roles.public:
            held.add(r.function)


def _service_core(
    plan: Plan, rooms: list[int], model: BuildingTypeModel, rng: np.random.Generator, roles: FunctionRoles
) -> None:
    """Toilets side by side (two or more when the core has four rooms) and other services."""
    weights = model.function_weights(SemanticLabel.SMALL)
    toilets = [f for f in ("toilet", "washroom", "bathroom") if f in weights]
    n_toilets = 2 if toilets and len(rooms) >= 3 else (1 if toilets and rng.random() < 0.6 else 0)
    for k, i in enumerate(rooms):
        if k < n_toilets:
            plan.rooms[i].function = toilets[0]
        else:
            plan.rooms[i].function = draw_function(rng, weights, roles.service, avoid=toilets)
