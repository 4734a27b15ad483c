"""Realistic houses: a day zone (kitchen, living room, entrance or hall) beside a night zone.

The night zone is one or more strips, each a hallway with bedrooms, bathrooms and closets on
both sides; the day zone is a column with the kitchen and the living or dining room, and an
entrance (a short corridor) or a hall between it and the night zone, which every hallway
starts from. The program (how many rooms of each label) is drawn from the model's label shares
for the requested area, sizes from its areas.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, ClassVar

from realistic_indoor.building.labels import SemanticLabel
from realistic_indoor.errors import RealisticIndoorError
from realistic_indoor.generator.base import DEFAULT_AREAS_M2, check_area, finish
from realistic_indoor.generator.connect import break_mazes, connect_circulation, ensure_reachable
from realistic_indoor.generator.doors import RULES, add_door, add_exterior_door, door_fits, exterior_walls
from realistic_indoor.generator.functions import draw_function
from realistic_indoor.generator.geometry import Rect, area_to_units, to_units
from realistic_indoor.generator.plan import B, C, H, M, Plan, PlanRoom, S
from realistic_indoor.generator.typed import model_params
from realistic_indoor.generator.wings.bays import DOOR_NEED
from realistic_indoor.generator.wings.corridors import corridor_fronts, segment_corridors
from realistic_indoor.models.building_model import OUTSIDE, BuildingTypeModel, default_model

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.building.building import Building

__all__ = ["HouseGenerator"]

MIN_AREA_M2, MAX_AREA_M2 = 50.0, 1000.0
BAND_M = (2.8, 4.2)
"""Depth of the room bands on either side of a hallway (m)."""
ASPECT = (1.0, 1.5)
"""Range of the drawn length-to-depth ratio a house's strips are chosen for."""
MIN_WIDTH = to_units(1.6)
"""Narrowest room along a hallway, so that its door fits (units)."""


@dataclass
class Program:
    """What a house holds: its day rooms and the rooms along its hallways.

    Attributes:
        hall: Area of the hall (m2), 0 for a house entered through a short corridor.
        kitchen: Area of the kitchen (m2).
        living: Labels and areas of the living and dining rooms (m2).
        night: Label, function and area (m2) of every room on a hallway.
        hallways: Number of corridor segments along the hallways.
    """

    hall: float
    kitchen: float
    living: list[tuple[SemanticLabel, str, float]] = field(default_factory=list)
    night: list[tuple[SemanticLabel, str, float]] = field(default_factory=list)
    hallways: int = 1


def _count(rng: np.random.Generator, expected: float) -> int:
    """A whole number with the given expectation (stochastic rounding)."""
    return int(expected + rng.random())


def _program(rng: np.random.Generator, area_m2: float, model: BuildingTypeModel) -> Program:
    """Rooms drawn from the model for a house of ``area_m2``.

    The kitchen, a bathroom and a living room (or a hall) come first; further night rooms are
    drawn one at a time, each with the label furthest behind its share of the model, until the
    rooms and corridors fill the area.
    """
    shares = model.shares()
    stats = {lab: model.stats(lab) for lab in SemanticLabel}
    n = area_m2 / model.mean_room_area()
    has_hall = area_m2 > 400 or rng.random() < min(1.0, shares[H] * n)
    hall = stats[H].sample_area(rng, 0.8 * stats[H].area_mean, 2.0 * stats[H].area_mean) if has_hall else 0.0
    hall = min(hall, 0.55 * area_m2)
    prog = Program(hall=hall, kitchen=stats[M].sample_area(rng, 8.0, 2.0 * stats[M].area_mean))
    if not has_hall:
        prog.living.append((B, "living room", stats[B].sample_area(rng, 12.0, 2.0 * stats[B].area_mean)))
    prog.night.append((S, "bathroom", stats[S].sample_area(rng, 3.0, 2.0 * stats[S].area_mean)))
    counts = {S: 1, M: 1, B: 0 if has_hall else 1}
    n_c = max(1, _count(rng, shares[C] * n))
    prog.hallways = max(1, n_c - 1)
    corridors = shares[C] * n * stats[C].area_mean
    _fit_mandatory(prog, 0.85 * area_m2 - corridors)
    used = prog.hall + prog.kitchen + sum(a for *_, a in prog.living + prog.night) + corridors
    while used < area_m2 - 0.5 * stats[M].area_mean or counts[M] < 2:
        label = max((S, M, B), key=lambda lab: shares[lab] * n - counts[lab] + 0.3 * rng.random())
        label = M if counts[M] < 2 else label
        a = stats[label].sample_area(rng, 0.5 * stats[label].area_mean, 2.0 * stats[label].area_mean)
        weights = model.function_weights(label)
        avoid = ("kitchen", "living room", "dining room") if label is not B or counts[B] else ("kitchen",)
        function = draw_function(rng, weights, avoid=avoid)
        if label is M and not any(f == "bedroom" for _, f, _ in prog.night):
            function = "bedroom"
        (prog.living if function in ("living room", "dining room") else prog.night).append(
            (label, function, a)
        )
        counts[label] += 1
        used += a
    order = rng.permutation(len(prog.night))
    prog.night = [prog.night[int(k)] for k in order]
    return prog


def _fit_mandatory(prog: Program, room: float) -> None:
    """Shrink the first rooms of a small house together so that they fit in ``room`` (m2)."""
    total = prog.hall + prog.kitchen + sum(a for *_, a in prog.living + prog.night)
    if total <= room:
        return
    f = max(room, 0.3 * total) / total
    prog.hall *= f
    prog.kitchen *= f
    prog.living = [(lab, fn, a * f) for lab, fn, a in prog.living]
    prog.night = [(lab, fn, a * f) for lab, fn, a in prog.night]


def _split(total: int, weights: list[float], least: int = 0) -> list[int]:
    """Cut ``total`` units into whole pieces in proportion to ``weights``, none under ``least``."""
    if least and total >= least * len(weights):
        scale = total / sum(weights)
        short = [w * scale < least for w in weights]
        rest = total - least * sum(short)
        free = sum(w for w, s in zip(weights, short, strict=True) if not s)
        if free > 0:
            weights = [least if s else w * rest / free for w, s in zip(weights, short, strict=True)]
    edges = [0]
    acc, whole = 0.0, sum(weights)
    for w in weights:
        acc += w
        edges.append(round(total * acc / whole))
    return [edges[k + 1] - edges[k] for k in range(len(weights))]


def _strips(
    rng: np.random.Generator, prog: Program, corridor: int, area_m2: float
) -> list[tuple[int, int, list, list]]:
    """Night rooms dealt to strips (front band depth, back band depth, front rooms, back rooms).

    One strip or two side by side, whichever makes the house's proportions nearer a drawn aspect
    ratio (1.0-1.5: houses are compact); two need four night rooms.
    """
    front_d, back_d = (to_units(rng.uniform(*BAND_M)) for _ in range(2))
    target = rng.uniform(*ASPECT)
    strip = front_d + corridor + back_d

    def miss(n: int) -> float:
        depth = n * strip
        length = area_to_units(area_m2) / depth
        return abs(abs(math.log(length / depth)) - math.log(target))

    n_strips = 2 if len(prog.night) >= 4 and miss(2) < miss(1) else 1
    strips = [[[], []] for _ in range(n_strips)]
    loads = [[0.0, 0.0] for _ in range(n_strips)]
    for room in sorted(prog.night, key=lambda r: -r[2]):
        k, side = min(((k, s) for k in range(n_strips) for s in (0, 1)), key=lambda ks: loads[ks[0]][ks[1]])
        strips[k][side].append(room)
        loads[k][side] += area_to_units(room[2]) / (front_d if side == 0 else back_d)
    for pair in strips:
        _balance(pair)
    return [(front_d if f else 0, back_d if b else 0, f, b) for f, b in strips]


def _balance(pair: list[list]) -> None:
    """Give a band of only small rooms an ordinary room from the other band, else merge the two.

    A band of small rooms alone would stretch them along the whole hallway; a single band makes a
    long, thin house.
    """
    if not (pair[0] and pair[1]):
        return
    small = [all(lab is S for lab, _, _ in side) for side in pair]
    if not any(small):
        return
    poor, rich = (0, 1) if small[0] else (1, 0)
    ordinary = [r for r in pair[rich] if r[0] is not S]
    if len(pair[rich]) >= 2 and ordinary and not small[rich]:
        room = min(ordinary, key=lambda r: r[2])
        pair[rich].remove(room)
        pair[poor].append(room)
    else:
        pair[0], pair[1] = pair[0] + pair[1], []


def _house_plan(rng: np.random.Generator, area_m2: float, model: BuildingTypeModel) -> Plan:
    prog = _program(rng, area_m2, model)
    c_stats = model.stats(C)
    corridor = to_units(min(max(math.sqrt(c_stats.area_mean / max(c_stats.axes_ratio_mean, 1.0)), 1.1), 1.8))
    entry_w = to_units(rng.uniform(2.2, 3.2))
    while True:
        strips = _strips(rng, prog, corridor, area_m2)
        depth = sum(f + corridor + b for f, b, _, _ in strips)
        x_day = sum(_day_columns(prog, depth, entry_w, strips[0][0] + corridor))
        least = max(
            sum(MIN_WIDTH if lab is S else to_units(2.4) for lab, _, _ in rooms)
            for f, b, fr, br in strips
            for rooms in (fr, br)
        )
        spare = area_to_units(area_m2) / depth - least
        if x_day <= spare or not (_drop_night_room(prog) or _shrink_day_zone(prog, spare / x_day)):
            break
    plan = Plan()
    _day_zone(plan, rng, prog, strips[0][0] + corridor, depth, entry_w)
    night_len = max(round(area_to_units(area_m2) / depth) - x_day, least, to_units(3.0))
    hallways = []
    y = 0
    for f, b, fr, br in strips:
        hallways.append((x_day, y + f, x_day + night_len, y + f + corridor))
        _band(plan, fr, (x_day, y, x_day + night_len, y + f), hallway_above=True)
        _band(
            plan, br, (x_day, y + f + corridor, x_day + night_len, y + f + corridor + b), hallway_above=False
        )
        y += f + corridor + b
    fronts = corridor_fronts(plan, hallways)
    segments = segment_corridors(hallways, prog.hallways, rng, 2 * corridor, [], fronts, DOOR_NEED)
    for seg in segments:
        plan.add(PlanRoom([seg], C, function="hallway", role="corridor"))
    return plan


def _drop_night_room(prog: Program) -> bool:
    """Leave out the smallest night room but the bathroom and the last bedroom (``False``: none left)."""
    keep_bedroom = sum(f == "bedroom" for _, f, _ in prog.night) <= 1
    pool = [
        k
        for k, (_, f, _) in enumerate(prog.night)
        if f != "bathroom" and not (keep_bedroom and f == "bedroom")
    ]
    if not pool:
        return False
    del prog.night[min(pool, key=lambda k: prog.night[k][2])]
    return True


def _shrink_day_zone(prog: Program, factor: float) -> bool:
    """Make the day zone fit: drop extra living rooms, then shrink its rooms (``False``: no change)."""
    if len(prog.living) > 1:
        del prog.living[1:]
        return True
    factor = max(factor, 0.5)
    if factor >= 0.98:
        return False
    prog.kitchen = max(prog.kitchen * factor, 7.0)
    prog.hall *= factor
    prog.living = [(lab, f, max(a * factor, 10.0)) for lab, f, a in prog.living]
    return True


def _day_columns(prog: Program, depth: int, entry_w: int, entry_depth: int) -> tuple[int, int]:
    """Widths of the day zone's two columns (kitchen and living rooms; hall or entrance).

    Where the living rooms reach over the entrance, the kitchen is as deep as the entrance and
    column A as wide as the kitchen or the living rooms need, whichever needs more.
    """
    living = area_to_units(sum(a for *_, a in prog.living))
    col_b = max(round(area_to_units(prog.hall) / depth), to_units(3.6)) if prog.hall else entry_w
    if _over_entry(prog, depth, entry_depth):
        col_a = max(area_to_units(prog.kitchen) / entry_depth, living / (depth - entry_depth) - col_b)
    else:
        col_a = (area_to_units(prog.kitchen) + living) / depth
    return max(round(col_a), to_units(2.6)), col_b


def _over_entry(prog: Program, depth: int, entry_depth: int) -> bool:
    """Whether the living rooms reach over the entrance (no hall, deep enough for a room above it)."""
    return not prog.hall and bool(prog.living) and depth - entry_depth >= to_units(2.6)


def _day_zone(
    plan: Plan, rng: np.random.Generator, prog: Program, entry_depth: int, depth: int, entry_w: int
) -> int:
    """Kitchen, living and dining rooms, and the entrance or hall; returns the night zone's start (x).

    Column A holds the kitchen with the living rooms above it (side by side in a shallow house);
    column B, next to the night zone, the hall (entered through a vestibule) or the entrance, with
    the living rooms reaching over the entrance where the house is deep enough.
    """
    living = area_to_units(sum(a for *_, a in prog.living))
    kitchen = area_to_units(prog.kitchen)
    room = to_units(2.6)
    col_a, col_b = _day_columns(prog, depth, entry_w, entry_depth)
    over_b = _over_entry(prog, depth, entry_depth)
    if prog.hall:
        _hall_with_vestibule(plan, rng, (col_a, 0, col_a + col_b, depth))
    else:
        top = entry_depth if over_b else depth
        plan.add(PlanRoom([(col_a, 0, col_a + col_b, top)], C, function="entrance", role="lobby"))
    if not living:
        plan.add(PlanRoom([(0, 0, col_a, depth)], M, function="kitchen", role="kitchen"))
        return col_a + col_b
    if depth < 2 * room:
        xk = (
            min(max(round(col_a * kitchen / (kitchen + living)), room), col_a - room)
            if col_a >= 2 * room
            else col_a // 2
        )
        plan.add(PlanRoom([(0, 0, xk, depth)], M, function="kitchen", role="kitchen"))
        _living(plan, prog, (xk, 0, col_a, depth))
        return col_a + col_b
    ys = entry_depth if over_b else round(depth * kitchen / (kitchen + living))
    ys = min(max(ys, room), depth - room)
    plan.add(PlanRoom([(0, 0, col_a, ys)], M, function="kitchen", role="kitchen"))
    _living(plan, prog, (0, ys, col_a + (col_b if over_b else 0), depth))
    return col_a + col_b


def _living(plan: Plan, prog: Program, box: Rect) -> None:
    x0, y0, x1, y1 = box
    x = x0
    for (label, function, _), w in zip(
        prog.living, _split(x1 - x0, [a for *_, a in prog.living]), strict=True
    ):
        plan.add(PlanRoom([(x, y0, x + w, y1)], label, function=function, role="living"))
        x += w


def _widths(rooms: list, length: int, depth: int) -> list[int]:
    """Widths of rooms along a strip: small rooms as their area needs, the others share the rest."""
    natural = [max(area_to_units(a) / max(depth, 1), MIN_WIDTH) for _, _, a in rooms]
    small = [lab is S for lab, _, _ in rooms]
    if (
        all(small)
        or not any(small)
        or sum(n for n, s in zip(natural, small, strict=True) if s) > 0.6 * length
    ):
        return _split(length, [a for *_, a in rooms], MIN_WIDTH)
    fixed = [round(n) if s else 0 for n, s in zip(natural, small, strict=True)]
    rest = _split(
        length - sum(fixed), [a for (_, _, a), s in zip(rooms, small, strict=True) if not s], MIN_WIDTH
    )
    it = iter(rest)
    return [f if s else next(it) for f, s in zip(fixed, small, strict=True)]


def _hall_with_vestibule(plan: Plan, rng: np.random.Generator, box: Rect) -> None:
    """A hall entered through a vestibule (a short corridor) set into its front side."""
    x0, y0, x1, y1 = box
    w = min(to_units(rng.uniform(2.2, 3.0)), x1 - x0 - to_units(1.2))
    d = to_units(rng.uniform(2.4, 3.4))
    a = x0 + int(rng.integers(0, x1 - x0 - w + 1))
    plan.add(PlanRoom([(a, y0, a + w, y0 + d)], C, function="entrance", role="lobby"))
    rects = [(x0, y0 + d, x1, y1), (x0, y0, a, y0 + d), (a + w, y0, x1, y0 + d)]
    plan.add(PlanRoom([r for r in rects if r[0] < r[2]], H, function="hall", role="hall"))


def _band(plan: Plan, rooms: list, box: Rect, hallway_above: bool) -> None:
    """Rooms side by side along a hallway, widths in proportion to their areas.

    A small room that would come out much deeper than it is wide takes only the part of the
    strip next to the hallway; the room beside it wraps around behind it.
    """
    if not rooms:
        return
    x0, y0, x1, y1 = box
    x = x0
    ids = []
    for (label, function, _), w in zip(rooms, _widths(rooms, x1 - x0, y1 - y0), strict=True):
        ids.append(plan.add(PlanRoom([(x, y0, x + w, y1)], label, function=function, role="room")))
        x += w
    for k, i in enumerate(ids):
        room = plan.rooms[i]
        mates = [ids[m] for m in (k - 1, k + 1) if 0 <= m < len(ids) and plan.rooms[ids[m]].label is not S]
        a, _, b, _ = room.rects[0]
        depth = max(round(area_to_units(rooms[k][2]) / (b - a)), to_units(1.5))
        if room.label is S and mates and depth <= y1 - y0 - to_units(1.2):
            front = (a, y1 - depth, b, y1) if hallway_above else (a, y0, b, y0 + depth)
            back = (a, y0, b, y1 - depth) if hallway_above else (a, y0 + depth, b, y1)
            room.rects = [front]
            plan.rooms[mates[0]].rects.append(back)


def _doors(plan: Plan, rng: np.random.Generator, model: BuildingTypeModel) -> None:
    """Front door, hallway openings, kitchen to living room, room doors, en-suite bathrooms."""
    lobby = next(i for i, r in enumerate(plan.rooms) if r.role == "lobby")
    order = [lobby] + [i for i, r in enumerate(plan.rooms) if r.role in ("hall", "living", "kitchen")]
    if not any(add_exterior_door(plan, i, RULES.exit) for i in order):
        raise RealisticIndoorError(
            "house layout without a wall for the front door (a bug: please report the seed)"
        )
    connect_circulation(plan)
    neighbours = plan.neighbours()
    kitchen = next(i for i, r in enumerate(plan.rooms) if r.role == "kitchen")
    living = [i for i, r in enumerate(plan.rooms) if r.role == "living"]
    centre = next((i for i, r in enumerate(plan.rooms) if r.role == "hall"), lobby)
    gateways = sum(_door(plan, rng, i, centre) for i in living)
    for i in living:
        _door(plan, rng, kitchen, i)
    if not gateways or len(living) > gateways or rng.random() < 0.5:
        _door(plan, rng, kitchen, centre)
    p_garden = min(1.0, model.connection(B, OUTSIDE) * model.stats(B).doors_mean)
    for i in living:
        walls = [w for w in exterior_walls(plan, i) if door_fits(w, RULES.room)]
        if walls and rng.random() < p_garden:
            add_door(plan, i, None, walls[0], RULES.room, rng)
    p_ensuite = model.connection(S, M.value) + model.connection(S, B.value)
    for i, r in enumerate(plan.rooms):
        if r.role != "room":
            continue
        hallway = [j for j in neighbours[i] if plan.rooms[j].label is C]
        bedrooms = [j for j in neighbours[i] if plan.rooms[j].function == "bedroom"]
        if r.label is S and r.function == "bathroom" and bedrooms and rng.random() < p_ensuite:
            _door(plan, rng, i, bedrooms[0])
        elif not any(_door(plan, rng, i, j) for j in hallway):
            _door(plan, rng, i, centre)
    ensure_reachable(plan, rng)
    break_mazes(plan, rng)


def _door(plan: Plan, rng: np.random.Generator, i: int, j: int) -> bool:
    walls = sorted((w for w in plan.shared(i, j) if door_fits(w, RULES.room)), key=lambda w: -w.length)
    return any(add_door(plan, i, j, w, RULES.room, rng, where="end") for w in walls)


@dataclass(frozen=True)
class HouseGenerator:
    """Houses: a hall or short corridors serving bedrooms and bathrooms; living room and kitchen connected.

    Args:
        area_m2: Floor area wanted (m2), from 50 to 1,000 (default 150).
        model: The building-type model (default: the paper's houses).

    Examples:
        >>> import numpy as np
        >>> b = HouseGenerator(area_m2=120)(np.random.default_rng(2))
        >>> round(b.area)
        120
    """

    area_m2: float = DEFAULT_AREAS_M2["house"]
    model: BuildingTypeModel | None = None

    name: ClassVar[str] = "house"

    def __post_init__(self) -> None:
        object.__setattr__(self, "area_m2", check_area("house", self.area_m2, MIN_AREA_M2, MAX_AREA_M2))

    def __call__(self, rng: np.random.Generator) -> Building:
        """A new house of about :attr:`area_m2` drawn with ``rng``."""
        model = self.model if self.model is not None else default_model("house")
        plan = _house_plan(rng, self.area_m2, model)
        _doors(plan, rng, model)
        params = {"area_m2": self.area_m2, **model_params(model, "house")}
        return finish(plan, rng, "house", {"generator": "house", "params": params})
