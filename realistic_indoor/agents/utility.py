"""Utility-based frontier exploration: frontiers scored by travel cost and information gain."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from realistic_indoor.agents.base import RobotSpec
from realistic_indoor.agents.explorer import ExplorerConfig, MapExplorer, PlanContext
from realistic_indoor.checks import require_positive
from realistic_indoor.errors import ConfigError
from realistic_indoor.navigation.frontiers import Frontiers
from realistic_indoor.navigation.goals import frontier_costs, unobserved_area_near
from realistic_indoor.navigation.planning import dijkstra

__all__ = ["UtilityConfig", "UtilityFrontierAgent"]

GAINS = ("length", "area")
"""Information-gain estimates :class:`UtilityConfig` accepts."""


@dataclass(frozen=True)
class UtilityConfig:
    """How frontiers are scored: ``gain_weight * gain - cost_weight * path``.

    The defaults are ROS explore_lite's (``potential_scale`` 3, ``gain_scale`` 1, gain = the
    frontier's length).

    Attributes:
        cost_weight: Weight of the path cost to the frontier (per metre of clear floor).
        gain_weight: Weight of the information gain.
        gain: ``"length"``: the frontier's length (m), as explore_lite; ``"area"``: the
            unobserved area within ``gain_radius_m`` of the frontier's nearest cell (m2).
        gain_radius_m: Radius of the ``"area"`` gain (m).
        explorer: The shared explorer settings.
    """

    cost_weight: float = 3.0
    gain_weight: float = 1.0
    gain: str = "length"
    gain_radius_m: float = 3.0
    explorer: ExplorerConfig = field(default_factory=ExplorerConfig)

    def __post_init__(self) -> None:
        require_positive("UtilityConfig", "cost_weight", self.cost_weight, "", allow_zero=True)
        require_positive("UtilityConfig", "gain_weight", self.gain_weight, "", allow_zero=True)
        require_positive("UtilityConfig", "gain_radius_m", self.gain_radius_m, "m")
        if self.gain not in GAINS:
            raise ConfigError(f"UtilityConfig.gain must be one of {', '.join(GAINS)}, got {self.gain!r}")


class UtilityFrontierAgent(MapExplorer):
    """Goes to the frontier with the best trade-off of information gain against travel cost.

    As ROS explore_lite: every frontier gets ``gain_weight * gain - cost_weight * cost``, the
    best one is the goal. Here the cost is the path cost on the agent's costmap (metres of clear
    floor, more near walls), not the straight-line distance explore_lite uses: a search for the
    nearest frontier bounds the best score possible, then one Dijkstra search, stopped at that
    bound, prices the frontiers; and the robot heads for the frontier's nearest
    cell. Long frontiers (open rooms, corridor ends) draw the robot further than the nearest
    frontier would; small nooks nearby are left for later.

    Args:
        spec: The robot's sensors and limits.
        config: Scoring weights and the explorer settings.
    """

    name = "utility"

    def __init__(self, spec: RobotSpec, config: UtilityConfig | None = None) -> None:
        self.utility = config or UtilityConfig()
        if not isinstance(self.utility, UtilityConfig):
            raise ConfigError(f"config must be a UtilityConfig, got {type(self.utility).__name__}")
        super().__init__(spec, self.utility.explorer)

    def _choose(self, frontiers: Frontiers, ctx: PlanContext) -> tuple[int, np.ndarray] | None:
        c = self.utility
        dist, _, nearest = dijkstra(ctx.cost, ctx.start, frontiers.mask, first_only=True)
        if nearest < 0:
            return None
        gains = self._gains(frontiers, ctx)
        # No frontier whose path costs more than this can beat the nearest one, whatever its gain.
        best = (
            c.gain_weight * gains[frontiers.labels.ravel()[nearest] - 1]
            - c.cost_weight * dist.ravel()[nearest] * ctx.resolution_m
        )
        bound = (c.gain_weight * gains.max() - best) / c.cost_weight if c.cost_weight > 0 else np.inf
        costs, cells, parent = frontier_costs(frontiers, ctx, max_cost_m=bound)
        score = np.where(np.isfinite(costs), c.gain_weight * gains - c.cost_weight * costs, -np.inf)
        return int(cells[int(np.argmax(score))]), parent

    def _gains(self, frontiers: Frontiers, ctx: PlanContext) -> np.ndarray:
        """Information gain of each frontier (``count``,).

        Its length (m), or the largest unobserved area (m2) within ``gain_radius_m`` of one of
        its cells.
        """
        if self.utility.gain == "length":
            return frontiers.sizes[1:] * ctx.resolution_m
        return unobserved_area_near(frontiers, ctx, self.utility.gain_radius_m)
