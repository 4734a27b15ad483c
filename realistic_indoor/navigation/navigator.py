"""The navigator under the map-based explorers and the environments' macro actions.

One loop, shared by every frontier explorer (:mod:`realistic_indoor.agents`) and by the
environments' macro actions (:mod:`realistic_indoor.envs`): map the scan on the robot's own map,
keep the plan or make a new one, and steer along the path; back up and replan when jammed,
blacklist a goal the robot makes no progress towards. In victim search a victim the sensor
detects is a goal of its own: the robot goes to it, then resumes exploring.

Only the choice of a goal is left to the caller. A step is three calls, so that a caller can
stop between them and ask someone else (a policy) where to go:

1. :meth:`Navigator.sense` takes the observation and says whether a goal must be chosen now:
   exactly where a classical explorer replans (its path is done, its goal no longer borders
   unobserved space, its path runs into a newly mapped obstacle, after a collision, when a
   victim is newly detected, and every ``replan_steps`` steps if the map has grown by
   ``replan_new_m2``);
2. if so, :meth:`Navigator.options` gives what there is to choose from (the planning window,
   the frontiers, the path to a detected victim) and :meth:`Navigator.commit` takes the choice;
3. :meth:`Navigator.command` returns the velocity command of the step.

:meth:`Navigator.step` runs the three with a goal-choosing function.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, NamedTuple

import numpy as np

from realistic_indoor.checks import require_int, require_positive
from realistic_indoor.errors import ConfigError
from realistic_indoor.navigation.follower import FollowerConfig, PathFollower
from realistic_indoor.navigation.frontiers import Frontiers, find_frontiers, unobserved
from realistic_indoor.navigation.own_map import Box, OwnMap
from realistic_indoor.navigation.planning import CostConfig, clearance, costmap, dijkstra, trace_path
from realistic_indoor.navigation.reflexes import Reflexes
from realistic_indoor.navigation.spec import RobotSpec
from realistic_indoor.navigation.victims import VictimTracker
from realistic_indoor.sim.lidar import beam_offsets
from realistic_indoor.sim.mapping import MAPPED_FREE

__all__ = ["ExplorerConfig", "Found", "Navigator", "PlanContext", "PlanOptions"]

_MAX_RECOVERIES = 3
"""After this many recoveries from jams (:class:`Reflexes`) on the way to one goal, the goal is
blacklisted."""


@dataclass(frozen=True)
class ExplorerConfig:
    """Settings of the map-based explorers.

    Attributes:
        map_resolution_m: Cell side of the agent's own map (m).
        min_frontier_m: Frontiers shorter than this are ignored (m).
        replan_steps: Replan after this many steps if the map has grown by ``replan_new_m2``.
        replan_new_m2: Newly mapped area that makes a periodic replan worth it (m2).
        stuck_steps: A robot that moved less than ``stuck_move_m`` in this many steps while
            heading for the same goal is stuck: the goal is blacklisted, and the robot backs
            up a little. A robot touching a wall or blocked right ahead 5 steps in a row backs
            up and replans; the fourth time on the way to one goal, the goal is blacklisted.
        stuck_move_m: See ``stuck_steps`` (m).
        blacklist_radius_m: Frontier cells this close to a blacklisted goal are ignored (m).
        goal_still_open_m: A goal stays valid while unobserved cells lie this close to it (m).
        min_goal_m: Frontier cells this close to the robot are not goals (m): the laser's
            blind sector behind the robot would otherwise make its own cell a frontier.
        victim_approach_m: In victim search, the robot goes this close to each victim it
            detects (m); ``None`` ignores detected victims.
        bump_half_width_m: A collision the laser does not explain (nothing seen within 0.1 m
            of the robot: the invisible line across an entrance) marks a wall across the robot's
            front, this much wider than the robot on each side (m).
        cost: Costmap weights.
        follower: Path-tracking settings.
    """

    map_resolution_m: float = 0.1
    min_frontier_m: float = 0.3
    replan_steps: int = 10
    replan_new_m2: float = 1.0
    stuck_steps: int = 25
    stuck_move_m: float = 0.3
    blacklist_radius_m: float = 1.0
    goal_still_open_m: float = 0.3
    min_goal_m: float = 0.6
    victim_approach_m: float | None = 1.0
    bump_half_width_m: float = 0.4
    cost: CostConfig = field(default_factory=CostConfig)
    follower: FollowerConfig = field(default_factory=FollowerConfig)

    def __post_init__(self) -> None:
        for name, unit in (
            ("map_resolution_m", "m"),
            ("min_frontier_m", "m"),
            ("stuck_move_m", "m"),
            ("blacklist_radius_m", "m"),
            ("goal_still_open_m", "m"),
            ("min_goal_m", "m"),
            ("bump_half_width_m", "m"),
        ):
            require_positive("ExplorerConfig", name, getattr(self, name), unit)
        require_positive("ExplorerConfig", "replan_new_m2", self.replan_new_m2, "m2", allow_zero=True)
        require_int("ExplorerConfig", "replan_steps", self.replan_steps, 1)
        require_int("ExplorerConfig", "stuck_steps", self.stuck_steps, 2)
        if self.victim_approach_m is not None:
            require_positive("ExplorerConfig", "victim_approach_m", self.victim_approach_m, "m")
        if not isinstance(self.cost, CostConfig) or not isinstance(self.follower, FollowerConfig):
            raise ConfigError("ExplorerConfig.cost and .follower must be a CostConfig and a FollowerConfig")


class PlanContext(NamedTuple):
    """What a goal chooser sees at planning time, on the planning window of the map.

    Attributes:
        box: The window of the map (cells) the arrays below cover.
        state: Map cells in the window.
        todo: Cells still to observe (unknown, or unswept in search).
        clearance_m: Distance from each cell to the nearest occupied cell (m).
        cost: Costmap (cost per cell, ``inf`` where lethal).
        start: The robot's cell in the window.
        pose: The robot's pose (odometry frame).
        resolution_m: Cell side (m).
    """

    box: Box
    state: np.ndarray
    todo: np.ndarray
    clearance_m: np.ndarray
    cost: np.ndarray
    start: tuple[int, int]
    pose: tuple[float, float, float]
    resolution_m: float


Found = tuple[int, np.ndarray]
"""A reachable goal: ``(flat index of the goal cell in the planning window, parent array of a
Dijkstra search from the robot)``, for :func:`~realistic_indoor.navigation.planning.trace_path`."""


class PlanOptions(NamedTuple):
    """What there is to choose from when the navigator asks for a goal.

    Attributes:
        ctx: The planning window and its costmap.
        frontiers: The frontiers still worth going to (those near the robot or near
            blacklisted goals dropped); ``frontiers.count`` may be 0.
        victim: Index (in :attr:`Navigator.victims`) of the detected victim to go to next, or
            ``None``: none is waiting, or none can be reached.
        victim_path: The path to that victim (``None`` when ``victim`` is ``None``).
        victim_cost_m: That path's cost (m of clear floor; ``nan`` when ``victim`` is ``None``).
    """

    ctx: PlanContext
    frontiers: Frontiers
    victim: int | None
    victim_path: Found | None
    victim_cost_m: float = math.nan


class Navigator:
    """The map, plan, follow loop of a map-based explorer (see the module docstring).

    Args:
        spec: The robot's sensors and limits.
        config: Navigation settings.

    Attributes:
        spec: The robot's sensors and limits.
        config: Navigation settings.
        map: The robot's own map.
        victims: Victims detected (search only; empty in exploration).
        follower: The path follower.
        reflexes: Jam, bump and stuck detection, and backing up.
        blacklist: Goals given up on (odometry frame, m); frontier cells near them are dropped.
        finished: Whether the last plan found nothing to go to (exploration is over).
        goal: The goal being driven to (m, odometry frame), or ``None``.
        pose: The pose of the last observation (odometry frame: m, m, rad).
        plans: Goals chosen (or found missing) this episode: the calls of :meth:`commit`.
    """

    def __init__(self, spec: RobotSpec, config: ExplorerConfig | None = None) -> None:
        self.spec = spec
        self.config = config or ExplorerConfig()
        if not isinstance(self.config, ExplorerConfig):
            raise ConfigError(f"config must be an ExplorerConfig, got {type(self.config).__name__}")
        c = self.config
        sensor = None if spec.victims is None else (spec.victims.sensor_range_m, spec.victims.sensor_fov_rad)
        self.map = OwnMap(beam_offsets(spec.lidar), spec.lidar.max_range_m, c.map_resolution_m, sensor)
        self.victims = VictimTracker(spec.victims.sensor_range_m if spec.victims else 1.0)
        self.follower = PathFollower(spec.robot.max_speed_m_s, spec.robot.max_turn_rate_rad_s, c.follower)
        self.reflexes = Reflexes(spec, self.map, c.bump_half_width_m, c.stuck_steps, c.stuck_move_m)
        self._min_cells = max(1, math.ceil(c.min_frontier_m / c.map_resolution_m))
        self.reset()

    def reset(self) -> None:
        """Forget the map, the plan, the blacklist and the victims."""
        self.map.reset()
        self.victims.reset()
        self.follower.clear()
        self.blacklist: list[tuple[float, float]] = []
        self.finished = False
        self.goal: tuple[float, float] | None = None
        self.pose: tuple[float, float, float] = (0.0, 0.0, 0.0)
        self._victim: int | None = None
        self.plans = 0
        self._frontier_goal = True
        self._since_plan = 0
        self._new_cells = 0
        self._new_victims = 0
        self._recoveries = 0
        self._ranges = np.zeros(0, dtype=np.float32)
        self._collided = False
        self._mode = "drive"
        self.reflexes.reset()

    def use_map(self, own_map: OwnMap) -> None:
        """Map onto ``own_map`` from now on: a map shared with teammates, in the same frame.

        The plan, blacklist and victims stay; the next :meth:`sense` integrates into it.
        """
        self.map = own_map
        self.reflexes.map = own_map

    # -- one step ----------------------------------------------------------------------------------------
    def step(
        self,
        obs: dict[str, np.ndarray],
        info: dict[str, Any],
        choose: Callable[[Frontiers, PlanContext], Found | None],
    ) -> tuple[float, float]:
        """Sense, plan with ``choose`` if a goal is needed, and return the command ``(v m/s, w rad/s)``.

        Args:
            obs: The environment's observation (``scan``, ``pose``, ``velocity``; ``victims``
                in search).
            info: The step's ``info`` (``collisions`` is the bumper).
            choose: Picks a goal among the frontiers (called only when there is at least one
                and no detected victim to go to); returns ``None`` if none is reachable.
        """
        if self.sense(obs, info):
            options = self.options()
            if options.victim is not None:
                found = options.victim_path
            else:
                found = choose(options.frontiers, options.ctx) if options.frontiers.count else None
            self.commit(options, found, to_victim=options.victim is not None)
        return self.command()

    def sense(self, obs: dict[str, np.ndarray], info: dict[str, Any]) -> bool:
        """Add the observation to the map and say whether a goal must be chosen before :meth:`command`.

        Args:
            obs: The environment's observation.
            info: The step's ``info``.

        Returns:
            Whether the caller must now call :meth:`options` and :meth:`commit`.
        """
        pose = (float(obs["pose"][0]), float(obs["pose"][1]), float(obs["pose"][2]))
        ranges = np.asarray(obs["scan"], dtype=np.float32) * np.float32(self.spec.lidar.max_range_m)
        reflexes = self.reflexes
        self._collided = reflexes.bumped(pose, ranges, float(obs["velocity"][0]), info)
        self._new_cells += self.map.integrate(pose, ranges, self.spec.robot.radius_m)
        self._since_plan += 1
        if "victims" in obs and self.config.victim_approach_m is not None:
            self._new_victims += self.victims.observe(pose, obs["victims"])
        self.pose, self._ranges = pose, ranges
        if reflexes.backing:
            self._mode = "back"
        elif reflexes.jammed:
            self._mode = "jammed"
        elif reflexes.stuck:
            self._mode = "stuck"
        else:
            self._mode = "drive"
        return self._mode == "drive" and (self._collided or self._needs_plan(pose))

    def command(self) -> tuple[float, float]:
        """The velocity command ``(v m/s, w rad/s)`` of this step, after :meth:`sense` (and the plan it asked for)."""
        reflexes, pose = self.reflexes, self.pose
        if self._mode == "back":
            v, w = reflexes.back_up()
        elif self._mode == "jammed":
            self._recover(pose)
            v, w = 0.0, 0.0
        elif self._mode == "stuck":
            self._give_up(pose)
            v, w = 0.0, 0.0
        else:
            v, w = self.follower.command(pose, reflexes.clearance_ahead(self._ranges))
            if self.follower.blocked:
                w = reflexes.turn_away(self._ranges)
        reflexes.record(pose, self._collided, self.follower.blocked, self.follower.turning)
        return v, w

    # -- when to plan --------------------------------------------------------------------------------------
    def _needs_plan(self, pose: tuple[float, float, float]) -> bool:
        c = self.config
        if self.finished:
            return self._since_plan >= c.replan_steps
        if self.follower.done(pose):
            if self._victim is not None:
                self.victims.visited[self._victim] = True
            return True
        if self._victim is None and (self.goal is None or (self._frontier_goal and not self._goal_open())):
            return True
        if self._path_blocked():
            return True
        if self._victim is None and self._new_victims:
            return True
        grown = self._new_cells * self.map.resolution_m**2 >= c.replan_new_m2
        return self._since_plan >= c.replan_steps and grown

    def _give_up(self, pose: tuple[float, float, float]) -> None:
        """No progress towards the goal: blacklist it (or mark the victim visited) and back up."""
        if self._victim is not None:
            self.victims.visited[self._victim] = True
        elif self.goal is not None:
            self.blacklist.append(self.goal)
        self._recover(pose)
        self.reflexes.restart_progress()

    def _recover(self, pose: tuple[float, float, float]) -> None:
        """Back up a little and replan; a goal that needed this too often is blacklisted."""
        self._recoveries += 1
        if self._recoveries > _MAX_RECOVERIES and self._victim is None and self.goal is not None:
            self.blacklist.append(self.goal)
            self._recoveries = 0
        self.follower.clear()
        self.reflexes.start_backup(pose)

    def _goal_open(self) -> bool:
        r, c = self.map.to_cell(*self.goal)
        k = max(1, round(self.config.goal_still_open_m / self.map.resolution_m))
        window = (slice(max(r - k, 0), r + k + 1), slice(max(c - k, 0), c + k + 1))
        searched = None if self.map.searched is None else self.map.searched[window]
        return bool(unobserved(self.map.state[window], searched).any())

    def _path_blocked(self) -> bool:
        ahead = self.follower.remaining[:40]
        if len(ahead) == 0:
            return False
        res = self.map.resolution_m
        cols = np.floor((ahead[:, 0] - self.map.origin[0]) / res).astype(np.intp)
        rows = np.floor((ahead[:, 1] - self.map.origin[1]) / res).astype(np.intp)
        return bool(np.any(self.map.state[rows, cols] != MAPPED_FREE))

    # -- planning ----------------------------------------------------------------------------------------
    def options(self) -> PlanOptions:
        """What there is to choose from now: the planning window, the frontiers, a victim's path.

        A detected victim not yet visited that cannot be reached is marked visited here (the
        classical explorers give up on it).
        """
        pose = self.pose
        ctx = self._context(pose)
        victim = self.victims.next_target() if self.config.victim_approach_m is not None else None
        victim_path, victim_cost_m = None, math.nan
        if victim is not None:
            victim_path, victim_cost_m = self._to_victim(ctx, self.victims.positions[victim])
            if victim_path is None:
                self.victims.visited[victim] = True
                victim = None
        frontiers = find_frontiers(ctx.state, self._searched(ctx.box), self._min_cells)
        c = self.config
        drop = self._near(ctx, [pose[:2]], c.min_goal_m) | self._near(
            ctx, self.blacklist, c.blacklist_radius_m
        )
        return PlanOptions(ctx, frontiers.without(drop), victim, victim_path, victim_cost_m)

    def commit(
        self, options: PlanOptions, found: Found | None, to_victim: bool = False, frontier: bool = True
    ) -> None:
        """Drive to ``found`` from now on (``None``: nothing to go to).

        Args:
            options: What :meth:`options` gave.
            found: The chosen goal, a cell of ``options.ctx``'s window with a parent array that
                leads there from the robot; ``None`` if there is nothing to go to.
            to_victim: Whether ``found`` is the path to ``options.victim``.
            frontier: Whether the goal is a frontier, to be given up once it no longer borders
                unobserved space; ``False`` for a waypoint, kept until reached (or blocked).
        """
        self._frontier_goal = frontier
        self.plans += 1
        self._since_plan = 0
        self._new_cells = 0
        self._new_victims = 0
        self._victim = options.victim if to_victim else None
        self.finished = found is None and self._victim is None
        if found is None:
            self.follower.clear()
            self.goal = None
            return
        ctx = options.ctx
        cells = trace_path(found[1], found[0])
        points = self.map.to_world(cells[:, 0] + ctx.box.r0, cells[:, 1] + ctx.box.c0)
        goal = (float(points[-1, 0]), float(points[-1, 1]))
        if self.goal is None or math.dist(goal, self.goal) > self.config.blacklist_radius_m:
            self.reflexes.restart_progress()
            self._recoveries = 0
        self.goal = goal
        self.follower.set_path(points)

    def _context(self, pose: tuple[float, float, float]) -> PlanContext:
        k = self.map.known
        h, w = self.map.state.shape
        box = Box(max(k.r0 - 2, 0), min(k.r1 + 2, h), max(k.c0 - 2, 0), min(k.c1 + 2, w))
        state = self.map.state[box.slices]
        r, c = self.map.to_cell(pose[0], pose[1])
        res = self.map.resolution_m
        clear = clearance(state, res)
        cost = costmap(state, clear, res, self.spec.robot.radius_m, self.config.cost)
        todo = unobserved(state, self._searched(box))
        return PlanContext(box, state, todo, clear, cost, (r - box.r0, c - box.c0), pose, res)

    def _searched(self, box: Box) -> np.ndarray | None:
        return None if self.map.searched is None else self.map.searched[box.slices]

    def _near(self, ctx: PlanContext, points: list[tuple[float, float]], radius_m: float) -> np.ndarray:
        """Cells of the planning window within ``radius_m`` of any of ``points`` (square windows)."""
        out = np.zeros(ctx.state.shape, dtype=bool)
        k = math.ceil(radius_m / ctx.resolution_m)
        for x, y in points:
            r, c = self.map.to_cell(x, y)
            r, c = r - ctx.box.r0, c - ctx.box.c0
            out[max(r - k, 0) : max(r + k + 1, 0), max(c - k, 0) : max(c + k + 1, 0)] = True
        return out

    def _to_victim(self, ctx: PlanContext, xy: np.ndarray) -> tuple[Found | None, float]:
        """The path to within ``victim_approach_m`` of ``xy`` and its cost (m), or ``(None, nan)``."""
        rows, cols = np.indices(ctx.state.shape)
        centre = self.map.to_world(np.array([ctx.box.r0]), np.array([ctx.box.c0]))[0]
        d = np.hypot(centre[0] + cols * ctx.resolution_m - xy[0], centre[1] + rows * ctx.resolution_m - xy[1])
        goals = (d <= self.config.victim_approach_m) & np.isfinite(ctx.cost)
        dist, parent, goal = dijkstra(ctx.cost, ctx.start, goals, first_only=True)
        if goal < 0:
            return None, math.nan
        return (goal, parent), float(dist.ravel()[goal]) * ctx.resolution_m
