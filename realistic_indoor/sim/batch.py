"""Batched simulation: many robots advanced by one compiled, multi-threaded call.

State lives in arrays with a leading robot axis (physics state, scans, counters) and in typed
lists indexed by robot (each robot's map) or by building (raster-derived fields, wall grids).
``robot_building[i]`` names robot ``i``'s building, so several robots in one building is a change
of data: today each robot gets its own building slot (see ``docs/architecture.md``).

One :func:`step_batch` call runs, for every robot in parallel (numba ``prange``, the GIL
released): the compiled disc physics (:mod:`realistic_indoor.sim.disc_physics`), the laser
(the raycaster's kernel), the map update and local view (the robot map's kernels) and the reward
terms, writing into preallocated arrays. The kernels are those of the single-robot classes, so a
robot's scans and map follow the same rules; only the physics differs from pymunk, within the
tolerance ``tests/sim/test_disc_physics.py`` states.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numba import njit, prange
from numba.typed import List

from realistic_indoor.sim._map_kernels import integrate_scan, render_local
from realistic_indoor.sim.disc_physics import STATE_SIZE, THETA, X, Y, drive, segment_grid
from realistic_indoor.sim.lidar import _readings
from realistic_indoor.sim.mapping import PIXEL_OF_STATE, MapBits, _targets
from realistic_indoor.sim.raycast import _cast_fan
from realistic_indoor.sim.world import World

__all__ = ["N_TERMS", "RESET", "SKIP", "STEP", "STEP_TERMS", "Batch", "step_batch", "step_batch_serial"]

SKIP, STEP, RESET = 0, 1, 2
"""What :func:`step_batch` does to a robot: nothing, a control step, or a first scan after a reset."""
STEP_TERMS = ("new_area", "collision", "time")
"""The reward terms a control step measures, in the columns the kernels write them: floor newly
observed (m2), whether the robot touched a wall (0 or 1), and the step itself (1)."""
N_TERMS = len(STEP_TERMS)
"""Reward terms per robot that the kernels write."""


class Batch:
    """The state of ``n`` robots, each in its own building slot, for :func:`step_batch`.

    Args:
        n: Number of robots.

    Attributes:
        phys: ``(n, STATE_SIZE)`` float64 physics state (:mod:`~realistic_indoor.sim.disc_physics`).
        robot_building: ``(n,)`` int64 building slot of each robot.
        building_meta: ``(n, 8)`` float64 per building slot: raster origin x, y (m), cell size
            (m), reachable cells, start pose x, y, heading (m, m, rad), unused.
        observed: ``(n,)`` int64 reachable cells each robot has observed.
        worlds: The :class:`World` of each building slot (``None`` before it is loaded).
    """

    def __init__(self, n: int) -> None:
        self.n = n
        self.phys = np.zeros((n, STATE_SIZE), dtype=np.float64)
        self.robot_building = np.arange(n, dtype=np.int64)
        self.building_meta = np.zeros((n, 8), dtype=np.float64)
        self.observed = np.zeros(n, dtype=np.int64)
        self.worlds: list[World | None] = [None] * n
        empty2 = np.zeros((1, 1), dtype=np.uint8)
        self.skips = _skip_fields(self.worlds)
        self.targets = List([empty2] * n)
        self.segments = List([np.zeros((1, 4))] * n)
        self.seg_start = List([np.zeros(2, dtype=np.int64)] * n)
        self.seg_items = List([np.zeros(0, dtype=np.int64)] * n)
        self.seg_origin = List([np.array([0.0, 0.0, 1.0, 1.0, 1.0])] * n)
        self.grids = List([empty2] * n)
        self.pooled = List([empty2] * n)
        self.bits: list[MapBits | None] = [None] * n
        self.todo = List([np.zeros((1, 1), dtype=np.int64)] * n)  # each robot's bits.todo
        self.walls = List([np.zeros((1, 1), dtype=np.int64)] * n)  # each robot's bits.walls

    def load(self, slot: int, world: World, reach_m: float, pool: int) -> None:
        """Make ``world`` the building of ``slot`` and give robot ``slot`` an empty map of it.

        Args:
            slot: Building slot (and robot) index.
            world: The world.
            reach_m: Robot radius plus half the wall thickness (m), for the wall grid.
            pool: Map cells per side of a pooled cell (the local view's pixel over the cell).
        """
        self.worlds[slot] = world
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
        self.grids[slot] = np.zeros((h, w), dtype=np.uint8)
        self.pooled[slot] = np.zeros((-(-h // pool), -(-w // pool)), dtype=np.uint8)
        bits = self.bits[slot] = MapBits(targets)
        self.todo[slot] = bits.todo
        self.walls[slot] = bits.walls
        x0, y0 = raster.origin
        start = world.start_pose
        reachable = float(np.count_nonzero(world.reachable))
        self.building_meta[slot] = (x0, y0, raster.resolution_m, reachable, *start, 0.0)

    def reset_robot(self, i: int) -> None:
        """Put robot ``i`` at rest at its building's start pose, with an empty map."""
        self.grids[i].fill(0)
        self.pooled[i].fill(0)
        self.bits[i].reset()
        self.observed[i] = 0
        self.phys[i] = 0.0
        meta = self.building_meta[self.robot_building[i]]
        self.phys[i, X], self.phys[i, Y] = meta[4], meta[5]
        self.phys[i, THETA] = math.remainder(meta[6], math.tau)

    def __getstate__(self) -> dict[str, Any]:
        """The state to pickle: numba's typed lists as plain lists (they do not pickle)."""
        state = {**self.__dict__, "skips": None}  # each world's raycaster holds its skip field
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
    robot_building,
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
):  # pragma: no cover - compiled
    """Advance every robot whose ``mode`` is :data:`STEP`; scan and map those at :data:`RESET`.

    Robots run in parallel (numba's threads, as many as ``numba.set_num_threads`` allows);
    :func:`step_batch_serial` is the same step on the calling thread only.

    Args:
        mode: ``(n,)`` int64 :data:`SKIP`, :data:`STEP` or :data:`RESET` per robot.
        commands: ``(n, 2)`` float64 ``(v m/s, w rad/s)``.
        phys: ``(n, STATE_SIZE)`` physics state, updated.
        robot_building: ``(n,)`` building slot of each robot.
        meta: ``(n_buildings, 8)`` :attr:`Batch.building_meta`.
        skips: Per building, the raycaster's skip field.
        targets: Per building, what a beam may mark in each cell (the robot map's targets).
        segments: Per building, ``(S, 4)`` wall segments (m).
        seg_start: Per building, the wall grid's bucket starts.
        seg_items: Per building, the wall grid's segment indices.
        seg_origin: Per building, the wall grid's origin, bucket side and size.
        grids: Per robot, its map (cell states), updated.
        pooled: Per robot, its pooled map, updated.
        todo: Per robot, the to-do bits of its map's free cells still unknown, updated.
        walls: Per robot, the bits of its map's wall cells not yet marked, updated.
        observed: ``(n,)`` reachable cells observed, updated.
        params: The robot's constants (:func:`~realistic_indoor.sim.disc_physics.drive_params`).
        cos_off: ``(n_beams,)`` cosines of the beam offsets.
        sin_off: ``(n_beams,)`` sines of the beam offsets.
        noise: ``(n, n_beams)`` standard normal draws for the range noise.
        lidar: ``(max range m, noise std m, closed fan 0/1)``.
        local: ``(pool cells, pixel size in pooled cells)``.
        out_scan: ``(n, n_beams)`` float32 readings (m), written.
        out_local: ``(n, 1, S, S)`` uint8 local views, written.
        out_terms: ``(n, T)`` float64 reward terms, ``T >= 3``: columns 0-2 written (new area m2,
            collision, time); further ones are the caller's (search: victims).
        out_motion: ``(n,)`` float64 distance driven (m), written.
    """
    for k in prange(mode.shape[0]):
        i = np.int64(k)  # prange counts in uint64; lists index with a signed int
        _step_robot(
            i, mode, commands, phys, robot_building, meta, skips, targets, segments, seg_start,
            seg_items, seg_origin, grids, pooled, todo, walls, observed, params, cos_off, sin_off, noise,
            lidar, local, out_scan, out_local, out_terms, out_motion,
        )  # fmt: skip


@njit(cache=True, nogil=True)
def step_batch_serial(
    mode,
    commands,
    phys,
    robot_building,
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
):  # pragma: no cover - compiled
    """:func:`step_batch` on the calling thread: no thread pool is started or woken.

    Where a step is short (a few robots), waking numba's threads costs more than it saves, and
    their OpenMP threads spinning afterwards slow other libraries of the process (torch) down.

    The three functions spell their parameters out: with ``*args`` numba types every argument
    in Python on each call (about 0.3 ms a call, against a few microseconds).
    """
    for i in range(mode.shape[0]):
        _step_robot(
            i, mode, commands, phys, robot_building, meta, skips, targets, segments, seg_start,
            seg_items, seg_origin, grids, pooled, todo, walls, observed, params, cos_off, sin_off, noise,
            lidar, local, out_scan, out_local, out_terms, out_motion,
        )  # fmt: skip


@njit(cache=True, nogil=True)
def _step_robot(
    i,
    mode,
    commands,
    phys,
    robot_building,
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
):  # pragma: no cover - compiled
    """Robot ``i``'s part of :func:`step_batch`."""
    n_beams = cos_off.shape[0]
    max_range, noise_std, closed = lidar[0], lidar[1], lidar[2] > 0.5
    pool, pixel = int(local[0]), local[1]
    if mode[i] == SKIP:
        return
    b = robot_building[i]
    collided = False
    distance = 0.0
    if mode[i] == STEP:
        collided, distance = drive(
            phys[i],
            commands[i, 0],
            commands[i, 1],
            segments[b],
            seg_start[b],
            seg_items[b],
            seg_origin[b],
            params,
        )
    x0, y0, res = meta[b, 0], meta[b, 1], meta[b, 2]
    px = (phys[i, X] - x0) / res
    py = (phys[i, Y] - y0) / res
    ch = math.cos(phys[i, THETA])
    sh = math.sin(phys[i, THETA])
    true_m = np.empty(n_beams, dtype=np.float32)
    kind = np.empty(n_beams, dtype=np.uint8)
    # every position in the single robot's own arithmetic (Raycaster.cast_into, RobotMap): a
    # last-bit difference moves a ray that runs along a cell boundary into the next row
    scale = 1.0 / res
    x_cast = (phys[i, X] - x0) * scale
    y_cast = (phys[i, Y] - y0) * scale
    _cast_fan(skips[b], x_cast, y_cast, ch, sh, cos_off, sin_off, max_range * scale, res, true_m, kind)
    _readings(true_m, kind, noise[i], noise_std, max_range, out_scan[i])
    new = integrate_scan(
        grids[i],
        pooled[i],
        pool,
        targets[b],
        todo[i],
        walls[i],
        px,
        py,
        ch,
        sh,
        cos_off,
        sin_off,
        true_m,
        kind,
        1.0 / res,
        closed,
    )
    observed[i] += new
    cell = res * pool
    x_view = (phys[i, X] - x0) / cell
    y_view = (phys[i, Y] - y0) / cell
    render_local(pooled[i], PIXEL_OF_STATE, x_view, y_view, ch, sh, pixel, out_local[i, 0])
    out_terms[i, 0] = new * (res * res)  # as RobotMap.update: cells times the cell area
    out_terms[i, 1] = 1.0 if collided else 0.0
    out_terms[i, 2] = 1.0
    out_motion[i] = distance
