"""A baseline like NIST's World Generator: a hallway ring, interior hallways, random room modules.

The user gives a grid of ``width_units`` x ``height_units`` cells of 3 m. Hallways run in a ring
along the perimeter and, inside, every 3 to 5 cells; the blocks between them are filled with
rectangular room modules of 1x1 to 4x4 cells chosen at random. Doors follow the World
Generator's rules: every room draws one to four doors on random walls it shares with rooms or
hallways, room-to-room doors are kept at random, a room's extra doors onto the same hallway are
pruned, and every room keeps at least one. Unlike the original it is seeded, and rooms left
unreachable get a door to a reachable neighbour, so every map is valid. Its maps have the faults
the paper measured on the 2013 competition map: corridors with few doors, offices opening onto
each other, few offices on a corridor.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, ClassVar

from realistic_indoor.building.labels import SemanticLabel
from realistic_indoor.errors import ConfigError
from realistic_indoor.generator.base import finish
from realistic_indoor.generator.connect import connect_circulation, ensure_reachable
from realistic_indoor.generator.doors import RULES, add_door, add_exterior_door
from realistic_indoor.generator.functions import draw_function
from realistic_indoor.generator.geometry import Contact, to_units
from realistic_indoor.generator.plan import B, C, H, M, Plan, PlanRoom, S
from realistic_indoor.generator.sampling import choice_index

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.building.building import Building

__all__ = ["CELL_M", "RandomGridGenerator"]

CELL_M = 3.0
"""Side of one grid cell (m), as in the World Generator."""
CELL = to_units(CELL_M)
MIN_UNITS, MAX_UNITS = 5, 200


MODULE_SIDES = (0.45, 0.3, 0.15, 0.1)
"""Chances of a module side of 1, 2, 3 and 4 cells (small modules are the most common)."""

FUNCTIONS = {
    S: {"office": 9, "empty room": 9},
    M: {"office": 8, "empty room": 2},
    B: {"office": 6, "empty room": 1, "maze room": 2, "service room": 4, "meeting room": 1, "other": 1},
    H: {"hall": 3, "other": 2},
    C: {"corridor": 1},
}
"""Functional labels by semantic label, weighted as in the 2013 competition map (Table 2)."""


def _label(w: int, h: int) -> SemanticLabel:
    """The label of a ``w`` x ``h`` module: 1 cell small, 2 medium, long ones of 6+ cells hall, else big."""
    cells = w * h
    if cells == 1:
        return S
    if cells == 2:
        return M
    return H if w != h and cells >= 6 else B


def _hallway_lines(rng: np.random.Generator, n: int) -> list[int]:
    """Indices of hallway lines across ``n`` cells: both ends, and every 3 to 5 cells between."""
    lines = [0]
    while True:
        nxt = lines[-1] + 1 + int(rng.integers(3, 6))
        if nxt >= n - 4:
            break
        lines.append(nxt)
    return [*lines, n - 1]


def _modules(rng: np.random.Generator, free: set[tuple[int, int]]) -> list[tuple[int, int, int, int]]:
    """Fill the free cells with random rectangles of 1x1 to 4x4 cells: ``(i, j, w, h)``."""
    out = []
    for j, i in sorted((j, i) for i, j in free):
        if (i, j) not in free:
            continue
        w, h = (choice_index(rng, MODULE_SIDES) + 1 for _ in range(2))
        w = next(k for k in range(w, 0, -1) if all((i + a, j) in free for a in range(k)))
        h = next(
            k for k in range(h, 0, -1) if all((i + a, j + b) in free for a in range(w) for b in range(k))
        )
        for a in range(w):
            for b in range(h):
                free.discard((i + a, j + b))
        out.append((i, j, w, h))
    return out


def _hallways(
    rng: np.random.Generator, cells: set[tuple[int, int]], cols: list[int], rows: list[int]
) -> list:
    """Hallway cells as straight segments of 2 to 7 cells, cut at crossings and at random."""
    segs = []
    for j in rows:
        run = sorted(i for i, jj in cells if jj == j)
        segs += _cut_run([(i, j) for i in run], rng, set(cols))
    for i in cols:
        run = sorted(j for ii, j in cells if ii == i and j not in rows)
        segs += _cut_run([(i, j) for j in run], rng, set(rows), vertical=True)
    return segs


def _cut_run(
    run: list[tuple[int, int]], rng: np.random.Generator, cross: set[int], vertical: bool = False
) -> list:
    out, cur = [], []
    for k, c in enumerate(run):
        gap = cur and (c[1] - cur[-1][1] if vertical else c[0] - cur[-1][0]) != 1
        if gap or (
            cur
            and len(cur) >= 2
            and ((c[0] if not vertical else c[1]) in cross or len(cur) >= rng.integers(4, 8))
        ):
            out.append(cur)
            cur = []
        cur.append(c)
        if k == len(run) - 1:
            out.append(cur)
    return [s for s in out if s]


def _grid_plan(rng: np.random.Generator, width: int, height: int) -> Plan:
    cols = _hallway_lines(rng, width)
    rows = _hallway_lines(rng, height) if rng.random() < 0.3 else [0, height - 1]
    hall_cells = {(i, j) for i in range(width) for j in range(height) if i in cols or j in rows}
    plan = Plan()
    for seg in _hallways(rng, hall_cells, cols, rows):
        (i0, j0), (i1, j1) = seg[0], seg[-1]
        plan.add(
            PlanRoom(
                [(i0 * CELL, j0 * CELL, (i1 + 1) * CELL, (j1 + 1) * CELL)], C, "corridor", role="corridor"
            )
        )
    free = {(i, j) for i in range(width) for j in range(height)} - hall_cells
    for i, j, w, h in _modules(rng, free):
        label = _label(w, h)
        rect = (i * CELL, j * CELL, (i + w) * CELL, (j + h) * CELL)
        plan.add(PlanRoom([rect], label, draw_function(rng, FUNCTIONS[label]), role="room"))
    return plan


def _unit_walls(plan: Plan, i: int, j: int) -> list[Contact]:
    """The wall between rooms ``i`` and ``j`` cut into pieces one cell long (where a door may go)."""
    out = []
    for c in plan.shared(i, j):
        for lo in range(c.lo, c.hi, CELL):
            out.append(Contact(c.axis, c.coord, lo, min(lo + CELL, c.hi)))
    return out


def _doors(plan: Plan, rng: np.random.Generator) -> None:
    """The World Generator's door rules, then an entrance on the ring and a reachability pass."""
    connect_circulation(plan)
    neighbours = plan.neighbours()
    chosen: set[tuple[int, int, str, int, int]] = set()
    for i, room in enumerate(plan.rooms):
        if room.is_circulation:
            continue
        walls = [(j, w) for j in neighbours[i] for w in _unit_walls(plan, i, j)]
        picks = rng.permutation(len(walls))[: int(rng.integers(1, 5))]
        kept, to_hall = [], set()
        for k in picks:
            j, w = walls[int(k)]
            if plan.rooms[j].is_circulation:
                if j in to_hall:
                    continue
                to_hall.add(j)
            elif rng.random() < 0.5:
                continue
            kept.append((j, w))
        if not kept:
            kept = [walls[int(picks[0])]]
        for j, w in kept:
            key = (min(i, j), max(i, j), w.axis, w.coord, w.lo)
            if key not in chosen:
                chosen.add(key)
                add_door(plan, i, j, w, RULES.room, where="centre")
    ring = [i for i, r in enumerate(plan.rooms) if r.is_circulation]
    for k in rng.permutation(len(ring)):
        if add_exterior_door(plan, ring[int(k)], RULES.exit, margin=RULES.open_margin):
            break
    ensure_reachable(plan, rng)


@dataclass(frozen=True)
class RandomGridGenerator:
    """Maps like NIST's World Generator (the 2013 competition map), the paper's baseline.

    Args:
        width_units: Grid width in 3 m cells (5 to 200).
        height_units: Grid height in 3 m cells (5 to 200).

    Examples:
        >>> import numpy as np
        >>> b = RandomGridGenerator(width_units=12, height_units=9)(np.random.default_rng(0))
        >>> round(b.area)
        972
    """

    width_units: int = 17
    height_units: int = 13

    name: ClassVar[str] = "random"

    def __post_init__(self) -> None:
        for field, value in (("width_units", self.width_units), ("height_units", self.height_units)):
            if isinstance(value, bool) or not isinstance(value, int) or not MIN_UNITS <= value <= MAX_UNITS:
                raise ConfigError(
                    f"random grid {field} must be a whole number of {CELL_M:g} m cells from "
                    f"{MIN_UNITS} to {MAX_UNITS}, not {value!r}"
                )

    @classmethod
    def from_area(cls, area_m2: float) -> RandomGridGenerator:
        """The grid nearest ``area_m2`` with sides in proportion about 4:3 (from 1:1 to 5:3).

        Raises:
            ConfigError: If the area gives a side under 5 or over 200 cells.
        """
        from realistic_indoor.generator.base import check_area

        low = MIN_UNITS * MIN_UNITS * CELL_M**2
        high = MAX_UNITS * MAX_UNITS * CELL_M**2
        area = check_area("random grid", area_m2, low, high)
        cells = area / CELL_M**2
        side = math.sqrt(cells * 4 / 3)
        pairs = [
            (w, h)
            for w in range(max(MIN_UNITS, int(side * 0.8)), min(MAX_UNITS, int(side * 1.3) + 2) + 1)
            for h in range(MIN_UNITS, w + 1)
            if w <= 5 * h / 3
        ]
        width, height = min(pairs, key=lambda p: (abs(p[0] * p[1] - cells), abs(p[0] / p[1] - 4 / 3)))
        return cls(width_units=width, height_units=height)

    def __call__(self, rng: np.random.Generator) -> Building:
        """A new map drawn with ``rng``."""
        plan = _grid_plan(rng, self.width_units, self.height_units)
        _doors(plan, rng)
        params = {"width_units": self.width_units, "height_units": self.height_units, "cell_m": CELL_M}
        return finish(plan, rng, "office", {"generator": "random", "params": params})
