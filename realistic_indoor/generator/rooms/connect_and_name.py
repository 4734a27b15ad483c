"""Doors and functions of the rooms cut from painted regions: the last step of a region layout.

:func:`connect_and_name` adds the doors (suites, circulation, entrances, rooms, reachability,
no mazes) and then the functions, by a layout's :class:`DoorRules`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from realistic_indoor.generator.connect import (
    break_mazes,
    connect_circulation,
    connect_rooms,
    door_habit_scale,
    ensure_reachable,
)
from realistic_indoor.generator.functions import FunctionRoles, assign_functions
from realistic_indoor.generator.plan import B, C, H, M
from realistic_indoor.generator.rooms.entrances import add_entrances, choose_lobby
from realistic_indoor.generator.rooms.suites import make_suites

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.plan import Plan
    from realistic_indoor.generator.rooms.style import TypeStyle
    from realistic_indoor.models.building_model import BuildingTypeModel

__all__ = ["DoorRules", "connect_and_name"]


@dataclass(frozen=True)
class DoorRules:
    """A layout's conventions for the doors of its rooms; the defaults are the paper's.

    Attributes:
        core_on_facade: Keep the type's core function (offices, classrooms) for rooms with an
            outside wall (see :class:`~realistic_indoor.generator.functions.FunctionRoles`).
        doors_per_room: Most further doors one room gets (see
            :func:`~realistic_indoor.generator.connect.connect_rooms`).
        habits: Each building draws its door habit from the model's
            (:func:`~realistic_indoor.generator.connect.door_habit_scale`), which scales its
            connected pairs and further doors.
        suites: The model's connected pairs of medium and big rooms become suites (see
            :func:`~realistic_indoor.generator.rooms.suites.make_suites`) instead of rooms with
            a door between them.
    """

    core_on_facade: bool = False
    doors_per_room: int = 1
    habits: bool = False
    suites: bool = False


def connect_and_name(
    plan: Plan, rng: np.random.Generator, model: BuildingTypeModel, style: TypeStyle, rules: DoorRules
) -> None:
    """Doors (suites, circulation, entrances, rooms, reachability, no mazes), then functions.

    Args:
        plan: The rooms, without doors.
        rng: The building's random generator.
        model: Connection frequencies, door counts, structures and function mixes.
        style: The type's functions by role and its required functions.
        rules: The layout's conventions.
    """
    pairs = model.structures.connected_room_pairs
    scale = door_habit_scale(model, rng) if rules.habits else 1.0
    if rules.suites:
        make_suites(plan, rng, min(pairs / 2 * scale, 1.0))
        pairs = 0.0
    connect_circulation(plan)
    add_entrances(plan, rng, choose_lobby(plan), style, model)
    connect_rooms(plan, model, rng, min(pairs * scale, 1.0), per_room=rules.doors_per_room, scale=scale)
    ensure_reachable(plan, rng)
    break_mazes(plan, rng)
    roles = FunctionRoles(
        service=style.service_functions,
        storage=style.storage_functions,
        ends=style.end_functions,
        entrance=style.entrance_functions,
        grouped=style.grouped_functions,
        core_on_facade=rules.core_on_facade,
    )
    assign_functions(plan, model, rng, roles)
    _require(plan, style.required_functions)


def _require(plan: Plan, functions: tuple[str, ...]) -> None:
    """Make sure each required function is present, giving it to the largest fitting room.

    A missing gym takes the largest hall that is not the lobby, a missing lab the largest big
    (else medium) room that opens onto a corridor.
    """
    present = {r.function for r in plan.rooms}
    partners = plan.door_partners()
    for function in functions:
        if function in present:
            continue
        if function == "gym":
            pool = [i for i, r in enumerate(plan.rooms) if r.label is H and r.role != "lobby"]
        else:
            pool = [
                i
                for i, r in enumerate(plan.rooms)
                if r.label in (B, M)
                and r.role == "room"
                and any(j is not None and plan.rooms[j].label is C for j in partners[i])
            ]
            pool = [i for i in pool if plan.rooms[i].label is B] or pool
        if pool:
            plan.rooms[max(pool, key=lambda i: plan.rooms[i].area)].function = function
