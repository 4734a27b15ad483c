"""How much of what a team saw more than one of its robots saw: the overlap of their views."""

from __future__ import annotations

import numpy as np

from realistic_indoor.navigation.own_map import OwnMap
from realistic_indoor.sim.lidar import beam_offsets
from realistic_indoor.sim.mapping import MAPPED_FREE

__all__ = ["ViewOverlap"]


class ViewOverlap:
    """The floor each robot's own laser has seen, on true poses, to measure the team's overlap.

    Each robot's scans are mapped at its true pose (world frame) by the explorers' mapping rule
    (:class:`~realistic_indoor.navigation.own_map.OwnMap`, 0.1 m cells), whatever the robots
    shared: the overlap is a property of where the robots looked, not of what they told each
    other.

    Args:
        n: Robots.
        lidar: The robots' laser (``LidarConfig``).
        resolution_m: Cell side (m).
    """

    def __init__(self, n: int, lidar, resolution_m: float = 0.1) -> None:
        offsets = beam_offsets(lidar)
        self.maps = [OwnMap(offsets, lidar.max_range_m, resolution_m) for _ in range(n)]

    def add(self, poses: np.ndarray, scans_m: np.ndarray) -> None:
        """Add every robot's scan (``(n, n_beams)`` m) taken at its pose (``(n, 3)``, world frame)."""
        for own, pose, scan in zip(self.maps, poses, scans_m, strict=True):
            own.integrate((float(pose[0]), float(pose[1]), float(pose[2])), scan)

    def share(self) -> float:
        """Share of the floor the robots saw that two or more of them saw, in [0, 1] (0 if none)."""
        res = self.maps[0].resolution_m
        boxes = []
        for own in self.maps:
            k = own.known
            r0 = round(own.origin[1] / res) + k.r0
            c0 = round(own.origin[0] / res) + k.c0
            boxes.append((r0, c0, own.state[k.slices] == MAPPED_FREE))
        top = min(b[0] for b in boxes)
        left = min(b[1] for b in boxes)
        height = max(b[0] + b[2].shape[0] for b in boxes) - top
        width = max(b[1] + b[2].shape[1] for b in boxes) - left
        counts = np.zeros((height, width), dtype=np.int16)
        for r0, c0, free in boxes:
            counts[r0 - top : r0 - top + free.shape[0], c0 - left : c0 - left + free.shape[1]] += free
        seen = int(np.count_nonzero(counts))
        return float(np.count_nonzero(counts >= 2) / seen) if seen else 0.0
