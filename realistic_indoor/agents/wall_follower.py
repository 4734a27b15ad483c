"""A reactive wall follower: keeps a wall at a set distance on one side, from the laser alone."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from realistic_indoor.agents.base import Agent, RobotSpec
from realistic_indoor.agents.openings import Opening, find_openings, lane_length
from realistic_indoor.checks import require_positive, require_range
from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.lidar import beam_offsets

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
_DOORWAY_STOP_M, _DOORWAY_MARGIN_M = 0.1, 0.03
"""A manoeuvre stops when something is this close ahead of the robot's disc (m), in a lane as
wide as the robot plus this on each side (m): a 0.6 m doorway lets a 0.5 m robot through."""
_CENTRING_M = 0.8
"""Walls within this ahead and to each side are a doorway's jambs to keep in the middle of (m)."""
_UNSEEN_M = 0.3
"""A collision while driving with nothing within this of the disc ahead is the invisible line
across an entrance (m)."""
_STEADY_STEPS, _STEADY_TURN = 1, 0.3
"""A doorway is taken only after this many steps along the wall turning under this share of the
turn-rate limit (not while the robot is already going round a corner)."""
_DOORWAY_SQUARE_RAD, _DOORWAY_AHEAD_M = math.radians(30.0), 2.0
"""A doorway is taken only if the side wall's line is within this of the heading (rad) and the
doorway's middle lies within this ahead of the robot (m): else the fit is not of one wall."""
_DOORWAY_PAUSE_STEPS = 10
"""After backing out of an entrance, doorways are not looked for during this many steps."""
_IN_RANGE = 0.999
"""Share of the laser's range under which a reading is a return, not the absence of one."""
_SEEK_ALIGNED = math.radians(15.0)
"""While seeking, the robot turns on the spot until the nearest return is this close to ahead (rad)."""
_CURVE_SPEED_SHARE, _CURVE_TURN_SHARE = 0.35, 0.5
"""Speed and turn rate, as shares of the limits, of the curve towards a side that lost its wall."""
_LOOP_RAD = math.tau
"""Net turning while following that means a lap without leaving: away from the followed side
round a room, towards it round a free-standing block (rad)."""
_BEYOND_M = 0.5
"""Through a doorway or an opening, the robot drives on until its disc is this far beyond the
line of the wall (m): clear of the jambs."""
_APPROACH_M = 0.6
"""Leaving a loop, the robot lines up this far in front of the opening's middle (m)."""
_ESCAPE_TRIES = 3
"""Openings tried in a row (each after backing out of an entrance) before following the other side."""


@dataclass(frozen=True)
class _Sectors:
    """The beams the rules look at when following the wall on one side.

    Attributes:
        sign: -1 for the right-hand wall, +1 for the left-hand one (turning towards it is
            ``sign`` times a positive turn rate).
        toward: Direction of each beam from the heading, measured towards the side (rad).
    """

    sign: float
    toward: np.ndarray
    side: np.ndarray
    other_side: np.ndarray
    diagonal: np.ndarray
    gap: np.ndarray
    beside: np.ndarray

    @classmethod
    def of(cls, offsets: np.ndarray, side: str) -> _Sectors:
        """The sectors of beams at ``offsets`` (rad, right to left) for following on ``side``."""
        sign = -1.0 if side == "right" else 1.0
        toward = offsets * sign
        return cls(
            sign,
            toward,
            side=(toward >= _SIDE[0]) & (toward <= _SIDE[1]),
            other_side=(-toward >= _SIDE[0]) & (-toward <= _SIDE[1]),
            diagonal=(toward >= _DIAGONAL[0]) & (toward < _DIAGONAL[1]),
            gap=(toward >= _GAP[0]) & (toward <= _GAP[1]),
            beside=(toward > _BESIDE[0]) & (toward < _BESIDE[1]),
        )


class WallFollower(Agent):
    """Follows the wall on one side (the right-hand rule), like a maze-solving robot.

    **Seeking** (at the start, and after losing the wall): it turns towards the nearest return
    of the scan and drives straight at it (straight ahead when nothing is in range) until a wall
    is within twice ``distance_m`` on the followed side or within ``distance_m`` of its disc
    ahead.

    **Following**: each step it looks at three sectors of the scan: ahead, the diagonal on the
    followed side and the followed side. With a wall ahead (or coming up on the diagonal) it
    turns away on the spot; with no wall on the side (an outer corner) it curves towards that
    side to go round; otherwise it drives on and steers to keep the side wall at ``distance_m``
    (proportional control; in a passage narrower than twice that, its middle). Curving for a
    full turn without meeting a wall means the wall is lost: it seeks again.

    **Doorways** in the followed wall are taken: the wall's line is fitted to the scan, the
    robot drives on to the doorway's middle, turns a quarter towards it and drives through,
    steering to the middle between the jambs. The laser cannot tell an entrance (the open air)
    from a hall deeper than its range: a robot stopped by something it does not see ahead has
    met the line across an entrance (its bumper tells it). It gives up the doorway and turns
    back; met while following, the line is turned away from as a wall ahead.

    **Loops**: it counts its net turning since it last went through a doorway, from the turn
    rate it measures (``obs["velocity"]``, as a maze robot counts its turns with a gyro; the
    Pledge algorithm's counter). A full turn away from the followed side means it has gone
    round a room without finding a way out (a doorway by a corner, a room too small to follow
    its walls): it leaves by an opening of the scan
    (:func:`~realistic_indoor.agents.openings.find_openings`), those with a wall seen beyond
    them first, the deepest first: it lines up in front of the opening's middle, drives
    through and follows on. Stopped by an entrance instead, it turns round and tries the
    openings it sees then; with none in view, it makes a half turn to look behind it. A full
    turn towards the followed side means it has gone round a free-standing block of rooms: it
    follows the other side from then on, as it does when a loop has no opening to leave by
    (it keeps no map).

    Args:
        spec: The robot's sensors and limits.
        side: ``"right"`` or ``"left"``: the wall it keeps beside it at the start.
        distance_m: Distance to keep between the robot's centre and the wall (m).
        speed_share: Share of the top speed it drives at, in ``(0, 1]``.
        gain: Turn rate per metre of distance error (rad/s per m).

    Attributes:
        seeking: Whether it is looking for a wall.
        following: The side of the wall it follows now (``side`` until a loop made it switch).
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
        offsets = beam_offsets(spec.lidar)
        self._offsets = offsets
        self._sectors = {s: _Sectors.of(offsets, s) for s in ("right", "left")}
        self._ahead = np.abs(offsets) < math.pi / 2
        self._cos, self._sin = np.cos(offsets), np.abs(np.sin(offsets))
        # Steps of curving towards the lost side that make a full turn: then the wall is lost.
        self._lost_limit = math.ceil(
            math.tau / (_CURVE_TURN_SHARE * spec.robot.max_turn_rate_rad_s * spec.dt_s)
        )
        self.reset()

    def reset(self, seed: int | None = None) -> None:
        """Start a new episode seeking a wall on ``side``."""
        self.seeking = True
        self.following = self.side
        self._s = self._sectors[self.side]
        self._curving_steps = 0
        self._steady_steps = 0
        self._doorway_pause = 0
        self._turned = 0.0
        self._collisions = 0
        self._escape_tries = 0
        self._looked_behind = False
        self._manoeuvre: list[tuple[float, float]] = []
        self._then: Callable[[], Any] | None = None
        self._backing_out: Callable[[], None] | None = None
        self._driving = False
        self._ranges = np.zeros(0)

    def act(self, obs: dict[str, np.ndarray], info: dict[str, Any]) -> np.ndarray | int:
        """Seek a wall, steer along it, or go on with a manoeuvre, from the current scan."""
        ranges = np.asarray(obs["scan"], dtype=float) * self.spec.lidar.max_range_m
        self._ranges = ranges
        self._turned -= self._s.sign * float(obs["velocity"][1]) * self.spec.dt_s
        unseen = self._bumped(info) and self._driving
        front = self._distance_ahead(ranges, _LANE_MARGIN_M)
        side = _nearest(ranges, self._s.side)
        near = front - self.spec.robot.radius_m <= self.distance_m or side <= 2.0 * self.distance_m
        if self.seeking and near:
            self.seeking = False
            self._curving_steps = 0
            self._turned = 0.0
        unseen = unseen and front > self.spec.robot.radius_m + _UNSEEN_M
        v, w = self._command(ranges, front, side, unseen)
        self._driving = v > 0.0
        return self.spec.action(v, w)

    def _command(self, ranges: np.ndarray, front: float, side: float, unseen: bool) -> tuple[float, float]:
        """The velocity ``(v m/s, w rad/s)`` of this step."""
        if unseen:
            self._bumped_unseen()
        if self._manoeuvre:
            return self._next_manoeuvre(ranges)
        if self._then is not None:
            then, self._then = self._then, None
            self._backing_out = None
            then()
        if self._manoeuvre:
            return self._next_manoeuvre(ranges)
        if self.seeking:
            return self._seek(ranges)
        if self._turned >= _LOOP_RAD:
            return self._leave_loop(ranges, front)
        if self._turned <= -_LOOP_RAD and self._curving_steps == 0:
            self._switch_side()
        return self._follow(ranges, front, side)

    def _bumped(self, info: dict[str, Any]) -> bool:
        """Whether the robot touched a wall during the last step (``info["collisions"]`` rose)."""
        count = int(info.get("collisions", 0))
        hit, self._collisions = count > self._collisions, count
        return hit

    def _distance_ahead(self, ranges: np.ndarray, margin_m: float) -> float:
        """How far the robot can drive straight before its disc plus ``margin_m`` meets a return (m)."""
        lane = self._ahead & (ranges * self._sin < self.spec.robot.radius_m + margin_m)
        return float((ranges[lane] * self._cos[lane]).min()) if lane.any() else math.inf

    def _seek(self, ranges: np.ndarray) -> tuple[float, float]:
        """Turn towards the nearest return, then drive straight at it."""
        v_max = self.speed_share * self.spec.robot.max_speed_m_s
        w_max = self.spec.robot.max_turn_rate_rad_s
        in_range = ranges < _IN_RANGE * self.spec.lidar.max_range_m
        if not in_range.any():
            return v_max, 0.0
        bearing = float(self._offsets[np.argmin(np.where(in_range, ranges, np.inf))])
        if abs(bearing) > _SEEK_ALIGNED:
            return 0.0, math.copysign(w_max, bearing)
        return v_max, max(-w_max, min(w_max, self.gain * bearing))

    def _follow(self, ranges: np.ndarray, front: float, side: float) -> tuple[float, float]:
        """Keep the wall at ``distance_m`` on the followed side; go round corners and doorways."""
        v_max = self.speed_share * self.spec.robot.max_speed_m_s
        w_max = self.spec.robot.max_turn_rate_rad_s
        sign = self._s.sign
        # in a passage narrower than twice the distance, keep to its middle
        keep = min(self.distance_m, 0.5 * (side + _nearest(ranges, self._s.other_side)))
        diagonal = _nearest(ranges, self._s.diagonal)
        if front < keep + self.spec.robot.radius_m or diagonal < keep:
            self._curving_steps = 0
            return 0.0, -sign * w_max
        steady = self._steady_steps >= _STEADY_STEPS and self._doorway_pause == 0
        self._steady_steps = 0
        self._doorway_pause = max(0, self._doorway_pause - 1)
        doorway = steady and side <= 2.0 * keep and _nearest(ranges, self._s.gap) > 3.0 * keep
        if doorway and self._plan_doorway(ranges, side):
            return self._next_manoeuvre(ranges)
        if side > 2.0 * keep:
            self._curving_steps += 1
            if self._curving_steps > self._lost_limit:
                self.seeking = True
                return self._seek(ranges)
            return _CURVE_SPEED_SHARE * v_max, sign * _CURVE_TURN_SHARE * w_max
        self._curving_steps = 0
        w = max(-w_max, min(w_max, -sign * self.gain * (keep - side)))
        self._steady_steps = self._steady_steps + 1 if abs(w) < _STEADY_TURN * w_max else 0
        return v_max, w

    def _plan_doorway(self, ranges: np.ndarray, side: float) -> bool:
        """Queue the way through a doorway in the side wall: square up, on to its middle, turn, through.

        The side wall's line is fitted to the returns beside the robot that stop at it; the
        doorway's extent along that line is where the beams that pass beyond it (the run of them
        around the one square to the side) cross it. The robot turns parallel to the wall,
        drives on to the doorway's middle, turns a quarter on the spot to face through, and
        drives on until its disc is :data:`_BEYOND_M` past the wall's line.

        Returns:
            Whether a doorway wide enough for the robot was found (and the manoeuvre queued).
        """
        s = self._s
        x, y = ranges * self._cos, ranges * np.sin(s.toward)  # ahead, towards the side (m)
        returns = s.beside & (ranges < _IN_RANGE * self.spec.lidar.max_range_m)
        through = s.beside & (y > side + _THROUGH_M)
        wall = returns & ~through & (y > 0)
        if wall.sum() < 3:
            return False
        through = _run_around(through, int(np.argmin(np.abs(s.toward - math.pi / 2))))
        if not through.any():
            return False
        slope, offset = np.polyfit(x[wall], y[wall], 1)
        angle = math.atan(slope)  # of the wall to the heading, > 0 turning towards the side
        t = s.toward[through]
        hit = offset / (np.sin(t) - slope * np.cos(t))  # range at which each beam crosses the line
        along = hit * np.cos(t - angle) - offset * math.sin(angle)  # from the robot's foot on it
        middle = 0.5 * (along.min() + along.max())
        if along.max() - along.min() < 2.0 * self.spec.robot.radius_m:
            return False
        if abs(angle) > _DOORWAY_SQUARE_RAD or not -self.spec.robot.radius_m < middle < _DOORWAY_AHEAD_M:
            return False
        self._queue(
            self._turn(s.sign * angle)
            + self._straight(max(0.0, middle))
            + self._turn(s.sign * math.pi / 2)
            + self._straight(offset * math.cos(angle) + self.spec.robot.radius_m + _BEYOND_M),
            then=self._went_through,
            back_out=self._left_entrance,
        )
        return True

    def _leave_loop(self, ranges: np.ndarray, front: float) -> tuple[float, float]:
        """Leave a room the robot has gone round: through an opening, else along the other side."""
        if self._try_escape():
            return self._next_manoeuvre(ranges)
        return self._follow(ranges, front, _nearest(ranges, self._s.side))

    def _try_escape(self) -> bool:
        """Queue the way out through an opening, else a half turn to look behind for one.

        Returns:
            Whether a manoeuvre was queued; if not (too many tries, or nothing behind either),
            the robot follows the other side from now on.
        """
        if self._escape_tries < _ESCAPE_TRIES and self._plan_escape(self._ranges):
            self._escape_tries += 1
            return True
        if self._escape_tries < _ESCAPE_TRIES and not self._looked_behind:
            self._looked_behind = True
            self._manoeuvre = self._turn(math.pi)
            self._then = self._try_escape
            return True
        self._switch_side()
        return False

    def _plan_escape(self, ranges: np.ndarray) -> bool:
        """Queue the way out through the best opening in view: line up in front of it, then through.

        Returns:
            Whether an opening the robot can line up with in a straight drive was found.
        """
        r = self.spec.robot.radius_m
        openings = find_openings(
            ranges, self._offsets, self.spec.lidar.max_range_m, 2.0 * (r + 0.5 * _LANE_MARGIN_M)
        )
        for opening in sorted(openings, key=_preference):
            normal = opening.normal
            spot = opening.middle - _APPROACH_M * normal
            distance, bearing = float(np.hypot(*spot)), math.atan2(spot[1], spot[0])
            if lane_length(ranges, self._offsets, bearing, r + _LANE_MARGIN_M) < distance:
                continue
            facing = math.remainder(math.atan2(normal[1], normal[0]) - bearing, math.tau)
            self._queue(
                self._turn(bearing)
                + self._straight(distance)
                + self._turn(facing)
                + self._straight(_APPROACH_M + r + _BEYOND_M),
                then=self._went_through,
                back_out=self._escape_again,
            )
            return True
        return False

    def _queue(
        self,
        commands: list[tuple[float, float]],
        then: Callable[[], Any],
        back_out: Callable[[], None],
    ) -> None:
        """Start a manoeuvre; ``then`` runs when it is done, ``back_out`` if it meets an entrance."""
        self._manoeuvre = commands
        self._then = then
        self._backing_out = back_out

    def _bumped_unseen(self) -> None:
        """Meeting the invisible line across an entrance: back out, or turn away as from a wall.

        A manoeuvre that led there is given up for its own way back; otherwise the robot turns a
        quarter away from the followed side, as a bumper's reflex. It does not reverse: it
        cannot see behind it.
        """
        back_out, self._backing_out = self._backing_out, None
        self._then = None
        if back_out is not None:
            back_out()
        else:
            self.seeking = False
            self._manoeuvre = self._turn(-self._s.sign * math.pi / 2)

    def _left_entrance(self) -> None:
        """Back out of an entrance taken for a doorway: a quarter turn back, doorways paused."""
        self._manoeuvre = self._turn(-self._s.sign * math.pi / 2)
        self._doorway_pause = _DOORWAY_PAUSE_STEPS

    def _escape_again(self) -> None:
        """Back out of an entrance taken for a way out: turn round, then try what is in view."""
        self._manoeuvre = self._turn(math.pi)
        self._then = self._try_escape

    def _went_through(self) -> None:
        """A doorway was passed: a new room, a new count of turns."""
        self._turned = 0.0
        self._escape_tries = 0
        self._looked_behind = False

    def _switch_side(self) -> None:
        """Follow the wall on the other side from now on."""
        self.following = "left" if self.following == "right" else "right"
        self._s = self._sectors[self.following]
        self._turned = 0.0
        self._escape_tries = 0
        self._looked_behind = False

    def _turn(self, angle_rad: float) -> list[tuple[float, float]]:
        """Commands that turn the robot on the spot by ``angle_rad`` (counter-clockwise positive)."""
        dt = self.spec.dt_s
        steps = math.ceil(abs(angle_rad) / (self.spec.robot.max_turn_rate_rad_s * dt))
        return [(0.0, angle_rad / (steps * dt))] * steps if steps else []

    def _straight(self, distance_m: float) -> list[tuple[float, float]]:
        """Commands that drive the robot straight on by ``distance_m``."""
        dt = self.spec.dt_s
        steps = math.ceil(distance_m / (self.speed_share * self.spec.robot.max_speed_m_s * dt))
        return [(distance_m / (steps * dt), 0.0)] * steps if steps > 0 else []

    def _next_manoeuvre(self, ranges: np.ndarray) -> tuple[float, float]:
        """The next command of the queued manoeuvre, unless something is right ahead.

        Driving straight between two walls closer than :data:`_CENTRING_M` on both sides (the
        jambs of a doorway), it steers to the middle between them.
        """
        v, w = self._manoeuvre[0]
        front = self._distance_ahead(ranges, _DOORWAY_MARGIN_M)
        if v > 0.0 and front < self.spec.robot.radius_m + _DOORWAY_STOP_M:
            self._manoeuvre = []
            self._then = self._backing_out = None
            return 0.0, -self._s.sign * self.spec.robot.max_turn_rate_rad_s
        self._manoeuvre.pop(0)
        if v > 0.0 and w == 0.0:
            w = self._centring(ranges)
        return v, w

    def _centring(self, ranges: np.ndarray) -> float:
        """Turn rate towards the middle between the walls just ahead on the left and right (rad/s)."""
        along, across = ranges * self._cos, ranges * np.sin(self._offsets)
        near = (along > 0.0) & (along < _CENTRING_M) & (np.abs(across) < _CENTRING_M)
        left, right = _nearest(across, near & (across > 0)), _nearest(-across, near & (across < 0))
        if math.isinf(left) or math.isinf(right):
            return 0.0
        w_max = self.spec.robot.max_turn_rate_rad_s
        return max(-w_max, min(w_max, self.gain * (left - right)))

    def __repr__(self) -> str:
        return f"WallFollower(side={self.side!r}, distance_m={self.distance_m})"


def _preference(opening: Opening) -> tuple[bool, float]:
    """Sort key of the openings to leave by: a wall seen beyond first, then the deepest."""
    return (not opening.seen_beyond, -opening.depth_m)


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
