"""A trained PPO policy behind the agent interface."""

from __future__ import annotations

import zipfile
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from realistic_indoor.agents.base import Agent, RobotSpec
from realistic_indoor.errors import ConfigError

__all__ = ["PPOAgent", "cached_model", "load_model"]

_MODELS: dict[tuple[str, str], Any] = {}
_BAD_MODEL = (ValueError, KeyError, OSError, RuntimeError, AssertionError, AttributeError, zipfile.BadZipFile)
"""What loading a file that is a zip archive but not a model of the kind asked for raises."""


def cached_model(path: str | Path, load: Callable[[str | Path], Any], kind: str, train: str) -> Any:
    """A model file loaded once per process by ``load``, or a one-line error.

    Model files are pickles: loading one can run code. Load only models you trust.

    Args:
        path: The model file (``.zip``).
        load: Loads it (after the file has been checked to be a zip archive).
        kind: What the model is, for messages (``"stable-baselines3 PPO model"``).
        train: The command that trains one, for messages.

    Raises:
        ConfigError: If the file is missing, is not a zip archive, or is not a model of ``kind``.
    """
    key = (kind, str(Path(path).resolve()))
    if key not in _MODELS:
        if not Path(path).is_file():
            raise ConfigError(f"{kind} {str(path)!r} not found (train one with: {train})")
        if not zipfile.is_zipfile(path):
            raise ConfigError(f"{str(path)!r} is not a model archive (a .zip file holding a {kind})")
        try:
            _MODELS[key] = load(path)
        except _BAD_MODEL as e:
            raise ConfigError(
                f"{str(path)!r} is not a {kind} ({type(e).__name__}: {e}); train one with: {train}"
            ) from None
    return _MODELS[key]


def load_model(path: str | Path) -> Any:
    """A saved stable-baselines3 PPO model, loaded once per process (CPU, one torch thread).

    Model files are pickles: loading one can run code. Load only models you trust.

    Raises:
        ConfigError: If the file is missing, is not a model archive, or stable-baselines3 /
            torch are not installed.
    """
    from realistic_indoor.agents.rl.train import require_rl

    def load(file: str | Path) -> Any:
        torch, sb3 = require_rl()
        torch.set_num_threads(1)
        return sb3.PPO.load(file, device="cpu")

    return cached_model(path, load, "stable-baselines3 PPO model", "realistic-indoor train")


class PPOAgent(Agent):
    """Acts with a trained PPO policy (stable-baselines3), greedily by default.

    The policy reads the observation keys it was trained on (a subset of the environment's)
    and its own action type: a discrete policy in a continuous environment sends the velocity of
    the chosen action, a continuous one in a discrete environment the nearest action.

    Args:
        spec: The robot's sensors and limits.
        model: Path of a saved model (``.zip``), or a loaded model.
        deterministic: Take the most likely action (else sample from the policy).

    Raises:
        ConfigError: If the model cannot be loaded.
    """

    name = "ppo"

    def __init__(self, spec: RobotSpec, model: str | Path | Any, deterministic: bool = True) -> None:
        super().__init__(spec)
        self.model = load_model(model) if isinstance(model, (str, Path)) else model
        self.source = str(model) if isinstance(model, (str, Path)) else type(model).__name__
        self.deterministic = deterministic
        self._keys = list(self.model.observation_space.spaces)
        self._discrete = hasattr(self.model.action_space, "n")

    def act(self, obs: dict[str, np.ndarray], info: dict[str, Any]) -> np.ndarray | int:
        """The policy's action for ``obs``, in the environment's action space."""
        missing = [k for k in self._keys if k not in obs]
        if missing:
            raise ConfigError(f"the PPO model reads observation keys {missing} that this environment lacks")
        part = {k: obs[k] for k in self._keys}
        for k, space in self.model.observation_space.spaces.items():
            if part[k].shape != space.shape:
                raise ConfigError(
                    f"the PPO model expects {k!r} of shape {space.shape}, the environment gives {part[k].shape}; "
                    "use the sensor settings it was trained with"
                )
        action, _ = self.model.predict(part, deterministic=self.deterministic)
        return self._convert(action)

    def _convert(self, action: np.ndarray) -> np.ndarray | int:
        r = self.spec.robot
        if self._discrete:
            if self.spec.action_type == "discrete":
                return int(action)
            from realistic_indoor.envs.actions import DISCRETE_ACTIONS

            _, v, w = DISCRETE_ACTIONS[int(action)]
            return self.spec.action(v * r.max_speed_m_s, w * r.max_turn_rate_rad_s)
        a = np.clip(np.asarray(action, dtype=float).ravel(), -1.0, 1.0)
        return self.spec.action(a[0] * r.max_speed_m_s, a[1] * r.max_turn_rate_rad_s)

    def __repr__(self) -> str:
        return f"PPOAgent({self.source!r})"
