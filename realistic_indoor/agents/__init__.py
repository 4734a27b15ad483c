"""Baseline explorers behind one small interface, and PPO training helpers.

Every agent has ``reset(seed=None)`` and ``act(obs, info) -> action``, and sees only what the
robot senses (the observation and the ``info`` dict), never the building::

    import gymnasium as gym
    import realistic_indoor.envs
    from realistic_indoor.agents import make_agent

    env = gym.make("OfficeExplore-v0")
    agent = make_agent("frontier", env)
    obs, info = env.reset(seed=0)
    agent.reset(seed=0)
    done = False
    while not done:
        obs, reward, terminated, truncated, info = env.step(agent.act(obs, info))
        done = terminated or truncated

Names (:data:`AGENTS`): ``random``, ``wall``, ``frontier``, ``utility``, ``structure``,
``ppo:<model.zip>`` (a trained stable-baselines3 model) and ``learned`` (the learned explorer:
a trained policy choosing among candidate goals; ``learned:<model.zip>`` for another model). See
``docs/agents.md``.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from realistic_indoor.errors import ConfigError

if TYPE_CHECKING:
    from realistic_indoor.agents.base import Agent

__all__ = [
    "AGENTS",
    "Agent",
    "ExplorerConfig",
    "FrontierAgent",
    "LearnedAgent",
    "PPOAgent",
    "RandomAgent",
    "RobotSpec",
    "StructureAgent",
    "UtilityFrontierAgent",
    "WallFollower",
    "agent_observations",
    "make_agent",
]

AGENTS: dict[str, str] = {
    "random": "realistic_indoor.agents.random_agent:RandomAgent",
    "wall": "realistic_indoor.agents.wall_follower:WallFollower",
    "frontier": "realistic_indoor.agents.frontier:FrontierAgent",
    "utility": "realistic_indoor.agents.utility:UtilityFrontierAgent",
    "structure": "realistic_indoor.agents.structure:StructureAgent",
    "ppo": "realistic_indoor.agents.rl.agent:PPOAgent",
    "learned": "realistic_indoor.agents.rl.learned_agent:LearnedAgent",
}
"""Agent names and their ``module:Class``; ``ppo`` needs a model: ``"ppo:path/to/model.zip"``;
``learned`` loads the committed learned explorer, ``"learned:path/to/model.zip"`` another."""

_LAZY = {
    "Agent": "realistic_indoor.agents.base",
    "RobotSpec": "realistic_indoor.agents.base",
    "ExplorerConfig": "realistic_indoor.agents.explorer",
    **{target.rsplit(":", 1)[1]: target.rsplit(":", 1)[0] for target in AGENTS.values()},
}


def make_agent(name: str, env: Any, **options: Any) -> Agent:
    """The agent called ``name`` for the robot of ``env``.

    Args:
        name: A key of :data:`AGENTS`; ``"ppo:<path>"`` loads the PPO model saved at ``path``,
            ``"learned:<path>"`` a learned explorer's model (``"learned"`` alone: the committed one).
        env: The environment (only its robot's sensors, limits and action space are read), or
            a :class:`~realistic_indoor.agents.base.RobotSpec`.
        **options: Keyword arguments of the agent's class (e.g. ``config=`` of an explorer).

    Raises:
        ConfigError: For an unknown name (the message lists the valid ones), a missing PPO
            model, or an environment that is not one of this package's.
    """
    from realistic_indoor.agents.base import RobotSpec

    key, colon, argument = str(name).strip().partition(":")
    key = key.lower()
    if colon and not argument.strip():
        raise ConfigError(f"agent {name!r}: nothing after ':'; give a model file ({key}:<path/to/model.zip>)")
    if key not in AGENTS:
        from realistic_indoor.agents.team import TEAM_AGENTS

        if key in TEAM_AGENTS:
            raise ConfigError(
                f"{key!r} is a team agent: run it on a team environment (evaluate --robots N, "
                "agents.team.make_team_agent)"
            )
        raise ConfigError(f"unknown agent {name!r}; valid: {', '.join(AGENTS)} (ppo as ppo:<model.zip>)")
    if key == "ppo":
        if not argument and "model" not in options:
            raise ConfigError("the ppo agent needs a trained model: ppo:<path/to/model.zip>")
        if argument:
            options["model"] = argument
    elif key == "learned":
        if argument:
            options["model"] = argument
        config = getattr(getattr(env, "unwrapped", env), "config", None)
        if config is not None and hasattr(config, "max_steps"):
            options.setdefault("max_steps", config.max_steps)
    elif argument:
        raise ConfigError(f"agent {key!r} takes no ':' argument, got {name!r}")
    spec = env if isinstance(env, RobotSpec) else RobotSpec.from_env(env)
    module, cls = AGENTS[key].split(":")
    return getattr(importlib.import_module(module), cls)(spec, **options)


def agent_observations(name: str) -> tuple[str, ...]:
    """The environments' extra observations (``EnvConfig.extra_observations``) the agent reads.

    A PPO model (``"ppo:<path>"``) trained with ``global_map`` or ``time_left`` in its view
    needs its environment to compute them; every other agent reads the standard observation
    (the learned explorer computes its candidates on its own side). Evaluation asks this before
    it makes an agent's environment.

    Raises:
        ConfigError: If a PPO model cannot be loaded.
    """
    key, _, argument = str(name).strip().partition(":")
    if key.lower() != "ppo" or not argument.strip():
        return ()
    from realistic_indoor.agents.rl.agent import load_model
    from realistic_indoor.envs.observations import EXTRA_OBSERVATIONS

    reads = load_model(argument).observation_space.spaces
    return tuple(k for k in EXTRA_OBSERVATIONS if k in reads)


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'realistic_indoor.agents' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(__all__)
