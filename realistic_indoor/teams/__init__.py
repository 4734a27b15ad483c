"""Robot teams: several robots exploring or searching one building, as PettingZoo environments.

``parallel_env(env_id, n_robots=N, comm=..., map_sharing=..., **kwargs)`` returns a PettingZoo
``ParallelEnv`` for any registered id (``OfficeExplore-v0``, ``OfficeSearch-v0``, ...), with the
id's keywords as ``gym.make`` takes them; ``env(...)`` the same as an AEC environment (PettingZoo's
``parallel_to_aec``). Needs the ``teams`` extra: ``pip install "realistic-indoor[teams]"``.
See docs/teams.md.

    from realistic_indoor import teams

    env = teams.parallel_env("OfficeExplore-v0", n_robots=4, comm="wss", map_sharing="comm")
    observations, infos = env.reset(seed=0)
"""

from __future__ import annotations

from typing import Any

from realistic_indoor.teams.config import MAP_SHARING, MAX_ROBOTS, TeamConfig
from realistic_indoor.teams.links import (
    COMM_MODELS,
    LineOfSightLinks,
    NoLinks,
    RangeLinks,
    UnlimitedLinks,
    WssLinks,
)

__all__ = [
    "COMM_MODELS",
    "MAP_SHARING",
    "MAX_ROBOTS",
    "LineOfSightLinks",
    "NoLinks",
    "RangeLinks",
    "TeamConfig",
    "UnlimitedLinks",
    "WssLinks",
    "env",
    "parallel_env",
]


def parallel_env(
    env_id: str, n_robots: int = 2, comm: Any = "wss", map_sharing: str = "comm", **kwargs: Any
) -> Any:
    """A team of ``n_robots`` on the registered id ``env_id``, as a PettingZoo ``ParallelEnv``.

    Args:
        env_id: A registered id, e.g. ``"OfficeExplore-v0"``.
        n_robots: Robots in the team, 1 to :data:`MAX_ROBOTS`.
        comm: The radio links: a name of :data:`COMM_MODELS` or a link model (``WssLinks(...)``).
        map_sharing: One of :data:`MAP_SHARING`.
        **kwargs: ``render_mode`` and fields of ``EnvConfig``, as ``gym.make(env_id, **kwargs)``.

    Raises:
        ConfigError: For bad settings (one line each).
        DependencyNotInstalled: Without PettingZoo (``pip install "realistic-indoor[teams]"``).
    """
    return _parallel_class()(env_id, n_robots=n_robots, comm=comm, map_sharing=map_sharing, **kwargs)


def env(env_id: str, n_robots: int = 2, comm: Any = "wss", map_sharing: str = "comm", **kwargs: Any) -> Any:
    """:func:`parallel_env` as a PettingZoo AEC environment (``pettingzoo.utils.parallel_to_aec``)."""
    from pettingzoo.utils import parallel_to_aec

    return parallel_to_aec(parallel_env(env_id, n_robots, comm, map_sharing, **kwargs))


def _parallel_class() -> type:
    try:
        import pettingzoo  # noqa: F401
    except ImportError as e:
        from gymnasium.error import DependencyNotInstalled

        raise DependencyNotInstalled(
            'robot teams need PettingZoo: pip install "realistic-indoor[teams]"'
        ) from e
    from realistic_indoor.teams.parallel import TeamParallelEnv

    return TeamParallelEnv
