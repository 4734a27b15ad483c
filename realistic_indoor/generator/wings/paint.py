"""From a sized skeleton to rectangles: corridor lines, halls, room strips (bays) and end rooms.

The lattice is cut into a fine grid of bands (per column: west rooms, corridor, east rooms, then
the gap to the next column; per row likewise). Every fine cell gets one owner: a corridor line,
a hall, a bay of rooms along a corridor, a small end room, or nothing (outside). Cells of the
same owner are then merged into rectangles. The rules that decide which bay a junction's corner
joins make every bay a rectangle that runs along its corridor, whatever the junction.
"""

from __future__ import annotations

from realistic_indoor.generator.geometry import Rect
from realistic_indoor.generator.rooms.regions import Bay, FloorRegions
from realistic_indoor.generator.wings.skeleton import Skeleton

__all__ = ["footprint_cells", "paint"]

Tag = tuple
Cell = tuple[int, int]

_ACCESS = {"HT": "S", "HB": "N", "VL": "E", "VR": "W"}
"""Side of a bay that faces its corridor, by bay kind (a top bay's corridor is to its south)."""


class _Bands:
    """Index of the fine bands along one axis."""

    def __init__(self, n: int, split_gaps: set[int]) -> None:
        self.keys: list[tuple[str, int]] = []
        for i in range(n):
            self.keys += [("L", i), ("C", i), ("R", i)]
            if i < n - 1:
                self.keys += [("G1", i), ("G2", i)] if i in split_gaps else [("G", i)]
        self.index = {k: n for n, k in enumerate(self.keys)}

    def __call__(self, kind: str, i: int) -> int:
        return self.index[(kind, i)]

    def gap(self, i: int) -> list[int]:
        return [self.index[k] for k in (("G", i), ("G1", i), ("G2", i)) if k in self.index]

    def widths(self, node_bands: list[list[int]], gaps: list[int]) -> list[int]:
        out = []
        for kind, i in self.keys:
            if kind in ("L", "C", "R"):
                out.append(node_bands[i]["LCR".index(kind)])
            elif kind == "G":
                out.append(gaps[i])
            else:
                half = gaps[i] // 2
                out.append(half if kind == "G1" else gaps[i] - half)
        return out


def footprint_cells(sk: Skeleton) -> tuple[_Bands, _Bands, dict[Cell, Tag]]:
    """Assign an owner to every fine cell of the skeleton's lattice (sizes not needed)."""
    X = _Bands(sk.nx, set())
    Y = _Bands(sk.ny, {j for _, j in sk.filled})
    grid: dict[Cell, Tag] = {}
    _corridors(sk, X, Y, grid)
    _edge_bays(sk, X, Y, grid)
    for node in sk.nodes():
        _junction(sk, X, Y, grid, node)
    for i, j in sk.nodes():
        if (i, j) in sk.halls:
            for k in (X("L", i), X("C", i), X("R", i)):
                for m in (Y("L", j), Y("C", j), Y("R", j)):
                    grid[(k, m)] = ("hall", i, j)
    return X, Y, grid


def _corridors(sk: Skeleton, X: _Bands, Y: _Bands, grid: dict[Cell, Tag]) -> None:
    arm = {"E": ("R", "C"), "W": ("L", "C"), "N": ("C", "R"), "S": ("C", "L")}
    for i, j in sk.nodes():
        dirs = sk.dirs((i, j))
        horizontal = bool(dirs & {"E", "W"})
        grid[(X("C", i), Y("C", j))] = ("cor", "h", j) if horizontal else ("cor", "v", i)
        opened = {d for (n, d) in sk.open_ends if n == (i, j)}
        for d in dirs | opened:
            kx, ky = arm[d]
            grid[(X(kx, i), Y(ky, j))] = ("cor", "h", j) if d in "EW" else ("cor", "v", i)
    for i, j in sk.hedges:
        for k in X.gap(i):
            grid[(k, Y("C", j))] = ("cor", "h", j)
    for i, j in sk.vedges:
        for m in Y.gap(j):
            grid[(X("C", i), m)] = ("cor", "v", i)


def _edge_bays(sk: Skeleton, X: _Bands, Y: _Bands, grid: dict[Cell, Tag]) -> None:
    for i, j in sk.hedges:
        for k in X.gap(i):
            grid[(k, Y("L", j))] = ("bay", "HB", j)
            grid[(k, Y("R", j))] = ("bay", "HT", j)
    for i, j in sk.vedges:
        for m in Y.gap(j):
            grid[(X("L", i), m)] = ("bay", "VL", i)
            grid[(X("R", i), m)] = ("bay", "VR", i)
    for i, j in sorted(sk.filled):
        g1, g2 = Y("G1", j), Y("G2", j)
        cols = X.gap(i)
        for side in (i, i + 1):
            if not sk.has_vertical(side) or (side, j) not in sk.vedges:
                cols += [X("L", side), X("C", side), X("R", side)]
        for k in cols:
            grid.setdefault((k, g1), ("bay", "HT", j))
            grid.setdefault((k, g2), ("bay", "HB", j + 1))


def _junction(sk: Skeleton, X: _Bands, Y: _Bands, grid: dict[Cell, Tag], node: tuple[int, int]) -> None:
    """Give the non-corridor cells of a junction block to the bays around it (see module doc)."""
    i, j = node
    dirs = sk.dirs(node)
    xs = (X.index[("L", i)], X.index[("C", i)], X.index[("R", i)])
    ys = (Y.index[("L", j)], Y.index[("C", j)], Y.index[("R", j)])

    def give(cells: tuple[Cell, Cell, Cell], first: str, last: str, tag: Tag) -> None:
        """Hand a row of three block cells to a bay.

        The ends go on the sides the junction opens to (``first``, ``last``) when the middle
        cell is corridor; otherwise all three go, if the junction opens to either side.
        """
        if grid.get(cells[1], ("",))[0] == "cor":
            for cell, side in ((cells[0], first), (cells[2], last)):
                if side in dirs:
                    grid.setdefault(cell, tag)
        elif first in dirs or last in dirs:
            for cell in cells:
                grid.setdefault(cell, tag)

    for dy, kind in ((2, "HT"), (0, "HB")):
        give(((xs[0], ys[dy]), (xs[1], ys[dy]), (xs[2], ys[dy])), "W", "E", ("bay", kind, j))
    for dx, kind in ((0, "VL"), (2, "VR")):
        give(((xs[dx], ys[0]), (xs[dx], ys[1]), (xs[dx], ys[2])), "S", "N", ("bay", kind, i))
    for c in ((xs[0], ys[1]), (xs[2], ys[1]), (xs[1], ys[0]), (xs[1], ys[2])):
        grid.setdefault(c, ("end", i, j))


def paint(sk: Skeleton) -> FloorRegions:
    """Rectangles of every corridor line, hall, bay and end room of a sized skeleton."""
    X, Y, grid = footprint_cells(sk)
    xw = X.widths(sk.cols, sk.col_gaps)
    yw = Y.widths(sk.rows, sk.row_gaps)
    xs = _cumulative(xw)
    ys = _cumulative(yw)
    out = FloorRegions(area=sum(xw[k] * yw[m] for k, m in grid))

    def rect(k0: int, m0: int, k1: int, m1: int) -> Rect:
        return (xs[k0], ys[m0], xs[k1 + 1], ys[m1 + 1])

    by_tag: dict[Tag, list[Cell]] = {}
    for c in sorted(grid):
        by_tag.setdefault(grid[c], []).append(c)
    for tag, cells in by_tag.items():
        kind = tag[0]
        if kind == "cor":
            out.corridors += [rect(*r) for r in _runs(cells, along_x=tag[1] == "h")]
        elif kind == "hall":
            ks, ms = [c[0] for c in cells], [c[1] for c in cells]
            out.halls.append(((tag[1], tag[2]), [rect(min(ks), min(ms), max(ks), max(ms))]))
        elif kind == "bay":
            along_x = tag[1] in ("HT", "HB")
            for r in _strips(cells, along_x):
                out.bays.append(Bay(rect(*r), "x" if along_x else "y", _ACCESS[tag[1]]))
        else:
            out.ends += [rect(k, m, k, m) for k, m in cells]
    out.holes = _holes(grid, xs, ys)
    out.corridors = [r for r in out.corridors if _solid(r)]
    out.bays = [b for b in out.bays if _solid(b.rect)]
    out.ends = [r for r in out.ends if _solid(r)]
    return out


def _solid(r: Rect) -> bool:
    return r[2] > r[0] and r[3] > r[1]


def _cumulative(widths: list[int]) -> list[int]:
    out = [0]
    for w in widths:
        out.append(out[-1] + w)
    return out


def _consecutive(values: list[int], key=lambda v: None) -> list[tuple[int, int]]:
    """``(first, last)`` of each run of consecutive sorted ``values`` with the same ``key``."""
    out: list[tuple[int, int]] = []
    for v in values:
        if out and v == out[-1][1] + 1 and key(v) == key(out[-1][1]):
            out[-1] = (out[-1][0], v)
        else:
            out.append((v, v))
    return out


def _runs(cells: list[Cell], along_x: bool) -> list[tuple[int, int, int, int]]:
    """Maximal straight runs of cells in one band: ``(k0, m0, k1, m1)`` index boxes."""
    lines: dict[int, list[int]] = {}
    for k, m in cells:
        fixed, moving = (m, k) if along_x else (k, m)
        lines.setdefault(fixed, []).append(moving)
    out = []
    for fixed, moving in lines.items():
        for a, b in _consecutive(sorted(moving)):
            out.append((a, fixed, b, fixed) if along_x else (fixed, a, fixed, b))
    return out


def _strips(cells: list[Cell], along_x: bool) -> list[tuple[int, int, int, int]]:
    """Rectangles of a bay's cells: consecutive columns (rows) with the same cross extent."""
    across: dict[int, list[int]] = {}
    for k, m in cells:
        a, b = (k, m) if along_x else (m, k)
        across.setdefault(a, []).append(b)
    extent = {a: (min(v), max(v)) for a, v in across.items()}
    out = []
    for a, b in _consecutive(sorted(extent), key=extent.get):
        lo, hi = extent[a]
        out.append((a, lo, b, hi) if along_x else (lo, a, hi, b))
    return out


def _holes(grid: dict[Cell, Tag], xs: list[int], ys: list[int]) -> list[Rect]:
    """Outside cells that cannot reach the lattice's border: courtyards."""
    nk, nm = len(xs) - 1, len(ys) - 1
    outside = {(k, m) for k in range(nk) for m in range(nm)} - set(grid)
    free = [c for c in outside if c[0] in (0, nk - 1) or c[1] in (0, nm - 1)]
    seen = set(free)
    while free:
        k, m = free.pop()
        for c in ((k + 1, m), (k - 1, m), (k, m + 1), (k, m - 1)):
            if c in outside and c not in seen:
                seen.add(c)
                free.append(c)
    return [
        (xs[k], ys[m], xs[k + 1], ys[m + 1])
        for k, m in sorted(outside - seen)
        if xs[k + 1] > xs[k] and ys[m + 1] > ys[m]
    ]
