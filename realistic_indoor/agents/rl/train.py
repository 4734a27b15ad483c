"""PPO training with stable-baselines3 (imported here only, when training starts)."""

from __future__ import annotations

import json
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from realistic_indoor.agents.rl.config import PPOConfig
from realistic_indoor.agents.rl.envs import make_vec_env
from realistic_indoor.files import atomic_path, write_text

__all__ = ["TrainResult", "require_rl", "train_ppo"]


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


def train_ppo(config: PPOConfig, out_path: str | Path, log: Callable[[str], object] = print) -> TrainResult:
    """Train PPO on ``config.env_ids`` and save the model to ``out_path`` (``.zip``).

    Args:
        config: The training run.
        out_path: Where to save the model; the config and training curve go to the same
            name with ``.json``.
        log: Receives a progress line about every 10,000 steps.

    Raises:
        ConfigError: If stable-baselines3 or torch are missing (``pip install "realistic-indoor[rl]"``).
    """
    torch, sb3 = require_rl()
    from stable_baselines3.common.callbacks import BaseCallback

    torch.set_num_threads(config.torch_threads)
    out_path = Path(out_path).with_suffix(".zip")
    out_path.parent.mkdir(parents=True, exist_ok=True)
    venv = make_vec_env(config)
    curve: list[dict[str, float]] = []

    class Progress(BaseCallback):
        def __init__(self) -> None:
            super().__init__()
            self.start = time.perf_counter()
            self.next_log = 0
            self.coverages: list[float] = []

        def _on_step(self) -> bool:
            for info in self.locals["infos"]:
                if "episode" in info:
                    self.coverages.append(float(info["coverage"]))
            if self.num_timesteps >= self.next_log:
                self.next_log += 10_000
                recent = self.coverages[-50:]
                mean = sum(recent) / len(recent) if recent else float("nan")
                elapsed = time.perf_counter() - self.start
                curve.append({"timesteps": self.num_timesteps, "seconds": elapsed, "coverage": mean})
                log(
                    f"{self.num_timesteps:>9} steps  {elapsed:7.0f} s  {len(self.coverages):5d} episodes  "
                    f"coverage (last 50) {mean:.3f}"
                )
            return True

    model = sb3.PPO(
        "MultiInputPolicy",
        venv,
        n_steps=config.n_steps,
        batch_size=config.batch_size,
        n_epochs=config.n_epochs,
        learning_rate=config.learning_rate,
        gamma=config.gamma,
        gae_lambda=config.gae_lambda,
        ent_coef=config.ent_coef,
        clip_range=config.clip_range,
        seed=config.seed,
        device="cpu",
        verbose=0,
    )
    progress = Progress()
    start = time.perf_counter()
    try:
        model.learn(total_timesteps=config.total_timesteps, callback=progress)
    finally:
        venv.close()
    seconds = time.perf_counter() - start
    with atomic_path(out_path) as tmp:
        model.save(tmp)
    recent = progress.coverages[-50:]
    result = TrainResult(
        out_path,
        int(model.num_timesteps),
        seconds,
        len(progress.coverages),
        sum(recent) / len(recent) if recent else float("nan"),
    )
    meta = {
        "config": config.to_dict(),
        "timesteps": result.timesteps,
        "seconds": round(seconds, 1),
        "episodes": result.episodes,
        "last_coverage": result.last_coverage,
        "curve": curve,
    }
    write_text(out_path.with_suffix(".json"), json.dumps(meta, indent=1) + "\n")
    return result


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
