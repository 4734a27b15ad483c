"""Reinforcement learning: PPO training on a mix of building types and the trained agent.

``realistic-indoor train`` (and ``experiments/train_ppo.py``) run :func:`train_ppo` then
:func:`realistic_indoor.evaluation.ppo.evaluate_ppo` with a preset of :data:`PPO_PRESETS` and :data:`PPO_EVAL_PRESETS`.
stable-baselines3 and torch are imported only when a model is trained or loaded
(``pip install "realistic-indoor[rl]"``).
"""

from __future__ import annotations

from realistic_indoor.agents.rl.config import (
    PPO_EVAL_PRESETS,
    PPO_PRESETS,
    EvalPlan,
    PPOConfig,
    env_ids_of,
    ppo_preset,
)

__all__ = [
    "PPO_EVAL_PRESETS",
    "PPO_PRESETS",
    "EvalPlan",
    "PPOAgent",
    "PPOConfig",
    "TrainResult",
    "env_ids_of",
    "load_model",
    "ppo_preset",
    "train_ppo",
]


def __getattr__(name: str):
    import importlib

    where = {
        "PPOAgent": "agent",
        "load_model": "agent",
        "TrainResult": "train",
        "train_ppo": "train",
    }
    if name in where:
        return getattr(importlib.import_module(f"realistic_indoor.agents.rl.{where[name]}"), name)
    raise AttributeError(f"module 'realistic_indoor.agents.rl' has no attribute {name!r}")
