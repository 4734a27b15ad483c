"""Compiled disc-against-walls physics: the pymunk robot's motion, with no Python per step.

:class:`~realistic_indoor.sim.robot.Robot` drives a pymunk body; this module moves the same
disc the same way in numba, so a batch of robots can step in one compiled call
(:mod:`realistic_indoor.sim.batch`). It reproduces what pymunk (Chipmunk 2D) does in one
``space.step(h)`` for a disc of infinite moment among static segments of friction and elasticity
0, in pymunk's order:

1. the position moves by ``h`` times the body's velocity plus its bias velocity (the velocity
   left by the previous sub-step: a sub-step moves with what the solver let through before);
2. contacts: every wall segment (a capsule of half the wall thickness) the disc overlaps;
3. the velocity is set to the command along the heading (the robot's velocity function);
4. the impulse each wall already touched in the previous sub-step ended with is applied again
   (Chipmunk's warm starting), then ten Gauss-Seidel iterations of the contact solver take
   away any velocity into a wall (accumulated normal impulses clamped at 0) and add a bias
   velocity that pushes an overlap deeper than the slop back out (``1 - bias ** h`` of it per
   sub-step).

pymunk remains the reference: ``tests/sim/test_disc_physics.py`` holds this module to it on the
same command sequences in the same buildings. What is left of the difference comes from the
order in which the solver visits simultaneous contacts (pymunk's follows its spatial index),
which after ten iterations changes the result slightly where the robot touches two walls.

Walls are found through a uniform grid of buckets (:class:`SegmentGrid`): each bucket lists
the segments that can touch a disc centred anywhere in it, so a sub-step tests only those.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, NamedTuple

import numpy as np
from numba import njit

from realistic_indoor.sim.robot import _COLLISION_BIAS, _COLLISION_SLOP_M, Motion, Robot, RobotConfig

if TYPE_CHECKING:
    from realistic_indoor.sim.world import World

__all__ = ["STATE_SIZE", "DiscRobot", "SegmentGrid", "drive_params", "robot_in_world", "segment_grid"]

SOLVER_ITERATIONS = 10
"""Iterations of the contact solver per sub-step (pymunk's default ``space.iterations``)."""
BUCKET_M = 1.0
"""Side of a bucket of the segment grid (m)."""
MAX_CONTACTS = 8
"""Most wall segments one disc can touch at once that the solver takes into account."""
X, Y, THETA, V, W, VX, VY, BX, BY, N_CACHED = range(10)
CACHED_IDS = 10
"""State index of the segments touched in the last sub-step (as floats), then their impulses."""
STATE_SIZE = CACHED_IDS + 2 * MAX_CONTACTS
"""Floats of a robot's physics state: x, y, heading (m, m, rad), speed and turn rate after the
limits (m/s, rad/s), the body's velocity (m/s, x and y), its bias velocity (m/s, x and y), the
number of walls touched in the last sub-step, their segment indices and their impulses (m/s)."""
N_PARAMS = 11
"""Floats of :func:`drive_params`."""


class SegmentGrid(NamedTuple):
    """Wall segments bucketed on a uniform grid, for the contact search of one building.

    Attributes:
        segments: ``(S, 4)`` float64 ``(ax, ay, bx, by)`` segment ends (m).
        start: ``(ny * nx + 1,)`` int64: bucket ``k`` lists ``items[start[k]:start[k + 1]]``.
        items: int64 segment indices, bucket by bucket.
        origin: ``(x0, y0, bucket_m, nx, ny)`` float64: the grid's corner (m), bucket side (m),
            buckets along x and y.
    """

    segments: np.ndarray
    start: np.ndarray
    items: np.ndarray
    origin: np.ndarray


def segment_grid(segments: np.ndarray, reach_m: float, bucket_m: float = BUCKET_M) -> SegmentGrid:
    """Bucket wall segments so that a disc's contacts are found from the bucket of its centre.

    Args:
        segments: ``(S, 2, 2)`` wall segments (m), e.g. :attr:`World.collision_segments`.
        reach_m: Largest distance from a segment's centre line at which a disc's centre touches
            it (m): the disc's radius plus half the wall thickness.
        bucket_m: Side of a bucket (m).

    Returns:
        The grid; a bucket lists every segment within ``reach_m`` of any point in it.
    """
    segs = np.array(segments, dtype=np.float64).reshape(-1, 4)  # a writable copy
    pad = reach_m + 1e-6
    if len(segs):
        x0 = math.floor((min(segs[:, 0].min(), segs[:, 2].min()) - pad) / bucket_m) * bucket_m
        y0 = math.floor((min(segs[:, 1].min(), segs[:, 3].min()) - pad) / bucket_m) * bucket_m
        nx = math.ceil((max(segs[:, 0].max(), segs[:, 2].max()) + pad - x0) / bucket_m) + 1
        ny = math.ceil((max(segs[:, 1].max(), segs[:, 3].max()) + pad - y0) / bucket_m) + 1
    else:
        x0 = y0 = 0.0
        nx = ny = 1
    start, items = _bucket(segs, x0, y0, bucket_m, nx, ny, pad)
    return SegmentGrid(segs, start, items, np.array([x0, y0, bucket_m, nx, ny], dtype=np.float64))


def drive_params(config: RobotConfig, wall_thickness_m: float) -> np.ndarray:
    """The robot's constants as the float64 array the compiled step takes.

    Args:
        config: Body, limits and control rate.
        wall_thickness_m: Thickness of the walls (m).

    Returns:
        ``(N_PARAMS,)``: radius plus half wall (m), speed and turn limits (m/s, rad/s), speed
        and turn-rate change per control step (m/s, rad/s), control step (s), sub-steps,
        slop (m), share of an overlap removed per sub-step, solver iterations, half wall (m).
    """
    h = config.dt_s / config.substeps
    return np.array(
        [
            config.radius_m + wall_thickness_m / 2,
            config.max_speed_m_s,
            config.max_turn_rate_rad_s,
            config.max_accel_m_s2 * config.dt_s,
            config.max_angular_accel_rad_s2 * config.dt_s,
            config.dt_s,
            config.substeps,
            _COLLISION_SLOP_M,
            1.0 - _COLLISION_BIAS**h,
            SOLVER_ITERATIONS,
            wall_thickness_m / 2,
        ],
        dtype=np.float64,
    )


class DiscRobot:
    """The compiled counterpart of :class:`~realistic_indoor.sim.robot.Robot`, one robot.

    Same constructor, :meth:`reset`, :meth:`step`, :attr:`pose` and :attr:`velocity`; the state
    is one float64 array (:data:`STATE_SIZE`), the walls a :class:`SegmentGrid`.

    Args:
        segments: ``(N, 2, 2)`` wall segments (m), e.g. :attr:`World.collision_segments`.
        config: Body, limits and control rate.
        wall_thickness_m: Thickness given to the wall segments (m).
        pose: Initial ``(x, y, theta)`` (m, m, rad).
    """

    def __init__(
        self,
        segments: np.ndarray,
        config: RobotConfig | None = None,
        wall_thickness_m: float = 0.1,
        pose: tuple[float, float, float] = (0.0, 0.0, 0.0),
    ) -> None:
        self.config = config or RobotConfig()
        self.params = drive_params(self.config, wall_thickness_m)
        self.grid = segment_grid(segments, self.params[0])
        self.state = np.zeros(STATE_SIZE, dtype=np.float64)
        self.reset(pose)

    @classmethod
    def in_world(cls, world: World, config: RobotConfig | None = None) -> DiscRobot:
        """A robot among ``world``'s walls, at its start pose."""
        return cls(world.collision_segments, config, world.config.wall_thickness_m, world.start_pose)

    def reset(self, pose: tuple[float, float, float]) -> None:
        """Put the robot at ``pose`` ``(x, y, theta)``, at rest."""
        self.state[:] = 0.0
        self.state[X], self.state[Y] = float(pose[0]), float(pose[1])
        self.state[THETA] = math.remainder(float(pose[2]), math.tau)

    @property
    def pose(self) -> tuple[float, float, float]:
        """``(x, y, theta)``: position (m) and heading (rad, in ``[-pi, pi]``)."""
        return (float(self.state[X]), float(self.state[Y]), float(self.state[THETA]))

    @property
    def velocity(self) -> tuple[float, float]:
        """``(v, w)``: current forward speed (m/s) and turning rate (rad/s), after limits."""
        return (float(self.state[V]), float(self.state[W]))

    def step(self, v_m_s: float, w_rad_s: float) -> Motion:
        """Drive for one control step, as :meth:`Robot.step` does; about 1 microsecond."""
        g = self.grid
        collided, distance = drive(
            self.state, float(v_m_s), float(w_rad_s), g.segments, g.start, g.items, g.origin, self.params
        )
        return Motion(bool(collided), float(distance))


def robot_in_world(world: World, config: RobotConfig | None = None) -> DiscRobot | Robot:
    """A robot at ``world``'s start pose, moved by the physics ``config.physics`` names.

    Args:
        world: The world whose walls the robot collides with.
        config: Body, limits, control rate and physics (default :class:`RobotConfig`).

    Returns:
        A :class:`DiscRobot` (``"compiled"``) or a pymunk :class:`~realistic_indoor.sim.robot.Robot`.
    """
    config = config or RobotConfig()
    kind = DiscRobot if config.physics == "compiled" else Robot
    return kind.in_world(world, config)


@njit(cache=True, nogil=True)
def _bucket(segs, x0, y0, cell, nx, ny, pad):  # pragma: no cover - compiled
    """CSR lists of the segments within ``pad`` of each bucket (by their padded bounding box)."""
    counts = np.zeros(nx * ny + 1, dtype=np.int64)
    for pass_ in range(2):
        if pass_ == 1:
            for k in range(nx * ny):
                counts[k + 1] += counts[k]
            items = np.empty(counts[nx * ny], dtype=np.int64)
            fill = counts[:-1].copy()
        for s in range(segs.shape[0]):
            ax, ay, bx, by = segs[s, 0], segs[s, 1], segs[s, 2], segs[s, 3]
            c0 = max(math.floor((min(ax, bx) - pad - x0) / cell), 0)
            c1 = min(math.floor((max(ax, bx) + pad - x0) / cell), nx - 1)
            r0 = max(math.floor((min(ay, by) - pad - y0) / cell), 0)
            r1 = min(math.floor((max(ay, by) + pad - y0) / cell), ny - 1)
            for r in range(r0, r1 + 1):
                for c in range(c0, c1 + 1):
                    if _segment_box_distance(ax, ay, bx, by, x0 + c * cell, y0 + r * cell, cell) <= pad:
                        if pass_ == 0:
                            counts[r * nx + c + 1] += 1
                        else:
                            items[fill[r * nx + c]] = s
                            fill[r * nx + c] += 1
    return counts, items


@njit(cache=True, nogil=True)
def _segment_box_distance(ax, ay, bx, by, x0, y0, side):  # pragma: no cover - compiled
    """A lower bound of the distance (m) between a segment and a square.

    The distance from the square's centre less half its diagonal, 0 if that is negative.
    """
    cx = x0 + 0.5 * side
    cy = y0 + 0.5 * side
    d = math.sqrt(_point_segment_sq(cx, cy, ax, ay, bx, by)[0]) - side * 0.7071067811865476
    return max(d, 0.0)


@njit(cache=True, nogil=True, inline="always")
def _point_segment_sq(px, py, ax, ay, bx, by):  # pragma: no cover - compiled
    """Squared distance from a point to a segment, and the closest point (Chipmunk's formula)."""
    dx = bx - ax
    dy = by - ay
    length_sq = dx * dx + dy * dy
    t = ((px - ax) * dx + (py - ay) * dy) / length_sq if length_sq > 0.0 else 0.0
    t = min(max(t, 0.0), 1.0)
    qx = ax + t * dx
    qy = ay + t * dy
    return (px - qx) * (px - qx) + (py - qy) * (py - qy), qx, qy


@njit(cache=True, nogil=True)
def drive(state, cmd_v, cmd_w, segs, start, items, origin, params):  # pragma: no cover - compiled
    """One control step of one robot, in place on ``state``; returns ``(collided, distance_m)``.

    ``cmd_v`` (m/s) and ``cmd_w`` (rad/s) are the command; the limits of ``params``
    (:func:`drive_params`) apply as in :meth:`Robot.step`.
    """
    reach, v_max, w_max, dv_max, dw_max, dt, n_sub = (
        params[0],
        params[1],
        params[2],
        params[3],
        params[4],
        params[5],
        params[6],
    )
    v = state[V] + min(max(min(max(cmd_v, -v_max), v_max) - state[V], -dv_max), dv_max)
    w = state[W] + min(max(min(max(cmd_w, -w_max), w_max) - state[W], -dw_max), dw_max)
    state[V] = v
    state[W] = w
    substeps = int(n_sub)
    h = dt / substeps
    x0, y0 = state[X], state[Y]
    theta = state[THETA]
    nxs = np.empty(MAX_CONTACTS)
    nys = np.empty(MAX_CONTACTS)
    bias = np.empty(MAX_CONTACTS)
    ids = np.empty(MAX_CONTACTS, dtype=np.int64)
    touched = False
    for _ in range(substeps):
        state[X] += (state[VX] + state[BX]) * h
        state[Y] += (state[VY] + state[BY]) * h
        state[BX] = 0.0
        state[BY] = 0.0
        n = _contacts(state[X], state[Y], reach, segs, start, items, origin, params, h, nxs, nys, bias, ids)
        touched = touched or n > 0
        mid = theta + 0.5 * w * h
        state[VX] = v * math.cos(mid)
        state[VY] = v * math.sin(mid)
        _solve(state, nxs, nys, bias, ids, n, int(params[9]))
        theta += w * h
    state[THETA] = theta - 2.0 * math.pi * np.rint(theta / (2.0 * math.pi))  # math.remainder
    return touched, math.hypot(state[X] - x0, state[Y] - y0)


@njit(cache=True, nogil=True, inline="always")
def _contacts(px, py, reach, segs, start, items, origin, params, h, nxs, nys, bias, ids):  # pragma: no cover
    """Normals (wall to robot) and bias velocities (m/s) of the segments the disc overlaps."""
    gx0, gy0, cell, gnx, gny = origin[0], origin[1], origin[2], int(origin[3]), int(origin[4])
    c = math.floor((px - gx0) / cell)
    r = math.floor((py - gy0) / cell)
    if c < 0 or r < 0 or c >= gnx or r >= gny:
        return 0
    slop, bias_coef = params[7], params[8]
    k = r * gnx + c
    n = 0
    for j in range(start[k], start[k + 1]):
        s = items[j]
        d2, qx, qy = _point_segment_sq(px, py, segs[s, 0], segs[s, 1], segs[s, 2], segs[s, 3])
        if d2 < reach * reach and n < MAX_CONTACTS:
            d = math.sqrt(d2)
            if d > 0.0:
                nxs[n] = (px - qx) / d
                nys[n] = (py - qy) / d
            else:
                nxs[n] = 1.0
                nys[n] = 0.0
            bias[n] = bias_coef * max(reach - d - slop, 0.0) / h
            ids[n] = s
            n += 1
    return n


@njit(cache=True, nogil=True, inline="always")
def _solve(state, nxs, nys, bias, ids, n, iterations):  # pragma: no cover - compiled
    """Chipmunk's sequential impulses for a body of unit mass against static contacts.

    Warm start: a wall touched in the previous sub-step starts from the impulse it ended with
    there (cached in ``state``); the contacts and their final impulses are cached for the next.
    """
    jn = np.zeros(MAX_CONTACTS)
    jb = np.zeros(MAX_CONTACTS)
    cached = int(state[N_CACHED])
    for i in range(n):
        for c in range(cached):
            if int(state[CACHED_IDS + c]) == ids[i]:
                jn[i] = state[CACHED_IDS + MAX_CONTACTS + c]
                state[VX] += nxs[i] * jn[i]
                state[VY] += nys[i] * jn[i]
    for _ in range(iterations):
        for i in range(n):
            nx, ny = nxs[i], nys[i]
            vbn = state[BX] * nx + state[BY] * ny
            old = jb[i]
            jb[i] = max(old + bias[i] - vbn, 0.0)
            state[BX] += nx * (jb[i] - old)
            state[BY] += ny * (jb[i] - old)
            vn = state[VX] * nx + state[VY] * ny
            old = jn[i]
            jn[i] = max(old - vn, 0.0)
            state[VX] += nx * (jn[i] - old)
            state[VY] += ny * (jn[i] - old)
    state[N_CACHED] = n
    for i in range(n):
        state[CACHED_IDS + i] = ids[i]
        state[CACHED_IDS + MAX_CONTACTS + i] = jn[i]
