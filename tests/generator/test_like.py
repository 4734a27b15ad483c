"""Like-for-like sets: one generated building per plan, with the plan's floor area."""

from __future__ import annotations

import pytest

from realistic_indoor.building import Building, Room
from realistic_indoor.errors import ConfigError
from realistic_indoor.generator import area_limits, generate_like
from realistic_indoor.io.json_format import dumps


def _plan(width_m: float, depth_m: float) -> Building:
    """A plan of one room: floor area width x depth."""
    return Building("office", (Room.rectangle("r", "big", "office", (0, 0, width_m, depth_m)),))


def test_generate_like__twin_has_the_plans_floor_area():
    plans = [("small", _plan(30, 40)), ("large", _plan(60, 50))]  # 1,200 and 3,000 m2
    twins = list(generate_like(plans, "office"))
    assert [t.name for t in twins] == ["small", "large"]
    assert [t.plan_area_m2 for t in twins] == [1200.0, 3000.0]
    for twin in twins:
        assert twin.building.area == pytest.approx(twin.plan_area_m2, rel=0.02)
        assert not twin.clamped
        assert twin.building.metadata["like"]["plan"] == twin.name


def test_generate_like__several_twins_per_plan_differ_and_repeat_per_seed():
    plans = [("a", _plan(30, 40))]
    first = list(generate_like(plans, "school", count=2, seed=5))
    again = list(generate_like(plans, "school", count=2, seed=5))
    assert [t.name for t in first] == ["a_0", "a_1"]
    assert [t.building.metadata["seed"] for t in first] == [5, 6]
    assert dumps(first[0].building) == dumps(again[0].building)
    assert dumps(first[0].building) != dumps(first[1].building)


def test_generate_like__area_outside_the_limits_is_clamped_and_said():
    low, _high = area_limits("house")
    (twin,) = generate_like([("tiny", _plan(5, 5))], "house")  # 25 m2, under the smallest house
    assert twin.clamped and twin.plan_area_m2 == 25.0
    assert twin.building.area == pytest.approx(low, rel=0.05)


@pytest.mark.parametrize("name", ["office", "school", "house", "random"])
def test_area_limits__every_generator_makes_its_smallest_area(name):
    low, high = area_limits(name)
    assert 0 < low < high
    (twin,) = generate_like([("p", _plan(1, low))], name)
    assert not twin.clamped


def test_generate_like__bad_arguments_are_config_errors():
    with pytest.raises(ConfigError, match="unknown generator 'castle'"):
        list(generate_like([], "castle"))
    with pytest.raises(ConfigError, match="count"):
        list(generate_like([("p", _plan(30, 40))], "office", count=0))
