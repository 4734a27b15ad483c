"""Hungarian team exploration: robots and frontiers matched for the least total path cost."""

from __future__ import annotations

import math

import numpy as np

from realistic_indoor.agents.team.explorer import TeamExplorer, Teammate
from realistic_indoor.navigation.frontiers import Frontiers
from realistic_indoor.navigation.goals import frontier_costs, nearest_frontier
from realistic_indoor.navigation.navigator import Found, PlanContext

__all__ = ["HungarianAgent", "assign"]

_UNREACHABLE = 1e9
"""Cost standing in for an unreachable frontier in the assignment (m)."""


def assign(costs: np.ndarray) -> np.ndarray:
    """The frontier of each robot that minimises the total cost (Hungarian method).

    Args:
        costs: ``(robots, frontiers)`` path costs (m; ``inf`` where unreachable), at least one
            frontier.

    Returns:
        ``(robots,)`` int64 frontier index per robot: distinct frontiers when there are at least
        as many as robots; with fewer, the frontiers are offered again (each as many times as
        needed) so that every robot gets one.
    """
    from scipy.optimize import linear_sum_assignment

    robots, frontiers = costs.shape
    copies = math.ceil(robots / frontiers)
    matrix = np.tile(np.where(np.isfinite(costs), costs, _UNREACHABLE), (1, copies))
    rows, cols = linear_sum_assignment(matrix)
    out = np.empty(robots, dtype=np.int64)
    out[rows] = cols % frontiers
    return out


class HungarianAgent(TeamExplorer):
    """Robots matched to frontiers for the least total path cost, recomputed as each robot replans.

    The assignment of robots to frontiers as a linear assignment problem solved by the
    Hungarian method (Kuhn 1955; ``scipy.optimize.linear_sum_assignment``), a baseline of the
    multi-robot exploration literature: a robot that must choose a goal prices every frontier
    (its nearest cell) from itself and from each teammate of its group (a Dijkstra search from
    each, on its own map), solves the assignment, and takes its part. Its teammates keep their
    goals until they replan and solve it again. A robot alone goes to its nearest frontier: with
    one robot this is the ``frontier`` team agent.

    Args:
        spec: The team's datasheet.
        config: Every robot's navigator settings.
    """

    name = "hungarian"

    def _choose(
        self, robot: int, frontiers: Frontiers, ctx: PlanContext, teammates: list[Teammate]
    ) -> Found | None:
        if not teammates:
            return nearest_frontier(frontiers, ctx)
        own, cells, parent = frontier_costs(frontiers, ctx)
        reachable = np.flatnonzero(np.isfinite(own))
        if len(reachable) == 0:
            return None
        rows = [own[reachable]]
        h, w = ctx.state.shape
        own_map = self.navigators[robot].map
        for mate in teammates:
            r, c = own_map.to_cell(mate.pose[0], mate.pose[1])
            r, c = r - ctx.box.r0, c - ctx.box.c0
            if 0 <= r < h and 0 <= c < w:
                rows.append(frontier_costs(frontiers, ctx._replace(start=(r, c)))[0][reachable])
        choice = reachable[assign(np.array(rows))[0]]
        return int(cells[choice]), parent
