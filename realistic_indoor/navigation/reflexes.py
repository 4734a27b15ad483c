"""The reactions below planning: bumper, free space ahead, jams, being stuck, backing up."""

from __future__ import annotations

import math
from collections import deque
from typing import Any

import numpy as np

from realistic_indoor.navigation.own_map import OwnMap
from realistic_indoor.navigation.spec import RobotSpec
from realistic_indoor.sim.lidar import beam_offsets
from realistic_indoor.sim.mapping import MAPPED_FREE

__all__ = ["Reflexes"]

BACKUP_STEPS, BACKUP_SPEED = 3, 0.3
"""A robot backs up this many steps at this share of its top speed."""
JAM_STEPS = 5
"""A robot touching a wall, or blocked right ahead, this many steps in a row is jammed."""
_EXPLAINED_M, _MIN_BUMP_SPEED_M_S = 0.1, 0.1
"""A collision is explained by a wall the laser sees this close ahead of the robot's disc (m); a
robot slower than this (m/s) is not told apart from one stopped by an obstacle."""


class Reflexes:
    """What a map-based explorer does between plans to keep moving.

    Args:
        spec: The robot's sensors and limits.
        own_map: The agent's map (unseen obstacles are marked on it; backing up checks it).
        bump_half_width_m: Half-length of the wall marked where the robot hit an unseen obstacle,
            beyond the robot's radius (m).
        stuck_steps: Window of steps over which progress is measured.
        stuck_move_m: Less motion than this over the window is being stuck (m).

    Attributes:
        backing: Steps of backing up still to do.
    """

    def __init__(
        self,
        spec: RobotSpec,
        own_map: OwnMap,
        bump_half_width_m: float,
        stuck_steps: int,
        stuck_move_m: float,
    ) -> None:
        self.spec = spec
        self.map = own_map
        self.bump_half_width_m = bump_half_width_m
        self.stuck_move_m = stuck_move_m
        self._offsets = beam_offsets(spec.lidar)
        self._recent: deque[tuple[float, float]] = deque(maxlen=stuck_steps)
        self.reset()

    def reset(self) -> None:
        """Forget the last episode."""
        self.backing = 0
        self._collisions = 0
        self._jam = 0
        self._away = 0.0
        self._last_pose: tuple[float, float, float] | None = None
        self._recent.clear()

    # -- sensing ---------------------------------------------------------------------------------------
    def bumped(
        self, pose: tuple[float, float, float], ranges: np.ndarray, speed_m_s: float, info: dict[str, Any]
    ) -> bool:
        """Whether the robot touched a wall during the last step (``info["collisions"]`` rose).

        A contact that stopped the robot while it drove forward, with no wall in the laser's
        view just ahead of it, is an obstacle the laser cannot see (the line across an
        entrance): it is marked on the map, across the direction the robot was driving.
        """
        count = int(info.get("collisions", 0))
        hit = count > self._collisions
        self._collisions = count
        self._recent.append(pose[:2])
        if hit and self._last_pose is not None and self._unexplained(pose, ranges, speed_m_s):
            r = self.spec.robot.radius_m
            heading = self._last_pose[2]
            self.map.mark_blocked((pose[0], pose[1], heading), r, r + self.bump_half_width_m)
        return hit

    def clearance_ahead(self, ranges: np.ndarray) -> float:
        """Free distance in front of the robot's disc along its heading (m), from the scan."""
        r = self.spec.robot.radius_m
        lateral = np.abs(ranges * np.sin(self._offsets))
        ahead = (np.abs(self._offsets) < math.pi / 2) & (lateral <= r)
        if not ahead.any():
            return self.spec.lidar.max_range_m
        return float(np.min(ranges[ahead] * np.cos(self._offsets[ahead]))) - r

    def turn_away(self, ranges: np.ndarray) -> float:
        """Turn rate away from the nearer side of an obstacle right ahead (rad/s).

        Pure pursuit cuts corners: at a door jamb the robot can end up facing the jamb's end
        with its path just beyond it. Turning away lets it slide past.
        """
        if self._away == 0.0:  # keep the side chosen when the block began: no dithering
            front = np.abs(self._offsets) <= math.pi / 3
            left = float(np.min(ranges[front & (self._offsets > 0)], initial=np.inf))
            right = float(np.min(ranges[front & (self._offsets < 0)], initial=np.inf))
            self._away = 0.5 if right < left else -0.5
        return self._away * self.spec.robot.max_turn_rate_rad_s

    # -- after each command ------------------------------------------------------------------------------
    def record(self, pose: tuple[float, float, float], collided: bool, blocked: bool, turning: bool) -> None:
        """Note the pose a command was sent from, and whether the robot pushed against something.

        Touching a wall while turning on the spot towards the path is not a jam.
        """
        self._jam = self._jam + 1 if (collided or blocked) and not turning else 0
        if not blocked:
            self._away = 0.0
        self._last_pose = pose

    @property
    def jammed(self) -> bool:
        """Whether the robot has pushed against something for ``JAM_STEPS`` steps in a row."""
        return self._jam >= JAM_STEPS

    @property
    def stuck(self) -> bool:
        """Whether the robot moved less than ``stuck_move_m`` over the last ``stuck_steps`` steps."""
        if len(self._recent) < self._recent.maxlen:
            return False
        (x0, y0), (x1, y1) = self._recent[0], self._recent[-1]
        return math.hypot(x1 - x0, y1 - y0) < self.stuck_move_m

    def restart_progress(self) -> None:
        """Start measuring progress afresh (a new goal)."""
        self._recent.clear()

    # -- backing up ------------------------------------------------------------------------------------
    def start_backup(self, pose: tuple[float, float, float]) -> None:
        """Back up for ``BACKUP_STEPS`` steps, if the map shows free floor behind the robot."""
        self._jam = 0
        self.backing = BACKUP_STEPS if self._room_behind(pose) else 0

    def back_up(self) -> tuple[float, float]:
        """The backing-up command ``(v m/s, w rad/s)`` of this step."""
        self.backing -= 1
        return -BACKUP_SPEED * self.spec.robot.max_speed_m_s, 0.0

    def _unexplained(self, pose: tuple[float, float, float], ranges: np.ndarray, speed_m_s: float) -> bool:
        """Whether the robot, driving forward, went less than half the way with nothing seen ahead."""
        if speed_m_s < _MIN_BUMP_SPEED_M_S:
            return False
        x0, y0, heading = self._last_pose
        forward = (pose[0] - x0) * math.cos(heading) + (pose[1] - y0) * math.sin(heading)
        return forward < 0.5 * speed_m_s * self.spec.dt_s and self.clearance_ahead(ranges) > _EXPLAINED_M

    def _room_behind(self, pose: tuple[float, float, float]) -> bool:
        x, y, heading = pose
        r = self.spec.robot
        reach = r.radius_m + BACKUP_STEPS * BACKUP_SPEED * r.max_speed_m_s * self.spec.dt_s
        h, w = self.map.state.shape
        for side in (-0.8, 0.0, 0.8):
            angle = heading + math.pi + side
            row, col = self.map.to_cell(x + reach * math.cos(angle), y + reach * math.sin(angle))
            if not (0 <= row < h and 0 <= col < w) or self.map.state[row, col] != MAPPED_FREE:
                return False
        return True
