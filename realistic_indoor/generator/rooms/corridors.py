"""Cutting straight corridor pieces into segments, as real plans divide long corridors."""

from __future__ import annotations

from typing import TYPE_CHECKING

from realistic_indoor.generator.geometry import Rect, contacts_by_pair

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.plan import Plan

__all__ = ["corridor_fronts", "segment_corridors"]


def corridor_fronts(plan: Plan, pieces: list[Rect]) -> list[list[tuple[int, int]]]:
    """For each corridor piece, the spans along it of the plan's rooms touching its long sides."""
    shapes = [[p] for p in pieces] + [r.rects for r in plan.rooms]
    out: list[list[tuple[int, int]]] = [[] for _ in pieces]
    for (k, j), walls in contacts_by_pair(shapes).items():
        if k < len(pieces) <= j:
            x0, y0, x1, y1 = pieces[k]
            axis = "h" if (x1 - x0) >= (y1 - y0) else "v"
            out[k] += [(w.lo, w.hi) for w in walls if w.axis == axis]
    return out


def _long(r: Rect) -> tuple[int, int, bool]:
    """Start and end along the long side, and whether that side runs along x."""
    along_x = (r[2] - r[0]) >= (r[3] - r[1])
    return (r[0], r[2], True) if along_x else (r[1], r[3], False)


def segment_corridors(
    pieces: list[Rect],
    n_segments: int,
    rng: np.random.Generator,
    min_length: int,
    junctions: list[Rect],
    fronts: list[list[tuple[int, int]]],
    need: int,
) -> list[Rect]:
    """Cut corridor pieces into about ``n_segments`` segments in all.

    Extra cuts go to the longest pieces first (in proportion to length), never making a segment
    shorter than ``min_length``. A cut is moved onto a nearby junction (the side of a corridor or
    hall that meets the piece), where real plans divide corridors, never falls inside the span
    where a junction meets the piece, and never leaves a room along the corridor without ``need``
    of wall on one segment for its door.

    Args:
        pieces: Straight corridor rectangles (units).
        n_segments: Number of segments wanted over all pieces (at least one per piece).
        rng: Random source.
        min_length: Shortest segment (units).
        junctions: Rectangles of other circulation spaces; their sides are preferred cut points.
        fronts: Per piece, the spans along it of the rooms that open onto it.
        need: Wall a door needs with its clearances (units).

    Returns:
        The segments, piece by piece in order along each piece.
    """
    lengths = [_long(r)[1] - _long(r)[0] for r in pieces]
    capacity = [max(0, length // max(min_length, 1) - 1) for length in lengths]
    cuts = [0] * len(pieces)
    for _ in range(max(0, n_segments - len(pieces))):
        best, best_len = -1, 0.0
        for k, length in enumerate(lengths):
            seg = length / (cuts[k] + 1)
            if cuts[k] < capacity[k] and seg > best_len:
                best, best_len = k, seg
        if best < 0:
            break
        cuts[best] += 1
    out = []
    for r, n, front in zip(pieces, cuts, fronts, strict=True):
        out += _cut(r, n, rng, min_length, junctions, front, need)
    return out


def _cut(
    r: Rect,
    n: int,
    rng: np.random.Generator,
    min_length: int,
    junctions: list[Rect],
    front: list[tuple[int, int]],
    need: int,
) -> list[Rect]:
    a, b, along_x = _long(r)
    if n <= 0:
        return [r]
    seg = (b - a) / (n + 1)
    preferred = _junction_points(r, along_x, junctions)
    inside = _junction_spans(r, along_x, junctions)
    candidates = sorted(
        p for p in _fine_points(a, b, front, need) if not any(lo < p < hi for lo, hi in inside)
    )
    points = []
    prev = a
    for k in range(1, n + 1):
        p = round(a + k * seg + rng.uniform(-0.2, 0.2) * seg)
        near = [q for q in preferred if abs(q - p) <= 0.35 * seg]
        if near:
            p = min(near, key=lambda q: abs(q - p))
        lo, hi = prev + min_length, b - min_length * (n + 1 - k)
        ok = [q for q in candidates if lo <= q <= hi and _door_room(q, front, need)]
        if not ok:
            continue
        p = min(ok, key=lambda q: abs(q - p))
        points.append(p)
        prev = p
    edges = [a, *points, b]
    if along_x:
        return [(edges[k], r[1], edges[k + 1], r[3]) for k in range(len(edges) - 1)]
    return [(r[0], edges[k], r[2], edges[k + 1]) for k in range(len(edges) - 1)]


def _fine_points(a: int, b: int, front: list[tuple[int, int]], need: int) -> list[int]:
    """Positions worth trying as cuts: room boundaries and every 10 units in between."""
    pts = {v for lo, hi in front for v in (lo, hi)} | set(range(a, b, 10))
    return [p for p in pts if a < p < b]


def _door_room(p: int, front: list[tuple[int, int]], need: int) -> bool:
    """Whether a cut at ``p`` leaves every room it crosses ``need`` of wall on one side."""
    return all(max(p - lo, hi - p) >= need for lo, hi in front if lo < p < hi)


def _junction_spans(r: Rect, along_x: bool, junctions: list[Rect]) -> list[tuple[int, int]]:
    """Spans along ``r`` over which another circulation space meets its side.

    A cut inside one would let that space open onto both segments: a loop of three spaces that
    real plans do not have.
    """
    out = []
    for j in junctions:
        if along_x and (j[1] == r[3] or j[3] == r[1]) and j[0] < r[2] and j[2] > r[0]:
            out.append((j[0], j[2]))
        elif not along_x and (j[0] == r[2] or j[2] == r[0]) and j[1] < r[3] and j[3] > r[1]:
            out.append((j[1], j[3]))
    return out


def _junction_points(r: Rect, along_x: bool, junctions: list[Rect]) -> list[int]:
    """Positions along ``r`` where another circulation space meets its side."""
    lo, hi = (r[0], r[2]) if along_x else (r[1], r[3])
    return sorted({v for span in _junction_spans(r, along_x, junctions) for v in span if lo < v < hi})
