"""A structure-aware explorer: corridors and halls first, then the rooms off them."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from realistic_indoor.agents.base import RobotSpec
from realistic_indoor.agents.explorer import ExplorerConfig, MapExplorer, PlanContext
from realistic_indoor.checks import require_positive
from realistic_indoor.errors import ConfigError
from realistic_indoor.navigation.frontiers import Frontiers
from realistic_indoor.navigation.goals import frontier_costs, off_circulation
from realistic_indoor.navigation.planning import dijkstra
from realistic_indoor.navigation.regions import RegionConfig, Regions, find_regions

__all__ = ["StructureAgent", "StructureConfig"]


@dataclass(frozen=True)
class StructureConfig:
    """Settings of the structure-aware explorer.

    Attributes:
        room_factor: A frontier in a room (or not in a recognised corridor or hall) counts as
            this many times farther than it is, >= 1: with 4, a room's doorway 2 m away
            competes with a corridor's end 8 m away.
        reach_m: A frontier belongs to the region whose core lies within this distance (m).
        regions: The region classification thresholds.
        explorer: The shared explorer settings.
    """

    room_factor: float = 4.0
    reach_m: float = 0.25
    regions: RegionConfig = field(default_factory=RegionConfig)
    explorer: ExplorerConfig = field(default_factory=ExplorerConfig)

    def __post_init__(self) -> None:
        require_positive("StructureConfig", "room_factor", self.room_factor, "")
        require_positive("StructureConfig", "reach_m", self.reach_m, "m")
        if self.room_factor < 1.0:
            raise ConfigError(f"StructureConfig.room_factor must be >= 1, got {self.room_factor!r}")


class StructureAgent(MapExplorer):
    """Explores the circulation (corridors, halls) first, then the rooms off it.

    Real buildings, unlike random ones, are organised around their circulation: in an office
    nearly every room opens on a corridor. This explorer recognises corridors and halls on its
    own map by the shape of the free space (:func:`~realistic_indoor.navigation.regions.find_regions`:
    the known floor split at doorways, each part classified as long and thin, wide, or neither)
    and goes to the frontier with the lowest path cost, where a frontier in a room costs
    ``room_factor`` times its path. Sweeping the corridors first maps the building's skeleton
    and looks into every room through its door; the rooms still unseen are visited after, the
    nearest first (or on the way, when a door is close).

    Args:
        spec: The robot's sensors and limits.
        config: The room factor, region thresholds and explorer settings.

    Attributes:
        regions: The regions found at the last plan (for inspection and figures).
    """

    name = "structure"

    def __init__(self, spec: RobotSpec, config: StructureConfig | None = None) -> None:
        self.structure = config or StructureConfig()
        if not isinstance(self.structure, StructureConfig):
            raise ConfigError(f"config must be a StructureConfig, got {type(self.structure).__name__}")
        self.regions: Regions | None = None
        super().__init__(spec, self.structure.explorer)

    def _choose(self, frontiers: Frontiers, ctx: PlanContext) -> tuple[int, np.ndarray] | None:
        dist, _, nearest = dijkstra(ctx.cost, ctx.start, frontiers.mask, first_only=True)
        if nearest < 0:
            return None
        self.regions = find_regions(ctx.state, ctx.clearance_m, ctx.resolution_m, self.structure.regions)
        reach = max(1, round(self.structure.reach_m / ctx.resolution_m))
        factor = np.where(off_circulation(frontiers, self.regions, reach), self.structure.room_factor, 1.0)
        # A frontier whose path costs more than the nearest one's weighted cost cannot win.
        bound = dist.ravel()[nearest] * ctx.resolution_m * factor[frontiers.labels.ravel()[nearest] - 1]
        costs, cells, parent = frontier_costs(frontiers, ctx, max_cost_m=bound)
        weighted = np.where(np.isfinite(costs), costs * factor, np.inf)
        return int(cells[int(np.argmin(weighted))]), parent
