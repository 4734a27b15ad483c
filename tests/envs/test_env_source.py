"""EnvConfig.source: one field says where buildings come from; the older keywords map onto it."""

from __future__ import annotations

from pathlib import Path

import gymnasium as gym
import pytest
from env_helpers import ToyOffice

import realistic_indoor.envs  # noqa: F401  (registers the ids)
from realistic_indoor.envs import EnvConfig, preset_config
from realistic_indoor.envs.source import CustomGenerator, FixedBuilding, GeneratedBuildings, PlanFile
from realistic_indoor.errors import ConfigError


def test_default_source__is_generated_offices_of_the_default_area():
    assert EnvConfig().source == GeneratedBuildings("office", None, {})


@pytest.mark.parametrize(
    ("value", "expected"),
    [
        ("school", GeneratedBuildings("school")),
        ({"building_type": "house", "area_m2": 120.0}, GeneratedBuildings("house", 120.0)),
        ("plans/off-1.xml", PlanFile("plans/off-1.xml")),
        (Path("plans/off-1.xml"), PlanFile(Path("plans/off-1.xml"))),
    ],
)
def test_source_shorthand__becomes_its_kind(value, expected):
    assert EnvConfig(source=value).source == expected


def test_source_building_and_callable__become_fixed_and_custom(toy_building):
    toy = ToyOffice()
    assert EnvConfig(source=toy_building).source == FixedBuilding(toy_building)
    assert EnvConfig(source=toy).source == CustomGenerator(toy)


@pytest.mark.parametrize(
    ("old", "new"),
    [
        ({"building_type": "school", "area_m2": 900.0}, {"source": GeneratedBuildings("school", 900.0)}),
        (
            {"generator_params": {"model": "paper"}},
            {"source": GeneratedBuildings("office", None, {"model": "paper"})},
        ),
        ({"plan_path": "a.xml"}, {"source": PlanFile("a.xml")}),
    ],
)
def test_old_keywords__map_onto_source(old, new):
    assert EnvConfig(**old) == EnvConfig(**new)
    assert EnvConfig().replace(**old) == EnvConfig(**new)


def test_old_building_and_generator_keywords__map_onto_source(toy_building):
    toy = ToyOffice()
    assert EnvConfig(building=toy_building).source == FixedBuilding(toy_building)
    assert EnvConfig(generator=toy).source == CustomGenerator(toy)


def test_area_override__keeps_the_type_and_options():
    config = EnvConfig(source=GeneratedBuildings("school", 900.0, {"model": "paper"}))
    assert config.replace(area_m2=1500.0).source == GeneratedBuildings("school", 1500.0, {"model": "paper"})


def test_building_type_override__switches_a_fixed_source_back_to_generated(toy_building):
    config = EnvConfig(source=toy_building).replace(building_type="house")
    assert config.source == GeneratedBuildings("house")


def test_area_for_a_fixed_building__is_refused_not_ignored(toy_building):
    with pytest.raises(ConfigError, match="area_m2 apply to buildings drawn by a named generator"):
        EnvConfig(source=toy_building).replace(area_m2=500.0)
    with pytest.raises(
        ConfigError, match="area_m2 set the named generator's buildings, not those of building"
    ):
        EnvConfig(building=toy_building, area_m2=500.0)


def test_source_given_twice__is_refused(toy_building):
    with pytest.raises(ConfigError, match="give the building source once, got source and building"):
        EnvConfig(source="office", building=toy_building)
    with pytest.raises(ConfigError, match="got source and building_type"):
        EnvConfig().replace(source=toy_building, building_type="house")


@pytest.mark.parametrize(
    ("value", "match"),
    [
        (3, "EnvConfig.source must be"),
        ({"type": "office"}, "unknown key 'type'"),
        ("castle", None),
    ],
)
def test_bad_source__raises_config_error(value, match):
    if match is None:  # a string that is no type is a plan path: it fails when read
        assert EnvConfig(source=value).source == PlanFile("castle")
        return
    with pytest.raises(ConfigError, match=match):
        EnvConfig(source=value)


def test_gym_make__source_keyword_overrides_the_preset(toy_building):
    env = gym.make("SchoolExplore-v0", source=toy_building)
    assert env.unwrapped.config.source == FixedBuilding(toy_building)
    assert env.unwrapped.config.max_steps == preset_config("SchoolExplore-v0").max_steps
    env.reset(seed=0)
    assert env.unwrapped.building is toy_building
    env.close()


def test_gym_make__old_keywords_override_the_preset(toy_building):
    env = gym.make("SchoolExplore-v0", building=toy_building)
    assert env.unwrapped.config.source == FixedBuilding(toy_building)
    env.close()


def test_gym_make_vec__takes_the_preset_and_source(toy_building):
    envs = gym.make_vec("HouseExplore-v0", num_envs=2, source=toy_building)
    assert envs.config.source == FixedBuilding(toy_building)
    assert envs.config.max_steps == preset_config("HouseExplore-v0").max_steps
    envs.close()
