"""The lobby and the doors to the outside: main entrance, side doors in halls, exits at corridor ends."""

from __future__ import annotations

from typing import TYPE_CHECKING

from realistic_indoor.building.labels import OUTSIDE
from realistic_indoor.generator.doors import RULES, add_exterior_door, exterior_walls
from realistic_indoor.generator.plan import H

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.plan import Plan
    from realistic_indoor.generator.rooms.style import TypeStyle
    from realistic_indoor.models.building_model import BuildingTypeModel

__all__ = ["add_entrances", "choose_lobby"]


def choose_lobby(plan: Plan) -> int:
    """Make the hall with a facade nearest the middle of the building the lobby (-1: none)."""
    ids = [i for i, r in enumerate(plan.rooms) if r.role == "hall"]
    with_facade = [i for i in ids if exterior_walls(plan, i)]
    if not with_facade:
        return -1
    boxes = [r.bounds for r in plan.rooms]
    cx = (min(b[0] for b in boxes) + max(b[2] for b in boxes)) / 2
    cy = (min(b[1] for b in boxes) + max(b[3] for b in boxes)) / 2

    def off_centre(i: int) -> float:
        x0, y0, x1, y1 = plan.rooms[i].bounds
        return abs((x0 + x1) / 2 - cx) + abs((y0 + y1) / 2 - cy)

    lobby = min(with_facade, key=off_centre)
    plan.rooms[lobby].role = "lobby"
    return lobby


def add_entrances(
    plan: Plan, rng: np.random.Generator, lobby: int, style: TypeStyle, model: BuildingTypeModel
) -> None:
    """The main entrance in the lobby (or at a corridor end), side doors in halls, exits at corridor ends.

    Other halls on the facade get a side door with the probability that makes their share of
    doors to the outside the model's.
    """
    placed = False
    p_side = min(1.0, model.connection(H, OUTSIDE) * model.stats(H).doors_mean)
    for i, r in enumerate(plan.rooms):
        if r.role not in ("lobby", "hall") or (i != lobby and rng.random() >= p_side):
            continue
        placed |= add_exterior_door(plan, i, RULES.entrance if i == lobby else RULES.exit)
    for i, r in enumerate(plan.rooms):
        if r.role != "corridor" or (placed and rng.random() >= style.exit_p):
            continue
        x0, y0, x1, y1 = r.rects[0]
        across = "v" if (x1 - x0) >= (y1 - y0) else "h"
        placed |= add_exterior_door(plan, i, RULES.exit, axis=across, margin=RULES.open_margin)
    if not placed:
        order = sorted(
            range(len(plan.rooms)),
            key=lambda i: (not plan.rooms[i].is_circulation, plan.rooms[i].role == "annex"),
        )
        any(add_exterior_door(plan, i, RULES.room) for i in order)
