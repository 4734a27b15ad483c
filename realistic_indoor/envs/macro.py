"""Macro actions: the policy chooses where to go, the classical explorers' navigator drives there.

With ``action_type="frontier"`` an environment's action is an index into the K best candidate
goals (``Discrete(K)``, :attr:`MacroConfig.n_candidates`, 16 by default): in search the next
detected victim not yet visited, if one is reachable, then one goal per frontier component of
the robot's own map, nearest first by path cost. The robot's
:class:`~realistic_indoor.navigation.navigator.Navigator` (the map, planner, follower and
reflexes of the map-based explorers) plans a path to the chosen goal and drives it, one
primitive control step after another, until it would replan: the goal is reached or no longer
borders unobserved space, the path is blocked, the robot bumped, a victim was newly detected, or
``replan_steps`` steps passed while the map grew. There the environment asks for the next
decision. A policy that always chooses 0 therefore drives exactly as the nearest-frontier
explorer (``frontier``) does.

:meth:`FrontierActions.action_masks` says which candidates exist (for sb3-contrib's
``MaskablePPO``); a masked choice is replaced by candidate 0 (``info["fallback"]``). Where the
navigator finds nothing to go to it does what the classical explorer does, waiting and looking
again every ``replan_steps`` steps, within the same decision, until something appears or the
episode ends.
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
from realistic_indoor.navigation.goals import off_circulation, unobserved_area_near
from realistic_indoor.navigation.navigator import ExplorerConfig, Found, Navigator, PlanOptions
from realistic_indoor.navigation.planning import nearest_labels, trace_path
from realistic_indoor.navigation.regions import RegionConfig, find_regions
from realistic_indoor.navigation.spec import RobotSpec

__all__ = [
    "CANDIDATE_FEATURES",
    "MACRO_ACTION_TYPES",
    "Candidates",
    "FrontierActions",
    "MacroConfig",
    "rank_candidates",
]

MACRO_ACTION_TYPES = ("frontier",)
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

_LENGTH_UNIT_M = 10.0
"""Metres per unit of the length features of the ``candidates`` observation."""
_AREA_UNIT_M2 = 10.0
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
    """

    n_candidates: int = 16
    navigator: ExplorerConfig = field(default_factory=ExplorerConfig)
    gain_radius_m: float = 3.0
    regions: RegionConfig = field(default_factory=RegionConfig)
    reach_m: float = 0.25

    def __post_init__(self) -> None:
        require_int("MacroConfig", "n_candidates", self.n_candidates, 1)
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
        goal, parent = options.victim_path
        goals.append(options.victim_path)
        cells.append(int(goal))
        costs.append(_path_cost_m(ctx, parent, goal))
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


def _path_cost_m(ctx: Any, parent: np.ndarray, goal: int) -> float:
    """Path cost (m of clear floor) of the path to ``goal``: recomputed along the traced cells."""
    cells = trace_path(parent, goal)
    steps = np.hypot(*np.diff(cells, axis=0).T)
    return float(np.sum(steps * ctx.cost[cells[1:, 0], cells[1:, 1]]) * ctx.resolution_m)


class FrontierActions:
    """The ``"frontier"`` macro actions of one environment: candidates, masks, the navigator.

    The environment calls :meth:`reset` with its first observation, :meth:`choose` with each
    action, then :meth:`command` and :meth:`sense` once per primitive step until :meth:`sense`
    asks for a decision.

    Args:
        spec: The robot (its action type is ``"continuous"``: the commands the navigator sends).
        config: The macro settings.

    Attributes:
        space: ``Discrete(n_candidates)``.
        navigator: The navigator that drives.
        candidates: The candidates of the pending decision (``None`` when none is pending: only
            after a reset in which there was nothing to go to).
    """

    def __init__(self, spec: RobotSpec, config: MacroConfig) -> None:
        self.spec = spec
        self.config = config
        self.k = config.n_candidates
        self.space = spaces.Discrete(self.k)
        self.navigator = Navigator(spec, config.navigator)
        self.candidates: Candidates | None = None
        self._options: PlanOptions | None = None

    def reset(self, obs: dict[str, np.ndarray], info: dict[str, Any]) -> None:
        """Start an episode at its first observation (the first decision is asked there)."""
        self.navigator.reset()
        self.candidates = self._options = None
        self.sense(obs, info)

    def sense(self, obs: dict[str, np.ndarray], info: dict[str, Any]) -> bool:
        """Take a primitive step's observation; whether a decision is now pending.

        Where the navigator wants a goal but there is no candidate, it is told so at once (it
        waits, as the classical explorer does) and no decision is asked.
        """
        if not self.navigator.sense(obs, info):
            return False
        options = self.navigator.options()
        candidates = rank_candidates(options, self.config, self.navigator)
        if candidates.count == 0:
            self.navigator.commit(options, None)
            return False
        self.candidates, self._options = candidates, options
        return True

    def action_masks(self) -> np.ndarray:
        """``(K,)`` bool: which actions choose a candidate that exists.

        With no decision pending (nothing to go to at the start), action 0 alone is allowed: it
        means "carry on".
        """
        mask = np.zeros(self.k, dtype=bool)
        mask[: self.candidates.count if self.candidates is not None else 1] = True
        return mask

    def choose(self, action: object) -> tuple[int, bool]:
        """Commit the navigator to the candidate ``action`` chose.

        Returns:
            ``(candidate index used, whether the choice was masked and replaced by 0)``.

        Raises:
            ActionError: If ``action`` is not an integer in ``0..K-1``.
        """
        index = discrete_index(action, self.k, "frontier action", "an index into the candidate goals")
        if self.candidates is None:
            return 0, index != 0
        fallback = index >= self.candidates.count
        used = 0 if fallback else index
        self.navigator.commit(
            self._options, self.candidates.goals[used], to_victim=self.candidates.victim[used]
        )
        self.candidates = self._options = None
        return used, fallback

    def command(self) -> np.ndarray:
        """The primitive (continuous) action of this step, as the explorer agents send it."""
        return self.spec.action(*self.navigator.command())

    def marks(self, start_pose: tuple[float, float, float]) -> dict[str, np.ndarray | None]:
        """The pending candidates and the current goal in the plan's frame, for the top view.

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
        return {
            "candidates_xy": None if self.candidates is None else to_plan(self.candidates.xy),
            "goal_xy": None if goal is None else to_plan(np.array(goal))[0],
        }

    def features(self) -> np.ndarray:
        """The ``candidates`` observation: ``(K * F,)`` float32, ``F = len(CANDIDATE_FEATURES)``.

        Row ``i`` of its ``(K, F)`` reshape describes candidate ``i`` (see
        :data:`CANDIDATE_FEATURES`); flat, as stable-baselines3's ``MultiInputPolicy`` expects.
        """
        out = np.zeros((self.k, len(CANDIDATE_FEATURES)), dtype=np.float32)
        c = self.candidates
        if c is None or c.count == 0:
            return out.ravel()
        x, y, heading = self.navigator.pose
        dx, dy = c.xy[:, 0] - x, c.xy[:, 1] - y
        bearing = np.arctan2(dy, dx) - heading
        n = c.count
        out[:n, 0] = 1.0
        out[:n, 1] = np.minimum(c.cost_m / _LENGTH_UNIT_M, _MAX_LENGTH)
        out[:n, 2] = np.minimum(np.hypot(dx, dy) / _LENGTH_UNIT_M, _MAX_LENGTH)
        out[:n, 3] = np.cos(bearing)
        out[:n, 4] = np.sin(bearing)
        out[:n, 5] = np.minimum(c.size_m / _LENGTH_UNIT_M, _MAX_LENGTH)
        out[:n, 6] = np.minimum(c.unobserved_m2 / _AREA_UNIT_M2, _MAX_LENGTH)
        out[:n, 7] = c.in_room
        out[:n, 8] = np.array(c.victim, dtype=np.float32)
        return out.ravel()

    def features_space(self) -> spaces.Box:
        """The space of :meth:`features`."""
        low = np.zeros((self.k, len(CANDIDATE_FEATURES)), dtype=np.float32)
        low[:, 3:5] = -1.0
        high = np.full(low.shape, _MAX_LENGTH, dtype=np.float32)
        high[:, [0, 3, 4, 7, 8]] = 1.0
        return spaces.Box(low.ravel(), high.ravel(), dtype=np.float32)
