"""Robot teams as a PettingZoo ``ParallelEnv``: every registered id, several robots in one building."""

from __future__ import annotations

from typing import Any

import gymnasium as gym
import numpy as np
from gymnasium import spaces
from gymnasium.utils import seeding
from pettingzoo import ParallelEnv

from realistic_indoor.envs.actions import ActionMap
from realistic_indoor.envs.observations import batch_observations, explore_observations, mark_points
from realistic_indoor.envs.presets import preset_config
from realistic_indoor.envs.render import Scene, draw_team
from realistic_indoor.envs.rewards import reward_terms, weighted_sum
from realistic_indoor.envs.search import VictimObservation, given_victims
from realistic_indoor.envs.source import episode_building
from realistic_indoor.errors import ActionError, ConfigError
from realistic_indoor.sim.lidar import beam_offsets
from realistic_indoor.teams.config import TeamConfig
from realistic_indoor.teams.observations import (
    base_space,
    observe_team,
    state_space,
    teammates_space,
)
from realistic_indoor.teams.simulation import TeamSimulation

__all__ = ["TeamParallelEnv"]


class TeamParallelEnv(ParallelEnv):
    """A team of robots exploring (or searching) one building, on PettingZoo's parallel API.

    The task of the registered id (``OfficeExplore-v0``, ``OfficeSearch-v0``, ...) with its
    configuration and keywords, as ``gym.make`` takes them, run by ``n_robots`` robots in one
    building: they start at the entrance beside a base station
    (:mod:`~realistic_indoor.teams.starts`), collide with the walls and each other, and share
    what their links (:mod:`~realistic_indoor.teams.links`) and the map sharing
    (:mod:`~realistic_indoor.teams.maps`) allow. See docs/teams.md.

    - **Agents**: ``robot_0``, ``robot_1``, ...; all act every step and all end together.
    - **Actions**: the single environment's primitive actions (``continuous``: ``Box(-1, 1,
      (2,))``, or ``discrete``: ``Discrete(6)``); macro actions are the agent's own business
      (run the navigator per robot on its side).
    - **Observations**: the single environment's (``scan``, ``local_map`` of the robot's map,
      ``velocity``, ``pose``: odometry from the robot's own start; search adds ``victims``),
      plus ``teammates`` and ``base`` (:mod:`~realistic_indoor.teams.observations`).
    - **Rewards**: each robot's weighted terms, as the single environment's: the floor its scan
      added to its own map, its contacts (walls or teammates), time, and in search the victims
      it found first.
    - **Episode end**: exploration ends when the team map covers ``coverage_target`` of the
      reachable floor; search when every victim is found (by anyone); both are truncated at the
      configuration's ``max_steps`` (the id's step limit by default).
    - **state()**: the team map around the base station, robot 0's start heading up: ``(4, S,
      S)`` uint8 channels free, wall, unknown, robots (``global_map``'s size and pixel).
    - **info** (per agent): ``coverage`` and ``observed_area_m2`` of the team, ``own_coverage``,
      ``path_length_m``, ``collisions``, ``linked_to_base``, ``messages`` and ``map_cells_sent``
      (team totals this episode), ``rewards`` after a step, ``start_pose`` after a reset; search
      adds ``victims_found``, ``victims_total`` and ``victims_reported`` (findings that reached
      the base through the links).
    - **reset options**: ``building`` (a fixed building) and, in search, ``victims``; others
      are ignored (PettingZoo's API test passes one of its own).

    Args:
        env_id: A registered id.
        n_robots: Robots, an integer in [1, :data:`~realistic_indoor.teams.config.MAX_ROBOTS`].
        comm: The link model or its name (:data:`~realistic_indoor.teams.links.COMM_MODELS`).
        map_sharing: ``"shared"``, ``"own"`` or ``"comm"``.
        render_mode: ``None`` or ``"rgb_array"``.
        **kwargs: Fields of :class:`~realistic_indoor.envs.config.EnvConfig`, as ``gym.make``.

    Raises:
        ConfigError: For an unknown id, a bad keyword or team setting, macro actions, extra
            observations, the ``coverage_auc`` term or pymunk physics.
    """

    metadata = {"render_modes": ["rgb_array"], "name": "realistic_indoor_team_v0", "is_parallelizable": True}

    def __init__(
        self,
        env_id: str,
        n_robots: int = 2,
        comm: Any = "wss",
        map_sharing: str = "comm",
        render_mode: str | None = None,
        **kwargs: Any,
    ) -> None:
        self.team = TeamConfig(n_robots=n_robots, comm=comm, map_sharing=map_sharing)
        self.config = preset_config(env_id, **kwargs)
        _require_team_config(self.config)
        if render_mode not in (None, "rgb_array"):
            raise ConfigError(f"render_mode must be 'rgb_array' or None, got {render_mode!r}")
        self.env_id = env_id
        self.render_mode = render_mode
        self.metadata = {**self.metadata, "render_fps": self.config.robot.control_hz}
        self.task = "search" if env_id.endswith("Search-v0") else "explore"
        self.possible_agents = [f"robot_{i}" for i in range(self.team.n_robots)]
        self.agents: list[str] = []
        c = self.config.robot
        self._actions = ActionMap(self.config.action_type, c.max_speed_m_s, c.max_turn_rate_rad_s)
        self._action_spaces = {
            agent: ActionMap(self.config.action_type, c.max_speed_m_s, c.max_turn_rate_rad_s).space
            for agent in self.possible_agents
        }
        self._victim_view = VictimObservation(self.config) if self.task == "search" else None
        self._obs_space = self._observation_space()
        self.state_space = state_space(self.config.global_map.size_px)
        self._sim = TeamSimulation(self.config, self.team, victims=self.task == "search")
        self._source = self.config.source.generator()
        self._rng: np.random.Generator | None = None
        self._scan_scale = np.float32(1.0 / self.config.lidar.max_range_m)

    # -- PettingZoo's API ------------------------------------------------------------------------
    def observation_space(self, agent: str) -> spaces.Dict:
        """Every agent's observation space (one object, the same each call)."""
        return self._obs_space

    def action_space(self, agent: str) -> spaces.Space:
        """The agent's action space: the single environment's primitive one (its own object)."""
        return self._action_spaces[agent]

    def reset(
        self, seed: int | None = None, options: dict[str, Any] | None = None
    ) -> tuple[dict[str, dict[str, np.ndarray]], dict[str, dict[str, Any]]]:
        """Start an episode in a new building (drawn from the seed) or in ``options["building"]``.

        The same seed gives the same building, starts, victims, laser noise and, with the same
        actions, the same team episode.
        """
        if seed is not None or self._rng is None:
            self._rng, _ = seeding.np_random(seed)
        options = options or {}
        building = options.get("building")
        drawn = building is None
        victims = options.get("victims") if self.task == "search" else None
        xy = None if victims is None else given_victims(victims, self.config)
        self._sim.load(episode_building(self._source(self._rng) if drawn else building, given=not drawn))
        self._sim.reset(self._rng, xy)
        self.agents = list(self.possible_agents)
        infos = self._infos()
        for i, agent in enumerate(self.agents):
            infos[agent]["start_pose"] = tuple(float(v) for v in self._sim.starts[i])
        return self._observe(), infos

    def step(self, actions: dict[str, Any]) -> tuple[dict, dict, dict, dict, dict]:
        """Every robot takes its action for one control step; then observations, rewards, ends, infos.

        Raises:
            ActionError: If an action is missing, names an unknown or finished agent, or is not
                in the action space.
            ResetNeeded: Before the first reset or after the episode ended.
        """
        if not self.agents:
            raise gym.error.ResetNeeded("call reset() before step(): the episode has ended or not started")
        commands = self._commands(actions)
        found = self._sim.step(commands, self._rng)
        rewards, terms = {}, {}
        for i, agent in enumerate(self.agents):
            out = self._sim.out
            victims = int(found[i]) if self._sim.victims is not None else None
            terms[agent] = reward_terms(out.terms[i, 0], bool(out.terms[i, 1] > 0), victims)
            rewards[agent] = weighted_sum(self.config.rewards, terms[agent])
        terminated = self._task_done()
        truncated = self._sim.steps >= self.config.max_steps
        obs, infos = self._observe(), self._infos()
        for agent in self.agents:
            infos[agent]["rewards"] = terms[agent]
        terminations = dict.fromkeys(self.agents, terminated)
        truncations = dict.fromkeys(self.agents, truncated)
        if terminated or truncated:
            self.agents = []
        return obs, rewards, terminations, truncations, infos

    def state(self) -> np.ndarray:
        """The team map: ``(4, S, S)`` uint8 free, wall, unknown and robot channels (0 or 255)."""
        sim = self._sim
        g = self.config.global_map
        image = np.zeros(self.state_space.shape, dtype=np.uint8)
        up = float(sim.starts[0, 2])
        sim.batch.global_view(sim.maps.coverage_map, sim.base_xy, up, g.resolution_m, image[0], image[1])
        image[2][(image[0] == 0) & (image[1] == 0)] = 255
        mark_points(image[3], sim.poses[:, :2], sim.base_xy, up, g.resolution_m)
        return image

    def render(self) -> np.ndarray | None:
        """A top view: the plan, the team map, every robot's trajectory, scan and disc, the base.

        Returns:
            With ``render_mode="rgb_array"``, an ``(H, W, 3)`` uint8 image; else ``None``.
        """
        if self.render_mode is None:
            gym.logger.warn('render() needs a render mode: parallel_env(..., render_mode="rgb_array")')
            return None
        sim = self._sim
        if sim.world is None:
            raise gym.error.ResetNeeded("call reset() before render()")
        offsets = beam_offsets(self.config.lidar)
        returned = sim.returned_beams
        team_grid = sim.batch.grids[sim.maps.coverage_map]
        victims = (None, None) if sim.victims is None else (sim.victims.xy, sim.victims.found)
        scenes = [
            Scene(
                raster=sim.world.raster,
                map_grid=team_grid,
                trajectory_xy=np.asarray(sim.trajectories[i]),
                pose=tuple(float(v) for v in pose),
                scan_pose=tuple(float(v) for v in pose),
                scan_ranges_m=sim.out.scan[i],
                scan_offsets_rad=offsets,
                scan_returned=returned[i],
                radius_m=self.config.robot.radius_m,
                victims_xy=victims[0],
                victims_found=victims[1],
            )
            for i, pose in enumerate(sim.poses)
        ]
        return draw_team(scenes, sim.base_xy)

    def close(self) -> None:
        """Nothing to free (no window)."""

    # -- state a user may inspect ------------------------------------------------------------------
    @property
    def simulation(self) -> TeamSimulation:
        """The team's world, robots, maps and links (read them, don't change them)."""
        return self._sim

    # -- internals ---------------------------------------------------------------------------------
    def _observation_space(self) -> spaces.Dict:
        parts = {k: p.space for k, p in explore_observations(self.config).items()}
        if self._victim_view is not None:
            parts["victims"] = self._victim_view.space
        parts["teammates"] = teammates_space(self.team.n_robots)
        parts["base"] = base_space()
        return spaces.Dict(parts)

    def _commands(self, actions: dict[str, Any]) -> np.ndarray:
        """``(n, 2)`` commands from the agents' actions, checked."""
        if not isinstance(actions, dict):
            raise ActionError(f"step() takes a dict of actions keyed by agent, got {type(actions).__name__}")
        unknown = sorted(set(actions) - set(self.agents))
        if unknown:
            raise ActionError(f"step(): no live agent {unknown[0]!r}; agents: {', '.join(self.agents)}")
        missing = [a for a in self.agents if a not in actions]
        if missing:
            raise ActionError(f"step() needs an action for every live agent: missing {', '.join(missing)}")
        return np.array([self._actions.command(actions[a]) for a in self.agents], dtype=float)

    def _task_done(self) -> bool:
        sim = self._sim
        if sim.victims is not None:
            return sim.victims.all_found
        return bool(self.config.explored(sim.coverage))

    def _observe(self) -> dict[str, dict[str, np.ndarray]]:
        sim = self._sim
        base = batch_observations(
            sim.batch.phys, sim.starts, self._actions.limits, sim.out.scan, self._scan_scale, sim.out.local
        )
        poses = sim.poses
        teammates, to_base = observe_team(poses, sim.base_xy, sim.links, sim.components)
        out = {}
        for i, agent in enumerate(self.agents):
            obs = {k: v[i] for k, v in base.items()}
            if self._victim_view is not None:
                view = _RobotView(sim.victims.xy, sim.in_view[i])
                obs["victims"] = self._victim_view.encode(tuple(float(v) for v in poses[i]), view)
            obs["teammates"] = teammates[i]
            obs["base"] = to_base[i]
            out[agent] = obs
        return out

    def _infos(self) -> dict[str, dict[str, Any]]:
        sim = self._sim
        cell_m2 = sim.batch.building_meta[0, 2] ** 2
        team = {
            "coverage": sim.coverage,
            "observed_area_m2": float(sim.batch.observed[sim.maps.coverage_map] * cell_m2),
            "messages": sim.messages,
            "map_cells_sent": sim.cells_sent,
        }
        if sim.victims is not None:
            team.update(sim.victims.counts())
            team["victims_reported"] = int(sim.reported.sum())
        n = self.team.n_robots
        return {
            agent: {
                **team,
                "own_coverage": sim.own_coverage(i),
                "path_length_m": float(sim.path_length_m[i]),
                "collisions": int(sim.collisions[i]),
                "linked_to_base": bool(sim.components[i] == sim.components[n]),
            }
            for i, agent in enumerate(self.agents)
        }


class _RobotView:
    """What one robot's victim sensor saw: the victims and the ones in its view (for ``encode``)."""

    def __init__(self, xy: np.ndarray, in_view: np.ndarray) -> None:
        self.xy = xy
        self.in_view = in_view


def _require_team_config(config: Any) -> None:
    """Refuse what a team does not run (:meth:`~realistic_indoor.envs.config.EnvConfig.batch_refusal`)."""
    if refused := config.batch_refusal():
        kind, what = refused
        fix = {
            "actions": "run macro decisions per robot on the agent's side",
            "reward": "set rewards={'coverage_auc': 0.0}",
            "observations": "leave extra_observations out",
            "physics": "leave robot physics at 'compiled'",
        }[kind]
        raise ConfigError(f"a team cannot run {what}; {fix}")
