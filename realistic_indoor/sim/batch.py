"""Batched simulation: many robots advanced by one compiled, multi-threaded call.

State lives in arrays with a leading robot axis (physics state, scans, counters) and in typed
lists indexed by map (cells, pooled cells, bits) or by building (raster-derived fields, wall
grids). Robots, maps and buildings are indexed apart: ``robot_building[i]`` names robot ``i``'s
building, ``robot_map[i]`` the map it sees, and each map lists the robots whose scans it
integrates. The native vector environment gives each robot a building and a map of its own; a
team puts several robots in one building, sharing a map or each with its own (see
``docs/architecture.md`` and ``docs/teams.md``).

One :func:`step_batch` call runs, in parallel (numba ``prange``, the GIL released): the compiled
disc physics of each building's robots together (:mod:`realistic_indoor.sim.disc_physics`: they
collide with the walls and with each other), each robot's laser (the raycaster's kernel), each
map's update with its robots' scans in turn (the robot map's kernels), and each robot's local
view and reward terms, writing into preallocated arrays. The kernels are those of the
single-robot classes, so a robot's scans and map follow the same rules; only the physics
differs from pymunk, within the tolerance ``tests/sim/test_disc_physics.py`` states.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, NamedTuple

import numpy as np
from numba import njit, prange
from numba.typed import List

from realistic_indoor.errors import ConfigError
from realistic_indoor.sim._map_kernels import integrate_scan, merge_maps, render_local, scatter_global
from realistic_indoor.sim.disc_physics import (
    STATE_SIZE,
    THETA,
    DiscRobot,
    SegmentGrid,
    X,
    Y,
    drive_group,
    drive_params,
    segment_grid,
)
from realistic_indoor.sim.lidar import _readings, beam_offsets
from realistic_indoor.sim.mapping import PIXEL_OF_STATE, MapBits, MapStorage, _targets, beam_table
from realistic_indoor.sim.raycast import _cast_fan
from realistic_indoor.sim.world import World

if TYPE_CHECKING:
    from realistic_indoor.sim.lidar import LidarConfig
    from realistic_indoor.sim.mapping import LocalMapConfig
    from realistic_indoor.sim.robot import RobotConfig
    from realistic_indoor.sim.world import WorldConfig

__all__ = [
    "N_TERMS",
    "RESET",
    "SKIP",
    "STEP",
    "STEP_TERMS",
    "Batch",
    "StepConstants",
    "StepOutputs",
    "step_batch",
    "step_batch_serial",
    "step_constants",
]

SKIP, STEP, RESET = 0, 1, 2
"""What :func:`step_batch` does to a robot: nothing, a control step, or a first scan after a reset."""
STEP_TERMS = ("new_area", "collision", "time")
"""The reward terms a control step measures, in the columns the kernels write them: floor newly
observed (m2), whether the robot touched a wall (0 or 1), and the step itself (1)."""
N_TERMS = len(STEP_TERMS)
"""Reward terms per robot that the kernels write."""


class Batch:
    """The state of ``n`` robots, their buildings and their maps, for :func:`step_batch`.

    Robots, buildings and maps are indexed apart. ``robot_building[i]`` is robot ``i``'s
    building slot; ``robot_map[i]`` the map it sees (its local view) and is rewarded by; and
    each map integrates the scans of a list of robots, in order (``map_robots(m)``). By default
    each robot has a building slot and a map of its own (the native vector environment); a team
    puts several robots in one slot and gives them one map, or one each plus a team map that
    integrates every robot's scans. The robots of a map must all be in its building.

    Args:
        n: Number of robots.
        robot_building: ``(n,)`` building slot of each robot; default ``0..n-1``.
        robot_map: ``(n,)`` map of each robot; default ``0..n-1``.
        map_scans: For each map, the robots whose scans it integrates, in order; default: each
            map the robots whose map it is, in increasing order. A robot's own map must list it.

    Attributes:
        phys: ``(n, STATE_SIZE)`` float64 physics state (:mod:`~realistic_indoor.sim.disc_physics`).
        robot_building: ``(n,)`` int64 building slot of each robot.
        robot_map: ``(n,)`` int64 map of each robot.
        map_building: ``(n_maps,)`` int64 building slot of each map.
        layout: int64 the indices the compiled step reads, in one array: nine offsets, then
            ``robot_building``, ``robot_map``, the robots of each building, the robots whose
            scans each map integrates and the maps of each building (:func:`step_batch`).
        building_meta: ``(n_buildings, 8)`` float64 per building slot: raster origin x, y (m),
            cell size (m), reachable cells, start pose x, y, heading (m, m, rad), unused.
        observed: ``(n_maps,)`` int64 reachable cells each map has observed.
        worlds: The :class:`World` of each building slot (``None`` before it is loaded).

    Raises:
        ConfigError: If the layout is inconsistent (a map whose robots are in two buildings, a
            robot whose own map does not integrate its scans, an index out of range).
    """

    def __init__(
        self,
        n: int,
        robot_building: np.ndarray | None = None,
        robot_map: np.ndarray | None = None,
        map_scans: list[list[int]] | None = None,
    ) -> None:
        self.n = n
        self.phys = np.zeros((n, STATE_SIZE), dtype=np.float64)
        self.robot_building = _indices(robot_building, n)
        self.n_buildings = int(self.robot_building.max()) + 1 if n else 0
        self.building_meta = np.zeros((self.n_buildings, 8), dtype=np.float64)
        self.worlds: list[World | None] = [None] * self.n_buildings
        empty2 = np.zeros((1, 1), dtype=np.uint8)
        self.skips = _skip_fields(self.worlds)
        self.targets = List([empty2] * self.n_buildings)
        self.segments = List([np.zeros((1, 4))] * self.n_buildings)
        self.seg_start = List([np.zeros(2, dtype=np.int64)] * self.n_buildings)
        self.seg_items = List([np.zeros(0, dtype=np.int64)] * self.n_buildings)
        self.seg_origin = List([np.array([0.0, 0.0, 1.0, 1.0, 1.0])] * self.n_buildings)
        self.building_start, self.building_robots = _csr(
            [list(np.flatnonzero(self.robot_building == b)) for b in range(self.n_buildings)]
        )
        self.set_maps(_indices(robot_map, n), map_scans)

    def set_maps(self, robot_map: np.ndarray, map_scans: list[list[int]] | None = None) -> None:
        """Give the robots other maps (a team whose links changed): indices only, maps kept.

        Args:
            robot_map: ``(n,)`` map of each robot, from ``0`` to ``n_maps - 1``.
            map_scans: As the constructor's; its length is the number of maps. The number of
                maps may not change once maps were made (:meth:`load`).

        Raises:
            ConfigError: As the constructor.
        """
        robot_map = np.asarray(robot_map, dtype=np.int64)
        if map_scans is None:
            map_scans = [list(np.flatnonzero(robot_map == m)) for m in range(int(robot_map.max()) + 1)]
        _check_layout(self.robot_building, robot_map, map_scans)
        if hasattr(self, "grids") and len(map_scans) != len(self.grids):
            raise ConfigError(
                f"Batch.set_maps: {len(map_scans)} maps given, the batch holds {len(self.grids)}"
            )
        self.robot_map = robot_map
        self.map_start, self.map_robots = _csr(map_scans)
        self.map_building = np.array(
            [self.robot_building[r[0]] if len(r) else 0 for r in map_scans], dtype=np.int64
        )
        self._state: tuple | None = None  # the arrays and lists Batch.step passes, gathered once
        self.maps_start, self.building_maps = _csr(
            [list(np.flatnonzero(self.map_building == b)) for b in range(self.n_buildings)]
        )
        parts = (self.robot_building, robot_map, self.building_start, self.building_robots, self.map_start,
                 self.map_robots, self.maps_start, self.building_maps)  # fmt: skip
        offsets = 9 + np.concatenate([[0], np.cumsum([len(p) for p in parts])])
        self.layout = np.concatenate([offsets, *parts]).astype(np.int64)
        if not hasattr(self, "grids"):
            self._make_map_lists(len(map_scans))

    def _make_map_lists(self, n_maps: int) -> None:
        empty2 = np.zeros((1, 1), dtype=np.uint8)
        self.observed = np.zeros(n_maps, dtype=np.int64)
        self.grids = List([empty2] * n_maps)
        self.pooled = List([empty2] * n_maps)
        self.bits: list[MapBits | None] = [None] * n_maps
        self.todo = List([np.zeros((1, 1), dtype=np.int64)] * n_maps)  # each map's bits.todo
        self.walls = List([np.zeros((1, 1), dtype=np.int64)] * n_maps)  # each map's bits.walls

    @property
    def n_maps(self) -> int:
        """Number of maps."""
        return len(self.grids)

    def map_robots_of(self, m: int) -> np.ndarray:
        """The robots whose scans map ``m`` integrates, in order."""
        return self.map_robots[self.map_start[m] : self.map_start[m + 1]]

    def load(self, slot: int, world: World, reach_m: float, pool: int) -> None:
        """Make ``world`` the building of ``slot`` and give every map of ``slot`` an empty map of it.

        Args:
            slot: Building slot index.
            world: The world.
            reach_m: Robot radius plus half the wall thickness (m), for the wall grid.
            pool: Map cells per side of a pooled cell (the local view's pixel over the cell).
        """
        self.worlds[slot] = world
        self.pool = pool
        raster = world.raster
        targets = _targets(world)
        grid = segment_grid(world.collision_segments, reach_m)
        self.skips[slot] = world.raycaster._skip
        self.targets[slot] = targets
        self.segments[slot] = grid.segments
        self.seg_start[slot] = grid.start
        self.seg_items[slot] = grid.items
        self.seg_origin[slot] = grid.origin
        h, w = raster.shape
        for m in np.flatnonzero(self.map_building == slot):
            self.grids[m] = np.zeros((h, w), dtype=np.uint8)
            self.pooled[m] = np.zeros((-(-h // pool), -(-w // pool)), dtype=np.uint8)
            bits = self.bits[m] = MapBits(targets)
            self.todo[m] = bits.todo
            self.walls[m] = bits.walls
        x0, y0 = raster.origin
        start = world.start_pose
        reachable = float(np.count_nonzero(world.reachable))
        self.building_meta[slot] = (x0, y0, raster.resolution_m, reachable, *start, 0.0)
        self._state = None  # the step's tuples, where it passes them, hold the old arrays

    def reset_map(self, m: int) -> None:
        """Empty map ``m``: every cell unknown, nothing observed."""
        self.grids[m].fill(0)
        self.pooled[m].fill(0)
        self.bits[m].reset()
        self.observed[m] = 0

    def map_storage(self, m: int) -> MapStorage:
        """Map ``m``'s arrays, for a :class:`~realistic_indoor.sim.mapping.RobotMap` on this map.

        The robot map reads and resets the map while :func:`step_batch` updates it (the single
        environment's map). Valid until the building of the map's slot changes (:meth:`load`).
        """
        b = int(self.map_building[m])
        return MapStorage(self.grids[m], self.pooled[m], self.targets[b], self.bits[m], self.observed, m)

    def robot(self, i: int, config: RobotConfig, params: np.ndarray) -> DiscRobot:
        """Robot ``i`` as a :class:`~realistic_indoor.sim.disc_physics.DiscRobot` on its row of :attr:`phys`.

        Its pose and velocity are kept current by :func:`step_batch`. Valid until the building of
        its slot changes (:meth:`load`).

        Args:
            i: The robot.
            config: Its body, limits and control rate.
            params: Its constants (:attr:`StepConstants.params`).
        """
        b = int(self.robot_building[i])
        grid = SegmentGrid(self.segments[b], self.seg_start[b], self.seg_items[b], self.seg_origin[b])
        return DiscRobot.sharing(self.phys[i], grid, params, config)

    def place(self, i: int, pose: tuple[float, float, float] | None = None) -> None:
        """Put robot ``i`` at rest at ``pose`` ``(x m, y m, heading rad)``, by default its building's start."""
        if pose is None:
            meta = self.building_meta[self.robot_building[i]]
            pose = (meta[4], meta[5], meta[6])
        self.phys[i] = 0.0
        self.phys[i, X], self.phys[i, Y] = pose[0], pose[1]
        self.phys[i, THETA] = math.remainder(pose[2], math.tau)

    def reset_robot(self, i: int) -> None:
        """Put robot ``i`` at rest at its building's start pose, with its map emptied."""
        self.reset_map(int(self.robot_map[i]))
        self.place(i)

    def copy_map(self, dst: int, src: int) -> None:
        """Make map ``dst`` a copy of map ``src`` (of the same building): cells, bits, observed cells."""
        self.grids[dst][...] = self.grids[src]
        self.pooled[dst][...] = self.pooled[src]
        self.bits[dst].todo[...] = self.bits[src].todo
        self.bits[dst].walls[...] = self.bits[src].walls
        self.observed[dst] = self.observed[src]

    def merge_map(self, dst: int, src: int) -> int:
        """Add to map ``dst`` what map ``src`` (of the same building) knows and it does not.

        Returns:
            The reachable floor cells newly observed in ``dst`` (what :attr:`observed` counts).
        """
        reachable = merge_maps(
            self.grids[dst], self.pooled[dst], self.pool, self.targets[self.map_building[dst]], self.todo[dst],
            self.walls[dst], self.todo[src], self.walls[src],
        )  # fmt: skip
        self.observed[dst] += reachable
        return int(reachable)

    def global_view(
        self, m: int, centre_xy: tuple[float, float], up_rad: float, resolution_m: float, free: np.ndarray,
        wall: np.ndarray,
    ) -> None:  # fmt: skip
        """Mark map ``m``'s known floor and walls on a fixed-orientation image, as :meth:`RobotMap.global_view`."""
        meta = self.building_meta[self.map_building[m]]
        cell = meta[2] * self.pool
        scatter_global(
            self.pooled[m], (centre_xy[0] - meta[0]) / cell, (centre_xy[1] - meta[1]) / cell, math.cos(up_rad),
            math.sin(up_rad), cell / resolution_m, free, wall,
        )  # fmt: skip

    def step(self, kernel: Any, mode: np.ndarray, commands: np.ndarray, noise: np.ndarray,
             constants: StepConstants, out: StepOutputs) -> None:  # fmt: skip
        """Run ``kernel`` (:func:`step_batch` or :func:`step_batch_serial`) on this batch.

        Args:
            kernel: The compiled step.
            mode: ``(n,)`` int64 :data:`SKIP`, :data:`STEP` or :data:`RESET` per robot.
            commands: ``(n, 2)`` float64 ``(v m/s, w rad/s)``.
            noise: ``(n, n_beams)`` standard normal draws for the range noise.
            constants: The robot's, laser's and local view's constants.
            out: The arrays the step writes.
        """
        if self._state is None:
            lists = (self.skips, self.targets, self.segments, self.seg_start, self.seg_items, self.seg_origin,
                     self.grids, self.pooled, self.todo, self.walls)  # fmt: skip
            if self.n_buildings == 1 and self.n_maps == 1:
                # one building and one map (the single environment's batch of one): tuples, which
                # the call types in about 0.1 us each against 1.1 us for a typed list
                lists = tuple(tuple(x) for x in lists)
            self._state = (self.phys, self.layout, self.building_meta, *lists, self.observed)
        c = constants
        kernel(mode, commands, *self._state, c.params, c.cos_off, c.sin_off, noise, c.lidar, c.local, *out)

    def __getstate__(self) -> dict[str, Any]:
        """The state to pickle: numba's typed lists as plain lists (they do not pickle)."""
        state = {
            **self.__dict__,
            "skips": None,
            "_state": None,
        }  # each world's raycaster holds its skip field
        for name in _TYPED_LISTS:
            state[name] = list(state[name])
        return state

    def __setstate__(self, state: dict[str, Any]) -> None:
        """Rebuild the typed lists; the skip fields are the (unpickled) worlds' own again."""
        for name in _TYPED_LISTS:
            state[name] = List(state[name])
        state["skips"] = _skip_fields(state["worlds"])
        self.__dict__.update(state)

    @property
    def nbytes(self) -> int:
        """Memory held by the batch's arrays and its worlds (bytes)."""
        lists = (self.targets, self.grids, self.pooled, self.segments, self.seg_items)
        total = sum(int(a.nbytes) for lst in lists for a in lst)
        total += sum(b.nbytes for b in self.bits if b is not None)
        worlds = sum(
            w.nbytes for w in {id(w): w for w in self.worlds if w is not None}.values()
        )  # shared once
        return total + worlds + self.phys.nbytes


class StepConstants(NamedTuple):
    """What :meth:`Batch.step` reads and never changes.

    Attributes:
        params: The robot's constants (:func:`~realistic_indoor.sim.disc_physics.drive_params`).
        cos_off: ``(n_beams,)`` cosines of the beam offsets.
        sin_off: ``(n_beams,)`` sines of the beam offsets.
        lidar: ``(max range m, noise std m, closed fan 0/1)``.
        local: ``(pool cells, pixel size in pooled cells)``.
    """

    params: np.ndarray
    cos_off: np.ndarray
    sin_off: np.ndarray
    lidar: np.ndarray
    local: np.ndarray


def step_constants(
    robot: RobotConfig, world: WorldConfig, lidar: LidarConfig, local_map: LocalMapConfig
) -> StepConstants:
    """The constants of a batch's step for robots of ``robot``'s body with ``lidar``'s laser.

    Args:
        robot: Body, limits and control rate.
        world: Raster resolution (the maps' cells) and wall thickness.
        lidar: The laser scanner.
        local_map: The local view's size and pixel.
    """
    cos, sin, closed = beam_table(beam_offsets(lidar))
    pool, pixel = local_map.pooling(world.resolution_m)
    return StepConstants(
        drive_params(robot, world.wall_thickness_m),
        cos,
        sin,
        np.array([lidar.max_range_m, lidar.noise_std_m, float(closed)]),
        np.array([pool, pixel]),
    )


class StepOutputs(NamedTuple):
    """The arrays :meth:`Batch.step` writes (see :func:`step_batch`).

    Attributes:
        scan: ``(n, n_beams)`` float32 readings (m).
        local: ``(n, 1, S, S)`` uint8 local views.
        terms: ``(n, T)`` float64 reward terms, ``T >= 3``.
        motion: ``(n,)`` float64 distance driven (m).
        true_m: ``(n, n_beams)`` float32 noise-free ranges (m) of the latest scans.
        kinds: ``(n, n_beams)`` uint8 what each beam of the latest scans ended on.
    """

    scan: np.ndarray
    local: np.ndarray
    terms: np.ndarray
    motion: np.ndarray
    true_m: np.ndarray
    kinds: np.ndarray

    @classmethod
    def zeros(cls, n: int, n_beams: int, size_px: int, n_terms: int = N_TERMS) -> StepOutputs:
        """Zeroed outputs for ``n`` robots, ``n_beams`` beams, ``size_px`` views, ``n_terms`` terms."""
        return cls(
            np.zeros((n, n_beams), np.float32),
            np.zeros((n, 1, size_px, size_px), np.uint8),
            np.zeros((n, n_terms)),
            np.zeros(n),
            np.zeros((n, n_beams), np.float32),
            np.zeros((n, n_beams), np.uint8),
        )


def _indices(given: np.ndarray | None, n: int) -> np.ndarray:
    """``given`` as an int64 array of ``n`` indices, or ``0..n-1``."""
    if given is None:
        return np.arange(n, dtype=np.int64)
    out = np.asarray(given, dtype=np.int64)
    if out.shape != (n,) or (n and out.min() < 0):
        raise ConfigError(f"Batch: {n} non-negative indices needed, got {given!r}")
    return out


def _csr(lists: list[list[int]]) -> tuple[np.ndarray, np.ndarray]:
    """Lists of robot indices as ``(start, items)``: list ``k`` is ``items[start[k]:start[k + 1]]``."""
    start = np.zeros(len(lists) + 1, dtype=np.int64)
    start[1:] = np.cumsum([len(x) for x in lists])
    items = np.array([int(i) for x in lists for i in x], dtype=np.int64)
    return start, items


def _check_layout(robot_building: np.ndarray, robot_map: np.ndarray, map_scans: list[list[int]]) -> None:
    """Refuse maps that mix buildings, robots whose map does not take their scans, bad indices."""
    n = len(robot_building)
    if robot_map.shape != (n,) or (n and (robot_map.min() < 0 or robot_map.max() >= len(map_scans))):
        raise ConfigError(
            f"Batch: robot_map must name one of {len(map_scans)} maps per robot, got {robot_map!r}"
        )
    for m, robots in enumerate(map_scans):
        if any(not 0 <= r < n for r in robots) or len({int(robot_building[r]) for r in robots}) > 1:
            raise ConfigError(f"Batch: map {m} must integrate robots of one building, got {robots!r}")
    for i in range(n):
        if i not in map_scans[robot_map[i]]:
            raise ConfigError(f"Batch: robot {i}'s map {robot_map[i]} does not integrate its scans")


_TYPED_LISTS = (
    "targets",
    "segments",
    "seg_start",
    "seg_items",
    "seg_origin",
    "grids",
    "pooled",
    "todo",
    "walls",
)
"""The :class:`Batch` attributes held in numba typed lists, besides ``skips`` (:func:`_skip_fields`)."""


def _skip_fields(worlds: list[World | None]) -> List:
    """The typed list of each slot's skip field: its world's raycaster's, read-only, or a placeholder."""
    frozen = np.zeros((1, 1), dtype=np.uint8)
    frozen.setflags(write=False)  # the raycasters' skip fields are read-only
    return List([frozen if w is None else w.raycaster._skip for w in worlds])


@njit(cache=True, nogil=True, parallel=True)
def step_batch(
    mode,
    commands,
    phys,
    layout,
    meta,
    skips,
    targets,
    segments,
    seg_start,
    seg_items,
    seg_origin,
    grids,
    pooled,
    todo,
    walls,
    observed,
    params,
    cos_off,
    sin_off,
    noise,
    lidar,
    local,
    out_scan,
    out_local,
    out_terms,
    out_motion,
    out_true,
    out_kinds,
):  # pragma: no cover - compiled
    """Advance every robot whose ``mode`` is :data:`STEP`; scan and map those at :data:`RESET`.

    Buildings run in parallel (numba's threads, as many as ``numba.set_num_threads`` allows), and
    in each, in turn: the physics of its stepped robots, moved together (they collide with each
    other); each robot's laser scan; each of its maps' update with the scans it integrates, one
    robot after the other (a map belongs to one building, so two robots never write one map at
    once); each robot's local view and reward terms. One parallel loop, not one per phase: each
    loop's end waits for the slowest thread (``docs/benchmarks.md``). :func:`step_batch_serial`
    is the same step on the calling thread only.

    Args:
        mode: ``(n,)`` int64 :data:`SKIP`, :data:`STEP` or :data:`RESET` per robot.
        commands: ``(n, 2)`` float64 ``(v m/s, w rad/s)``.
        phys: ``(n, STATE_SIZE)`` physics state, updated.
        layout: :attr:`Batch.layout`, the robots', maps' and buildings' indices in one int64
            array (one argument instead of eight: each costs the call about 0.4 us of typing):
            ``robot_building`` ``(n,)``; ``robot_map`` ``(n,)`` the map each robot sees (its local
            view, its new-area term); the robots of building ``b``,
            ``building_robots[building_start[b]:building_start[b + 1]]``; the robots whose scans
            map ``m`` integrates, in order, ``map_robots[map_start[m]:map_start[m + 1]]``; the
            maps of building ``b``, ``building_maps[maps_start[b]:maps_start[b + 1]]``.
        meta: ``(n_buildings, 8)`` :attr:`Batch.building_meta`.
        skips: Per building, the raycaster's skip field.
        targets: Per building, what a beam may mark in each cell (the robot map's targets).
        segments: Per building, ``(S, 4)`` wall segments (m).
        seg_start: Per building, the wall grid's bucket starts.
        seg_items: Per building, the wall grid's segment indices.
        seg_origin: Per building, the wall grid's origin, bucket side and size.
        grids: Per map, its cell states, updated.
        pooled: Per map, its pooled cells, updated.
        todo: Per map, the to-do bits of its free cells still unknown, updated.
        walls: Per map, the bits of its wall cells not yet marked, updated.
        observed: ``(n_maps,)`` reachable cells observed, updated.
        params: The robot's constants (:func:`~realistic_indoor.sim.disc_physics.drive_params`).
        cos_off: ``(n_beams,)`` cosines of the beam offsets.
        sin_off: ``(n_beams,)`` sines of the beam offsets.
        noise: ``(n, n_beams)`` standard normal draws for the range noise.
        lidar: ``(max range m, noise std m, closed fan 0/1)``.
        local: ``(pool cells, pixel size in pooled cells)``.
        out_scan: ``(n, n_beams)`` float32 readings (m), written.
        out_local: ``(n, 1, S, S)`` uint8 local views, written.
        out_terms: ``(n, T)`` float64 reward terms, ``T >= 3``: columns 0-2 written (new area m2
            that the robot's scan added to its own map, collision with a wall or another robot,
            time); further ones are the caller's (search: victims).
        out_motion: ``(n,)`` float64 distance driven (m), written.
        out_true: ``(n, n_beams)`` float32 noise-free range of each beam (m), written: where it
            entered a wall or left the building (:class:`~realistic_indoor.sim.raycast.RayHits`).
        out_kinds: ``(n, n_beams)`` uint8 what each beam ended on (``RASTER_*``), written.
    """
    for k in prange(layout[3] - layout[2] - 1):  # building_start's length, less one
        b = np.int64(k)  # prange counts in uint64; lists index with a signed int
        _step_building(
            b, mode, commands, phys, layout, meta, skips, targets, segments, seg_start, seg_items, seg_origin,
            grids, pooled, todo, walls, observed, params, cos_off, sin_off, noise, lidar, local, out_true,
            out_kinds, out_scan, out_local, out_terms, out_motion,
        )  # fmt: skip


@njit(cache=True, nogil=True)
def step_batch_serial(
    mode,
    commands,
    phys,
    layout,
    meta,
    skips,
    targets,
    segments,
    seg_start,
    seg_items,
    seg_origin,
    grids,
    pooled,
    todo,
    walls,
    observed,
    params,
    cos_off,
    sin_off,
    noise,
    lidar,
    local,
    out_scan,
    out_local,
    out_terms,
    out_motion,
    out_true,
    out_kinds,
):  # pragma: no cover - compiled
    """:func:`step_batch` on the calling thread: no thread pool is started or woken.

    Where a step is short (a few robots), waking numba's threads costs more than it saves, and
    their OpenMP threads spinning afterwards slow other libraries of the process (torch) down.

    The kernels spell their parameters out: with ``*args`` numba types every argument in
    Python on each call (about 0.3 ms a call, against a few microseconds).
    """
    for b in range(layout[3] - layout[2] - 1):
        _step_building(
            b, mode, commands, phys, layout, meta, skips, targets, segments, seg_start, seg_items, seg_origin,
            grids, pooled, todo, walls, observed, params, cos_off, sin_off, noise, lidar, local, out_true,
            out_kinds, out_scan, out_local, out_terms, out_motion,
        )  # fmt: skip


@njit(cache=True, nogil=True, inline="always")
def _layout_parts(layout):  # pragma: no cover - compiled
    """The eight index arrays of :attr:`Batch.layout`, as views.

    ``robot_building``, ``robot_map``, ``building_start``, ``building_robots``, ``map_start``,
    ``map_robots``, ``maps_start``, ``building_maps``: the header's nine entries bound them.
    """
    return (
        layout[layout[0] : layout[1]],
        layout[layout[1] : layout[2]],
        layout[layout[2] : layout[3]],
        layout[layout[3] : layout[4]],
        layout[layout[4] : layout[5]],
        layout[layout[5] : layout[6]],
        layout[layout[6] : layout[7]],
        layout[layout[7] : layout[8]],
    )


@njit(cache=True, nogil=True)
def _step_building(
    b, mode, commands, phys, layout, meta, skips, targets, segments, seg_start, seg_items, seg_origin, grids,
    pooled, todo, walls, observed, params, cos_off, sin_off, noise, lidar, local, true_m, kinds, out_scan,
    out_local, out_terms, out_motion,
):  # fmt: skip  # pragma: no cover - compiled
    """Building ``b``'s part of :func:`step_batch`: its robots' physics, scans, maps and views, in turn."""
    (
        robot_building,
        robot_map,
        building_start,
        building_robots,
        map_start,
        map_robots,
        maps_start,
        building_maps,
    ) = _layout_parts(layout)
    _drive_building(b, mode, commands, phys, building_start, building_robots, segments, seg_start,
                    seg_items, seg_origin, params, out_terms, out_motion)  # fmt: skip
    members = building_robots[building_start[b] : building_start[b + 1]]
    for i in members:
        _scan_robot(i, mode, phys, robot_building, meta, skips, cos_off, sin_off, noise, lidar,
                    true_m, kinds, out_scan)  # fmt: skip
    for j in range(maps_start[b], maps_start[b + 1]):
        _update_map(building_maps[j], mode, phys, robot_building, robot_map, map_start, map_robots, meta,
                    targets, grids, pooled, todo, walls, observed, cos_off, sin_off, lidar, local, true_m,
                    kinds, out_terms)  # fmt: skip
    for i in members:
        _view_robot(i, mode, phys, robot_building, robot_map, meta, pooled, local, out_local)


@njit(cache=True, nogil=True, inline="always")
def _drive_building(b, mode, commands, phys, building_start, building_robots, segments, seg_start, seg_items,
                    seg_origin, params, out_terms, out_motion):  # fmt: skip  # pragma: no cover - compiled
    """Move building ``b``'s robots at :data:`STEP` together; collision and distance terms of all its robots."""
    members = building_robots[building_start[b] : building_start[b + 1]]
    stepped = 0
    for i in members:
        if mode[i] != SKIP:
            out_terms[i, 1] = 0.0
            out_terms[i, 2] = 1.0
            out_motion[i] = 0.0
        stepped += 1 if mode[i] == STEP else 0
    if stepped == 0:
        return
    robots = np.empty(stepped, dtype=np.int64)
    j = 0
    for i in members:
        if mode[i] == STEP:
            robots[j] = i
            j += 1
    touched, distance = drive_group(
        phys, robots, commands, segments[b], seg_start[b], seg_items[b], seg_origin[b], params
    )
    for j in range(stepped):
        out_terms[robots[j], 1] = 1.0 if touched[j] else 0.0
        out_motion[robots[j]] = distance[j]


@njit(cache=True, nogil=True, inline="always")
def _scan_robot(i, mode, phys, robot_building, meta, skips, cos_off, sin_off, noise, lidar, true_m, kinds,
                out_scan):  # fmt: skip  # pragma: no cover - compiled
    """Robot ``i``'s laser scan from where it stands: true ranges and kinds, and its readings."""
    if mode[i] == SKIP:
        return
    b = robot_building[i]
    x0, y0, res = meta[b, 0], meta[b, 1], meta[b, 2]
    # every position in the single robot's own arithmetic (Raycaster.cast_into, RobotMap): a
    # last-bit difference moves a ray that runs along a cell boundary into the next row
    scale = 1.0 / res
    x_cast = (phys[i, X] - x0) * scale
    y_cast = (phys[i, Y] - y0) * scale
    ch = math.cos(phys[i, THETA])
    sh = math.sin(phys[i, THETA])
    max_range = lidar[0]
    _cast_fan(skips[b], x_cast, y_cast, ch, sh, cos_off, sin_off, max_range * scale, res, true_m[i], kinds[i])
    _readings(true_m[i], kinds[i], noise[i], lidar[1], max_range, out_scan[i])


@njit(cache=True, nogil=True, inline="always")
def _update_map(m, mode, phys, robot_building, robot_map, map_start, map_robots, meta, targets, grids, pooled,
                todo, walls, observed, cos_off, sin_off, lidar, local, true_m, kinds,
                out_terms):  # fmt: skip  # pragma: no cover - compiled
    """Integrate into map ``m`` the scans of its robots, one after the other; new-area terms."""
    closed = lidar[2] > 0.5
    pool = int(local[0])
    for j in range(map_start[m], map_start[m + 1]):
        i = map_robots[j]
        if mode[i] == SKIP:
            continue
        b = robot_building[i]
        x0, y0, res = meta[b, 0], meta[b, 1], meta[b, 2]
        px = (phys[i, X] - x0) / res
        py = (phys[i, Y] - y0) / res
        ch = math.cos(phys[i, THETA])
        sh = math.sin(phys[i, THETA])
        new = integrate_scan(grids[m], pooled[m], pool, targets[b], todo[m], walls[m], px, py, ch, sh,
                             cos_off, sin_off, true_m[i], kinds[i], 1.0 / res, closed)  # fmt: skip
        observed[m] += new
        if robot_map[i] == m:
            out_terms[i, 0] = new * (res * res)  # as RobotMap.update: cells times the cell area


@njit(cache=True, nogil=True, inline="always")
def _view_robot(i, mode, phys, robot_building, robot_map, meta, pooled, local,
                out_local):  # fmt: skip  # pragma: no cover - compiled
    """Robot ``i``'s local view of its map, after every map's update."""
    if mode[i] == SKIP:
        return
    b = robot_building[i]
    x0, y0, res = meta[b, 0], meta[b, 1], meta[b, 2]
    cell = res * local[0]
    x_view = (phys[i, X] - x0) / cell
    y_view = (phys[i, Y] - y0) / cell
    ch = math.cos(phys[i, THETA])
    sh = math.sin(phys[i, THETA])
    render_local(pooled[robot_map[i]], PIXEL_OF_STATE, x_view, y_view, ch, sh, local[1], out_local[i, 0])
