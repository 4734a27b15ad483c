"""Compiled interval passes of :mod:`realistic_indoor.building.rect_walls` (numba, loaded lazily).

Each takes the pieces of wall on lines of one direction as three arrays (the line's coordinate,
the low and the high end, metres) and returns new ones, in the order the NumPy expressions they
replace gave.
"""

from __future__ import annotations

import numpy as np
from numba import njit

__all__ = ["cut_pieces", "merge_sides", "split_pieces"]


@njit(cache=True, nogil=True)
def merge_sides(line, lo, hi):  # pragma: no cover - compiled
    """Sides sorted by line, then low end, joined where they overlap or touch on a line."""
    n = line.shape[0]
    out_line, out_lo, out_hi = np.empty(n), np.empty(n), np.empty(n)
    k = -1
    for i in range(n):
        if k >= 0 and out_line[k] == line[i] and lo[i] <= out_hi[k]:
            out_hi[k] = max(out_hi[k], hi[i])
        else:
            k += 1
            out_line[k], out_lo[k], out_hi[k] = line[i], lo[i], hi[i]
    return out_line[: k + 1], out_lo[: k + 1], out_hi[: k + 1]


@njit(cache=True, nogil=True)
def cut_pieces(line, lo, hi, boxes):  # pragma: no cover - compiled
    """The pieces less the closed boxes ``(across lo, across hi, along lo, along hi)``.

    A box takes from a piece whose line it reaches (its edges included) what it covers along
    the line, where that has a length. The pieces no box touches come first, as they were,
    then what is left of the others, piece by piece.
    """
    n, g = line.shape[0], boxes.shape[0]
    hits = np.zeros(n, dtype=np.int64)
    for i in range(n):
        for j in range(g):
            if _hits(line[i], lo[i], hi[i], boxes[j]):
                hits[i] += 1
    size = n + int(hits.sum())  # each cut adds at most one piece
    out_line, out_lo, out_hi = np.empty(size), np.empty(size), np.empty(size)
    k = 0
    for i in range(n):
        if hits[i] == 0:
            out_line[k], out_lo[k], out_hi[k] = line[i], lo[i], hi[i]
            k += 1
    span_lo, span_hi = np.empty(g + 1), np.empty(g + 1)
    new_lo, new_hi = np.empty(g + 1), np.empty(g + 1)
    for i in range(n):
        if hits[i] == 0:
            continue
        m = 1
        span_lo[0], span_hi[0] = lo[i], hi[i]
        for j in range(g):
            if not _hits(line[i], lo[i], hi[i], boxes[j]):
                continue
            a, b = boxes[j, 2], boxes[j, 3]
            kept = 0
            for s in range(m):
                x0, x1 = span_lo[s], span_hi[s]
                if min(x1, a) > x0:
                    new_lo[kept], new_hi[kept] = x0, min(x1, a)
                    kept += 1
                if x1 > max(x0, b):
                    new_lo[kept], new_hi[kept] = max(x0, b), x1
                    kept += 1
            m = kept
            span_lo[:m], span_hi[:m] = new_lo[:m], new_hi[:m]
        for s in range(m):
            out_line[k], out_lo[k], out_hi[k] = line[i], span_lo[s], span_hi[s]
            k += 1
    return out_line[:k], out_lo[:k], out_hi[:k]


@njit(cache=True, nogil=True, inline="always")
def _hits(line, lo, hi, box):  # pragma: no cover - compiled
    """Whether ``box`` takes a length from the piece: it reaches the line and overlaps the piece."""
    return box[0] <= line <= box[1] and box[2] < hi and box[3] > lo and box[2] < box[3]


@njit(cache=True, nogil=True)
def split_pieces(line, lo, hi, at, a, b):  # pragma: no cover - compiled
    """The pieces cut where a piece across them (at ``at``, from ``a`` to ``b``) meets them inside.

    Each piece's cut points are taken once each, in order along it.
    """
    n, m = line.shape[0], at.shape[0]
    out_line, out_lo, out_hi = [], [], []
    points = np.empty(m + 2)
    for i in range(n):
        count = 0
        points[count] = lo[i]
        count += 1
        for j in range(m):
            if lo[i] < at[j] < hi[i] and a[j] <= line[i] <= b[j]:
                points[count] = at[j]
                count += 1
        points[count] = hi[i]
        count += 1
        order = np.sort(points[:count])
        previous = order[0]
        for p in order[1:]:
            if p != previous:
                out_line.append(line[i])
                out_lo.append(previous)
                out_hi.append(p)
                previous = p
    return np.array(out_line), np.array(out_lo), np.array(out_hi)
