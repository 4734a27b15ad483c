"""Exploration: drive a laser-equipped robot through a building until its map covers the floor."""

from __future__ import annotations

from typing import Any

import gymnasium as gym
import numpy as np
from gymnasium import spaces

from realistic_indoor.building.building import Building
from realistic_indoor.envs.actions import ActionMap
from realistic_indoor.envs.config import EnvConfig, require_reset_options, require_task_fields
from realistic_indoor.envs.macro import MACRO_ACTION_TYPES, MACRO_ACTIONS, MacroActions
from realistic_indoor.envs.observations import (
    TIME_LEFT_SPACE,
    GlobalMapObservation,
    explore_observations,
    time_left,
)
from realistic_indoor.envs.presets import base_config
from realistic_indoor.envs.rewards import auc_weight, reward_terms, weighted_sum
from realistic_indoor.envs.simulation import Simulation, StepOutcome
from realistic_indoor.envs.source import episode_building
from realistic_indoor.errors import ConfigError
from realistic_indoor.navigation.spec import RobotSpec

__all__ = ["ExploreEnv"]


class ExploreEnv(gym.Env):
    """Explore a building with a differential-drive robot, a 2D laser scanner and a map.

    ## Description

    A disc robot (compiled physics, or pymunk with ``robot={"physics": "pymunk"}``: it collides
    with the walls and slides along them) starts at
    the entrance of a building it has never seen. Each control step it drives with the
    commanded linear and angular velocity, takes a laser scan and adds it to its occupancy
    map. The goal is to observe the building's floor as fast as possible without bumping into
    walls. By default every episode runs in a new building drawn by a realistic generator
    (office, school, house) or the random baseline, from the episode's seed.

    ## Action Space

    With ``action_type="continuous"`` (default) the action is a ``ndarray`` of shape ``(2,)``
    in ``[-1, 1]``, scaled to the robot's limits. Finite values outside ``[-1, 1]`` are
    clipped to it; NaN, infinities and any other shape raise
    :class:`~realistic_indoor.errors.ActionError`:

    | Num | Action                  | Min | Max | Unit at 1                         |
    |-----|-------------------------|-----|-----|-----------------------------------|
    | 0   | Linear velocity command | -1  | 1   | ``robot.max_speed_m_s`` (m/s)      |
    | 1   | Turn rate command (CCW) | -1  | 1   | ``robot.max_turn_rate_rad_s`` (rad/s) |

    With ``action_type="discrete"`` it is ``Discrete(6)``: forward, forward-left, forward-right,
    turn left, turn right, back (see :data:`realistic_indoor.envs.actions.DISCRETE_ACTIONS`):
    an ``int``, a NumPy integer or a 0-d integer array in ``0..5``; anything else (``-1``,
    ``6``, ``2.9``, ``True``) raises :class:`~realistic_indoor.errors.ActionError`.
    The robot reaches a command as fast as its acceleration limits allow.

    With ``action_type="frontier"`` it is ``Discrete(macro.n_candidates)`` (16): a candidate goal
    (in search the next detected victim, then the reachable frontiers, nearest first), driven
    to by the map-based explorers' navigator until it would replan, over several primitive
    steps (:mod:`realistic_indoor.envs.macro`); :meth:`action_masks` says which candidates
    exist. Always choosing 0 drives as the nearest-frontier explorer does. With
    ``action_type="waypoint"`` it is ``Discrete(macro.waypoint_grid ** 2)`` (49): a cell of a
    grid around the robot, start heading up, snapped to reachable known floor.

    ## Observation Space

    A ``Dict``:

    | Key         | Shape            | Dtype   | Min            | Max           | Meaning                                         |
    |-------------|------------------|---------|----------------|---------------|-------------------------------------------------|
    | `scan`      | `(n_beams,)`     | float32 | 0              | 1             | laser ranges / ``max_range_m``, right to left   |
    | `local_map` | `(1, S, S)`      | uint8   | 0              | 255           | map image, robot at the centre heading up: 0 wall, 128 unknown, 255 free |
    | `velocity`  | `(2,)`           | float32 | -limits        | limits        | forward speed (m/s), turn rate (rad/s)          |
    | `pose`      | `(3,)`           | float32 | (-1000, -1000, -pi) | (1000, 1000, pi) | odometry: x (m) along the start heading, y (m) to its left, heading (rad), relative to the start pose |

    ``S`` is ``local_map.size_px`` (64 by default, 0.2 m per pixel: a 12.8 m square). The
    defaults give 109 beams over 270 degrees with a 10 m range. With ``action_type="frontier"``
    the dict adds ``candidates`` (``(K * 9,)`` float32: per candidate goal, whether it exists,
    its path cost and distance in units of 10 m, the cosine and sine of its bearing, its
    frontier length in units of 10 m, the unobserved area near it in units of 10 m2, whether it
    lies off the corridors and halls recognised on the map, whether it is a victim;
    :data:`~realistic_indoor.envs.macro.CANDIDATE_FEATURES`) and ``time_left`` (``(1,)``: the
    share of the step limit still to come). ``extra_observations=["global_map", "time_left"]``
    adds these in any mode: ``global_map`` is ``(4, S, S)`` uint8 (free, wall, unknown, visited
    channels of 0 or 255; the robot's whole map around it, start heading up, ``global_map.resolution_m``
    per pixel: :class:`~realistic_indoor.envs.observations.GlobalMapObservation`).

    ## Rewards

    The reward is a weighted sum of named terms (weights: ``EnvConfig.rewards``); the terms
    themselves are returned in ``info["rewards"]``:

    | Term        | Value                                         | Default weight |
    |-------------|-----------------------------------------------|----------------|
    | `new_area`  | reachable floor observed for the first time (m2) | 0.1 per m2  |
    | `collision` | 1 if the robot touched a wall during the step | -0.5           |
    | `time`      | 1 every step                                  | -0.01          |
    | `coverage_auc` | coverage gain x ``(max_steps + 1 - t) / (max_steps + 1)`` at step ``t`` (only if weighted) | 0 |

    With every weight 0 but ``coverage_auc`` (1), the undiscounted return is the episode's coverage
    AUC minus the coverage at reset. With macro actions a step's reward and ``info["rewards"]``
    sum its primitive steps'.

    ## Starting State

    The robot stands at rest and its map holds the first scan. Where it stands
    (:meth:`~realistic_indoor.sim.world.World.default_start_pose`, returned by ``reset`` as
    ``info["start_pose"]``):

    1. Just inside an entrance (a door to the outside), facing inward: on the door's centre
       line, at the first depth from 0.3 m (in 5 cm steps, up to 3 m) that is
       ``world.start_clearance_m`` (0.4 m) clear of walls. Entrances are tried in the plan's
       order, those of the building's main part first; the first with such a point wins.
    2. Without one (real plans often have no exterior door), in the largest hall of the main
       part, else in its largest room: at its centroid, or if that is not clear of walls, at
       the point farthest from its walls; facing +x (heading 0).
    3. Failing both, on the free cell farthest from any wall, facing +x.

    The main part is the set of rooms joined by doors that holds the most floor
    (:meth:`~realistic_indoor.sim.world.World.main_part`): a real plan may have rooms no door
    reaches, or separate flats.

    ## Episode End

    1. Termination: the map covers ``coverage_target`` (0.9 by default) of the reachable floor.
    2. Truncation: ``max_steps`` control steps have passed (also the registered
       ``max_episode_steps``).

    ## Arguments

    ``gym.make(id, **kwargs)`` and ``ExploreEnv(config, render_mode, preset, **kwargs)`` take
    any field of :class:`~realistic_indoor.envs.config.EnvConfig` as a keyword, overriding the
    preset's configuration:

    | Parameter         | Type                 | Default     | Description                                   |
    |-------------------|----------------------|-------------|-----------------------------------------------|
    | `config`          | `EnvConfig`          | preset      | the whole configuration (replaces the preset) |
    | `render_mode`     | `str` or `None`      | `None`      | `"rgb_array"`: a top view; `"human"`: it in a window |
    | `preset`          | `str` or `None`      | the id      | registered id whose configuration is the base (`gym.make` passes it) |
    | `source`          | `BuildingSource`     | preset      | where buildings come from: a building type (`"office"`, `"school"`, `"house"`, `"random"`), a `Building`, a plan file, an `rng -> Building` callable |
    | `building_type`   | `str`                | preset      | older keyword: the source's building type      |
    | `area_m2`         | `float`              | generator's | floor area asked of the generator (m2)        |
    | `generator_params` | mapping             | `{}`        | more options of the named generator           |
    | `generator`       | callable             | `None`      | older keyword: any `rng -> Building` generator |
    | `building`        | `Building`           | `None`      | older keyword: one fixed building for every episode |
    | `plan_path`       | path                 | `None`      | older keyword: a plan file run as a fixed building |
    | `world`           | `WorldConfig`        | 0.05 m      | raster (and map) resolution, wall thickness   |
    | `robot`           | `RobotConfig`        | 0.25 m disc | radius, limits, control rate (5 Hz), sub-steps |
    | `lidar`           | `LidarConfig`        | 109 beams   | field of view, beams, range (10 m), noise     |
    | `local_map`       | `LocalMapConfig`     | 64 px       | size and resolution of the map image          |
    | `rewards`         | `RewardWeights`      | see above   | weight of each reward term                    |
    | `coverage_target` | `float`              | 0.9         | coverage that ends the episode                |
    | `max_steps`       | `int`                | preset      | steps before truncation                       |
    | `action_type`     | `str`                | continuous  | `"continuous"`, `"discrete"`, `"frontier"` or `"waypoint"` |
    | `macro`           | `MacroConfig`        | 16 candidates | candidate goals per decision, navigator settings (`"frontier"` only) |
    | `extra_observations` | tuple of names    | `None`      | `global_map`, `candidates`, `time_left` (default: the latter two with macro actions) |
    | `global_map`      | `GlobalMapConfig`    | 64 px, 1 m    | size and pixel side of the `global_map` observation |

    ``victims`` (search only) is refused with a :class:`~realistic_indoor.errors.ConfigError`,
    as is any name that is not a field.

    ``reset(options={"building": b})`` runs that episode in building ``b``.

    ``render_mode="human"`` shows the top view in a pygame window (install the ``viz`` extra:
    ``pip install "realistic-indoor[viz]"``), drawn at every ``reset`` and ``step`` and
    paced at ``metadata["render_fps"]`` (the control rate: real time); ``close()`` closes it.

    ``info`` holds ``coverage`` (share of the reachable floor observed), ``observed_area_m2``,
    ``path_length_m`` (distance driven), ``collisions`` (steps with a wall contact); after
    ``reset``, ``start_pose``: ``(x m, y m, heading rad)`` of the robot's start in the plan's
    frame (the building's coordinates, heading counter-clockwise from +x); after a step,
    ``rewards``. With macro actions a step's ``info`` adds ``primitive_steps`` (control steps
    the decision took), ``steps`` (control steps so far), ``choice`` (the candidate driven to)
    and ``fallback`` (whether the chosen action was masked and candidate 0 taken instead).

    ```python
    >>> import gymnasium as gym
    >>> import realistic_indoor.envs
    >>> env = gym.make("OfficeExplore-v0", area_m2=400.0)
    >>> obs, info = env.reset(seed=0)
    >>> sorted(obs)
    ['local_map', 'pose', 'scan', 'velocity']

    ```

    ## Version History

    * v0: Initial version.
    """

    metadata = {"render_modes": ["human", "rgb_array"], "render_fps": 5}
    reset_options: frozenset[str] = frozenset({"building"})
    """Keys ``reset(options=...)`` accepts."""
    task = "explore"
    """The task, for the config fields only one task uses (:data:`~realistic_indoor.envs.config.TASK_FIELDS`)."""

    def __init__(
        self,
        config: EnvConfig | None = None,
        render_mode: str | None = None,
        preset: str | None = None,
        **overrides: Any,
    ) -> None:
        self.config = base_config(config, preset).replace(**overrides)
        require_task_fields(self.config, self.task, overrides)
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ConfigError(
                f"render_mode must be one of {self.metadata['render_modes']} or None, got {render_mode!r}"
            )
        self.render_mode = render_mode
        self.metadata = {**self.metadata, "render_fps": self.config.robot.control_hz}
        self._source = self.config.source.generator()
        self._sim = self._make_simulation()
        macro = self.config.action_type in MACRO_ACTION_TYPES
        self._actions = ActionMap(
            "continuous" if macro else self.config.action_type,
            self.config.robot.max_speed_m_s,
            self.config.robot.max_turn_rate_rad_s,
        )
        self._observations = self._make_observations()
        self._macro = self._make_macro() if macro else None
        self.action_space = self._actions.space if self._macro is None else self._macro.space
        self._extras = self.config.observation_extras
        self._global_map = GlobalMapObservation(self.config) if "global_map" in self._extras else None
        obs_spaces = {k: o.space for k, o in self._observations.items()}
        if self._global_map is not None:
            obs_spaces["global_map"] = self._global_map.space
        if "candidates" in self._extras:
            obs_spaces["candidates"] = self._macro.features_space()
        if "time_left" in self._extras:
            obs_spaces["time_left"] = TIME_LEFT_SPACE
        self.observation_space = spaces.Dict(obs_spaces)
        self._steps = 0
        self._coverage = 0.0
        self._window = None

    # -- the Gymnasium API ----------------------------------------------------------------------
    def reset(
        self, *, seed: int | None = None, options: dict[str, Any] | None = None
    ) -> tuple[dict[str, np.ndarray], dict[str, Any]]:
        """Start an episode in a new building (drawn from the seed) or in ``options["building"]``.

        Returns:
            The first observation and ``info``, which adds to a step's info ``start_pose``:
            ``(x m, y m, heading rad)`` where the robot starts, in the plan's frame.
        """
        super().reset(seed=seed)
        options = require_reset_options(options, self.reset_options)
        building = options.get("building")
        drawn = building is None
        self._sim.load(episode_building(self._source(self.np_random) if drawn else building, given=not drawn))
        self._reset_simulation(options)
        self._steps = 0
        self._coverage = self._sim.map.coverage
        info = self._info()
        info["start_pose"] = self._sim.world.start_pose
        obs = self._observe()
        if self._macro is not None:
            self._macro.reset(obs, info)
        if self.render_mode == "human":
            self.render()
        return self._with_extras(obs), info

    def step(
        self, action: np.ndarray | int
    ) -> tuple[dict[str, np.ndarray], float, bool, bool, dict[str, Any]]:
        """Drive one control step, scan, map; return observation, reward, end flags and info.

        Raises:
            ActionError: If ``action`` is not in the action space (NaN or infinite, wrongly
                shaped, or a discrete action that is not an integer in ``0..5``).
        """
        if self._sim.world is None:
            raise gym.error.ResetNeeded("call reset() before step()")
        if self._macro is not None:
            return self._macro_step(action)
        obs, reward, terminated, truncated, info = self._primitive_step(action)
        return self._with_extras(obs), reward, terminated, truncated, info

    def action_masks(self) -> np.ndarray:
        """Which actions are valid now, as sb3-contrib's ``MaskablePPO`` asks.

        Returns:
            With ``action_type="frontier"``, ``(K,)`` bool: the candidate goals that exist
            (:meth:`~realistic_indoor.envs.macro.FrontierActions.action_masks`); with primitive
            actions, every action (all ``True``: ``(6,)`` discrete, ``(2,)`` continuous).
        """
        if self._macro is not None:
            return self._macro.action_masks()
        return np.ones(self.action_space.shape or (int(self.action_space.n),), dtype=bool)

    def _primitive_step(
        self, action: np.ndarray | int
    ) -> tuple[dict[str, np.ndarray], float, bool, bool, dict[str, Any]]:
        """One control step with a velocity action (continuous or discrete); the task's own observation."""
        v, w = self._actions.command(action)
        outcome = self._sim.step(v, w, self.np_random)
        self._steps += 1
        terms = self._reward_terms(outcome)
        if self.config.rewards.coverage_auc != 0.0:
            coverage = self._sim.map.coverage
            terms["coverage_auc"] = (coverage - self._coverage) * auc_weight(
                self._steps, self.config.max_steps
            )
            self._coverage = coverage
        reward = weighted_sum(self.config.rewards, terms)
        terminated = self._terminated()
        truncated = self._steps >= self.config.max_steps
        info = self._info()
        info["rewards"] = terms
        if self.render_mode == "human":
            self.render()
        return self._observe(), reward, terminated, truncated, info

    def _macro_step(self, action: object) -> tuple[dict[str, np.ndarray], float, bool, bool, dict[str, Any]]:
        """One decision: commit to the chosen goal, then drive primitive steps to the next decision."""
        macro = self._macro
        chosen, fallback = macro.choose(action)
        reward, steps, totals = 0.0, 0, {}
        while True:
            obs, r, terminated, truncated, info = self._primitive_step(macro.command())
            reward += r
            steps += 1
            for name, value in info["rewards"].items():
                totals[name] = totals.get(name, 0.0) + value
            if terminated or truncated or macro.sense(obs, info):
                break
        info["rewards"] = totals
        info["primitive_steps"] = steps
        info["steps"] = self._steps
        info["choice"] = chosen
        info["fallback"] = fallback
        return self._with_extras(obs), reward, terminated, truncated, info

    def _with_extras(self, obs: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
        """The task's observation with the extra keys in force (``EnvConfig.observation_extras``)."""
        if not self._extras:
            return obs
        obs = dict(obs)
        if self._global_map is not None:
            obs["global_map"] = self._global_map.observe(self._sim)
        if "candidates" in self._extras:
            obs["candidates"] = self._macro.features()
        if "time_left" in self._extras:
            obs["time_left"] = time_left(self._steps, self.config.max_steps)
        return obs

    def _make_macro(self) -> MacroActions:
        """The macro actions and their navigator, for the robot the observations describe."""
        victims = self.config.victims if "victims" in self._observations else None
        spec = RobotSpec(self.config.lidar, self.config.robot, victims, "continuous")
        return MACRO_ACTIONS[self.config.action_type](spec, self.config.macro)

    def render(self) -> np.ndarray | None:
        """A top view of the episode: the plan, the robot's map, the trajectory, the scan, the robot.

        Returns:
            With ``render_mode="rgb_array"``, an ``(H, W, 3)`` uint8 image; with ``"human"``,
            ``None``, the image being shown in a pygame window (``reset`` and ``step`` call
            this themselves).

        Raises:
            DependencyNotInstalled: If ``render_mode="human"`` and pygame is not installed
                (``pip install "realistic-indoor[viz]"``).
        """
        if self.render_mode is None:
            gym.logger.warn('render() needs a render mode: gym.make(..., render_mode="rgb_array")')
            return None
        if self._sim.world is None:
            raise gym.error.ResetNeeded("call reset() before render()")
        from realistic_indoor.envs.render import top_view

        victims = self.victims
        marks = self._macro.marks(self._sim.world.start_pose) if self._macro is not None else {}
        frame = top_view(self._sim, *(victims or (None, None)), **marks)
        if self.render_mode == "rgb_array":
            return frame
        if self._window is None:
            from realistic_indoor.envs.window import Window

            title = f"realistic-indoor: {self.spec.id if self.spec else type(self).__name__}"
            self._window = Window(title, self.metadata["render_fps"])
        self._window.show(frame)
        return None

    def close(self) -> None:
        """Close the window of ``render_mode="human"``, if one is open."""
        if self._window is not None:
            self._window.close()
            self._window = None
        super().close()

    def __getstate__(self) -> dict[str, Any]:
        """The state to pickle: all but the window (a copy opens its own when it renders)."""
        return {**self.__dict__, "_window": None}

    # -- state a user may inspect --------------------------------------------------------------------
    @property
    def building(self) -> Building | None:
        """The building of the current episode (``None`` before the first reset)."""
        return self._sim.building

    @property
    def simulation(self) -> Simulation:
        """The world, robot, laser and map of the current episode (read them, don't change them)."""
        return self._sim

    @property
    def victims(self) -> tuple[np.ndarray, np.ndarray] | None:
        """Positions and found flags of the victims; ``None``: exploration has none."""
        return None

    # -- hooks a task overrides ------------------------------------------------------------------------
    def _make_simulation(self) -> Simulation:
        """The task's simulation (exploration: no victims)."""
        return Simulation(self.config)

    def _make_observations(self) -> dict[str, Any]:
        return explore_observations(self.config)

    def _reset_simulation(self, options: dict[str, Any]) -> None:
        """Start the simulation's episode, with what the task takes from ``reset``'s options."""
        self._sim.reset(self.np_random)

    def _reward_terms(self, outcome: StepOutcome) -> dict[str, float]:
        """The reward terms of a step, from what the simulation's step reported.

        The simulation senses and finds; this only reads its outcome, so overriding it changes
        rewards, never what the robot finds.
        """
        return reward_terms(outcome.new_area_m2, outcome.collided, outcome.victims_found)

    def _terminated(self) -> bool:
        return bool(self.config.explored(self._sim.map.coverage))

    def _info(self) -> dict[str, Any]:
        sim = self._sim
        return {
            "coverage": sim.map.coverage,
            "observed_area_m2": sim.map.observed_area_m2,
            "path_length_m": sim.path_length_m,
            "collisions": sim.collisions,
        }

    def _observe(self) -> dict[str, np.ndarray]:
        return {name: part.observe(self._sim) for name, part in self._observations.items()}
