import json
from importlib import resources

import pytest

from realistic_indoor.building import Building, BuildingType, Room, SemanticLabel
from realistic_indoor.errors import ConfigError, RealisticIndoorError
from realistic_indoor.validator.compare import common_building_type, compare_sets, judged_type, prepare_set
from realistic_indoor.validator.plan_sets import PlanSet, SkippedPlan, SkippedPlanWarning
from realistic_indoor.validator.reference import paper_reference


@pytest.fixture
def mazes(maze_office, scaled):
    return PlanSet.of("mazes", [scaled(maze_office, f) for f in (0.9, 1.0, 1.1, 1.2)])


@pytest.fixture
def tidy(tiny_office, scaled):
    return PlanSet.of("tidy", [scaled(tiny_office, f) for f in (0.9, 1.0, 1.1, 1.2)])


def _doorless() -> Building:
    return Building(
        "office", (Room.rectangle("a", "medium", "office", (0, 0, 4, 4)),), (), {"source": "doorless.json"}
    )


def test_compare_sets__scores_tables_and_tests_for_each_set(mazes, tidy):
    c = compare_sets([mazes, tidy], seed=0)
    assert c.building_type is BuildingType.OFFICE
    assert c.reference.name == "real offices"
    assert [s.name for s in c.sets] == ["mazes", "tidy"]
    assert c.sets[0].connectivity.core_touching_corridor_pct == pytest.approx(60.0)
    assert c.sets[1].connectivity.core_touching_corridor_pct == pytest.approx(100.0)
    assert c.sets[0].rooms == 32
    pairs = [(t.name_a, t.name_b, t.features) for t in c.two_sample]
    assert pairs == [("mazes", "tidy", "room"), ("mazes", "tidy", "building"), ("mazes", "tidy", "all")]
    assert c.two_sample[0].accuracy == pytest.approx(1.0)
    assert len(c.sets[0].measures) == len(mazes.buildings)


def test_compare_sets__same_as_score_of_the_set_alone(mazes):
    from realistic_indoor.validator.score import realism_score

    c = compare_sets([mazes], "office")
    assert c.sets[0].score == realism_score(mazes.buildings, paper_reference("office"))
    assert c.two_sample == ()
    assert any("needs two sets" in n or "compares two sets" in n for n in c.notes)


def test_compare_sets__reference_fitted_from_plans_joins_the_two_sample_tests(mazes, tidy):
    c = compare_sets([mazes], "office", reference=tidy)
    assert c.reference.name == "tidy"
    assert c.reference_set is not None
    assert [(t.name_a, t.name_b) for t in c.two_sample] == [("mazes", "tidy")] * 3
    assert len(c.reference_measures) == len(tidy.buildings)
    assert c.reference.connectivity["core_touching_corridor_pct"] == pytest.approx(100.0)


def test_compare_sets__a_set_against_itself_scores_zero(tidy):
    c = compare_sets([tidy], "office", reference=PlanSet("same", tidy.buildings, tidy.sources))
    assert c.sets[0].score.overall == pytest.approx(0.0)


def test_compare_sets__infers_labels_of_unlabelled_plans(maze_office, strip_labels):
    plain = PlanSet.of("plain", [strip_labels(maze_office)] * 2)
    c = compare_sets([plain], "office", two_sample=False)
    assert c.sets[0].inferred == ("maze_office", "maze_office")
    assert c.sets[0].table[SemanticLabel.CORRIDOR]["count"] == 2  # C1 of each plan; C2 looks like a room
    c = compare_sets([plain], "office", infer="never", two_sample=False)
    assert c.sets[0].inferred == ()


def test_compare_sets__plan_without_doors_is_a_clear_error_or_skipped(mazes):
    bad = PlanSet("bad", (*mazes.buildings, _doorless()), (*mazes.sources, "doorless.json"))
    with pytest.raises(RealisticIndoorError, match=r"doorless.json: the plan has no doors.*skip_bad=True"):
        compare_sets([bad], "office")
    with pytest.warns(SkippedPlanWarning, match=r"^skipped doorless.json: the plan has no doors"):
        c = compare_sets([bad], "office", skip_bad=True, two_sample=False)
    assert len(c.sets[0].plans) == 4
    assert c.sets[0].skipped[0][0] == "doorless.json"


def test_compare_sets__bad_input_messages(mazes):
    with pytest.raises(ConfigError, match="holds no plans"):
        compare_sets([PlanSet("none", (), ())], "office")
    with pytest.raises(ConfigError, match="at least one set"):
        compare_sets([], "office")
    with pytest.raises(ConfigError, match="unknown building type 'castle'"):
        compare_sets([mazes], "castle")
    with pytest.raises(ConfigError, match="no reference table 'mall'"):
        compare_sets([mazes], "office", reference="mall")
    with pytest.raises(ConfigError, match="same name"):
        compare_sets([mazes, mazes], "office")
    with (
        pytest.raises(ConfigError, match=r"all 1 left out, e\.g\. doorless\.json: the plan has no doors"),
        pytest.warns(SkippedPlanWarning),
    ):
        prepare_set(PlanSet.of("x", [_doorless()]), "office", skip_bad=True)
    with pytest.raises(ConfigError, match="unknown label inference mode"):
        prepare_set(mazes, "office", infer="sometimes")


def test_common_building_type__from_the_plans_or_a_clear_error(mazes, room_chain_house):
    assert common_building_type([mazes]) is BuildingType.OFFICE
    with pytest.raises(ConfigError, match=r"several types \(house, office\); choose one with --type"):
        common_building_type([mazes, PlanSet.of("h", [room_chain_house])])
    unknown = Building("unknown", mazes.buildings[0].rooms, mazes.buildings[0].doors)
    with pytest.raises(ConfigError, match="do not say what type"):
        common_building_type([PlanSet.of("u", [unknown])])


def test_compare_sets__scale_flags_use_the_plan_type(maze_office, scaled):
    big = PlanSet.of("big", [scaled(maze_office, 10.0), maze_office])
    (flag,) = compare_sets([big], "office", two_sample=False).sets[0].scale_flags
    data = json.loads(
        resources.files("realistic_indoor").joinpath("data/real_models.json").read_text("utf-8")
    )
    expected = data["office"]["labels"]["medium"]["area_mean"]  # real offices' medium rooms
    assert flag.length_factor == pytest.approx((expected / 1600) ** 0.5)
    assert flag.reference == "real offices"


def test_judged_type__valid_types_are_the_three_with_a_reference():
    assert judged_type("School") is BuildingType.SCHOOL
    with pytest.raises(ConfigError) as e:
        judged_type("castle")
    assert str(e.value) == "unknown building type 'castle'; valid types: office, school, house"
    with pytest.raises(
        ConfigError, match=r"cannot be judged as of type 'unknown'; choose one of: office, school, house$"
    ):
        judged_type("unknown")


def test_compare_sets__unreadable_plans_of_sets_and_reference_are_reported(mazes, tidy):
    """Plans a set could not read come first among its left-out plans; the reference's go to notes."""
    broken = PlanSet(
        mazes.name, mazes.buildings, mazes.sources, (SkippedPlan("broken.xml", "malformed XML"),)
    )
    ref = PlanSet(tidy.name, tidy.buildings, tidy.sources, (SkippedPlan("empty.json", "no rooms key"),))
    c = compare_sets([broken], "office", reference=ref, two_sample=False)
    assert c.sets[0].skipped == (("broken.xml", "malformed XML"),)
    assert len(c.sets[0].plans) == 4
    assert c.reference_skipped == (("empty.json", "no rooms key"),)
    assert "reference tidy: left out empty.json: no rooms key" in c.notes
