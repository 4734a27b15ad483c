"""A stable-baselines3 ``VecEnv`` over robot teams: one shared policy, each robot a sub-environment.

Parameter sharing, the usual way to train one policy for a team with single-agent RL: every robot
of every team is one sub-environment of the ``VecEnv``, so a PPO rollout of ``n_steps`` holds
``n_steps`` steps of each robot, and the policy learns from all of them. A team's robots act in
the same step and end together; when a team's episode ends, each of its robots gets
``info["terminal_observation"]`` and ``info["episode"]`` (its own return and the episode's
length, as SB3's ``Monitor`` gives them, plus the team's final ``coverage``), and the team starts
its next episode in the same step (SB3's convention).

    from sb3_contrib import MaskablePPO  # or stable_baselines3.PPO
    from realistic_indoor import teams
    from realistic_indoor.agents.rl.team_vec_env import TeamVecEnv

    venv = TeamVecEnv([teams.parallel_env("OfficeExplore-v0", n_robots=4, action_type="discrete")])
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import gymnasium as gym
import numpy as np
from stable_baselines3.common.vec_env.base_vec_env import VecEnvStepReturn

from realistic_indoor.agents.rl.shared_vec_env import SharedStateVecEnv
from realistic_indoor.errors import ConfigError

__all__ = ["TeamVecEnv"]


class TeamVecEnv(SharedStateVecEnv):
    """Several team environments as one SB3 ``VecEnv`` of all their robots.

    Sub-environment ``i`` is robot ``i - first`` of the team whose robots take the numbers from
    ``first``, in the order of ``teams``. :meth:`seed` (SB3's: sub-environment ``i`` gets
    ``seed + i``) seeds each team with the seed of its first robot.

    Args:
        teams: PettingZoo team environments (:func:`realistic_indoor.teams.parallel_env`) with
            the same observation and action spaces (the same number of robots, sensors and
            action type).
        keys: Observation keys the policy reads; ``None`` for all of them.

    Raises:
        ConfigError: If ``teams`` is empty, their spaces differ or a key is unknown.
    """

    def __init__(self, teams: Sequence[Any], keys: Sequence[str] | None = None) -> None:
        if not teams:
            raise ConfigError("TeamVecEnv needs at least one team environment")
        self.teams = list(teams)
        first = self.teams[0]
        agent = first.possible_agents[0]
        full = first.observation_space(agent)
        self.keys = tuple(full.spaces) if keys is None else tuple(keys)
        unknown = [k for k in self.keys if k not in full.spaces]
        if unknown:
            raise ConfigError(
                f"TeamVecEnv: no observation keys {unknown}; the team's: {', '.join(full.spaces)}"
            )
        for team in self.teams[1:]:
            a = team.possible_agents[0]
            if team.observation_space(a) != full or team.action_space(a) != first.action_space(agent):
                raise ConfigError(
                    "TeamVecEnv: the teams' observation or action spaces differ (robots, sensors, actions)"
                )
        sizes = [len(t.possible_agents) for t in self.teams]
        self._bounds = np.concatenate([[0], np.cumsum(sizes)]).astype(np.int64)
        self.render_mode = None
        obs_space = gym.spaces.Dict({k: full.spaces[k] for k in self.keys})
        super().__init__(int(self._bounds[-1]), obs_space, first.action_space(agent))
        self._actions: np.ndarray | None = None
        self._clear_episodes()

    def reset(self) -> dict[str, np.ndarray]:
        """Start an episode in every team (seeded by :meth:`seed` if it was called)."""
        parts = []
        for j, team in enumerate(self.teams):
            obs, _ = team.reset(seed=self._seeds[int(self._bounds[j])])
            parts.append(self._robots(team, obs))
        self._reset_seeds()
        self._clear_episodes()
        return self._join(parts)

    def step_async(self, actions: np.ndarray) -> None:
        """Remember the actions of the next :meth:`step_wait` (one per robot, in robot order)."""
        self._actions = np.asarray(actions)

    def step_wait(self) -> VecEnvStepReturn:
        """Step every team; a team whose episode ended starts its next one (same-step reset)."""
        if self._actions is None:
            raise RuntimeError("step_async() must come before step_wait()")
        parts, rewards, dones, infos = [], [], [], []
        for j, team in enumerate(self.teams):
            lo, hi = int(self._bounds[j]), int(self._bounds[j + 1])
            agents = list(team.agents)
            obs, reward, terminated, truncated, info = team.step(
                {a: self._actions[lo + k] for k, a in enumerate(agents)}
            )
            team_rewards = np.array([reward[a] for a in agents], dtype=np.float32)
            ended = bool(terminated[agents[0]] or truncated[agents[0]])
            limited = bool(truncated[agents[0]] and not terminated[agents[0]])
            robot_infos = [dict(info[a], **{"TimeLimit.truncated": limited}) for a in agents]
            self._count_step(lo, team_rewards)
            robot_obs = self._robots(team, obs, agents)
            if ended:
                for k, item in enumerate(robot_infos):
                    item["episode"] = self._episode(lo + k, item["coverage"])
                    item["terminal_observation"] = {key: robot_obs[key][k].copy() for key in self.keys}
                fresh, _ = team.reset()
                robot_obs = self._robots(team, fresh)
            parts.append(robot_obs)
            rewards.append(team_rewards)
            dones.append(np.full(hi - lo, ended))
            infos.extend(robot_infos)
        self._actions = None
        return self._join(parts), np.concatenate(rewards), np.concatenate(dones), infos

    def _robots(
        self, team: Any, obs: dict[str, dict[str, np.ndarray]], agents: list[str] | None = None
    ) -> dict:
        """The team's observations as arrays with one row per robot (the policy's keys)."""
        names = team.possible_agents if agents is None else agents
        return {k: np.stack([obs[a][k] for a in names]) for k in self.keys}

    def _join(self, parts: list[dict[str, np.ndarray]]) -> dict[str, np.ndarray]:
        return {k: np.concatenate([p[k] for p in parts]) for k in self.keys}

    def close(self) -> None:
        """Close every team."""
        for team in self.teams:
            team.close()

    def _owner_of(self, i: int) -> Any:
        """The team that sub-environment ``i`` is a robot of."""
        return self.teams[int(np.searchsorted(self._bounds, i, side="right")) - 1]
