"""The stable-baselines3 adapter of the native vector envs: SB3's autoreset, Monitor's infos, PPO."""

from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import data_equivalence

pytest.importorskip("stable_baselines3")

from realistic_indoor.agents.rl import ppo_preset
from realistic_indoor.agents.rl.batched_vec_env import BatchedVecEnv
from realistic_indoor.agents.rl.envs import make_vec_env
from realistic_indoor.envs.render import tile

KEYS = ("scan", "local_map", "velocity")


def _venv(n: int = 3, max_steps: int = 5, **kwargs) -> BatchedVecEnv:
    envs = gym.make_vec(
        "OfficeExplore-v0", num_envs=n, area_m2=300.0, max_steps=max_steps, action_type="discrete", **kwargs
    )
    return BatchedVecEnv([envs], KEYS)


def test_batched_vec_env__resets_in_the_same_step_with_terminal_observation_and_episode():
    venv = _venv()
    venv.seed(0)
    obs = venv.reset()
    assert set(obs) == set(KEYS) and obs["scan"].shape == (3, 109)
    for _ in range(5):
        obs, reward, done, infos = venv.step(np.array([1, 1, 1]))
    assert reward.dtype == np.float32 and done.all()
    for k, info in enumerate(infos):
        assert info["TimeLimit.truncated"] and info["episode"]["l"] == 5
        assert set(info["terminal_observation"]) == set(KEYS)
        assert not np.array_equal(info["terminal_observation"]["local_map"], obs["local_map"][k])
    assert (obs["velocity"] == 0).all()  # the new episodes' first observations: at rest
    obs, _, done, infos = venv.step(np.array([1, 1, 1]))
    assert not done.any() and all("episode" not in i for i in infos)  # no second reset next step


def test_batched_vec_env__renders_every_sub_env_in_its_numbering():
    groups = [
        gym.make_vec(env_id, num_envs=n, area_m2=300.0, render_mode="rgb_array")
        for env_id, n in (("OfficeExplore-v0", 2), ("HouseExplore-v0", 1))
    ]
    venv = BatchedVecEnv(groups, KEYS, order=[0, 2, 1])  # office, house, office
    assert venv.render_mode == "rgb_array"
    venv.seed(5)
    venv.reset()
    venv.step(np.zeros((3, 2), np.float32))
    images = venv.get_images()
    office, house = groups[0].render(), groups[1].render()
    for got, want in zip(images, [office[0], house[0], office[1]], strict=True):
        np.testing.assert_array_equal(got, want)
    np.testing.assert_array_equal(venv.render(), tile(images))
    with pytest.warns(UserWarning, match='render_mode="human"'):
        assert venv.render("human") is None
    with pytest.warns(UserWarning, match="no `render_mode`"):
        assert _venv().render() is None  # SB3's own answer


def test_batched_vec_env__refuses_an_order_that_is_no_permutation():
    envs = gym.make_vec("OfficeExplore-v0", num_envs=2, area_m2=300.0)
    with pytest.raises(ValueError, match="permutation"):
        BatchedVecEnv([envs], KEYS, order=[0, 0])


def test_batched_vec_env__restart_leaves_other_sub_envs_as_they_are():
    envs = gym.make_vec("OfficeExplore-v0", num_envs=2, area_m2=300.0)
    envs.reset(seed=1)
    obs, *_ = envs.step(np.array([[1.0, 0.3], [1.0, -0.3]], dtype=np.float32))
    again = envs.restart(np.array([0]))
    assert np.array_equal(again["scan"][1], obs["scan"][1])
    assert np.array_equal(again["pose"][1], obs["pose"][1])
    assert np.allclose(again["pose"][0], 0.0) and np.allclose(again["velocity"][0], 0.0)


def test_batched_vec_env__same_seed_same_rollout():
    def rollout():
        venv = _venv(max_steps=4)
        venv.seed(3)
        out = [venv.reset()["scan"]]
        for a in range(10):
            out.append(venv.step(np.full(3, a % 6))[0]["scan"])
        return np.stack(out)

    assert np.array_equal(rollout(), rollout())


def test_make_vec_env__batched_mixes_the_ids_in_one_vec_env():
    config = ppo_preset("smoke", vec_env="batched", n_envs=4)
    venv = make_vec_env(config)
    assert isinstance(venv, BatchedVecEnv) and venv.num_envs == 4
    assert [g.num_envs for g in venv.groups] == [2, 1, 1]  # office, school, house in turn
    obs = venv.reset()
    assert obs["local_map"].shape == (4, 1, 64, 64)
    venv.close()


def test_make_vec_env__batched_steps_the_episodes_of_the_dummy_vec_env():
    def rollout(vec_env):
        config = ppo_preset("smoke", vec_env=vec_env, n_envs=4, max_steps=12, seed=5)
        venv = make_vec_env(config)  # offices, schools and houses in turn, seeds 5 to 8
        rng = np.random.default_rng(0)
        out = [dict(venv.reset())]
        for _ in range(30):  # across two resets of every sub-environment
            obs, reward, done, infos = venv.step(rng.integers(0, 6, 4))
            out += [dict(obs), reward, done, [i["TimeLimit.truncated"] for i in infos]]
            out += [
                {k: i[k] for k in ("coverage", "observed_area_m2", "path_length_m", "collisions", "rewards")}
                for i in infos
            ]
            out += [{k: v for k, v in i["episode"].items() if k != "t"} for i in infos if "episode" in i]
            out += [dict(i["terminal_observation"]) for i in infos if "terminal_observation" in i]
        venv.close()
        return out

    batched, dummy = rollout("batched"), rollout("dummy")
    assert data_equivalence(batched, dummy, exact=True)
    assert sum(1 for item in dummy if isinstance(item, dict) and "l" in item) == 8  # 2 episodes each


def test_make_vec_env__search_ids_train_batched_with_the_victim_sensor():
    config = ppo_preset("smoke", env_ids=("HouseSearch-v0",), vec_env="batched", n_envs=2, max_steps=5)
    venv = make_vec_env(config)
    assert isinstance(venv, BatchedVecEnv)
    obs = venv.reset()
    assert obs["victims"].shape == (2, 9)
    for _ in range(5):
        obs, _, done, infos = venv.step(np.array([venv.action_space.sample() for _ in range(2)]))
    assert done.all() and all(info["episode"]["l"] == 5 for info in infos)
    venv.close()


def test_ppo__learns_a_few_hundred_steps_on_the_batched_vec_env(request):
    import torch
    from stable_baselines3 import PPO

    threads = torch.get_num_threads()
    torch.set_num_threads(1)
    request.addfinalizer(lambda: torch.set_num_threads(threads))
    venv = _venv(n=4, max_steps=50)
    model = PPO("MultiInputPolicy", venv, n_steps=64, batch_size=64, n_epochs=1, seed=0, device="cpu")
    model.learn(total_timesteps=512)
    assert model.num_timesteps >= 512
    assert len(model.ep_info_buffer) >= 4  # Monitor-like episode records reached SB3
