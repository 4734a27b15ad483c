"""What a robot of a team observes beyond the single environment's observation, and the team's state.

Each robot sees what it would see alone (:mod:`realistic_indoor.envs.observations`) plus:

- ``teammates``: ``(n_robots - 1, 5)`` float32, one row per other robot in agent order:
  ``(direct, connected, x, y, heading)``: 1 if linked to it directly, 1 if linked directly or
  through others; then, when connected, its pose in this robot's frame (``x`` m ahead, ``y`` m
  to the left, clipped to :data:`~realistic_indoor.envs.observations.POSE_LIMIT_M`; heading
  difference in rad, ``[-pi, pi]``), zeros when not (a robot knows where a teammate is only
  through its links).
- ``base``: ``(4,)`` float32 ``(direct, connected, x, y)``: its link to the base station, and the
  base's position in its frame (known from the start: the robots start beside it).

The team's state (:func:`state_image`, PettingZoo's ``state()``) is a fixed-orientation image of
the team map: what the team as a whole has observed.
"""

from __future__ import annotations

import math

import numpy as np
from gymnasium import spaces
from numba import njit

from realistic_indoor.envs.observations import POSE_LIMIT_M
from realistic_indoor.sim.disc_physics import wrap_angle

__all__ = [
    "base_space",
    "observe_team",
    "state_space",
    "teammates_space",
]


def teammates_space(n_robots: int) -> spaces.Box:
    """The space of ``teammates`` for a team of ``n_robots``."""
    high = np.array([1.0, 1.0, POSE_LIMIT_M, POSE_LIMIT_M, math.pi], dtype=np.float32)
    low = np.array([0.0, 0.0, -POSE_LIMIT_M, -POSE_LIMIT_M, -math.pi], dtype=np.float32)
    n = n_robots - 1
    return spaces.Box(np.tile(low, (n, 1)), np.tile(high, (n, 1)), (n, 5), np.float32)


def base_space() -> spaces.Box:
    """The space of ``base``."""
    high = np.array([1.0, 1.0, POSE_LIMIT_M, POSE_LIMIT_M], dtype=np.float32)
    low = np.array([0.0, 0.0, -POSE_LIMIT_M, -POSE_LIMIT_M], dtype=np.float32)
    return spaces.Box(low, high, (4,), np.float32)


def observe_team(
    poses: np.ndarray, base_xy: tuple[float, float], links: np.ndarray, components: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Each robot's ``teammates`` and ``base`` observations, in one compiled call.

    Args:
        poses: ``(n, 3)`` robot poses ``(x m, y m, heading rad)``.
        base_xy: The base station's position (m).
        links: ``(n + 1, n + 1)`` bool direct links (robots, then the base).
        components: ``(n + 1,)`` component of each node in the link graph.

    Returns:
        ``(teammates, base)``: ``(n, n - 1, 5)`` and ``(n, 4)`` float32, as the module describes.
    """
    return _team_view(poses, links, components, float(base_xy[0]), float(base_xy[1]), POSE_LIMIT_M)


@njit(cache=True, nogil=True)
def _team_view(poses, links, components, base_x, base_y, limit):  # pragma: no cover - compiled
    """Each robot's ``teammates`` and ``base`` rows: other nodes in its frame, clipped to ``limit`` (m)."""
    n = poses.shape[0]
    mates = np.zeros((n, max(n - 1, 0), 5), dtype=np.float32)
    base = np.zeros((n, 4), dtype=np.float32)
    for i in range(n):
        c, s = math.cos(poses[i, 2]), math.sin(poses[i, 2])
        k = 0
        for j in range(n):
            if j == i:
                continue
            known = components[i] == components[j]
            mates[i, k, 0] = 1.0 if links[i, j] else 0.0
            mates[i, k, 1] = 1.0 if known else 0.0
            if known:
                dx, dy = poses[j, 0] - poses[i, 0], poses[j, 1] - poses[i, 1]
                mates[i, k, 2] = min(max(c * dx + s * dy, -limit), limit)
                mates[i, k, 3] = min(max(c * dy - s * dx, -limit), limit)
                mates[i, k, 4] = wrap_angle(poses[j, 2] - poses[i, 2])
            k += 1
        base[i, 0] = 1.0 if links[i, n] else 0.0
        base[i, 1] = 1.0 if components[i] == components[n] else 0.0
        dx, dy = base_x - poses[i, 0], base_y - poses[i, 1]
        base[i, 2] = min(max(c * dx + s * dy, -limit), limit)
        base[i, 3] = min(max(c * dy - s * dx, -limit), limit)
    return mates, base


def state_space(size_px: int) -> spaces.Box:
    """The team state's space: ``(4, S, S)`` uint8 (free, wall, unknown, robots; 0 or 255)."""
    return spaces.Box(0, 255, (4, size_px, size_px), np.uint8)
