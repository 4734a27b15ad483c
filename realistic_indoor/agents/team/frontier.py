"""Uncoordinated team exploration: each robot its nearest frontier (Yamauchi 1998)."""

from __future__ import annotations

from realistic_indoor.agents.team.explorer import TeamExplorer, Teammate
from realistic_indoor.navigation.frontiers import Frontiers
from realistic_indoor.navigation.goals import nearest_frontier
from realistic_indoor.navigation.navigator import Found, PlanContext

__all__ = ["TeamFrontierAgent"]


class TeamFrontierAgent(TeamExplorer):
    """Every robot goes to the nearest reachable frontier of the map it knows, ignoring the others.

    B. Yamauchi, "Frontier-based exploration using multiple robots", Autonomous Agents 1998:
    each robot runs single-robot frontier exploration on what it knows; the robots cooperate
    only by sharing maps (as the team's map sharing allows), never by dividing the frontiers.
    Several robots may head for one frontier.

    Args:
        spec: The team's datasheet.
        config: Every robot's navigator settings.
    """

    name = "frontier"

    def _choose(
        self, robot: int, frontiers: Frontiers, ctx: PlanContext, teammates: list[Teammate]
    ) -> Found | None:
        return nearest_frontier(frontiers, ctx)
