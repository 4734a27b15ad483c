"""A reactive wall follower: keeps a wall at a set distance on one side, from the laser alone."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from realistic_indoor.agents.base import Agent, RobotSpec
from realistic_indoor.checks import require_positive, require_range
from realistic_indoor.errors import ConfigError

__all__ = ["WallFollower"]

_LANE_MARGIN_M = 0.1
"""The distance ahead is that of the nearest return in the robot's lane: its width plus this on
each side (m)."""
_SIDE = (math.radians(60.0), math.radians(120.0))
"""Sector of beams, from the heading, whose nearest return is the distance to the side wall (rad)."""
_DIAGONAL = (math.radians(20.0), math.radians(60.0))
"""Sector that sees a wall coming up ahead on the followed side (rad)."""
_GAP = (math.radians(75.0), math.radians(105.0))
"""Sector straight to the followed side through which a doorway in the side wall shows (rad)."""
_BESIDE = (math.radians(30.0), math.radians(150.0))
"""Beams whose crossings of the side wall's line tell where a doorway in it lies (rad)."""
_THROUGH_M = 0.5
"""A beam passes through a doorway when it reaches this far beyond the side wall's line (m)."""
_DOORWAY_STOP_M = 0.1
"""A doorway manoeuvre stops when something is this close ahead of the robot's disc (m)."""
_STEADY_STEPS, _STEADY_TURN = 1, 0.3
"""A doorway is taken only after this many steps along the wall turning under this share of the
turn-rate limit (not while the robot is already going round a corner)."""
_IN_RANGE = 0.999
"""Share of the laser's range under which a reading is a return, not the absence of one."""
_SEEK_ALIGNED = math.radians(15.0)
"""While seeking, the robot turns on the spot until the nearest return is this close to ahead (rad)."""
_CURVE_SPEED_SHARE, _CURVE_TURN_SHARE = 0.35, 0.5
"""Speed and turn rate, as shares of the limits, of the curve towards a side that lost its wall."""


class WallFollower(Agent):
    """Follows the wall on one side (the right-hand rule), like a maze-solving robot.

    It has two states. **Seeking** (at the start, and after losing the wall): it turns towards
    the nearest return of the scan and drives straight at it (straight ahead when nothing is in
    range) until a wall is within twice ``distance_m`` on the followed side or ahead, as maze
    robots do. **Following**: each step it looks at three sectors of the scan: ahead, the
    diagonal on the followed side and the followed side. With a wall ahead (or coming up on the
    diagonal) it turns away on the spot; with no wall on the side (a doorway, an outer corner)
    it curves towards that side to go round; otherwise it drives on and steers to keep the side
    wall at ``distance_m`` (proportional control; in a passage narrower than twice that, its
    middle). Curving for a full turn without meeting a
    wall means the wall is lost: it seeks again. It has no map: a building with a loop of
    corridors can trap it in the loop.

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
        self._toward = toward
        self._beside = (toward > _BESIDE[0]) & (toward < _BESIDE[1])
        self._ahead = np.abs(offsets) < math.pi / 2
        self._cos, self._sin = np.cos(offsets), np.abs(np.sin(offsets))
        self._side = (toward >= _SIDE[0]) & (toward <= _SIDE[1])
        self._other_side = (-toward >= _SIDE[0]) & (-toward <= _SIDE[1])
        self._diagonal = (toward >= _DIAGONAL[0]) & (toward < _DIAGONAL[1])
        self._gap = (toward >= _GAP[0]) & (toward <= _GAP[1])
        self._sign = -1.0 if side == "right" else 1.0
        self._offsets = offsets
        # Steps of curving towards the lost side that make a full turn: then the wall is lost.
        self._lost_limit = math.ceil(
            math.tau / (_CURVE_TURN_SHARE * spec.robot.max_turn_rate_rad_s * spec.dt_s)
        )
        self.seeking = True
        self._curving_steps = 0
        self._steady_steps = 0
        self._manoeuvre: list[tuple[float, float]] = []

    def reset(self, seed: int | None = None) -> None:
        """Start a new episode seeking a wall."""
        self.seeking = True
        self._curving_steps = 0
        self._steady_steps = 0
        self._manoeuvre = []

    def act(self, obs: dict[str, np.ndarray], info: dict[str, Any]) -> np.ndarray | int:
        """Seek a wall, or steer along it, from the current scan."""
        ranges = np.asarray(obs["scan"], dtype=float) * self.spec.lidar.max_range_m
        keep = self.distance_m
        front = self._distance_ahead(ranges)
        side = _nearest(ranges, self._side)
        if self.seeking and min(front - self.spec.robot.radius_m, side) <= 2.0 * keep:
            self.seeking = False
            self._curving_steps = 0
        if self._manoeuvre:
            return self._next_manoeuvre(front)
        if self.seeking:
            return self._seek(ranges, front)
        return self._follow(ranges, front, side)

    def _distance_ahead(self, ranges: np.ndarray) -> float:
        """How far the robot can drive straight before its disc (plus a margin) meets a return (m)."""
        lane = self._ahead & (ranges * self._sin < self.spec.robot.radius_m + _LANE_MARGIN_M)
        return float((ranges[lane] * self._cos[lane]).min()) if lane.any() else math.inf

    def _seek(self, ranges: np.ndarray, front: float) -> np.ndarray | int:
        """Turn towards the nearest return, then drive straight at it."""
        v_max = self.speed_share * self.spec.robot.max_speed_m_s
        w_max = self.spec.robot.max_turn_rate_rad_s
        in_range = ranges < _IN_RANGE * self.spec.lidar.max_range_m
        if not in_range.any():
            return self.spec.action(v_max, 0.0)
        bearing = float(self._offsets[np.argmin(np.where(in_range, ranges, np.inf))])
        if abs(bearing) > _SEEK_ALIGNED:
            return self.spec.action(0.0, math.copysign(w_max, bearing))
        return self.spec.action(v_max, max(-w_max, min(w_max, self.gain * bearing)))

    def _plan_doorway(self, ranges: np.ndarray, side: float) -> bool:
        """Queue the way through a doorway in the side wall: square up, on to its middle, turn, through.

        The side wall's line is fitted to the returns beside the robot that stop at it; the
        doorway's extent along that line is where the beams that pass beyond it (the run of them
        around the one square to the side) cross it. The
        robot turns parallel to the wall, drives on to the doorway's middle, turns a quarter on
        the spot to face through, and drives on until its disc has passed the wall's line.

        Returns:
            Whether a doorway wide enough for the robot was found (and the manoeuvre queued).
        """
        x, y = ranges * self._cos, ranges * np.sin(self._toward)  # ahead, towards the side (m)
        returns = self._beside & (ranges < _IN_RANGE * self.spec.lidar.max_range_m)
        through = self._beside & (y > side + _THROUGH_M)
        wall = returns & ~through & (y > 0)
        # an opening with nothing in range behind it leads outside (an entrance): not taken
        if wall.sum() < 3 or not (through & returns).any():
            return False
        through = _run_around(through, int(np.argmin(np.abs(self._toward - math.pi / 2))))
        if not through.any():
            return False
        slope, offset = np.polyfit(x[wall], y[wall], 1)
        angle = math.atan(slope)  # of the wall to the heading, > 0 turning towards the side
        t = self._toward[through]
        hit = offset / (np.sin(t) - slope * np.cos(t))  # range at which each beam crosses the line
        along = hit * np.cos(t - angle) - offset * math.sin(angle)  # from the robot's foot on it
        if along.max() - along.min() < 2.0 * self.spec.robot.radius_m:
            return False
        self._manoeuvre = self._turn(angle)
        self._manoeuvre += self._straight(max(0.0, 0.5 * (along.min() + along.max())))
        self._manoeuvre += self._turn(math.pi / 2)
        self._manoeuvre += self._straight(offset * math.cos(angle) + self.spec.robot.radius_m)
        return True

    def _turn(self, angle_rad: float) -> list[tuple[float, float]]:
        """Commands that turn the robot on the spot by ``angle_rad`` towards the followed side."""
        dt = self.spec.dt_s
        steps = math.ceil(abs(angle_rad) / (self.spec.robot.max_turn_rate_rad_s * dt))
        return [(0.0, self._sign * angle_rad / (steps * dt))] * steps if steps else []

    def _straight(self, distance_m: float) -> list[tuple[float, float]]:
        """Commands that drive the robot straight on by ``distance_m``."""
        dt = self.spec.dt_s
        steps = math.ceil(distance_m / (self.speed_share * self.spec.robot.max_speed_m_s * dt))
        return [(distance_m / (steps * dt), 0.0)] * steps if steps > 0 else []

    def _next_manoeuvre(self, front: float) -> np.ndarray | int:
        """The next command of the queued manoeuvre, unless something is right ahead."""
        if front < self.spec.robot.radius_m + _DOORWAY_STOP_M:
            self._manoeuvre = []
            return self.spec.action(0.0, -self._sign * self.spec.robot.max_turn_rate_rad_s)
        v, w = self._manoeuvre.pop(0)
        return self.spec.action(v, w)

    def _follow(self, ranges: np.ndarray, front: float, side: float) -> np.ndarray | int:
        """Keep the wall at ``distance_m`` on the followed side; go round corners and doorways."""
        v_max = self.speed_share * self.spec.robot.max_speed_m_s
        w_max = self.spec.robot.max_turn_rate_rad_s
        # in a passage narrower than twice the distance, keep to its middle
        keep = min(self.distance_m, 0.5 * (side + _nearest(ranges, self._other_side)))
        diagonal = _nearest(ranges, self._diagonal)
        if front < keep + self.spec.robot.radius_m or diagonal < keep:
            self._curving_steps = 0
            return self.spec.action(0.0, -self._sign * w_max)
        steady = self._steady_steps >= _STEADY_STEPS
        self._steady_steps = 0
        doorway = steady and side <= 2.0 * keep and _nearest(ranges, self._gap) > 3.0 * keep
        if doorway and self._plan_doorway(ranges, side):
            return self._next_manoeuvre(front)
        if side > 2.0 * keep:
            self._curving_steps += 1
            if self._curving_steps > self._lost_limit:
                self.seeking = True
                return self._seek(ranges, front)
            return self.spec.action(_CURVE_SPEED_SHARE * v_max, self._sign * _CURVE_TURN_SHARE * w_max)
        self._curving_steps = 0
        w = max(-w_max, min(w_max, -self._sign * self.gain * (keep - side)))
        self._steady_steps = self._steady_steps + 1 if abs(w) < _STEADY_TURN * w_max else 0
        return self.spec.action(v_max, w)

    def __repr__(self) -> str:
        return f"WallFollower(side={self.side!r}, distance_m={self.distance_m})"


def _nearest(ranges: np.ndarray, sector: np.ndarray) -> float:
    """Nearest return in a sector of beams (infinite for an empty sector)."""
    return float(ranges[sector].min()) if sector.any() else math.inf


def _run_around(mask: np.ndarray, i: int) -> np.ndarray:
    """The run of consecutive true entries of ``mask`` that holds entry ``i`` (none if it is false)."""
    run = np.zeros_like(mask)
    if not mask[i]:
        return run
    lo, hi = i, i
    while lo > 0 and mask[lo - 1]:
        lo -= 1
    while hi < len(mask) - 1 and mask[hi + 1]:
        hi += 1
    run[lo : hi + 1] = True
    return run
