"""Every registered environment, MiniGrid style: API checks, determinism, pickling, limits, vectors."""

from __future__ import annotations

import pickle
import warnings

import gymnasium as gym
import numpy as np
import pytest
from env_helpers import TEST_AREAS_M2, make_env
from gymnasium.utils.env_checker import check_env, data_equivalence

from realistic_indoor.envs import PRESETS
from realistic_indoor.envs.render import ViewFrame

ALL_IDS = sorted(PRESETS)


def _rollout(env: gym.Env, seed: int, n_steps: int) -> list:
    env.action_space.seed(seed)
    out = [env.reset(seed=seed)]
    for _ in range(n_steps):
        out.append(env.step(env.action_space.sample()))
    return out


def test_registry__holds_every_preset_with_its_step_limit():
    for env_id, preset in PRESETS.items():
        spec = gym.spec(env_id)
        assert spec.max_episode_steps == preset.max_episode_steps == preset.kwargs["max_steps"]
    assert set(ALL_IDS) == {
        f"{t}{task}-v0" for t in ("Office", "School", "House", "Random") for task in ("Explore", "Search")
    }


@pytest.mark.parametrize("env_id", ALL_IDS)
def test_env__passes_gymnasium_check_env_without_warnings(env_id):
    env = make_env(env_id)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_env(env.unwrapped)
    env.close()


@pytest.mark.parametrize("env_id", ALL_IDS)
def test_env__passes_stable_baselines3_check_env(env_id):
    from stable_baselines3.common.env_checker import check_env as sb3_check_env

    env = make_env(env_id)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sb3_check_env(env.unwrapped, warn=True)
    env.close()


@pytest.mark.parametrize("env_id", ALL_IDS)
def test_env__same_seed_gives_the_same_rollout(env_id):
    a = _rollout(make_env(env_id), seed=7, n_steps=30)
    b = _rollout(make_env(env_id), seed=7, n_steps=30)
    assert data_equivalence(a, b, exact=True)


@pytest.mark.parametrize("env_id", ALL_IDS)
def test_env__new_seed_gives_a_new_building(env_id):
    env = make_env(env_id)
    env.reset(seed=1)
    first = env.unwrapped.building
    env.reset(seed=2)
    assert env.unwrapped.building != first


@pytest.mark.parametrize("env_id", ALL_IDS)
def test_env__pickled_copy_continues_identically(env_id):
    env = make_env(env_id)
    _rollout(env, seed=3, n_steps=5)
    copy = pickle.loads(pickle.dumps(env))
    actions = [env.action_space.sample() for _ in range(10)]
    assert data_equivalence([env.step(a) for a in actions], [copy.step(a) for a in actions], exact=True)


@pytest.mark.parametrize("env_id", ALL_IDS)
def test_env__truncates_exactly_at_the_step_limit(env_id):
    no_early_end = {"coverage_target": 1.0} if "Explore" in env_id else {}  # search: no such field
    env = make_env(env_id, max_steps=7, **no_early_end)
    env.reset(seed=0)
    ends = [env.step(np.zeros(2, np.float32))[2:4] for _ in range(7)]
    assert ends[:-1] == [(False, False)] * 6
    assert ends[-1] == (False, True)


@pytest.mark.parametrize("env_id", ALL_IDS)
def test_env__gym_make_vec_sync_and_async_agree(env_id):
    area = TEST_AREAS_M2[PRESETS[env_id].building_type]
    results = {}
    for mode in ("sync", "async"):
        envs = gym.make_vec(env_id, num_envs=2, vectorization_mode=mode, area_m2=area, max_steps=10)
        envs.action_space.seed(0)
        obs, _ = envs.reset(seed=0)
        for _ in range(15):  # past the step limit: sub-environments reset on their own
            obs, reward, *_ = envs.step(envs.action_space.sample())
        assert obs["local_map"].shape == (2, *envs.single_observation_space["local_map"].shape)
        assert envs.single_observation_space.contains({k: v[0] for k, v in obs.items()})
        results[mode] = (obs, reward)
        envs.close()
    assert data_equivalence(results["sync"], results["async"], exact=True)
    assert not np.array_equal(results["sync"][0]["scan"][0], results["sync"][0]["scan"][1])


@pytest.mark.parametrize("env_id", ALL_IDS)
def test_env__renders_an_rgb_top_view(env_id):
    env = make_env(env_id, render_mode="rgb_array")
    env.reset(seed=0)
    env.step(env.action_space.sample())
    image = env.render()
    frame = ViewFrame(env.unwrapped.simulation.world.raster)  # a pixel per cell, up to 1024 a side
    assert image.dtype == np.uint8 and image.shape == (*frame.shape, 3) and max(frame.shape) <= 1024
    assert len(np.unique(image.reshape(-1, 3), axis=0)) > 4  # plan, map, robot, rays at least


def _run_python(code: str) -> str:
    import subprocess
    import sys

    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout


def test_registration__imports_nothing_heavy():
    out = _run_python(
        "import sys, gymnasium as gym, realistic_indoor.envs\n"
        "print(gym.spec('OfficeExplore-v0').max_episode_steps,"
        " [m for m in ('numba', 'pymunk', 'scipy', 'realistic_indoor.sim') if m in sys.modules])\n"
    )
    assert out.split() == [str(PRESETS["OfficeExplore-v0"].max_episode_steps), "[]"]


def test_make__with_the_module_prefix_needs_no_import():
    out = _run_python(
        "import gymnasium as gym\n"
        "from realistic_indoor.building import Building, Door, Room\n"
        "rooms = (Room.rectangle('a', 'hall', 'hall', (0, 0, 6, 4)),)\n"
        "b = Building('office', rooms, (Door('e', 'a', None, 0.0, 2.0, 1.0, 1.5708),))\n"
        "env = gym.make('realistic_indoor.envs:OfficeExplore-v0', building=b)\n"
        "print(type(env.unwrapped).__name__, env.reset(seed=0)[1]['coverage'] > 0)\n"
    )
    assert out.split() == ["ExploreEnv", "True"]
