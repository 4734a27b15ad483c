"""Team explorers: one robot is the single explorer, links bound what robots know, the team spreads out."""

from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest

pytest.importorskip("pettingzoo", reason="the team environments need PettingZoo (the 'teams' extra)")

from agent_helpers import team_actions

from realistic_indoor import teams
from realistic_indoor.agents import make_agent
from realistic_indoor.agents.team import TEAM_AGENTS, TeamSpec, make_team_agent
from realistic_indoor.errors import ConfigError

OFFICE = {"area_m2": 300.0, "max_steps": 250}
"""A small office and a short episode keep the tests fast."""


@pytest.mark.parametrize("name", sorted(set(TEAM_AGENTS) - {"learned"}))
def test_one_robot__every_classical_team_agent_drives_as_the_single_frontier_explorer(name):
    single = gym.make("OfficeExplore-v0", **OFFICE)
    explorer = make_agent("frontier", single)
    obs, info = single.reset(seed=4)
    explorer.reset(seed=4)
    expected = []
    done = False
    while not done:
        action = explorer.act(obs, info)
        expected.append(np.asarray(action))
        obs, _, terminated, truncated, info = single.step(action)
        done = terminated or truncated
    env = teams.parallel_env("OfficeExplore-v0", n_robots=1, comm="none", map_sharing="own", **OFFICE)
    actions = team_actions(make_team_agent(name, env), env, seed=4)
    assert np.array_equal(actions[:, 0], np.array(expected))


@pytest.mark.parametrize("name", ["coordinated", "hungarian"])
def test_without_links__a_coordinated_robot_knows_no_teammate_and_drives_as_an_uncoordinated_one(name):
    env = teams.parallel_env("OfficeExplore-v0", n_robots=2, comm="none", map_sharing="comm", **OFFICE)
    agent = make_team_agent(name, env)
    observations, infos = env.reset(seed=2)
    agent.reset(seed=2)
    agent.act(observations, infos)
    assert agent.teammates(0) == [] and agent.teammates(1) == []
    assert agent.navigators[0].map is not agent.navigators[1].map
    uncoordinated = team_actions(make_team_agent("frontier", env), env, seed=2, steps=150)
    assert np.array_equal(team_actions(agent, env, seed=2, steps=150), uncoordinated)


def test_unlimited_links__robots_share_one_map_and_know_each_others_goals():
    env = teams.parallel_env("OfficeExplore-v0", n_robots=3, comm="unlimited", map_sharing="comm", **OFFICE)
    agent = make_team_agent("coordinated", env)
    team_actions(agent, env, seed=1, steps=20)
    maps = {id(nav.map) for nav in agent.navigators}
    assert len(maps) == 1
    mates = agent.teammates(1)
    assert [m.robot for m in mates] == [0, 2]
    assert mates[0].goal == agent.navigators[0].goal


def test_coordinated__four_robots_head_for_different_places_where_uncoordinated_ones_bunch():
    env = teams.parallel_env("OfficeExplore-v0", n_robots=4, comm="unlimited", **OFFICE)

    def spread(name):
        agent = make_team_agent(name, env)
        team_actions(agent, env, seed=0, steps=30)
        goals = np.array([nav.goal for nav in agent.navigators if nav.goal is not None])
        return len(goals), min(np.hypot(*(a - b)) for i, a in enumerate(goals) for b in goals[i + 1 :])

    count, closest = spread("coordinated")
    assert count == 4 and closest > 1.0


def test_same_seed__same_team_episode():
    env = teams.parallel_env("OfficeExplore-v0", n_robots=3, comm="wss", **OFFICE)
    agent = make_team_agent("coordinated", env)
    first = team_actions(agent, env, seed=7, steps=120)
    assert np.array_equal(first, team_actions(agent, env, seed=7, steps=120))


def test_bad_input__one_line_config_errors():
    with pytest.raises(
        ConfigError,
        match=r"unknown team agent .burgard.; valid: frontier, coordinated, hungarian, learned \(single",
    ):
        make_team_agent("burgard", teams.parallel_env("OfficeExplore-v0", n_robots=2, **OFFICE))
    with pytest.raises(ConfigError, match="team agents need a team environment"):
        make_team_agent("frontier", gym.make("OfficeExplore-v0", **OFFICE))
    env = teams.parallel_env("OfficeExplore-v0", n_robots=2, **OFFICE)
    agent = make_team_agent("frontier", env)
    observations, _ = env.reset(seed=0)
    with pytest.raises(ConfigError, match="start_pose of robot_0 missing"):
        agent.act(observations, {a: {} for a in observations})
    with pytest.raises(ConfigError, match="n_robots"):
        TeamSpec(TeamSpec.from_env(env).robot, n_robots=teams.MAX_ROBOTS + 1)


@pytest.mark.parametrize(("comm", "told"), [("unlimited", True), ("none", False)])
def test_search__a_linked_teammate_knows_a_detected_victim_as_taken_and_an_unlinked_one_does_not(comm, told):
    env = teams.parallel_env("OfficeSearch-v0", n_robots=2, comm=comm, map_sharing="comm", **OFFICE)
    agent = make_team_agent("frontier", env)
    observations, infos = env.reset(seed=1)
    agent.reset(seed=1)
    first = None
    while env.agents and first is None:
        observations, _, _, _, infos = env.step(agent.act(observations, infos))
        seen = [len(nav.victims.positions) for nav in agent.navigators]
        first = next((i for i, n in enumerate(seen) if n), None)
    assert first is not None, "no victim detected in the episode"
    other = agent.navigators[1 - first].victims
    agent.act(observations, infos)
    detected = agent.navigators[first].victims.positions[0]
    known = [bool(np.hypot(*(p - detected)) < 1.0) for p in other.positions]
    assert any(known) == told
    if told:
        assert other.visited[known.index(True)]
