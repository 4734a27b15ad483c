"""The rerun recorder writes a replayable .rrd file of the episodes."""

from __future__ import annotations

import sys

import gymnasium as gym
import pytest
from env_helpers import make_env

from realistic_indoor.envs import RerunRecorder, record_rerun
from realistic_indoor.errors import ConfigError


def _rows_by_entity(path) -> dict[str, int]:
    from rerun.chunk import RrdReader

    rows: dict[str, int] = {}
    for chunk in RrdReader(path).stream():
        rows[chunk.entity_path] = rows.get(chunk.entity_path, 0) + chunk.num_rows
    return rows


def test_recorder__writes_plan_map_scans_trajectory_victims_and_metrics(tmp_path):
    path = tmp_path / "search.rrd"
    env = record_rerun(make_env("OfficeSearch-v0", max_steps=12), path, map_every=5)
    env.reset(seed=0)
    steps = 0
    for _ in range(20):  # one reset on the way
        _, _, terminated, truncated, _ = env.step(env.action_space.sample())
        steps += 1
        if terminated or truncated:
            env.reset()
    env.close()
    env.close()
    rows = _rows_by_entity(path)
    for entity in ("/world/plan", "/world/map", "/world/trajectory", "/world/victims", "/metrics/coverage"):
        assert rows.get(entity, 0) > 0, entity
    assert rows["/world/robot"] == rows["/world/scan"] == steps + 2  # two resets
    assert rows["/metrics/reward"] == steps
    assert rows["/world/plan"] == 2  # the toy generator draws a new building per episode


def test_recorder__refuses_other_environments(tmp_path):
    with pytest.raises(ConfigError, match="realistic-indoor"):
        RerunRecorder(gym.make("CartPole-v1"), tmp_path / "x.rrd")


def test_recorder__without_rerun_names_the_pip_extra(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "rerun", None)
    with pytest.raises(gym.error.DependencyNotInstalled, match=r"realistic-indoor\[viz\]"):
        record_rerun(make_env("OfficeExplore-v0"), tmp_path / "x.rrd")
