"""The registered environments: one preset (keyword overrides of the config) per id."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, NamedTuple

if TYPE_CHECKING:
    from realistic_indoor.envs.config import EnvConfig

__all__ = ["PRESETS", "EnvPreset", "base_config", "preset_config"]

_ENTRY_POINTS = {
    "Explore": "realistic_indoor.envs.explore:ExploreEnv",
    "Search": "realistic_indoor.envs.search:SearchEnv",
}
_VECTOR_ENTRY_POINTS = {
    "Explore": "realistic_indoor.envs.vector:BatchedExploreEnv",
    "Search": "realistic_indoor.envs.vector_search:BatchedSearchEnv",
}
"""The native vector environment of each task (``gym.make_vec``)."""
_MAX_STEPS = {
    "Explore": {"office": 6000, "school": 6000, "house": 1000, "random": 6000},
    "Search": {"office": 12000, "school": 15000, "house": 1000, "random": 12000},
}
"""Control steps (0.2 s each at 5 Hz) per episode, by task and building type, for buildings of
the generator's default size. Measured with the nearest-frontier explorer (``FrontierAgent``).
Exploration: it needed at most 4,957 steps to observe 90% of default offices (20 seeds), 4,413
on schools and 309 on houses (10 seeds each). Search, sweeping the floor with the victim sensor:
it needed at most 9,493 steps to find the 3 victims of default offices (10 seeds), 11,560 on
schools (6 seeds) and 462 on houses (10 seeds). Each limit leaves it about 20% or more to spare.
Random maps have the offices' floor area and get their limits, so the two compare at equal time
(the explorer needs at most 2,569 and 5,646 steps there)."""


class EnvPreset(NamedTuple):
    """One registered environment.

    Attributes:
        env_id: The id ``gym.make`` takes, e.g. ``"OfficeExplore-v0"``.
        entry_point: ``"module:Class"`` of the environment.
        kwargs: Config fields the preset sets (the rest keep the environment's defaults):
            ``source`` (the building type) and ``max_steps``; plain values only, so
            registering imports nothing heavy. (Gymnasium is given ``{"preset": env_id}``: the
            environment starts from :func:`preset_config` and applies ``gym.make``'s keywords
            to it, so they override the preset's.)
        max_episode_steps: The step limit (also ``kwargs["max_steps"]``).
        vector_entry_point: ``"module:Class"`` of the native vector environment that
            ``gym.make_vec`` returns (every registered id has one), or ``None`` (Gymnasium's
            sync vector of single envs).
    """

    env_id: str
    entry_point: str
    kwargs: dict[str, Any]
    max_episode_steps: int
    vector_entry_point: str | None = None

    @property
    def building_type(self) -> str:
        """The generator of the preset's buildings (``"office"``, ..., ``"random"``)."""
        return self.kwargs["source"]


def _presets() -> dict[str, EnvPreset]:
    out = {}
    for task, entry_point in _ENTRY_POINTS.items():
        for building_type, max_steps in _MAX_STEPS[task].items():
            env_id = f"{building_type.capitalize()}{task}-v0"
            kwargs = {"source": building_type, "max_steps": max_steps}
            out[env_id] = EnvPreset(env_id, entry_point, kwargs, max_steps, _VECTOR_ENTRY_POINTS[task])
    return out


PRESETS: dict[str, EnvPreset] = _presets()
"""Every registered environment, keyed by id: ``{Office,School,House,Random}{Explore,Search}-v0``."""


def preset_config(env_id: str, **overrides: Any):
    """The full :class:`~realistic_indoor.envs.config.EnvConfig` of a registered id.

    Args:
        env_id: A key of :data:`PRESETS`.
        **overrides: Config fields to change.

    Raises:
        ConfigError: If the id is unknown, an override is invalid, or it is a field the id's
            task does not use (``victims`` on an Explore id, ``coverage_target`` on a Search id).
    """
    from realistic_indoor.envs.config import EnvConfig, require_task_fields
    from realistic_indoor.errors import ConfigError

    if env_id not in PRESETS:
        raise ConfigError(f"unknown environment id {env_id!r}; registered: {', '.join(PRESETS)}")
    config = EnvConfig(**PRESETS[env_id].kwargs).replace(**overrides)
    task = next(t for t in _ENTRY_POINTS if env_id.endswith(f"{t}-v0"))
    require_task_fields(config, task.lower(), overrides)
    return config


def base_config(config: EnvConfig | None, preset: str | None) -> EnvConfig:
    """The configuration an environment starts from, before its keyword overrides.

    Args:
        config: A whole configuration; it wins over ``preset``.
        preset: A registered id (``gym.make`` passes the id it makes); its configuration is
            used when ``config`` is ``None``.

    Raises:
        ConfigError: If ``config`` is not an ``EnvConfig`` or ``preset`` is not a registered id.
    """
    from realistic_indoor.envs.config import EnvConfig
    from realistic_indoor.errors import ConfigError

    if config is not None:
        if not isinstance(config, EnvConfig):
            raise ConfigError(f"config must be an EnvConfig, got {type(config).__name__}")
        return config
    if preset is None:
        return EnvConfig()
    return preset_config(preset)
