"""The learned explorer per robot: the single-robot policy sees what it saw alone, robot by robot."""

from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest

pytest.importorskip("pettingzoo", reason="the team environments need PettingZoo (the 'teams' extra)")

from agent_helpers import AlwaysChoose, team_actions

from realistic_indoor import teams
from realistic_indoor.agents import make_agent
from realistic_indoor.agents.team import make_team_agent
from realistic_indoor.errors import ConfigError

OFFICE = {"area_m2": 300.0, "max_steps": 250}
"""A small office and a short episode keep the tests fast."""


def single_run(model, seed):
    """The single-robot learned agent's actions and what its policy saw, on the small office."""
    env = gym.make("OfficeExplore-v0", **OFFICE)
    agent = make_agent("learned", env, model=model)
    obs, info = env.reset(seed=seed)
    agent.reset()
    actions = []
    done = False
    while not done:
        action = agent.act(obs, info)
        actions.append(np.asarray(action))
        obs, _, terminated, truncated, info = env.step(action)
        done = terminated or truncated
    return np.array(actions)


def test_choosing_0__every_robot_goes_to_its_nearest_frontier_as_uncoordinated_frontier_does():
    env = teams.parallel_env("OfficeExplore-v0", n_robots=3, comm="unlimited", **OFFICE)
    model = AlwaysChoose(0)
    learned = team_actions(make_team_agent("learned", env, model=model), env, seed=3, steps=200)
    frontier = team_actions(make_team_agent("frontier", env), env, seed=3, steps=200)
    assert np.array_equal(learned, frontier)
    assert len(model.seen) > 3  # the policy was asked, robot by robot


def test_one_robot_alone__the_policy_sees_and_does_what_the_single_learned_agent_does():
    model, alone = AlwaysChoose(1), AlwaysChoose(1)
    expected = single_run(alone, seed=6)
    env = teams.parallel_env("OfficeExplore-v0", n_robots=1, comm="none", map_sharing="own", **OFFICE)
    agent = make_team_agent("learned", env, model=model)
    assert agent.max_steps == OFFICE["max_steps"]  # read from the environment
    actions = team_actions(agent, env, seed=6)
    assert np.array_equal(actions[:, 0], expected)
    assert len(model.seen) == len(alone.seen) == agent.decisions
    for team_saw, single_saw in zip(model.seen, alone.seen, strict=True):
        assert np.array_equal(team_saw["mask"], single_saw["mask"])
        for key in ("candidates", "time_left"):
            assert np.array_equal(team_saw["obs"][key], single_saw["obs"][key])


def test_a_choice_other_than_0__drives_somewhere_else_than_the_nearest_frontier():
    env = teams.parallel_env("OfficeExplore-v0", n_robots=2, comm="unlimited", **OFFICE)
    second = team_actions(make_team_agent("learned", env, model=AlwaysChoose(1)), env, seed=3, steps=120)
    nearest = team_actions(make_team_agent("learned", env, model=AlwaysChoose(0)), env, seed=3, steps=120)
    assert not np.array_equal(second, nearest)


def test_committed_model__a_team_of_two_explores_an_office():
    pytest.importorskip("sb3_contrib", reason="the rl extra (sb3-contrib, torch) is not installed")
    env = teams.parallel_env("OfficeExplore-v0", n_robots=2, area_m2=300.0, max_steps=600)
    agent = make_team_agent("learned", env)
    observations, infos = env.reset(seed=0)
    agent.reset(seed=0)
    while env.agents:
        observations, _, _, _, infos = env.step(agent.act(observations, infos))
    assert agent.decisions > 2
    assert next(iter(infos.values()))["coverage"] > 0.5


def test_names__a_model_file_is_given_after_learned_and_nowhere_else(tmp_path):
    env = teams.parallel_env("OfficeExplore-v0", n_robots=2, **OFFICE)
    with pytest.raises(ConfigError, match="only learned takes"):
        make_team_agent("frontier:model.zip", env)
    with pytest.raises(ConfigError, match="only learned takes"):
        make_team_agent("learned:", env)
    with pytest.raises(ConfigError) as error:
        make_team_agent(f"learned:{tmp_path / 'missing.zip'}", env)
    assert "\n" not in str(error.value)
