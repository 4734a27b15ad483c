"""Openings in a laser scan: gaps between two wall ends that a robot fits through."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["Opening", "find_openings", "lane_length"]

JUMP_M = 0.5
"""Consecutive beams whose ranges differ by more than this see the two sides of an opening (m)."""
_WALL_BEAMS = 2
"""The line of a wall that ends at a gap runs through its end and the return this many beams
before (two, not one: laser noise makes the direction between neighbours unreliable)."""


@dataclass(frozen=True)
class Opening:
    """A gap in the walls around the robot, in the robot's frame (x ahead, y to the left; m).

    Attributes:
        a: The wall end on the right of the gap, as the robot sees it (m, m).
        b: The wall end on its left (m, m).
        width_m: Distance between the two wall ends (m).
        depth_m: How far beyond the line between them the farthest beam through the gap reaches
            (m); a beam without a return counts at the laser's range.
        seen_beyond: Whether a beam through the gap returned from something (a wall of the
            space behind it). An opening with nothing in range behind it may be an entrance
            (the open air) or a space deeper than the laser's range.
    """

    a: tuple[float, float]
    b: tuple[float, float]
    width_m: float
    depth_m: float
    seen_beyond: bool

    @property
    def middle(self) -> np.ndarray:
        """The middle of the gap (m, m)."""
        return 0.5 * (np.asarray(self.a) + np.asarray(self.b))

    @property
    def normal(self) -> np.ndarray:
        """Unit vector across the gap, pointing away from the robot."""
        ax, ay = self.a
        bx, by = self.b
        n = np.array((by - ay, ax - bx)) / self.width_m
        return n if float(n @ self.middle) >= 0.0 else -n


def find_openings(
    ranges: np.ndarray, offsets: np.ndarray, max_range_m: float, min_width_m: float
) -> list[Opening]:
    """The gaps in a scan between two wall ends at least ``min_width_m`` apart.

    A gap starts where the range jumps up by more than :data:`JUMP_M` from one beam to the next
    and ends at the next beam nearer than every beam of the gap by as much; every beam in
    between must pass beyond the line joining the two ends. Each end must be a wall end: the
    beam past it reaches beyond the line of the wall it ends (through the last returns before
    it) by half of :data:`JUMP_M`. A wall seen at a grazing angle, whose ranges grow quickly
    from beam to beam, is no gap: the beams past it stay on its line, or short of it when they
    return nothing. Doorways seen from inside a room, the ends of partitions and the mouths of
    side passages are gaps; a recess whose back wall is within :data:`JUMP_M` of its mouth is not.

    Args:
        ranges: Ranges of the beams (m), right to left; beams without a return at ``max_range_m``.
        offsets: Direction of each beam from the heading (rad), right to left.
        max_range_m: The laser's range (m).
        min_width_m: Narrowest gap reported (m).

    Returns:
        The gaps, right to left.
    """
    r = np.minimum(np.asarray(ranges, dtype=float), max_range_m)
    points = np.column_stack((r * np.cos(offsets), r * np.sin(offsets)))
    openings = []
    for i in np.flatnonzero(np.diff(r) > JUMP_M):
        if not _past_wall_end(points, int(i), -1):
            continue
        j = _other_end(points, r, int(i))
        opening = None if j is None else _opening(points, r, int(i), j, max_range_m, min_width_m)
        if opening is not None:
            openings.append(opening)
    return openings


def _past_wall_end(points: np.ndarray, end: int, step: int) -> bool:
    """Whether the beam after wall end ``end`` reaches beyond the line of the wall it ends.

    The wall's line runs through ``points[end]`` and a return :data:`_WALL_BEAMS` beams before
    it (``step`` = -1: to the right of it; +1: to the left), or one beam more or less when that
    one is not on the same wall (a beam slipping through a crack between two walls); the beam
    after is the next one the other way.
    """
    q1, past = points[end], points[end - step]
    r_end = float(np.hypot(*q1))
    for k in (_WALL_BEAMS, _WALL_BEAMS + 1, _WALL_BEAMS - 1):
        before = end + step * k
        if not 0 <= before < len(points):
            continue
        d = q1 - points[before]
        length = float(np.hypot(*d))
        if length > 0.0 and abs(float(np.hypot(*points[before])) - r_end) < JUMP_M:
            n = np.array((d[1], -d[0])) / length
            if float(n @ q1) < 0.0:
                n = -n
            return float((past - q1) @ n) > 0.5 * JUMP_M
    return False


def _other_end(points: np.ndarray, r: np.ndarray, i: int) -> int | None:
    """The other wall end of a gap starting at beam ``i``, if any.

    It is the first beam after ``i + 1`` nearer than all beams since ``i`` by :data:`JUMP_M`
    that is a wall end.
    """
    nearest = r[i + 1]
    for k in range(i + 2, len(r)):
        if r[k] < nearest - JUMP_M and _past_wall_end(points, k, 1):
            return k
        nearest = min(nearest, r[k])
    return None


def _opening(
    points: np.ndarray, r: np.ndarray, i: int, j: int, max_range_m: float, min_width_m: float
) -> Opening | None:
    """The gap between wall ends ``points[i]`` and ``points[j]``, if it is one the robot fits."""
    a, b = points[i], points[j]
    width = float(np.hypot(*(b - a)))
    if width < min_width_m:
        return None
    n = np.array((b[1] - a[1], a[0] - b[0])) / width
    if float(n @ (a + b)) < 0.0:
        n = -n
    beyond = (points[i + 1 : j] - a) @ n
    if not len(beyond) or beyond.min() < 0.5 * JUMP_M:
        return None
    seen = bool((r[i + 1 : j] < max_range_m * 0.999).any())
    return Opening(tuple(a), tuple(b), width, float(beyond.max()), seen)


def lane_length(ranges: np.ndarray, offsets: np.ndarray, direction_rad: float, half_width_m: float) -> float:
    """How far the robot can drive straight towards ``direction_rad`` before a return is in its lane.

    Args:
        ranges: Ranges of the beams (m); a beam without a return counts as one at its range.
        offsets: Direction of each beam from the heading (rad).
        direction_rad: Direction of travel from the heading (rad).
        half_width_m: Half the lane's width (m): the robot's radius and a margin.

    Returns:
        Distance along ``direction_rad`` to the nearest return in the lane (m); infinite if none.
    """
    rel = offsets - direction_rad
    along, across = ranges * np.cos(rel), np.abs(ranges * np.sin(rel))
    lane = (along > 0.0) & (across < half_width_m)
    return float(along[lane].min()) if lane.any() else math.inf
