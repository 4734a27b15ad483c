import pytest

from realistic_indoor.models.scale import expected_room_area, scale_check
from realistic_indoor.validator.label_inference import infer_labels


def test_scale_check__plausible_plan_is_not_flagged(maze_office):
    assert scale_check(maze_office) is None


def test_scale_check__ten_times_too_long_is_flagged_with_the_fix(maze_office, scaled):
    flag = scale_check(scaled(maze_office, 10.0))
    assert flag is not None
    assert flag.measured == "medium rooms"
    assert flag.median_m2 == pytest.approx(1600.0)
    assert flag.expected_m2 == pytest.approx(18.5)
    assert flag.length_factor == pytest.approx((18.5 / 1600) ** 0.5)
    assert flag.message.startswith("maze_office: scale looks wrong: medium rooms have a median of 1600.0 m2")
    assert "too large" in flag.message


def test_scale_check__too_small_and_compared_with_the_given_type(maze_office, scaled):
    assert scale_check(scaled(maze_office, 0.3)) is not None
    assert "too small" in scale_check(maze_office, "school").message


def test_scale_check__inferred_labels_use_all_ordinary_rooms(maze_office, scaled):
    flag = scale_check(infer_labels(scaled(maze_office, 10.0)))
    assert flag.measured == "small/medium/big rooms"
    assert flag.expected_m2 == pytest.approx(expected_room_area("office", None))


def test_expected_room_area__share_weighted_mean_of_ordinary_rooms():
    mean = (23.2 * 4.5 + 34.5 * 18.5 + 14.8 * 31.3) / (23.2 + 34.5 + 14.8)
    assert expected_room_area("office", None) == pytest.approx(mean)
