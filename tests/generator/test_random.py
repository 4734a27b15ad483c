"""The World-Generator-like baseline: its layout rules, and the faults the paper measured on it."""

import numpy as np
import pytest

from realistic_indoor.building import ROOM_LABELS, SemanticLabel
from realistic_indoor.errors import ConfigError
from realistic_indoor.generator import RandomGridGenerator, generate, make_generator
from realistic_indoor.io.json_format import dumps
from realistic_indoor.models import reference_table
from realistic_indoor.validator.connectivity import Connectivity, connectivity
from realistic_indoor.validator.tables import label_table

C = SemanticLabel.CORRIDOR


def test_random__grid_of_3_m_cells_with_a_hallway_ring():
    b = RandomGridGenerator(width_units=10, height_units=7)(np.random.default_rng(4))
    x0, y0, x1, y1 = b.bounds
    assert sorted([x1 - x0, y1 - y0]) == [21.0, 30.0]
    for r in b.rooms:
        for x, y in r.outline:
            assert x % 3 == pytest.approx(0) or x % 3 == pytest.approx(3)
            assert y % 3 == pytest.approx(0) or y % 3 == pytest.approx(3)
    ring = [r for r in b.rooms if r.label is C and (r.bounds[0] == x0 or r.bounds[2] == x1)]
    assert ring, "hallways run along the perimeter"
    for r in b.rooms:
        if r.label is not C:
            rx0, ry0, rx1, ry1 = r.bounds
            assert x0 < rx0 and rx1 < x1 and y0 < ry0 and ry1 < y1, "rooms lie inside the ring"
            assert max(rx1 - rx0, ry1 - ry0) <= 12.0, "modules are at most 4 x 4 cells"


def test_random__every_room_has_one_to_a_few_doors(samples):
    for b in samples("random")[:50]:
        for r in b.rooms:
            if r.label in ROOM_LABELS:
                assert 1 <= len(b.doors_of[r.id]) <= 8


def test_random__area_picks_a_grid_and_seed_repeats(samples):
    gen = make_generator("random", 1200)
    assert gen == RandomGridGenerator.from_area(1200)
    assert gen.width_units * gen.height_units * 9 == pytest.approx(1200, rel=0.1)
    assert dumps(generate("random", seed=3)) == dumps(generate("random", seed=3))
    assert dumps(generate("random", seed=3)) != dumps(generate("random", seed=4))


def test_random__grid_size_options_and_their_errors():
    assert make_generator("random", width_units=8, height_units=6) == RandomGridGenerator(8, 6)
    with pytest.raises(ConfigError, match="from 5 to 200"):
        RandomGridGenerator(width_units=3, height_units=8)
    with pytest.raises(ConfigError, match="either an area or"):
        make_generator("random", 500, width_units=8, height_units=6)
    with pytest.raises(ConfigError, match="bad option"):
        make_generator("random", floors=2)


@pytest.fixture(scope="module")
def random_connectivity(samples):
    return Connectivity.combine([connectivity(b) for b in samples("random")])


def test_random__few_offices_touch_a_corridor(random_connectivity):
    assert random_connectivity.core_touching_corridor_pct < 80.0


def test_random__offices_open_onto_each_other(samples):
    linked = offices = 0
    for b in samples("random"):
        for r in b.rooms:
            if r.function == "office":
                offices += 1
                linked += any(
                    d.other(r.id) and b.room(d.other(r.id)).label in ROOM_LABELS for d in b.doors_of[r.id]
                )
    assert linked / offices >= 0.3


def test_random__corridors_have_few_doors(samples):
    got = label_table(samples("random"))[C]["doors_mean"]
    assert got < reference_table("office")[C]["doors_mean"] - 1.5


def test_random__misses_the_realistic_generators_criteria(samples, random_connectivity):
    got, ref = label_table(samples("random")), reference_table("office")
    missed = [lab for lab in ROOM_LABELS if abs(got[lab]["doors_mean"] - ref[lab]["doors_mean"]) > 0.3]
    assert len(missed) == 3
    assert not 60.0 <= random_connectivity.only_to_corridors_pct <= 80.0
