"""What a robot of a team observes beyond the single environment's observation, and the team's state.

Each robot sees what it would see alone (:mod:`realistic_indoor.envs.observations`) plus:

- ``teammates``: ``(n_robots - 1, 5)`` float32, one row per other robot in agent order:
  ``(direct, connected, x, y, heading)``: 1 if linked to it directly, 1 if linked directly or
  through others; then, when connected, its pose in this robot's frame (``x`` m ahead, ``y`` m
  to the left, clipped to :data:`~realistic_indoor.envs.observations.POSE_LIMIT_M`; heading
  difference in rad, ``[-pi, pi)``), zeros when not (a robot knows where a teammate is only
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

from realistic_indoor.envs.observations import POSE_LIMIT_M
from realistic_indoor.sim.disc_physics import wrap_angle

__all__ = ["base_space", "observe_base", "observe_teammates", "state_space", "teammates_space"]


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


def _relative(poses: np.ndarray, xy: np.ndarray) -> np.ndarray:
    """``(n, k, 2)`` the points ``xy`` (``(k, 2)`` m) in each robot's frame (x ahead, y left), clipped."""
    c, s = np.cos(poses[:, 2])[:, None], np.sin(poses[:, 2])[:, None]
    dx = xy[None, :, 0] - poses[:, None, 0]
    dy = xy[None, :, 1] - poses[:, None, 1]
    out = np.stack([c * dx + s * dy, c * dy - s * dx], axis=-1)
    return np.clip(out, -POSE_LIMIT_M, POSE_LIMIT_M)


def observe_teammates(poses: np.ndarray, links: np.ndarray, components: np.ndarray) -> np.ndarray:
    """``(n, n - 1, 5)`` float32: each robot's ``teammates`` observation.

    Args:
        poses: ``(n, 3)`` robot poses ``(x m, y m, heading rad)``.
        links: ``(n + 1, n + 1)`` bool direct links (robots, then the base).
        components: ``(n + 1,)`` component of each node in the link graph.
    """
    n = len(poses)
    rows = np.zeros((n, n, 5))
    robots = components[:n]
    known = robots[:, None] == robots[None, :]
    rows[..., 0] = links[:n, :n]
    rows[..., 1] = known
    rows[..., 2:4] = _relative(poses, poses[:, :2])
    rows[..., 4] = wrap_angle(poses[None, :, 2] - poses[:, None, 2])
    rows[~known, 2:] = 0.0
    others = ~np.eye(n, dtype=bool)
    return rows[others].reshape(n, n - 1, 5).astype(np.float32)


def observe_base(poses: np.ndarray, base_xy: tuple[float, float], links: np.ndarray, components: np.ndarray):
    """``(n, 4)`` float32: each robot's ``base`` observation (the base is the last node)."""
    n = len(poses)
    out = np.zeros((n, 4), dtype=np.float32)
    out[:, 0] = links[:n, n]
    out[:, 1] = components[:n] == components[n]
    out[:, 2:] = _relative(poses, np.array([base_xy], dtype=float))[:, 0]
    return out


def state_space(size_px: int) -> spaces.Box:
    """The team state's space: ``(4, S, S)`` uint8 (free, wall, unknown, robots; 0 or 255)."""
    return spaces.Box(0, 255, (4, size_px, size_px), np.uint8)
