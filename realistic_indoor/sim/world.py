"""A world: one building ready to simulate (raster, raycaster, reachable floor, start pose)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from realistic_indoor.building.building import Building
from realistic_indoor.building.labels import SemanticLabel
from realistic_indoor.checks import require_between
from realistic_indoor.errors import ConfigError
from realistic_indoor.sim._world_kernels import clear_at_least, reachable_from
from realistic_indoor.sim.raster import (
    DEFAULT_MARGIN_M,
    DEFAULT_RESOLUTION_M,
    DEFAULT_WALL_THICKNESS_M,
    OccupancyRaster,
    rasterize,
)
from realistic_indoor.sim.raycast import Raycaster, raster_fields

__all__ = ["World", "WorldConfig"]

Pose = tuple[float, float, float]

_MAX_REACH_CELLS = 40
"""Widest look around a point (cells) for :meth:`World.is_clear`; beyond, the whole clearance is
computed once (about 3 ms for a default office) and read."""
_ENTRANCE_DEPTHS_M = np.arange(0.3, 3.0, 0.05)
"""Distances from an entrance, inward, tried in turn for the start position (m)."""


@dataclass(frozen=True)
class WorldConfig:
    """How a building becomes a world.

    Every field has a plausible range, checked on construction; a value outside it raises a
    one-line ``ConfigError``.

    Attributes:
        resolution_m: Side of a raster cell (m), in [0.01, 1]; the robot's map has the same
            cells.
        wall_thickness_m: Thickness of the walls in the raster and in the physics (m), in
            [0, 1]; thinner than a cell, a wall is one cell wide.
        margin_m: Outside band kept around the building in the raster (m), in [0, 10].
        start_clearance_m: Least distance from the start position to any wall (m), in
            [0.05, 3]; must exceed the robot's radius.
    """

    resolution_m: float = DEFAULT_RESOLUTION_M
    wall_thickness_m: float = DEFAULT_WALL_THICKNESS_M
    margin_m: float = DEFAULT_MARGIN_M
    start_clearance_m: float = 0.4

    def __post_init__(self) -> None:
        require_between("WorldConfig", "resolution_m", self.resolution_m, 0.01, 1.0, "m")
        require_between("WorldConfig", "wall_thickness_m", self.wall_thickness_m, 0.0, 1.0, "m")
        require_between("WorldConfig", "margin_m", self.margin_m, 0.0, 10.0, "m")
        require_between("WorldConfig", "start_clearance_m", self.start_clearance_m, 0.05, 3.0, "m")


class World:
    """One building, prepared for simulation. Build one per building; reuse it across episodes.

    Args:
        building: The building.
        config: Raster and start settings.
        start_pose: ``(x, y, theta)`` where the robot starts (m, m, rad); by default
            :meth:`default_start_pose`.

    Raises:
        ConfigError: If the building has no room, or the start pose is not on free floor at
            least ``start_clearance_m`` from every wall.

    Attributes:
        building: The building.
        config: The settings it was built with.
        raster: Its occupancy raster (free, wall, outside).
        raycaster: Raycaster on the raster (lasers, line of sight).
        clearance_m: ``(H, W)`` float32 distance from each free cell to the nearest wall or
            outside cell (m), 0 elsewhere; computed when first read (:meth:`is_clear` answers
            "at least this far?" without it).
        start_pose: Where the robot starts.
        reachable: ``(H, W)`` bool, the free cells connected to the start cell (4-neighbours):
            the floor coverage is measured on.
        reachable_area_m2: Area of the reachable cells (m2).
        collision_segments: ``(N, 2, 2)`` wall segments for physics (m): the building's walls
            plus a segment closing each exterior door, so the robot cannot leave.
    """

    def __init__(
        self, building: Building, config: WorldConfig | None = None, start_pose: Pose | None = None
    ) -> None:
        self.building = building
        self.config = config or WorldConfig()
        c = self.config
        self.raster: OccupancyRaster = rasterize(building, c.resolution_m, c.wall_thickness_m, c.margin_m)
        self.raycaster = Raycaster(self.raster)
        self.start_pose = self._checked_start(start_pose) if start_pose else self.default_start_pose()
        self.reachable = self._reachable_from(self.start_pose)
        self.reachable_area_m2 = float(np.count_nonzero(self.reachable)) * self.raster.cell_area_m2
        self.collision_segments = _collision_segments(building)

    @cached_property
    def clearance_m(self) -> np.ndarray:
        """``(H, W)`` float32 distance (m) from each free cell to the nearest wall or outside cell.

        The distance from the cell's centre to the nearest non-free cell's centre less half a
        cell, 0 off the free floor. Computed on first use (about 3 ms and 4 bytes per cell for a
        default office) and kept: a world's build and its start need only
        :meth:`is_clear`, which looks around the points it is asked about.
        """
        return raster_fields(self.raster)[1]

    @property
    def nbytes(self) -> int:
        """Memory held by the world's arrays (bytes), the clearance once it was asked for."""
        arrays = [self.raster.grid, self.reachable, self.collision_segments]
        if "clearance_m" in self.__dict__:
            arrays.append(self.clearance_m)
        return int(sum(a.nbytes for a in arrays)) + self.raycaster.nbytes

    def clearance_at(self, xy: np.ndarray | tuple[float, float]) -> np.ndarray:
        """Distance (m) from points to the nearest wall or outside cell; 0 off the free floor."""
        row, col = self.raster.world_to_cell(xy)
        inside = self.raster.in_bounds(row, col)
        out = np.zeros(np.shape(row), dtype=np.float32)
        out[inside] = self.clearance_m[row[inside], col[inside]]
        return out

    def is_clear(self, xy: np.ndarray | tuple[float, float], min_m: float) -> np.ndarray:
        """Whether points are at least ``min_m`` from every wall and outside cell.

        The same as ``clearance_at(xy) >= min_m`` (compared in float32, as NumPy compares that
        float32 array with a float), found by looking at the cells within ``min_m`` (and two
        more) of each point instead of computing the whole floor's clearance: about 1 us a point
        for 0.4 m at 0.05 m cells. Beyond 40 cells (2 m at 0.05 m) it computes and keeps the
        whole clearance instead, as it reads it once something else has.

        Args:
            xy: ``(x, y)`` or ``(N, 2)`` points (m).
            min_m: Least clearance (m).

        Returns:
            Bool, one per point (a 0-d array for one point).

        Raises:
            ConfigError: If ``min_m`` is not a finite number.
        """
        if not math.isfinite(min_m):
            raise ConfigError(f"min_m must be a finite number of metres, got {min_m!r}")
        res = self.raster.resolution_m
        cells = min_m / res + 0.5  # centre to an obstacle cell's centre (cells), at the least
        if "clearance_m" in self.__dict__ or math.ceil(cells) + 2 > _MAX_REACH_CELLS:
            return np.asarray(self.clearance_at(xy) >= min_m)
        reach = max(math.ceil(cells) + 2, 0)
        row, col = self.raster.world_to_cell(xy)
        out = np.empty(np.shape(row), dtype=bool)
        rows = np.ascontiguousarray(np.ravel(row), dtype=np.int64)
        cols = np.ascontiguousarray(np.ravel(col), dtype=np.int64)
        flat = out.reshape(-1)
        least = np.float32(min_m)  # as clearance_at(xy) >= min_m compares: in float32
        clear_at_least(self.raster.grid, rows, cols, reach, np.float32(0.5), np.float32(res), least, flat)
        return out

    def default_start_pose(self) -> Pose:
        """The robot's default start: at the entrance, else in the middle of the largest space.

        With an exterior door, the start is just inside the first one, facing inward: on the
        door's centre line, at the first distance (from 0.3 m on) that is ``start_clearance_m``
        clear of walls. Without one (real plans often have none), it is the point of the largest
        hall (else the largest room): its centroid, or if that is not clear of walls, the point
        farthest from its walls; facing +x. If neither fits, the free cell farthest from any
        wall.

        Entrances, halls and rooms of the building's main part come first: the rooms joined by
        doors that hold the most floor together. A plan may have rooms that no door reaches (a
        space whose portals the file lacks) or separate parts (two flats of one floor); starting
        there, a robot would explore only that piece.
        """
        main = self.main_part()
        entrances = sorted(self.building.entrances, key=lambda door: door.room_a not in main)
        for door in entrances:
            pose = self._inside_door(door)
            if pose is not None:
                return pose
        pose = self._middle_of_largest_space(main)
        if pose is not None:
            return pose
        return self._most_open_cell()

    def main_part(self) -> set[str]:
        """Ids of the rooms of the building's main part: joined by doors, the most floor together."""
        import networkx as nx

        if _all_joined(self.building):  # the usual case: one part, no graph or areas needed
            return {r.id for r in self.building.rooms}
        parts = nx.connected_components(self.building.graph())
        area = self.building.room_by_id
        return max(parts, key=lambda part: sum(area[r].area for r in part), default=set())

    def _inside_door(self, door) -> Pose | None:
        room = self.building.room_by_id.get(door.room_a)
        if room is None:
            return None
        dx, dy = door.direction
        normal = np.array([-dy, dx])
        centre = np.array([door.x, door.y])
        if not room.polygon.contains(_point(centre + 0.1 * normal)):
            normal = -normal
        points = centre + _ENTRANCE_DEPTHS_M[:, None] * normal
        ok = np.flatnonzero(self.is_clear(points, self.config.start_clearance_m))
        if not len(ok):
            return None
        x, y = points[ok[0]]
        return (float(x), float(y), math.atan2(normal[1], normal[0]))

    def _middle_of_largest_space(self, main: set[str]) -> Pose | None:
        from shapely.ops import polylabel

        rooms = sorted(self.building.rooms, key=lambda r: (r.id not in main, -r.area))
        halls = [r for r in rooms if r.label == SemanticLabel.HALL]
        for room in halls[:1] + rooms[:1]:
            for p in (room.polygon.centroid, polylabel(room.polygon, tolerance=self.config.resolution_m)):
                if p.within(room.polygon) and self.is_clear((p.x, p.y), self.config.start_clearance_m):
                    return (float(p.x), float(p.y), 0.0)
        return None

    def _most_open_cell(self) -> Pose:
        best = np.unravel_index(np.argmax(self.clearance_m), self.clearance_m.shape)
        if self.clearance_m[best] < self.config.start_clearance_m:
            raise ConfigError(
                f"no free floor is {self.config.start_clearance_m} m clear of walls in this building; "
                "lower WorldConfig.start_clearance_m or use a finer resolution_m"
            )
        x, y = self.raster.cell_to_world(*best)
        return (float(x), float(y), 0.0)

    def _checked_start(self, pose: Pose) -> Pose:
        x, y, theta = (float(v) for v in pose)
        if not self.is_clear((x, y), self.config.start_clearance_m):
            clear = float(self.clearance_at((x, y)))
            raise ConfigError(
                f"start pose ({x:.2f}, {y:.2f}) is {clear:.2f} m from the nearest wall or off the "
                f"floor; it must be on free floor at least {self.config.start_clearance_m} m from walls"
            )
        return (x, y, theta)

    def _reachable_from(self, pose: Pose) -> np.ndarray:
        row, col = self.raster.world_to_cell(pose[:2])  # free: the start is clear of walls
        return reachable_from(self.raster.grid, int(row), int(col))


def _all_joined(building: Building) -> bool:
    """Whether interior doors join every room of ``building`` to every other (and name only its rooms)."""
    links: dict[str, list[str]] = {r.id: [] for r in building.rooms}
    for door in building.doors:
        if door.room_b is None:
            continue
        if door.room_a not in links or door.room_b not in links:
            return False
        links[door.room_a].append(door.room_b)
        links[door.room_b].append(door.room_a)
    if not links:
        return False
    seen = {next(iter(links))}
    todo = list(seen)
    while todo:
        for other in links[todo.pop()]:
            if other not in seen:
                seen.add(other)
                todo.append(other)
    return len(seen) == len(links)


def _point(xy: np.ndarray):
    from shapely.geometry import Point

    return Point(float(xy[0]), float(xy[1]))


def _collision_segments(building: Building) -> np.ndarray:
    doors = [np.array(d.segment) for d in building.entrances]
    segments = np.concatenate(
        [np.asarray(building.walls, dtype=float).reshape(-1, 2, 2), *(d[None] for d in doors)]
    )
    segments.setflags(write=False)
    return segments
