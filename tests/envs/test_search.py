"""SearchEnv: victims are found when the sensor sees them, rewarded once, and end the episode."""

from __future__ import annotations

import math

import numpy as np
import pytest
import shapely
from env_helpers import ToyOffice

from realistic_indoor.envs.search import SearchEnv
from realistic_indoor.errors import ConfigError

FORWARD = np.array([1.0, 0.0], np.float32)
TURN_LEFT = np.array([0.0, 1.0], np.float32)


def _env(building, **kwargs):
    return SearchEnv(building=building, victims={"n_victims": 1}, **kwargs)


def test_victim__ahead_in_range_is_found_once_with_reward(toy_building):
    env = _env(toy_building)
    _, info = env.reset(seed=0, options={"victims": [[5.0, 5.0]]})  # in the corridor, ~4.6 m ahead
    assert info["victims_found"] == 0 and info["victims_total"] == 1
    for _ in range(20):
        obs, reward, terminated, _, info = env.step(FORWARD)
        if terminated:
            break
    assert terminated and info["victims_found"] == 1 and info["rewards"]["victim"] == 1.0
    x = env.simulation.robot.pose[0]
    assert 5.0 - x <= env.config.victims.sensor_range_m
    assert reward == pytest.approx(
        sum(getattr(env.config.rewards, k) * v for k, v in info["rewards"].items())
    )
    seen = obs["victims"]
    assert seen[0] == 1.0 and seen[1] == pytest.approx((5.0 - x) / 3.0, abs=1e-3)
    assert seen[2] == pytest.approx(0.0, abs=1e-3)  # straight ahead


@pytest.mark.parametrize(("victim_y", "seen"), [(5.8, True), (7.0, False)])
def test_victim__is_seen_only_in_line_of_sight(toy_building, victim_y, seen):
    env = _env(toy_building)
    env.reset(seed=0)
    x0 = env.simulation.robot.pose[0]
    # 0.8 m north in the corridor, or 2 m north in an office behind the corridor wall
    env.reset(seed=0, options={"victims": [[x0, victim_y]]})
    while env.simulation.robot.pose[2] < 1.2:  # turn to face north
        env.step(TURN_LEFT)
    for _ in range(3):
        obs, _, terminated, _, info = env.step(np.zeros(2, np.float32))
    assert abs(env.simulation.robot.pose[2] - math.pi / 2) < math.radians(30)
    assert terminated == seen and info["victims_found"] == int(seen)
    assert obs["victims"].any() == seen


def test_victims__are_placed_in_rooms_by_default():
    env = SearchEnv(generator=ToyOffice(n_rooms=3), victims={"n_victims": 6})
    for seed in range(3):
        env.reset(seed=seed)
        xy, found = env.victims
        rooms = [r.polygon for r in env.building.rooms if r.label.value != "corridor"]
        inside = shapely.contains_xy(shapely.union_all(rooms), xy[:, 0], xy[:, 1])
        assert inside.all() and xy.shape == (6, 2) and found.dtype == bool


def test_victims_option__rejects_a_wrong_shape(toy_building):
    env = _env(toy_building)
    with pytest.raises(ConfigError, match="n_victims"):
        env.reset(seed=0, options={"victims": [[1.0, 2.0], [3.0, 4.0]]})


class TimeOnlySearch(SearchEnv):
    """A search whose reward ignores victims: before issue 16 this stopped victims being found."""

    def _reward_terms(self, outcome):
        return {"time": 1.0}


@pytest.mark.parametrize(
    "make",
    [
        lambda b: TimeOnlySearch(building=b, victims={"n_victims": 2}),
        lambda b: SearchEnv(building=b, victims={"n_victims": 2}, rewards={"victim": 0.0, "new_area": 0.0}),
    ],
    ids=["reward-hook-overridden", "other-weights"],
)
def test_victims__are_found_by_the_step_whatever_the_rewards(toy_building, make):
    victims = np.array([[4.0, 5.0], [7.0, 5.0]])  # on the corridor's centre line, ahead
    plain, other = SearchEnv(building=toy_building, victims={"n_victims": 2}), make(toy_building)
    runs = []
    for env in (plain, other):
        _, info = env.reset(seed=0, options={"victims": victims})
        found, terminated = [info["victims_found"]], False
        while not terminated and len(found) <= 40:
            _, _, terminated, _, info = env.step(FORWARD)
            found.append(info["victims_found"])
        runs.append(found)
        assert terminated and env.victims[1].all()

    # in the empty corridor a victim ahead is found at the first pose within sensor range (3 m)
    xy = np.array(plain.simulation.trajectory)  # the start, then the position after each step
    distance_m = np.linalg.norm(xy[:, None, :] - victims[None, :, :], axis=2)  # (poses, victims)
    expected = np.maximum.accumulate(distance_m <= 3.0, axis=0).sum(axis=1).tolist()
    assert runs[0] == runs[1] == expected
    assert 0 < expected.index(1) < expected.index(2)
