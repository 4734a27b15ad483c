import math

import pytest

from realistic_indoor.building import SemanticLabel
from realistic_indoor.validator.reference import fitted_reference, paper_reference
from realistic_indoor.validator.score import ScoreConfig, realism_score


def test_realism_score__a_set_against_itself_is_zero(maze_office, tiny_office):
    ref = fitted_reference([maze_office, tiny_office], "hand-made")
    s = realism_score([maze_office, tiny_office], ref)
    assert s.overall == pytest.approx(0.0)
    assert s.tv_distance == pytest.approx(0.0)


def test_realism_score__terms_of_the_maze_office_against_the_paper(maze_office):
    s = realism_score([maze_office], paper_reference("office"))
    # hall and big rooms missing: 6 cells at the cap; the other 9 computed by hand
    cells = [
        (26 - 30.5) / 25.7, (3.5 - 6.7) / 4.8, (6.5 - 8.1) / 7.3,  # corridors
        (4 - 4.5) / 2.3, 0.0, (1.0 - 1.3) / 0.7,  # small: doorways 1.0 vs 1.0 +/- 0.1
        (17.6 - 18.5) / 14.4, (1.4 - 1.2) / 0.3, (1.1 - 1.9) / 0.8,  # medium
    ]  # fmt: skip
    assert s.features == pytest.approx((30 + sum(abs(c) for c in cells)) / 15)
    assert s.tv_distance == pytest.approx((4.4 + 6.6 + 10.7 + 28.0 + 14.8) / 200)
    assert s.shares == pytest.approx(s.tv_distance / 0.1)
    assert s.connectivity == pytest.approx(((98 - 60) / 10 + (70 - 50) / 10) / 2)
    assert s.overall == pytest.approx((s.features + s.shares + s.connectivity) / 3)


def test_realism_score__worst_deviations_in_words(maze_office):
    worst = realism_score([maze_office], paper_reference("office")).worst(4)
    assert worst[0] == "there are no halls (6.6% of rooms in real offices)"
    assert "60% of offices touch a corridor; real offices 98%" in worst


def test_realism_score__corridor_doorways_sentence_as_the_paper_puts_it(maze_office):
    s = realism_score([maze_office], paper_reference("office"))
    sentences = [d.sentence for d in s.deviations]
    assert "corridors have 3.5 doorways; real offices 6.7 +/- 4.8" in sentences


def test_realism_score__std_floor_limits_near_constant_features(tiny_office):
    s = realism_score([tiny_office], paper_reference("office"))
    doors = next(d for d in s.deviations if d.subject == "medium" and d.feature == "doors")
    assert doors.z == pytest.approx((1.2 - 1.0) / 0.3)
    floored = realism_score([tiny_office], paper_reference("office"), ScoreConfig(doors_floor=1.0))
    doors = next(d for d in floored.deviations if d.subject == "medium" and d.feature == "doors")
    assert doors.z == pytest.approx((1.2 - 1.0) / 1.0)


def test_realism_score__no_connectivity_reference_leaves_two_terms(maze_office):
    s = realism_score([maze_office], paper_reference("school"))
    assert math.isnan(s.connectivity)
    assert s.overall == pytest.approx((s.features + s.shares) / 2)


def test_realism_score__contributions_are_capped(maze_office):
    s = realism_score([maze_office], paper_reference("school"), ScoreConfig(cap=1.0))
    assert max(d.z for d in s.deviations) <= 1.0


def test_paper_reference__competition_map_knows_the_27_percent():
    ref = paper_reference("robocup_2013_final_map")
    assert ref.connectivity == {"core_touching_corridor_pct": 27.0}
    assert ref.name == "the 2013 competition map"


def test_fitted_reference__spreads_over_buildings(maze_office, tiny_office):
    ref = fitted_reference([maze_office, tiny_office], "two")
    assert ref.connectivity["core_touching_corridor_pct"] == pytest.approx(100 * 5 / 7)
    assert ref.connectivity_std["core_touching_corridor_pct"] == pytest.approx(20.0)
    assert ref.table[SemanticLabel.CORRIDOR]["count"] == 3
