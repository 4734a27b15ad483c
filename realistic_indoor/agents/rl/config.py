"""Configuration of PPO training: environments, budget and hyper-parameters, with presets."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import asdict, dataclass, field, replace
from typing import Any

from realistic_indoor.checks import require_int, require_positive, require_range
from realistic_indoor.errors import ConfigError

__all__ = ["PPO_PRESETS", "PPOConfig", "ppo_preset"]

REALISTIC_IDS = ("OfficeExplore-v0", "SchoolExplore-v0", "HouseExplore-v0")
RANDOM_IDS = ("RandomExplore-v0",)


@dataclass(frozen=True)
class PPOConfig:
    """A PPO training run (stable-baselines3, ``MultiInputPolicy`` on the Dict observation).

    Attributes:
        env_ids: Registered ids trained on; the vectorised environments take them in turn, so
            a mix of building types is trained on together.
        areas_m2: Floor area asked of each building type's generator while training (m2);
            smaller than the defaults, so that episodes see whole buildings. Types missing
            use the generator's default.
        max_steps: Episode length while training (control steps).
        action_type: ``"discrete"`` (6 actions; learns faster) or ``"continuous"``. A
            discrete policy still drives continuous environments: the agent sends the velocity
            of the chosen action.
        obs_keys: Observation keys the policy reads (``pose`` is left out by default: absolute
            odometry does not generalise across buildings); ``victims`` is added for search ids.
        n_envs: Environments run in parallel.
        vec_env: ``"subproc"`` (one process each) or ``"dummy"`` (all in this process).
        total_timesteps: Environment steps of training, over all environments.
        seed: Seed of the policy and of the environments (``seed + i`` for the ``i``-th).
        n_steps: Steps per environment per rollout.
        batch_size: Minibatch size.
        n_epochs: Passes over each rollout.
        learning_rate: Adam step size.
        gamma: Discount factor.
        gae_lambda: GAE parameter.
        ent_coef: Entropy bonus.
        clip_range: PPO clipping.
        torch_threads: Threads torch may use in the training process.
    """

    env_ids: tuple[str, ...] = REALISTIC_IDS
    areas_m2: Mapping[str, float] = field(
        default_factory=lambda: {"office": 600.0, "school": 900.0, "house": 150.0, "random": 600.0}
    )
    max_steps: int = 600
    action_type: str = "discrete"
    obs_keys: tuple[str, ...] = ("scan", "local_map", "velocity")
    n_envs: int = 4
    vec_env: str = "subproc"
    total_timesteps: int = 500_000
    seed: int = 0
    n_steps: int = 512
    batch_size: int = 256
    n_epochs: int = 4
    learning_rate: float = 3e-4
    gamma: float = 0.99
    gae_lambda: float = 0.95
    ent_coef: float = 0.01
    clip_range: float = 0.2
    torch_threads: int = 1

    def __post_init__(self) -> None:
        from realistic_indoor.envs import PRESETS

        unknown = [e for e in self.env_ids if e not in PRESETS]
        if not self.env_ids or unknown:
            raise ConfigError(f"PPOConfig.env_ids: unknown ids {unknown}; registered: {', '.join(PRESETS)}")
        if self.action_type not in ("discrete", "continuous"):
            raise ConfigError(
                f"PPOConfig.action_type must be discrete or continuous, got {self.action_type!r}"
            )
        if self.vec_env not in ("subproc", "dummy"):
            raise ConfigError(f"PPOConfig.vec_env must be subproc or dummy, got {self.vec_env!r}")
        for name in (
            "max_steps",
            "n_envs",
            "total_timesteps",
            "n_steps",
            "batch_size",
            "n_epochs",
            "torch_threads",
        ):
            require_int("PPOConfig", name, getattr(self, name), 1)
        require_positive("PPOConfig", "learning_rate", self.learning_rate, "")
        require_range("PPOConfig", "gamma", self.gamma, 0.0, 1.0, "")
        require_range("PPOConfig", "gae_lambda", self.gae_lambda, 0.0, 1.0, "")
        require_positive("PPOConfig", "ent_coef", self.ent_coef, "", allow_zero=True)
        require_positive("PPOConfig", "clip_range", self.clip_range, "")
        object.__setattr__(self, "areas_m2", dict(self.areas_m2))

    def replace(self, **changes: Any) -> PPOConfig:
        """A copy with some fields changed (checked again)."""
        return replace(self, **changes)

    def to_dict(self) -> dict[str, Any]:
        """Plain values (for the JSON saved next to a model)."""
        out = asdict(self)
        out["env_ids"] = list(self.env_ids)
        out["obs_keys"] = list(self.obs_keys)
        return out


PPO_PRESETS: dict[str, dict[str, Any]] = {
    "default": {},
    "long": {
        "total_timesteps": 3_000_000,
        "n_envs": 8,
        "max_steps": 1000,
        "areas_m2": {"office": 1200.0, "school": 1800.0, "house": 150.0, "random": 1200.0},
        "n_steps": 1024,
        "n_epochs": 10,
    },
    "smoke": {
        "total_timesteps": 256,
        "n_envs": 2,
        "vec_env": "dummy",
        "n_steps": 64,
        "batch_size": 64,
        "n_epochs": 1,
        "max_steps": 64,
    },
}
"""Named overrides of :class:`PPOConfig`: ``default`` (about 20 minutes on 2 CPU cores),
``long`` (3 M steps on bigger buildings: hours; better explorers), ``smoke`` (seconds, for tests)."""


def ppo_preset(name: str, **changes: Any) -> PPOConfig:
    """The config of a preset of :data:`PPO_PRESETS`, with ``changes`` on top.

    Raises:
        ConfigError: For an unknown preset or an invalid change.
    """
    if name not in PPO_PRESETS:
        raise ConfigError(f"unknown PPO preset {name!r}; presets: {', '.join(PPO_PRESETS)}")
    return PPOConfig(**{**PPO_PRESETS[name], **changes})
