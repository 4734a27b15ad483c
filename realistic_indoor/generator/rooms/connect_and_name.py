"""Doors and functions of the rooms cut from painted regions: the last step of a region layout.

:func:`connect_and_name` adds the doors (circulation, entrances, rooms, reachability, no
mazes) and then the functions.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from realistic_indoor.generator.connect import (
    break_mazes,
    connect_circulation,
    connect_rooms,
    ensure_reachable,
)
from realistic_indoor.generator.functions import FunctionRoles, assign_functions
from realistic_indoor.generator.plan import B, C, H, M
from realistic_indoor.generator.rooms.entrances import add_entrances, choose_lobby

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.plan import Plan
    from realistic_indoor.generator.wings.style import WingStyle
    from realistic_indoor.models.building_model import BuildingTypeModel

__all__ = ["connect_and_name"]


def connect_and_name(
    plan: Plan,
    rng: np.random.Generator,
    model: BuildingTypeModel,
    style: WingStyle,
    core_on_facade: bool = False,
    doors_per_room: int = 1,
    pairs: float | None = None,
    door_scale: float = 1.0,
) -> None:
    """Doors (circulation, entrances, rooms, reachability, no mazes), then functions.

    ``core_on_facade`` keeps the type's core function (offices, classrooms) for rooms with an
    outside wall (see :class:`~realistic_indoor.generator.functions.FunctionRoles`);
    ``doors_per_room`` is the most further doors one room gets and ``pairs`` the share of
    medium and big rooms given a connecting door to a neighbour (default: the model's), see
    :func:`~realistic_indoor.generator.connect.connect_rooms`; ``door_scale`` is the building's
    door habit (:func:`~realistic_indoor.generator.connect.door_habit_scale`).
    """
    connect_circulation(plan)
    add_entrances(plan, rng, choose_lobby(plan), style, model)
    share = model.structures.connected_room_pairs if pairs is None else pairs
    connect_rooms(plan, model, rng, share, per_room=doors_per_room, scale=door_scale)
    ensure_reachable(plan, rng)
    break_mazes(plan, rng)
    roles = FunctionRoles(
        service=style.service_functions,
        storage=style.storage_functions,
        ends=style.end_functions,
        entrance=style.entrance_functions,
        grouped=style.grouped_functions,
        core_on_facade=core_on_facade,
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
