import json

import gymnasium as gym
import numpy as np
import pytest
from agent_helpers import drive, small_env

from realistic_indoor.agents import make_agent
from realistic_indoor.agents.rl import PPOConfig, ppo_preset
from realistic_indoor.envs import PRESETS
from realistic_indoor.errors import ConfigError

pytest.importorskip("stable_baselines3")


LOG_LINES: list[str] = []


@pytest.fixture(scope="module")
def model_path(tmp_path_factory):
    from realistic_indoor.agents.rl import train_ppo

    path = tmp_path_factory.mktemp("ppo") / "smoke.zip"
    config = ppo_preset("smoke", env_ids=("HouseExplore-v0",))
    result = train_ppo(config, path, log=LOG_LINES.append, progress=True, log_every=128)
    assert result.model_path == path and result.timesteps >= 256
    return path


def test_train_ppo__saves_the_model_and_its_config(model_path):
    meta = json.loads(model_path.with_suffix(".json").read_text())
    assert meta["config"]["env_ids"] == ["HouseExplore-v0"] and meta["timesteps"] >= 256
    assert [point["timesteps"] for point in meta["curve"]] == [128, 256]
    assert not list(model_path.parent.glob(".*tmp*"))  # no temporary file left behind


def test_train_ppo__logs_steps_episodes_and_coverage(model_path):
    assert len(LOG_LINES) == 2 and LOG_LINES[-1].split()[:2] == ["256", "steps"]
    assert "episodes  coverage (last 50)" in LOG_LINES[-1]


@pytest.mark.parametrize("action_type", ["continuous", "discrete"])
def test_ppo_agent__acts_in_either_action_space(model_path, hall_office, action_type):
    env = gym.make("OfficeExplore-v0", building=hall_office, action_type=action_type)
    agent = make_agent(f"ppo:{model_path}", env)
    actions, _ = drive(env, agent, steps=20)
    assert all(isinstance(a, int) for a in actions) == (action_type == "discrete")
    again, _ = drive(env, agent, steps=20)
    assert np.array_equal(np.array(actions), np.array(again))  # greedy: deterministic


@pytest.mark.parametrize("env_id", sorted(PRESETS))
def test_ppo_agent__runs_on_every_registered_id(model_path, env_id):
    env = small_env(env_id, max_steps=20)
    actions, _ = drive(env, make_agent(f"ppo:{model_path}", env), seed=1)
    assert len(actions) >= 1


def test_ppo_agent__clear_errors(model_path, hall_office, tmp_path):
    env = gym.make("OfficeExplore-v0", building=hall_office, local_map={"size_px": 48})
    agent = make_agent(f"ppo:{model_path}", env)
    obs, info = env.reset(seed=0)
    with pytest.raises(ConfigError, match="expects 'local_map' of shape"):
        agent.act(obs, info)
    with pytest.raises(ConfigError, match="not found"):
        make_agent(f"ppo:{tmp_path / 'none.zip'}", env)
    corrupt = tmp_path / "corrupt.zip"
    corrupt.write_bytes(b"PK\x03\x04 not a model")
    with pytest.raises(ConfigError, match="is not a model archive"):
        make_agent(f"ppo:{corrupt}", env)
    import zipfile

    with zipfile.ZipFile(tmp_path / "other.zip", "w") as archive:
        archive.writestr("notes.txt", "an archive, but not of a model")
    with pytest.raises(ConfigError, match="not a stable-baselines3 PPO model"):
        make_agent(f"ppo:{tmp_path / 'other.zip'}", env)


def test_ppo_config__rejects_bad_values():
    with pytest.raises(ConfigError, match="unknown ids"):
        PPOConfig(env_ids=("MazeExplore-v0",))
    with pytest.raises(ConfigError, match="unknown PPO preset"):
        ppo_preset("huge")
    with pytest.raises(ConfigError, match="n_envs"):
        ppo_preset("default", n_envs=0)
