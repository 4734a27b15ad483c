"""Doors of a generated plan: openings between circulation spaces, room doors, reachability.

Ordinary rooms open onto a corridor or a hall, chosen with the model's connection frequencies;
closets and core rooms open into the room or short corridor they belong to; extra doors bring
each label's mean door count to the model's (a second door to the corridor, a connecting door
between two neighbouring rooms that both have their own, or a door to the garden). A last pass
makes sure every room is reachable from outside.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from realistic_indoor.building.labels import OUTSIDE, ROOM_LABELS, SemanticLabel
from realistic_indoor.errors import RealisticIndoorError
from realistic_indoor.generator.doors import RULES, add_door, door_fits, exterior_walls, open_between
from realistic_indoor.generator.plan import C, H

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.plan import Plan
    from realistic_indoor.models.building_model import BuildingTypeModel

__all__ = ["break_mazes", "connect_circulation", "connect_rooms", "door_habit_scale", "ensure_reachable"]


def connect_circulation(plan: Plan, only: set[int] | None = None) -> None:
    """Open every pair of touching corridors and halls into each other.

    Args:
        plan: The plan.
        only: If given, just the pairs with a room in this set that no door joins yet.
    """
    joined = {frozenset((d.a, d.b)) for d in plan.doors} if only is not None else set()
    for i, j in sorted(plan.contacts()):
        if not (plan.rooms[i].is_circulation and plan.rooms[j].is_circulation):
            continue
        if only is None or ((i in only or j in only) and frozenset((i, j)) not in joined):
            open_between(plan, i, j)


def _door_to(plan: Plan, i: int, j: int, rng: np.random.Generator, width: int, where: str = "end") -> bool:
    walls = [w for w in plan.shared(i, j) if door_fits(w, width)]
    walls.sort(key=lambda w: -w.length)
    return any(add_door(plan, i, j, w, width, rng, where=where) for w in walls)


def connect_rooms(
    plan: Plan,
    model: BuildingTypeModel,
    rng: np.random.Generator,
    pairs: float,
    only: set[int] | None = None,
    per_room: int = 1,
    scale: float = 1.0,
) -> None:
    """Doors of every room that is not a corridor or hall.

    Args:
        plan: The plan, circulation already connected.
        model: Connection frequencies and mean door counts per label.
        rng: Random source.
        pairs: Share of medium and big rooms to give a connecting door to a neighbour.
        only: If given, just these rooms get doors (the others keep theirs).
        per_room: Most second doors one room may get while bringing its label's mean door
            count to the model's: 1 spreads them over many rooms, more gathers them in fewer
            (real plans have most rooms with one door and a few with several).
        scale: Factor on each label's further doors per room: the building's habit (see
            :func:`door_habit_scale`).
    """
    chosen = set(range(len(plan.rooms))) if only is None else only
    neighbours = plan.neighbours()
    options = [_circulation_options(plan, i, neighbours[i]) for i in range(len(plan.rooms))]
    p_hall = _hall_preference(plan, options, model, chosen)
    for i, room in enumerate(plan.rooms):
        if room.is_circulation or i not in chosen:
            continue
        if room.host >= 0 and _door_to(plan, i, room.host, rng, RULES.room):
            continue
        _primary_door(plan, i, options[i], p_hall[room.label], rng)
    _connecting_doors(plan, neighbours, rng, pairs, chosen)
    _extra_doors(plan, neighbours, model, rng, chosen, per_room, scale)


def _circulation_options(plan: Plan, i: int, near: list[int]) -> dict[SemanticLabel, list[int]]:
    """Corridors and halls room ``i`` shares enough wall with for a door."""
    out: dict[SemanticLabel, list[int]] = {C: [], H: []}
    if plan.rooms[i].is_circulation:
        return out
    for j in near:
        lab = plan.rooms[j].label
        if lab in out and any(door_fits(w, RULES.room) for w in plan.shared(i, j)):
            out[lab].append(j)
    return out


def _hall_preference(
    plan: Plan, options: list[dict[SemanticLabel, list[int]]], model: BuildingTypeModel, chosen: set[int]
) -> dict[SemanticLabel, float]:
    """Probability that a room beside both a corridor and a hall opens onto the hall.

    Chosen per label so that the share of its doors that lead to halls is the model's: the
    model's share divided by the share of rooms that could open onto a hall at all.
    """
    out = {}
    for label in ROOM_LABELS:
        rooms = [k for k, r in enumerate(plan.rooms) if r.label is label and r.host < 0 and k in chosen]
        beside = sum(1 for k in rooms if options[k][H])
        to_c, to_h = model.connection(label, C.value), model.connection(label, H.value)
        wanted = to_h / (to_c + to_h) if to_c + to_h > 0 else 0.0
        out[label] = min(1.0, wanted * len(rooms) / beside) if beside else 0.0
    return out


def _primary_door(
    plan: Plan, i: int, options: dict[SemanticLabel, list[int]], p_hall: float, rng: np.random.Generator
) -> None:
    """The room's door to a corridor or a hall (``p_hall``: chance of the hall when both are there)."""
    kinds = [k for k in (C, H) if options[k]]
    if len(kinds) == 2:
        kinds = [H, C] if rng.random() < p_hall else [C, H]
    for kind in kinds:
        j = max(options[kind], key=lambda n: max(x.length for x in plan.shared(i, n)))
        if _door_to(plan, i, j, rng, RULES.room):
            return
    plan.rooms[i].role = "back" if plan.rooms[i].role == "room" else plan.rooms[i].role


def _connecting_doors(
    plan: Plan, neighbours: list[list[int]], rng: np.random.Generator, share: float, chosen: set[int]
) -> None:
    """Connecting doors between neighbouring medium/big rooms that each have a door of their own."""
    big = [
        i
        for i, r in enumerate(plan.rooms)
        if r.label in (SemanticLabel.MEDIUM, SemanticLabel.BIG) and i in chosen
    ]
    if not big:
        return
    used: set[int] = set()
    want = int(share * len(big) / 2 + rng.random())
    for k in rng.permutation(len(big)):
        if want <= 0:
            break
        i = big[int(k)]
        if i in used or plan.rooms[i].role != "room":
            continue
        mates = [j for j in neighbours[i] if j in big and j not in used and plan.rooms[j].role == "room"]
        for j in rng.permutation(mates) if mates else ():
            if _door_to(plan, i, int(j), rng, RULES.room):
                used |= {i, int(j)}
                want -= 1
                break


def door_habit_scale(model: BuildingTypeModel, rng: np.random.Generator) -> float:
    """One building's factor on further doors per room, drawn from the model's door habits.

    1 (and nothing drawn) for a model without habits; else the drawn rate of further doors per
    ordinary room over the model's pooled rate.
    """
    if model.door_habits.mean_rate <= 0:
        return 1.0
    rate = model.door_habits.draw(rng)
    shares = model.shares()
    pooled = sum(shares[lab] * max(model.stats(lab).doors_mean - 1.0, 0.0) for lab in ROOM_LABELS)
    pooled /= max(sum(shares[lab] for lab in ROOM_LABELS), 1e-9)
    return rate / pooled if pooled > 0 else 0.0


def _extra_doors(
    plan: Plan,
    neighbours: list[list[int]],
    model: BuildingTypeModel,
    rng: np.random.Generator,
    chosen: set[int],
    per_room: int = 1,
    scale: float = 1.0,
) -> None:
    """Further doors (to circulation or outside) until each label's mean door count is the model's.

    ``scale`` multiplies each label's further doors per room (the building's habit, see
    :class:`~realistic_indoor.models.building_model.DoorHabits`).
    """
    counts = plan.door_count()
    for label in ROOM_LABELS:
        rooms = [i for i, r in enumerate(plan.rooms) if r.label is label and r.role == "room" and i in chosen]
        if not rooms:
            continue
        everyone = [i for i, r in enumerate(plan.rooms) if r.label is label and i in chosen]
        mean = model.stats(label).doors_mean
        wanted = mean if scale == 1.0 else 1.0 + scale * (mean - 1.0)
        deficit = wanted * len(everyone) - sum(counts[i] for i in everyone)
        rooms.sort(key=lambda i: -plan.rooms[i].area - rng.random())
        p_out = model.connection(label, OUTSIDE)
        for i in rooms:
            if deficit < 0.5 and rng.random() > deficit:
                break
            for _ in range(per_room):
                if deficit <= 0 or not _one_more_door(
                    plan, i, neighbours[i], rng, outside=rng.random() < p_out
                ):
                    break
                deficit -= 1


def _one_more_door(plan: Plan, i: int, near: list[int], rng: np.random.Generator, outside: bool) -> bool:
    if outside:
        for w in exterior_walls(plan, i):
            if door_fits(w, RULES.room) and add_door(plan, i, None, w, RULES.room, rng):
                return True
    circ = [j for j in near if plan.rooms[j].is_circulation]
    circ.sort(key=lambda j: -max(w.length for w in plan.shared(i, j)))
    return any(_door_to(plan, i, j, rng, RULES.room) for j in circ)


def ensure_reachable(plan: Plan, rng: np.random.Generator) -> None:
    """Add doors until every room can be reached from an exterior door.

    An unreachable room gets a door to a reachable neighbour, circulation first.

    Raises:
        RealisticIndoorError: If some room shares no wall long enough for a door with any
            reachable room (a layout bug, never expected).
    """
    while True:
        seen = plan.reachable()
        lost = [i for i, s in enumerate(seen) if not s]
        if not lost:
            return
        neighbours = plan.neighbours()
        progress = False
        for i in lost:
            near = [j for j in neighbours[i] if seen[j]]
            near.sort(key=lambda j: (not plan.rooms[j].is_circulation, plan.rooms[j].label in ROOM_LABELS))
            for j in near:
                width = RULES.room
                if plan.rooms[i].is_circulation and plan.rooms[j].is_circulation:
                    if open_between(plan, i, j):
                        progress = True
                        break
                elif _door_to(plan, i, j, rng, width, where="centre"):
                    progress = True
                    break
            if progress:
                break
        if not progress:
            raise RealisticIndoorError(
                f"generator could not reach {len(lost)} rooms (a bug: please report the seed)"
            )


def break_mazes(plan: Plan, rng: np.random.Generator, min_rooms: int = 3) -> None:
    """Give room mazes a second way out.

    A maze is a group of at least ``min_rooms`` ordinary rooms joined by doors among themselves
    of which at most one opens onto a corridor, a hall or outside (the validator's definition);
    one of its other rooms gets a door to a corridor or hall it touches, else to the outside.
    A room entered through its host (a gym's changing rooms and stores, a closet) gets no
    door to the outside: real plans have none there, so a suite of a big room and its service
    rooms that touch no corridor stays as it is.
    """
    ordinary = [i for i, r in enumerate(plan.rooms) if r.label in ROOM_LABELS]
    group = {i: i for i in ordinary}

    def find(i: int) -> int:
        while group[i] != i:
            group[i] = group[group[i]]
            i = group[i]
        return i

    gateway = set()
    for d in plan.doors:
        if d.b is not None and d.a in group and d.b in group:
            group[find(d.a)] = find(d.b)
        for i, j in ((d.a, d.b), (d.b, d.a)):
            if i in group and (j is None or plan.rooms[j].is_circulation):
                gateway.add(i)
    members: dict[int, list[int]] = {}
    for i in ordinary:
        members.setdefault(find(i), []).append(i)
    neighbours = plan.neighbours()
    for rooms in members.values():
        if len(rooms) < min_rooms or sum(i in gateway for i in rooms) > 1:
            continue
        for i in (i for i in rooms if i not in gateway):
            circ = [j for j in neighbours[i] if plan.rooms[j].is_circulation]
            if any(_door_to(plan, i, j, rng, RULES.room) for j in circ) or (
                plan.rooms[i].host < 0
                and any(
                    add_door(plan, i, None, w, RULES.room, rng)
                    for w in exterior_walls(plan, i)
                    if door_fits(w, RULES.room)
                )
            ):
                break
