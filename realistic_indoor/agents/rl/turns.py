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
    spaces. A seeded ``reset(seed=s)`` starts the turns again from the first environment and
    gives environment ``p`` the seed ``s + p * seed_stride`` for its next episode (so workers
    seeded ``s, s + 1, ..., s + seed_stride - 1`` never share a seed); later episodes of each
    environment continue its own random stream, as a single environment's do.

    Methods the environments have and this class does not (``action_masks``, ...) are the
    current environment's, through ``get_wrapper_attr``.

    Args:
        makers: Callables that each build one environment.
        seed_stride: Step between the seeds of the environments of one seeded reset (the
            number of workers).

    Raises:
        ConfigError: If ``makers`` is empty, ``seed_stride`` is below 1, or the spaces differ.
    """

    def __init__(self, makers: Sequence[Callable[[], gym.Env]], seed_stride: int = 1) -> None:
        if not makers:
            raise ConfigError("TakeTurns needs at least one environment to run")
        if isinstance(seed_stride, bool) or not isinstance(seed_stride, int) or seed_stride < 1:
            raise ConfigError(f"TakeTurns: seed_stride must be an int >= 1, got {seed_stride!r}")
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
        self.seed_stride = seed_stride
        self.turn = -1
        self._seeds: list[int | None] = [None] * len(self.envs)

    @property
    def current(self) -> gym.Env:
        """The environment of the episode under way (the first before any reset)."""
        return self.envs[max(self.turn, 0)]

    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None) -> tuple[Any, dict]:
        """The next environment's first observation (the first environment's after a seeded reset)."""
        if seed is not None:
            self._seeds = [seed + p * self.seed_stride for p in range(len(self.envs))]
            self.turn = -1
        self.turn = (self.turn + 1) % len(self.envs)
        own, self._seeds[self.turn] = self._seeds[self.turn], None
        return self.current.reset(seed=own, options=options)

    def step(self, action: Any) -> tuple[Any, float, bool, bool, dict]:
        """A step of the current environment."""
        return self.current.step(action)

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


def _name(env: gym.Env) -> str:
    spec = getattr(env, "spec", None)
    return spec.id if spec is not None else type(env).__name__
