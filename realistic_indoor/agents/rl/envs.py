"""Training environments for PPO: a mix of ids, vectorised, observations filtered to the policy's keys."""

from __future__ import annotations

from typing import Any

from realistic_indoor.agents.rl.config import PPOConfig

__all__ = ["EnvFactory", "env_factories", "make_vec_env"]


class EnvFactory:
    """Builds one training environment (picklable, for sub-process vector environments).

    Args:
        env_id: The registered id.
        config: The training run (area per building type, step limit, action type, keys).
    """

    def __init__(self, env_id: str, config: PPOConfig) -> None:
        from realistic_indoor.envs import PRESETS
        from realistic_indoor.envs.observations import EXTRA_OBSERVATIONS

        self.env_id = env_id
        building_type = PRESETS[env_id].building_type
        self.kwargs: dict[str, Any] = {"max_steps": config.max_steps, "max_episode_steps": config.max_steps}
        if building_type in config.areas_m2:
            self.kwargs["area_m2"] = config.areas_m2[building_type]
        self.kwargs["action_type"] = config.action_type
        self.keys = tuple(config.obs_keys) + (("victims",) if "Search" in env_id else ())
        extras = tuple(k for k in EXTRA_OBSERVATIONS if k in self.keys)
        if extras:
            self.kwargs["extra_observations"] = extras
        # the native vector environments compute no extra observations
        self.batched = PRESETS[env_id].vector_entry_point is not None and not extras

    def __call__(self) -> Any:
        """A new environment: the id with the training settings, filtered keys, a Monitor."""
        import gymnasium as gym
        from gymnasium.wrappers import FilterObservation
        from stable_baselines3.common.monitor import Monitor

        import realistic_indoor.envs  # noqa: F401 - registers the ids

        env = FilterObservation(gym.make(self.env_id, **self.kwargs), list(self.keys))
        return Monitor(env, info_keywords=("coverage",))


def env_factories(config: PPOConfig) -> list[EnvFactory]:
    """One factory per environment: the ids of ``config.env_ids`` in turn."""
    return [EnvFactory(config.env_ids[i % len(config.env_ids)], config) for i in range(config.n_envs)]


def make_vec_env(config: PPOConfig) -> Any:
    """The stable-baselines3 vector environment of a training run, seeded with ``config.seed``.

    ``vec_env="batched"``: the ids' native vector environments (one compiled step each, in this
    process) behind :class:`~realistic_indoor.agents.rl.batched_vec_env.BatchedVecEnv`, the ids
    taking the ``n_envs`` sub-environments in turn, numbered as the other two number them: with
    one seed all three step the same episodes. Otherwise one Gymnasium environment per
    sub-environment, in sub-processes (``"subproc"``, and ``"batched"`` where the native vector
    environments cannot run the training's environments: extra observations) or in this process
    (``"dummy"``).
    """
    from stable_baselines3.common.vec_env import DummyVecEnv, SubprocVecEnv

    factories = env_factories(config)
    if config.vec_env == "batched" and all(f.batched for f in factories):
        venv = _batched(factories)
    elif config.vec_env in ("subproc", "batched") and config.n_envs > 1:
        venv = SubprocVecEnv(factories, start_method="fork")
    else:
        venv = DummyVecEnv(factories)
    venv.seed(config.seed)
    return venv


def _batched(factories: list[EnvFactory]) -> Any:
    """One native vector environment per id, with as many sub-environments as it has factories."""
    import gymnasium as gym

    import realistic_indoor.envs  # noqa: F401 - registers the ids
    from realistic_indoor.agents.rl.batched_vec_env import BatchedVecEnv

    members: dict[str, list[int]] = {}  # each id's factories, in the order they come
    for i, f in enumerate(factories):
        members.setdefault(f.env_id, []).append(i)
    by_id = {f.env_id: f for f in factories}
    groups = [
        gym.make_vec(env_id, num_envs=len(m), vectorization_mode="vector_entry_point", **by_id[env_id].kwargs)
        for env_id, m in members.items()
    ]
    grouped = [i for m in members.values() for i in m]  # factory of each group-after-group position
    order = [grouped.index(i) for i in range(len(factories))]
    return BatchedVecEnv(groups, factories[0].keys, order)
