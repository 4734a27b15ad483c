import gymnasium as gym
import numpy as np
import pytest
from agent_helpers import drive

from realistic_indoor.agents import make_agent
from realistic_indoor.agents.explorer import ExplorerConfig
from realistic_indoor.errors import ConfigError


def test_frontier_agent__covers_a_hand_made_office(hall_office):
    env = gym.make("OfficeExplore-v0", building=hall_office, max_steps=600, max_episode_steps=600)
    agent = make_agent("frontier", env)
    actions, info = drive(env, agent)
    assert info["coverage"] >= 0.9
    assert len(actions) < 600
    assert info["collisions"] <= 15


def test_frontier_agent__same_seed_same_actions(hall_office):
    env = gym.make("OfficeExplore-v0", building=hall_office)
    agent = make_agent("frontier", env)
    first, _ = drive(env, agent, seed=3, steps=150)
    second, _ = drive(env, agent, seed=3, steps=150)
    assert np.array_equal(np.array(first), np.array(second))


def test_frontier_agent__search_goes_to_victims(hall_office):
    env = gym.make("OfficeSearch-v0", building=hall_office, max_steps=1200, max_episode_steps=1200)
    agent = make_agent("frontier", env)
    _, info = drive(env, agent, seed=1)
    assert info["victims_found"] == info["victims_total"]
    truth, _ = env.unwrapped.victims
    start = env.unwrapped.simulation.world.start_pose
    c, s = np.cos(start[2]), np.sin(start[2])
    seen = agent.victims.positions @ np.array([[c, s], [-s, c]]) + start[:2]  # odometry -> world
    assert len(seen) >= 2  # the last victim ends the episode before the agent sees it
    assert all(np.min(np.hypot(*(truth - p).T)) < 0.2 for p in seen)
    assert agent.victims.visited.all()


def test_frontier_agent__discrete_actions(hall_office):
    env = gym.make("OfficeExplore-v0", building=hall_office, action_type="discrete")
    agent = make_agent("frontier", env)
    actions, info = drive(env, agent, steps=200)
    assert all(isinstance(a, int) for a in actions)
    assert info["coverage"] > 0.3


def test_explorer_config__rejects_bad_values():
    with pytest.raises(ConfigError, match="map_resolution_m"):
        ExplorerConfig(map_resolution_m=0.0)
    with pytest.raises(ConfigError, match="stuck_steps"):
        ExplorerConfig(stuck_steps=1)
