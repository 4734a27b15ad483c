"""Sizes of a skeleton: room depths and corridor widths of every line, halls, and wing lengths.

Wing lengths are scaled together so that the footprint has the requested area; the area is a
quadratic in the scale (cells are products of band widths), solved exactly.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from realistic_indoor.generator.geometry import to_units
from realistic_indoor.generator.sampling import choice_index
from realistic_indoor.generator.wings.paint import footprint_cells
from realistic_indoor.generator.wings.skeleton import DIRS

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.rooms.dims import Dims
    from realistic_indoor.generator.wings.skeleton import Skeleton
    from realistic_indoor.generator.wings.style import WingStyle

__all__ = ["MIN_COURT_M", "MIN_GAP_M", "choose_halls", "choose_open_ends", "size_skeleton"]

MIN_GAP_M = 3.0
"""Shortest wing between two junctions (m); shorter ones would leave slivers of rooms."""

MIN_COURT_M = 9.0
"""Narrowest courtyard between two parallel wings (m); narrower ones are built over, the rooms
on both sides growing deeper (a deep plan)."""


def choose_halls(sk: Skeleton, rng: np.random.Generator, n_halls: int, junction_share: float) -> None:
    """Make up to ``n_halls`` nodes halls: the entrance first, then junctions and straight runs.

    The entrance hall sits on a node with a free side (a straight run or a T), nearest the middle
    of the building; a share ``junction_share`` of the other halls go to junctions of three or
    more wings, the rest to straight runs, and dead ends when nothing else is left.
    """
    nodes = sk.nodes()
    dirs = {n: sk.dirs(n) for n in nodes}
    straight = [n for n in nodes if dirs[n] in ({"E", "W"}, {"N", "S"})]
    junctions = [n for n in nodes if len(dirs[n]) >= 3]
    ends = [n for n in nodes if len(dirs[n]) == 1]
    if n_halls <= 0:
        return
    ci, cj = (sk.nx - 1) / 2, (sk.ny - 1) / 2
    first = straight + [n for n in junctions if len(dirs[n]) == 3]
    if first:
        weights = [1.0 / (1.0 + abs(i - ci) + abs(j - cj)) for i, j in first]
        sk.halls.add(first[choice_index(rng, [w / sum(weights) for w in weights])])
    near = {n for h in sk.halls for n in _around(h, dirs[h])}
    for _ in range(n_halls - len(sk.halls)):
        pick = _next_hall(sk, rng, (junctions, straight + ends), near, junction_share)
        if pick is None:
            break
        sk.halls.add(pick)
        near |= set(_around(pick, dirs[pick]))


def _around(node: tuple[int, int], dirs: set[str]) -> list[tuple[int, int]]:
    return [(node[0] + DIRS[d][0], node[1] + DIRS[d][1]) for d in dirs]


def _next_hall(
    sk: Skeleton,
    rng: np.random.Generator,
    pools: tuple[list[tuple[int, int]], list[tuple[int, int]]],
    near: set[tuple[int, int]],
    junction_share: float,
) -> tuple[int, int] | None:
    """The next hall: a junction or a straight run apart from other halls, else any free node."""
    for apart in (True, False):
        free_j, free_s = (
            [n for n in pool if n not in sk.halls and not (apart and n in near)] for pool in pools
        )
        pool = free_j if (free_j and (rng.random() < junction_share or not free_s)) else free_s
        if pool:
            return pool[int(rng.integers(len(pool)))]
    return None


def choose_open_ends(sk: Skeleton, rng: np.random.Generator, p_open: float) -> None:
    """Let dead-end corridors run on to the facade with probability ``p_open`` each."""
    opposite = {"E": "W", "W": "E", "N": "S", "S": "N"}
    for node in sk.nodes():
        dirs = sk.dirs(node)
        if len(dirs) == 1 and node not in sk.halls and rng.random() < p_open:
            sk.open_ends.add((node, opposite[next(iter(dirs))]))


def _sides(rng: np.random.Generator, dims: Dims, style: WingStyle) -> list[int]:
    kinds = list(style.side_weights)
    w = [style.side_weights[k] for k in kinds]
    kind = kinds[choice_index(rng, [x / sum(w) for x in w])]

    def deep() -> int:
        return round(dims.depth * rng.uniform(0.9, 1.12))

    if kind == "double":
        out = [deep(), deep()]
    elif kind == "single":
        out = [deep(), 0]
    else:
        out = [deep(), round(dims.shallow * rng.uniform(0.9, 1.1))]
    if rng.random() < 0.5:
        out.reverse()
    return out


def _end_length(rng: np.random.Generator) -> int:
    return to_units(rng.uniform(1.6, 2.6))


def _line_bands(sk: Skeleton, rng: np.random.Generator, dims: Dims, style: WingStyle) -> None:
    """Bands of every column and row: room strips where wings run, end pieces elsewhere."""
    sk.cols = _axis_bands(sk.nx, sk.has_vertical, rng, dims, style)
    sk.rows = _axis_bands(sk.ny, sk.has_horizontal, rng, dims, style)
    _deepen_filled(sk, {j for _, j in sk.filled}, dims)


def _axis_bands(n: int, has_wing, rng: np.random.Generator, dims: Dims, style: WingStyle) -> list[list[int]]:
    """Bands of the lattice lines along one axis (first/last lines get end pieces outwards)."""
    out = []
    for i in range(n):
        if has_wing(i):
            a, b = _sides(rng, dims, style)
            out.append([a, dims.corridor, b])
        else:
            low = _end_length(rng) if i == 0 else 0
            high = _end_length(rng) if i == n - 1 else 0
            out.append([low, to_units(rng.uniform(1.5, 3.0)), high])
    return out


def _deepen_filled(sk: Skeleton, rows: set[int], dims: Dims) -> None:
    """Rooms on both sides of a built-over courtyard (rows ``j`` and ``j + 1``) get a full strip."""
    for j in rows:
        sk.rows[j][2] = max(sk.rows[j][2], dims.depth)
        sk.rows[j + 1][0] = max(sk.rows[j + 1][0], dims.depth)


def _hall_bands(sk: Skeleton, rng: np.random.Generator, dims: Dims) -> None:
    """Size the blocks of halls off vertical (horizontal) wings to a hall's area.

    A hall in a column without vertical wings takes the width that gives it a hall's area over
    its row's depth (likewise in a row without horizontal wings); junction halls keep the size
    their wings give them.
    """
    for i, j in sorted(sk.halls):
        if not sk.has_vertical(i):
            sk.cols[i] = _hall_span(rng, dims, sum(sk.rows[j]), sk.cols[i])
        elif not sk.has_horizontal(j):
            sk.rows[j] = _hall_span(rng, dims, sum(sk.cols[i]), sk.rows[j])


def _hall_span(rng: np.random.Generator, dims: Dims, across: int, bands: list[int]) -> list[int]:
    width = rng.uniform(0.9, 1.8) * dims.hall_area / max(across, 1)
    width = min(max(width, 1.3 * dims.corridor, to_units(4.0)), 3.0 * across)
    side = round((width - dims.corridor) / 2)
    return [max(side, bands[0]), dims.corridor, max(side, bands[2])]


def size_skeleton(
    sk: Skeleton,
    rng: np.random.Generator,
    dims: Dims,
    style: WingStyle,
    area_units: float,
    halls: tuple[int, float],
) -> float:
    """Give the skeleton band sizes, halls, open ends and gap lengths for ``area_units``.

    Args:
        sk: The skeleton (its graph and shape).
        rng: Random source.
        dims: Corridor width and room depths.
        style: The type's conventions (sides of corridors, open ends).
        area_units: Footprint area wanted (square units).
        halls: Number of halls wanted and the share of them at junctions.

    Returns:
        The mean wing length (m) the area called for (0 if the junctions alone exceed the area);
        the caller rejects shapes whose wings come out too short or too long.
    """
    _line_bands(sk, rng, dims, style)
    choose_halls(sk, rng, halls[0], halls[1])
    choose_open_ends(sk, rng, style.open_end_p)
    _hall_bands(sk, rng, dims)
    col_base = [rng.uniform(0.75, 1.25) for _ in range(sk.nx - 1)]
    row_base = [rng.uniform(0.75, 1.25) for _ in range(sk.ny - 1)]
    deep_gap = {j: to_units(rng.uniform(1.0, 5.0)) for _, j in sk.filled}
    scale = _scale(sk, col_base, row_base, deep_gap, area_units)
    narrow = {
        (i, j)
        for i, j in sk.hedges
        if (i, j + 1) in sk.hedges and j not in deep_gap and scale * row_base[j] < to_units(MIN_COURT_M)
    }
    if narrow:
        sk.filled |= narrow
        _deepen_filled(sk, {j for _, j in narrow}, dims)
        scale = _scale(sk, col_base, row_base, deep_gap, area_units)
    shortest = to_units(MIN_GAP_M)
    sk.col_gaps = [max(shortest, round(scale * b)) for b in col_base]
    sk.row_gaps = [deep_gap.get(j, max(shortest, round(scale * b))) for j, b in enumerate(row_base)]
    scalable = col_base + [b for j, b in enumerate(row_base) if j not in deep_gap]
    return scale * (sum(scalable) / len(scalable)) / to_units(1.0) if scalable else 0.0


def _scale(
    sk: Skeleton, col_base: list[float], row_base: list[float], fixed: dict[int, int], area_units: float
) -> float:
    """The factor on the gaps' base lengths that gives the footprint ``area_units``."""
    X, Y, grid = footprint_cells(sk)

    def widths(bands, node_bands, base, fixed):
        """Per fine band: (constant, coefficient of the scale)."""
        out = []
        for kind, i in bands.keys:
            if kind in ("L", "C", "R"):
                out.append((node_bands[i]["LCR".index(kind)], 0.0))
            elif i in fixed:
                out.append((fixed[i] / (2 if kind != "G" else 1), 0.0))
            else:
                out.append((0.0, base[i] / (2 if kind != "G" else 1)))
        return out

    xw = widths(X, sk.cols, col_base, {})
    yw = widths(Y, sk.rows, row_base, fixed)
    a0 = a1 = a2 = 0.0
    for k, m in grid:
        (p, q), (r, s) = xw[k], yw[m]
        a0 += p * r
        a1 += p * s + q * r
        a2 += q * s
    return _solve(a2, a1, a0 - area_units)


def _solve(a: float, b: float, c: float) -> float:
    """The positive root of ``a s^2 + b s + c = 0`` (0 if there is none)."""
    if a <= 1e-12:
        return max(-c / b, 0.0) if b > 0 else 0.0
    disc = b * b - 4 * a * c
    if disc < 0:
        return 0.0
    return max((-b + math.sqrt(disc)) / (2 * a), 0.0)
