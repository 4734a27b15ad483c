"""Coordinated team exploration (Burgard et al. 2005): utility minus cost, utility discounted by teammates' goals."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from realistic_indoor.agents.team.base import TeamSpec
from realistic_indoor.agents.team.explorer import TeamExplorer, Teammate
from realistic_indoor.checks import require_positive
from realistic_indoor.errors import ConfigError
from realistic_indoor.navigation.frontiers import Frontiers
from realistic_indoor.navigation.goals import nearest_frontier
from realistic_indoor.navigation.navigator import ExplorerConfig, Found, PlanContext
from realistic_indoor.navigation.planning import dijkstra

__all__ = ["CoordinatedAgent", "CoordinatedConfig", "frontier_utility"]


@dataclass(frozen=True)
class CoordinatedConfig:
    """Burgard's trade-off: a frontier cell scores ``utility - cost_weight * path cost``.

    Attributes:
        cost_weight: Weight of the path cost (per metre of clear floor): a frontier a teammate's
            goal fully covers (utility 0) loses to a free one up to ``1 / cost_weight`` metres
            farther. Default 0.1: one laser range (10 m).
        visibility_m: A teammate's goal discounts the utility of frontier cells within this
            distance of it, by ``1 - d / visibility_m``; ``None``: the laser's range (Burgard's
            choice: what the teammate will see from there).
        explorer: Every robot's navigator settings.
    """

    cost_weight: float = 0.1
    visibility_m: float | None = None
    explorer: ExplorerConfig = field(default_factory=ExplorerConfig)

    def __post_init__(self) -> None:
        require_positive("CoordinatedConfig", "cost_weight", self.cost_weight, "1/m")
        if self.visibility_m is not None:
            require_positive("CoordinatedConfig", "visibility_m", self.visibility_m, "m")
        if not isinstance(self.explorer, ExplorerConfig):
            raise ConfigError(f"CoordinatedConfig.explorer must be an ExplorerConfig, got {self.explorer!r}")


def frontier_utility(points: np.ndarray, goals: list[tuple[float, float]], visibility_m: float) -> np.ndarray:
    """Burgard's utility of frontier cells at ``points`` (``(N, 2)`` m) given teammates' ``goals``.

    Each cell starts at 1 and loses ``P(d) = max(0, 1 - d / visibility_m)`` for each goal at
    straight-line distance ``d``: the chance that a robot at that goal sees it. It may go below 0.

    Returns:
        ``(N,)`` float64 utilities.
    """
    utility = np.ones(len(points))
    for gx, gy in goals:
        d = np.hypot(points[:, 0] - gx, points[:, 1] - gy)
        utility -= np.maximum(0.0, 1.0 - d / visibility_m)
    return utility


class CoordinatedAgent(TeamExplorer):
    """Coordinated exploration: each robot weighs a frontier's utility against its path cost.

    W. Burgard, M. Moors, C. Stachniss, F. Schneider, "Coordinated multi-robot exploration",
    IEEE Transactions on Robotics 21(3), 2005: frontier cells start with utility 1; a robot
    assigned a target lowers the utility of the cells near it by the chance it will see them from
    there; the next robot takes the cell with the best ``utility - cost_weight * cost``, and so
    on in turn. Here a robot that must choose (when its navigator replans) discounts by the goals
    of the teammates it is linked to, directly or through others (those that chose earlier this
    step included), on the map it knows; a robot alone, or linked to none, scores every cell 1,
    so it goes to the nearest frontier: with one robot this is the ``frontier`` team agent.

    Args:
        spec: The team's datasheet.
        config: The trade-off and the navigator settings.
    """

    name = "coordinated"

    def __init__(self, spec: TeamSpec, config: CoordinatedConfig | None = None) -> None:
        self.coordination = config or CoordinatedConfig()
        if not isinstance(self.coordination, CoordinatedConfig):
            raise ConfigError(f"config must be a CoordinatedConfig, got {type(self.coordination).__name__}")
        super().__init__(spec, self.coordination.explorer)
        self._visibility_m = self.coordination.visibility_m or spec.robot.lidar.max_range_m

    def _choose(
        self, robot: int, frontiers: Frontiers, ctx: PlanContext, teammates: list[Teammate]
    ) -> Found | None:
        goals = [t.goal for t in teammates if t.goal is not None]
        if not goals:
            return nearest_frontier(frontiers, ctx)
        beta = self.coordination.cost_weight
        dist, _, nearest = dijkstra(ctx.cost, ctx.start, frontiers.mask, first_only=True)
        if nearest < 0:
            return None
        res = ctx.resolution_m
        near_xy = self._points(robot, ctx, np.array([nearest]))
        best = frontier_utility(near_xy, goals, self._visibility_m)[0] - beta * dist.ravel()[nearest] * res
        bound_m = (1.0 - best) / beta  # no cell farther than this can score better (utility <= 1)
        dist, parent, _ = dijkstra(
            ctx.cost, ctx.start, frontiers.mask, False, bound_m / res + 1.0
        )  # a cell more: rounding
        cells = np.flatnonzero(frontiers.mask.ravel() & np.isfinite(dist.ravel()))
        score = frontier_utility(self._points(robot, ctx, cells), goals, self._visibility_m)
        score -= beta * dist.ravel()[cells] * res
        return int(cells[int(np.argmax(score))]), parent

    def _points(self, robot: int, ctx: PlanContext, flat: np.ndarray) -> np.ndarray:
        """``(N, 2)`` team-frame centres (m) of the window cells with flat indices ``flat``."""
        rows, cols = np.divmod(np.asarray(flat, dtype=np.int64), ctx.state.shape[1])
        return self.navigators[robot].map.to_world(rows + ctx.box.r0, cols + ctx.box.c0)
