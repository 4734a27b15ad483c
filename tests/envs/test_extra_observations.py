"""Optional observations (``extra_observations``): the global map, candidate goals, the time left.

The global map is checked against the ground truth through the inverse of its definition: each
pixel's centre, taken back to the plan frame from the robot's position and the start heading,
must lie on the floor (free pixels) or by a wall (wall pixels) of the world's raster.
"""

from __future__ import annotations

import warnings

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.raster import RASTER_FREE, RASTER_WALL


def _plan_points(obs, sim, rows, cols, config):
    """Plan-frame centres of global-map pixels: the image's definition, inverted."""
    s, res = config.size_px, config.resolution_m
    x, y, _ = sim.robot.pose
    up = sim.world.start_pose[2]
    ahead = (s / 2 - rows - 0.5) * res
    left = (s / 2 - cols - 0.5) * res
    return np.stack(
        [x + ahead * np.cos(up) - left * np.sin(up), y + ahead * np.sin(up) + left * np.cos(up)], -1
    )


def _near(raster, points, value, reach_m):
    """Whether a cell of ``value`` lies within ``reach_m`` (a square) of each point."""
    hit = np.zeros(len(points), dtype=bool)
    for dx in np.linspace(-reach_m, reach_m, 15):
        for dy in np.linspace(-reach_m, reach_m, 15):
            rr, cc = raster.world_to_cell(points + np.array([dx, dy]))
            inside = (rr >= 0) & (rr < raster.grid.shape[0]) & (cc >= 0) & (cc < raster.grid.shape[1])
            got = np.full(len(points), 255)
            got[inside] = raster.grid[rr[inside], cc[inside]]
            hit |= got == value
    return hit


@pytest.mark.parametrize("seed", [3, 4])
def test_global_map__shows_the_mapped_floor_and_walls_where_they_are(seed):
    fine = {"size_px": 128, "resolution_m": 0.5}  # finer than the default, for a tight check
    env = gym.make("OfficeExplore-v0", area_m2=600.0, extra_observations=["global_map"], global_map=fine)
    env.action_space.seed(seed)
    obs, _ = env.reset(seed=seed)
    for _ in range(60):
        obs, *_ = env.step(env.action_space.sample())
    sim, config = env.unwrapped.simulation, env.unwrapped.config.global_map
    image = obs["global_map"]
    assert image.shape == (4, 128, 128) and set(np.unique(image)) <= {0, 255}
    for channel, value in ((0, RASTER_FREE), (1, RASTER_WALL)):
        rows, cols = np.nonzero(image[channel])
        assert len(rows) > 10
        points = _plan_points(obs, sim, rows, cols, config)
        # half a pixel, plus the 0.2 m cells the map is pooled on
        assert _near(sim.world.raster, points, value, 0.25 + 0.2).all()
    unknown = image[2] == 255
    assert np.array_equal(unknown, (image[0] == 0) & (image[1] == 0))
    assert image[3][64, 64] == 255  # the robot stands in the centre pixel, which it has visited
    assert env.observation_space.contains(obs)


def test_global_map__default_is_64_pixels_of_1_m_with_the_robot_in_the_centre_pixel():
    env = gym.make("HouseExplore-v0", extra_observations=["global_map"])
    obs, _ = env.reset(seed=2)
    image = obs["global_map"]
    assert image.shape == (4, 64, 64)
    assert image[3][32, 32] == 255  # visited: the robot's start, in the centre pixel
    # a house (150 m2) fits in 64 m x 64 m: the mapped floor lies well inside the image
    rows, cols = np.nonzero(image[0])
    assert len(rows) > 4 and rows.min() > 8 and rows.max() < 56 and cols.min() > 8 and cols.max() < 56


def test_global_map__keeps_the_start_heading_up_while_the_robot_turns():
    env = gym.make("HouseExplore-v0", extra_observations=["global_map"])
    obs, _ = env.reset(seed=1)
    for _ in range(5):
        obs, *_ = env.step(np.array([0.0, 0.0], dtype=np.float32))  # settle, nothing new to see
    before = obs["global_map"]
    for _ in range(8):  # turn on the spot, about 90 degrees
        obs, *_ = env.step(np.array([0.0, 1.0], dtype=np.float32))
    after = obs["global_map"]
    walls_kept = (before[1] == 255) & (after[1] == 255)
    assert walls_kept.sum() >= 0.9 * (before[1] == 255).sum()  # the walls seen before stay where they were


def test_time_left__falls_by_one_step_limit_share_per_step():
    env = gym.make("HouseExplore-v0", max_steps=40, extra_observations=["time_left"])
    obs, _ = env.reset(seed=0)
    assert obs["time_left"][0] == 1.0
    for step in range(1, 11):
        obs, *_ = env.step(env.action_space.sample())
        assert obs["time_left"][0] == pytest.approx(1.0 - step / 40)


@pytest.mark.parametrize(
    "kwargs",
    [
        {"extra_observations": ["global_map", "time_left"], "action_type": "discrete"},
        {"extra_observations": ["global_map", "candidates", "time_left"], "action_type": "frontier"},
    ],
)
def test_extra_observations__pass_check_env(kwargs):
    from stable_baselines3.common.env_checker import check_env as sb3_check_env

    env = gym.make("HouseSearch-v0", max_steps=50, **kwargs)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_env(env.unwrapped)
        sb3_check_env(env.unwrapped, warn=True)


def test_extra_observations__bad_names_are_one_line_errors():
    with pytest.raises(ConfigError, match="unknown 'map'") as error:
        gym.make("HouseExplore-v0", extra_observations=["map"])
    assert "\n" not in str(error.value)
    with pytest.raises(ConfigError, match="'candidates' needs frontier macro actions"):
        gym.make("HouseExplore-v0", extra_observations=["candidates"])
    with pytest.raises(ConfigError, match="tuple of names"):
        gym.make("HouseExplore-v0", extra_observations="global_map")
    with pytest.raises(ConfigError, match="vectorization_mode='sync'"):
        gym.make_vec("HouseExplore-v0", num_envs=2, extra_observations=["time_left"])


def test_extra_observations__default_to_none_with_primitive_actions_and_candidates_with_macro():
    plain = gym.make("HouseExplore-v0")
    assert sorted(plain.observation_space.spaces) == ["local_map", "pose", "scan", "velocity"]
    macro = gym.make("HouseExplore-v0", action_type="frontier")
    assert {"candidates", "time_left"} <= set(macro.observation_space.spaces)
    lean = gym.make("HouseExplore-v0", action_type="frontier", extra_observations=[])
    assert "candidates" not in lean.observation_space.spaces
