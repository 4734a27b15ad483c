"""ExploreEnv: start, observations, rewards, episode end, building sources."""

from __future__ import annotations

import numpy as np
import pytest
from env_helpers import ToyOffice

from realistic_indoor.envs.explore import ExploreEnv
from realistic_indoor.envs.rewards import RewardWeights, weighted_sum
from realistic_indoor.io import load

FORWARD = np.array([1.0, 0.0], np.float32)


def test_reset__starts_at_the_entrance_facing_inward(toy_building):
    env = ExploreEnv(building=toy_building)
    obs, info = env.reset(seed=0)
    x, y, theta = env.simulation.robot.pose
    assert 0.0 < x < 1.0 and y == pytest.approx(5.0)  # just inside the door at x = 0, y = 5
    assert theta == pytest.approx(0.0)  # facing +x, into the corridor
    np.testing.assert_array_equal(obs["pose"], np.zeros(3, np.float32))
    np.testing.assert_array_equal(obs["velocity"], np.zeros(2, np.float32))
    assert 0.0 < info["coverage"] < 1.0 and info["path_length_m"] == 0.0 and info["collisions"] == 0


def test_pose__is_odometry_relative_to_the_start(toy_building):
    env = ExploreEnv(building=toy_building)
    env.reset(seed=0)
    for _ in range(10):
        obs, *_ = env.step(FORWARD)
    x, y, heading = obs["pose"]
    start = env.simulation.world.start_pose
    assert x == pytest.approx(env.simulation.robot.pose[0] - start[0], abs=1e-4)
    assert x > 1.0 and y == pytest.approx(0.0, abs=1e-4) and heading == pytest.approx(0.0, abs=1e-5)
    assert obs["velocity"][0] == pytest.approx(env.config.robot.max_speed_m_s)


def test_local_map__is_an_image_centred_on_the_robot_heading_up(toy_building):
    from stable_baselines3.common.preprocessing import is_image_space

    env = ExploreEnv(building=toy_building)
    obs, _ = env.reset(seed=0)
    assert is_image_space(env.observation_space["local_map"])
    image = obs["local_map"][0]
    s = image.shape[0]
    c = s // 2
    px = env.config.local_map.resolution_m
    assert image[c, c] == 255  # the robot stands on free floor
    ahead = image[: c - 1, c]  # straight up the image: along the 2 m wide corridor, seen free
    assert (ahead[-int(3.0 / px) :] == 255).all()
    left, right = image[c, : c - 1], image[c, c + 2 :]  # corridor walls 1 m to either side
    assert (left == 0).any() and (right == 0).any()
    assert abs((c - np.flatnonzero(left == 0).max()) * px - 1.0) <= 2 * px


def test_scan__is_normalised_ranges(toy_building):
    env = ExploreEnv(building=toy_building)
    obs, _ = env.reset(seed=0)
    scan = obs["scan"]
    np.testing.assert_allclose(scan, env.simulation.scan.ranges_m / env.config.lidar.max_range_m, rtol=1e-6)
    middle = scan[len(scan) // 2]  # straight ahead: the far end of the corridor, about 8 m away
    assert middle * env.config.lidar.max_range_m == pytest.approx(8.0 - env.simulation.robot.pose[0], abs=0.1)


def test_rewards__are_the_weighted_named_terms(toy_building):
    weights = RewardWeights(new_area=0.5, collision=-2.0, time=-0.1)
    env = ExploreEnv(building=toy_building, rewards=weights)
    _, info0 = env.reset(seed=0)
    total_new = 0.0
    for _ in range(20):
        _, reward, _, _, info = env.step(FORWARD)
        assert set(info["rewards"]) == {"new_area", "collision", "time"}
        assert reward == pytest.approx(weighted_sum(weights, info["rewards"]))
        total_new += info["rewards"]["new_area"]
    assert total_new == pytest.approx(info["observed_area_m2"] - info0["observed_area_m2"])


def test_collision__is_counted_and_costs_reward(toy_building):
    env = ExploreEnv(building=toy_building)
    env.reset(seed=0)
    env.step(np.array([0.0, 1.0], np.float32))  # turn to face the corridor's side wall
    hits = [env.step(FORWARD)[4]["rewards"]["collision"] for _ in range(15)]
    assert max(hits) == 1.0
    assert env.step(FORWARD)[4]["collisions"] == sum(hits) + 1


def test_episode__terminates_when_coverage_reaches_the_target(toy_building):
    env = ExploreEnv(building=toy_building, coverage_target=0.35, max_steps=500)
    env.reset(seed=0)
    for _ in range(500):
        _, _, terminated, _, info = env.step(np.array([0.6, 0.3], np.float32))
        assert terminated == (info["coverage"] >= 0.35)
        if terminated:
            break
    assert terminated


def test_discrete_actions__map_to_velocity_commands(toy_building):
    env = ExploreEnv(building=toy_building, action_type="discrete")
    assert env.action_space.n == 6
    env.reset(seed=0)
    for _ in range(5):
        obs, *_ = env.step(3)  # turn left
    assert obs["pose"][2] > 0.5 and abs(obs["pose"][0]) < 1e-3


def test_options_building__runs_that_episode_in_it(toy_building):
    env = ExploreEnv(generator=ToyOffice())
    env.reset(seed=0, options={"building": toy_building})
    assert env.building is toy_building
    env.reset(seed=0)
    assert env.building is not toy_building


def test_fixed_building__is_reused_across_resets(toy_building):
    env = ExploreEnv(building=toy_building)
    env.reset(seed=0)
    world = env.simulation.world
    env.reset(seed=1)
    assert env.simulation.world is world


def test_plan_path__runs_a_real_plan(real_plans_dir):
    path = sorted((real_plans_dir / "office").glob("*.xml"))[0]
    env = ExploreEnv(plan_path=path, max_steps=20)
    obs, info = env.reset(seed=0)
    assert env.building == load(path)
    for _ in range(20):
        obs, _, _, truncated, info = env.step(env.action_space.sample())
    assert truncated and info["coverage"] > 0.0
    assert env.observation_space.contains(obs)


def test_reset__with_the_same_seed_draws_the_same_building():
    env = ExploreEnv(generator=ToyOffice())
    env.reset(seed=5)
    first = env.building
    env.reset(seed=6)
    env.reset(seed=5)
    assert env.building == first
