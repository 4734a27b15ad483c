"""TakeTurns: several environments in one, an episode each in turn, seeded without overlaps.

Expected values are counted by hand: with three environments, episodes 0, 1, 2, 3 run in
environments 0, 1, 2, 0; worker i of w, reset with seed s + i, gives environment p the seed
s * w * 3 + i + p * w.
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


def _turns(n: int = 3, workers: int = 1, index: int = 0) -> TakeTurns:
    return TakeTurns([lambda t=t: _Counter(t) for t in range(n)], workers, index)


def test_take_turns__episodes_go_round_the_environments():
    env = _turns(3)
    tags = []
    for _ in range(7):
        obs = env.reset()[0]
        tags.append(obs)
        assert env.step(1)[0] == obs  # the step goes to the episode's environment
    assert tags == [0, 1, 2, 0, 1, 2, 0]


def test_take_turns__a_seeded_reset_starts_again_and_spaces_the_seeds_by_the_workers():
    env = _turns(3, workers=2, index=0)
    env.reset()
    env.reset()  # now in environment 1
    assert env.reset(seed=0)[0] == 0  # back to the first
    env.reset()
    env.reset()
    env.reset()  # the first again: its stream goes on unseeded
    assert [e.seeds for e in env.envs] == [[None, 0, None], [None, 2], [4]]


def test_take_turns__no_two_run_seeds_workers_or_environments_share_a_seed():
    # runs seeded 0..9, two workers (reset with run seed + index), three environments each
    seeds = [
        s for run in range(10) for i in range(2) for s in _turns(3, workers=2, index=i).seeds_for(run + i)
    ]
    assert sorted(seeds) == list(range(60))  # run r takes 6r..6r+5: all distinct
    # run 1, worker 1 (seed 2): 1 * 2 * 3 + 1 + p * 2
    assert _turns(3, workers=2, index=1).seeds_for(2) == [7, 9, 11]
    # one environment: worker i of run s gets s * w + i (run 0 keeps the plain s + i)
    assert [_turns(1, workers=2, index=i).seeds_for(s + i)[0] for s in (0, 1) for i in (0, 1)] == [0, 1, 2, 3]


def test_take_turns__under_a_stable_baselines3_vector_env_masks_follow_the_auto_reset():
    pytest.importorskip("stable_baselines3", reason="the rl extra (stable-baselines3) is not installed")
    from stable_baselines3.common.monitor import Monitor
    from stable_baselines3.common.vec_env import DummyVecEnv

    venv = DummyVecEnv([lambda: Monitor(_turns(2))])
    venv.seed(10)
    assert venv.reset()[0] == 0
    assert venv.env_method("action_masks")[0].tolist() == [True, False]
    obs, _, done, infos = venv.step([1])  # every episode is one step: done, reset into environment 1
    assert done[0] and obs[0] == 1 and infos[0]["env_id"] == "0" and "episode" in infos[0]
    assert venv.env_method("action_masks")[0].tolist() == [True, True]
    assert venv.get_attr("turn") == [1]
    # run seed 10, one worker, two environments: 10 * 1 * 2 + p
    assert [e.seeds for e in venv.envs[0].get_wrapper_attr("envs")] == [[20], [21]]


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
    with pytest.raises(ConfigError, match="workers"):
        TakeTurns([lambda: _Counter(0)], workers=0)
    with pytest.raises(ConfigError, match="below workers"):
        TakeTurns([lambda: _Counter(0)], workers=2, index=2)
    with pytest.raises(ConfigError, match="seed >= 0"):
        _turns(2, workers=2, index=1).reset(seed=0)


def test_learned_recipe__two_workers_train_on_every_building_type():
    """Worker i starts at id i % 3 and runs the other two in turn: houses are trained on too."""
    from realistic_indoor.agents.rl.learned import learned_env_factories, learned_preset

    ids = ("OfficeExplore-v0", "SchoolExplore-v0", "HouseExplore-v0")
    factories = learned_env_factories(learned_preset("learned", env_ids=ids, n_envs=2))
    assert [f.env_ids for f in factories] == [ids, (ids[1], ids[2], ids[0])]
    assert [(f.workers, f.index) for f in factories] == [(2, 0), (2, 1)]
    one = learned_env_factories(learned_preset("learned", env_ids=("RandomExplore-v0",), n_envs=2))
    assert [f.env_ids for f in one] == [("RandomExplore-v0",)] * 2


def test_learned_recipe__an_environment_of_two_ids_runs_both_with_their_own_seeds():
    """Worker 0 of 2 seeded 5: its first id's first episode has seed 5 * 2 * 2 = 20, its second's 22."""
    pytest.importorskip("stable_baselines3", reason="the rl extra (stable-baselines3) is not installed")
    from realistic_indoor.agents.rl.learned import LearnedEnvFactory, learned_preset, make_learned_env

    ids = ("HouseExplore-v0", "HouseSearch-v0")
    env = LearnedEnvFactory(ids, learned_preset("learned", env_ids=ids), workers=2, index=0)()
    firsts = [env.reset(seed=5), env.reset()]
    assert [info["env_id"] for _, info in firsts] == list(ids)
    assert env.get_wrapper_attr("action_masks")().shape == (16,)
    for (env_id, seed), (obs, _) in zip([(ids[0], 20), (ids[1], 22)], firsts, strict=True):
        alone = make_learned_env(env_id, 16, 100.0)
        expected = alone.reset(seed=seed)[0]
        assert np.array_equal(obs["candidates"], expected["candidates"]), env_id
        alone.close()
    env.close()
