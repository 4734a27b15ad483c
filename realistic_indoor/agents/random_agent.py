"""The random baseline: uniformly random actions."""

from __future__ import annotations

from typing import Any

import numpy as np

from realistic_indoor.agents.base import Agent, RobotSpec
from realistic_indoor.checks import require_int

__all__ = ["RandomAgent"]


class RandomAgent(Agent):
    """Uniformly random actions, each held for ``hold_steps`` control steps.

    With the default ``hold_steps=1`` it is ``env.action_space.sample()`` drawn from the
    agent's own generator: the usual lower bound of exploration benchmarks.

    Args:
        spec: The robot's sensors and limits.
        hold_steps: Control steps each random action is repeated, >= 1.
        seed: Seed of the agent's generator (also settable per episode by :meth:`reset`).
    """

    name = "random"

    def __init__(self, spec: RobotSpec, hold_steps: int = 1, seed: int | None = None) -> None:
        super().__init__(spec)
        require_int("RandomAgent", "hold_steps", hold_steps, 1)
        self.hold_steps = hold_steps
        self._rng = np.random.default_rng(seed)
        self._action: np.ndarray | int = 0
        self._held = 0

    def reset(self, seed: int | None = None) -> None:
        """Start an episode; a ``seed`` restarts the agent's generator."""
        if seed is not None:
            self._rng = np.random.default_rng(seed)
        self._held = 0

    def act(self, obs: dict[str, np.ndarray], info: dict[str, Any]) -> np.ndarray | int:
        """A random action (the same one for ``hold_steps`` steps)."""
        if self._held == 0:
            if self.spec.action_type == "discrete":
                from realistic_indoor.envs.actions import DISCRETE_ACTIONS

                self._action = int(self._rng.integers(len(DISCRETE_ACTIONS)))
            else:
                self._action = self._rng.uniform(-1.0, 1.0, 2).astype(np.float32)
        self._held = (self._held + 1) % self.hold_steps
        return self._action
