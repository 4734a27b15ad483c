"""Axis-aligned rectangles on the generator's integer grid, and the walls they share.

Generation works in integer grid units of :data:`UNIT_M` metres so that shared walls are found
by exact comparison; coordinates become metres only when the ``Building`` is built. Lengths
convert with :func:`to_units` and :func:`to_metres`, areas (m2 and square units) with
:func:`area_to_units` and :func:`area_to_m2`.
"""

from __future__ import annotations

from collections import defaultdict
from typing import NamedTuple

__all__ = [
    "UNITS2_PER_M2",
    "UNITS_PER_M",
    "UNIT_M",
    "Contact",
    "Rect",
    "area_to_m2",
    "area_to_units",
    "contact",
    "contacts_by_pair",
    "outline",
    "subtract_intervals",
    "to_metres",
    "to_units",
]

UNITS_PER_M = 10
"""Grid units per metre: every wall lies on a 0.1 m grid."""

UNIT_M = 1 / UNITS_PER_M
"""Size of one grid unit (m)."""

UNITS2_PER_M2 = UNITS_PER_M**2
"""Square grid units per square metre (100: one square unit is 0.01 m2)."""

Rect = tuple[int, int, int, int]
"""``(x0, y0, x1, y1)`` in grid units, ``x0 < x1`` and ``y0 < y1``."""


class Contact(NamedTuple):
    """A wall piece shared by two rectangles.

    Attributes:
        axis: ``"v"`` for a vertical wall (at ``x = coord``), ``"h"`` for a horizontal one.
        coord: The wall's fixed coordinate (units).
        lo: Start of the shared piece along the wall (units).
        hi: End of the shared piece (units).
    """

    axis: str
    coord: int
    lo: int
    hi: int

    @property
    def length(self) -> int:
        """Length of the shared piece (units)."""
        return self.hi - self.lo


def to_units(metres: float) -> int:
    """A length in metres rounded to whole grid units."""
    return round(metres * UNITS_PER_M)


def to_metres(units: float) -> float:
    """Grid units in metres (a division, so 3 units print as 0.3)."""
    return units / UNITS_PER_M


def area_to_units(m2: float) -> float:
    """An area in square grid units, not rounded.

    Args:
        m2: The area (m2).

    Returns:
        The same area (square units): ``m2 * UNITS2_PER_M2``.

    Examples:
        >>> area_to_units(12.5)
        1250.0
    """
    return m2 * UNITS2_PER_M2


def area_to_m2(units2: float) -> float:
    """An area in square metres.

    Args:
        units2: The area (square units).

    Returns:
        The same area (m2): ``units2 / UNITS2_PER_M2``.

    Examples:
        >>> area_to_m2(1250)
        12.5
    """
    return units2 / UNITS2_PER_M2


def contact(a: Rect, b: Rect) -> Contact | None:
    """The wall piece two rectangles share, or ``None`` if they only meet at a corner or not at all."""
    if a[2] == b[0] or a[0] == b[2]:
        lo, hi = max(a[1], b[1]), min(a[3], b[3])
        if hi > lo:
            return Contact("v", a[2] if a[2] == b[0] else a[0], lo, hi)
    if a[3] == b[1] or a[1] == b[3]:
        lo, hi = max(a[0], b[0]), min(a[2], b[2])
        if hi > lo:
            return Contact("h", a[3] if a[3] == b[1] else a[1], lo, hi)
    return None


def contacts_by_pair(shapes: list[list[Rect]]) -> dict[tuple[int, int], list[Contact]]:
    """Every shared wall piece between shapes (each shape a list of rectangles).

    Rectangles are indexed by the coordinates of their sides, so the cost grows with the number
    of rectangles, not its square.

    Returns:
        ``{(i, j): contacts}`` for shape indices ``i < j`` that share at least one wall piece.
    """
    by_left: dict[int, list[tuple[int, Rect]]] = defaultdict(list)
    by_bottom: dict[int, list[tuple[int, Rect]]] = defaultdict(list)
    for i, rects in enumerate(shapes):
        for r in rects:
            by_left[r[0]].append((i, r))
            by_bottom[r[1]].append((i, r))
    out: dict[tuple[int, int], list[Contact]] = defaultdict(list)
    for i, rects in enumerate(shapes):
        for r in rects:
            for j, s in by_left.get(r[2], ()):
                if j != i and min(r[3], s[3]) > max(r[1], s[1]):
                    key = (i, j) if i < j else (j, i)
                    out[key].append(Contact("v", r[2], max(r[1], s[1]), min(r[3], s[3])))
            for j, s in by_bottom.get(r[3], ()):
                if j != i and min(r[2], s[2]) > max(r[0], s[0]):
                    key = (i, j) if i < j else (j, i)
                    out[key].append(Contact("h", r[3], max(r[0], s[0]), min(r[2], s[2])))
    return dict(out)


def subtract_intervals(lo: int, hi: int, cuts: list[tuple[int, int]]) -> list[tuple[int, int]]:
    """The parts of ``[lo, hi]`` not covered by any of ``cuts`` (sorted, non-empty)."""
    out, start = [], lo
    for a, b in sorted(cuts):
        if a > start:
            out.append((start, min(a, hi)))
        start = max(start, b)
        if start >= hi:
            break
    if start < hi:
        out.append((start, hi))
    return [(a, b) for a, b in out if b > a]


def outline(rects: list[Rect]) -> list[tuple[int, int]]:
    """The counter-clockwise outline of a union of rectangles that forms one simple polygon.

    Sides shared between the rectangles are dropped, the remaining boundary pieces are chained
    into a ring and collinear vertices removed.
    """
    if len(rects) == 1:
        x0, y0, x1, y1 = rects[0]
        return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    edges = _boundary_edges(rects)
    nxt = {a: b for a, b in edges}
    start = min(nxt)
    ring, p = [start], nxt[start]
    while p != start:
        ring.append(p)
        p = nxt[p]
    return _drop_collinear(ring)


def _boundary_edges(rects: list[Rect]) -> list[tuple[tuple[int, int], tuple[int, int]]]:
    """Directed unit-free boundary pieces of the union, counter-clockwise around the interior."""
    xs = sorted({v for r in rects for v in (r[0], r[2])})
    ys = sorted({v for r in rects for v in (r[1], r[3])})
    col = {x: i for i, x in enumerate(xs)}
    row = {y: j for j, y in enumerate(ys)}
    # filled[i + 1][j + 1]: whether the grid cell between xs[i], xs[i + 1] and ys[j], ys[j + 1] is
    # covered; a border of empty cells stands for the outside
    filled = [[False] * (len(ys) + 1) for _ in range(len(xs) + 1)]
    for r in rects:
        for i in range(col[r[0]], col[r[2]]):
            for j in range(row[r[1]], row[r[3]]):
                filled[i + 1][j + 1] = True
    edges = []
    for i in range(len(xs) - 1):
        for j in range(len(ys) - 1):
            if not filled[i + 1][j + 1]:
                continue
            x0, x1, y0, y1 = xs[i], xs[i + 1], ys[j], ys[j + 1]
            if not filled[i + 1][j]:
                edges.append(((x0, y0), (x1, y0)))
            if not filled[i + 2][j + 1]:
                edges.append(((x1, y0), (x1, y1)))
            if not filled[i + 1][j + 2]:
                edges.append(((x1, y1), (x0, y1)))
            if not filled[i][j + 1]:
                edges.append(((x0, y1), (x0, y0)))
    return edges


def _drop_collinear(ring: list[tuple[int, int]]) -> list[tuple[int, int]]:
    out = []
    n = len(ring)
    for k in range(n):
        a, b, c = ring[k - 1], ring[k], ring[(k + 1) % n]
        if (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]) != 0:
            out.append(b)
    return out
