"""TakeTurns: several environments in one, an episode each in turn, seeded without overlaps.

Expected values are counted by hand: with three environments, episodes 0, 1, 2, 3 run in
environments 0, 1, 2, 0; a seeded reset with seed s and stride w gives them s, s + w, s + 2w.
"""

from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest

from realistic_indoor.agents.rl.turns import TakeTurns
from realistic_indoor.errors import ConfigError


class _Counter(gym.Env):
    """An environment that remembers the seeds of its resets; its observation is its tag."""

    def __init__(self, tag: int, n_obs: int = 8) -> None:
        self.tag = tag
        self.observation_space = gym.spaces.Discrete(n_obs)
        self.action_space = gym.spaces.Discrete(2)
        self.seeds: list[int | None] = []

    def reset(self, *, seed=None, options=None):
        super().reset(seed=seed)
        self.seeds.append(seed)
        return self.tag, {"tag": self.tag}

    def step(self, action):
        return self.tag, float(action), True, False, {"tag": self.tag}

    def action_masks(self) -> np.ndarray:
        return np.array([True, self.tag % 2 == 1])


def _turns(n: int = 3, stride: int = 1) -> TakeTurns:
    return TakeTurns([lambda t=t: _Counter(t) for t in range(n)], seed_stride=stride)


def test_take_turns__episodes_go_round_the_environments():
    env = _turns(3)
    tags = []
    for _ in range(7):
        obs = env.reset()[0]
        tags.append(obs)
        assert env.step(1)[0] == obs  # the step goes to the episode's environment
    assert tags == [0, 1, 2, 0, 1, 2, 0]


def test_take_turns__a_seeded_reset_starts_again_and_spaces_the_seeds_by_the_stride():
    env = _turns(3, stride=2)  # worker 0 of two: worker 1 would take 11, 13, 15
    env.reset()
    env.reset()  # now in environment 1
    assert env.reset(seed=10)[0] == 0  # back to the first
    env.reset()
    env.reset()
    env.reset()  # the first again: its stream goes on unseeded
    assert [e.seeds for e in env.envs] == [[None, 10, None], [None, 12], [14]]


def test_take_turns__methods_it_lacks_are_the_current_environments():
    env = gym.wrappers.RecordEpisodeStatistics(_turns(2))
    env.reset()
    assert env.get_wrapper_attr("action_masks")().tolist() == [True, False]
    env.reset()
    assert env.get_wrapper_attr("action_masks")().tolist() == [True, True]
    assert env.get_wrapper_attr("current").tag == 1


def test_take_turns__environments_with_other_spaces_are_a_one_line_config_error():
    with pytest.raises(ConfigError, match="share their observation and action spaces") as error:
        TakeTurns([lambda: _Counter(0), lambda: _Counter(1, n_obs=9)])
    assert "\n" not in str(error.value)
    with pytest.raises(ConfigError, match="at least one"):
        TakeTurns([])
    with pytest.raises(ConfigError, match="seed_stride"):
        TakeTurns([lambda: _Counter(0)], seed_stride=0)


def test_learned_recipe__two_workers_train_on_every_building_type():
    """Worker i starts at id i % 3 and runs the other two in turn: houses are trained on too."""
    from realistic_indoor.agents.rl.learned import learned_env_factories, learned_preset

    ids = ("OfficeExplore-v0", "SchoolExplore-v0", "HouseExplore-v0")
    factories = learned_env_factories(learned_preset("learned", env_ids=ids, n_envs=2))
    assert [f.env_ids for f in factories] == [ids, (ids[1], ids[2], ids[0])]
    assert {f.seed_stride for f in factories} == {2}
    one = learned_env_factories(learned_preset("learned", env_ids=("RandomExplore-v0",), n_envs=2))
    assert [f.env_ids for f in one] == [("RandomExplore-v0",)] * 2


def test_learned_recipe__an_environment_of_two_ids_runs_both_with_their_own_seeds():
    """Seeded 5 with stride 2, the second id's first episode is its own environment's seed 7."""
    pytest.importorskip("stable_baselines3", reason="the rl extra (stable-baselines3) is not installed")
    from realistic_indoor.agents.rl.learned import LearnedEnvFactory, learned_preset, make_learned_env

    ids = ("HouseExplore-v0", "HouseSearch-v0")
    env = LearnedEnvFactory(ids, learned_preset("learned", env_ids=ids), seed_stride=2)()
    firsts = [env.reset(seed=5)[0], env.reset()[0]]
    assert env.get_wrapper_attr("current").spec.id == ids[1]
    assert env.get_wrapper_attr("action_masks")().shape == (16,)
    for (env_id, seed), obs in zip([(ids[0], 5), (ids[1], 7)], firsts, strict=True):
        alone = make_learned_env(env_id, 16, 100.0)
        expected = alone.reset(seed=seed)[0]
        assert np.array_equal(obs["candidates"], expected["candidates"]), env_id
        alone.close()
    env.close()
