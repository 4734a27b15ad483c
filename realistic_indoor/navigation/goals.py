"""Goals among the frontiers: the nearest one, and the path cost to each.

The choices the navigator's callers share: the nearest-frontier explorer's goal, and the path
cost to every frontier that the utility and structure explorers, and the environments' frontier
macro actions, rank frontiers by.
"""

from __future__ import annotations

import numpy as np

from realistic_indoor.navigation.frontiers import Frontiers
from realistic_indoor.navigation.navigator import Found, PlanContext
from realistic_indoor.navigation.planning import dijkstra

__all__ = ["frontier_costs", "nearest_frontier"]


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
