"""The map-based explorer loop that frontier agents share: map, choose a goal, plan, follow, repeat.

Each step the agent adds the scan to its own map (:class:`OwnMap`), then keeps its plan or makes
a new one, and steers along the path. It replans when the path is done, when its goal is no
longer a frontier, when the path runs into a newly seen obstacle, after a collision, and when
the map has grown enough since the last plan. A goal the robot cannot get closer to is
blacklisted. In victim search, a victim the sensor detects becomes the next goal: the robot goes
to it, then resumes exploring. Subclasses only choose the goal among the frontiers.
"""

from __future__ import annotations

import math
from abc import abstractmethod
from dataclasses import dataclass, field
from typing import Any, NamedTuple

import numpy as np

from realistic_indoor.agents.base import Agent, RobotSpec
from realistic_indoor.agents.follower import FollowerConfig, PathFollower
from realistic_indoor.agents.frontiers import Frontiers, find_frontiers, unobserved
from realistic_indoor.agents.occupancy import Box, OwnMap
from realistic_indoor.agents.planning import CostConfig, clearance, costmap, dijkstra, trace_path
from realistic_indoor.agents.reflexes import Reflexes
from realistic_indoor.agents.victims import VictimTracker
from realistic_indoor.checks import require_int, require_positive
from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.lidar import beam_offsets
from realistic_indoor.sim.mapping import MAPPED_FREE

__all__ = ["ExplorerConfig", "MapExplorer", "PlanContext"]

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


class MapExplorer(Agent):
    """Base of the frontier explorers: the map, plan, follow loop (see the module docstring).

    Args:
        spec: The robot's sensors and limits.
        config: Explorer settings.

    Attributes:
        map: The agent's own map.
        victims: Victims detected (search only; empty in exploration).
        finished: Whether the last plan found no reachable frontier (exploration is over).
    """

    def __init__(self, spec: RobotSpec, config: ExplorerConfig | None = None) -> None:
        super().__init__(spec)
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

    def reset(self, seed: int | None = None) -> None:
        """Forget the map, the plan, the blacklist and the victims."""
        self.map.reset()
        self.victims.reset()
        self.follower.clear()
        self.blacklist: list[tuple[float, float]] = []
        self.finished = False
        self._goal: tuple[float, float] | None = None
        self._victim: int | None = None
        self._since_plan = 0
        self._new_cells = 0
        self._recoveries = 0
        self.reflexes.reset()

    # -- the loop ----------------------------------------------------------------------------------------
    def act(self, obs: dict[str, np.ndarray], info: dict[str, Any]) -> np.ndarray | int:
        """Map the scan, replan if needed, and return the action that follows the path."""
        pose = (float(obs["pose"][0]), float(obs["pose"][1]), float(obs["pose"][2]))
        ranges = np.asarray(obs["scan"], dtype=np.float32) * np.float32(self.spec.lidar.max_range_m)
        reflexes = self.reflexes
        collided = reflexes.bumped(pose, ranges, float(obs["velocity"][0]), info)
        self._new_cells += self.map.integrate(pose, ranges, self.spec.robot.radius_m)
        self._since_plan += 1
        if "victims" in obs and self.config.victim_approach_m is not None:
            self.victims.observe(pose, obs["victims"])
        if reflexes.backing:
            v, w = reflexes.back_up()
        elif reflexes.jammed:
            self._recover(pose)
            v, w = 0.0, 0.0
        elif reflexes.stuck:
            self._give_up(pose)
            v, w = 0.0, 0.0
        else:
            if collided or self._needs_plan(pose):
                self._plan(pose)
            v, w = self.follower.command(pose, reflexes.clearance_ahead(ranges))
            if self.follower.blocked:
                w = reflexes.turn_away(ranges)
        reflexes.record(pose, collided, self.follower.blocked, self.follower.turning)
        return self.spec.action(v, w)

    def _needs_plan(self, pose: tuple[float, float, float]) -> bool:
        c = self.config
        if self.finished:
            return self._since_plan >= c.replan_steps
        if self.follower.done(pose):
            if self._victim is not None:
                self.victims.visited[self._victim] = True
            return True
        if self._victim is None and (self._goal is None or not self._goal_open()):
            return True
        if self._path_blocked():
            return True
        if self._victim is None and self.victims.next_target() is not None:
            return True
        grown = self._new_cells * self.map.resolution_m**2 >= c.replan_new_m2
        return self._since_plan >= c.replan_steps and grown

    def _give_up(self, pose: tuple[float, float, float]) -> None:
        """No progress towards the goal: blacklist it (or mark the victim visited) and back up."""
        if self._victim is not None:
            self.victims.visited[self._victim] = True
        elif self._goal is not None:
            self.blacklist.append(self._goal)
        self._recover(pose)
        self.reflexes.restart_progress()

    def _recover(self, pose: tuple[float, float, float]) -> None:
        """Back up a little and replan; a goal that needed this too often is blacklisted."""
        self._recoveries += 1
        if self._recoveries > _MAX_RECOVERIES and self._victim is None and self._goal is not None:
            self.blacklist.append(self._goal)
            self._recoveries = 0
        self.follower.clear()
        self.reflexes.start_backup(pose)

    def _goal_open(self) -> bool:
        r, c = self.map.to_cell(*self._goal)
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
    def _plan(self, pose: tuple[float, float, float]) -> None:
        self._since_plan = 0
        self._new_cells = 0
        ctx = self._context(pose)
        self._victim = self.victims.next_target() if self.config.victim_approach_m is not None else None
        if self._victim is not None:
            found = self._to_victim(ctx, self.victims.positions[self._victim])
            if found is None:
                self.victims.visited[self._victim] = True
                self._victim = None
        else:
            found = None
        if found is None:
            frontiers = find_frontiers(ctx.state, self._searched(ctx.box), self._min_cells)
            c = self.config
            drop = self._near(ctx, [pose[:2]], c.min_goal_m) | self._near(
                ctx, self.blacklist, c.blacklist_radius_m
            )
            frontiers = frontiers.without(drop)
            found = self._choose(frontiers, ctx) if frontiers.count else None
        self.finished = found is None and self._victim is None
        if found is None:
            self.follower.clear()
            self._goal = None
            return
        cells = trace_path(found[1], found[0])
        points = self.map.to_world(cells[:, 0] + ctx.box.r0, cells[:, 1] + ctx.box.c0)
        goal = (float(points[-1, 0]), float(points[-1, 1]))
        if self._goal is None or math.dist(goal, self._goal) > self.config.blacklist_radius_m:
            self.reflexes.restart_progress()
            self._recoveries = 0
        self._goal = goal
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

    def _to_victim(self, ctx: PlanContext, xy: np.ndarray) -> tuple[int, np.ndarray] | None:
        rows, cols = np.indices(ctx.state.shape)
        centre = self.map.to_world(np.array([ctx.box.r0]), np.array([ctx.box.c0]))[0]
        d = np.hypot(centre[0] + cols * ctx.resolution_m - xy[0], centre[1] + rows * ctx.resolution_m - xy[1])
        goals = (d <= self.config.victim_approach_m) & np.isfinite(ctx.cost)
        _, parent, goal = dijkstra(ctx.cost, ctx.start, goals, first_only=True)
        return None if goal < 0 else (goal, parent)

    @abstractmethod
    def _choose(self, frontiers: Frontiers, ctx: PlanContext) -> tuple[int, np.ndarray] | None:
        """Pick the goal among the frontiers.

        Returns:
            ``(flat index of the goal cell in the window, parent array of a Dijkstra from the
            robot)``, or ``None`` if no frontier is reachable.
        """
