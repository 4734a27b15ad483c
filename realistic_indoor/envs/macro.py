"""Macro actions: the policy chooses where to go, the classical explorers' navigator drives there.

With ``action_type="frontier"`` an environment's action is an index into the K best candidate
goals (``Discrete(K)``, :attr:`MacroConfig.n_candidates`, 16 by default): in search the next
detected victim not yet visited, if one is reachable, then one goal per frontier component of
the robot's own map, nearest first by path cost. With ``action_type="waypoint"`` it is a cell
of a coarse grid around the robot (:class:`WaypointActions`), snapped to the nearest reachable
known free cell. The robot's :class:`~realistic_indoor.navigation.navigator.Navigator` (the
map, planner, follower and reflexes of the map-based explorers) plans a path to the chosen goal
and drives it, one primitive control step after another, until it would replan: the goal is
reached (or, for a frontier, no longer borders unobserved space), the path is blocked, the robot
bumped, a victim was newly detected, or ``replan_steps`` steps passed while the map grew. There
the environment asks for the next decision. A policy that always chooses frontier candidate 0
therefore drives exactly as the nearest-frontier explorer (``frontier``) does.

:meth:`MacroActions.action_masks` says which actions offer a goal (for sb3-contrib's
``MaskablePPO``); a masked choice is replaced by the first allowed action, candidate 0 for
frontiers (``info["fallback"]``). Where the navigator finds nothing to go to it does what the
classical explorer does, waiting and looking again every ``replan_steps`` steps, within the same
decision, until something appears or the episode ends.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, NamedTuple

import numpy as np
from gymnasium import spaces

from realistic_indoor.checks import require_int, require_positive
from realistic_indoor.envs.actions import discrete_index
from realistic_indoor.errors import ConfigError
from realistic_indoor.navigation.goals import nearest_points, off_circulation, unobserved_area_near
from realistic_indoor.navigation.navigator import ExplorerConfig, Found, Navigator, PlanOptions
from realistic_indoor.navigation.planning import dijkstra, nearest_labels
from realistic_indoor.navigation.regions import RegionConfig, find_regions
from realistic_indoor.navigation.spec import RobotSpec

__all__ = [
    "AREA_UNIT_M2",
    "CANDIDATE_FEATURES",
    "LENGTH_UNIT_M",
    "MACRO_ACTIONS",
    "MACRO_ACTION_TYPES",
    "Candidates",
    "FrontierActions",
    "MacroActions",
    "MacroConfig",
    "WaypointActions",
    "candidate_features",
    "rank_candidates",
]

MACRO_ACTION_TYPES = ("frontier", "waypoint")
"""Action types whose action chooses a goal rather than a velocity."""

CANDIDATE_FEATURES = (
    "valid",
    "path_cost",
    "distance",
    "cos_bearing",
    "sin_bearing",
    "size",
    "unobserved",
    "in_room",
    "victim",
)
"""Columns of the ``candidates`` observation, per candidate: 1 if it exists; path cost to it in
units of 10 m of clear floor; straight-line distance in units of 10 m; cosine and sine of its
bearing from the robot's heading; the frontier's length in units of 10 m; the largest unobserved
area within ``gain_radius_m`` (3 m) of its cells, in units of 10 m2; 1 if it lies off the
corridors and halls the robot has recognised on its map (the structure explorer's room
frontiers); 1 if it is a detected victim (whose frontier columns are 0). Lengths and areas are
capped at 100 units. Rows of candidates that do not exist are 0."""

LENGTH_UNIT_M = 10.0
"""Metres per unit of the length features of the ``candidates`` observation."""
AREA_UNIT_M2 = 10.0
"""Square metres per unit of the area feature of the ``candidates`` observation."""
_MAX_LENGTH = 100.0
"""Length features are capped at this many units (1 km): the observation space is bounded."""


@dataclass(frozen=True)
class MacroConfig:
    """Settings of the macro actions.

    Attributes:
        n_candidates: Candidate goals a decision chooses among (K of ``Discrete(K)``), >= 1.
        navigator: The navigator that drives to the chosen goal: the map-based explorers'
            settings (own map resolution, replanning, costmap, follower, getting unstuck).
        gain_radius_m: Half-side of the square around a frontier's cells whose unobserved area
            is its ``unobserved`` feature (m), as the utility explorer's area gain.
        regions: How corridors and halls are recognised on the map (the ``in_room`` feature),
            as the structure explorer does.
        reach_m: A frontier within this distance of a corridor's or hall's core is not in a
            room (m).
        waypoint_grid: Side of the ``"waypoint"`` actions' grid (cells; odd, >= 3: the robot
            stands in the middle cell); the action space is ``Discrete(waypoint_grid ** 2)``.
        waypoint_cell_m: Side of a cell of that grid (m).
    """

    n_candidates: int = 16
    navigator: ExplorerConfig = field(default_factory=ExplorerConfig)
    gain_radius_m: float = 3.0
    regions: RegionConfig = field(default_factory=RegionConfig)
    reach_m: float = 0.25
    waypoint_grid: int = 7
    waypoint_cell_m: float = 2.0

    def __post_init__(self) -> None:
        require_int("MacroConfig", "n_candidates", self.n_candidates, 1)
        require_int("MacroConfig", "waypoint_grid", self.waypoint_grid, 3)
        if self.waypoint_grid % 2 == 0:
            raise ConfigError(
                f"MacroConfig.waypoint_grid must be odd (the robot in the middle cell), got {self.waypoint_grid}"
            )
        require_positive("MacroConfig", "waypoint_cell_m", self.waypoint_cell_m, "m")
        require_positive("MacroConfig", "gain_radius_m", self.gain_radius_m, "m")
        require_positive("MacroConfig", "reach_m", self.reach_m, "m")
        if not isinstance(self.regions, RegionConfig):
            raise ConfigError(
                f"MacroConfig.regions must be a RegionConfig, got {type(self.regions).__name__}"
            )
        if not isinstance(self.navigator, ExplorerConfig):
            raise ConfigError(
                f"MacroConfig.navigator must be an ExplorerConfig, got {type(self.navigator).__name__}"
            )


class Candidates(NamedTuple):
    """The candidate goals of one decision, best first.

    Attributes:
        goals: Per candidate, the goal cell and the Dijkstra parent array that leads there.
        victim: Per candidate, whether it is a detected victim.
        xy: ``(n, 2)`` goal points (m, odometry frame).
        cost_m: ``(n,)`` path costs (m of clear floor).
        size_m: ``(n,)`` frontier lengths (m; 0 for a victim).
        unobserved_m2: ``(n,)`` unobserved area near each frontier (m2; 0 for a victim).
        in_room: ``(n,)`` bool: the frontier lies off the recognised corridors and halls.
    """

    goals: list[Found]
    victim: list[bool]
    xy: np.ndarray
    cost_m: np.ndarray
    size_m: np.ndarray
    unobserved_m2: np.ndarray
    in_room: np.ndarray

    @property
    def count(self) -> int:
        """Number of candidates."""
        return len(self.goals)


def rank_candidates(options: PlanOptions, config: MacroConfig, navigator: Navigator) -> Candidates:
    """The ``k`` best candidate goals of a decision: the victim to go to (if any), then frontiers.

    Frontiers are ranked by the path cost to their nearest cell, ties by that cell's index in
    the planning window: the order in which one Dijkstra search from the robot settles them
    (:func:`~realistic_indoor.navigation.planning.nearest_labels`, stopped at the ``k``-th), so
    candidate 0 is the nearest-frontier explorer's goal. Frontiers the robot cannot reach are
    not candidates.

    Args:
        options: What the navigator offers (:meth:`Navigator.options`).
        config: The number of candidates and how their features are measured.
        navigator: The navigator (its map turns cells into points).
    """
    ctx, k = options.ctx, config.n_candidates
    goals: list[Found] = []
    cells: list[int] = []
    costs: list[float] = []
    labels = np.zeros(0, dtype=np.int64)
    if options.victim is not None and options.victim_path is not None:
        goals.append(options.victim_path)
        cells.append(int(options.victim_path[0]))
        costs.append(options.victim_cost_m)
    n_victims = len(goals)
    frontiers = options.frontiers
    if frontiers.count and len(goals) < k:
        dist, parent, labels, nearest = nearest_labels(
            ctx.cost, ctx.start, frontiers.labels, frontiers.count, k - len(goals)
        )
        flat_dist = dist.ravel()
        goals.extend((cell, parent) for cell in nearest.tolist())
        cells.extend(nearest.tolist())
        costs.extend((flat_dist[nearest] * ctx.resolution_m).tolist())
    size, area, in_room = (np.zeros(len(goals)) for _ in range(3))
    if len(labels):
        res = ctx.resolution_m
        size[n_victims:] = frontiers.sizes[labels] * res
        area[n_victims:] = unobserved_area_near(frontiers, ctx, config.gain_radius_m)[labels - 1]
        regions = find_regions(ctx.state, ctx.clearance_m, res, config.regions)
        reach = max(1, round(config.reach_m / res))
        in_room[n_victims:] = off_circulation(frontiers, regions, reach)[labels - 1]
    w = ctx.state.shape[1]
    flat = np.array(cells, dtype=np.int64)
    xy = navigator.map.to_world(flat // w + ctx.box.r0, flat % w + ctx.box.c0).reshape(-1, 2)
    victim = [True] * n_victims + [False] * (len(goals) - n_victims)
    return Candidates(goals, victim, xy, np.array(costs, dtype=float), size, area, in_room.astype(bool))


def candidate_features(candidates: Candidates | None, pose: tuple[float, float, float], k: int) -> np.ndarray:
    """The ``candidates`` observation: ``(K * F,)`` float32, ``F = len(CANDIDATE_FEATURES)``.

    Row ``i`` of its ``(K, F)`` reshape describes candidate ``i`` (see
    :data:`CANDIDATE_FEATURES`); rows past the last candidate are zero; flat, as
    stable-baselines3's ``MultiInputPolicy`` expects.

    Args:
        candidates: The decision's candidates (``None``: no decision pending, all zero).
        pose: The robot's pose in the candidates' frame (m, m, rad).
        k: Number of rows, K (the action count).
    """
    out = np.zeros((k, len(CANDIDATE_FEATURES)), dtype=np.float32)
    c = candidates
    if c is None or c.count == 0:
        return out.ravel()
    x, y, heading = pose
    dx, dy = c.xy[:, 0] - x, c.xy[:, 1] - y
    bearing = np.arctan2(dy, dx) - heading
    n = c.count
    out[:n, 0] = 1.0
    out[:n, 1] = np.minimum(c.cost_m / LENGTH_UNIT_M, _MAX_LENGTH)
    out[:n, 2] = np.minimum(np.hypot(dx, dy) / LENGTH_UNIT_M, _MAX_LENGTH)
    out[:n, 3] = np.cos(bearing)
    out[:n, 4] = np.sin(bearing)
    out[:n, 5] = np.minimum(c.size_m / LENGTH_UNIT_M, _MAX_LENGTH)
    out[:n, 6] = np.minimum(c.unobserved_m2 / AREA_UNIT_M2, _MAX_LENGTH)
    out[:n, 7] = c.in_room
    out[:n, 8] = np.array(c.victim, dtype=np.float32)
    return out.ravel()


class MacroActions:
    """Macro actions of one environment: decisions, masks, the navigator (the shared part).

    The environment calls :meth:`reset` with its first observation, :meth:`choose` with each
    action, then :meth:`command` and :meth:`sense` once per primitive step until :meth:`sense`
    asks for a decision. A subclass says what the K actions offer (:meth:`_offer`).

    Args:
        spec: The robot (its action type is ``"continuous"``: the commands the navigator sends).
        config: The macro settings.
        k: Number of actions.

    Attributes:
        space: ``Discrete(k)``.
        navigator: The navigator that drives.
        candidates: The goals of the pending decision (``None`` when none is pending: only after
            a reset in which there was nothing to go to).
    """

    what = "macro action"
    """What an action is, for messages."""
    meaning = "an index into the goals offered"
    frontier_goals = True
    """Whether goals are frontiers (given up once no longer bordering unobserved space)."""

    def __init__(self, spec: RobotSpec, config: MacroConfig, k: int) -> None:
        self.spec = spec
        self.config = config
        self.k = k
        self.space = spaces.Discrete(k)
        self.navigator = Navigator(spec, config.navigator)
        self.candidates: Candidates | None = None
        self._mask = np.zeros(k, dtype=bool)
        self._options: PlanOptions | None = None

    def reset(self, obs: dict[str, np.ndarray], info: dict[str, Any]) -> None:
        """Start an episode at its first observation (the first decision is asked there)."""
        self.navigator.reset()
        self.candidates = self._options = None
        self.sense(obs, info)

    def sense(self, obs: dict[str, np.ndarray], info: dict[str, Any]) -> bool:
        """Take a primitive step's observation; whether a decision is now pending.

        Where the navigator wants a goal but no action offers one, it is told so at once (it
        waits, as the classical explorer does) and no decision is asked.
        """
        if not self.navigator.sense(obs, info):
            return False
        options = self.navigator.options()
        candidates, mask = self._offer(options)
        if not mask.any():
            self.navigator.commit(options, None)
            return False
        self.candidates, self._options, self._mask = candidates, options, mask
        return True

    def action_masks(self) -> np.ndarray:
        """``(K,)`` bool: which actions offer a goal now.

        With no decision pending (nothing to go to at the start), action 0 alone is allowed: it
        means "carry on".
        """
        if self.candidates is None:
            return np.arange(self.k) == 0
        return self._mask.copy()

    def choose(self, action: object) -> tuple[int, bool]:
        """Commit the navigator to the goal ``action`` chose.

        Returns:
            ``(action used, whether the chosen one was masked and replaced)``: a masked action
            is replaced by the first allowed one (candidate 0 for frontiers).

        Raises:
            ActionError: If ``action`` is not an integer in ``0..K-1``.
        """
        index = discrete_index(action, self.k, self.what, self.meaning)
        if self.candidates is None:
            return 0, index != 0
        fallback = not self._mask[index]
        used = int(np.argmax(self._mask)) if fallback else index
        self.navigator.commit(
            self._options,
            self.candidates.goals[used],
            to_victim=self.candidates.victim[used],
            frontier=self.frontier_goals,
        )
        self.candidates = self._options = None
        return used, fallback

    def command(self) -> np.ndarray:
        """The primitive (continuous) action of this step, as the explorer agents send it."""
        return self.spec.action(*self.navigator.command())

    def marks(self, start_pose: tuple[float, float, float]) -> dict[str, np.ndarray | None]:
        """The pending goals offered and the current goal in the plan's frame, for the top view.

        Args:
            start_pose: The episode's start ``(x m, y m, heading rad)`` in the plan's frame: the
                origin of the odometry frame the navigator works in.

        Returns:
            ``{"candidates_xy": (n, 2) or None, "goal_xy": (2,) or None}`` (m).
        """
        x0, y0, t0 = start_pose
        c, s = math.cos(t0), math.sin(t0)

        def to_plan(xy: np.ndarray) -> np.ndarray:
            xy = np.asarray(xy, dtype=float).reshape(-1, 2)
            return np.stack([x0 + c * xy[:, 0] - s * xy[:, 1], y0 + s * xy[:, 0] + c * xy[:, 1]], axis=1)

        goal = self.navigator.goal
        offered = None
        if self.candidates is not None:
            offered = to_plan(self.candidates.xy[self._mask[: len(self.candidates.xy)]])
        return {"candidates_xy": offered, "goal_xy": None if goal is None else to_plan(np.array(goal))[0]}

    def _offer(self, options: PlanOptions) -> tuple[Candidates, np.ndarray]:
        """The goals the K actions offer, and which actions offer one (``(K,)`` bool)."""
        raise NotImplementedError


class FrontierActions(MacroActions):
    """The ``"frontier"`` macro actions: the K best candidate goals (see the module docstring).

    Args:
        spec: The robot (its action type is ``"continuous"``).
        config: The macro settings (``n_candidates`` is K).
    """

    what = "frontier action"
    meaning = "an index into the candidate goals"

    def __init__(self, spec: RobotSpec, config: MacroConfig) -> None:
        super().__init__(spec, config, config.n_candidates)

    def _offer(self, options: PlanOptions) -> tuple[Candidates, np.ndarray]:
        candidates = rank_candidates(options, self.config, self.navigator)
        return candidates, np.arange(self.k) < candidates.count

    def features(self) -> np.ndarray:
        """The ``candidates`` observation of the pending decision (see :func:`candidate_features`)."""
        return candidate_features(self.candidates, self.navigator.pose, self.k)

    def features_space(self) -> spaces.Box:
        """The space of :meth:`features`."""
        low = np.zeros((self.k, len(CANDIDATE_FEATURES)), dtype=np.float32)
        low[:, 3:5] = -1.0
        high = np.full(low.shape, _MAX_LENGTH, dtype=np.float32)
        high[:, [0, 3, 4, 7, 8]] = 1.0
        return spaces.Box(low.ravel(), high.ravel(), dtype=np.float32)


class WaypointActions(MacroActions):
    """The ``"waypoint"`` macro actions: a cell of a coarse grid around the robot.

    The grid (``waypoint_grid`` x ``waypoint_grid`` cells of ``waypoint_cell_m``, 7 x 2 m by
    default) is centred on the robot and turned with the heading it started with: action ``i *
    G + j`` is row ``i`` (0 ahead, along the start heading) and column ``j`` (0 to the left), as
    the ``global_map`` observation draws the map. The cell's centre is snapped to the nearest
    known free cell the robot can reach (ties to the cheaper path); actions whose snapped goal
    lies within ``navigator.min_goal_m`` of the robot are masked. The navigator drives there
    and asks again when it arrives, is blocked or bumps, or when its map has grown (every
    ``replan_steps`` steps).

    Args:
        spec: The robot (its action type is ``"continuous"``).
        config: The macro settings.
    """

    what = "waypoint action"
    meaning = "a cell of the waypoint grid, row by row from ahead-left"
    frontier_goals = False

    def __init__(self, spec: RobotSpec, config: MacroConfig) -> None:
        super().__init__(spec, config, config.waypoint_grid**2)

    def targets(self) -> np.ndarray:
        """``(K, 2)`` the grid cells' centres around the robot (m, odometry frame)."""
        g, cell = self.config.waypoint_grid, self.config.waypoint_cell_m
        rows, cols = np.divmod(np.arange(g * g), g)
        x, y, _ = self.navigator.pose
        ahead = (g / 2 - rows - 0.5) * cell
        left = (g / 2 - cols - 0.5) * cell
        return np.stack([x + ahead, y + left], axis=1)

    def _offer(self, options: PlanOptions) -> tuple[Candidates, np.ndarray]:
        ctx = options.ctx
        dist, parent, _ = dijkstra(
            ctx.cost, ctx.start, np.zeros(ctx.cost.shape, dtype=bool), first_only=False
        )
        rows, cols = np.nonzero(np.isfinite(dist))
        points = self.navigator.map.to_world(rows + ctx.box.r0, cols + ctx.box.c0).reshape(-1, 2)
        nearest = nearest_points(points, self.targets(), dist[rows, cols])
        xy = points[nearest]
        flat = rows[nearest] * ctx.state.shape[1] + cols[nearest]
        x, y, _ = self.navigator.pose
        mask = np.hypot(xy[:, 0] - x, xy[:, 1] - y) >= self.config.navigator.min_goal_m
        goals = [(int(f), parent) for f in flat]
        zeros = np.zeros(self.k)
        cost = dist[rows[nearest], cols[nearest]] * ctx.resolution_m
        return Candidates(goals, [False] * self.k, xy, cost, zeros, zeros, zeros.astype(bool)), mask


MACRO_ACTIONS: dict[str, type[MacroActions]] = {"frontier": FrontierActions, "waypoint": WaypointActions}
"""The class of each macro action type."""
