"""Realistic houses: a day zone (kitchen, living room, entrance or hall) beside a night zone.

The night zone is one or more strips, each a hallway with bedrooms, bathrooms and closets on
both sides; the day zone is a column with the kitchen and the living or dining room, and an
entrance (a short corridor) or a hall between it and the night zone, which every hallway
starts from. Where that makes the house nearer square, it is laid out in two rows instead: the
kitchen, the entrance and the night zone below, the hall and the living rooms across the row
above (a night zone of one band beside the day zone makes a long, thin house). The program
(how many rooms of each label) is drawn from the model's label shares for the requested area,
sizes from its areas.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, ClassVar, NamedTuple

from realistic_indoor.building.labels import OUTSIDE, SemanticLabel
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
from realistic_indoor.models.building_model import BuildingTypeModel, default_model

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.building.building import Building
    from realistic_indoor.models.building_model import LabelStats

__all__ = ["HouseGenerator"]

MIN_AREA_M2, MAX_AREA_M2 = 50.0, 1000.0
"""Floor areas a house may be asked for (m2)."""

# The program: which rooms a house holds, and how large.

ALWAYS_HALL_M2 = 400
"""Floor area above which a house always has a hall (m2); smaller ones have one by chance."""
HALL_MAX_SHARE = 0.55
"""Largest share of the floor area the hall takes."""
FIRST_ROOMS_SHARE = 0.85
"""Share of the floor area (less the corridors) the first rooms must fit in."""
FIRST_ROOMS_MIN_SCALE = 0.3
"""Least factor the first rooms of a small house are shrunk by to fit."""
MIN_MEDIUM_ROOMS = 2
"""Medium rooms every house holds (the kitchen and a bedroom)."""
FILL_SLACK = 0.5
"""Rooms are added until the program is within this many mean medium-room areas of the floor area."""
LABEL_JITTER = 0.3
"""Largest random amount (rooms) added to a label's shortfall when choosing the next room's label."""
LIVING_FUNCTIONS = ("living room", "dining room")
"""Functions of the day zone's living rooms."""
DAY_FUNCTIONS = ("kitchen", *LIVING_FUNCTIONS)
"""Functions of the day zone's rooms."""


class ProgramRoom(NamedTuple):
    """One room of the program.

    Attributes:
        label: Semantic label.
        function: Functional label.
        area_m2: Area wanted (m2).
    """

    label: SemanticLabel
    function: str
    area_m2: float


class AreaRange(NamedTuple):
    """Bounds of a drawn room area, in multiples of the mean area of the room's label.

    Attributes:
        low: Lower bound (times the label's mean area).
        high: Upper bound (times the label's mean area).
    """

    low: float
    high: float

    def draw(self, rng: np.random.Generator, stats: LabelStats) -> float:
        """An area drawn from the label's statistics, clipped to this range (m2)."""
        return stats.sample_area(rng, self.low * stats.area_mean, self.high * stats.area_mean)


class FirstRoom(NamedTuple):
    """A room the program starts with, and the bounds of its drawn area.

    Attributes:
        label: Semantic label.
        function: Functional label.
        min_m2: Least area drawn (m2).
        max_x_mean: Largest area drawn (times the label's mean area).
    """

    label: SemanticLabel
    function: str
    min_m2: float
    max_x_mean: float

    def draw(self, rng: np.random.Generator, model: BuildingTypeModel) -> ProgramRoom:
        """This room with an area drawn from the model's statistics of its label."""
        stats = model.stats(self.label)
        return ProgramRoom(
            self.label, self.function, stats.sample_area(rng, self.min_m2, self.max_x_mean * stats.area_mean)
        )


HALL_AREA = AreaRange(0.8, 2.0)
"""Bounds of the hall's area (times the mean hall area)."""
ROOM_AREA = AreaRange(0.5, 2.0)
"""Bounds of the area of every room added after the first ones (times its label's mean area)."""
KITCHEN = FirstRoom(M, "kitchen", 8.0, 2.0)
"""The kitchen: from 8 m2 to twice the mean medium-room area."""
LIVING_ROOM = FirstRoom(B, "living room", 12.0, 2.0)
"""The living room of a house without a hall: from 12 m2 to twice the mean big-room area."""
BATHROOM = FirstRoom(S, "bathroom", 3.0, 2.0)
"""The first bathroom: from 3 m2 to twice the mean small-room area."""

# The night zone: strips of a hallway between two bands of rooms.

BAND_M = (2.8, 4.2)
"""Depth of the room bands on either side of a hallway (m)."""
ASPECT = (1.0, 1.5)
"""Range of the drawn length-to-depth ratio a house's strips are chosen for."""
MIN_STRIP_ROOMS = 2
"""Fewest night rooms per strip where there are several; more than two strips need a hall."""
HALLWAY_WIDTH_M = (1.1, 1.8)
"""Narrowest and widest hallway (m); between them, the width of the model's mean corridor."""
MIN_WIDTH = to_units(1.6)
"""Narrowest room along a hallway, so that its door fits (units)."""
MIN_ORDINARY_WIDTH = to_units(2.4)
"""Narrowest room along a hallway other than a small one, when fitting the night zone (units)."""
MIN_NIGHT_LENGTH = to_units(3.0)
"""Shortest night zone along its hallways (units)."""
SMALL_ROOMS_MAX_SHARE = 0.6
"""Largest share of a band's length its small rooms take at the width their area needs."""
MIN_TUCKED_DEPTH = to_units(1.5)
"""Shallowest a small room tucked in next to the hallway is made (units)."""
MIN_WRAP_DEPTH = to_units(1.2)
"""Least depth of the part of a room that wraps around behind a tucked-in small room (units)."""
ROWS_BAND_MAX = to_units(5.0)
"""Deepest a band of a two-row house's night zone is made for its largest room (units)."""
MIN_NIGHT_SQUEEZE = 0.7
"""Least share of its natural length a two-row house's night zone is squeezed to, so that the
row above it keeps its rooms in proportion."""
ROWS_SQUEEZE_STEPS = 6
"""Night-zone lengths tried between the natural length and the most squeezed one."""
MAX_DAY_ELONGATION = 3.0
"""Longest a day room is made where the layout can choose, in multiples of its width."""

# The day zone: kitchen and living rooms (column A), hall or entrance (column B).

ENTRANCE_WIDTH_M = (2.2, 3.2)
"""Range of the entrance's drawn width (m)."""
MIN_DAY_ROOM = to_units(2.6)
"""Shortest side of the kitchen and the living rooms, and narrowest column A (units)."""
MIN_HALL_WIDTH = to_units(3.6)
"""Narrowest hall column (units)."""
VESTIBULE_WIDTH_M = (2.2, 3.0)
"""Range of the vestibule's drawn width (m)."""
VESTIBULE_DEPTH_M = (2.4, 3.4)
"""Range of the vestibule's drawn depth (m)."""
MIN_HALL_BESIDE_VESTIBULE = to_units(1.2)
"""Narrowest the hall is beside the vestibule (units)."""
DAY_SHRINK_LEAST = 0.5
"""Least factor the day zone's rooms are shrunk by in one step."""
DAY_SHRINK_NEGLIGIBLE = 0.98
"""A shrinking factor above this leaves the day zone as it is."""
MIN_SHRUNK_KITCHEN_M2 = 7.0
"""Smallest a shrunk kitchen is made (m2)."""
MIN_SHRUNK_LIVING_M2 = 10.0
"""Smallest a shrunk living room is made (m2)."""

# Doors.

P_KITCHEN_TO_CENTRE = 0.5
"""Chance of a door from the kitchen to the hall or entrance where the living rooms already lead there."""


class Strip(NamedTuple):
    """Night rooms along one hallway: a band in front of it and a band behind it.

    Attributes:
        front_depth: Depth of the front band (units), 0 where it has no rooms.
        back_depth: Depth of the back band (units), 0 where it has no rooms.
        front: Rooms of the front band.
        back: Rooms of the back band.
    """

    front_depth: int
    back_depth: int
    front: list[ProgramRoom]
    back: list[ProgramRoom]


@dataclass
class Program:
    """What a house holds: its day rooms and the rooms along its hallways.

    Attributes:
        hall: Area of the hall (m2), 0 for a house entered through a short corridor.
        kitchen: Area of the kitchen (m2).
        living: The living and dining rooms.
        night: Every room on a hallway.
        hallways: Number of corridor segments along the hallways.
    """

    hall: float
    kitchen: float
    living: list[ProgramRoom] = field(default_factory=list)
    night: list[ProgramRoom] = field(default_factory=list)
    hallways: int = 1


def _count(rng: np.random.Generator, expected: float) -> int:
    """A whole number with the given expectation (stochastic rounding)."""
    return int(expected + rng.random())


def _total(rooms: list[ProgramRoom]) -> float:
    """The rooms' summed area (m2)."""
    return sum(r.area_m2 for r in rooms)


def _program(rng: np.random.Generator, area_m2: float, model: BuildingTypeModel) -> Program:
    """Rooms drawn from the model for a house of ``area_m2``.

    The kitchen, a bathroom and a living room (or a hall) come first; further night rooms are
    drawn one at a time, each with the label furthest behind its share of the model, until the
    rooms and corridors fill the area.
    """
    shares = model.shares()
    n = area_m2 / model.mean_room_area()
    prog = _first_rooms(rng, area_m2, model, n)
    counts = {S: 1, M: 1, B: len(prog.living)}
    n_c = max(1, _count(rng, shares[C] * n))
    prog.hallways = max(1, n_c - 1)
    corridors = shares[C] * n * model.stats(C).area_mean
    _fit_mandatory(prog, FIRST_ROOMS_SHARE * area_m2 - corridors)
    used = prog.hall + prog.kitchen + _total(prog.living + prog.night) + corridors
    wanted = {lab: shares[lab] * n for lab in (S, M, B)}
    while used < area_m2 - FILL_SLACK * model.stats(M).area_mean or counts[M] < MIN_MEDIUM_ROOMS:
        used += _add_room(rng, prog, model, counts, wanted)
    order = rng.permutation(len(prog.night))
    prog.night = [prog.night[int(k)] for k in order]
    return prog


def _first_rooms(rng: np.random.Generator, area_m2: float, model: BuildingTypeModel, n: float) -> Program:
    """The program's first rooms: a hall or a living room, the kitchen and a bathroom.

    Args:
        rng: Random source.
        area_m2: The house's floor area (m2).
        model: The building-type model.
        n: Rooms the house is expected to hold.
    """
    has_hall = area_m2 > ALWAYS_HALL_M2 or rng.random() < min(1.0, model.shares()[H] * n)
    hall = HALL_AREA.draw(rng, model.stats(H)) if has_hall else 0.0
    prog = Program(hall=min(hall, HALL_MAX_SHARE * area_m2), kitchen=KITCHEN.draw(rng, model).area_m2)
    if not has_hall:
        prog.living.append(LIVING_ROOM.draw(rng, model))
    prog.night.append(BATHROOM.draw(rng, model))
    return prog


def _add_room(
    rng: np.random.Generator,
    prog: Program,
    model: BuildingTypeModel,
    counts: dict[SemanticLabel, int],
    wanted: dict[SemanticLabel, float],
) -> float:
    """Add a room with the label furthest behind the rooms ``wanted`` of it; returns its area (m2).

    ``counts`` (rooms of each label so far) is updated. Its function is drawn again where it came
    out a kitchen: the program's kitchen is the only one.
    """
    label = max((S, M, B), key=lambda lab: wanted[lab] - counts[lab] + LABEL_JITTER * rng.random())
    label = M if counts[M] < MIN_MEDIUM_ROOMS else label
    a = ROOM_AREA.draw(rng, model.stats(label))
    avoid = DAY_FUNCTIONS if label is not B or counts[B] else (KITCHEN.function,)
    weights = model.function_weights(label)
    function = draw_function(rng, weights, avoid=avoid)
    if function == KITCHEN.function and len(weights) > 1:  # the house has its kitchen
        function = draw_function(rng, {k: v for k, v in weights.items() if k != function}, avoid=avoid)
    if label is M and not any(r.function == "bedroom" for r in prog.night):
        function = "bedroom"
    (prog.living if function in LIVING_FUNCTIONS else prog.night).append(ProgramRoom(label, function, a))
    counts[label] += 1
    return a


def _fit_mandatory(prog: Program, room: float) -> None:
    """Shrink the first rooms of a small house together so that they fit in ``room`` (m2)."""
    total = prog.hall + prog.kitchen + _total(prog.living + prog.night)
    if total <= room:
        return
    f = max(room, FIRST_ROOMS_MIN_SCALE * total) / total
    prog.hall *= f
    prog.kitchen *= f
    prog.living = [r._replace(area_m2=r.area_m2 * f) for r in prog.living]
    prog.night = [r._replace(area_m2=r.area_m2 * f) for r in prog.night]


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


def _strips(rng: np.random.Generator, prog: Program, corridor: int, area_m2: float) -> list[Strip]:
    """Night rooms dealt to strips side by side.

    As many strips as make the house's proportions nearest a drawn aspect ratio (:data:`ASPECT`:
    houses are compact), with at least :data:`MIN_STRIP_ROOMS` night rooms each; more than two
    only in a house with a hall, which every hallway starts from.
    """
    front_d, back_d = (to_units(rng.uniform(*BAND_M)) for _ in range(2))
    target = rng.uniform(*ASPECT)
    strip = front_d + corridor + back_d

    def miss(n: int) -> float:
        depth = n * strip
        return abs(_elongation(area_to_units(area_m2) / depth, depth) - math.log(target))

    most = len(prog.night) // MIN_STRIP_ROOMS if prog.hall else min(len(prog.night) // MIN_STRIP_ROOMS, 2)
    n_strips = min(range(1, max(most, 1) + 1), key=miss)
    strips = [[[], []] for _ in range(n_strips)]
    loads = [[0.0, 0.0] for _ in range(n_strips)]
    for room in sorted(prog.night, key=lambda r: -r.area_m2):
        k, side = min(((k, s) for k in range(n_strips) for s in (0, 1)), key=lambda ks: loads[ks[0]][ks[1]])
        strips[k][side].append(room)
        loads[k][side] += area_to_units(room.area_m2) / (front_d if side == 0 else back_d)
    for pair in strips:
        _balance(pair)
    return [Strip(front_d if f else 0, back_d if b else 0, f, b) for f, b in strips]


def _balance(pair: list[list[ProgramRoom]]) -> None:
    """Give a band of only small rooms an ordinary room from the other band, else merge the two.

    A band of small rooms alone would stretch them along the whole hallway; a single band makes a
    long, thin house.
    """
    if not (pair[0] and pair[1]):
        return
    small = [all(r.label is S for r in side) for side in pair]
    if not any(small):
        return
    poor, rich = (0, 1) if small[0] else (1, 0)
    ordinary = [r for r in pair[rich] if r.label is not S]
    if len(pair[rich]) >= 2 and ordinary and not small[rich]:
        room = min(ordinary, key=lambda r: r.area_m2)
        pair[rich].remove(room)
        pair[poor].append(room)
    else:
        pair[0], pair[1] = pair[0] + pair[1], []


def _hallway_width(model: BuildingTypeModel) -> int:
    """Width of the hallways: the model's mean corridor's, within :data:`HALLWAY_WIDTH_M` (units)."""
    c_stats = model.stats(C)
    lo, hi = HALLWAY_WIDTH_M
    return to_units(min(max(math.sqrt(c_stats.area_mean / max(c_stats.axes_ratio_mean, 1.0)), lo), hi))


def _least_night_length(strips: list[Strip]) -> int:
    """Length of the longest band with every room at its narrowest (units)."""
    return max(sum(_least_width(r) for r in rooms) for strip in strips for rooms in (strip.front, strip.back))


def _house_plan(rng: np.random.Generator, area_m2: float, model: BuildingTypeModel) -> Plan:
    """The house's rooms and hallways, without doors.

    The strips are drawn again, with a night room fewer or a smaller day zone, until the day zone
    fits beside the night zone's least length. The entrance reaches the first hallway, with the
    living rooms over it, in a house of one strip, and spans the depth, reaching every hallway,
    in a house of several.
    """
    prog = _program(rng, area_m2, model)
    corridor = _hallway_width(model)
    entry_w = to_units(rng.uniform(*ENTRANCE_WIDTH_M))
    while True:
        strips = _strips(rng, prog, corridor, area_m2)
        depth = sum(f + corridor + b for f, b, _, _ in strips)
        entry_depth = strips[0].front_depth + corridor if len(strips) == 1 else depth
        x_day = sum(_day_columns(prog, depth, entry_w, entry_depth))
        least = _least_night_length(strips)
        spare = area_to_units(area_m2) / depth - least
        if x_day <= spare or not (_drop_night_room(prog) or _shrink_day_zone(prog, spare / x_day)):
            break
    plan = Plan()
    night_len = max(round(area_to_units(area_m2) / depth) - x_day, least, MIN_NIGHT_LENGTH)
    rows = _rows(prog, strips, corridor, entry_w, area_m2)
    if rows is not None and _elongation(*rows.size) < _elongation(x_day + night_len, depth):
        hallways = _rows_zones(plan, corridor, entry_w, rows)
    else:
        _day_zone(plan, rng, prog, entry_depth, depth, entry_w)
        hallways = _night_zone(plan, strips, corridor, x_day, night_len)
    fronts = corridor_fronts(plan, hallways)
    segments = segment_corridors(hallways, prog.hallways, rng, 2 * corridor, [], fronts, DOOR_NEED)
    for seg in segments:
        plan.add(PlanRoom([seg], C, function="hallway", role="corridor"))
    return plan


class Rows(NamedTuple):
    """Sizes of a house in two rows: kitchen, entrance and night zone below; living space above.

    Attributes:
        kitchen: Width of the kitchen in the lower row (units), 0 where it is in the upper row.
        night: Length of the night zone (units).
        top: Depth of the upper row (units).
        width: The house's width (units).
        depth: Depth of the lower row, the night zone's (units).
        strip: The night zone's strip.
        upper: The upper row's rooms.
        rects: Their rectangles, in the upper row's frame (units).
    """

    kitchen: int
    night: int
    top: int
    width: int
    depth: int
    strip: Strip
    upper: list[ProgramRoom]
    rects: list[Rect]

    @property
    def size(self) -> tuple[int, int]:
        """Width and depth of the house (units)."""
        return self.width, self.depth + self.top


def _elongation(width: float, depth: float) -> float:
    """How far a ``width`` by ``depth`` rectangle is from a square: ``|log(width / depth)|``."""
    return abs(math.log(width / depth))


def _least_width(room: ProgramRoom) -> int:
    """Narrowest a room along a hallway is made: a small room's door, an ordinary room's use (units)."""
    return MIN_WIDTH if room.label is S else MIN_ORDINARY_WIDTH


def _natural_night_length(strip: Strip) -> int:
    """Length of the strip's longer band, each room as wide as its area needs, or its least width (units)."""
    return max(
        sum(max(round(area_to_units(r.area_m2) / depth), _least_width(r)) for r in rooms)
        for rooms, depth in ((strip.front, strip.front_depth), (strip.back, strip.back_depth))
        if rooms
    )


def _upper_rects(rooms: list[ProgramRoom], width: int, top: int, first: int) -> list[Rect]:
    """The upper row's rooms: the first across its depth, the others beside it (units, row's frame).

    Widths follow the rooms' areas, the first made at least ``first`` wide (it reaches over the
    entrance, which it opens from) where the others keep :data:`MIN_DAY_ROOM`; the others share
    the rest of the row side by side along its longer side, so a deep row stacks them.
    """
    if len(rooms) == 1:
        return [(0, 0, width, top)]
    areas = [r.area_m2 for r in rooms]
    w0 = _split(width, areas, MIN_DAY_ROOM)[0]
    if w0 < first and width - first >= MIN_DAY_ROOM * (len(rooms) - 1):
        w0 = first
    return [(0, 0, w0, top), *_side_by_side((w0, 0, width, top), areas[1:], MIN_DAY_ROOM)]


def _fair_day_room(rect: Rect) -> bool:
    """Whether a day room is at least :data:`MIN_DAY_ROOM` across and at most :data:`MAX_DAY_ELONGATION` long."""
    x0, y0, x1, y1 = rect
    short, long = sorted((x1 - x0, y1 - y0))
    return short >= MIN_DAY_ROOM and long <= MAX_DAY_ELONGATION * short


def _deepened(strip: Strip) -> Strip:
    """The strip with each band as deep as its largest ordinary room is wide, within :data:`ROWS_BAND_MAX`.

    In two rows nothing beside the night zone sets its depth, and a deeper band keeps a large
    bedroom from stretching along the hallway.
    """

    def depth(rooms: list[ProgramRoom], now: int) -> int:
        ordinary = [r.area_m2 for r in rooms if r.label is not S]
        if not ordinary:
            return now
        return min(max(round(math.sqrt(area_to_units(max(ordinary)))), now), max(now, ROWS_BAND_MAX))

    return strip._replace(
        front_depth=depth(strip.front, strip.front_depth), back_depth=depth(strip.back, strip.back_depth)
    )


def _rows(prog: Program, strips: list[Strip], corridor: int, entry_w: int, area_m2: float) -> Rows | None:
    """Sizes of the two-row layout, or ``None`` where it does not suit the house.

    A night zone of one strip is shallow (about 5 m with rooms on one side of its hallway): beside
    the day zone it makes a long, thin house. In two rows, the entrance and the night zone (a
    single band deepened, see :func:`_deepened`, at its natural length) share the lower row, as
    deep as the night zone, with the kitchen beside them; the hall (first, over the kitchen and
    the entrance) and the living rooms take the row above, across the whole width. Where the
    upper rooms would not suit (:func:`_upper_fits`: too shallow, more than
    :data:`MAX_DAY_ELONGATION` times as long as deep, short of the entrance), the kitchen moves
    up into the row, at its far end; where even then they would not, the night zone is
    squeezed, step by step, down to :data:`MIN_NIGHT_SQUEEZE` of its natural length (its rooms
    narrower, as in the columns), with the kitchen below, then above; where nothing suits, the
    house keeps its columns (``None``).

    Args:
        prog: The program.
        strips: The night zone's strips (one, else ``None``).
        corridor: Width of the hallway (units).
        entry_w: Width of the entrance (units).
        area_m2: The house's floor area (m2).
    """
    if len(strips) > 1:
        return None
    strip = strips[0] if strips[0].back else _deepened(strips[0])
    depth = strip.front_depth + corridor + strip.back_depth
    natural = max(_natural_night_length(strip), MIN_NIGHT_LENGTH)
    least = max(_least_night_length([strip]), MIN_NIGHT_LENGTH, round(MIN_NIGHT_SQUEEZE * natural))
    squeezed = sorted(
        {natural - (natural - least) * k // ROWS_SQUEEZE_STEPS for k in range(1, ROWS_SQUEEZE_STEPS + 1)}
    )
    least_top = MIN_HALL_WIDTH if prog.hall else MIN_DAY_ROOM
    hall = [ProgramRoom(H, "hall", prog.hall)] if prog.hall else []
    for nights in ([natural], squeezed[::-1] if least < natural else []):
        for kitchen in (max(round(area_to_units(prog.kitchen) / depth), MIN_DAY_ROOM), 0):
            upper = [*hall, *prog.living] + ([] if kitchen else [ProgramRoom(M, "kitchen", prog.kitchen)])
            for night in nights:
                width = kitchen + entry_w + night
                top = round((area_to_units(area_m2) - width * depth) / width)
                if top < least_top:
                    continue
                rects = _upper_rects(upper, width, top, kitchen + entry_w)
                if _upper_fits(rects, kitchen + entry_w, bool(hall)):
                    return Rows(kitchen, night, top, width, depth, strip, upper, rects)
    return None


def _upper_fits(rects: list[Rect], entrance_end: int, has_hall: bool) -> bool:
    """Whether the upper row's rooms suit the house.

    The first must reach over the entrance (to ``entrance_end``, units), a hall be at least
    :data:`MIN_HALL_WIDTH` across, and every room fair (:func:`_fair_day_room`).
    """
    x0, y0, x1, y1 = rects[0]
    hall_ok = not has_hall or min(x1 - x0, y1 - y0) >= MIN_HALL_WIDTH
    return x1 >= entrance_end and hall_ok and all(_fair_day_room(r) for r in rects)


def _rows_zones(plan: Plan, corridor: int, entry_w: int, rows: Rows) -> list[Rect]:
    """Lay out a house in two rows (see :func:`_rows`); returns the night zone's hallways.

    Args:
        plan: The plan the rooms are added to.
        corridor: Width of the hallway (units).
        entry_w: Width of the entrance (units).
        rows: The layout's sizes and the upper row's rooms.
    """
    depth = rows.depth
    if rows.kitchen:
        plan.add(PlanRoom([(0, 0, rows.kitchen, depth)], M, function="kitchen", role="kitchen"))
    x = rows.kitchen
    plan.add(PlanRoom([(x, 0, x + entry_w, depth)], C, function="entrance", role="lobby"))
    hallways = _night_zone(plan, [rows.strip], corridor, x + entry_w, rows.night)
    for r, (x0, y0, x1, y1) in zip(rows.upper, rows.rects, strict=True):
        role = "hall" if r.label is H else "kitchen" if r.function == KITCHEN.function else "living"
        plan.add(PlanRoom([(x0, depth + y0, x1, depth + y1)], r.label, function=r.function, role=role))
    return hallways


def _night_zone(plan: Plan, strips: list[Strip], corridor: int, x0: int, length: int) -> list[Rect]:
    """Lay out the strips' bands one above the other from ``x0``; returns the hallways between them.

    Args:
        plan: The plan the rooms are added to.
        strips: The strips, bottom first.
        corridor: Width of the hallways (units).
        x0: Where the night zone starts (units).
        length: Length of the night zone (units).
    """
    hallways = []
    y = 0
    x1 = x0 + length
    for f, b, fr, br in strips:
        hallways.append((x0, y + f, x1, y + f + corridor))
        _band(plan, fr, (x0, y, x1, y + f), hallway_above=True)
        _band(plan, br, (x0, y + f + corridor, x1, y + f + corridor + b), hallway_above=False)
        y += f + corridor + b
    return hallways


def _drop_night_room(prog: Program) -> bool:
    """Leave out the smallest night room but the bathroom and the last bedroom (``False``: none left)."""
    keep_bedroom = sum(r.function == "bedroom" for r in prog.night) <= 1
    pool = [
        k
        for k, r in enumerate(prog.night)
        if r.function != "bathroom" and not (keep_bedroom and r.function == "bedroom")
    ]
    if not pool:
        return False
    del prog.night[min(pool, key=lambda k: prog.night[k].area_m2)]
    return True


def _shrink_day_zone(prog: Program, factor: float) -> bool:
    """Make the day zone fit: drop extra living rooms, then shrink its rooms (``False``: no change)."""
    if len(prog.living) > 1:
        del prog.living[1:]
        return True
    factor = max(factor, DAY_SHRINK_LEAST)
    if factor >= DAY_SHRINK_NEGLIGIBLE:
        return False
    prog.kitchen = max(prog.kitchen * factor, MIN_SHRUNK_KITCHEN_M2)
    prog.hall *= factor
    prog.living = [r._replace(area_m2=max(r.area_m2 * factor, MIN_SHRUNK_LIVING_M2)) for r in prog.living]
    return True


def _day_columns(prog: Program, depth: int, entry_w: int, entry_depth: int) -> tuple[int, int]:
    """Widths of the day zone's two columns (kitchen and living rooms; hall or entrance).

    Where the living rooms reach over the entrance, the kitchen is as deep as the entrance and
    column A as wide as the kitchen or the living rooms need, whichever needs more. A column A
    more than :data:`MAX_DAY_ELONGATION` times as deep as wide is widened to the side of its
    largest room, whose rooms lie one above the other.
    """
    living = area_to_units(_total(prog.living))
    col_b = max(round(area_to_units(prog.hall) / depth), MIN_HALL_WIDTH) if prog.hall else entry_w
    if _over_entry(prog, depth, entry_depth):
        col_a = max(area_to_units(prog.kitchen) / entry_depth, living / (depth - entry_depth) - col_b)
    else:
        col_a = (area_to_units(prog.kitchen) + living) / depth
    col_a = max(round(col_a), MIN_DAY_ROOM)
    if prog.living and depth > MAX_DAY_ELONGATION * col_a:
        largest = max(prog.kitchen, *(r.area_m2 for r in prog.living))
        col_a = max(col_a, round(math.sqrt(area_to_units(largest))))
    return col_a, col_b


def _over_entry(prog: Program, depth: int, entry_depth: int) -> bool:
    """Whether the living rooms reach over the entrance (no hall, deep enough for a room above it)."""
    return not prog.hall and bool(prog.living) and depth - entry_depth >= MIN_DAY_ROOM


def _day_zone(
    plan: Plan, rng: np.random.Generator, prog: Program, entry_depth: int, depth: int, entry_w: int
) -> int:
    """Kitchen, living and dining rooms, and the entrance or hall; returns the night zone's start (x).

    Column A holds the kitchen with the living rooms above it (side by side in a shallow house);
    column B, next to the night zone, the hall (entered through a vestibule) or the entrance, with
    the living rooms reaching over the entrance where the house is deep enough. A kitchen alone
    in a column more than :data:`MAX_DAY_ELONGATION` times as deep as wide takes the depth its
    area needs, and the hall the rest of the column.
    """
    living = area_to_units(_total(prog.living))
    kitchen = area_to_units(prog.kitchen)
    room = MIN_DAY_ROOM
    col_a, col_b = _day_columns(prog, depth, entry_w, entry_depth)
    over_b = _over_entry(prog, depth, entry_depth)
    if prog.hall:
        _hall_with_vestibule(plan, rng, (col_a, 0, col_a + col_b, depth))
    else:
        top = entry_depth if over_b else depth
        plan.add(PlanRoom([(col_a, 0, col_a + col_b, top)], C, function="entrance", role="lobby"))
    if not living:
        yk = max(round(kitchen / col_a), room)
        if prog.hall and depth > MAX_DAY_ELONGATION * col_a and depth - yk >= room:
            plan.add(PlanRoom([(0, 0, col_a, yk)], M, function="kitchen", role="kitchen"))
            next(r for r in plan.rooms if r.role == "hall").rects.append((0, yk, col_a, depth))
        else:
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
    """The living rooms side by side along the longer side of ``box`` (units), in proportion to their areas."""
    for r, rect in zip(prog.living, _side_by_side(box, [r.area_m2 for r in prog.living]), strict=True):
        plan.add(PlanRoom([rect], r.label, function=r.function, role="living"))


def _side_by_side(box: Rect, areas: list[float], least: int = 0) -> list[Rect]:
    """Rectangles filling ``box`` (units) side by side along its longer side, in proportion to ``areas``.

    None is narrower than ``least`` where the box is long enough for all (see :func:`_split`).
    """
    x0, y0, x1, y1 = box
    along_x = x1 - x0 >= y1 - y0
    at = x0 if along_x else y0
    rects = []
    for w in _split(max(x1 - x0, y1 - y0), areas, least):
        rects.append((at, y0, at + w, y1) if along_x else (x0, at, x1, at + w))
        at += w
    return rects


def _widths(rooms: list[ProgramRoom], length: int, depth: int) -> list[int]:
    """Widths of rooms along a strip: small rooms as their area needs, the others share the rest.

    Args:
        rooms: The band's rooms.
        length: Length of the band (units).
        depth: Depth of the band (units).

    Returns:
        Each room's width (units), together ``length``.
    """
    natural = [max(area_to_units(r.area_m2) / max(depth, 1), MIN_WIDTH) for r in rooms]
    small = [r.label is S for r in rooms]
    if (
        all(small)
        or not any(small)
        or sum(n for n, s in zip(natural, small, strict=True) if s) > SMALL_ROOMS_MAX_SHARE * length
    ):
        return _split(length, [r.area_m2 for r in rooms], MIN_WIDTH)
    fixed = [round(n) if s else 0 for n, s in zip(natural, small, strict=True)]
    rest = _split(
        length - sum(fixed), [r.area_m2 for r, s in zip(rooms, small, strict=True) if not s], MIN_WIDTH
    )
    it = iter(rest)
    return [f if s else next(it) for f, s in zip(fixed, small, strict=True)]


def _hall_with_vestibule(plan: Plan, rng: np.random.Generator, box: Rect) -> None:
    """A hall entered through a vestibule (a short corridor) set into its front side.

    The hall beside the vestibule is either :data:`MIN_HALL_BESIDE_VESTIBULE` wide or more, or
    absent (the vestibule in a corner).
    """
    x0, y0, x1, y1 = box
    w = min(to_units(rng.uniform(*VESTIBULE_WIDTH_M)), x1 - x0 - MIN_HALL_BESIDE_VESTIBULE)
    d = to_units(rng.uniform(*VESTIBULE_DEPTH_M))
    a = x0 + int(rng.integers(0, x1 - x0 - w + 1))
    if 0 < a - x0 < MIN_HALL_BESIDE_VESTIBULE:
        a = x0
    elif 0 < x1 - a - w < MIN_HALL_BESIDE_VESTIBULE:
        a = x1 - w
    plan.add(PlanRoom([(a, y0, a + w, y0 + d)], C, function="entrance", role="lobby"))
    rects = [(x0, y0 + d, x1, y1), (x0, y0, a, y0 + d), (a + w, y0, x1, y0 + d)]
    plan.add(PlanRoom([r for r in rects if r[0] < r[2]], H, function="hall", role="hall"))


def _band(plan: Plan, rooms: list[ProgramRoom], box: Rect, hallway_above: bool) -> None:
    """Rooms side by side along a hallway in ``box`` (units), widths in proportion to their areas.

    A small room that would come out much deeper than it is wide takes only the part of the
    strip next to the hallway; the room beside it wraps around behind it.
    """
    if not rooms:
        return
    x0, y0, x1, y1 = box
    x = x0
    ids = []
    for r, w in zip(rooms, _widths(rooms, x1 - x0, y1 - y0), strict=True):
        ids.append(plan.add(PlanRoom([(x, y0, x + w, y1)], r.label, function=r.function, role="room")))
        x += w
    _tuck_small_rooms(plan, ids, rooms, (y0, y1), hallway_above)


def _tuck_small_rooms(
    plan: Plan, ids: list[int], rooms: list[ProgramRoom], band: tuple[int, int], hallway_above: bool
) -> None:
    """Cut each small room of a band to its area's depth next to the hallway, where it can.

    The part behind it goes to an ordinary room beside it, which wraps around the small room.

    Args:
        plan: The plan holding the band's rooms.
        ids: The band's rooms in the plan, in order along the band.
        rooms: Their program.
        band: The band's extent across the hallway, ``(y0, y1)`` (units).
        hallway_above: Whether the hallway lies along ``y1`` (else along ``y0``).
    """
    y0, y1 = band
    for k, i in enumerate(ids):
        room = plan.rooms[i]
        mates = [ids[m] for m in (k - 1, k + 1) if 0 <= m < len(ids) and plan.rooms[ids[m]].label is not S]
        a, _, b, _ = room.rects[0]
        depth = max(round(area_to_units(rooms[k].area_m2) / (b - a)), MIN_TUCKED_DEPTH)
        if room.label is S and mates and depth <= y1 - y0 - MIN_WRAP_DEPTH:
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
    centre = next((i for i, r in enumerate(plan.rooms) if r.role == "hall"), lobby)
    _day_doors(plan, rng, model, centre)
    _night_doors(plan, rng, model, neighbours, centre)
    ensure_reachable(plan, rng)
    break_mazes(plan, rng)


def _day_doors(plan: Plan, rng: np.random.Generator, model: BuildingTypeModel, centre: int) -> None:
    """Doors of the day zone: living rooms to the hall or entrance (``centre``) and the kitchen, garden doors.

    The kitchen opens onto the centre where it joins no living room, or where a living room does
    not open onto the centre, else by chance. A living room that touches neither opens into a
    neighbouring living room.
    """
    kitchen = next(i for i, r in enumerate(plan.rooms) if r.role == "kitchen")
    living = [i for i, r in enumerate(plan.rooms) if r.role == "living"]
    gateways = sum(_door(plan, rng, i, centre) for i in living)
    joined = [_door(plan, rng, kitchen, i) for i in living]
    if not any(joined) or len(living) > gateways or rng.random() < P_KITCHEN_TO_CENTRE:
        _door(plan, rng, kitchen, centre)
    for i in living:
        if not any(i in (d.a, d.b) for d in plan.doors):
            any(_door(plan, rng, i, j) for j in living if j != i)
    p_garden = min(1.0, model.connection(B, OUTSIDE) * model.stats(B).doors_mean)
    for i in living:
        walls = [w for w in exterior_walls(plan, i) if door_fits(w, RULES.room)]
        if walls and rng.random() < p_garden:
            add_door(plan, i, None, walls[0], RULES.room, rng)


def _night_doors(
    plan: Plan, rng: np.random.Generator, model: BuildingTypeModel, neighbours: list[list[int]], centre: int
) -> None:
    """A door from every night room to its hallway (else to ``centre``), or a bathroom's to a bedroom."""
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


def _door(plan: Plan, rng: np.random.Generator, i: int, j: int) -> bool:
    """A room door between rooms ``i`` and ``j``, on the longest shared wall it fits (``False``: none fits)."""
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
        >>> abs(b.area - 120) < 1  # within a row of 0.1 m grid units
        True
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
