"""The robot's own occupancy map, built from its scans: coverage and an egocentric local view.

:class:`RobotMap` maps a world's cells against its ground truth; :class:`FreeSpaceMarker`
applies the same rule for what a scan sweeps to a bare grid, for a robot that builds its own
map from its readings alone.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from realistic_indoor.checks import require_between, require_int, require_positive
from realistic_indoor.errors import ConfigError
from realistic_indoor.sim._map_kernels import (
    MAPPED_FREE,
    MAPPED_OCCUPIED,
    MAPPED_UNKNOWN,
    TRUTH_REACHABLE,
    coverage_share,
    coverage_share_compiled,
    integrate_scan,
    map_targets,
    render_local,
    scatter_global,
    start_bits,
    unknown_bits,
)
from realistic_indoor.sim.raster import RASTER_FREE

if TYPE_CHECKING:
    from realistic_indoor.sim.lidar import Scan
    from realistic_indoor.sim.world import World

__all__ = [
    "MAPPED_FREE",
    "MAPPED_OCCUPIED",
    "MAPPED_UNKNOWN",
    "PIXEL_FREE",
    "PIXEL_OCCUPIED",
    "PIXEL_OF_STATE",
    "PIXEL_UNKNOWN",
    "FreeSpaceMarker",
    "LocalMapConfig",
    "MapBits",
    "MapStorage",
    "RobotMap",
    "beam_table",
    "coverage_share",
    "coverage_share_compiled",
    "require_view_out",
]

PIXEL_OCCUPIED, PIXEL_UNKNOWN, PIXEL_FREE = 0, 128, 255
"""Grey levels of the local map image: walls black, free floor white, unknown grey."""
PIXEL_OF_STATE = np.array([PIXEL_UNKNOWN, PIXEL_FREE, PIXEL_OCCUPIED], dtype=np.uint8)
"""The local map image's grey level of each map cell state (indexed by the ``MAPPED_*`` value)."""
PIXEL_OF_STATE.setflags(write=False)


class MapBits:
    """A map's to-do and wall bits, and those of the empty map it starts again from.

    Args:
        targets: ``(H, W)`` uint8 what a beam may mark in each cell (``TRUTH_*``).

    Attributes:
        todo: The free cells still unknown (:func:`~realistic_indoor.sim._map_kernels.todo_bits`),
            cleared as the map marks them.
        walls: The wall cells not yet marked
            (:func:`~realistic_indoor.sim._map_kernels.wall_bits`), cleared likewise.
    """

    def __init__(self, targets: np.ndarray) -> None:
        self._todo_at_start, self._walls_at_start = start_bits(targets)
        self.todo = self._todo_at_start.copy()
        self.walls = self._walls_at_start.copy()

    @property
    def nbytes(self) -> int:
        """Memory held by the bits (bytes)."""
        return 2 * (self.todo.nbytes + self.walls.nbytes)

    def reset(self) -> None:
        """Back to the empty map's bits, in place (the arrays stay the same objects)."""
        self.todo[...] = self._todo_at_start
        self.walls[...] = self._walls_at_start


class MapStorage(NamedTuple):
    """The arrays a map lives in, when another owner holds them (a batch's map).

    Attributes:
        grid: ``(H, W)`` uint8 cell states, written in place.
        pooled: The pooled cells, written in place.
        targets: ``(H, W)`` uint8 what a beam may mark in each cell (read only).
        bits: The map's to-do and wall bits.
        observed: int64 reachable cells observed, per map of the owner; this map's count is
            ``observed[index]``, updated in place.
        index: This map's entry of ``observed``.
    """

    grid: np.ndarray
    pooled: np.ndarray
    targets: np.ndarray
    bits: MapBits
    observed: np.ndarray
    index: int


@dataclass(frozen=True)
class LocalMapConfig:
    """The egocentric local map: a square image of the robot's map around the robot.

    Attributes:
        size_px: Side of the image (pixels), an integer in [1, 1024]; 64 suits
            stable-baselines3's ``CnnPolicy``.
        resolution_m: Side of a pixel (m), in [0.01, 2]. Coarser than the map, each pixel shows
            the map cells it covers, walls first (a 5 cm wall never vanishes from a 20 cm pixel).
    """

    size_px: int = 64
    resolution_m: float = 0.2

    def __post_init__(self) -> None:
        require_int("LocalMapConfig", "size_px", self.size_px, 1, 1024)
        require_between("LocalMapConfig", "resolution_m", self.resolution_m, 0.01, 2.0, "m")

    def pooling(self, cell_m: float) -> tuple[int, float]:
        """How map cells of ``cell_m`` metres are pooled for the image, as the kernels take it.

        Returns:
            ``(pool, pixel)``: map cells per side of a pooled cell (the largest whole number that
            fits a pixel, at least 1), and a pixel's side in pooled cells.
        """
        pool = max(1, int(self.resolution_m / cell_m + 1e-9))
        return pool, self.resolution_m / (cell_m * pool)


class RobotMap:
    """The occupancy map a robot builds from its scans, on the world's raster cells.

    A scan marks as free the floor inside the fan its beams sweep (between each two neighbouring
    beams, up to the shorter of their ranges) and along each beam, and marks as occupied each
    wall cell a beam returned from. Localisation is perfect and the noise-free ranges are used
    (as is usual in exploration benchmarks); only cells that are free floor in the ground truth
    are marked free, so a map never shows free space inside walls, nor outside the building.
    Cells never change once observed.

    Coverage is the observed share of the world's reachable floor (:attr:`World.reachable`).

    Args:
        world: The world whose cells and ground truth the map uses.
        local: Size and resolution of :meth:`local_view` images.
        storage: Arrays of another owner to live in (a batch's map, whose compiled step then
            updates this map: :meth:`realistic_indoor.sim.batch.Batch.map_storage`); by default
            the map makes its own.

    Attributes:
        world: The world.
        local: The local-view settings.
    """

    def __init__(
        self, world: World, local: LocalMapConfig | None = None, storage: MapStorage | None = None
    ) -> None:
        self.world = world
        self.local = local or LocalMapConfig()
        self._res = world.raster.resolution_m
        self._x0, self._y0 = world.raster.origin
        self._pool = self.local.pooling(self._res)[0]
        if storage is None:
            targets = _targets(world)
            h, w = world.raster.shape
            storage = MapStorage(
                np.zeros((h, w), dtype=np.uint8),
                np.zeros((-(-h // self._pool), -(-w // self._pool)), dtype=np.uint8),
                targets,
                MapBits(targets),
                np.zeros(1, dtype=np.int64),
                0,
            )
        self._grid, self._pooled, self._targets, self._bits, self._counts, self._index = storage
        self._reachable_cells = int(np.count_nonzero(world.reachable))
        self._offsets: np.ndarray | None = None
        self._cos = self._sin = np.zeros(0)
        self._closed = False

    @property
    def grid(self) -> np.ndarray:
        """The map: ``(H, W)`` uint8 cell states, the world raster's cells; read-only, kept current.

        States are :data:`MAPPED_UNKNOWN`, :data:`MAPPED_FREE` and :data:`MAPPED_OCCUPIED`.
        """
        view = self._grid.view()
        view.setflags(write=False)
        return view

    @property
    def _observed(self) -> int:
        """Reachable cells observed so far."""
        return int(self._counts[self._index])

    @property
    def coverage(self) -> float:
        """Observed share of the reachable floor, in ``[0, 1]``."""
        return coverage_share(self._observed, self._reachable_cells)

    @property
    def observed_area_m2(self) -> float:
        """Area of the reachable floor observed so far (m2)."""
        return self._observed * self._res**2

    @property
    def nbytes(self) -> int:
        """Memory held by the map (bytes)."""
        arrays = (self._grid, self._pooled, self._targets)
        return int(sum(a.nbytes for a in arrays)) + self._bits.nbytes

    def reset(self) -> None:
        """Forget everything: every cell unknown, coverage 0."""
        self._grid.fill(MAPPED_UNKNOWN)
        self._pooled.fill(MAPPED_UNKNOWN)
        self._bits.reset()
        self._counts[self._index] = 0

    def update(self, scan: Scan) -> float:
        """Add a scan to the map.

        Args:
            scan: A scan taken in this map's world (:meth:`Lidar.scan`).

        Returns:
            Area of reachable floor observed for the first time (m2): the exploration reward.
            Summed over an episode it equals :attr:`observed_area_m2`. Cost: about 1 ns per
            not yet observed cell the scan's fan covers; 20-50 microseconds along a drive.
        """
        if scan.offsets_rad is not self._offsets:
            self._set_beams(scan.offsets_rad)
        x, y, theta = scan.pose
        new = integrate_scan(
            self._grid,
            self._pooled,
            self._pool,
            self._targets,
            self._bits.todo,
            self._bits.walls,
            (x - self._x0) / self._res,
            (y - self._y0) / self._res,
            math.cos(theta),
            math.sin(theta),
            self._cos,
            self._sin,
            scan.true.range_m,
            scan.true.kind,
            1.0 / self._res,
            self._closed,
        )
        self._counts[self._index] += new
        return new * self._res**2

    def local_view(self, pose: tuple[float, float, float], out: np.ndarray | None = None) -> np.ndarray:
        """An image of the map around ``pose``: robot at the centre, heading up.

        Row 0 is ahead of the robot, column 0 to its left; pixels show walls
        (:data:`PIXEL_OCCUPIED`), free floor (:data:`PIXEL_FREE`) or unknown
        (:data:`PIXEL_UNKNOWN`, also beyond the map's edge).

        Args:
            pose: ``(x, y, theta)`` of the robot (m, m, rad).
            out: A C-contiguous ``(size_px, size_px)`` uint8 array to fill (e.g. a view into an
                observation buffer); a new one if ``None``.

        Returns:
            The image. Cost: about 5 microseconds for 64 x 64 pixels.

        Raises:
            ConfigError: If ``out`` is not a C-contiguous ``(size_px, size_px)`` uint8 array.
        """
        s = self.local.size_px
        if out is None:
            out = np.empty((s, s), dtype=np.uint8)
        else:
            require_view_out(out, s)
        x, y, theta = pose
        cell = self._res * self._pool
        render_local(
            self._pooled,
            PIXEL_OF_STATE,
            (x - self._x0) / cell,
            (y - self._y0) / cell,
            math.cos(theta),
            math.sin(theta),
            self.local.resolution_m / cell,
            out,
        )
        return out

    def global_view(
        self,
        centre_xy: tuple[float, float],
        up_rad: float,
        resolution_m: float,
        free: np.ndarray,
        wall: np.ndarray,
    ) -> None:
        """Mark the known floor and walls of the whole map on a fixed-orientation image.

        The image is centred on ``centre_xy`` with the direction ``up_rad`` up; each pixel
        (``resolution_m`` across) that holds a mapped free cell gets 255 in ``free``, one that
        holds a mapped wall cell 255 in ``wall`` (both can), as :meth:`local_view` pools them
        (at ``local_map.resolution_m``). Pixels are not cleared first.

        Args:
            centre_xy: The image's centre (m, plan frame).
            up_rad: The plan-frame direction shown up (rad).
            resolution_m: Side of a pixel (m).
            free: ``(S, S)`` uint8 image to mark free floor on.
            wall: ``(S, S)`` uint8 image to mark walls on.

        Cost: one pass over the pooled map (about 0.1-0.3 ms for a 2,000 m2 office).
        """
        cell = self._res * self._pool
        scatter_global(
            self._pooled,
            (centre_xy[0] - self._x0) / cell,
            (centre_xy[1] - self._y0) / cell,
            math.cos(up_rad),
            math.sin(up_rad),
            cell / resolution_m,
            free,
            wall,
        )

    def _set_beams(self, offsets: np.ndarray) -> None:
        self._offsets = offsets
        self._cos, self._sin, self._closed = beam_table(offsets)


class FreeSpaceMarker:
    """The floor a scan swept, on a bare grid: :class:`RobotMap`'s rule with no ground truth.

    A scan sweeps the cells whose centre lies in the fan between each two neighbouring beams (up
    to the shorter of their ranges) and the cells each beam crosses, as :meth:`RobotMap.update`
    marks them free; here every cell of the grid may be free, and nothing is marked occupied.
    For an agent that builds its own map from its readings and odometry (it knows no world).

    Args:
        shape: ``(rows, cols)`` of the grid (cells).
        resolution_m: Side of a cell (m).
        offsets_rad: ``(n_beams,)`` beam directions relative to the heading (rad, increasing),
            e.g. :func:`~realistic_indoor.sim.lidar.beam_offsets` of the scanner's config.

    Attributes:
        shape: ``(rows, cols)`` of the grid (cells).
        resolution_m: Side of a cell (m).
    """

    def __init__(self, shape: tuple[int, int], resolution_m: float, offsets_rad: np.ndarray) -> None:
        require_int("FreeSpaceMarker", "shape[0]", shape[0], 1)
        require_int("FreeSpaceMarker", "shape[1]", shape[1], 1)
        require_positive("FreeSpaceMarker", "resolution_m", resolution_m, "m")
        offsets = np.asarray(offsets_rad, dtype=float)
        if offsets.ndim != 1 or len(offsets) == 0:
            raise ConfigError(f"FreeSpaceMarker needs a 1-D array of beam offsets, got shape {offsets.shape}")
        self.shape = (int(shape[0]), int(shape[1]))
        self.resolution_m = resolution_m
        self._cos, self._sin, self._closed = beam_table(offsets)
        self._kind = np.full(len(offsets), RASTER_FREE, dtype=np.uint8)  # no beam marks a wall
        # every cell may be free and none is a wall; each cell marked counts (mark_unknown's count)
        self._targets = np.full(self.shape, TRUTH_REACHABLE, dtype=np.uint8)
        self._bits = MapBits(self._targets)
        self._grid = np.zeros(self.shape, dtype=np.uint8)
        self._pool = max(self.shape)  # one pooled cell: the kernel keeps a pooled copy, unused here
        self._pooled = np.zeros((1, 1), dtype=np.uint8)
        self._unknown = np.empty_like(self._bits.todo)

    def free(self, pose: tuple[float, float, float], ranges_m: np.ndarray) -> np.ndarray:
        """The cells a scan swept free.

        Args:
            pose: ``(x m, y m, heading rad)`` of the scanner in the grid's frame: ``(0, 0)`` is
                the lower-left corner of cell ``(0, 0)``, rows along y, columns along x.
            ranges_m: ``(n_beams,)`` how far each beam saw free floor (m), as float32; a
                returned beam's reading less a margin keeps its wall cell out.

        Returns:
            ``(rows, cols)`` bool array, ``True`` on the swept cells; a new array. Cost: about
            1 ns per cell of the fan, as :meth:`RobotMap.update`.
        """
        self._grid.fill(MAPPED_UNKNOWN)
        self._bits.reset()
        self._sweep(pose, ranges_m, self._grid, self._bits.todo)
        return self._grid == MAPPED_FREE

    def mark_unknown(self, pose: tuple[float, float, float], ranges_m: np.ndarray, cells: np.ndarray) -> int:
        """Mark free, in place, the unknown cells of a map that a scan sweeps; return how many.

        The same cells as ``free(pose, ranges_m) & (cells == MAPPED_UNKNOWN)``, found without
        sweeping the cells already known: only the unknown ones are visited.

        Args:
            pose: As :meth:`free`, in the frame of ``cells``.
            ranges_m: As :meth:`free`.
            cells: ``(rows, cols)`` uint8 ``MAPPED_*`` map of the marker's shape (a window of a
                larger map may be passed as a view), updated.
        """
        if cells.shape != self.shape or cells.dtype != np.uint8:
            raise ConfigError(
                f"FreeSpaceMarker of shape {self.shape} needs uint8 cells of that shape, got {cells.dtype} {cells.shape}"
            )
        unknown_bits(cells, self._unknown)
        return self._sweep(pose, ranges_m, cells, self._unknown)

    def _sweep(
        self,
        pose: tuple[float, float, float],
        ranges_m: np.ndarray,
        grid: np.ndarray,
        todo: np.ndarray,
    ) -> int:
        """Mark free in ``grid`` the cells of ``todo`` the scan sweeps; return how many."""
        x, y, theta = pose
        res = self.resolution_m
        return int(
            integrate_scan(
                grid,
                self._pooled,
                self._pool,
                self._targets,
                todo,
                self._bits.walls,
                x / res,
                y / res,
                math.cos(theta),
                math.sin(theta),
                self._cos,
                self._sin,
                np.asarray(ranges_m, dtype=np.float32),
                self._kind,
                1.0 / res,
                self._closed,
            )
        )


def require_view_out(out: np.ndarray, size_px: int) -> None:
    """Refuse a local view's ``out`` that is not a C-contiguous ``(size_px, size_px)`` uint8 array.

    Raises:
        ConfigError: Naming the array needed and the one given.
    """
    if out.shape != (size_px, size_px) or out.dtype != np.uint8 or not out.flags.c_contiguous:
        raise ConfigError(
            f"local_view(out=...) needs a C-contiguous ({size_px}, {size_px}) uint8 array, "
            f"got {out.dtype} {out.shape}"
        )


def beam_table(offsets: np.ndarray) -> tuple[np.ndarray, np.ndarray, bool]:
    """Cosines and sines of the beam offsets, and whether the beams close a full circle.

    A closed fan also sweeps between its last and first beam; every map update (the robot's
    map, :class:`FreeSpaceMarker`, the batched simulation) decides it here.
    """
    n = len(offsets)
    span = (offsets[-1] - offsets[0]) * n / (n - 1) if n > 2 else 0.0
    return np.cos(offsets), np.sin(offsets), bool(n > 2 and math.isclose(span, 2 * math.pi, abs_tol=1e-6))


def _targets(world: World) -> np.ndarray:
    """What a beam may mark in each cell: wall, outside, free, or free and reachable."""
    return map_targets(world.raster.grid, world.reachable)
