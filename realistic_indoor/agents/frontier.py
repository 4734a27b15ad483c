"""Nearest-frontier exploration (Yamauchi 1997)."""

from __future__ import annotations

from realistic_indoor.agents.explorer import MapExplorer, PlanContext
from realistic_indoor.navigation.frontiers import Frontiers
from realistic_indoor.navigation.goals import nearest_frontier
from realistic_indoor.navigation.navigator import Found

__all__ = ["FrontierAgent"]


class FrontierAgent(MapExplorer):
    """Goes to the nearest reachable frontier, by path cost on its own map.

    B. Yamauchi, "A frontier-based approach for autonomous exploration", CIRA 1997: frontiers
    are the boundaries between known free space and unknown space; the robot repeatedly drives
    to the closest one. Here "closest" is the cost of the path on the agent's costmap (the
    robot's radius kept from walls), found by one Dijkstra search that stops at the first
    frontier cell it settles; frontiers it cannot reach are never found by that search, and goals it
    makes no progress towards are blacklisted (see
    :class:`~realistic_indoor.navigation.navigator.Navigator` for the loop and the settings).

    Args:
        spec: The robot's sensors and limits.
        config: Explorer settings (:class:`~realistic_indoor.agents.explorer.ExplorerConfig`).
    """

    name = "frontier"

    def _choose(self, frontiers: Frontiers, ctx: PlanContext) -> Found | None:
        return nearest_frontier(frontiers, ctx)
