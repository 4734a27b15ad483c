"""The map-based explorers' agent: a navigator that chooses its own goals.

The navigator maps each scan, keeps or remakes the plan, follows the path and gets the robot
unstuck (see :mod:`realistic_indoor.navigation.navigator`); an explorer only chooses the goal
among the frontiers when the navigator asks for one. In victim search a detected victim is
always the next goal.
"""

from __future__ import annotations

from abc import abstractmethod
from typing import Any

import numpy as np

from realistic_indoor.agents.base import Agent, RobotSpec
from realistic_indoor.navigation.frontiers import Frontiers
from realistic_indoor.navigation.navigator import ExplorerConfig, Found, Navigator, PlanContext
from realistic_indoor.navigation.own_map import OwnMap
from realistic_indoor.navigation.victims import VictimTracker

__all__ = ["ExplorerConfig", "MapExplorer", "PlanContext"]


class MapExplorer(Agent):
    """Base of the frontier explorers: a navigator and a rule for choosing goals.

    Args:
        spec: The robot's sensors and limits.
        config: Explorer settings.

    Attributes:
        navigator: The map, plan and follow loop.
        config: Explorer settings.
    """

    def __init__(self, spec: RobotSpec, config: ExplorerConfig | None = None) -> None:
        super().__init__(spec)
        self.navigator = Navigator(spec, config)
        self.config = self.navigator.config

    @property
    def map(self) -> OwnMap:
        """The agent's own map."""
        return self.navigator.map

    @property
    def victims(self) -> VictimTracker:
        """Victims detected (search only; empty in exploration)."""
        return self.navigator.victims

    @property
    def finished(self) -> bool:
        """Whether the last plan found no reachable frontier (exploration is over)."""
        return self.navigator.finished

    def reset(self, seed: int | None = None) -> None:
        """Forget the map, the plan, the blacklist and the victims."""
        self.navigator.reset()

    def act(self, obs: dict[str, np.ndarray], info: dict[str, Any]) -> np.ndarray | int:
        """Map the scan, replan if needed, and return the action that follows the path."""
        return self.spec.action(*self.navigator.step(obs, info, self._choose))

    @abstractmethod
    def _choose(self, frontiers: Frontiers, ctx: PlanContext) -> Found | None:
        """Pick the goal among the frontiers.

        Returns:
            ``(flat index of the goal cell in the window, parent array of a Dijkstra from the
            robot)``, or ``None`` if no frontier is reachable.
        """
