"""A stable-baselines3 ``VecEnv`` over the native vector environments (one compiled step per id).

stable-baselines3 resets a finished sub-environment in the same step, returning the new
episode's first observation and the last one in ``info["terminal_observation"]``; the native
:class:`~realistic_indoor.envs.vector.BatchedExploreEnv` resets on the next step (Gymnasium's
default). The adapter restarts finished sub-environments at once
(:meth:`BatchedExploreEnv.restart`) and does what SB3's ``Monitor`` would: ``info["episode"]``
(return, length, seconds, final coverage) when an episode ends and ``TimeLimit.truncated``; each
sub-environment's ``info`` also holds what the single environment's does (``coverage``,
``rewards``, ``path_length_m``, ...).
"""

from __future__ import annotations

import warnings
from collections.abc import Sequence
from typing import Any

import gymnasium as gym
import numpy as np
from stable_baselines3.common.vec_env.base_vec_env import VecEnvStepReturn

from realistic_indoor.agents.rl.shared_vec_env import SharedStateVecEnv

__all__ = ["BatchedVecEnv"]


class BatchedVecEnv(SharedStateVecEnv):
    """Several native vector environments (e.g. one per registered id) as one SB3 ``VecEnv``.

    Observations are filtered to ``keys``. By default sub-environments are numbered group after
    group; ``order`` numbers them otherwise, e.g. as a ``DummyVecEnv`` of single environments
    taking several ids in turn: with the same seed (:meth:`seed` gives sub-environment ``i``
    ``seed + i``) it then steps exactly that ``DummyVecEnv``'s episodes.

    Args:
        groups: Native vector environments with the same action space and observation keys.
        keys: Observation keys the policy reads.
        order: For each sub-environment, in this ``VecEnv``'s numbering, its position when the
            groups' sub-environments are listed group after group (a permutation of
            ``range(num_envs)``); ``None`` for group after group.

    Raises:
        ValueError: If ``groups`` is empty, their spaces differ or ``order`` is no permutation.
    """

    def __init__(
        self, groups: Sequence[Any], keys: Sequence[str], order: Sequence[int] | None = None
    ) -> None:
        if not groups:
            raise ValueError("BatchedVecEnv needs at least one vector environment")
        self.groups = list(groups)
        self.keys = tuple(keys)
        first = self.groups[0]
        obs_space = gym.spaces.Dict({k: first.single_observation_space[k] for k in self.keys})
        for g in self.groups[1:]:
            if g.single_action_space != first.single_action_space or any(
                g.single_observation_space[k] != obs_space[k] for k in self.keys
            ):
                raise ValueError("BatchedVecEnv: the vector environments' spaces differ")
        sizes = [g.num_envs for g in self.groups]
        self._bounds = np.concatenate([[0], np.cumsum(sizes)])
        n = int(self._bounds[-1])
        self._order = np.arange(n) if order is None else np.asarray(order, dtype=np.int64)
        if sorted(self._order.tolist()) != list(range(n)):
            raise ValueError(f"BatchedVecEnv: order must be a permutation of range({n}), got {order!r}")
        self._rank = np.argsort(self._order)  # group-after-group position -> this numbering
        self._in_order = bool((self._order == np.arange(n)).all())
        self.render_mode = None
        super().__init__(n, obs_space, first.single_action_space)
        self._actions: np.ndarray | None = None
        self._clear_episodes()

    def reset(self) -> dict[str, np.ndarray]:
        """Start an episode in every sub-environment (seeded by :meth:`seed` if it was called)."""
        parts = []
        grouped_seeds = [self._seeds[i] for i in self._rank]
        for j, g in enumerate(self.groups):
            lo, hi = self._bounds[j], self._bounds[j + 1]
            seeds = grouped_seeds[lo:hi]
            obs, _ = g.reset(seed=None if all(s is None for s in seeds) else list(seeds))
            parts.append(obs)
        self._reset_seeds()
        self._clear_episodes()
        return self._join(parts)

    def step_async(self, actions: np.ndarray) -> None:
        """Remember the actions of the next :meth:`step_wait`."""
        self._actions = np.asarray(actions)[self._rank]  # in group-after-group order

    def step_wait(self) -> VecEnvStepReturn:
        """Step every group; restart the finished sub-environments (same-step autoreset)."""
        if self._actions is None:
            raise RuntimeError("step_async() must come before step_wait()")
        parts, rewards, dones, infos = [], [], [], []
        for j, g in enumerate(self.groups):
            lo, hi = self._bounds[j], self._bounds[j + 1]
            obs, reward, terminated, truncated, info = g.step(self._actions[lo:hi])
            done = terminated | truncated
            group_infos = self._infos(lo, reward, terminated, truncated, info)
            if done.any():
                ended = np.flatnonzero(done)
                for k in ended:
                    group_infos[k]["terminal_observation"] = {key: obs[key][k].copy() for key in self.keys}
                obs = g.restart(ended)
            parts.append(obs)
            rewards.append(reward)
            dones.append(done)
            infos.extend(group_infos)
        self._actions = None
        rewards_all = np.concatenate(rewards).astype(np.float32)[self._order]
        return (
            self._join(parts),
            rewards_all,
            np.concatenate(dones)[self._order],
            [infos[i] for i in self._order],
        )

    def _infos(
        self, lo: int, reward: np.ndarray, terminated: np.ndarray, truncated: np.ndarray, info: dict
    ) -> list[dict[str, Any]]:
        """Per sub-environment ``info`` dicts of one group (Monitor's ``episode`` at an end)."""
        n = len(reward)
        self._count_step(lo, reward)
        out = _env_infos(info, n)  # what the single env's info holds
        ended = terminated | truncated
        limited = (truncated & ~terminated).tolist()
        for k, item in enumerate(out):
            item["TimeLimit.truncated"] = limited[k]
        for k in np.flatnonzero(ended):
            out[k]["episode"] = self._episode(lo + int(k), out[k]["coverage"])
        return out

    def _join(self, parts: list[dict[str, np.ndarray]]) -> dict[str, np.ndarray]:
        if len(parts) == 1 and self._in_order:  # the group's arrays are new at every step: no copy
            return {k: parts[0][k] for k in self.keys}
        return {k: np.concatenate([p[k] for p in parts])[self._order] for k in self.keys}

    def close(self) -> None:
        """Close every group."""
        for g in self.groups:
            g.close()

    def get_images(self) -> list[np.ndarray | None]:
        """Each sub-environment's top view, in this ``VecEnv``'s numbering.

        The groups must be made with ``render_mode="rgb_array"`` (``None`` entries otherwise);
        each frame has its own building's size.
        """
        frames: list[np.ndarray | None] = []
        for g in self.groups:
            drawn = g.render() if g.render_mode == "rgb_array" else None
            frames.extend(drawn if drawn is not None else [None] * g.num_envs)
        return [frames[i] for i in self._order]

    def render(self, mode: str | None = None) -> np.ndarray | None:
        """The sub-environments' top views side by side (SB3's ``render``).

        The image's size follows the buildings': it changes when a sub-environment moves to a
        building of another size (a video of it then holds one set of buildings only).

        With ``render_mode="rgb_array"`` groups, one image of every frame
        (:func:`~realistic_indoor.envs.render.tile`: SB3's own tiling takes frames of one size
        only, and each building has its own); with ``"human"`` groups, each group shows its
        window (``mode="human"`` on ``"rgb_array"`` groups warns: make them ``"human"``);
        otherwise SB3's answer (a warning, ``None``).
        """
        if self.render_mode == "rgb_array" and mode in (None, "rgb_array"):
            from realistic_indoor.envs.render import tile

            return tile(self.get_images())
        if self.render_mode == "human" and mode in (None, "human"):
            for g in self.groups:
                g.render()
            return None
        if self.render_mode == "rgb_array" and mode == "human":
            warnings.warn(
                'to watch the sub-environments, make the vector envs with render_mode="human"', stacklevel=2
            )
            return None
        return super().render(mode)

    def _owner_of(self, i: int) -> Any:
        """The native vector environment that sub-environment ``i`` belongs to."""
        j = int(self._order[i])
        return self.groups[int(np.searchsorted(self._bounds, j, side="right")) - 1]


def _env_infos(info: dict[str, Any], n: int) -> list[dict[str, Any]]:
    """Each sub-environment's part of a native vector env's ``info`` (arrays and ``_key`` masks).

    Each array becomes Python values once (``tolist``), not one ``item()`` per value.
    """
    columns: list[tuple[str, Any]] = []
    for key, value in info.items():
        if key.startswith("_"):
            continue
        if isinstance(value, dict):
            columns.append((key, {name: v.tolist() for name, v in value.items()}))
        else:
            columns.append((key, value.tolist()))
    return [
        {
            key: {name: c[k] for name, c in col.items()} if isinstance(col, dict) else col[k]
            for key, col in columns
        }
        for k in range(n)
    ]
