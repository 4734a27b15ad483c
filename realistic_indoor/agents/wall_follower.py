"""A reactive wall follower: keeps a wall at a set distance on one side, from the laser alone."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from realistic_indoor.agents.base import Agent, RobotSpec
from realistic_indoor.checks import require_positive, require_range
from realistic_indoor.errors import ConfigError

__all__ = ["WallFollower"]

_FRONT = math.radians(30.0)
"""Half-width of the sector whose nearest return is the distance ahead (rad)."""
_SIDE = (math.radians(60.0), math.radians(120.0))
"""Sector of beams, from the heading, whose nearest return is the distance to the side wall (rad)."""
_DIAGONAL = (math.radians(20.0), math.radians(60.0))
"""Sector that sees a wall coming up ahead on the followed side (rad)."""


class WallFollower(Agent):
    """Follows the wall on one side (the right-hand rule), like a maze-solving robot.

    Each step it looks at three sectors of the scan: ahead, the diagonal on the followed side
    and the followed side. With a wall ahead (or coming up on the diagonal) it turns away on the
    spot; with no wall on the side it curves towards that side to find one; otherwise it drives
    on and steers to keep the side wall at ``distance_m`` (proportional control). It has no
    memory and no map: a building with a loop of corridors can trap it in the loop.

    Args:
        spec: The robot's sensors and limits.
        side: ``"right"`` or ``"left"``: the wall it keeps beside it.
        distance_m: Distance to keep between the robot's centre and the wall (m).
        speed_share: Share of the top speed it drives at, in ``(0, 1]``.
        gain: Turn rate per metre of distance error (rad/s per m).
    """

    name = "wall"

    def __init__(
        self,
        spec: RobotSpec,
        side: str = "right",
        distance_m: float = 0.7,
        speed_share: float = 0.8,
        gain: float = 3.0,
    ) -> None:
        super().__init__(spec)
        if side not in ("right", "left"):
            raise ConfigError(f"WallFollower.side must be 'right' or 'left', got {side!r}")
        require_positive("WallFollower", "distance_m", distance_m, "m")
        require_range("WallFollower", "speed_share", speed_share, 0.0, 1.0, "")
        require_positive("WallFollower", "gain", gain, "rad/s per m")
        self.side = side
        self.distance_m = distance_m
        self.speed_share = speed_share
        self.gain = gain
        offsets = spec.beam_offsets_rad()
        toward = offsets * (-1.0 if side == "right" else 1.0)  # angles measured towards the side
        self._front = np.abs(offsets) <= _FRONT
        self._side = (toward >= _SIDE[0]) & (toward <= _SIDE[1])
        self._diagonal = (toward >= _DIAGONAL[0]) & (toward < _DIAGONAL[1])
        self._sign = -1.0 if side == "right" else 1.0

    def act(self, obs: dict[str, np.ndarray], info: dict[str, Any]) -> np.ndarray | int:
        """Steer along the wall from the current scan."""
        ranges = np.asarray(obs["scan"], dtype=float) * self.spec.lidar.max_range_m
        v_max = self.speed_share * self.spec.robot.max_speed_m_s
        w_max = self.spec.robot.max_turn_rate_rad_s
        keep = self.distance_m
        front = _nearest(ranges, self._front)
        diagonal = _nearest(ranges, self._diagonal)
        side = _nearest(ranges, self._side)
        if front < keep + self.spec.robot.radius_m or diagonal < keep:
            return self.spec.action(0.0, -self._sign * w_max)
        if side > 2.0 * keep:
            return self.spec.action(0.6 * v_max, self._sign * 0.5 * w_max)
        w = -self._sign * self.gain * (keep - side)
        return self.spec.action(v_max, max(-w_max, min(w_max, w)))

    def __repr__(self) -> str:
        return f"WallFollower(side={self.side!r}, distance_m={self.distance_m})"


def _nearest(ranges: np.ndarray, sector: np.ndarray) -> float:
    """Nearest return in a sector of beams (infinite for an empty sector)."""
    return float(ranges[sector].min()) if sector.any() else math.inf
