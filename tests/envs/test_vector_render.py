"""render() of the native vector environments: each sub-environment's frame is the single env's."""

from __future__ import annotations

import pickle

import gymnasium as gym
import numpy as np
import pytest
from env_helpers import TEST_AREAS_M2

from realistic_indoor.envs import PRESETS
from realistic_indoor.envs.render import COLOURS, tile
from realistic_indoor.envs.window import upscaled
from realistic_indoor.errors import ConfigError

WHITE = COLOURS["outside"]


@pytest.mark.parametrize(
    ("env_id", "extra"),
    [
        ("OfficeExplore-v0", {}),
        ("HouseSearch-v0", {"victims": {"n_victims": 10, "sensor_range_m": 6.0}}),  # some are found
    ],
)
def test_rgb_array__sub_env_k_draws_the_single_env_seeded_with_seed_plus_k(env_id, extra):
    area = TEST_AREAS_M2[PRESETS[env_id].building_type]
    kwargs = {"area_m2": area, "max_steps": 40, "render_mode": "rgb_array", **extra}
    envs = gym.make_vec(env_id, num_envs=2, **kwargs)
    singles = [gym.make(env_id, **kwargs) for _ in range(2)]
    envs.reset(seed=20)
    for k, single in enumerate(singles):
        single.reset(seed=20 + k)
    rng = np.random.default_rng(4)
    pending = [False, False]  # the single env starts its next episode when the vector env does
    compared = 0
    for step in range(90):  # two episodes of 40 steps, a reset step after each
        if step % 10 == 0:
            frames = envs.render()
            assert isinstance(frames, tuple) and len(frames) == 2
            for k, single in enumerate(singles):
                np.testing.assert_array_equal(frames[k], single.render())
                compared += 1
        actions = rng.uniform(-1, 1, (2, 2)).astype(np.float32)
        envs.step(actions)
        for k, single in enumerate(singles):
            if pending[k]:
                single.reset()
                pending[k] = False
                continue
            _, _, terminated, truncated, _ = single.step(actions[k])
            pending[k] = terminated or truncated
    assert compared == 18
    found = [int(v[1].sum()) for v in envs.unwrapped.victims] if "Search" in env_id else [1]
    assert sum(found) > 0  # found victims are drawn green, and compared


def test_render__without_a_mode_warns_and_before_reset_asks_for_one():
    envs = gym.make_vec("HouseExplore-v0", num_envs=2, area_m2=TEST_AREAS_M2["house"])
    envs.reset(seed=0)
    with pytest.warns(UserWarning, match="render_mode"):
        assert envs.render() is None
    drawn = gym.make_vec("HouseExplore-v0", num_envs=2, render_mode="rgb_array")
    with pytest.raises(gym.error.ResetNeeded):
        drawn.render()
    with pytest.raises(ConfigError, match="render_mode must be one of"):
        gym.make_vec("HouseExplore-v0", num_envs=2, render_mode="ansi")


def test_tile__puts_frames_in_rows_of_cells_as_large_as_the_largest():
    a = np.full((2, 3, 3), 1, np.uint8)
    b = np.full((1, 1, 3), 2, np.uint8)
    c = np.full((3, 2, 3), 3, np.uint8)
    out = tile([a, b, c], gap_px=1)  # 2 columns of 3 x 3 cells, a 1-pixel gap: 7 x 7
    expected = np.empty((7, 7, 3), np.uint8)
    expected[...] = WHITE
    expected[0:2, 0:3] = 1
    expected[0:1, 4:5] = 2
    expected[4:7, 0:2] = 3
    np.testing.assert_array_equal(out, expected)
    np.testing.assert_array_equal(tile([a]), a)


def test_human__one_window_shows_every_sub_env_side_by_side(monkeypatch):
    monkeypatch.setenv("SDL_VIDEODRIVER", "dummy")
    pygame = pytest.importorskip("pygame", reason="render_mode='human' needs pygame (the viz extra)")
    kwargs = {"num_envs": 3, "area_m2": TEST_AREAS_M2["house"]}
    human = gym.make_vec("HouseExplore-v0", render_mode="human", **kwargs)
    twin = gym.make_vec("HouseExplore-v0", render_mode="rgb_array", **kwargs)
    assert human.metadata["render_fps"] == 5  # the control rate, as the single env
    human.reset(seed=1)
    twin.reset(seed=1)
    actions = np.tile(np.array([1.0, 0.4], np.float32), (3, 1))
    for _ in range(3):
        human.step(actions)
        twin.step(actions)
        assert pygame.display.get_caption()[0].endswith("HouseExplore-v0 x 3")
        shown = pygame.surfarray.array3d(pygame.display.get_surface()).swapaxes(0, 1)
        np.testing.assert_array_equal(shown, upscaled(tile(twin.render())))  # step() drew it
    assert human.render() is None
    human.close()
    assert not pygame.display.get_init()


def test_rgb_array__a_pickled_env_draws_what_the_original_draws():
    envs = gym.make_vec(
        "HouseExplore-v0", num_envs=2, area_m2=TEST_AREAS_M2["house"], render_mode="rgb_array"
    )
    envs.reset(seed=3)
    actions = np.tile(np.array([1.0, -0.3], np.float32), (2, 1))
    for _ in range(5):
        envs.step(actions)
    copy = pickle.loads(pickle.dumps(envs))
    for _ in range(5):
        envs.step(actions)
        copy.step(actions)
    for mine, theirs in zip(envs.render(), copy.render(), strict=True):  # the trajectories came along
        np.testing.assert_array_equal(mine, theirs)
