"""Goals among the frontiers: the nearest one, the path cost to each, and what lies around them.

What the navigator's callers share: the nearest-frontier explorer's goal; the path cost to
every frontier, which the utility and structure explorers rank frontiers by; and two measures of
each frontier that they and the environments' macro actions (the ``candidates`` observation)
use: the unobserved area near it, and whether it lies off the corridors and halls.
"""

from __future__ import annotations

import numpy as np
from numba import njit
from scipy import ndimage

from realistic_indoor.navigation.frontiers import Frontiers
from realistic_indoor.navigation.navigator import Found, PlanContext
from realistic_indoor.navigation.planning import dijkstra
from realistic_indoor.navigation.regions import Regions

__all__ = ["frontier_costs", "nearest_frontier", "nearest_points", "off_circulation", "unobserved_area_near"]


def nearest_frontier(frontiers: Frontiers, ctx: PlanContext) -> Found | None:
    """The frontier cell with the cheapest path from the robot (Yamauchi's nearest frontier).

    One Dijkstra search on the costmap, stopped at the first frontier cell it settles.

    Returns:
        ``(flat index of that cell in the window, parent array)``, or ``None`` if no frontier
        cell is reachable.
    """
    _, parent, goal = dijkstra(ctx.cost, ctx.start, frontiers.mask, first_only=True)
    return None if goal < 0 else (goal, parent)


def frontier_costs(
    frontiers: Frontiers, ctx: PlanContext, max_cost_m: float = np.inf
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Path cost to each frontier, from one Dijkstra search from the robot.

    Args:
        frontiers: The frontiers.
        ctx: The planning window.
        max_cost_m: Frontiers farther than this (path cost in metres of clear floor) count as
            unreachable; a bound keeps the search small.

    Returns:
        ``(costs, cells, parent)``: per frontier (``count``,) the path cost to its nearest cell
        in metres of clear floor (``inf`` if unreachable) and that cell's flat index (-1 if
        unreachable), and the Dijkstra parent array for :func:`trace_path`.
    """
    dist, parent, _ = dijkstra(ctx.cost, ctx.start, frontiers.mask, False, max_cost_m / ctx.resolution_m)
    flat = np.flatnonzero(frontiers.mask)
    d = dist.ravel()[flat]
    lab = frontiers.labels.ravel()[flat]
    order = np.lexsort((d, lab))
    first = order[np.r_[True, np.diff(lab[order]) != 0]]  # the nearest cell of each frontier
    costs = np.full(frontiers.count, np.inf)
    cells = np.full(frontiers.count, -1, dtype=np.int64)
    costs[lab[first] - 1] = d[first]
    reached = np.isfinite(costs)
    cells[lab[first] - 1] = flat[first]
    cells[~reached] = -1
    return costs * ctx.resolution_m, cells, parent


def unobserved_area_near(frontiers: Frontiers, ctx: PlanContext, radius_m: float) -> np.ndarray:
    """The largest unobserved area within a square of half-side ``radius_m`` of a frontier's cells.

    Args:
        frontiers: The frontiers.
        ctx: The planning window (``ctx.todo``: the cells still to observe).
        radius_m: Half the side of the square (m).

    Returns:
        ``(count,)`` area (m2) per frontier.
    """
    res = ctx.resolution_m
    k = max(1, round(radius_m / res))
    area = ndimage.uniform_filter(ctx.todo.astype(np.float32), size=2 * k + 1, mode="constant")
    rows, cols = np.nonzero(frontiers.mask)
    best = np.zeros(frontiers.count + 1)
    np.maximum.at(best, frontiers.labels[rows, cols], area[rows, cols])
    return best[1:] * (2 * k + 1) ** 2 * res**2


def off_circulation(frontiers: Frontiers, regions: Regions, reach_cells: int) -> np.ndarray:
    """Whether each frontier lies off the circulation: no corridor or hall core within reach.

    Args:
        frontiers: The frontiers.
        regions: The regions of the same window (:func:`~realistic_indoor.navigation.regions.find_regions`).
        reach_cells: A frontier cell within this many cells of a corridor's or hall's core
            (sampled every other cell) touches the circulation.

    Returns:
        ``(count,)`` bool: ``True`` for a frontier in a room (or in no recognised region).
    """
    k = reach_cells
    circulation = regions.circulation()
    rows, cols = np.nonzero(frontiers.mask)
    h, w = circulation.shape
    near = np.zeros(len(rows), dtype=bool)
    for dr in range(-k, k + 1, 2):
        for dc in range(-k, k + 1, 2):
            if dr * dr + dc * dc <= k * k:
                r, c = np.clip(rows + dr, 0, h - 1), np.clip(cols + dc, 0, w - 1)
                near |= circulation[r, c]
    touching = np.bincount(frontiers.labels[rows, cols], weights=near, minlength=frontiers.count + 1)
    return touching[1:] == 0


def nearest_points(points: np.ndarray, targets: np.ndarray, tie: np.ndarray) -> np.ndarray:
    """For each target, the index of the nearest point (Euclidean), ties to the smaller ``tie``.

    Args:
        points: ``(N, 2)`` candidate points (N >= 1).
        targets: ``(M, 2)`` points to snap.
        tie: ``(N,)`` what decides between equally near points (a path cost, say); then the
            smaller index.

    Returns:
        ``(M,)`` int64 indices into ``points``.
    """
    return _nearest_points(
        np.ascontiguousarray(points, dtype=np.float64),
        np.ascontiguousarray(targets, dtype=np.float64),
        np.ascontiguousarray(tie, dtype=np.float64),
    )


@njit(cache=True)
def _nearest_points(points, targets, tie):  # pragma: no cover - compiled
    out = np.empty(len(targets), dtype=np.int64)
    for t in range(len(targets)):
        best, best_d, best_tie = 0, np.inf, np.inf
        tx, ty = targets[t, 0], targets[t, 1]
        for i in range(len(points)):
            dx = points[i, 0] - tx
            dy = points[i, 1] - ty
            d = dx * dx + dy * dy
            if d < best_d or (d == best_d and tie[i] < best_tie):
                best, best_d, best_tie = i, d, tie[i]
        out[t] = best
    return out
