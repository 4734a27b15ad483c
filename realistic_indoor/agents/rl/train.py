"""PPO training with stable-baselines3 (imported here only, when training starts)."""

from __future__ import annotations

import json
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from realistic_indoor.agents.rl.config import PPOConfig
from realistic_indoor.agents.rl.envs import make_vec_env
from realistic_indoor.files import atomic_path, write_text

__all__ = ["PPO_ARGUMENTS", "TrainResult", "ppo_arguments", "require_rl", "train_ppo"]

PPO_ARGUMENTS = (
    "n_steps",
    "batch_size",
    "n_epochs",
    "learning_rate",
    "gamma",
    "gae_lambda",
    "ent_coef",
    "clip_range",
    "seed",
)
"""The fields of a training config that are stable-baselines3 PPO's (and MaskablePPO's) own arguments."""


@dataclass(frozen=True)
class TrainResult:
    """What a training run produced.

    Attributes:
        model_path: The saved model (``.zip``); its config is beside it as ``.json``.
        timesteps: Environment steps trained.
        seconds: Wall-clock time of the training (s).
        episodes: Training episodes completed.
        last_coverage: Mean final coverage of the last 50 training episodes.
    """

    model_path: Path
    timesteps: int
    seconds: float
    episodes: int
    last_coverage: float


def train_ppo(
    config: PPOConfig,
    out_path: str | Path,
    log: Callable[[str], object] = print,
    progress: bool = False,
    log_every: int = 10_000,
) -> TrainResult:
    """Train PPO on ``config.env_ids`` and save the model to ``out_path`` (``.zip``).

    The model and its ``.json`` are written whole or not at all (an interrupted run leaves any
    earlier file at ``out_path`` as it was).

    Args:
        config: The training run.
        out_path: Where to save the model; the config and training curve go to the same
            name with ``.json``.
        log: Receives a progress line (steps, seconds, episodes, mean coverage, environment
            steps per second of collecting, and the share of wall-clock time spent collecting
            rollouts against learning from them) every ``log_every`` steps and at the end.
        progress: Also show a progress bar (tqdm, on stderr, only when it is a terminal) with
            the episodes finished and their mean coverage.
        log_every: Environment steps between two progress lines (and points of the curve).

    Raises:
        ConfigError: If stable-baselines3 or torch are missing (``pip install "realistic-indoor[rl]"``).
    """
    torch, sb3 = require_rl()
    torch.set_num_threads(config.torch_threads)
    out_path = Path(out_path).with_suffix(".zip")
    out_path.parent.mkdir(parents=True, exist_ok=True)
    venv = make_vec_env(config)
    tracker = _progress_callback(config.total_timesteps, log, progress, log_every)
    model = sb3.PPO("MultiInputPolicy", venv, policy_kwargs=_policy_kwargs(config), **ppo_arguments(config))
    start = time.perf_counter()
    try:
        model.learn(total_timesteps=config.total_timesteps, callback=tracker)
    finally:
        venv.close()
    seconds = time.perf_counter() - start
    with atomic_path(out_path) as tmp:
        model.save(tmp)
    result = TrainResult(out_path, int(model.num_timesteps), seconds, len(tracker.coverages), tracker.mean())
    meta = {
        "config": config.to_dict(),
        "timesteps": result.timesteps,
        "seconds": round(seconds, 1),
        "episodes": result.episodes,
        "last_coverage": result.last_coverage,
        "collect_seconds": round(tracker.collecting, 1),
        "env_steps_per_s": round(result.timesteps / max(tracker.collecting, 1e-9), 1),
        "collect_share": round(tracker.collecting / max(seconds, 1e-9), 3),
        "curve": tracker.curve,
    }
    write_text(out_path.with_suffix(".json"), json.dumps(meta, indent=1) + "\n")
    return result


def ppo_arguments(config: Any) -> dict[str, Any]:
    """The keyword arguments of ``PPO`` (or ``MaskablePPO``) from a training config's fields.

    Args:
        config: A :class:`~realistic_indoor.agents.rl.config.PPOConfig` or
            :class:`~realistic_indoor.agents.rl.learned.LearnedConfig`.
    """
    return {**{name: getattr(config, name) for name in PPO_ARGUMENTS}, "device": "cpu", "verbose": 0}


def _policy_kwargs(config: Any) -> dict[str, Any] | None:
    """``policy_kwargs`` of ``PPO`` for :attr:`PPOConfig.map_encoder` (``None``: the default encoder)."""
    if getattr(config, "map_encoder", "nature") == "nature":
        return None
    from realistic_indoor.agents.rl.encoders import MapEncoder

    return {"features_extractor_class": MapEncoder}


def _progress_callback(total: int, log: Callable[[str], object], bar: bool, log_every: int) -> Any:
    """A stable-baselines3 callback that collects episode coverages, logs lines and drives a bar.

    Args:
        total: Environment steps of the run (the bar's length).
        log: Receives the progress lines.
        bar: Show a tqdm bar (on stderr, when it is a terminal).
        log_every: Steps between two progress lines.
    """
    from stable_baselines3.common.callbacks import BaseCallback
    from tqdm import tqdm

    class Progress(BaseCallback):
        """Coverage of the finished episodes; a line every ``log_every`` steps and at the end."""

        def __init__(self) -> None:
            super().__init__()
            self.start = time.perf_counter()
            self.next_log = log_every
            self.coverages: list[float] = []
            self.curve: list[dict[str, float]] = []
            self.bar = tqdm(disable=True)
            self.collecting = 0.0
            self.rollout_start = self.start

        def mean(self) -> float:
            """Mean final coverage of the last 50 episodes (NaN before the first ends)."""
            recent = self.coverages[-50:]
            return sum(recent) / len(recent) if recent else float("nan")

        def _on_training_start(self) -> None:
            self.start = time.perf_counter()
            self.bar = tqdm(total=total, unit="step", desc="training PPO", disable=None if bar else True)

        def _on_rollout_start(self) -> None:
            self.rollout_start = time.perf_counter()

        def _on_rollout_end(self) -> None:
            self.collecting += time.perf_counter() - self.rollout_start

        def _on_step(self) -> bool:
            ended = [float(i["coverage"]) for i in self.locals["infos"] if "episode" in i]
            self.coverages.extend(ended)
            self.bar.update(self.num_timesteps - self.bar.n)
            if ended:
                self.bar.set_postfix_str(f"{len(self.coverages)} episodes, coverage {self.mean():.3f}")
            if self.num_timesteps >= self.next_log:
                self.next_log += log_every
                self._log()
            return True

        def _on_training_end(self) -> None:
            if not self.curve or self.curve[-1]["timesteps"] != self.num_timesteps:
                self._log()
            self.bar.close()

        def _log(self) -> None:
            elapsed = time.perf_counter() - self.start
            mean = self.mean()
            rate = self.num_timesteps / max(self.collecting, 1e-9)
            share = self.collecting / max(elapsed, 1e-9)
            self.curve.append(
                {
                    "timesteps": self.num_timesteps,
                    "seconds": elapsed,
                    "coverage": mean,
                    "env_steps_per_s": rate,
                    "collect_share": share,
                }
            )
            line = (
                f"{self.num_timesteps:>9} steps  {elapsed:7.0f} s  {len(self.coverages):5d} episodes  "
                f"coverage (last 50) {mean:.3f}  env {rate:,.0f} steps/s  collect {share:.0%} / learn {1 - share:.0%}"
            )
            with tqdm.external_write_mode():
                log(line)

    return Progress()


def require_rl():
    """The modules ``torch`` and ``stable_baselines3``, or a ConfigError naming the install."""
    from realistic_indoor.errors import ConfigError

    try:
        import stable_baselines3
        import torch
    except ImportError as e:
        raise ConfigError(
            f'PPO needs stable-baselines3 and torch ({e.name} is missing): pip install "realistic-indoor[rl]"'
        ) from None
    return torch, stable_baselines3
