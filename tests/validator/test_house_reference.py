"""House plans against the house programme: counts by function, hallway widths, bathroom and bedroom access."""

from __future__ import annotations

import json
import math
import statistics

import numpy as np
import pytest
from shapely.geometry import Polygon

from realistic_indoor.building import Building, Door, Room
from realistic_indoor.generator import make_generator
from realistic_indoor.validator import PlanSet, compare_sets, render_comparison
from realistic_indoor.validator.house_programme import (
    CountRange,
    allowed_counts,
    hallway_width,
    house_check,
    house_summary,
)

V = math.pi / 2  # a door on a vertical wall


def house(
    hallway_m: float = 1.0, bedroom: str = "bedroom", study: str = "study", ensuite: bool = False
) -> Building:
    """A house of 15 m x 10 m = 150 m2 with three bedrooms along one hallway.

    ::

        y=10 +-------+--------+--------+
             |   K   |   B3   |   St   |      K kitchen 5x4, L living 5x6
        y=6  +--d----+        |        |      E entrance 2x4, H hallway 10 x hallway_m
             |       +---d----+---d----+      B1 4x4, W bathroom 2x4, B2 2x4 below H;
             |   L   d  H (5..15 x 4..4+hallway_m) B3 5x(6-hallway_m), St (a study) above it
        y=4  |       +-d-+-d--+-d-+-d--+
             |       d E |  B1  |W | B2|
        y=0  +-------+-e-+------+--+---+
             x=0     5   7      11 13  15

    Args:
        hallway_m: Width of the hallway (m); the rooms above it lose what it gains.
        bedroom: Function of B1, B2 and B3.
        study: Function of St.
        ensuite: Let St open into B3 instead of the hallway.
    """
    top = 4 + hallway_m
    rooms = (
        Room.rectangle("L", "big", "living room", (0, 0, 5, 6)),
        Room.rectangle("K", "medium", "kitchen", (0, 6, 5, 10)),
        Room.rectangle("E", "hall", "entrance", (5, 0, 7, 4)),
        Room.rectangle("H", "corridor", "hallway", (5, 4, 15, top)),
        Room.rectangle("B1", "medium", bedroom, (7, 0, 11, 4)),
        Room.rectangle("W", "small", "bathroom", (11, 0, 13, 4)),
        Room.rectangle("B2", "small", bedroom, (13, 0, 15, 4)),
        Room.rectangle("B3", "medium", bedroom, (5, top, 10, 10)),
        Room.rectangle("St", "medium", study, (10, top, 15, 10)),
    )
    doors = [
        Door("e", "E", None, 6, 0),
        Door("d1", "E", "H", 6, 4),
        Door("d2", "L", "E", 5, 2, 0.9, V),
        Door("d3", "K", "L", 2.5, 6),
        Door("d4", "B1", "H", 9, 4),
        Door("d5", "W", "H", 12, 4),
        Door("d6", "B2", "H", 14, 4),
        Door("d7", "B3", "H", 7.5, top),
        Door("d8", "St", "B3", 10, 8, 0.9, V) if ensuite else Door("d8", "St", "H", 12.5, top),
    ]
    return Building("house", rooms, tuple(doors), {"source": "hand-made house"})


def rewired(b: Building, door: Door) -> Building:
    """``b`` with ``door`` in place of its door of the same id."""
    return Building("house", b.rooms, tuple(door if d.id == door.id else d for d in b.doors))


def test_hallway_width__the_short_side_of_the_rectangle_with_its_area_and_perimeter():
    assert hallway_width(Polygon([(0, 0), (10, 0), (10, 1), (0, 1)])) == pytest.approx(1.0)
    # an L of arms 10 m and 6 m, 1 m wide: area 15 m2, perimeter 32 m, so sides 15 m and 1 m
    # (its smallest enclosing rectangle would be 6 m wide)
    ell = Polygon([(0, 0), (10, 0), (10, 1), (1, 1), (1, 6), (0, 6)])
    assert hallway_width(ell) == pytest.approx(1.0)


def test_allowed_counts__the_tables_bands_near_the_floor_area():
    # 170 m2 lies in 150-190 only: bedrooms 3-4, bathrooms 1-2, living rooms 1
    at_170 = allowed_counts(170.0)
    assert (at_170["bedrooms"], at_170["bathrooms"], at_170["living_rooms"]) == (
        CountRange(3, 4),
        CountRange(1, 2),
        CountRange(1, 1),
    )
    # 150 m2 is within 2% of 120-150 (bedrooms 3) and in 150-190 (3-4)
    assert allowed_counts(150.0)["bedrooms"] == CountRange(3, 4)
    # 64 m2 is within 2% of 65-90: bedrooms 1 (50-65) or 1-2 (65-90)
    assert allowed_counts(64.0)["bedrooms"] == CountRange(1, 2)
    assert allowed_counts(100.0)["bedrooms"] == CountRange(2, 3)
    fixed = allowed_counts(100.0)
    assert (str(fixed["kitchens"]), str(fixed["entrances"]), str(fixed["hallways"])) == (
        "1",
        "1",
        "1 or more",
    )


def test_house_check__a_house_of_the_programme_is_inside_on_every_item():
    c = house_check(house())
    assert c.floor_area_m2 == pytest.approx(150.0)
    assert c.bands == ("120-150 m2", "150-190 m2")
    assert c.counts == {
        "bedrooms": 3,
        "bathrooms": 1,
        "kitchens": 1,
        "living_rooms": 1,
        "entrances": 1,
        "hallways": 1,
    }
    assert c.hallway_widths_m == pytest.approx((1.0,))
    assert c.corridor_share == pytest.approx(10 / 150)
    assert c.bathroom_reachable is True and c.bedrooms_open_off_living is True
    assert all(c.items.values()) and c.inside and c.problems() == ()


def test_house_check__a_bathroom_reached_only_through_a_bedroom_is_flagged():
    c = house_check(rewired(house(), Door("d5", "W", "B1", 11, 2, 0.9, V)))
    assert c.bathroom_reachable is False and not c.inside
    assert c.problems() == ("every bathroom is reached only through a bedroom",)


def test_house_check__an_en_suite_beside_a_bathroom_off_the_hallway_is_fine():
    c = house_check(house(study="bathroom", ensuite=True))
    assert c.counts["bathrooms"] == 2 and c.bathroom_reachable is True
    assert c.inside


def test_house_check__a_wide_hallway_is_flagged_with_its_floor_share():
    # a 10 m x 2.5 m hallway: 2.5 m wide, 25 m2 of 150 m2 (16.7%) corridor-labelled
    c = house_check(house(hallway_m=2.5))
    assert c.hallway_widths_m == pytest.approx((2.5,))
    assert c.corridor_share == pytest.approx(25 / 150)
    assert {k for k, ok in c.items.items() if not ok} == {"hallway_width", "corridor_share"}
    assert c.problems() == (
        "hallways 2.50 m wide; the programme has 0.9-1.5 m",
        "16.7% of the floor corridor-labelled; the programme has at most 15%",
    )


def test_house_check__a_house_of_150_m2_without_bedrooms_is_flagged():
    c = house_check(house(bedroom="study"))
    assert c.counts["bedrooms"] == 0 and c.items["bedrooms"] is False
    assert c.bedrooms_open_off_living is None and c.items["bedroom_access"] is None
    assert c.problems() == ("0 bedrooms; the programme has 3-4 at 120-150 m2 or 150-190 m2",)


def test_house_check__a_bedroom_entered_through_another_is_flagged():
    c = house_check(rewired(house(), Door("d6", "B2", "W", 13, 2, 0.9, V)))
    assert c.bedrooms_open_off_living is False
    assert c.problems() == ("a bedroom opens off neither a hallway nor the living area",)


def test_house_summary__share_of_plans_inside_per_item():
    s = house_summary(
        [house_check(house()), house_check(house(bedroom="study")), house_check(house(hallway_m=2.5))]
    )
    assert s.plans == 3
    assert s.inside["bedrooms"] == pytest.approx(2 / 3)
    assert s.inside["hallway_width"] == pytest.approx(2 / 3)
    assert s.inside["bedroom_access"] == 1.0  # judged on the two plans with bedrooms
    assert s.all_inside == pytest.approx(1 / 3)
    assert s.medians["bedrooms"] == 3 and s.medians["hallway_width"] == pytest.approx(1.0)


@pytest.mark.parametrize("area", [60.0, 100.0, 150.0, 250.0, 400.0])
def test_generated_houses__follow_the_programme(area):
    # docs/generator.md: houses of 60-400 m2 follow the programme table; hallways 0.9-1.5 m
    gen = make_generator("house", area)
    checks = [house_check(gen(np.random.default_rng(seed))) for seed in range(8)]
    assert house_summary(checks).all_inside == 1.0, [c.problems() for c in checks if not c.inside]


def test_generated_houses__the_default_size_meets_issue_34():
    # 60 houses of 150 m2: median >= 3 bedrooms, hallways median <= 1.5 m, corridor floor <= 15%
    gen = make_generator("house", 150.0)
    checks = [house_check(gen(np.random.default_rng(seed))) for seed in range(60)]
    s = house_summary(checks)
    assert s.medians["bedrooms"] >= 3
    assert s.medians["hallway_width"] <= 1.5
    assert max(c.corridor_share for c in checks) <= 0.15
    assert statistics.median(c.corridor_share for c in checks) == pytest.approx(s.medians["corridor_share"])


def test_validate__house_sets_get_the_programme_table_and_json():
    good, bad = PlanSet.of("good", [house(), house()]), PlanSet.of("bad", [house(), house(bedroom="study")])
    c = compare_sets([good, bad], "house", two_sample=False)
    text = render_comparison(c, "markdown")
    assert "### House programme: against the house programme of docs/generator.md" in text
    assert "NDSS, SOC, LHDG, LABC, T1, ADM, DIN" in text
    assert "| bedrooms | 100% [3] | 50% [1.5] | 3 at 120-150 m2; 3-4 at 150-190 m2 |" in text
    assert "### Houses outside the programme" in text
    assert "bad: hand-made house: 0 bedrooms; the programme has 3-4" in text
    data = json.loads(render_comparison(c, "json"))
    assert set(data["house_reference"]["sources"]) == {"NDSS", "SOC", "LHDG", "LABC", "T1", "ADM", "DIN"}
    bad_set = data["sets"][1]["house_programme"]
    assert bad_set["summary"]["inside"]["bedrooms"] == 0.5
    assert [p["inside"] for p in bad_set["plans"]] == [True, False]
    csv = render_comparison(c, "csv")
    assert "house,bad,bedrooms,share_inside,0.5" in csv


def test_validate__other_types_get_no_house_programme():
    c = compare_sets([PlanSet.of("h", [house()])], "office", two_sample=False)
    assert c.sets[0].houses == () and c.sets[0].house_summary is None
    assert "House programme" not in render_comparison(c, "table")
    assert "house_reference" not in json.loads(render_comparison(c, "json"))
