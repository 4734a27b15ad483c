import gymnasium as gym
import numpy as np
import pytest
from agent_helpers import drive, small_env

from realistic_indoor.agents import AGENTS, RandomAgent, RobotSpec, make_agent
from realistic_indoor.envs import PRESETS
from realistic_indoor.envs.search import SearchEnv
from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.lidar import beam_offsets

try:
    import sb3_contrib  # noqa: F401 - the learned explorer's model needs it

    _RL = True
except ImportError:
    _RL = False
MAP_FREE_AGENTS = [
    pytest.param(
        name, marks=pytest.mark.skipif(name == "learned" and not _RL, reason="the rl extra is absent")
    )
    for name in AGENTS
    if name != "ppo"
]


@pytest.mark.parametrize("env_id", sorted(PRESETS))
@pytest.mark.parametrize("name", MAP_FREE_AGENTS)
def test_every_agent__runs_on_every_registered_id(name, env_id):
    env = small_env(env_id, max_steps=30)
    agent = make_agent(name, env)
    actions, info = drive(env, agent, seed=1)
    assert (
        len(actions) == 30
        or info["coverage"] >= 0.9
        or info.get("victims_found") == info.get("victims_total")
    )


class _Blindfolded(SearchEnv):
    """A search environment whose building and simulator cannot be read from outside."""

    @property
    def building(self):
        raise AssertionError("an agent read the building")

    @property
    def simulation(self):
        raise AssertionError("an agent read the simulator")

    @property
    def victims(self):
        raise AssertionError("an agent read the victims")


@pytest.mark.parametrize("name", MAP_FREE_AGENTS)
def test_every_agent__needs_only_observations_and_info(name, hall_office):
    env = _Blindfolded(building=hall_office, max_steps=300)
    agent = make_agent(name, RobotSpec.from_env(env))
    actions, info = drive(env, agent, seed=2)
    assert len(actions) == 300 or info["victims_found"] == info["victims_total"]
    if name in ("frontier", "utility", "structure", "learned"):
        assert info["victims_found"] >= 1


def test_make_agent__unknown_name_lists_the_valid_ones(hall_office):
    env = gym.make("OfficeExplore-v0", building=hall_office)
    with pytest.raises(ConfigError, match=r"unknown agent 'astar'.*frontier"):
        make_agent("astar", env)
    with pytest.raises(ConfigError, match=r"ppo:<path/to/model.zip>"):
        make_agent("ppo", env)
    with pytest.raises(ConfigError, match="takes no ':' argument"):
        make_agent("frontier:fast", env)


def test_make_agent__needs_an_environment_of_this_package():
    with pytest.raises(ConfigError, match="realistic_indoor environment"):
        make_agent("random", gym.make("CartPole-v1"))


def test_make_agent__refuses_a_macro_environment_in_one_line():
    with pytest.raises(ConfigError, match="action_type 'continuous' or 'discrete', not 'frontier'") as error:
        make_agent("frontier", gym.make("HouseExplore-v0", action_type="frontier"))
    assert "\n" not in str(error.value)


def test_make_agent__passes_options_and_accepts_a_spec():
    agent = make_agent("random", RobotSpec(), hold_steps=3, seed=0)
    assert isinstance(agent, RandomAgent) and agent.hold_steps == 3


def test_robot_spec__reads_the_environment(hall_office):
    env = gym.make("OfficeSearch-v0", building=hall_office, lidar={"n_beams": 61}, action_type="discrete")
    spec = RobotSpec.from_env(env)
    assert spec.lidar.n_beams == 61 and len(beam_offsets(spec.lidar)) == 61
    assert spec.victims is not None and spec.action_type == "discrete"
    assert RobotSpec.from_env(gym.make("OfficeExplore-v0", building=hall_office)).victims is None
    assert spec.action(1.0, 0.0) == 0  # forward
    assert spec.action(0.0, -2.0) == 4  # turn right


def test_random_agent__seeded_and_held(hall_office):
    env = gym.make("OfficeExplore-v0", building=hall_office)
    agent = make_agent("random", env, hold_steps=2)
    first, _ = drive(env, agent, seed=5, steps=20)
    second, _ = drive(env, agent, seed=5, steps=20)
    assert np.array_equal(first, second)
    assert np.array_equal(first[0], first[1]) and not np.array_equal(first[1], first[2])


def test_wall_follower__explores_along_the_walls_and_through_doors_without_crashing(hall_office):
    from shapely.geometry import Point

    env = gym.make("OfficeExplore-v0", building=hall_office, max_steps=400, max_episode_steps=400)
    agent = make_agent("wall", env)
    _, info = drive(env, agent)
    offices = [r.polygon for r in hall_office.rooms if r.function == "office"]
    entered = {
        i
        for x, y in env.unwrapped.simulation.trajectory
        for i, p in enumerate(offices)
        if p.contains(Point(x, y))
    }
    assert len(entered) >= 2  # through 0.9 m doors off the corridor, not only past them
    assert info["coverage"] >= 0.75
    assert info["collisions"] <= 5
