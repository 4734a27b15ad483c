"""Building-level measures in a comparison: summaries, deviations from reference plans, the CLI."""

from __future__ import annotations

import json
import math

import pytest

from realistic_indoor.cli import main
from realistic_indoor.validator.building_measures import BuildingMeasures, deviations, measure_summary


def _measures(fill: float, loops: int = 0) -> BuildingMeasures:
    nan = math.nan
    return BuildingMeasures(fill, 0.5, 1.0, 0.3, 200.0, 3.0, 0.5, 0.8, 0.7, loops, nan)


def test_measure_summary__median_and_quartiles_over_plans():
    summary = measure_summary([_measures(f) for f in (0.2, 0.4, 0.6, 0.8, 1.0)])
    # numpy's linear quartiles of 0.2..1.0 in steps of 0.2: 0.4, 0.6, 0.8
    # spread between the plans: the interquartile range over the median, (0.8 - 0.4) / 0.6
    expected = {"median": 0.6, "q1": 0.4, "q3": 0.8, "spread": 0.4 / 0.6, "n": 5}
    assert summary["footprint_fill"] == pytest.approx(expected)
    assert summary["circulation_share"]["spread"] == 0.0  # every plan alike
    assert math.isnan(summary["core_facade_share"]["median"]) and summary["core_facade_share"]["n"] == 0
    assert math.isnan(summary["core_facade_share"]["spread"])


def test_deviations__distance_outside_the_reference_interquartile_range():
    reference = measure_summary([_measures(f) for f in (0.8, 0.9, 1.0)])  # fill quartiles 0.85 and 0.95
    generated = measure_summary([_measures(0.45), _measures(0.45)])
    rows = {name: distance for name, distance, _ in deviations(generated, reference)}
    assert rows["footprint_fill"] == pytest.approx((0.85 - 0.45) / 0.10)  # 4 ranges below the first quartile
    assert rows["circulation_share"] == 0.0  # the same everywhere: inside the range
    assert deviations(generated, reference)[0][0] == "footprint_fill"


def test_validate__prints_building_measures_and_a_two_sample_test_per_feature_group(plan_folders, capsys):
    argv = ["validate", str(plan_folders / "mazes"), str(plan_folders / "tidy"), "--format", "json"]
    assert main(argv) == 0
    data = json.loads(capsys.readouterr().out)
    assert [t["features"] for t in data["two_sample"]] == ["room", "building", "all"]
    mazes = data["sets"][0]
    assert len(mazes["plan_measures"]) == 4
    assert set(mazes["building_measures"]) >= {"footprint_fill", "circulation_share", "rooms_per_hectare"}


def test_validate__building_deviations_against_reference_plans(plan_folders, capsys):
    argv = [
        "validate",
        str(plan_folders / "mazes"),
        "--reference",
        str(plan_folders / "tidy"),
        "--no-two-sample",
    ]
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert "Building-level measures" in out
    assert "interquartile range" in out.split("Worst deviations")[1]


def test_validate__unknown_feature_group_is_one_line(plan_folders, capsys):
    argv = ["validate", str(plan_folders / "mazes"), "--two-sample-features", "room,castle"]
    assert main(argv) == 1
    err = capsys.readouterr().err.strip()
    assert "--two-sample-features" in err and "room, building, all" in err and len(err.splitlines()) == 1
