"""Path following: pure pursuit of a look-ahead point, turning in place when it lies behind."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from realistic_indoor.checks import require_positive

__all__ = ["FollowerConfig", "PathFollower"]

_MIN_SPEED_SHARE = 0.15
"""Share of the top speed kept when closing in on the path's end (so the end is reached)."""
_STOP_M = 0.05
"""The robot stops (and only turns) when an obstacle is this close ahead of its disc (m)."""


@dataclass(frozen=True)
class FollowerConfig:
    """How the robot tracks a path.

    Attributes:
        lookahead_m: Distance along the path of the point the robot steers to (m).
        goal_tolerance_m: The path is done when the robot is this close to its end (m).
        turn_gain: Turn rate per radian of heading error (1/s).
        turn_in_place_rad: Heading errors above this turn the robot on the spot (rad).
        slow_radius_m: Speed falls linearly over this distance to an obstacle ahead (m,
            measured beyond the robot's radius; to zero) or to the path's end (to 15%).
    """

    lookahead_m: float = 0.6
    goal_tolerance_m: float = 0.3
    turn_gain: float = 3.0
    turn_in_place_rad: float = math.radians(60.0)
    slow_radius_m: float = 0.6

    def __post_init__(self) -> None:
        for name, unit in (
            ("lookahead_m", "m"),
            ("goal_tolerance_m", "m"),
            ("turn_gain", "1/s"),
            ("turn_in_place_rad", "rad"),
            ("slow_radius_m", "m"),
        ):
            require_positive("FollowerConfig", name, getattr(self, name), unit)


class PathFollower:
    """Drives along a path of points with pure pursuit.

    Args:
        max_speed_m_s: The robot's speed limit (m/s).
        max_turn_rad_s: The robot's turn-rate limit (rad/s).
        config: Tracking settings.

    Attributes:
        path: ``(N, 2)`` points (m) being followed; empty when there is none.
        blocked: Whether the last command wanted to drive on but an obstacle right ahead
            stopped it.
        turning: Whether the last command turned the robot on the spot towards the path.
    """

    def __init__(
        self, max_speed_m_s: float, max_turn_rad_s: float, config: FollowerConfig | None = None
    ) -> None:
        self.v_max = max_speed_m_s
        self.w_max = max_turn_rad_s
        self.config = config or FollowerConfig()
        self.path = np.zeros((0, 2))
        self.blocked = False
        self.turning = False
        self._progress = 0

    def set_path(self, points: np.ndarray) -> None:
        """Follow ``points`` (``(N, 2)`` m) from the first."""
        self.path = np.asarray(points, dtype=float).reshape(-1, 2)
        self._progress = 0

    def clear(self) -> None:
        """Drop the path."""
        self.set_path(np.zeros((0, 2)))

    @property
    def remaining(self) -> np.ndarray:
        """The part of the path not yet passed."""
        return self.path[self._progress :]

    def done(self, pose: tuple[float, float, float]) -> bool:
        """Whether there is no path or the robot has reached its end."""
        if len(self.path) == 0:
            return True
        return math.dist(pose[:2], self.path[-1]) <= self.config.goal_tolerance_m

    def command(self, pose: tuple[float, float, float], clearance_ahead_m: float) -> tuple[float, float]:
        """The velocity ``(v m/s, w rad/s)`` that tracks the path from ``pose``.

        Args:
            pose: The robot's pose (m, m, rad).
            clearance_ahead_m: Free distance ahead of the robot's front (m), from the laser.
        """
        self.blocked = self.turning = False
        if self.done(pose):
            return 0.0, 0.0
        x, y, heading = pose
        target = self._lookahead(x, y)
        error = math.remainder(math.atan2(target[1] - y, target[0] - x) - heading, math.tau)
        c = self.config
        w = max(-self.w_max, min(self.w_max, c.turn_gain * error))
        if abs(error) > c.turn_in_place_rad:
            self.turning = True
            return 0.0, w
        to_end = math.dist((x, y), self.path[-1])
        near_end = max(_MIN_SPEED_SHARE, min(1.0, to_end / c.slow_radius_m))
        near_obstacle = min(1.0, max(0.0, (clearance_ahead_m - _STOP_M) / c.slow_radius_m))
        self.blocked = near_obstacle == 0.0
        return self.v_max * math.cos(error) * min(near_end, near_obstacle), w

    def _lookahead(self, x: float, y: float) -> np.ndarray:
        """The first point at least ``lookahead_m`` ahead, after the one nearest the robot."""
        window = self.path[self._progress : self._progress + 50]
        d = np.hypot(window[:, 0] - x, window[:, 1] - y)
        self._progress += int(np.argmin(d))
        ahead = self.path[self._progress :]
        far = np.flatnonzero(np.hypot(ahead[:, 0] - x, ahead[:, 1] - y) >= self.config.lookahead_m)
        return ahead[far[0]] if len(far) else ahead[-1]
