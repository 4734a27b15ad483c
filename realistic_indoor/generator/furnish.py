"""Rooms, doors and functions for painted regions: the part the wing and block layouts share.

A layout paints its footprint into :class:`~realistic_indoor.generator.wings.paint.Regions`
(corridor pieces, halls, strips of rooms, end rooms, courtyards);
:func:`rooms_from_regions` cuts the strips into rooms and the corridors into segments, and
:func:`connect_and_name` adds the doors (circulation, entrances, rooms, reachability, no
mazes) and the functions.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from realistic_indoor.building.labels import OUTSIDE
from realistic_indoor.generator.connect import (
    break_mazes,
    connect_circulation,
    connect_rooms,
    ensure_reachable,
)
from realistic_indoor.generator.doors import RULES, add_exterior_door, door_fits, exterior_walls
from realistic_indoor.generator.functions import FunctionRoles, assign_functions
from realistic_indoor.generator.geometry import Rect, area_to_units, to_units
from realistic_indoor.generator.plan import B, C, H, M, Plan, PlanRoom, S
from realistic_indoor.generator.wings.bays import DOOR_NEED, BayContext, subdivide
from realistic_indoor.generator.wings.budget import building_budget
from realistic_indoor.generator.wings.corridors import corridor_fronts, segment_corridors
from realistic_indoor.generator.wings.halls import carve_hall_bays
from realistic_indoor.generator.wings.sizing import Dims

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.wings.paint import Regions
    from realistic_indoor.generator.wings.style import WingStyle
    from realistic_indoor.models.building_model import BuildingTypeModel

__all__ = ["connect_and_name", "layout_dims", "make_suites", "rooms_from_regions"]


def rooms_from_regions(
    regions: Regions,
    rng: np.random.Generator,
    model: BuildingTypeModel,
    style: WingStyle,
    dims: Dims,
    hall_rooms: bool = True,
    corridor_cuts: float | None = None,
    max_axes_ratio: float = math.inf,
    widen_last_room: bool = False,
    placed_small: float = 0.0,
) -> Plan:
    """Halls, rooms cut from the strips, end rooms and corridor segments of painted regions.

    With ``hall_rooms``, large halls get a strip of rooms along a side (see
    :func:`~realistic_indoor.generator.wings.halls.carve_hall_bays`); ``corridor_cuts``
    overrides the style's share of corridor segments to cut; rooms are at least a strip's depth
    over ``max_axes_ratio`` wide; ``widen_last_room``: see
    :class:`~realistic_indoor.generator.wings.bays.BayContext`; ``placed_small``: small rooms
    the building gets besides these (see :func:`~realistic_indoor.generator.wings.budget.building_budget`).
    """
    if hall_rooms:
        carve_hall_bays(regions, rng, round(dims.depth * rng.uniform(0.8, 1.0)), style.hall_rooms_p)
    plan = Plan(exterior_holes=regions.holes)
    for _, rects in regions.halls:
        plan.add(PlanRoom(rects, H, role="hall"))
    circulation = regions.corridors + [r for _, rects in regions.halls for r in rects]
    stub = to_units(rng.uniform(1.3, 1.6))
    limit = (dims.depth + dims.shallow) // 2
    budget = building_budget(regions, model, stub, style.core_rooms, limit, placed_small)
    ctx = BayContext(
        model, budget, circulation, stub, style.core_rooms, limit, max_axes_ratio, widen_last_room
    )
    for k in rng.permutation(len(regions.bays)):
        subdivide(plan, regions.bays[int(k)], rng, ctx)
    for rect in regions.ends:
        plan.add(PlanRoom([rect], S, role="end"))
    cuts = style.corridor_cuts if corridor_cuts is None else corridor_cuts
    _corridors(plan, regions, model, rng, dims, cuts)
    return plan


def make_suites(plan: Plan, rng: np.random.Generator, share: float) -> None:
    """Make about ``share`` of the medium and big rooms inner rooms of a neighbour (a suite).

    An inner room's only door leads into its host, a medium or big room that keeps its own door
    to the corridor (an office with a meeting room behind it, a manager's office behind a
    secretary's). Real plans have such rooms; a generator that gives every room its own
    corridor door has too many rooms with two doors and too few reached through another room.
    """
    rooms = [i for i, r in enumerate(plan.rooms) if r.label in (M, B) and r.role == "room" and r.host < 0]
    ordinary = set(rooms)
    want = int(share * len(rooms) + rng.random())
    neighbours = plan.neighbours()
    hosts: set[int] = set()
    for k in rng.permutation(len(rooms)):
        if want <= 0:
            break
        j = rooms[int(k)]
        if j in hosts:
            continue
        mates = [
            i
            for i in neighbours[j]
            if i in ordinary and i not in hosts and plan.rooms[i].host < 0 and _door_wall(plan, i, j)
        ]
        if mates:
            host = mates[int(rng.integers(len(mates)))]
            plan.rooms[j].host, plan.rooms[j].role = host, "back"
            hosts.add(host)
            want -= 1


def _door_wall(plan: Plan, i: int, j: int) -> bool:
    """Whether rooms ``i`` and ``j`` share a wall a room door fits in."""
    return any(door_fits(w, RULES.room) for w in plan.shared(i, j))


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
    _entrances(plan, rng, _lobby(plan), style, model)
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


def _lobby(plan: Plan) -> int:
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


def _corridors(
    plan: Plan,
    regions: Regions,
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


def _entrances(
    plan: Plan, rng: np.random.Generator, lobby: int, style: WingStyle, model: BuildingTypeModel
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


def _clamp(v: float, lo_hi: tuple[float, float]) -> float:
    return min(max(v, lo_hi[0]), lo_hi[1])


def layout_dims(rng: np.random.Generator, model: BuildingTypeModel, style: WingStyle) -> Dims:
    """Corridor width and room depths from the model's corridors, medium and small rooms.

    A corridor of mean area ``a`` and axes ratio ``r`` is ``sqrt(a / r)`` wide; a strip of rooms
    is as deep as a square medium room, ``sqrt(a)`` (a strip of small rooms likewise); the
    style keeps both within the type's usual ranges.
    """
    c, m, s, h = (model.stats(lab) for lab in (C, M, S, H))
    corridor = _clamp(
        style.corridor_scale * math.sqrt(c.area_mean / max(c.axes_ratio_mean, 1.0)), style.corridor_width_m
    )
    depth = _clamp(style.depth_scale * math.sqrt(m.area_mean), style.room_depth_m)
    shallow = _clamp(math.sqrt(s.area_mean), style.shallow_depth_m)
    return Dims(
        corridor=to_units(corridor * rng.uniform(0.9, 1.1)),
        depth=to_units(depth * rng.uniform(0.92, 1.08)),
        shallow=to_units(shallow),
        hall_area=round(area_to_units(h.area_mean)),
    )
