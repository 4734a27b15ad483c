"""The house's doors: the front door, the day rooms among themselves, every night room to the hallway."""

from __future__ import annotations

import itertools
from typing import TYPE_CHECKING

from realistic_indoor.building.labels import OUTSIDE
from realistic_indoor.errors import RealisticIndoorError
from realistic_indoor.generator.connect import ensure_reachable
from realistic_indoor.generator.doors import RULES, add_door, door_fits, open_between
from realistic_indoor.generator.geometry import Contact
from realistic_indoor.generator.plan import B, M, S

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.plan import Plan
    from realistic_indoor.models.building_model import BuildingTypeModel

__all__ = ["add_doors"]

P_DAY_ROOM_TO_HALLWAY = 0.5
"""Chance that a day room beside the hallway, other than the living room, also opens onto it."""
ROOM_DOOR_WALL = RULES.needed(RULES.room)
"""Shortest wall a room door fits on, its clearances included (units)."""
MAZE_ROOMS = 3
"""Rooms reached through one another alone that make a room maze (the validator's definition)."""


def add_doors(plan: Plan, rng: np.random.Generator, model: BuildingTypeModel, size: tuple[int, int]) -> None:
    """Front door, entrance to hallway, the day rooms' doors, the night rooms' doors, then reachability.

    Every night room touches the hallway along its whole width and the day rooms form a
    sequence from the living room with a back door where needed, so no group of rooms is
    reached only through one another (a room maze).

    The model gives the chance of an en-suite bathroom (its small rooms' connections to medium
    and big rooms) and of a garden door from a living room.

    Args:
        plan: The plan with every room of the house, no door yet.
        rng: Random source.
        model: The building-type model.
        size: Width and depth of the house's rectangular footprint (units), its south-west
            corner at the origin.

    Raises:
        RealisticIndoorError: If the entrance has no wall for the front door (a layout bug).
    """
    entrance = _role(plan, "lobby")[0]
    if not _front_door(plan, entrance, size):
        raise RealisticIndoorError(
            "house layout without a wall for the front door (a bug: please report the seed)"
        )
    hallway = _role(plan, "corridor")[0]
    open_between(plan, entrance, hallway)
    _day_doors(plan, rng, model, size, entrance, hallway)
    _night_doors(plan, rng, model, hallway)
    ensure_reachable(plan, rng)


def _facades(plan: Plan, i: int, size: tuple[int, int]) -> list[Contact]:
    """The sides of rectangular room ``i`` on the footprint's outline, longest first.

    The footprint is the rectangle ``(0, 0, *size)``, so a side on its edge faces outside (what
    :func:`~realistic_indoor.generator.doors.exterior_walls` finds for any plan, much faster).
    """
    (x0, y0, x1, y1), width, depth = plan.rooms[i].rects[0], *size
    sides = [("h", y0, x0, x1, y0 == 0), ("h", y1, x0, x1, y1 == depth), ("v", x0, y0, y1, x0 == 0)]
    sides.append(("v", x1, y0, y1, x1 == width))
    return sorted((Contact(a, c, lo, hi) for a, c, lo, hi, out in sides if out), key=lambda w: (-w.length, w))


def _front_door(plan: Plan, entrance: int, size: tuple[int, int]) -> bool:
    """The front door, as wide as an exit door where the facade allows, at the middle of the entrance's facade."""
    for w in _facades(plan, entrance, size):
        width = min(RULES.exit, w.length - 2 * RULES.margin)
        if width >= RULES.room and add_door(plan, entrance, None, w, width, where="centre"):
            return True
    return False


def _role(plan: Plan, role: str) -> list[int]:
    return [i for i, r in enumerate(plan.rooms) if r.role == role]


def _day_doors(
    plan: Plan,
    rng: np.random.Generator,
    model: BuildingTypeModel,
    size: tuple[int, int],
    entrance: int,
    hallway: int,
) -> None:
    """The living room to the entrance, each day room to the next, some to the hallway, garden doors.

    The day rooms lie in the order they were laid out (living rooms, dining rooms, kitchen),
    each beside the one before, so they form an open sequence ending at the kitchen. Where
    three or more of them are reached through the living room alone, the kitchen gets a back
    door (else they would be a room maze).
    """
    day = [i for i, r in enumerate(plan.rooms) if r.role in ("living", "kitchen")]
    if not _door(plan, rng, day[0], entrance):
        _door(plan, rng, day[0], hallway)
    for a, b in itertools.pairwise(day):
        _door(plan, rng, b, a)
    for i in day[1:]:
        if rng.random() < P_DAY_ROOM_TO_HALLWAY:
            _door(plan, rng, i, hallway)
    p_garden = min(1.0, model.connection(B, OUTSIDE) * model.stats(B).doors_mean)
    for i in day:
        if plan.rooms[i].role == "living" and rng.random() < p_garden:
            _outside(plan, rng, i, size)
    gateways = {d.a for d in plan.doors if d.a in day and (d.b is None or plan.rooms[d.b].is_circulation)}
    gateways |= {d.b for d in plan.doors if d.b in day and plan.rooms[d.a].is_circulation}
    if len(day) >= MAZE_ROOMS and len(gateways) <= 1:
        _outside(plan, rng, next(i for i in reversed(day) if i not in gateways), size)


def _outside(plan: Plan, rng: np.random.Generator, i: int, size: tuple[int, int]) -> bool:
    """A room door from room ``i`` to the outside on its longest facade that takes one."""
    return any(
        add_door(plan, i, None, w, RULES.room, rng)
        for w in _facades(plan, i, size)
        if door_fits(w, RULES.room)
    )


def _night_doors(plan: Plan, rng: np.random.Generator, model: BuildingTypeModel, hallway: int) -> None:
    """A door from every night room to the hallway, but for en-suite bathrooms.

    A bathroom beside a bedroom opens into it alone (en suite) with the model's chance, once
    another bathroom opens onto the hallway (a bathroom is always reachable without crossing a
    bedroom), and into a bedroom that has no en-suite bathroom yet.
    """
    p_ensuite = model.connection(S, M.value) + model.connection(S, B.value)
    public_bath = False
    suites: set[int] = set()
    for i, r in enumerate(plan.rooms):
        if r.role != "room":
            continue
        if r.function == "bathroom" and public_bath and rng.random() < p_ensuite:
            bedrooms = [
                j
                for j, o in enumerate(plan.rooms)
                if o.function == "bedroom" and j not in suites and plan.shared(i, j)
            ]
            if bedrooms and _door(plan, rng, i, bedrooms[0]):
                suites.add(bedrooms[0])
                continue
        if _door(plan, rng, i, hallway) and r.function == "bathroom":
            public_bath = True


def _door(plan: Plan, rng: np.random.Generator, i: int, j: int) -> bool:
    """A room door between rooms ``i`` and ``j``, on the longest shared wall it fits (``False``: none fits)."""
    walls = [w for w in plan.shared(i, j) if w.length >= ROOM_DOOR_WALL]
    if len(walls) > 1:
        walls.sort(key=lambda w: -w.length)
    return any(add_door(plan, i, j, w, RULES.room, rng, where="end") for w in walls)
