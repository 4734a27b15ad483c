"""Small schools (300-800 m2): valid, of the area asked for, one corridor of classrooms, no gym."""

import numpy as np
import pytest

from realistic_indoor.building import SemanticLabel, check_building
from realistic_indoor.errors import ConfigError
from realistic_indoor.generator import area_limits, generate, make_generator
from realistic_indoor.generator.rooms.annex import draw_annex
from realistic_indoor.generator.rooms.style import SCHOOL_STYLE
from realistic_indoor.io.json_format import dumps
from realistic_indoor.validator.connectivity import room_mazes

SMALLEST_M2 = 300.0
SEEDS_AT_SMALLEST = 200
BETWEEN_M2 = [350, 450, 600, 700, 799]
CIRCULATION = (SemanticLabel.CORRIDOR, SemanticLabel.HALL)


def _buildings(area_m2, seeds, model=None):
    gen = make_generator("school", area_m2, model=model)
    return [gen(np.random.default_rng(seed)) for seed in range(seeds)]


def test_small_school__the_smallest_school_is_300_m2_and_a_smaller_one_names_it():
    assert area_limits("school")[0] == SMALLEST_M2
    with pytest.raises(ConfigError, match="smallest is 300 m2"):
        make_generator("school", 299)
    assert generate("school", SMALLEST_M2, seed=0).area == pytest.approx(SMALLEST_M2, rel=0.1)


def test_small_school__every_seed_at_the_smallest_size_is_valid_and_without_mazes():
    bad = {}
    for seed, b in enumerate(_buildings(SMALLEST_M2, SEEDS_AT_SMALLEST)):
        problems = [str(f) for f in check_building(b)] + [f"maze {m}" for m in room_mazes(b)]
        if problems:
            bad[seed] = problems
    assert bad == {}


@pytest.mark.parametrize("model", [None, "paper"])
@pytest.mark.parametrize("area", [SMALLEST_M2, *BETWEEN_M2])
def test_small_school__sizes_up_to_800_m2_are_valid_and_of_the_area_asked_for(area, model):
    errors = []
    for seed, b in enumerate(_buildings(area, 30, model)):
        assert [str(f) for f in check_building(b)] == [], f"seed {seed}"
        errors.append(abs(b.area / area - 1.0))
    assert max(errors) <= 0.1
    assert np.mean(np.array(errors) <= 0.015) >= 0.9


def test_small_school__same_seed_gives_identical_json():
    assert dumps(generate("school", SMALLEST_M2, seed=4)) == dumps(generate("school", SMALLEST_M2, seed=4))


def test_small_school__is_mostly_one_corridor_with_classrooms_opening_onto_it():
    buildings = _buildings(400, 40)
    assert sum(b.metadata["shape"] == "double-loaded" for b in buildings) >= 0.9 * len(buildings)
    classrooms, apart = 0, 0
    for b in buildings:
        assert any(r.label is SemanticLabel.CORRIDOR for r in b.rooms), b.metadata
        for r in b.rooms:
            if r.function == "classroom":
                doors = b.doors_of[r.id]
                classrooms += 1
                apart += not any(d.other(r.id) and b.room(d.other(r.id)).label in CIRCULATION for d in doors)
    # classrooms open onto a corridor or hall; 3 of the 321 in the shared real schools do not
    assert classrooms >= 2 * len(buildings)
    assert apart <= 0.03 * classrooms


def test_draw_annex__no_gym_below_600_m2_sometimes_below_1200_m2_always_above():
    rng = np.random.default_rng(0)
    for area in (300.0, 599.0):
        annex, style = draw_annex(rng, area, SCHOOL_STYLE)
        assert annex == 0.0
        assert "gym" not in style.required_functions
    middle = [draw_annex(rng, 900.0, SCHOOL_STYLE)[0] > 0 for _ in range(400)]
    assert 0.4 <= np.mean(middle) <= 0.6
    for area in (1200.0, 3000.0):
        annex, style = draw_annex(rng, area, SCHOOL_STYLE)
        assert 250.0 <= annex <= 450.0
        assert style is SCHOOL_STYLE


def test_small_school__has_no_gym_annex_where_a_larger_one_always_has_one():
    for b in _buildings(550, 30):
        # no gym annex (a big gym of 150 m2 or more); rooms are sized for the building's drawn
        # room density, so a low draw gives a small school a large lab or classroom, but none
        # as large as the annex would be (at least a quarter of the floor and a gym)
        assert not [r for r in b.rooms if r.function == "gym" and r.area >= 150.0], b.metadata
        largest = max(r.area for r in b.rooms if r.label not in CIRCULATION)
        assert largest < 0.4 * b.area, b.metadata
    for b in _buildings(1200, 20):
        gym = max((r for r in b.rooms if r.function == "gym"), key=lambda r: r.area)
        assert gym.label is SemanticLabel.BIG and gym.area >= 150.0
