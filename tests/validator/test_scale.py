import json
from importlib import resources

import pytest

from realistic_indoor.models.scale import expected_room_area, scale_check
from realistic_indoor.validator.label_inference import infer_labels


def _real_medium_mean(building_type: str) -> float:
    """The mean medium-room area of the model fitted to real plans, read from its data file."""
    text = resources.files("realistic_indoor").joinpath("data/real_models.json").read_text("utf-8")
    return json.loads(text)[building_type]["labels"]["medium"]["area_mean"]


def test_scale_check__plausible_plan_is_not_flagged(maze_office):
    assert scale_check(maze_office) is None


def test_scale_check__ten_times_too_long_is_flagged_with_the_fix(maze_office, scaled):
    flag = scale_check(scaled(maze_office, 10.0), reference="paper")
    assert flag is not None
    assert flag.measured == "medium rooms"
    assert flag.median_m2 == pytest.approx(1600.0)
    assert flag.expected_m2 == pytest.approx(18.5)
    assert flag.length_factor == pytest.approx((18.5 / 1600) ** 0.5)
    assert flag.message.startswith("maze_office: scale looks wrong: medium rooms have a median of 1600.0 m2")
    assert "too large" in flag.message and "in the paper's Table 1" in flag.message


def test_scale_check__judges_against_real_plans_of_the_type_by_default(maze_office, scaled):
    expected = _real_medium_mean("office")
    flag = scale_check(scaled(maze_office, 10.0))
    assert flag.expected_m2 == pytest.approx(expected)
    assert flag.length_factor == pytest.approx((expected / 1600) ** 0.5)
    assert f"expected about {expected:.1f} m2 in real offices" in flag.message
    # medium rooms of 60 m2 (16 m2 in the maze): 3.2x the paper's 18.5 m2, 1.7x real offices' mean
    sixty = scaled(maze_office, (60 / 16) ** 0.5)
    assert scale_check(sixty, reference="paper") is not None
    assert scale_check(sixty) is None
    assert "in the paper's Table 1" in scale_check(scaled(maze_office, 10.0), "house").message


def test_scale_check__flags_one_shared_real_office_not_three(real_plans_dir):
    import warnings

    from realistic_indoor.io import load

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        plans = {p.name: load(p) for p in sorted((real_plans_dir / "office").glob("*.xml"))}
    by_paper = sorted(n for n, b in plans.items() if scale_check(b, reference="paper"))
    by_real = sorted(n for n, b in plans.items() if scale_check(b))
    assert by_paper == ["ED21.xml", "Milano-1.xml", next(n for n in plans if n.startswith("dentist"))]
    assert by_real == [next(n for n in plans if n.startswith("dentist"))]  # 9,000 m2 for 25 rooms


def test_scale_check__too_small_and_compared_with_the_given_type(maze_office, scaled):
    assert scale_check(scaled(maze_office, 0.3)) is not None
    assert "too small" in scale_check(maze_office, "school").message


def test_scale_check__inferred_labels_use_all_ordinary_rooms(maze_office, scaled):
    flag = scale_check(infer_labels(scaled(maze_office, 10.0)), reference="paper")
    assert flag.measured == "small/medium/big rooms"
    assert flag.expected_m2 == pytest.approx(expected_room_area("office", None, "paper"))


def test_expected_room_area__share_weighted_mean_of_ordinary_rooms():
    mean = (23.2 * 4.5 + 34.5 * 18.5 + 14.8 * 31.3) / (23.2 + 34.5 + 14.8)
    assert expected_room_area("office", None, "paper") == pytest.approx(mean)
