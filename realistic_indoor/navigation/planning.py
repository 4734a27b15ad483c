"""Path planning on the agent's own map: a costmap with the robot's radius, and Dijkstra.

The costmap follows ROS's layered costmaps in spirit: occupied and unknown cells are lethal;
free cells closer to an obstacle than the robot's radius (plus half a cell, as an obstacle cell
reaches that far past a wall's surface) are "inscribed": allowed, at a high cost, so the robot
can leave a spot where it brushed a wall and still squeeze through a door the map draws a little
narrow; beyond that the cost decays with clearance, which keeps paths in the middle of corridors
and doorways. Dijkstra runs from the robot's cell over 8 neighbours (no corner cutting) and stops
at the first goal cell it settles, or explores everything when every distance is needed.
"""

from __future__ import annotations

import heapq
import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from realistic_indoor.checks import require_positive
from realistic_indoor.sim.fields import distance_field
from realistic_indoor.sim.mapping import MAPPED_FREE, MAPPED_OCCUPIED

__all__ = ["CostConfig", "clearance", "costmap", "dijkstra", "nearest_labels", "trace_path"]

_DR = np.array([0, 0, 1, -1, 1, 1, -1, -1], dtype=np.int64)
_DC = np.array([1, -1, 0, 0, 1, -1, 1, -1], dtype=np.int64)
_STEP = np.array([1.0, 1.0, 1.0, 1.0, math.sqrt(2), math.sqrt(2), math.sqrt(2), math.sqrt(2)])


@dataclass(frozen=True)
class CostConfig:
    """How the costmap weighs the nearness of obstacles.

    Attributes:
        inscribed_cost: Cost per cell of free cells within the robot's radius of an obstacle
            (a clear cell far from walls costs 1).
        decay_m: Clearance (m) beyond the inscribed radius over which the extra cost falls to 0.
        decay_cost: Extra cost per cell just outside the inscribed radius.
    """

    inscribed_cost: float = 40.0
    decay_m: float = 0.5
    decay_cost: float = 3.0

    def __post_init__(self) -> None:
        require_positive("CostConfig", "inscribed_cost", self.inscribed_cost, "")
        require_positive("CostConfig", "decay_m", self.decay_m, "m")
        require_positive("CostConfig", "decay_cost", self.decay_cost, "", allow_zero=True)


def clearance(state: np.ndarray, resolution_m: float) -> np.ndarray:
    """Distance from each cell's centre to the nearest occupied cell's centre (m, float32).

    Cost: the simulator's exact Euclidean distance transform
    (:func:`~realistic_indoor.sim.fields.distance_field`), about 5-13 ms per million cells.
    """
    return distance_field(state == MAPPED_OCCUPIED, resolution_m)


def costmap(
    state: np.ndarray, clearance_m: np.ndarray, resolution_m: float, radius_m: float, config: CostConfig
) -> np.ndarray:
    """Cost per cell of moving through each cell of a map (float64; ``inf`` where lethal).

    Args:
        state: ``(H, W)`` cells of the agent's map (unknown, free, occupied).
        clearance_m: Distance to the nearest obstacle (:func:`clearance`, m).
        resolution_m: Side of a cell (m).
        radius_m: The robot's radius (m).
        config: The cost weights.

    Returns:
        The costmap: 1 on clear free floor, more near obstacles, ``inf`` on unknown and
        occupied cells.
    """
    inscribed = radius_m + 0.5 * resolution_m
    extra = np.clip((inscribed + config.decay_m - clearance_m) / config.decay_m, 0.0, 1.0) * config.decay_cost
    cost = 1.0 + extra
    cost[clearance_m < inscribed] = config.inscribed_cost
    cost[state != MAPPED_FREE] = np.inf
    return cost


def dijkstra(
    cost: np.ndarray, start: tuple[int, int], goals: np.ndarray, first_only: bool, max_cost: float = math.inf
) -> tuple[np.ndarray, np.ndarray, int]:
    """Shortest paths from ``start`` over a costmap.

    Moving to a neighbour costs its cell cost times the step length (cells); a diagonal step
    needs both cells beside it passable. The start cell is left even if it is lethal.

    Args:
        cost: ``(H, W)`` cost per cell, ``inf`` for lethal cells.
        start: ``(row, col)`` of the robot.
        goals: ``(H, W)`` bool mask of goal cells.
        first_only: Stop at the first goal settled (the nearest); else settle every cell
            up to ``max_cost``.
        max_cost: Cells whose path costs more are left unreached (``inf`` distance).

    Returns:
        ``(dist, parent, goal)``: path cost to each cell (cells; ``inf`` if unreached), the
        direction index each cell was reached from (-1 for none), and the flat index of the
        nearest goal (-1 if no goal is reachable).
    """
    return _dijkstra(cost, start[0], start[1], goals, first_only, max_cost)


def nearest_labels(
    cost: np.ndarray, start: tuple[int, int], labels: np.ndarray, count: int, k: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The ``k`` nearest labelled regions (frontiers) from ``start``, by one Dijkstra search.

    The search of :func:`dijkstra`, stopped once cells of ``k`` different labels are settled:
    the first settled cell of each label is its nearest cell, and labels come in the order the
    search settles them (by path cost, ties by the smaller flat index), so the first is the
    goal :func:`dijkstra` with ``first_only`` finds.

    Args:
        cost: ``(H, W)`` cost per cell, ``inf`` for lethal cells.
        start: ``(row, col)`` of the robot.
        labels: ``(H, W)`` int label of each goal cell (1..count), 0 elsewhere.
        count: The largest label.
        k: How many labels to find.

    Returns:
        ``(dist, parent, found_labels, found_cells)``: path costs (cells; ``inf`` where not
        settled or not reached), the parent array for :func:`trace_path`, and the labels found
        and the flat index of each one's nearest cell, nearest first (fewer than ``k`` if fewer
        are reachable).
    """
    return _nearest_labels(cost, start[0], start[1], labels, int(count), int(k))


def trace_path(parent: np.ndarray, goal: int) -> np.ndarray:
    """The cells from the start to the flat index ``goal``, as ``(N, 2)`` ``(row, col)``."""
    return _trace(parent, goal)


@njit(cache=True)
def _dijkstra(cost, sr, sc, goals, first_only, max_cost):  # pragma: no cover - compiled
    h, w = cost.shape
    dist = np.full((h, w), np.inf)
    parent = np.full((h, w), -1, dtype=np.int8)
    dist[sr, sc] = 0.0
    heap = [(0.0, sr * w + sc)]
    found = -1
    while heap:
        d, idx = heapq.heappop(heap)
        r = idx // w
        c = idx - r * w
        if d > dist[r, c]:
            continue
        if d > max_cost:
            break
        if goals[r, c]:
            if found < 0:
                found = idx
            if first_only:
                break
        for k in range(8):
            rr = r + _DR[k]
            cc = c + _DC[k]
            if rr < 0 or rr >= h or cc < 0 or cc >= w:
                continue
            step = cost[rr, cc]
            if not np.isfinite(step):
                continue
            if k >= 4 and not (np.isfinite(cost[r, cc]) and np.isfinite(cost[rr, c])):
                continue
            nd = d + _STEP[k] * step
            if nd < dist[rr, cc]:
                dist[rr, cc] = nd
                parent[rr, cc] = k
                heapq.heappush(heap, (nd, rr * w + cc))
    if np.isfinite(max_cost):
        for r in range(h):
            for c in range(w):
                if dist[r, c] > max_cost:
                    dist[r, c] = np.inf
    return dist, parent, found


# The relaxation of a settled cell's neighbours is written out in both searches, not shared
# through a helper: calling one (even with inline="always") made the full search 10-15% slower.


@njit(cache=True)
def _nearest_labels(cost, sr, sc, labels, count, k):  # pragma: no cover - compiled
    h, w = cost.shape
    dist = np.full((h, w), np.inf)
    parent = np.full((h, w), -1, dtype=np.int8)
    dist[sr, sc] = 0.0
    heap = [(0.0, sr * w + sc)]
    seen = np.zeros(count + 1, dtype=np.bool_)
    found_labels = np.empty(k, dtype=np.int64)
    found_cells = np.empty(k, dtype=np.int64)
    n = 0
    while heap and n < k:
        d, idx = heapq.heappop(heap)
        r = idx // w
        c = idx - r * w
        if d > dist[r, c]:
            continue
        lab = labels[r, c]
        if lab > 0 and not seen[lab]:
            seen[lab] = True
            found_labels[n] = lab
            found_cells[n] = idx
            n += 1
            if n == k:
                break
        for q in range(8):
            rr = r + _DR[q]
            cc = c + _DC[q]
            if rr < 0 or rr >= h or cc < 0 or cc >= w:
                continue
            step = cost[rr, cc]
            if not np.isfinite(step):
                continue
            if q >= 4 and not (np.isfinite(cost[r, cc]) and np.isfinite(cost[rr, c])):
                continue
            nd = d + _STEP[q] * step
            if nd < dist[rr, cc]:
                dist[rr, cc] = nd
                parent[rr, cc] = q
                heapq.heappush(heap, (nd, rr * w + cc))
    return dist, parent, found_labels[:n], found_cells[:n]


@njit(cache=True)
def _trace(parent, goal):  # pragma: no cover - compiled
    w = parent.shape[1]
    out = []
    r = goal // w
    c = goal - r * w
    while True:
        out.append((r, c))
        k = parent[r, c]
        if k < 0:
            break
        r -= _DR[k]
        c -= _DC[k]
    n = len(out)
    cells = np.empty((n, 2), dtype=np.int64)
    for i in range(n):
        cells[n - 1 - i, 0] = out[i][0]
        cells[n - 1 - i, 1] = out[i][1]
    return cells
