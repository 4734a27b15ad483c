"""Team explorers: baselines that drive every robot of a team environment at once.

A team agent has ``reset(seed=None)`` and ``act(observations, infos) -> actions``, dicts keyed
by agent (``robot_0`` ...), and sees only what the robots sense; a robot knows its teammates'
positions, goals and maps only through its links::

    from realistic_indoor import teams
    from realistic_indoor.agents.team import make_team_agent

    env = teams.parallel_env("OfficeExplore-v0", n_robots=4)
    agent = make_team_agent("coordinated", env)
    observations, infos = env.reset(seed=0)
    agent.reset(seed=0)
    while env.agents:
        observations, rewards, terminations, truncations, infos = env.step(agent.act(observations, infos))

Names (:data:`TEAM_AGENTS`): ``frontier`` (each robot its nearest frontier), ``coordinated``
(Burgard et al. 2005), ``hungarian`` (robots matched to frontiers by path cost), ``learned``
(the learned explorer's policy per robot; ``learned:<model.zip>`` for another model). See
``docs/teams.md``.
"""

from __future__ import annotations

import importlib
from typing import Any

from realistic_indoor.agents.team.base import TeamAgent, TeamSpec
from realistic_indoor.errors import ConfigError

__all__ = ["TEAM_AGENTS", "TeamAgent", "TeamSpec", "make_team_agent"]

TEAM_AGENTS: dict[str, str] = {
    "frontier": "realistic_indoor.agents.team.frontier:TeamFrontierAgent",
    "coordinated": "realistic_indoor.agents.team.coordinated:CoordinatedAgent",
    "hungarian": "realistic_indoor.agents.team.hungarian:HungarianAgent",
    "learned": "realistic_indoor.agents.team.learned:TeamLearnedAgent",
}
"""Team agent names and their ``module:Class``."""


def make_team_agent(name: str, env: Any, **options: Any) -> TeamAgent:
    """The team agent called ``name`` for the robots of the team environment ``env``.

    Args:
        name: A key of :data:`TEAM_AGENTS`; ``"learned:<path>"`` runs the learned explorer
            saved at ``path`` on every robot (``"learned"`` alone: the committed one).
        env: A team environment (:func:`realistic_indoor.teams.parallel_env`; only its robots'
            sensors, limits, number and map sharing are read), or a :class:`TeamSpec`.
        **options: Keyword arguments of the agent's class (``config=``).

    Raises:
        ConfigError: For an unknown name (the message lists the valid ones), a ``:`` argument
            to an agent other than ``learned``, a missing model, or an environment that is not a
            team environment.
    """
    key, colon, argument = str(name).strip().partition(":")
    key = key.lower()
    if key not in TEAM_AGENTS:
        raise ConfigError(
            f"unknown team agent {name!r}; valid: {', '.join(TEAM_AGENTS)} (single-robot agents run without teams)"
        )
    if colon and (key != "learned" or not argument.strip()):
        raise ConfigError(
            f"team agent {name!r}: only learned takes a ':' argument, a model file (learned:<path/to/model.zip>)"
        )
    if key == "learned":
        if argument:
            options["model"] = argument.strip()
        config = getattr(getattr(env, "unwrapped", env), "config", None)
        if config is not None and hasattr(config, "max_steps"):
            options.setdefault("max_steps", config.max_steps)
    spec = env if isinstance(env, TeamSpec) else TeamSpec.from_env(env)
    module, cls = TEAM_AGENTS[key].split(":")
    return getattr(importlib.import_module(module), cls)(spec, **options)
