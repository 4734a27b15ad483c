"""The part of a stable-baselines3 ``VecEnv`` whose sub-environments share an owner's state.

:class:`~realistic_indoor.agents.rl.batched_vec_env.BatchedVecEnv` (sub-environments of native
vector environments) and :class:`~realistic_indoor.agents.rl.team_vec_env.TeamVecEnv` (robots
of teams) both step several owners, each holding several sub-environments: an attribute is the
owner's, and nothing can be set or called on one sub-environment alone. Both also do what SB3's
``Monitor`` does for each sub-environment: ``info["episode"]`` when an episode ends.
"""

from __future__ import annotations

import time
from abc import abstractmethod
from typing import Any

import gymnasium as gym
import numpy as np
from stable_baselines3.common.vec_env.base_vec_env import VecEnv, VecEnvIndices

__all__ = ["SharedStateVecEnv"]


class SharedStateVecEnv(VecEnv):
    """A ``VecEnv`` whose sub-environments belong to owners (vector environments, teams)."""

    def _clear_episodes(self) -> None:
        """Every sub-environment starts an episode now (returns, lengths and clocks at zero)."""
        self._returns = np.zeros(self.num_envs)
        self._lengths = np.zeros(self.num_envs, dtype=np.int64)
        self._starts = np.full(self.num_envs, time.perf_counter())

    def _count_step(self, lo: int, rewards: np.ndarray) -> None:
        """One step of sub-environments ``lo, lo + 1, ...`` with these rewards."""
        n = len(rewards)
        self._returns[lo : lo + n] += rewards
        self._lengths[lo : lo + n] += 1

    def _episode(self, i: int, coverage: float) -> dict[str, Any]:
        """SB3's ``info["episode"]`` of sub-environment ``i``'s ended episode; the next one starts.

        Return (rounded as SB3's ``Monitor`` rounds it), length, seconds and the final coverage
        (``Monitor(info_keywords=("coverage",))`` adds it).
        """
        now = time.perf_counter()
        out = {
            "r": round(float(self._returns[i]), 6),
            "l": int(self._lengths[i]),
            "t": round(now - self._starts[i], 6),
            "coverage": coverage,
        }
        self._returns[i], self._lengths[i], self._starts[i] = 0.0, 0, now
        return out

    @abstractmethod
    def _owner_of(self, i: int) -> Any:
        """The owner of sub-environment ``i`` (in this ``VecEnv``'s numbering)."""

    def get_attr(self, attr_name: str, indices: VecEnvIndices = None) -> list[Any]:
        """The attribute of each sub-environment's owner (``render_mode``, say)."""
        return [getattr(self._owner_of(int(i)), attr_name) for i in self._get_indices(indices)]

    def set_attr(self, attr_name: str, value: Any, indices: VecEnvIndices = None) -> None:
        """Not supported: sub-environments share their owner's state."""
        raise NotImplementedError(f"{type(self).__name__} sub-environments have no attributes of their own")

    def env_method(
        self, method_name: str, *args: Any, indices: VecEnvIndices = None, **kwargs: Any
    ) -> list[Any]:
        """Not supported: sub-environments share their owner's state."""
        raise NotImplementedError(f"{type(self).__name__} sub-environments have no methods of their own")

    def env_is_wrapped(self, wrapper_class: type[gym.Wrapper], indices: VecEnvIndices = None) -> list[bool]:
        """``False`` for every sub-environment (no Gymnasium wrappers; ``episode`` is built in)."""
        return [False for _ in self._get_indices(indices)]
