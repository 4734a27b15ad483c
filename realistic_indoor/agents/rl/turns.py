"""One training environment that runs several in turn, an episode each: a mix of building types in any number of workers.

A vector environment with fewer sub-environments than ids would otherwise never train on the
ids past its last sub-environment (two workers over offices, schools and houses: no house).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import gymnasium as gym

from realistic_indoor.errors import ConfigError

__all__ = ["TakeTurns"]


class TakeTurns(gym.Env):
    """Runs the environments of ``makers`` in turn: episode ``n`` in environment ``n % len(makers)``.

    Every environment is built at once and must have the first one's observation and action
    spaces. It is worker ``index`` of ``workers`` in a vector environment seeded ``s``, which
    resets it with ``seed = s + index`` (stable-baselines3's numbering). A seeded reset starts
    the turns again from the first environment and gives environment ``p`` the seed ``s *
    workers * len(makers) + index + p * workers`` for its next episode: every run seed, worker
    and environment has a seed of its own (with ``s + index``, runs seeded ``s`` and ``s + 1``
    would share a worker's buildings). Later episodes of each environment continue its own
    random stream, as a single environment's do.

    Methods and attributes the environments have and this class does not (``action_masks``,
    ...) are the current environment's, through ``get_wrapper_attr`` and ``has_wrapper_attr``;
    ``unwrapped`` is this object.

    Args:
        makers: Callables that each build one environment.
        workers: Workers of the vector environment (1: used alone).
        index: This worker's index, below ``workers``.

    Raises:
        ConfigError: If ``makers`` is empty, ``workers`` or ``index`` are out of range, or the
            spaces differ.
    """

    def __init__(self, makers: Sequence[Callable[[], gym.Env]], workers: int = 1, index: int = 0) -> None:
        if not makers:
            raise ConfigError("TakeTurns needs at least one environment to run")
        for name, value, low in (("workers", workers, 1), ("index", index, 0)):
            if isinstance(value, bool) or not isinstance(value, int) or value < low:
                raise ConfigError(f"TakeTurns: {name} must be an int >= {low}, got {value!r}")
        if index >= workers:
            raise ConfigError(f"TakeTurns: index ({index}) must be below workers ({workers})")
        self.envs = [make() for make in makers]
        first = self.envs[0]
        for i, env in enumerate(self.envs[1:], 1):
            if env.observation_space != first.observation_space or env.action_space != first.action_space:
                raise ConfigError(
                    f"TakeTurns: environment {i} ({_name(env)}) has other spaces than environment 0 "
                    f"({_name(first)}); environments taking turns must share their observation and action spaces"
                )
        self.observation_space = first.observation_space
        self.action_space = first.action_space
        self.metadata = first.metadata
        self.render_mode = first.render_mode
        self.workers = workers
        self.index = index
        self.turn = -1
        self._seeds: list[int | None] = [None] * len(self.envs)

    @property
    def current(self) -> gym.Env:
        """The environment of the episode under way (the first before any reset)."""
        return self.envs[max(self.turn, 0)]

    @property
    def env_id(self) -> str:
        """The registered id of the episode under way (the turn's index for an env without one)."""
        return _name(self.current, str(self.turn))

    def seeds_for(self, seed: int) -> list[int]:
        """The seeds a reset with ``seed`` gives the environments, in turn order.

        Raises:
            ConfigError: If ``seed`` is below ``index`` (it is not ``s + index``).
        """
        run = seed - self.index
        if run < 0:
            raise ConfigError(
                f"TakeTurns: worker {self.index} is reset with its vector environment's seed plus {self.index}, "
                f"got seed {seed}; seed the vector environment with a seed >= 0"
            )
        n = len(self.envs)
        return [run * self.workers * n + self.index + p * self.workers for p in range(n)]

    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None) -> tuple[Any, dict]:
        """The next environment's first observation (the first environment's after a seeded reset)."""
        super().reset(seed=seed)
        if seed is not None:
            self._seeds = list(self.seeds_for(seed))
            self.turn = -1
        self.turn = (self.turn + 1) % len(self.envs)
        own, self._seeds[self.turn] = self._seeds[self.turn], None
        obs, info = self.current.reset(seed=own, options=options)
        return obs, {**info, "env_id": self.env_id}

    def step(self, action: Any) -> tuple[Any, float, bool, bool, dict]:
        """A step of the current environment; its ``info`` gains ``env_id`` (the id, or the turn's index)."""
        obs, reward, terminated, truncated, info = self.current.step(action)
        return obs, reward, terminated, truncated, {**info, "env_id": self.env_id}

    def render(self) -> Any:
        """The current environment's frame."""
        return self.current.render()

    def close(self) -> None:
        """Closes every environment."""
        for env in self.envs:
            env.close()

    def get_wrapper_attr(self, name: str) -> Any:
        """This object's attribute ``name``, else the current environment's."""
        if hasattr(self, name):
            return getattr(self, name)
        return self.current.get_wrapper_attr(name)

    def has_wrapper_attr(self, name: str) -> bool:
        """Whether this object or the current environment has ``name``."""
        return hasattr(self, name) or self.current.has_wrapper_attr(name)


def _name(env: gym.Env, default: str | None = None) -> str:
    """The environment's registered id, else ``default``, else its class name."""
    spec = getattr(env, "spec", None)
    return spec.id if spec is not None else default or type(env).__name__
