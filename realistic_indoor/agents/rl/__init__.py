"""Reinforcement learning: PPO training on a mix of building types, and the trained agent.

stable-baselines3 and torch are imported only when a model is trained or loaded
(``pip install "realistic-indoor[rl]"``).
"""

from __future__ import annotations

from realistic_indoor.agents.rl.config import PPO_PRESETS, PPOConfig, ppo_preset

__all__ = ["PPO_PRESETS", "PPOAgent", "PPOConfig", "TrainResult", "load_model", "ppo_preset", "train_ppo"]


def __getattr__(name: str):
    import importlib

    where = {"PPOAgent": "agent", "load_model": "agent", "TrainResult": "train", "train_ppo": "train"}
    if name in where:
        return getattr(importlib.import_module(f"realistic_indoor.agents.rl.{where[name]}"), name)
    raise AttributeError(f"module 'realistic_indoor.agents.rl' has no attribute {name!r}")
