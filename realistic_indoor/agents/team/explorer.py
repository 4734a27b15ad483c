"""The team explorers' base: the single-robot navigator per robot, goals chosen with the team in mind.

Each robot runs the navigator of the map-based explorers
(:class:`~realistic_indoor.navigation.navigator.Navigator`: own map, frontiers, planner,
follower, reflexes) in the team frame, on the map the team's map sharing gives it
(:mod:`~realistic_indoor.agents.team.knowledge`). Robots sense and plan in turn, robot 0 first,
so a robot choosing a goal knows the goals its group chose before it, this step included. A
team explorer only says how a robot chooses its goal, given what it knows of its group.
"""

from __future__ import annotations

import functools
from abc import abstractmethod
from typing import Any, NamedTuple

import numpy as np

from realistic_indoor.agents.team.base import TeamAgent, TeamSpec
from realistic_indoor.agents.team.knowledge import TeamFrames, TeamMaps, groups, share_victims
from realistic_indoor.errors import ConfigError
from realistic_indoor.navigation.frontiers import Frontiers
from realistic_indoor.navigation.navigator import ExplorerConfig, Found, Navigator, PlanContext

__all__ = ["TeamExplorer", "Teammate"]


class Teammate(NamedTuple):
    """What a robot knows of a teammate of its group when it chooses a goal.

    Attributes:
        robot: The teammate's index.
        pose: Its pose in the team frame (m, m, rad).
        goal: The goal it drives to (team frame, m), or ``None``.
    """

    robot: int
    pose: tuple[float, float, float]
    goal: tuple[float, float] | None


class TeamExplorer(TeamAgent):
    """Base of the team explorers: a navigator per robot and a rule for choosing goals.

    Args:
        spec: The team's datasheet.
        config: Every robot's navigator settings.

    Attributes:
        navigators: One per robot, in agent order.
        config: The navigator settings.
    """

    def __init__(self, spec: TeamSpec, config: ExplorerConfig | None = None) -> None:
        super().__init__(spec)
        if config is not None and not isinstance(config, ExplorerConfig):
            raise ConfigError(f"config must be an ExplorerConfig, got {type(config).__name__}")
        self.navigators = [Navigator(spec.robot, config) for _ in range(spec.n_robots)]
        self.config = self.navigators[0].config
        self._own_maps = [nav.map for nav in self.navigators]
        self.reset()

    @property
    def plans(self) -> int:
        """Goals chosen (or found missing) by the whole team this episode."""
        return sum(nav.plans for nav in self.navigators)

    def reset(self, seed: int | None = None) -> None:
        """Forget the maps, plans, blacklists and victims; the next ``act`` reads the start poses."""
        for nav, own in zip(self.navigators, self._own_maps, strict=True):
            nav.use_map(own)
            nav.reset()
        self._maps = TeamMaps(self.spec.n_robots, self.spec.map_sharing, lambda i: self._own_maps[i])
        for nav, own in zip(self.navigators, self._maps.maps, strict=True):
            nav.use_map(own)
        self._frames: TeamFrames | None = None
        self._group = np.zeros(self.spec.n_robots, dtype=np.int64)
        self._poses: list[tuple[float, float, float]] = []

    def act(
        self, observations: dict[str, dict[str, np.ndarray]], infos: dict[str, dict[str, Any]]
    ) -> dict[str, np.ndarray | int]:
        """Share maps and detected victims within groups, then each robot in turn maps its scan, replans and steers."""
        agents = self.spec.agents
        if self._frames is None:
            self._frames = TeamFrames.from_infos(infos, agents)
        self._group = groups(observations, agents)
        for i in self._maps.update(self._group):
            self.navigators[i].use_map(self._maps.maps[i])
        if self.spec.robot.victims is not None:
            share_victims([nav.victims for nav in self.navigators], self._group)
        team_obs = [self._in_team_frame(i, observations[a]) for i, a in enumerate(agents)]
        self._poses = [tuple(float(v) for v in obs["pose"][:3]) for obs in team_obs]
        actions = {}
        for i, agent in enumerate(agents):
            v, w = self.navigators[i].step(team_obs[i], infos[agent], functools.partial(self._choose_for, i))
            actions[agent] = self.spec.robot.action(v, w)
        return actions

    def teammates(self, robot: int) -> list[Teammate]:
        """The teammates ``robot`` is linked to, directly or through others, now."""
        return [
            Teammate(j, self._poses[j], self.navigators[j].goal)
            for j in range(self.spec.n_robots)
            if j != robot and self._group[j] == self._group[robot]
        ]

    def _in_team_frame(self, robot: int, obs: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
        pose = self._frames.to_team(robot, obs["pose"])
        return obs if pose is obs["pose"] else {**obs, "pose": pose}

    def _choose_for(self, robot: int, frontiers: Frontiers, ctx: PlanContext) -> Found | None:
        return self._choose(robot, frontiers, ctx, self.teammates(robot))

    @abstractmethod
    def _choose(
        self, robot: int, frontiers: Frontiers, ctx: PlanContext, teammates: list[Teammate]
    ) -> Found | None:
        """Pick robot ``robot``'s goal among the frontiers of its map, knowing its group.

        Returns:
            ``(flat index of the goal cell in the window, parent array of a Dijkstra from the
            robot)``, or ``None`` if no frontier is reachable.
        """
