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
    config = ppo_preset("smoke", env_ids=("HouseExplore-v0",), n_envs=2)
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
    # two environments over three ids: the third (houses) would never be trained on
    with pytest.raises(ConfigError, match="HouseExplore-v0 would never be trained on") as error:
        ppo_preset("default", n_envs=2)
    assert "\n" not in str(error.value)


@pytest.fixture(scope="module")
def global_map_model(tmp_path_factory):
    """A smoke-trained model whose policy reads the robot's whole map and the time left."""
    from realistic_indoor.agents.rl import train_ppo

    path = tmp_path_factory.mktemp("ppo_global") / "global.zip"
    preset = ppo_preset("global-map")
    config = ppo_preset(
        "smoke",
        env_ids=("HouseExplore-v0",),
        n_envs=2,
        obs_keys=preset.obs_keys,
        map_encoder=preset.map_encoder,
    )
    train_ppo(config, path, log=lambda line: None)
    return path


def test_global_map_preset__the_policy_reads_the_whole_map_and_the_time_left(global_map_model):
    from realistic_indoor.agents.rl.agent import load_model

    spaces = load_model(global_map_model).observation_space.spaces
    assert list(spaces) == sorted(["scan", "local_map", "velocity", "global_map", "time_left"])
    assert spaces["global_map"].shape == (4, 64, 64)  # GlobalMapConfig's default


def test_global_map_preset__encodes_each_map_with_the_compact_cnn(global_map_model):
    from realistic_indoor.agents.rl.agent import load_model
    from realistic_indoor.agents.rl.encoders import MapEncoder

    encoder = load_model(global_map_model).policy.features_extractor
    assert isinstance(encoder, MapEncoder)
    # scan 109 + velocity 2 + time left 1, and 128 features per map image
    assert encoder.features_dim == 109 + 2 + 1 + 2 * 128
    weights = {k: sum(w.numel() for w in part.parameters()) for k, part in encoder.extractors.items()}
    # 8x8/4, 4x4/2 and 3x3/1 convolutions to 16, 32, 32 channels, then 32*4*4 -> 128, with biases
    rest = 16 + (16 * 32 * 4 * 4 + 32) + (32 * 32 * 3 * 3 + 32) + (32 * 4 * 4 * 128 + 128)
    assert weights["global_map"] == 4 * 16 * 8 * 8 + rest  # 4 channels in
    assert weights["local_map"] == 1 * 16 * 8 * 8 + rest
    assert weights["scan"] == weights["velocity"] == weights["time_left"] == 0


def test_global_map_preset__model_loads_in_a_fresh_process(global_map_model):
    """A saved compact encoder is found again by its import path, where nothing imported it yet."""
    import subprocess
    import sys

    code = (
        "import sys; from stable_baselines3 import PPO; "
        "m = PPO.load(sys.argv[1], device='cpu'); print(type(m.policy.features_extractor).__name__)"
    )
    done = subprocess.run(
        [sys.executable, "-c", code, str(global_map_model)], capture_output=True, text=True, check=False
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "MapEncoder"


def test_compact_encoder__refuses_images_too_small_for_its_convolutions_in_one_line():
    from gymnasium import spaces

    from realistic_indoor.agents.rl.encoders import CompactCNN

    CompactCNN(spaces.Box(0, 255, (4, 36, 36), np.uint8))  # the smallest side it takes
    with pytest.raises(ConfigError, match="at least 36 pixels a side, got 32 x 32") as err:
        CompactCNN(spaces.Box(0, 255, (4, 32, 32), np.uint8))
    assert "\n" not in str(err.value)


def test_ppo_config__unknown_map_encoder_is_a_one_line_error():
    with pytest.raises(ConfigError, match="map_encoder must be one of nature, compact") as err:
        PPOConfig(map_encoder="resnet")
    assert "\n" not in str(err.value)


def test_evaluation_gives_a_global_map_model_its_observations(global_map_model):
    from realistic_indoor.agents import agent_observations
    from realistic_indoor.evaluation import evaluate

    assert agent_observations(f"ppo:{global_map_model}") == ("global_map", "time_left")
    assert agent_observations("frontier") == () and agent_observations("learned") == ()
    results = evaluate(
        [f"ppo:{global_map_model}"],
        ["HouseExplore-v0"],
        episodes=1,
        env_kwargs={"max_steps": 15},
        progress=False,
        workers=1,
    )
    assert [r.steps for r in results] == [15]


def test_ppo_config__candidates_need_the_learned_recipe():
    with pytest.raises(ConfigError, match="'candidates' needs macro actions") as err:
        PPOConfig(obs_keys=("scan", "candidates"))
    assert "\n" not in str(err.value)


def test_extra_observations_train_in_sub_processes_where_the_native_vector_env_cannot():
    from stable_baselines3.common.vec_env import SubprocVecEnv

    from realistic_indoor.agents.rl.envs import make_vec_env

    venv = make_vec_env(ppo_preset("global-map", n_envs=2, env_ids=("HouseExplore-v0",)))
    try:
        assert isinstance(venv, SubprocVecEnv)  # asked for "batched", the default
        assert venv.observation_space["time_left"].shape == (1,)
        assert venv.reset()["global_map"].shape == (2, 4, 64, 64)
    finally:
        venv.close()
