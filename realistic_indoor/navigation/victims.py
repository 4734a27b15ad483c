"""Victims the robot has detected: positions in its odometry frame, and which it has visited."""

from __future__ import annotations

import math

import numpy as np

__all__ = ["VictimTracker"]


class VictimTracker:
    """Turns the victim sensor's readings into a list of victims to go to.

    Each reading ``(1, range / sensor_range, bearing / pi)`` of ``obs["victims"]`` becomes a
    position; readings within ``merge_m`` of a known victim are the same victim.

    Args:
        sensor_range_m: Range of the victim sensor (m), to undo the observation's scaling.
        merge_m: Readings this close to a known victim are that victim (m).

    Attributes:
        positions: ``(N, 2)`` positions of the victims detected so far (m, odometry frame).
        visited: ``(N,)`` bool: whether the robot has gone to each (or given up on it).
    """

    def __init__(self, sensor_range_m: float, merge_m: float = 1.0) -> None:
        self.sensor_range_m = sensor_range_m
        self.merge_m = merge_m
        self.reset()

    def reset(self) -> None:
        """Forget every victim."""
        self.positions = np.zeros((0, 2))
        self.visited = np.zeros(0, dtype=bool)

    def observe(self, pose: tuple[float, float, float], reading: np.ndarray) -> int:
        """Add the victims in ``reading`` (``obs["victims"]``) seen from ``pose``; return how many are new."""
        rows = np.asarray(reading, dtype=float).reshape(-1, 3)
        rows = rows[rows[:, 0] > 0.5]
        x, y, heading = pose
        new = 0
        for _, rng, bearing in rows:
            angle = heading + bearing * math.pi
            p = np.array(
                [
                    x + rng * self.sensor_range_m * math.cos(angle),
                    y + rng * self.sensor_range_m * math.sin(angle),
                ]
            )
            new += self._add(p, visited=False)
        return new

    def claim(self, positions: np.ndarray) -> int:
        """Add victims someone else goes to (``(k, 2)`` m, this tracker's frame) as visited.

        A position within ``merge_m`` of a victim already known is that victim and changes
        nothing. Returns how many were added.
        """
        return sum(self._add(p, visited=True) for p in np.asarray(positions, dtype=float).reshape(-1, 2))

    def _add(self, p: np.ndarray, visited: bool) -> int:
        """Add the victim at ``p`` unless one known is within ``merge_m``; 1 if added, else 0."""
        if len(self.positions) and np.min(np.hypot(*(self.positions - p).T)) < self.merge_m:
            return 0
        self.positions = np.vstack([self.positions, p])
        self.visited = np.append(self.visited, visited)
        return 1

    def next_target(self) -> int | None:
        """Index of the first victim not yet visited, or ``None``."""
        left = np.flatnonzero(~self.visited)
        return int(left[0]) if len(left) else None
