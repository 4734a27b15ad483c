"""PPO training (environments, budget, hyper-parameters) and its evaluation: configs and presets."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import asdict, dataclass, field, replace
from typing import Any

from realistic_indoor.checks import require_int, require_positive, require_range
from realistic_indoor.errors import ConfigError

__all__ = [
    "ENV_SETS",
    "MAP_ENCODERS",
    "PPO_EVAL_PRESETS",
    "PPO_PRESETS",
    "VEC_ENVS",
    "EvalPlan",
    "PPOConfig",
    "env_ids_of",
    "ppo_preset",
]

REALISTIC_IDS = ("OfficeExplore-v0", "SchoolExplore-v0", "HouseExplore-v0")
RANDOM_IDS = ("RandomExplore-v0",)
ENV_SETS: dict[str, tuple[str, ...]] = {"realistic": REALISTIC_IDS, "random": RANDOM_IDS}
"""Named sets of training ids: ``realistic`` (offices, schools, houses) and ``random`` (the baseline)."""
MAP_ENCODERS = ("nature", "compact")
"""How a PPO policy encodes its map images: :attr:`PPOConfig.map_encoder`."""
VEC_ENVS = ("batched", "subproc", "dummy")
"""How training environments run: :attr:`PPOConfig.vec_env`."""
TRAINING_AREAS_M2: dict[str, float] = {"office": 600.0, "school": 900.0, "house": 150.0, "random": 600.0}
"""Floor area per building type while training (m2): smaller than the generators' defaults, so
that training episodes see whole buildings."""


@dataclass(frozen=True)
class PPOConfig:
    """A PPO training run (stable-baselines3, ``MultiInputPolicy`` on the Dict observation).

    Attributes:
        env_ids: Registered ids trained on; the vectorised environments take them in turn (the
            ``i``-th runs id ``i % len(env_ids)``), so a mix of building types is trained on
            together: ``n_envs`` must be at least the number of ids.
        areas_m2: Floor area asked of each building type's generator while training (m2);
            smaller than the defaults, so that episodes see whole buildings. Types missing
            use the generator's default.
        max_steps: Episode length while training (control steps).
        action_type: ``"discrete"`` (6 actions; learns faster) or ``"continuous"``. A
            discrete policy still drives continuous environments: the agent sends the velocity
            of the chosen action.
        obs_keys: Observation keys the policy reads (``pose`` is left out by default: absolute
            odometry does not generalise across buildings); ``victims`` is added for search ids.
            ``global_map`` and ``time_left`` are the environments' extra observations
            (``EnvConfig.extra_observations``): naming one asks the environments for it, and
            evaluation gives a model that reads them the same (the ``global-map`` preset).
            ``candidates`` needs macro actions: the learned explorer's recipe
            (:mod:`~realistic_indoor.agents.rl.learned`).
        map_encoder: How the policy encodes each map image (``local_map``, ``global_map``):
            ``"nature"`` (stable-baselines3's default, the Atari CNN and a 256-wide layer: 340 k
            weights on the 64-pixel global map) or ``"compact"``
            (:class:`~realistic_indoor.agents.rl.encoders.MapEncoder`: the same kernels and
            strides with fewer channels, averaged to 4 x 4, and a 128-wide layer: 87 k weights;
            images of at least 36 pixels a side).
        n_envs: Environments run in parallel.
        vec_env: ``"batched"`` (the default: the ids' native vector environments, all
            sub-environments of an id stepped by one compiled call, in this process; with
            extra observations, which those do not compute, ``"subproc"`` instead),
            ``"subproc"`` (one process each) or ``"dummy"`` (all in this process, in turn).
            All three step the same episodes for one seed, so training is the same; the first
            51,200 steps of the default preset took 66.8 s batched, 68.3 s subproc and 63.1 s
            dummy, and with 16 environments batched collected 6% faster than dummy
            (docs/benchmarks.md).
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
    areas_m2: Mapping[str, float] = field(default_factory=lambda: dict(TRAINING_AREAS_M2))
    max_steps: int = 600
    action_type: str = "discrete"
    obs_keys: tuple[str, ...] = ("scan", "local_map", "velocity")
    map_encoder: str = "nature"
    n_envs: int = 4
    vec_env: str = "batched"
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
        if "candidates" in self.obs_keys:
            raise ConfigError(
                "PPOConfig.obs_keys: 'candidates' needs macro actions; train the learned explorer "
                "(realistic-indoor train --preset learned) to choose among candidates"
            )
        if self.map_encoder not in MAP_ENCODERS:
            raise ConfigError(
                f"PPOConfig.map_encoder must be one of {', '.join(MAP_ENCODERS)}, got {self.map_encoder!r}"
            )
        if self.vec_env not in VEC_ENVS:
            raise ConfigError(f"PPOConfig.vec_env must be one of {', '.join(VEC_ENVS)}, got {self.vec_env!r}")
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
        require_int("PPOConfig", "seed", self.seed, 0)
        if self.n_envs < len(self.env_ids):
            raise ConfigError(
                f"PPOConfig.n_envs ({self.n_envs}) is below the number of env_ids ({len(self.env_ids)}): "
                f"{', '.join(self.env_ids[self.n_envs :])} would never be trained on; use n_envs >= "
                f"{len(self.env_ids)} (--n-envs) or fewer ids"
            )
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
    "global-map": {
        "obs_keys": ("scan", "local_map", "velocity", "global_map", "time_left"),
        "map_encoder": "compact",
    },
    "smoke": {
        "total_timesteps": 256,
        "n_envs": 3,
        "vec_env": "dummy",
        "n_steps": 64,
        "batch_size": 64,
        "n_epochs": 1,
        "max_steps": 64,
    },
}
"""Named overrides of :class:`PPOConfig`: ``default`` (about 20 minutes on 2 CPU cores),
``long`` (3 M steps on bigger buildings: hours; better explorers), ``global-map`` (the default
run with the robot's whole map, ``global_map``, and the share of the step limit left,
``time_left``, in the policy's view, each map through the compact encoder: primitive-action PPO
with what the learned explorer's navigator knows), ``smoke`` (256 steps: checks the set-up in seconds, and the tests use it)."""


def ppo_preset(name: str, **changes: Any) -> PPOConfig:
    """The config of a preset of :data:`PPO_PRESETS`, with ``changes`` on top.

    Raises:
        ConfigError: For an unknown preset or an invalid change.
    """
    if name not in PPO_PRESETS:
        raise ConfigError(f"unknown PPO preset {name!r}; presets: {', '.join(PPO_PRESETS)}")
    return PPOConfig(**{**PPO_PRESETS[name], **changes})


@dataclass(frozen=True)
class EvalPlan:
    """The evaluation after a training run: the PPO agent against baselines on the training ids.

    Attributes:
        episodes: Episodes (seeds) per agent and id; 0 skips the evaluation.
        max_steps: Step limit of each episode (control steps of 0.2 s); ``None`` keeps each id's
            own limit (6,000 for offices, schools and random maps, 1,000 for houses).
        areas_m2: Floor area per building type (m2); ``None`` keeps the generators' default
            sizes, on which the ids' step limits were measured.
        baselines: Agents the PPO agent is compared with.
        seed: First seed of the episodes (apart from the training seeds).
    """

    episodes: int
    max_steps: int | None = None
    areas_m2: Mapping[str, float] | None = None
    baselines: tuple[str, ...] = ("random", "frontier")
    seed: int = 1000

    def __post_init__(self) -> None:
        require_int("EvalPlan", "episodes", self.episodes, 0)
        if self.max_steps is not None:
            require_int("EvalPlan", "max_steps", self.max_steps, 1)
        require_int("EvalPlan", "seed", self.seed, 0)
        if self.areas_m2 is not None:
            for building_type, area in self.areas_m2.items():
                require_positive("EvalPlan", f"areas_m2[{building_type!r}]", area, "m2")
            object.__setattr__(self, "areas_m2", dict(self.areas_m2))

    def replace(self, **changes: Any) -> EvalPlan:
        """A copy with some fields changed (checked again)."""
        return replace(self, **changes)

    def describe(self) -> str:
        """The plan in words, e.g. ``"1 episode per id (at most 50 steps, training-size buildings)"``."""
        episodes = f"{self.episodes} episode{'s' if self.episodes != 1 else ''} per id"
        limit = "the ids' step limits" if self.max_steps is None else f"at most {self.max_steps} steps"
        sizes = "default-size buildings" if self.areas_m2 is None else "training-size buildings"
        return f"{episodes} ({limit}, {sizes})"


PPO_EVAL_PRESETS: dict[str, EvalPlan] = {
    "default": EvalPlan(episodes=2),
    "long": EvalPlan(episodes=10),
    "global-map": EvalPlan(episodes=2),
    "smoke": EvalPlan(episodes=1, max_steps=50, areas_m2=TRAINING_AREAS_M2),
    "learned": EvalPlan(episodes=2, baselines=("frontier", "utility", "structure")),
    "learned-smoke": EvalPlan(
        episodes=1, max_steps=50, areas_m2=TRAINING_AREAS_M2, baselines=("frontier", "structure")
    ),
}
"""The evaluation after each preset's training, on default-size buildings at the ids' step limits:
``default`` 2 episodes per agent and id (140 CPU-seconds: 2 to 6 minutes on 2 cores), ``long`` 10;
``smoke`` 1 episode of 50 steps on training-size buildings (seconds: it checks that the model
loads and acts, not how well); ``learned`` and ``learned-smoke`` (the learned explorer's presets,
:data:`~realistic_indoor.agents.rl.learned.LEARNED_PRESETS`) against the frontier, utility and
structure explorers."""


def env_ids_of(envs: str, option: str = "--envs") -> tuple[str, ...]:
    """The ids of ``envs``: a name of :data:`ENV_SETS`, or comma-separated registered ids.

    Args:
        envs: ``"realistic"``, ``"random"``, or ids such as ``"OfficeExplore-v0,HouseExplore-v0"``.
        option: How the user gave ``envs``, named in the error.

    Raises:
        ConfigError: If ``envs`` names no set and holds an unknown id or none.
    """
    from realistic_indoor.envs import PRESETS

    if envs in ENV_SETS:
        return ENV_SETS[envs]
    ids = tuple(dict.fromkeys(e.strip() for e in envs.split(",") if e.strip()))
    unknown = [e for e in ids if e not in PRESETS]
    if not ids or unknown:
        what = f"unknown id {', '.join(map(repr, unknown))}" if unknown else "no id given"
        raise ConfigError(
            f"{option}: {what}; use {' or '.join(ENV_SETS)}, or comma-separated ids of {', '.join(PRESETS)}"
        )
    return ids
