"""What each robot of a team knows: a common frame, who it is linked to, and whose map it shares.

Every robot's odometry starts at its own start pose; the robots start together, so their start
poses relative to robot 0 are known (the reset's ``info["start_pose"]``) and every pose is put in
the *team frame*, robot 0's odometry frame. The robots linked directly or through others (the
``connected`` column of the ``teammates`` observation) form groups; what a robot knows of its
teammates (their positions, their goals, their maps) comes only from its group.

Robots of a group also tell each other the victims they detected (:func:`share_victims`).
Maps follow the team's map sharing, as the environment's do: ``shared``, one map for the team;
``own``, a map each; ``comm``, the robots of a group map onto one map, a robot leaving a group
keeps a copy, and groups that join merge their maps.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from realistic_indoor.errors import ConfigError
from realistic_indoor.navigation.own_map import OwnMap
from realistic_indoor.navigation.victims import VictimTracker

__all__ = ["TeamFrames", "TeamMaps", "groups", "share_victims"]

Pose = tuple[float, float, float]


class TeamFrames:
    """Each robot's start pose in the team frame (robot 0's odometry frame).

    Args:
        starts: ``(n, 3)`` the robots' start poses in any common frame (m, m, rad).
    """

    def __init__(self, starts: np.ndarray) -> None:
        x0, y0, t0 = (float(v) for v in starts[0])
        c, s = math.cos(t0), math.sin(t0)
        self.offsets: list[Pose] = [
            (c * (x - x0) + s * (y - y0), c * (y - y0) - s * (x - x0), float(t) - t0)
            for x, y, t in np.asarray(starts, dtype=float)
        ]

    @classmethod
    def from_infos(cls, infos: Mapping[str, Mapping[str, Any]], agents: list[str]) -> TeamFrames:
        """The frames from the reset's infos (``start_pose`` per agent).

        Raises:
            ConfigError: If a robot's ``start_pose`` is missing (pass the reset's infos to the
                first ``act``).
        """
        missing = [a for a in agents if "start_pose" not in infos.get(a, {})]
        if missing:
            raise ConfigError(
                f"team agents need the reset's infos on their first act (start_pose of {missing[0]} missing)"
            )
        return cls(np.array([infos[a]["start_pose"] for a in agents], dtype=float))

    def to_team(self, robot: int, pose: np.ndarray) -> np.ndarray:
        """Robot ``robot``'s odometry pose ``(x, y, heading)`` in the team frame (float32)."""
        dx, dy, dt = self.offsets[robot]
        if robot == 0 or (dx, dy, dt) == (0.0, 0.0, 0.0):
            return pose
        x, y, t = (float(v) for v in pose[:3])
        c, s = math.cos(dt), math.sin(dt)
        return np.array([dx + c * x - s * y, dy + s * x + c * y, t + dt], dtype=np.float32)


def groups(observations: Mapping[str, Mapping[str, np.ndarray]], agents: list[str]) -> np.ndarray:
    """``(n,)`` the group of each robot: robots linked directly or through others share one.

    Read from each robot's ``teammates`` observation (column 1: connected); numbered in order of
    their lowest robot.
    """
    n = len(agents)
    out = np.full(n, -1, dtype=np.int64)
    label = 0
    for i, agent in enumerate(agents):
        if out[i] >= 0:
            continue
        out[i] = label
        if n > 1:
            others = [j for j in range(n) if j != i]
            connected = np.asarray(observations[agent]["teammates"])[:, 1] > 0.5
            out[[j for j, c in zip(others, connected, strict=True) if c]] = label
        label += 1
    return out


def share_victims(trackers: list[VictimTracker], group: np.ndarray) -> None:
    """Tell each robot the victims its group detected: a teammate's victim is the teammate's to visit.

    Every victim a robot of the group has detected (team frame) that robot ``i`` does not know
    is added to ``i``'s tracker as visited, so that ``i`` does not drive to it too; the robot
    that detected it goes on as before. Two robots that detect one victim in the same step both
    keep it.

    Args:
        trackers: Each robot's detected victims, in the team frame.
        group: ``(n,)`` each robot's group (:func:`groups`).
    """
    for i, mine in enumerate(trackers):
        for j, theirs in enumerate(trackers):
            if j != i and group[j] == group[i] and len(theirs.positions):
                mine.claim(theirs.positions)


class TeamMaps:
    """Which map each robot's navigator maps onto, kept as the team's map sharing says.

    Args:
        n: Robots.
        sharing: ``"shared"``, ``"own"`` or ``"comm"``.
        new_map: Makes an empty map (the navigators' own at the start).

    Attributes:
        maps: The map of each robot (one object for robots that share one).
    """

    def __init__(self, n: int, sharing: str, new_map: Callable[[int], OwnMap]) -> None:
        self.sharing = sharing
        first = new_map(0)
        self.maps = [first if sharing == "shared" else new_map(i) for i in range(n)]

    def update(self, group: np.ndarray) -> list[int]:
        """Share maps within each group (``comm`` only); return the robots whose map changed."""
        if self.sharing != "comm":
            return []
        changed = self._split(group)
        for label in np.unique(group):
            members = np.flatnonzero(group == label)
            distinct = list(dict.fromkeys(id(self.maps[i]) for i in members))
            if len(distinct) < 2:
                continue
            into = self.maps[members[0]]
            for i in members:
                if self.maps[i] is not into:
                    if not any(self.maps[j] is self.maps[i] for j in members if j < i):
                        into.merge(self.maps[i])
                    changed.append(int(i))
            for i in members:
                self.maps[i] = into
        return sorted(set(changed))

    def _split(self, group: np.ndarray) -> list[int]:
        """Robots sharing a map but no longer a group: all but the first group take a copy."""
        changed = []
        seen: dict[int, int] = {}
        copies: dict[tuple[int, int], OwnMap] = {}
        for i, own in enumerate(self.maps):
            owner = seen.setdefault(id(own), int(group[i]))
            if owner != group[i]:
                key = (id(own), int(group[i]))
                if key not in copies:
                    copies[key] = own.copy()
                self.maps[i] = copies[key]
                changed.append(i)
        return changed
