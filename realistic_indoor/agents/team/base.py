"""The team-agent interface, and what a team agent may know about its robots (never the building)."""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from realistic_indoor.checks import require_int
from realistic_indoor.errors import ConfigError
from realistic_indoor.navigation.spec import RobotSpec
from realistic_indoor.teams.config import MAP_SHARING, MAX_ROBOTS

__all__ = ["TeamAgent", "TeamSpec"]


@dataclass(frozen=True)
class TeamSpec:
    """A team's datasheet: each robot's sensors and limits, how many, and how maps are shared.

    Attributes:
        robot: Every robot's sensors, limits and action space.
        n_robots: Robots in the team, in [1, :data:`~realistic_indoor.teams.MAX_ROBOTS`].
        map_sharing: How the team shares maps (:data:`~realistic_indoor.teams.MAP_SHARING`);
            the agents' own maps follow the same rule.
    """

    robot: RobotSpec
    n_robots: int = 1
    map_sharing: str = "comm"

    def __post_init__(self) -> None:
        if not isinstance(self.robot, RobotSpec):
            raise ConfigError(f"TeamSpec.robot must be a RobotSpec, got {type(self.robot).__name__}")
        require_int("TeamSpec", "n_robots", self.n_robots, 1, MAX_ROBOTS)
        if self.map_sharing not in MAP_SHARING:
            raise ConfigError(
                f"TeamSpec.map_sharing must be one of {', '.join(MAP_SHARING)}, got {self.map_sharing!r}"
            )

    @property
    def agents(self) -> list[str]:
        """The team environment's agent names, ``robot_0`` first."""
        return [f"robot_{i}" for i in range(self.n_robots)]

    @classmethod
    def from_env(cls, env: Any) -> TeamSpec:
        """The spec of a team environment (:func:`realistic_indoor.teams.parallel_env`).

        Raises:
            ConfigError: If ``env`` is not a team environment of this package (a single
                robot's environment is refused: team agents act for every robot at once).
        """
        team = getattr(getattr(env, "unwrapped", env), "team", None)
        config = getattr(getattr(env, "unwrapped", env), "config", None)
        if team is None or config is None or not hasattr(config, "lidar"):
            raise ConfigError(
                f"team agents need a team environment (realistic_indoor.teams.parallel_env), got {type(env).__name__}"
            )
        searching = getattr(env, "task", "explore") == "search"
        robot = RobotSpec(
            config.lidar, config.robot, config.victims if searching else None, config.action_type
        )
        return cls(robot, team.n_robots, team.map_sharing)


class TeamAgent(ABC):
    """A team agent: one episode at a time, an action per robot per step.

    It sees only what the robots sense: each robot's observation (scan, map image, velocity,
    odometry, victims in view, ``teammates`` and ``base`` links) and ``info`` (the reset's
    ``start_pose``, from which it takes the robots' start poses relative to robot 0, known as
    the robots start together; the bumper). Robots learn of each other only through their links.

    Args:
        spec: The team's datasheet.

    Attributes:
        name: Registry name (see :func:`realistic_indoor.agents.team.make_team_agent`).
        spec: The team's datasheet.
    """

    name: ClassVar[str] = ""

    def __init__(self, spec: TeamSpec) -> None:
        if not isinstance(spec, TeamSpec):
            raise ConfigError(
                f"team agents take a TeamSpec (TeamSpec.from_env(env)), got {type(spec).__name__}"
            )
        self.spec = spec

    def reset(self, seed: int | None = None) -> None:  # noqa: B027 - an agent may have nothing to reset
        """Forget the last episode; ``seed`` seeds an agent's own randomness, if it has any."""

    @abstractmethod
    def act(
        self, observations: dict[str, dict[str, np.ndarray]], infos: dict[str, dict[str, Any]]
    ) -> dict[str, np.ndarray | int]:
        """Every robot's action for this step, keyed by agent (``robot_0`` ...)."""

    def __repr__(self) -> str:
        return f"{type(self).__name__}(n_robots={self.spec.n_robots})"
