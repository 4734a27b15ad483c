"""Cutting a bay (a strip of rooms along a corridor) into rooms.

A bay is filled from one end to the other with *units*, each spanning the bay's depth:

- ``room``: one medium or big room;
- ``closet``: a room with a small closet in its back corner, entered through the room;
- ``notch``: a small room at the corridor with the neighbouring room wrapping around behind it;
- ``core``: a service core, toilets, storage and stairs grouped together: in a deep bay a short
  corridor into the bay with small rooms on both sides, in a shallow one a row of small rooms
  side by side along the corridor;
- ``small``: one small room (in shallow bays).

Which unit comes next is drawn in proportion to what the building still needs (a
:class:`Budget`), so the whole building matches the model's label shares; widths follow the
model's areas for the bay's depth. Every unit must reach its corridor with room for a door;
units that do not are merged into a neighbour.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from realistic_indoor.building.labels import SemanticLabel
from realistic_indoor.generator.geometry import Rect, area_to_m2, area_to_units, contact, to_units
from realistic_indoor.generator.plan import Plan, PlanRoom
from realistic_indoor.generator.sampling import choice_index

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.rooms.regions import Bay
    from realistic_indoor.models.building_model import BuildingTypeModel

__all__ = ["BayContext", "Budget", "Unit", "core_shape", "label_for_area", "subdivide"]

S, M, B = SemanticLabel.SMALL, SemanticLabel.MEDIUM, SemanticLabel.BIG

DOOR_NEED = to_units(1.5)
"""Shared wall a room needs for a door with its clearances (units)."""
MIN_ROOM = to_units(2.4)
"""Narrowest ordinary room (units)."""
MIN_SMALL = to_units(1.5)
"""Narrowest small room (units)."""
STUB_DEPTH = to_units(5.0)
"""Bays at least this deep get service cores with their own short corridor (units)."""


@dataclass
class Budget:
    """How many units of each kind the building still needs (may go negative).

    Keys: ``"M"``, ``"B"`` (plain rooms), ``"closet"``, ``"notch"``, ``"core"``, ``"S"``.
    """

    want: dict[str, float]
    initial: dict[str, float] = field(default_factory=dict)

    def __post_init__(self) -> None:
        total = sum(max(v, 0.0) for v in self.want.values()) or 1.0
        self.initial = {k: max(v, 0.0) / total for k, v in self.want.items()}

    def pick(self, rng: np.random.Generator, kinds: list[str]) -> str:
        """A kind drawn in proportion to what is still wanted; once all is placed, to the plan."""
        w = [max(self.want.get(k, 0.0), 0.0) + 0.1 * self.initial.get(k, 0.0) + 1e-3 for k in kinds]
        total = sum(w)
        return kinds[choice_index(rng, [x / total for x in w])]

    def take(self, kind: str, n: float = 1.0) -> None:
        """Record that ``n`` units of ``kind`` were placed."""
        self.want[kind] = self.want.get(kind, 0.0) - n


@dataclass
class BayContext:
    """What subdividing needs besides the bay itself.

    Attributes:
        model: The building-type model (areas of small, medium and big rooms).
        budget: Units still wanted.
        circulation: Rectangles of corridors and halls the bay's rooms may open onto.
        stub_width: Width of a service core's corridor (units).
        core_rows: Range of small rooms per side of a core.
        shallow: Bays shallower than this hold small rooms and shallow medium rooms (units).
        max_axes_ratio: Rooms other than small ones are at least the bay's depth over this
            and at most the depth times this wide (a deep bay gets larger rooms rather than
            long narrow ones, a shallow one smaller rooms); unbounded by default.
        widen_last_room: Give the end of a deep bay too short for a room of its own to the
            room before it (within ``max_axes_ratio``) instead of making it a small room: real
            strips end in a wider room, not in a sliver.
    """

    model: BuildingTypeModel
    budget: Budget
    circulation: list[Rect]
    stub_width: int
    core_rows: tuple[int, int]
    shallow: int
    max_axes_ratio: float = math.inf
    widen_last_room: bool = False


@dataclass
class Unit:
    """A piece of a bay, ``t0..t1`` along it (units)."""

    kind: str
    t0: int
    t1: int
    label: SemanticLabel = M
    extra: dict = field(default_factory=dict)

    @property
    def width(self) -> int:
        """Extent along the bay (units)."""
        return self.t1 - self.t0


def _access(bay: Bay, circulation: list[Rect]) -> tuple[list[tuple[int, int]], int, int]:
    """Spans along the bay's corridor side that touch circulation, and the ends' contact lengths."""
    x0, y0, x1, y1 = bay.rect
    side_axis = "h" if bay.axis == "x" else "v"
    side_coord = {"S": y0, "N": y1, "W": x0, "E": x1}[bay.access]
    origin = x0 if bay.axis == "x" else y0
    start, stop = (x0, x1) if bay.axis == "x" else (y0, y1)
    spans, end0, end1 = [], 0, 0
    for r in circulation:
        c = contact(bay.rect, r)
        if c is None:
            continue
        if c.axis == side_axis and c.coord == side_coord:
            spans.append((c.lo - origin, c.hi - origin))
        elif c.axis != side_axis and c.coord == start:
            end0 += c.length
        elif c.axis != side_axis and c.coord == stop:
            end1 += c.length
    return sorted(spans), end0, end1


def _overlap(t0: int, t1: int, spans: list[tuple[int, int]]) -> int:
    return max((min(t1, b) - max(t0, a) for a, b in spans), default=0)


BIG_STRETCH = 1.6
"""How much longer than the axes-ratio limit a big room may run along a strip: open-plan offices
and classrooms take a shallow strip's length where a deep one would give them depth."""


def _room_width(rng: np.random.Generator, ctx: BayContext, label: SemanticLabel, depth: int) -> int:
    stats = ctx.model.stats(label)
    area = area_to_units(stats.sample_area(rng, 0.45 * stats.area_mean, 2.6 * stats.area_mean))
    low = MIN_SMALL if label is S else max(MIN_ROOM, round(depth / ctx.max_axes_ratio))
    high = (
        max(3 * depth, to_units(10.0))
        if label is S
        else min(
            max(3 * depth, to_units(10.0)), depth * ctx.max_axes_ratio * (BIG_STRETCH if label is B else 1.0)
        )
    )
    return int(min(max(area / depth, low), max(high, low)))


def core_shape(model: BuildingTypeModel, depth: int, rows_range: tuple[int, int]) -> tuple[int, int, int]:
    """Mean shape of a service core in a bay of ``depth``: rows per side, room width, rooms.

    A core in a deep bay has a short corridor with ``rows`` small rooms on each side; in a
    shallow bay it is a row of small rooms along the corridor (``rows`` is then the count).
    """
    stats = model.stats(S)
    area = area_to_units(stats.area_mean)
    if depth >= STUB_DEPTH:
        rows = int(min(max(round(depth / max(math.sqrt(area), 1)), rows_range[0] - 1, 1), rows_range[1]))
        width = int(min(max(area / (depth / rows), MIN_SMALL), to_units(3.2)))
        return rows, width, 2 * rows
    width = int(min(max(area / depth, MIN_SMALL), to_units(3.2)))
    return 3, width, 3


def _core_unit(t: int, rng: np.random.Generator, ctx: BayContext, depth: int) -> Unit:
    rows, width, _ = core_shape(ctx.model, depth, ctx.core_rows)
    stats = ctx.model.stats(S)
    scale = stats.sample_area(rng, 0.6 * stats.area_mean, 1.6 * stats.area_mean) / stats.area_mean
    width = int(min(max(width * scale, MIN_SMALL), to_units(3.2)))
    if depth < STUB_DEPTH:
        n = int(rng.integers(2, 5))
        return Unit("core", t, t + n * width, S, {"row": n})
    two = bool(rng.random() < 0.8)
    total = ctx.stub_width + width * (2 if two else 1)
    return Unit("core", t, t + total, S, {"rows": rows, "side": width, "stub": ctx.stub_width, "two": two})


def _plan_units(bay: Bay, rng: np.random.Generator, ctx: BayContext) -> list[Unit]:
    """Units from one end of the bay to the other, kinds drawn from the budget."""
    length, depth = bay.length, bay.depth
    shallow = depth < ctx.shallow
    units: list[Unit] = []
    t = 0
    while length - t >= MIN_SMALL:
        if shallow:
            kind = "S" if depth < to_units(2.4) else ctx.budget.pick(rng, ["S", "M"])
        else:
            kinds = ["M", "B", "closet", "notch", "core"]
            kind = ctx.budget.pick(rng, kinds)
        unit = _make_unit(kind, t, rng, ctx, depth)
        last = unit.t1 > length - MIN_ROOM
        if last and (length - t < _min_width(unit) or length - t < 0.6 * unit.width):
            unit = _filler(ctx, t, length, depth, shallow)
            if _widen_previous(units, unit, ctx, depth, shallow):
                break
        ctx.budget.take(unit.kind)
        units.append(unit)
        if last:
            break
        t = unit.t1
    if not units:
        label = S if shallow or length < MIN_ROOM else M
        units.append(Unit("S" if label is S else "M", 0, length, label))
    units[-1].t1 = length
    return units


def _widen_previous(units: list[Unit], filler: Unit, ctx: BayContext, depth: int, shallow: bool) -> bool:
    """Stretch the last plain room over a small ``filler`` if the style asks and the room allows."""
    if not ctx.widen_last_room or shallow or filler.label is not S or not units:
        return False
    prev = units[-1]
    if prev.kind not in ("M", "B") or filler.t1 - prev.t0 > depth * ctx.max_axes_ratio:
        return False
    prev.t1 = filler.t1
    prev.label = label_for_area(ctx.model, prev.width * depth)
    return True


def _filler(ctx: BayContext, t0: int, t1: int, depth: int, shallow: bool) -> Unit:
    """A plain room filling the end of a bay, labelled by its area."""
    label = label_for_area(ctx.model, (t1 - t0) * depth)
    if label is B and shallow:
        label = M
    return Unit({S: "S", M: "M", B: "B"}[label], t0, t1, label)


def label_for_area(model: BuildingTypeModel, area_units: float) -> SemanticLabel:
    """The ordinary label whose mean area is nearest ``area_units`` (square units) on a log scale."""
    a = max(area_to_m2(area_units), 1e-6)
    return min((S, M, B), key=lambda lab: abs(math.log(a / model.stats(lab).area_mean)))


def _min_width(u: Unit) -> int:
    if u.kind == "core" and "row" in u.extra:
        return MIN_SMALL * u.extra["row"]
    if u.kind == "core":
        return u.extra["side"] * (2 if u.extra["two"] else 1) + u.extra["stub"]
    if u.kind in ("closet", "notch"):
        return u.extra["w"] + MIN_ROOM
    return MIN_SMALL if u.label is S else MIN_ROOM


def _make_unit(kind: str, t: int, rng: np.random.Generator, ctx: BayContext, depth: int) -> Unit:
    if kind == "core":
        return _core_unit(t, rng, ctx, depth)
    if kind in ("closet", "notch"):
        label = M if rng.random() < 0.75 else B
        stats = ctx.model.stats(S)
        area = area_to_units(stats.sample_area(rng, 0.6 * stats.area_mean, 1.6 * stats.area_mean))
        w = int(min(max(math.sqrt(area), MIN_SMALL), to_units(2.6)))
        d = int(min(max(area / w, MIN_SMALL), depth - MIN_ROOM))
        room = _room_width(rng, ctx, label, depth)
        width = room + w if kind == "notch" else max(room, w + MIN_ROOM)
        return Unit(kind, t, t + width, label, {"w": w, "d": d, "far": bool(rng.random() < 0.5)})
    label = {"M": M, "B": B, "S": S}[kind]
    width = _room_width(rng, ctx, label, depth)
    if label is M and label_for_area(ctx.model, width * depth) is B:
        kind, label = "B", B  # a deep strip's rooms are big however they were drawn
    return Unit(kind, t, t + width, label)


def _core_layout(u: Unit) -> tuple[int, int]:
    """Start of the core's corridor along the bay, and the width of each side's rooms."""
    two, stub = u.extra["two"], u.extra["stub"]
    side = (u.width - stub) // (2 if two else 1)
    return (u.t0 + side if two else u.t0), side


def _fix_access(units: list[Unit], spans: list[tuple[int, int]], end0: int, end1: int) -> list[Unit]:
    """Merge units that cannot reach the corridor into a neighbour; demote cores that cannot."""
    k = 0
    while k < len(units):
        u = units[k]
        first, last = k == 0 and end0 >= DOOR_NEED, k == len(units) - 1 and end1 >= DOOR_NEED
        if len(units) == 1 or _reaches(u, spans, first, last):
            k += 1
            continue
        if u.kind in ("core", "closet", "notch"):
            u.kind, u.extra = ("S", {}) if u.width < MIN_ROOM else ("M", {})
            u.label = S if u.kind == "S" else M
            continue
        other = units[k - 1] if k > 0 else units[k + 1]
        other.t0, other.t1 = min(u.t0, other.t0), max(u.t1, other.t1)
        if other.kind == "S" and other.width >= MIN_ROOM:
            other.kind, other.label = "M", M
        del units[k]
        k = max(k - 1, 0)
    return units


def _reaches(u: Unit, spans: list[tuple[int, int]], at_start: bool, at_end: bool) -> bool:
    if u.kind == "core" and "row" in u.extra:
        return all(_overlap(a, b, spans) >= DOOR_NEED for a, b in _row_cuts(u))
    if u.kind == "core":
        a, _ = _core_layout(u)
        return _overlap(a, a + u.extra["stub"], spans) >= u.extra["stub"]
    if u.kind == "notch":
        ta, tb = _notch_span(u)
        rest = (u.t0, ta) if ta > u.t0 else (tb, u.t1)
        return _overlap(ta, tb, spans) >= DOOR_NEED and _overlap(*rest, spans) >= DOOR_NEED
    return at_start or at_end or _overlap(u.t0, u.t1, spans) >= DOOR_NEED


def _row_cuts(u: Unit) -> list[tuple[int, int]]:
    n = u.extra["row"]
    edges = [u.t0 + round(u.width * k / n) for k in range(n + 1)]
    return list(itertools.pairwise(edges))


def _notch_span(u: Unit) -> tuple[int, int]:
    w = u.extra["w"]
    return (u.t1 - w, u.t1) if u.extra["far"] else (u.t0, u.t0 + w)


def subdivide(plan: Plan, bay: Bay, rng: np.random.Generator, ctx: BayContext) -> list[list[int]]:
    """Cut ``bay`` into rooms and add them to ``plan``.

    Returns:
        The room indices of each unit, in order along the bay (a core's stub first).
    """
    spans, end0, end1 = _access(bay, ctx.circulation)
    units = _fix_access(_plan_units(bay, rng, ctx), spans, end0, end1)
    return [_emit(plan, bay, u) for u in units]


def _emit(plan: Plan, bay: Bay, u: Unit) -> list[int]:
    d = bay.depth
    if u.kind == "core":
        return _emit_core(plan, bay, u)
    if u.kind in ("closet", "notch"):
        cd = u.extra["d"]
        ta, tb = _notch_span(u)
        full = bay.local(u.t0, ta, 0, d) if ta > u.t0 else bay.local(tb, u.t1, 0, d)
        if u.kind == "notch":
            small, rest = bay.local(ta, tb, 0, cd), bay.local(ta, tb, cd, d)
        else:
            small, rest = bay.local(ta, tb, d - cd, d), bay.local(ta, tb, 0, d - cd)
        i = plan.add(PlanRoom([full, rest], u.label, role="room"))
        role = "closet" if u.kind == "closet" else "notch"
        j = plan.add(PlanRoom([small], S, role=role, host=i if role == "closet" else -1))
        return [i, j]
    return [plan.add(PlanRoom([bay.local(u.t0, u.t1, 0, d)], u.label, role="room"))]


def _emit_core(plan: Plan, bay: Bay, u: Unit) -> list[int]:
    d = bay.depth
    group = len(plan.rooms)
    if "row" in u.extra:
        return [
            plan.add(PlanRoom([bay.local(a, b, 0, d)], S, role="core", group=group)) for a, b in _row_cuts(u)
        ]
    rows, two, stub = u.extra["rows"], u.extra["two"], u.extra["stub"]
    a, _ = _core_layout(u)
    s = plan.add(PlanRoom([bay.local(a, a + stub, 0, d)], SemanticLabel.CORRIDOR, role="stub"))
    out = [s]
    cols = [(u.t0, a), (a + stub, u.t1)] if two else [(a + stub, u.t1)]
    cuts = [round(d * k / rows) for k in range(rows + 1)]
    for c0, c1 in cols:
        for k in range(rows):
            room = PlanRoom([bay.local(c0, c1, cuts[k], cuts[k + 1])], S, role="core", host=s, group=s)
            out.append(plan.add(room))
    return out
