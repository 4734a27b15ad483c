"""The corridor skeleton of a wing building: straight corridor lines on a coarse lattice.

A skeleton is a graph on lattice points ``(i, j)``: horizontal edges join ``(i, j)`` and
``(i + 1, j)``, vertical ones ``(i, j)`` and ``(i, j + 1)``. Every lattice column ``i`` has three
bands across it (rooms, corridor, rooms: ``cols[i]``), every row ``j`` likewise (``rows[j]``), and
consecutive columns and rows are ``col_gaps``/``row_gaps`` apart. A node is a junction block
(where corridors meet, turn, end, or where a hall is), an edge a wing: a corridor with a strip of
rooms on either side. Because every wing lives in its own lattice cell, wings never overlap, and
the footprint's proportions follow from the shape (bar, L, T, U, H, E, cross, courtyard, deep
plan, grid of courtyards) and the edge lengths.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from realistic_indoor.generator.sampling import choice_index

if TYPE_CHECKING:
    import numpy as np

__all__ = ["DIRS", "SHAPES", "Skeleton", "sample_shape"]

DIRS = {"E": (1, 0), "W": (-1, 0), "N": (0, 1), "S": (0, -1)}
"""Lattice step of each compass direction."""

Node = tuple[int, int]


@dataclass
class Skeleton:
    """A corridor skeleton and the sizes of its lattice (grid units).

    Attributes:
        nx: Number of lattice columns.
        ny: Number of lattice rows.
        hedges: Horizontal edges, by their western node.
        vedges: Vertical edges, by their southern node.
        cols: Per column, widths of its three bands (west rooms, corridor, east rooms).
        rows: Per row, heights of its three bands (south rooms, corridor, north rooms).
        col_gaps: Length of the wing between column ``i`` and ``i + 1``.
        row_gaps: Length of the wing between row ``j`` and ``j + 1``.
        halls: Nodes whose whole block is a hall.
        open_ends: ``(node, direction)`` pairs where a corridor runs on to the facade.
        filled: Row-gap faces ``(i, j)`` (between columns ``i, i + 1`` and rows ``j, j + 1``)
            filled by deepening the rooms on both sides (deep plans).
        shape: Name of the shape family.
    """

    nx: int
    ny: int
    hedges: set[Node]
    vedges: set[Node]
    cols: list[list[int]] = field(default_factory=list)
    rows: list[list[int]] = field(default_factory=list)
    col_gaps: list[int] = field(default_factory=list)
    row_gaps: list[int] = field(default_factory=list)
    halls: set[Node] = field(default_factory=set)
    open_ends: set[tuple[Node, str]] = field(default_factory=set)
    filled: set[Node] = field(default_factory=set)
    shape: str = ""

    def dirs(self, node: Node) -> set[str]:
        """Directions in which edges leave ``node``."""
        i, j = node
        out = set()
        if (i, j) in self.hedges:
            out.add("E")
        if (i - 1, j) in self.hedges:
            out.add("W")
        if (i, j) in self.vedges:
            out.add("N")
        if (i, j - 1) in self.vedges:
            out.add("S")
        return out

    def nodes(self) -> list[Node]:
        """Every node that an edge touches, in lattice order."""
        pts = {p for i, j in self.hedges for p in ((i, j), (i + 1, j))}
        pts |= {p for i, j in self.vedges for p in ((i, j), (i, j + 1))}
        return sorted(pts)

    def has_vertical(self, i: int) -> bool:
        """Whether any vertical wing runs along column ``i``."""
        return any(e[0] == i for e in self.vedges)

    def has_horizontal(self, j: int) -> bool:
        """Whether any horizontal wing runs along row ``j``."""
        return any(e[1] == j for e in self.hedges)


@dataclass(frozen=True)
class ShapeSpec:
    """A skeleton shape before sizing: spine length, ribs, closing run, deep plan."""

    name: str
    spine: int
    ribs: tuple[tuple[int, int, int], ...] = ()
    closure: int = 0
    deep: bool = False
    rows: int = 0


def _bar(rng: np.random.Generator, n: int) -> ShapeSpec:
    return ShapeSpec("bar", max(1, n))


def _l(rng: np.random.Generator, n: int) -> ShapeSpec:
    k = max(1, round(n * rng.uniform(0.3, 0.5)))
    m = max(1, n - k)
    return ShapeSpec("L", m, ((int(rng.choice([0, m])), int(rng.choice([-1, 1])), k),))


def _t(rng: np.random.Generator, n: int) -> ShapeSpec:
    k = max(1, round(n * rng.uniform(0.3, 0.45)))
    m = max(2, n - k)
    return ShapeSpec("T", m, ((int(rng.integers(1, m)), 1, k),))


def _cross(rng: np.random.Generator, n: int) -> ShapeSpec:
    k = max(1, round(n * rng.uniform(0.2, 0.3)))
    m = max(2, n - 2 * k)
    at = int(rng.integers(1, m))
    return ShapeSpec("cross", m, ((at, 1, k), (at, -1, k)))


def _u(rng: np.random.Generator, n: int) -> ShapeSpec:
    m = max(2, round(n * rng.uniform(0.3, 0.5)))
    k = max(1, round((n - m) / 2))
    return ShapeSpec("U", m, ((0, 1, k), (m, 1, k)))


def _h(rng: np.random.Generator, n: int) -> ShapeSpec:
    m = max(1, round(n * rng.uniform(0.15, 0.35)))
    k = max(1, round((n - m) / 4))
    return ShapeSpec("H", m, ((0, 1, k), (0, -1, k), (m, 1, k), (m, -1, k)))


def _e(rng: np.random.Generator, n: int) -> ShapeSpec:
    m = max(2, 2 * round(n * rng.uniform(0.25, 0.4) / 2))
    k = max(1, round((n - m) / 3))
    return ShapeSpec("E", m, ((0, 1, k), (m // 2, 1, k), (m, 1, k)))


def _comb(rng: np.random.Generator, n: int) -> ShapeSpec:
    """A spine with ribs at every other node, on one side (a comb) or both (a fishbone)."""
    k = 1 if n < 14 else int(rng.integers(1, 3))
    every = 2
    sides = (1,) if rng.random() < 0.5 else (1, -1)
    per_node = len(sides) * k / every
    m = max(2, round(n / (1 + per_node)))
    ribs = tuple((at, side, k) for at in range(0, m + 1, every) for side in sides)
    return ShapeSpec("comb", m, ribs)


def _court(rng: np.random.Generator, n: int) -> ShapeSpec:
    """Two parallel wings joined by cross wings: one courtyard, or a ladder of several."""
    k = 1 if n < 12 else int(rng.integers(1, 3))
    courts = 1 if n < 16 else int(rng.integers(1, 4))
    m = max(2 * courts, round((n - k * (courts + 1)) / 2))
    cols = sorted({round(m * c / courts) for c in range(courts + 1)})
    return ShapeSpec("court", m, tuple((at, 1, k) for at in cols), closure=k)


def _grid(rng: np.random.Generator, n: int) -> ShapeSpec:
    """Several parallel wings joined by cross wings: a block of courtyards (large buildings)."""
    rows = max(2, round(math.sqrt(n / rng.uniform(2.0, 3.0))))
    every = int(rng.integers(2, 5))
    m = max(2, round(n / rows))
    for _ in range(3):
        crossings = m // every + 1
        m = max(2, round((n - (rows - 1) * crossings) / rows))
    cols = sorted(set(range(0, m + 1, every)) | {m})
    return ShapeSpec("grid", m, tuple((at, 1, rows - 1) for at in cols), closure=rows - 1, rows=rows)


def _deep(rng: np.random.Generator, n: int) -> ShapeSpec:
    m = max(1, (n - 2) // 2)
    ribs = [(0, 1, 1), (m, 1, 1)]
    if m >= 4:
        ribs.append((m // 2, 1, 1))
    return ShapeSpec("deep", m, tuple(ribs), closure=1, deep=True)


SHAPES = {
    "bar": (_bar, 1, 5),
    "L": (_l, 2, 9),
    "T": (_t, 3, 10),
    "cross": (_cross, 4, 14),
    "U": (_u, 4, 16),
    "H": (_h, 5, 20),
    "E": (_e, 5, 20),
    "comb": (_comb, 5, 40),
    "court": (_court, 4, 40),
    "grid": (_grid, 14, 100_000),
    "deep": (_deep, 4, 24),
}
"""Shape families: the function that draws one, and the fewest and most edges it suits."""


def sample_shape(rng: np.random.Generator, n_edges: int, weights: dict[str, float]) -> Skeleton:
    """Draw a skeleton shape with about ``n_edges`` wing segments (sizes are set later).

    Args:
        rng: Random source.
        n_edges: Number of wing segments wanted (1 or more).
        weights: Relative frequency of each family of :data:`SHAPES`; families needing more
            edges than ``n_edges`` are left out.

    Returns:
        A skeleton with its graph, shape name and, for deep plans, the filled faces; band and
        gap sizes are left empty.
    """
    names = [k for k, w in weights.items() if w > 0 and SHAPES[k][1] <= n_edges <= SHAPES[k][2]]
    if not names:
        names = ["bar"] if n_edges <= SHAPES["bar"][2] else ["grid"]
    p = [weights.get(k, 1.0) for k in names]
    name = names[choice_index(rng, [w / sum(p) for w in p])]
    spec = SHAPES[name][0](rng, n_edges)
    return _build(spec)


def _build(spec: ShapeSpec) -> Skeleton:
    hedges = {(i, 0) for i in range(spec.spine)}
    vedges = set()
    for at, side, k in spec.ribs:
        for s in range(k):
            vedges.add((at, s) if side > 0 else (at, -s - 1))
    filled = set()
    if spec.closure:
        hedges |= {(i, spec.closure) for i in range(spec.spine)}
    for j in range(1, spec.rows - 1):
        hedges |= {(i, j) for i in range(spec.spine)}
    if spec.deep:
        filled = {(i, 0) for i in range(spec.spine)}
    j0 = -min([0] + [e[1] for e in vedges])
    hedges = {(i, j + j0) for i, j in hedges}
    vedges = {(i, j + j0) for i, j in vedges}
    filled = {(i, j + j0) for i, j in filled}
    ny = 1 + max([j for _, j in hedges] + [j + 1 for _, j in vedges])
    return Skeleton(spec.spine + 1, ny, hedges, vedges, filled=filled, shape=spec.name)
