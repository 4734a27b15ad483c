"""Recorded episodes of the map-based explorers, to show a refactor leaves their choices unchanged.

``python tests/agents/recorded_explorers.py`` writes ``tests/agents/data/recorded_explorers.json``;
``test_recorded_explorers.py`` replays each case and compares a digest of every action the
explorer took. Regenerate only when a change is meant to alter the explorers' episodes, and say
so in the commit.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Any

import gymnasium as gym
import numpy as np

import realistic_indoor.envs  # noqa: F401  (registers the ids)
from realistic_indoor.agents import make_agent

DATA = Path(__file__).parent / "data" / "recorded_explorers.json"

AGENT_NAMES = ("frontier", "utility", "structure")
ENV_CASES: dict[str, dict[str, Any]] = {
    "office": {"id": "OfficeExplore-v0", "kwargs": {"area_m2": 600.0}, "seed": 3},
    "school": {"id": "SchoolExplore-v0", "kwargs": {"area_m2": 900.0}, "seed": 4},
    "house-search": {"id": "HouseSearch-v0", "kwargs": {}, "seed": 5},
    "random-discrete": {"id": "RandomExplore-v0", "kwargs": {"action_type": "discrete"}, "seed": 6},
}
"""Each environment case: the id, its ``gym.make`` keywords and the episode's seed."""

N_STEPS = 300


def run_case(agent_name: str, case: dict[str, Any]) -> dict[str, Any]:
    """One episode of ``N_STEPS`` (or fewer, if it ends): a digest of the actions and the last coverage."""
    env = gym.make(case["id"], **case["kwargs"])
    agent = make_agent(agent_name, env)
    obs, info = env.reset(seed=case["seed"])
    agent.reset(seed=case["seed"])
    digest = hashlib.sha256()
    steps = 0
    for steps in range(1, N_STEPS + 1):  # noqa: B007 - the count is reported
        action = agent.act(obs, info)
        digest.update(np.asarray(action).tobytes())
        obs, _, terminated, truncated, info = env.step(action)
        if terminated or truncated:
            break
    env.close()
    return {"steps": steps, "coverage": repr(float(info["coverage"])), "digest": digest.hexdigest()}


def record() -> None:
    """Write every case's recording."""
    DATA.parent.mkdir(parents=True, exist_ok=True)
    out = {
        f"{agent}/{name}": run_case(agent, case) for agent in AGENT_NAMES for name, case in ENV_CASES.items()
    }
    DATA.write_text(json.dumps(out, indent=1) + "\n")


if __name__ == "__main__":
    record()
