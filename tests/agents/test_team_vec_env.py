"""One shared policy over a team: every robot a sub-environment of one stable-baselines3 VecEnv."""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("pettingzoo", reason="the team environments need PettingZoo (the 'teams' extra)")
pytest.importorskip("stable_baselines3", reason="TeamVecEnv needs stable-baselines3 (the 'rl' extra)")

from realistic_indoor import teams
from realistic_indoor.agents.rl.team_vec_env import TeamVecEnv
from realistic_indoor.errors import ConfigError

KWARGS = {"area_m2": 300.0, "action_type": "discrete"}


def team(n_robots=2, **kwargs):
    return teams.parallel_env("OfficeExplore-v0", n_robots=n_robots, **{**KWARGS, **kwargs})


def test_robots_of_every_team_are_the_sub_environments_in_order():
    venv = TeamVecEnv([team(2), team(2)])
    venv.seed(10)
    obs = venv.reset()
    # team j is seeded with its first robot's seed: 10 and 12
    direct = [team(2), team(2)]
    first = [d.reset(seed=s)[0] for d, s in zip(direct, (10, 12), strict=True)]
    assert venv.num_envs == 4
    for key in venv.keys:
        expected = np.stack([first[0]["robot_0"][key], first[0]["robot_1"][key],
                             first[1]["robot_0"][key], first[1]["robot_1"][key]])  # fmt: skip
        assert np.array_equal(obs[key], expected), key
    actions = np.array([2, 0, 5, 1])
    obs, rewards, dones, infos = venv.step(actions)
    out0 = direct[0].step({"robot_0": 2, "robot_1": 0})
    out1 = direct[1].step({"robot_0": 5, "robot_1": 1})
    assert rewards.tolist() == pytest.approx(
        [out0[1]["robot_0"], out0[1]["robot_1"], out1[1]["robot_0"], out1[1]["robot_1"]]
    )
    assert np.array_equal(obs["scan"][3], out1[0]["robot_1"]["scan"])
    assert not dones.any()
    assert infos[2]["path_length_m"] == out1[4]["robot_0"]["path_length_m"]


def test_a_team_that_ends_restarts_in_the_same_step_with_its_last_observation_kept():
    steps = 4
    venv = TeamVecEnv([team(3, max_steps=steps)])
    venv.seed(5)
    venv.reset()
    direct = team(3, max_steps=steps)
    direct.reset(seed=5)
    returns = np.zeros(3)
    for t in range(steps):
        obs, rewards, dones, infos = venv.step(np.array([1, 1, 1]))
        last, reward, _, truncations, _ = direct.step({a: 1 for a in direct.agents})
        step_rewards = [reward[a] for a in ("robot_0", "robot_1", "robot_2")]
        assert rewards.tolist() == pytest.approx(step_rewards)
        returns += step_rewards
        assert dones.tolist() == [t == steps - 1] * 3
    assert all(truncations.values())
    fresh, _ = direct.reset()  # the team's own generator goes on: the next building
    for k, agent in enumerate(("robot_0", "robot_1", "robot_2")):
        assert np.array_equal(infos[k]["terminal_observation"]["scan"], last[agent]["scan"])
        assert np.array_equal(obs["scan"][k], fresh[agent]["scan"])
        assert infos[k]["episode"]["l"] == steps
        assert infos[k]["episode"]["r"] == pytest.approx(returns[k], abs=1e-5)
        assert infos[k]["TimeLimit.truncated"] is True


def test_the_policy_reads_only_the_keys_it_is_given():
    venv = TeamVecEnv([team(2)], keys=("scan", "teammates"))
    assert list(venv.observation_space.spaces) == ["scan", "teammates"]
    assert venv.observation_space["teammates"].shape == (1, 5)
    assert set(venv.reset()) == {"scan", "teammates"}


@pytest.mark.parametrize(
    ("teams_", "keys", "words"),
    [
        (lambda: [], None, "at least one"),
        (lambda: [team(2), team(3)], None, "differ"),
        (lambda: [team(2)], ("scan", "lidar"), "lidar"),
    ],
)
def test_bad_settings__one_line_config_error(teams_, keys, words):
    with pytest.raises(ConfigError, match=words) as err:
        TeamVecEnv(teams_(), keys=keys)
    assert "\n" not in str(err.value)


def test_ppo_trains_one_shared_policy_over_the_team():
    from stable_baselines3 import PPO

    venv = TeamVecEnv([team(2, max_steps=20)], keys=("scan", "velocity", "teammates"))
    model = PPO("MultiInputPolicy", venv, n_steps=16, batch_size=16, n_epochs=1, seed=0, device="cpu")
    model.learn(total_timesteps=64)
    assert model.num_timesteps == 64  # 2 robots x 16 steps per rollout, twice
    assert len(model.ep_info_buffer) == 2 * 1  # the team ended once (20 steps): one episode per robot
    obs = venv.reset()
    actions, _ = model.predict(obs, deterministic=True)
    assert actions.shape == (2,)
