"""Frontiers (Yamauchi 1997): known free cells next to space the robot has still to observe.

In exploration the space still to observe is the unknown; in victim search it is also the floor
the laser has mapped but the victim sensor has not swept yet (:attr:`OwnMap.searched`), since a
victim is found only within the victim sensor's short range. Frontier cells are grouped into
frontiers by 8-connectivity; frontiers smaller than a minimum are noise and dropped.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit
from scipy import ndimage

from realistic_indoor.sim.mapping import MAPPED_FREE, MAPPED_UNKNOWN

__all__ = ["Frontiers", "find_frontiers", "unobserved"]

_EIGHT = np.ones((3, 3), dtype=bool)


class Frontiers(NamedTuple):
    """The frontiers of a map.

    Attributes:
        labels: ``(H, W)`` int32: frontier number (1..count) of each frontier cell, 0 elsewhere.
        count: Number of frontiers.
        sizes: ``(count + 1,)`` cells per frontier (entry 0 unused).
    """

    labels: np.ndarray
    count: int
    sizes: np.ndarray

    @property
    def mask(self) -> np.ndarray:
        """Frontier cells (bool)."""
        return self.labels > 0

    def without(self, drop: np.ndarray) -> Frontiers:
        """The frontiers with the cells of the bool mask ``drop`` removed (emptied ones dropped)."""
        return _compact(np.where(drop, 0, self.labels), self.count, min_cells=1)


def unobserved(state: np.ndarray, searched: np.ndarray | None = None) -> np.ndarray:
    """Cells still to observe: unknown, or (with ``searched``) free but not yet swept."""
    todo = state == MAPPED_UNKNOWN
    if searched is not None:
        todo |= (state == MAPPED_FREE) & ~searched
    return todo


def find_frontiers(state: np.ndarray, searched: np.ndarray | None = None, min_cells: int = 3) -> Frontiers:
    """The frontiers of a map: observed free cells with a 4-neighbour still to observe.

    Args:
        state: ``(H, W)`` cells of the agent's map.
        searched: Floor the victim sensor has swept, for victim search; ``None`` in exploration.
        min_cells: Frontiers with fewer cells are dropped.

    Returns:
        The frontiers, numbered in scan order.
    """
    todo = unobserved(state, searched)
    near = np.zeros_like(todo)
    near[1:] |= todo[:-1]
    near[:-1] |= todo[1:]
    near[:, 1:] |= todo[:, :-1]
    near[:, :-1] |= todo[:, 1:]
    cells = (state == MAPPED_FREE) & ~todo & near
    labels, count = ndimage.label(cells, structure=_EIGHT)
    return _compact(labels, count, min_cells)


def _compact(labels: np.ndarray, count: int, min_cells: int) -> Frontiers:
    """Drop the frontiers with fewer than ``min_cells`` cells and number the others 1..n."""
    out, sizes = _compact_labels(np.ascontiguousarray(labels), count, min_cells)
    return Frontiers(out, len(sizes) - 1, sizes)


@njit(cache=True, nogil=True)
def _compact_labels(labels, count, min_cells):  # pragma: no cover - compiled
    """:func:`_compact`'s work in two passes over the map: count the cells, then renumber.

    Returns:
        ``(labels, sizes)``: ``labels`` renumbered (int32, a new array), ``sizes`` int64 cells
        per kept label (entry 0: the cells unlabelled on input, unused).
    """
    flat = labels.ravel()
    counts = np.zeros(count + 1, dtype=np.int64)
    for v in flat:
        counts[v] += 1
    number = np.zeros(count + 1, dtype=np.int32)
    kept = 0
    for lab in range(1, count + 1):
        if counts[lab] >= min_cells:
            kept += 1
            number[lab] = kept
    sizes = np.empty(kept + 1, dtype=np.int64)
    sizes[0] = counts[0]
    for lab in range(1, count + 1):
        if number[lab]:
            sizes[number[lab]] = counts[lab]
    out = np.empty(labels.shape, dtype=np.int32)
    out_flat = out.ravel()
    for i in range(flat.shape[0]):
        out_flat[i] = number[flat[i]]
    return out, sizes
