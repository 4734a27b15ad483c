"""The robot a navigator drives, as its datasheet gives it: sensors, limits, how it is commanded.

Nothing here is about the building: this is all an agent (or an environment's macro actions)
learns of the robot besides its observations.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.lidar import LidarConfig
from realistic_indoor.sim.robot import RobotConfig
from realistic_indoor.sim.victims import VictimConfig

__all__ = ["DISCRETE_ACTIONS", "RobotSpec"]

DISCRETE_ACTIONS: tuple[tuple[str, float, float], ...] = (
    ("forward", 1.0, 0.0),
    ("forward-left", 0.5, 0.5),
    ("forward-right", 0.5, -0.5),
    ("turn-left", 0.0, 1.0),
    ("turn-right", 0.0, -1.0),
    ("back", -0.5, 0.0),
)
"""The discrete action set: name, linear and angular velocity as fractions of the limits."""

_TABLE = np.array([(v, w) for _, v, w in DISCRETE_ACTIONS])


@dataclass(frozen=True)
class RobotSpec:
    """The robot an agent drives: its sensors, limits and action space, as a datasheet gives them.

    This is everything an agent learns from the environment besides its observations: nothing
    about the building, the ground-truth map or the victims' positions.

    Attributes:
        lidar: The laser scanner (field of view, beams, range); scans come normalised by
            ``lidar.max_range_m`` in ``obs["scan"]``, beam ``i`` along
            :func:`~realistic_indoor.sim.lidar.beam_offsets` ``(lidar)[i]`` from the heading.
        robot: Disc radius (m), speed and turn limits (m/s, rad/s), control rate (Hz).
        victims: The victim sensor (range in m, field of view in rad) in search tasks; ``None``
            in exploration.
        action_type: ``"continuous"`` (``(v, w)`` as fractions of the limits) or ``"discrete"``
            (an index into :data:`DISCRETE_ACTIONS`).
    """

    lidar: LidarConfig = field(default_factory=LidarConfig)
    robot: RobotConfig = field(default_factory=RobotConfig)
    victims: VictimConfig | None = None
    action_type: str = "continuous"

    def __post_init__(self) -> None:
        if self.action_type not in ("continuous", "discrete"):
            raise ConfigError(
                f"RobotSpec.action_type must be continuous or discrete, got {self.action_type!r}"
            )

    @classmethod
    def from_env(cls, env: Any) -> RobotSpec:
        """The spec of an environment of this package (``gym.make`` result or the env itself).

        Reads the sensor, robot and action settings of ``env.unwrapped.config``; the victim
        sensor only if the observation has a ``victims`` key.

        Raises:
            ConfigError: If ``env`` is not one of this package's environments, or has macro
                actions (agents send primitive actions).
        """
        config = getattr(getattr(env, "unwrapped", env), "config", None)
        if config is None or not hasattr(config, "lidar"):
            raise ConfigError(
                f"agents need a realistic_indoor environment (ExploreEnv or SearchEnv), got {type(env).__name__}"
            )
        if config.action_type not in ("continuous", "discrete"):
            raise ConfigError(
                f"agents drive the robot step by step: make the environment with action_type 'continuous' "
                f"or 'discrete', not {config.action_type!r} (macro actions are for policies that choose goals; "
                "the learned explorer runs them on its own side in any environment)"
            )
        searching = "victims" in getattr(getattr(env, "observation_space", None), "spaces", {})
        return cls(config.lidar, config.robot, config.victims if searching else None, config.action_type)

    @property
    def dt_s(self) -> float:
        """Duration of one control step (s)."""
        return 1.0 / self.robot.control_hz

    def action(self, v_m_s: float, w_rad_s: float) -> np.ndarray | int:
        """The action that commands ``(v m/s, w rad/s)`` (the nearest one if discrete)."""
        v = max(-1.0, min(1.0, v_m_s / self.robot.max_speed_m_s))
        w = max(-1.0, min(1.0, w_rad_s / self.robot.max_turn_rate_rad_s))
        if self.action_type == "continuous":
            return np.array((v, w), dtype=np.float32)
        return int(np.argmin((_TABLE[:, 0] - v) ** 2 + (_TABLE[:, 1] - w) ** 2))
