"""Gymnasium environments: exploration and victim search in generated or real buildings.

Importing this package registers the ids of :data:`PRESETS` (``OfficeExplore-v0``,
``OfficeSearch-v0``, ... see :func:`register_envs`); the environments themselves load lazily::

    import gymnasium as gym
    import realistic_indoor.envs

    env = gym.make("OfficeExplore-v0")

``gym.make("realistic_indoor.envs:OfficeExplore-v0")`` works without the import.
"""

from __future__ import annotations

import importlib
from typing import Any

from realistic_indoor.envs.presets import PRESETS, EnvPreset, preset_config
from realistic_indoor.envs.registration import register_envs

_LAZY = {
    "ExploreEnv": "realistic_indoor.envs.explore",
    "SearchEnv": "realistic_indoor.envs.search",
    "EnvConfig": "realistic_indoor.envs.config",
    "RewardWeights": "realistic_indoor.envs.rewards",
    "BuildingSource": "realistic_indoor.envs.source",
    "GeneratedBuildings": "realistic_indoor.envs.source",
    "CustomGenerator": "realistic_indoor.envs.source",
    "FixedBuilding": "realistic_indoor.envs.source",
    "PlanFile": "realistic_indoor.envs.source",
    "RerunRecorder": "realistic_indoor.envs.recording",
    "record_rerun": "realistic_indoor.envs.recording",
}

__all__ = ["PRESETS", "EnvPreset", "preset_config", "register_envs", *_LAZY]

register_envs()


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'realistic_indoor.envs' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(__all__)
