"""Recorded episodes of the registered ids, to show a refactor leaves episodes unchanged.

``python tests/envs/recorded_episodes.py`` writes
``tests/envs/data/recorded_episodes.json``; ``test_recorded_episodes.py`` replays each case and
compares. The cases use the keywords ``gym.make`` took when they were recorded (commit 746c667),
so they also show that old keywords keep working.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Any

import gymnasium as gym
import numpy as np

import realistic_indoor  # noqa: F401  (registers the ids)

DATA = Path(__file__).parent / "data" / "recorded_episodes.json"


def _fixed_house() -> dict[str, Any]:
    from realistic_indoor.generator import generate

    return {"building": generate("house", seed=3)}


def _school_generator() -> dict[str, Any]:
    from realistic_indoor.generator import make_generator

    return {"generator": make_generator("school", area_m2=900.0)}


def _plan_file() -> dict[str, Any]:
    from realistic_indoor.generator import generate
    from realistic_indoor.io import save

    path = Path(__file__).parent / "data" / "recorded_office.json"
    if not path.exists():
        save(generate("office", area_m2=500.0, seed=11), path)
    return {"plan_path": str(path)}


CASES: dict[str, dict[str, Any]] = {
    "office-default": {"id": "OfficeExplore-v0", "kwargs": {"area_m2": 600.0}},
    "school-area": {"id": "SchoolExplore-v0", "kwargs": {"area_m2": 1200.0}},
    "house-search": {"id": "HouseSearch-v0", "kwargs": {}, "steps": 400},
    "office-search-discrete": {
        "id": "OfficeSearch-v0",
        "kwargs": {"area_m2": 400.0, "action_type": "discrete", "victims": {"n_victims": 2}},
    },
    "random-explore": {"id": "RandomExplore-v0", "kwargs": {}},
    "office-params": {
        "id": "OfficeExplore-v0",
        "kwargs": {"area_m2": 800.0, "generator_params": {"model": "paper"}},
    },
    "type-override": {"id": "OfficeExplore-v0", "kwargs": {"building_type": "house"}},
    "fixed-building": {"id": "HouseSearch-v0", "kwargs": {}, "extra": "_fixed_house", "steps": 400},
    "victims-beside-start": {
        "id": "HouseSearch-v0",
        "kwargs": {"victims": {"n_victims": 2}},
        "extra": "_fixed_house",
        "steps": 200,
        "victims_beside": [[1.0, 1.5708], [1.2, -1.5708]],
    },
    "generator-callable": {"id": "SchoolExplore-v0", "kwargs": {}, "extra": "_school_generator"},
    "plan-path": {"id": "OfficeExplore-v0", "kwargs": {}, "extra": "_plan_file"},
}
"""Each case: the id, JSON keywords, optionally a function adding keywords that are not JSON and
the steps per episode (else :data:`N_STEPS`) and victims placed beside the start pose, as
``(range m, bearing rad)`` from it (``reset`` option ``victims``)."""

N_STEPS = 40
EPISODES = 2
SEED = 7


VECTOR_CASE = {"id": "OfficeExplore-v0", "num_envs": 3, "kwargs": {"area_m2": 500.0, "max_steps": 25}}
"""A native vector environment (``gym.make_vec``), stepped past its episodes' end."""


def case_kwargs(case: dict[str, Any]) -> dict[str, Any]:
    """The ``gym.make`` keywords of a case."""
    extra = globals()[case["extra"]]() if "extra" in case else {}
    return {**case["kwargs"], **extra}


def run_case(case: dict[str, Any]) -> dict[str, Any]:
    """Two episodes of random actions: rewards, ends, the sum over steps of the victims found so
    far, and a digest of everything observed."""
    env = gym.make(case["id"], **case_kwargs(case))
    env.action_space.seed(SEED)
    digest = hashlib.sha256()
    rewards, ends, found = [], [], 0
    for episode in range(EPISODES):
        obs, info = env.reset(seed=SEED if episode == 0 else None)
        if "victims_beside" in case:
            options = {"victims": _beside(info["start_pose"], case["victims_beside"])}
            obs, info = env.reset(seed=SEED + episode, options=options)
        _update(digest, obs, info)
        for _ in range(case.get("steps", N_STEPS)):
            obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
            _update(digest, obs, info)
            rewards.append(repr(float(reward)))
            ends.append([bool(terminated), bool(truncated)])
            found += int(info.get("victims_found", 0))
            if terminated or truncated:
                break
    env.close()
    return {"rewards": rewards, "ends": ends, "victim_steps": found, "digest": digest.hexdigest()}


def run_vector_case(case: dict[str, Any]) -> dict[str, Any]:
    """60 steps of random actions in a vector environment: rewards and a digest."""
    envs = gym.make_vec(case["id"], num_envs=case["num_envs"], **case["kwargs"])
    envs.action_space.seed(SEED)
    digest = hashlib.sha256()
    obs, _ = envs.reset(seed=SEED)
    rewards = []
    for _ in range(60):
        obs, reward, terminated, truncated, _ = envs.step(envs.action_space.sample())
        _update(digest, obs, {})
        digest.update(np.concatenate([terminated, truncated]).tobytes())
        rewards.append([repr(float(r)) for r in reward])
    envs.close()
    return {"rewards": rewards, "digest": digest.hexdigest()}


def _beside(pose: tuple[float, float, float], polar: list[list[float]]) -> list[list[float]]:
    x, y, theta = pose
    return [[x + r * np.cos(theta + b), y + r * np.sin(theta + b)] for r, b in polar]


def _update(digest: Any, obs: dict[str, np.ndarray], info: dict[str, Any]) -> None:
    for key in sorted(obs):
        digest.update(key.encode())
        digest.update(np.ascontiguousarray(obs[key]).tobytes())
    plain = {k: v for k, v in info.items() if isinstance(v, (int, float, str, bool))}
    digest.update(json.dumps(plain, sort_keys=True).encode())
    for key in ("rewards", "start_pose"):
        if key in info:
            digest.update(repr(info[key]).encode())


def record() -> None:
    """Write every case's recording."""
    DATA.parent.mkdir(parents=True, exist_ok=True)
    out = {name: run_case(case) for name, case in CASES.items()}
    out["vector"] = run_vector_case(VECTOR_CASE)
    DATA.write_text(json.dumps(out, indent=1) + "\n")


if __name__ == "__main__":
    record()
