"""The agent's own global map, built from its scans and odometry with the simulator's mapping code.

The environment's observation holds only a small egocentric map image; a frontier explorer needs
the whole building it has seen. :class:`OwnMap` builds it from what the robot senses: each laser
scan (``obs["scan"]``) is rasterised at the odometry pose (``obs["pose"]``) by the simulator's
mapping rule (:class:`~realistic_indoor.sim.mapping.FreeSpaceMarker`, the fan
:class:`~realistic_indoor.sim.mapping.RobotMap` marks, with no ground truth) on a window around
the robot, and merged into a grid that grows as the robot travels. The cell
each returned beam ends in is marked occupied. The map's frame is the odometry frame: the start
pose at the origin, x along the start heading.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from realistic_indoor.sim.mapping import MAPPED_FREE, MAPPED_OCCUPIED, MAPPED_UNKNOWN, FreeSpaceMarker

__all__ = ["Box", "OwnMap"]

_RETURN_TOLERANCE = 1e-4
"""A reading within this share of the maximum range counts as "no return"."""
_WALL_SHRINK_M = 0.02
"""Free space is marked this much short of a returned beam's end (twice the default noise)."""


class Box(NamedTuple):
    """A rectangle of cells: rows ``r0:r1``, columns ``c0:c1``."""

    r0: int
    r1: int
    c0: int
    c1: int

    @property
    def slices(self) -> tuple[slice, slice]:
        """The rectangle as a NumPy index."""
        return slice(self.r0, self.r1), slice(self.c0, self.c1)


class _Window:
    """Rasterises one scan (or one sensor's part of it) on a square window around the robot."""

    def __init__(self, reach_m: float, resolution_m: float, offsets_rad: np.ndarray) -> None:
        self.half = math.ceil(reach_m / resolution_m) + 2
        self.size = 2 * self.half
        self._marker = FreeSpaceMarker((self.size, self.size), resolution_m, offsets_rad)

    def free(
        self, pose: tuple[float, float, float], ranges_m: np.ndarray, returned: np.ndarray
    ) -> np.ndarray:
        """Cells seen free by the beams, as a ``(size, size)`` bool array; ``pose`` in window metres."""
        return self._marker.free(pose, self._free_to(ranges_m, returned))

    def mark_unknown(
        self, pose: tuple[float, float, float], ranges_m: np.ndarray, returned: np.ndarray, cells: np.ndarray
    ) -> int:
        """Mark free the unknown ``cells`` (a ``(size, size)`` view) the beams see; return how many."""
        return self._marker.mark_unknown(pose, self._free_to(ranges_m, returned), cells)

    @staticmethod
    def _free_to(ranges_m: np.ndarray, returned: np.ndarray) -> np.ndarray:
        """How far each beam saw free floor (m, float32): a returned one stops short of its wall."""
        return np.where(returned, np.maximum(ranges_m - _WALL_SHRINK_M, 0.0), ranges_m).astype(np.float32)


class OwnMap:
    """A growing occupancy grid in the odometry frame, from scans and poses only.

    Args:
        offsets_rad: Beam directions of the laser relative to the heading (rad).
        max_range_m: The laser's maximum range (m); a reading at it means "no return".
        resolution_m: Side of a cell (m).
        search_sensor: ``(range m, field of view rad)`` of a victim sensor: also keep
            :attr:`searched`, the floor that sensor has swept (laser fan cut to its range and
            field of view); ``None`` for exploration only.
        grow_m: Margin added on a side when the robot's view passes the grid's edge (m).

    Attributes:
        state: ``(H, W)`` uint8 cells :data:`MAPPED_UNKNOWN`, :data:`MAPPED_FREE`,
            :data:`MAPPED_OCCUPIED`; row 0 is the lowest y.
        searched: ``(H, W)`` bool, or ``None`` without a search sensor.
        origin: Odometry coordinates ``(x0, y0)`` (m) of the lower-left corner of cell ``(0, 0)``.
        resolution_m: Side of a cell (m).
        known: Bounding box of the cells observed so far.
    """

    def __init__(
        self,
        offsets_rad: np.ndarray,
        max_range_m: float,
        resolution_m: float = 0.1,
        search_sensor: tuple[float, float] | None = None,
        grow_m: float = 20.0,
    ) -> None:
        self.resolution_m = float(resolution_m)
        self.max_range_m = float(max_range_m)
        self._offsets = np.asarray(offsets_rad, dtype=float)
        self._laser = _Window(max_range_m, resolution_m, self._offsets)
        self._search: _Window | None = None
        self._search_range_m = 0.0
        if search_sensor is not None:
            self._search_range_m, fov = search_sensor
            in_fov = np.abs(self._offsets) <= fov / 2 + 1e-9
            self._search_beams = np.flatnonzero(in_fov)
            self._search = _Window(self._search_range_m, resolution_m, self._offsets[in_fov].copy())
        self._grow = max(1, math.ceil(grow_m / resolution_m))
        self.reset()

    def reset(self) -> None:
        """Forget everything: an empty grid around the origin."""
        n = self._laser.size + 2 * self._grow
        self.state = np.full((n, n), MAPPED_UNKNOWN, dtype=np.uint8)
        self.searched = None if self._search is None else np.zeros((n, n), dtype=bool)
        self.origin = (-(n // 2) * self.resolution_m, -(n // 2) * self.resolution_m)
        self.known = Box(n // 2, n // 2 + 1, n // 2, n // 2 + 1)

    # -- coordinates ---------------------------------------------------------------------------------
    def to_cell(self, x: float, y: float) -> tuple[int, int]:
        """The ``(row, col)`` of the cell holding the point ``(x, y)`` (may lie off the grid)."""
        res = self.resolution_m
        return math.floor((y - self.origin[1]) / res), math.floor((x - self.origin[0]) / res)

    def to_world(self, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
        """Odometry coordinates (m) of cell centres, shape ``(N, 2)``."""
        res = self.resolution_m
        return np.stack(
            [
                self.origin[0] + (np.asarray(cols) + 0.5) * res,
                self.origin[1] + (np.asarray(rows) + 0.5) * res,
            ],
            axis=-1,
        )

    # -- sensing -------------------------------------------------------------------------------------
    def integrate(
        self, pose: tuple[float, float, float], ranges_m: np.ndarray, footprint_m: float = 0.0
    ) -> int:
        """Add a laser scan taken at ``pose`` (odometry frame); return the newly observed cells.

        Args:
            pose: ``(x m, y m, heading rad)`` of the robot.
            ranges_m: ``(n_beams,)`` readings (m); the maximum range means no return.
            footprint_m: The unknown cells within this distance of the robot are marked free:
                the robot stands there (its laser's blind sector may never have seen them).
        """
        ranges = np.asarray(ranges_m, dtype=np.float32)
        returned = ranges < self.max_range_m * (1.0 - _RETURN_TOLERANCE)
        box = self._window_box(pose, self._laser.half)
        local = self._local_pose(pose, box)
        new_free = self._laser.mark_unknown(local, ranges, returned, self.state[box.slices])
        new_walls = self._footprint(pose, footprint_m) if footprint_m > 0 else 0
        hits = self._endpoints(pose, ranges[returned], self._offsets[returned])
        new_walls += int(np.count_nonzero(self.state[hits] == MAPPED_UNKNOWN))
        self.state[hits] = MAPPED_OCCUPIED
        k = self.known
        self.known = Box(min(k.r0, box.r0), max(k.r1, box.r1), min(k.c0, box.c0), max(k.c1, box.c1))
        if self._search is not None:
            self._sweep(pose, ranges, returned)
        return new_free + new_walls

    def mark_blocked(self, pose: tuple[float, float, float], radius_m: float, half_width_m: float) -> None:
        """Mark as occupied a line across the path just ahead of a robot of ``radius_m``.

        For a bumper hit the laser does not explain (an obstacle it cannot see, such as the
        invisible line across an entrance): a segment ``2 * half_width_m`` long, perpendicular
        to the heading, at the front of the robot.
        """
        x, y, heading = pose
        ahead = radius_m + 0.5 * self.resolution_m
        n = max(2, math.ceil(2 * half_width_m / (0.5 * self.resolution_m)) + 1)
        side = np.linspace(-half_width_m, half_width_m, n)
        cx, cy = x + ahead * math.cos(heading), y + ahead * math.sin(heading)
        pts = np.stack([cx - side * math.sin(heading), cy + side * math.cos(heading)], axis=1)
        self._ensure(
            self._window_box((x, y, heading), math.ceil((ahead + half_width_m) / self.resolution_m) + 2)
        )
        rows, cols = self._cells(pts)
        self.state[rows, cols] = MAPPED_OCCUPIED

    # -- sharing -------------------------------------------------------------------------------------
    def copy(self) -> OwnMap:
        """An independent copy (a robot leaving a group keeps what the group knew)."""
        out = object.__new__(OwnMap)
        out.__dict__.update(self.__dict__)
        out.state = self.state.copy()
        out.searched = None if self.searched is None else self.searched.copy()
        return out

    def merge(self, other: OwnMap) -> int:
        """Add what ``other`` knows and this map does not; return the cells gained.

        Both maps must share a frame and a resolution (a team's maps in the team's frame):
        their grids then differ by whole cells. A cell unknown here takes ``other``'s state;
        the floor ``other``'s victim sensor swept counts as swept here too.
        """
        res = self.resolution_m
        dr = round((other.origin[1] - self.origin[1]) / res)
        dc = round((other.origin[0] - self.origin[0]) / res)
        k = other.known
        shift = self._ensure(Box(k.r0 + dr, k.r1 + dr, k.c0 + dc, k.c1 + dc))
        dr, dc = dr + shift[0], dc + shift[1]
        mine = self.state[k.r0 + dr : k.r1 + dr, k.c0 + dc : k.c1 + dc]
        theirs = other.state[k.slices]
        gained = (mine == MAPPED_UNKNOWN) & (theirs != MAPPED_UNKNOWN)
        mine[gained] = theirs[gained]
        if self.searched is not None and other.searched is not None:
            self.searched[k.r0 + dr : k.r1 + dr, k.c0 + dc : k.c1 + dc] |= other.searched[k.slices]
        own = self.known
        self.known = Box(
            min(own.r0, k.r0 + dr), max(own.r1, k.r1 + dr), min(own.c0, k.c0 + dc), max(own.c1, k.c1 + dc)
        )
        return int(np.count_nonzero(gained))

    # -- internals -----------------------------------------------------------------------------------
    def _window_box(self, pose: tuple[float, float, float], half: int) -> Box:
        r, c = self.to_cell(pose[0], pose[1])
        box = Box(r - half, r + half, c - half, c + half)
        shift = self._ensure(box)
        return Box(box.r0 + shift[0], box.r1 + shift[0], box.c0 + shift[1], box.c1 + shift[1])

    def _local_pose(self, pose: tuple[float, float, float], box: Box) -> tuple[float, float, float]:
        res = self.resolution_m
        return (
            float(pose[0] - (self.origin[0] + box.c0 * res)),
            float(pose[1] - (self.origin[1] + box.r0 * res)),
            float(pose[2]),
        )

    def _ensure(self, box: Box) -> tuple[int, int]:
        """Grow the grid to hold ``box``; return the shift of old cell indices (rows, cols)."""
        h, w = self.state.shape
        pad = (
            self._grow + max(0, -box.r0) if box.r0 < 0 else 0,
            self._grow + box.r1 - h if box.r1 > h else 0,
            self._grow + max(0, -box.c0) if box.c0 < 0 else 0,
            self._grow + box.c1 - w if box.c1 > w else 0,
        )
        if any(pad):
            widths = ((pad[0], pad[1]), (pad[2], pad[3]))
            self.state = np.pad(self.state, widths, constant_values=MAPPED_UNKNOWN)
            if self.searched is not None:
                self.searched = np.pad(self.searched, widths, constant_values=False)
            res = self.resolution_m
            self.origin = (self.origin[0] - pad[2] * res, self.origin[1] - pad[0] * res)
            k = self.known
            self.known = Box(k.r0 + pad[0], k.r1 + pad[0], k.c0 + pad[2], k.c1 + pad[2])
        return pad[0], pad[2]

    def _footprint(self, pose: tuple[float, float, float], radius_m: float) -> int:
        """Mark free the unknown cells under the robot's disc; return how many."""
        r, c = self.to_cell(pose[0], pose[1])
        k = math.ceil(radius_m / self.resolution_m)
        part = self.state[r - k : r + k + 1, c - k : c + k + 1]  # inside: the laser window holds it
        centres = self.to_world(*np.indices(part.shape) + np.array([r - k, c - k])[:, None, None])
        under = np.hypot(centres[..., 0] - pose[0], centres[..., 1] - pose[1]) <= radius_m
        new = under & (part == MAPPED_UNKNOWN)
        part[new] = MAPPED_FREE
        return int(np.count_nonzero(new))

    def _cells(self, pts: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        res = self.resolution_m
        rows = np.floor((pts[:, 1] - self.origin[1]) / res).astype(np.intp)
        cols = np.floor((pts[:, 0] - self.origin[0]) / res).astype(np.intp)
        h, w = self.state.shape
        ok = (rows >= 0) & (rows < h) & (cols >= 0) & (cols < w)
        return rows[ok], cols[ok]

    def _endpoints(
        self, pose: tuple[float, float, float], ranges_m: np.ndarray, offsets: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray]:
        """Cells the returned beams end in: half a cell past the reading, inside the wall."""
        x, y, heading = pose
        reach = ranges_m + 0.5 * self.resolution_m
        angles = heading + offsets
        return self._cells(np.stack([x + reach * np.cos(angles), y + reach * np.sin(angles)], axis=1))

    def _sweep(self, pose: tuple[float, float, float], ranges: np.ndarray, returned: np.ndarray) -> None:
        """Mark the floor the victim sensor swept: the laser's fan cut to the sensor's view."""
        beams = self._search_beams
        cut = np.minimum(ranges[beams], np.float32(self._search_range_m))
        box = self._window_box(pose, self._search.half)
        seen = self._search.free(self._local_pose(pose, box), cut, returned[beams] & (ranges[beams] <= cut))
        part = self.searched[box.slices]
        part |= seen & (self.state[box.slices] == MAPPED_FREE)
