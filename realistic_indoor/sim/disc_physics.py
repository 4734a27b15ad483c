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

Several robots of one building move together (:func:`drive_group`): as pymunk's bodies of one
space, each sub-step moves them all, finds their wall contacts and the pairs of robots that
overlap, and solves all these contacts in the same iterations, a contact of two robots as one
between two bodies of equal mass (``tests/sim/test_robot_team.py`` holds it to pymunk's
:class:`~realistic_indoor.sim.robot.RobotTeam`).

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

__all__ = [
    "STATE_SIZE",
    "DiscRobot",
    "SegmentGrid",
    "drive",
    "drive_group",
    "drive_params",
    "odometry",
    "robot_in_world",
    "segment_grid",
    "wrap_angle",
]

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
N_PARAMS = 12
"""Floats of :func:`drive_params`."""


@njit(cache=True, nogil=True)
def wrap_angle(t: float | np.ndarray) -> float | np.ndarray:
    """An angle (rad; a float or an array) wrapped into ``[-pi, pi]``: the heading rule of every robot.

    ``t - 2 pi * rint(t / 2 pi)``, which equals ``math.remainder(t, 2 pi)`` to the bit for
    ``|t| <= 3 pi`` (the nearest whole number of turns is at most 1, so the product and the
    difference are exact), the range of a heading plus a step's turn or a difference of two
    headings. Compiled, so kernels and Python share it.
    """
    return t - 2.0 * math.pi * np.rint(t / (2.0 * math.pi))


@njit(cache=True, nogil=True)
def odometry(
    x: float, y: float, theta: float, x0: float, y0: float, theta0: float, cos0: float, sin0: float
) -> tuple[float, float, float]:
    """A pose ``(x, y, theta)`` in the odometry frame of the start pose ``(x0, y0, theta0)``.

    ``x`` along the start heading, ``y`` to its left (m), the heading relative to the start's
    (rad, :func:`wrap_angle`); ``cos0``, ``sin0`` are the start heading's. The odometry rule of
    every robot, single, batched or in a team.
    """
    dx, dy = x - x0, y - y0
    return cos0 * dx + sin0 * dy, -sin0 * dx + cos0 * dy, wrap_angle(theta - theta0)


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
        slop (m), share of an overlap removed per sub-step, solver iterations, half wall (m),
        radius (m).
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
            config.radius_m,
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
    def sharing(
        cls, state: np.ndarray, grid: SegmentGrid, params: np.ndarray, config: RobotConfig
    ) -> DiscRobot:
        """A robot whose physics state is ``state``, in place: a row of a batch's states.

        Args:
            state: ``(STATE_SIZE,)`` float64 array the robot reads and writes (not copied).
            grid: Its building's wall grid.
            params: Its constants (:func:`drive_params` of ``config``).
            config: Body, limits and control rate.
        """
        robot = cls.__new__(cls)
        robot.config, robot.params, robot.grid, robot.state = config, params, grid, state
        return robot

    @classmethod
    def in_world(cls, world: World, config: RobotConfig | None = None) -> DiscRobot:
        """A robot among ``world``'s walls, at its start pose."""
        return cls(world.collision_segments, config, world.config.wall_thickness_m, world.start_pose)

    def reset(self, pose: tuple[float, float, float]) -> None:
        """Put the robot at ``pose`` ``(x, y, theta)``, at rest."""
        self.state[:] = 0.0
        self.state[X], self.state[Y] = float(pose[0]), float(pose[1])
        self.state[THETA] = math.remainder(float(pose[2]), math.tau)  # any angle: exact for every turn count

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
    (:func:`drive_params`) apply as in :meth:`Robot.step`. :func:`drive_group` with one robot.
    """
    phys = state.reshape(1, state.shape[0])
    robots = np.zeros(1, dtype=np.int64)
    commands = np.empty((1, 2))
    commands[0, 0] = cmd_v
    commands[0, 1] = cmd_w
    touched, distance = drive_group(phys, robots, commands, segs, start, items, origin, params)
    return touched[0], distance[0]


@njit(cache=True, nogil=True)
def drive_group(phys, robots, commands, segs, start, items, origin, params):  # pragma: no cover - compiled
    """One control step of the robots ``robots`` of one building, moved together, in place.

    Each robot moves as :func:`drive` moves one, and the robots also push each other apart:
    two discs closer than two radii (``params[11]``) are a contact of two bodies of equal mass,
    solved with the wall contacts in the same iterations (as pymunk solves two bodies of one
    space). A robot that touches no other robot moves exactly as it would alone.

    Args:
        phys: ``(n, STATE_SIZE)`` physics states, the rows of ``robots`` updated.
        robots: ``(k,)`` int64 rows of ``phys`` to move, in the order contacts are solved.
        commands: ``(n, 2)`` ``(v m/s, w rad/s)`` per row of ``phys``.
        segs: ``(S, 4)`` wall segments of the building (m).
        start: The wall grid's bucket starts.
        items: The wall grid's segment indices.
        origin: The wall grid's origin, bucket side and size.
        params: :func:`drive_params`.

    Returns:
        ``(touched, distance)``: ``(k,)`` bool, whether each robot touched a wall or another
        robot, and ``(k,)`` float64 the distance each moved (m).
    """
    k = robots.shape[0]
    reach, v_max, w_max, dv_max, dw_max, dt, n_sub = (
        params[0],
        params[1],
        params[2],
        params[3],
        params[4],
        params[5],
        params[6],
    )
    scalars = np.empty((5, k))  # few allocations: a robot's step is about 1 us
    vs, ws, thetas, x0s, y0s = scalars[0], scalars[1], scalars[2], scalars[3], scalars[4]
    for a in range(k):
        state = phys[robots[a]]
        cmd_v, cmd_w = commands[robots[a], 0], commands[robots[a], 1]
        v = state[V] + min(max(min(max(cmd_v, -v_max), v_max) - state[V], -dv_max), dv_max)
        w = state[W] + min(max(min(max(cmd_w, -w_max), w_max) - state[W], -dw_max), dw_max)
        state[V] = v
        state[W] = w
        vs[a], ws[a], thetas[a] = v, w, state[THETA]
        x0s[a], y0s[a] = state[X], state[Y]
    substeps = int(n_sub)
    h = dt / substeps
    wall_floats = np.empty((3, k, MAX_CONTACTS))
    walls = _Contacts(
        wall_floats[0],
        wall_floats[1],
        wall_floats[2],
        np.empty((k, MAX_CONTACTS), dtype=np.int64),
        np.zeros(k, dtype=np.int64),
    )
    n_max = k * (k - 1) // 2
    pair_ints = np.empty((2, n_max), dtype=np.int64)
    pair_floats = np.empty((3, n_max))
    pairs = _Pairs(pair_ints[0], pair_ints[1], pair_floats[0], pair_floats[1], pair_floats[2])
    wall_impulses = np.empty((2, k, MAX_CONTACTS))
    pair_impulses = np.empty((2, n_max))
    impulses = (wall_impulses[0], wall_impulses[1], pair_impulses[0], pair_impulses[1])
    touched = np.zeros(k, dtype=np.bool_)
    for _ in range(substeps):
        for a in range(k):
            state = phys[robots[a]]
            state[X] += (state[VX] + state[BX]) * h
            state[Y] += (state[VY] + state[BY]) * h
            state[BX] = 0.0
            state[BY] = 0.0
        for a in range(k):
            state = phys[robots[a]]
            n = _contacts(
                state[X], state[Y], reach, segs, start, items, origin, params, h,
                walls.nx[a], walls.ny[a], walls.bias[a], walls.ids[a],
            )  # fmt: skip
            walls.count[a] = n
            touched[a] = touched[a] or n > 0
        n_pairs = _pair_contacts(phys, robots, params, h, pairs, touched)
        for a in range(k):
            state = phys[robots[a]]
            mid = thetas[a] + 0.5 * ws[a] * h
            state[VX] = vs[a] * math.cos(mid)
            state[VY] = vs[a] * math.sin(mid)
        _solve(phys, robots, walls, pairs, n_pairs, int(params[9]), impulses)
        for a in range(k):
            thetas[a] += ws[a] * h
    distance = np.empty(k)
    for a in range(k):
        state = phys[robots[a]]
        theta = thetas[a]
        state[THETA] = wrap_angle(theta)
        distance[a] = math.hypot(state[X] - x0s[a], state[Y] - y0s[a])
    return touched, distance


class _Contacts(NamedTuple):
    """Wall contacts of each robot of a group in one sub-step (rows: robots)."""

    nx: np.ndarray
    ny: np.ndarray
    bias: np.ndarray
    ids: np.ndarray
    count: np.ndarray


class _Pairs(NamedTuple):
    """Robot-robot contacts of a group in one sub-step.

    The two robots (positions in the group), the normal from the second to the first, and the
    bias velocity (m/s).
    """

    a: np.ndarray
    b: np.ndarray
    nx: np.ndarray
    ny: np.ndarray
    bias: np.ndarray


@njit(cache=True, nogil=True, inline="always")
def _pair_contacts(phys, robots, params, h, pairs, touched):  # pragma: no cover - compiled
    """Find the pairs of robots closer than two radii; mark them touched; return how many."""
    reach = 2.0 * params[11]
    slop, bias_coef = params[7], params[8]
    n = 0
    k = robots.shape[0]
    for a in range(k):
        pa = phys[robots[a]]
        for b in range(a + 1, k):
            pb = phys[robots[b]]
            dx = pa[X] - pb[X]
            dy = pa[Y] - pb[Y]
            d2 = dx * dx + dy * dy
            if d2 < reach * reach:
                d = math.sqrt(d2)
                pairs.a[n] = a
                pairs.b[n] = b
                pairs.nx[n] = dx / d if d > 0.0 else 1.0
                pairs.ny[n] = dy / d if d > 0.0 else 0.0
                pairs.bias[n] = bias_coef * max(reach - d - slop, 0.0) / h
                touched[a] = True
                touched[b] = True
                n += 1
    return n


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
def _solve(phys, robots, walls, pairs, n_pairs, iterations, impulses):  # pragma: no cover - compiled
    """Chipmunk's sequential impulses for bodies of equal mass against walls and each other.

    Warm start: a contact already there in the previous sub-step starts from the impulse it
    ended with there (cached in the first robot's state: a wall by its segment index, another
    robot ``j`` as ``-1 - j``); the contacts and their final impulses are cached for the next.
    Impulses are per unit mass: a wall takes away the whole velocity into it, a contact of two
    robots half of it from each. ``impulses`` holds the arrays they accumulate in, zeroed here:
    normal and bias impulses of the walls ``(k, MAX_CONTACTS)``, then of the pairs.
    """
    k = robots.shape[0]
    jn, jb, pjn, pjb = impulses
    jn[:] = 0.0
    jb[:] = 0.0
    pjn[:] = 0.0
    pjb[:] = 0.0
    for a in range(k):
        state = phys[robots[a]]
        cached = int(state[N_CACHED])
        for i in range(walls.count[a]):
            for c in range(cached):
                if int(state[CACHED_IDS + c]) == walls.ids[a, i]:
                    jn[a, i] = state[CACHED_IDS + MAX_CONTACTS + c]
                    state[VX] += walls.nx[a, i] * jn[a, i]
                    state[VY] += walls.ny[a, i] * jn[a, i]
    for p in range(n_pairs):
        _warm_pair(phys, robots, pairs, p, pjn)
    for _ in range(iterations):
        for a in range(k):
            _wall_iteration(phys[robots[a]], walls, a, jn[a], jb[a])
        for p in range(n_pairs):
            _pair_iteration(phys[robots[pairs.a[p]]], phys[robots[pairs.b[p]]], pairs, p, pjn, pjb)
    for a in range(k):
        state = phys[robots[a]]
        n = walls.count[a]
        for i in range(n):
            state[CACHED_IDS + i] = walls.ids[a, i]
            state[CACHED_IDS + MAX_CONTACTS + i] = jn[a, i]
        for p in range(n_pairs):
            if pairs.a[p] == a and n < MAX_CONTACTS:
                state[CACHED_IDS + n] = -1 - robots[pairs.b[p]]
                state[CACHED_IDS + MAX_CONTACTS + n] = pjn[p]
                n += 1
        state[N_CACHED] = n


@njit(cache=True, nogil=True, inline="always")
def _wall_iteration(state, walls, a, jn, jb):  # pragma: no cover - compiled
    """One Gauss-Seidel pass over robot ``a``'s wall contacts (bias, then normal impulse)."""
    for i in range(walls.count[a]):
        nx, ny = walls.nx[a, i], walls.ny[a, i]
        vbn = state[BX] * nx + state[BY] * ny
        old = jb[i]
        jb[i] = max(old + walls.bias[a, i] - vbn, 0.0)
        state[BX] += nx * (jb[i] - old)
        state[BY] += ny * (jb[i] - old)
        vn = state[VX] * nx + state[VY] * ny
        old = jn[i]
        jn[i] = max(old - vn, 0.0)
        state[VX] += nx * (jn[i] - old)
        state[VY] += ny * (jn[i] - old)


@njit(cache=True, nogil=True, inline="always")
def _warm_pair(phys, robots, pairs, p, pjn):  # pragma: no cover - compiled
    """Apply again the impulse contact ``p`` of two robots ended the previous sub-step with."""
    sa, sb = phys[robots[pairs.a[p]]], phys[robots[pairs.b[p]]]
    other = -1 - robots[pairs.b[p]]
    for c in range(int(sa[N_CACHED])):
        if int(sa[CACHED_IDS + c]) == other:
            pjn[p] = sa[CACHED_IDS + MAX_CONTACTS + c]
            sa[VX] += pairs.nx[p] * pjn[p]
            sa[VY] += pairs.ny[p] * pjn[p]
            sb[VX] -= pairs.nx[p] * pjn[p]
            sb[VY] -= pairs.ny[p] * pjn[p]


@njit(cache=True, nogil=True, inline="always")
def _pair_iteration(sa, sb, pairs, p, pjn, pjb):  # pragma: no cover - compiled
    """One Gauss-Seidel pass over contact ``p`` of two robots of equal mass."""
    nx, ny = pairs.nx[p], pairs.ny[p]
    vbn = (sa[BX] - sb[BX]) * nx + (sa[BY] - sb[BY]) * ny
    old = pjb[p]
    pjb[p] = max(old + 0.5 * (pairs.bias[p] - vbn), 0.0)
    d = pjb[p] - old
    sa[BX] += nx * d
    sa[BY] += ny * d
    sb[BX] -= nx * d
    sb[BY] -= ny * d
    vn = (sa[VX] - sb[VX]) * nx + (sa[VY] - sb[VY]) * ny
    old = pjn[p]
    pjn[p] = max(old - 0.5 * vn, 0.0)
    d = pjn[p] - old
    sa[VX] += nx * d
    sa[VY] += ny * d
    sb[VX] -= nx * d
    sb[VY] -= ny * d
