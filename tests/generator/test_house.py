"""Structures of real houses: a hall or short corridors serving the rooms; kitchen and living room joined."""

import numpy as np
import pytest

from realistic_indoor.building import SemanticLabel
from realistic_indoor.generator import house, make_generator
from realistic_indoor.validator.building_measures import building_measures

C, H, S, M = SemanticLabel.CORRIDOR, SemanticLabel.HALL, SemanticLabel.SMALL, SemanticLabel.MEDIUM


def _others(b, rid):
    return [None if d.other(rid) is None else b.room(d.other(rid)) for d in b.doors_of[rid]]


def test_house__bedrooms_open_onto_a_hallway_or_hall(samples):
    served = bedrooms = 0
    for b in samples("house"):
        for r in b.rooms:
            if r.function == "bedroom":
                bedrooms += 1
                served += any(o is not None and o.label in (C, H) for o in _others(b, r.id))
    assert bedrooms and served / bedrooms >= 0.95


def test_house__bathrooms_open_onto_a_hallway_or_a_bedroom(samples):
    for b in samples("house"):
        for r in b.rooms:
            if r.function == "bathroom":
                others = _others(b, r.id)
                assert any(o is not None and (o.label in (C, H) or o.function == "bedroom") for o in others)


def test_house__kitchen_joined_to_the_living_room_or_hall(samples):
    for b in samples("house"):
        kitchen = next(r for r in b.rooms if r.function == "kitchen")
        assert any(
            o is not None and (o.function in ("living room", "dining room") or o.label is H)
            for o in _others(b, kitchen.id)
        ), b.metadata


def test_house__every_house_has_a_kitchen_a_bathroom_and_a_bedroom(samples):
    for b in samples("house"):
        functions = {r.function for r in b.rooms}
        assert {"kitchen", "bathroom", "bedroom"} <= functions or {
            "kitchen",
            "bathroom",
            "study",
        } <= functions


def test_house__corridors_are_short(samples):
    lengths = [
        max(r.bounds[2] - r.bounds[0], r.bounds[3] - r.bounds[1])
        for b in samples("house")
        for r in b.rooms
        if r.label is C
    ]
    assert sum(lengths) / len(lengths) <= 10.0


def test_house__compact_footprints_at_the_default_size(samples):
    # the test: a house is rarely more than twice as long as it is wide (over 200 seeds)
    measures = [building_measures(b) for b in samples("house")]
    aspect = np.array([m.aspect_ratio for m in measures])
    assert np.median(aspect) <= 2.0
    assert np.mean(aspect > 3.0) <= 0.05
    assert np.median([m.footprint_fill for m in measures]) >= 0.85


@pytest.mark.parametrize("area", [100.0, 300.0, 1000.0])
def test_house__compact_footprints_across_sizes(area):
    gen = make_generator("house", area)
    aspect = [building_measures(gen(np.random.default_rng(seed))).aspect_ratio for seed in range(30)]
    assert np.median(aspect) <= 2.0


def _night(front_depth, *rooms):
    return [house.Strip(front_depth, 0, [house.ProgramRoom(lab, f, a) for lab, f, a in rooms], [])]


BAND = ((M, "bedroom", 19.8), (S, "bathroom", 3.3))
# bedroom 1,980 units2 / 33 = 60 units long; bathroom 330 / 33 = 10, at least 16 for its door


def test_rows__kitchen_entrance_and_night_zone_below_the_living_space():
    prog = house.Program(hall=0.0, kitchen=20.0)
    rows = house._rows(prog, _night(33, *BAND), depth=50, entry_w=27, area_m2=150.0)
    # kitchen 2,000 / 50 = 40; width 40 + 27 + 76 = 143; upper row (15,000 - 143 * 50) / 143 = 54.9
    assert rows == house.Rows(kitchen=40, night=76, top=55, width=143, depth=50)


def test_rows__the_kitchen_moves_up_where_the_hall_would_be_too_shallow():
    prog = house.Program(hall=30.0, kitchen=20.0)
    # kitchen below: (12,000 - 7,150) / 143 = 33.9 < 36 (the narrowest hall); above: width 103,
    # (12,000 - 103 * 50) / 103 = 66.5
    rows = house._rows(prog, _night(33, *BAND), depth=50, entry_w=27, area_m2=120.0)
    assert rows == house.Rows(kitchen=0, night=76, top=67, width=103, depth=50)
    # at 60 m2 even the kitchen above leaves (6,000 - 5,150) / 103 = 8 < 36
    assert house._rows(prog, _night(33, *BAND), depth=50, entry_w=27, area_m2=60.0) is None
