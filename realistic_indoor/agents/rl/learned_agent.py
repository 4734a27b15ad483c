"""The learned explorer behind the agent interface: a trained policy chooses goals, the navigator drives.

In any environment of the package (continuous or discrete actions, exploration or search) the
agent runs the frontier macro actions on its own side (:class:`~realistic_indoor.envs.macro.FrontierActions`:
the explorers' navigator and the candidate goals), so it sees exactly what the policy saw in
training: at each decision the candidates and the share of the step limit left, and the policy
(a ``MaskablePPO`` model) picks one; between decisions the navigator drives.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from realistic_indoor.agents.base import Agent, RobotSpec
from realistic_indoor.agents.rl.agent import cached_model
from realistic_indoor.envs.macro import FrontierActions, MacroConfig
from realistic_indoor.envs.observations import time_left

__all__ = ["DEFAULT_MODEL", "LearnedAgent", "load_learned_model"]

DEFAULT_MODEL = Path(__file__).resolve().parents[2] / "data" / "learned_explorer.zip"
"""The committed model that ``make_agent("learned", env)`` loads (``learned:PATH`` for another)."""


def load_learned_model(path: str | Path) -> Any:
    """A saved ``MaskablePPO`` model, loaded once per process (CPU, one torch thread).

    Model files are pickles: loading one can run code. Load only models you trust.

    Raises:
        ConfigError: If the file is missing, is not a model archive, or sb3-contrib / torch are
            not installed.
    """
    from realistic_indoor.agents.rl.learned import require_learned

    def load(file: str | Path) -> Any:
        torch, sb3_contrib = require_learned()
        torch.set_num_threads(1)
        return sb3_contrib.MaskablePPO.load(file, device="cpu")

    return cached_model(
        path, load, "MaskablePPO model of the learned explorer", "realistic-indoor train --preset learned"
    )


class LearnedAgent(Agent):
    """Chooses goals with a trained policy; the explorers' navigator drives to them.

    Args:
        spec: The robot's sensors and limits.
        model: Path of a saved model (``.zip``), or a loaded model; default: the committed one.
        max_steps: The episode's step limit, for the policy's ``time_left`` (control steps);
            default: read from the environment by :func:`~realistic_indoor.agents.make_agent`,
            else 6,000.
        deterministic: Take the most likely choice (else sample from the policy).

    Attributes:
        decisions: Decisions taken in the current episode.
    """

    name = "learned"

    def __init__(
        self,
        spec: RobotSpec,
        model: str | Path | Any | None = None,
        max_steps: int = 6000,
        deterministic: bool = True,
    ) -> None:
        super().__init__(spec)
        model = DEFAULT_MODEL if model is None else model
        self.model = load_learned_model(model) if isinstance(model, (str, Path)) else model
        self.source = str(model) if isinstance(model, (str, Path)) else type(model).__name__
        self.deterministic = deterministic
        self.max_steps = int(max_steps)
        k = int(self.model.action_space.n)
        drive = RobotSpec(spec.lidar, spec.robot, spec.victims, "continuous")
        self.macro = FrontierActions(drive, MacroConfig(n_candidates=k))
        self.reset()

    def reset(self, seed: int | None = None) -> None:
        """Forget the episode."""
        self._steps = 0
        self._started = False
        self.decisions = 0

    def act(self, obs: dict[str, np.ndarray], info: dict[str, Any]) -> np.ndarray | int:
        """Sense; at a decision ask the policy; return the navigator's command as an action."""
        macro = self.macro
        if not self._started:
            macro.reset(obs, info)
            self._started = True
            pending = macro.candidates is not None
        else:
            pending = macro.sense(obs, info)
        if pending:
            policy_obs = {"candidates": macro.features(), "time_left": time_left(self._steps, self.max_steps)}
            choice, _ = self.model.predict(
                policy_obs, action_masks=macro.action_masks(), deterministic=self.deterministic
            )
            macro.choose(int(choice))
            self.decisions += 1
        self._steps += 1
        v, w = macro.navigator.command()
        return self.spec.action(v, w)

    def __repr__(self) -> str:
        return f"LearnedAgent({self.source!r})"
