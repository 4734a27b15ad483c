"""Property-based fuzzing of the physical settings: any value is accepted within its documented
range or refused with a one-line ``ConfigError``, and an accepted value builds a working env."""

from __future__ import annotations

import dataclasses

import gymnasium as gym
import pytest
from fuzz_settings import fuzz
from hypothesis import given
from hypothesis import strategies as st

import realistic_indoor  # noqa: F401 - registers the environments
from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.lidar import LidarConfig
from realistic_indoor.sim.robot import RobotConfig
from realistic_indoor.sim.world import WorldConfig

FUZZ = fuzz(150)
VALUES = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.integers(-(2**70), 2**70),
    st.booleans(),
    st.none(),
    st.text(max_size=4),
)
CONFIGS = [RobotConfig, LidarConfig, WorldConfig]


@pytest.mark.parametrize("config", CONFIGS, ids=lambda c: c.__name__)
@FUZZ
@given(data=st.data())
def test_any_value_of_a_setting_is_accepted_or_refused_in_one_line(config, data):
    field = data.draw(st.sampled_from([f.name for f in dataclasses.fields(config)]), label="field")
    value = data.draw(VALUES, label="value")
    try:
        made = config(**{field: value})
    except ConfigError as e:
        assert "\n" not in str(e) and config.__name__ in str(e)
        return
    assert getattr(made, field) == value


@fuzz(12)
@given(
    radius=st.floats(0.05, 2.0),
    speed=st.floats(0.05, 5.0),
    beams=st.integers(1, 3600),
    max_range=st.floats(0.1, 100.0),
)
def test_accepted_robots_and_lasers_run(radius, speed, beams, max_range):
    """Settings inside their ranges give an environment that resets and steps."""
    try:
        robot = RobotConfig(radius_m=radius, max_speed_m_s=speed)
    except ConfigError as e:  # too fast for its size at the default sub-steps: one line
        assert "\n" not in str(e) and "substeps" in str(e)
        return
    lidar = LidarConfig(n_beams=beams, max_range_m=max_range)
    env = gym.make("HouseExplore-v0", robot=robot, lidar=lidar, max_steps=3)
    try:
        env.reset(seed=0)
        for _ in range(3):
            env.step(env.action_space.sample())
    except ConfigError as e:  # a robot too large for every free cell of the house is refused
        assert "\n" not in str(e)
    finally:
        env.close()
