"""Registration of the environments with Gymnasium, from the presets in a loop."""

from __future__ import annotations

from realistic_indoor.envs.presets import PRESETS

__all__ = ["register_envs"]


def register_envs() -> None:
    """Register every id of :data:`~realistic_indoor.envs.presets.PRESETS` with Gymnasium.

    Light: entry points are strings, so nothing of the simulator is imported until an
    environment is made. Ids already registered are left as they are, so calling it again is
    harmless.
    """
    import gymnasium as gym

    for preset in PRESETS.values():
        if preset.env_id not in gym.registry:
            gym.register(
                id=preset.env_id,
                entry_point=preset.entry_point,
                kwargs={"preset": preset.env_id},
                max_episode_steps=preset.max_episode_steps,
                vector_entry_point=preset.vector_entry_point,
            )
