"""Bad configurations fail at construction with one clear ConfigError naming the field."""

from __future__ import annotations

import gymnasium as gym
import pytest
from env_helpers import ToyOffice, make_env

import realistic_indoor.envs  # noqa: F401  (registers the ids)
from realistic_indoor.envs import EnvConfig, ExploreEnv, preset_config
from realistic_indoor.envs.source import FixedBuilding, GeneratedBuildings
from realistic_indoor.errors import ConfigError, PlanFormatError, RealisticIndoorError


@pytest.mark.parametrize(
    ("overrides", "field"),
    [
        ({"lidar": {"max_range_m": -1.0}}, "max_range_m"),
        ({"lidar": {"n_beams": 0}}, "n_beams"),
        ({"building_type": "castle"}, "building type"),
        ({"coverage_target": 0.0}, "coverage_target"),
        ({"coverage_target": 1.5}, "coverage_target"),
        ({"max_steps": 0}, "max_steps"),
        ({"action_type": "teleport"}, "action_type"),
        ({"area_m2": -5.0}, "area_m2"),
        ({"robot": {"radius_m": 0.0}}, "radius_m"),
        ({"local_map": {"size_px": 0}}, "size_px"),
        ({"victims": {"sensor_range_m": -3.0}}, "sensor_range_m"),
        ({"rewards": {"time": float("nan")}}, "time"),
        ({"lidar": {"beams": 10}}, "no field 'beams'"),
        ({"n_beams": 10}, "no field 'n_beams'"),
        ({"lidar": 10}, "LidarConfig"),
        ({"plan_path": 3}, "plan_path must be a file path"),
        ({"generator": "office"}, "must be a callable"),
    ],
)
def test_bad_value__raises_config_error_naming_it(overrides, field):
    with pytest.raises(ConfigError, match=field):
        gym.make("OfficeExplore-v0", **overrides)


def test_two_building_sources__are_rejected(toy_building):
    with pytest.raises(ConfigError, match="at most one building source"):
        EnvConfig(building=toy_building, generator=ToyOffice())


def test_override_of_the_source__replaces_the_preset_source(toy_building):
    config = preset_config("OfficeExplore-v0", generator=ToyOffice())
    assert config.replace(building=toy_building).source == FixedBuilding(toy_building)


def test_missing_plan_file__raises_plan_format_error(tmp_path):
    with pytest.raises(PlanFormatError, match="no such file"):
        ExploreEnv(plan_path=tmp_path / "missing.xml")


def test_unknown_reset_option__raises_config_error():
    env = make_env("OfficeExplore-v0")
    with pytest.raises(ConfigError, match="unknown reset option 'seed_building'"):
        env.reset(options={"seed_building": 3})


def test_bad_render_mode__raises_config_error():
    with pytest.raises(RealisticIndoorError, match="render_mode"):
        ExploreEnv(generator=ToyOffice(), render_mode="ansi")


def test_step_before_reset__raises_reset_needed():
    with pytest.raises(gym.error.ResetNeeded):
        ExploreEnv(generator=ToyOffice()).step([0.0, 0.0])


def test_preset_config__is_the_registered_environment_config():
    env = gym.make("SchoolSearch-v0", max_steps=11, area_m2=900.0)
    assert env.unwrapped.config == preset_config("SchoolSearch-v0", max_steps=11, area_m2=900.0)
    assert env.unwrapped.config.source == GeneratedBuildings("school", 900.0)


def test_random_env__grid_size_in_generator_params_overrides_the_default_area():
    import gymnasium as gym

    env = gym.make("RandomExplore-v0", generator_params={"width_units": 8, "height_units": 6})
    env.reset(seed=0)
    x0, y0, x1, y1 = env.unwrapped.building.bounds
    assert (round(x1 - x0), round(y1 - y0)) in {(24, 18), (18, 24)}
    env.close()
