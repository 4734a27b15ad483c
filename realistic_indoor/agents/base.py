"""The agent interface, and what an agent may know about its robot (never about the building)."""

from __future__ import annotations

from abc import ABC, abstractmethod
from typing import Any, ClassVar

import numpy as np

from realistic_indoor.errors import ConfigError
from realistic_indoor.navigation.spec import RobotSpec

__all__ = ["Agent", "RobotSpec"]


class Agent(ABC):
    """An agent: one episode at a time, an action per observation.

    Agents see only what the robot senses: the observation (laser scan, map image, velocity,
    odometry, victims in view) and the ``info`` dict (coverage, distance, collisions). They
    never read the building or the environment's internals.

    Args:
        spec: The robot's sensors and limits.

    Attributes:
        name: Registry name (see :func:`realistic_indoor.agents.make_agent`).
        spec: The robot's sensors and limits.
    """

    name: ClassVar[str] = ""

    def __init__(self, spec: RobotSpec) -> None:
        if not isinstance(spec, RobotSpec):
            raise ConfigError(f"agents take a RobotSpec (RobotSpec.from_env(env)), got {type(spec).__name__}")
        self.spec = spec

    def reset(self, seed: int | None = None) -> None:  # noqa: B027 - most agents have nothing to reset
        """Forget the last episode; ``seed`` seeds an agent's own randomness, if it has any."""

    @abstractmethod
    def act(self, obs: dict[str, np.ndarray], info: dict[str, Any]) -> np.ndarray | int:
        """The action for this observation (in the environment's action space)."""

    def __repr__(self) -> str:
        return f"{type(self).__name__}()"
