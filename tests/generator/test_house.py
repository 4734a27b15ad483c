"""Structures of real houses: rooms along short hallways, living rooms by the entrance, bathrooms for all."""

import numpy as np
import pytest

from realistic_indoor.generator import make_generator
from realistic_indoor.generator.house.bands import Band, band_order, deal, split, tuck, widths
from realistic_indoor.generator.house.layout import frame
from realistic_indoor.generator.house.programme import Programme, ProgrammeRoom
from realistic_indoor.generator.house.rooms import day_rects
from realistic_indoor.generator.plan import C, H
from realistic_indoor.models.house_programme import PROGRAMME
from realistic_indoor.validator.building_measures import building_measures


def _others(b, rid):
    return [None if d.other(rid) is None else b.room(d.other(rid)) for d in b.doors_of[rid]]


def test_house__bedrooms_open_onto_a_hallway_or_the_living_area(samples):
    for b in samples("house"):
        for r in b.rooms:
            if r.function == "bedroom":
                assert any(
                    o is not None and (o.label in (C, H) or o.function == "living room")
                    for o in _others(b, r.id)
                ), b.metadata


def test_house__a_bathroom_is_reached_without_crossing_a_bedroom(samples):
    # every house has a bathroom on the hallway; the others open onto it or into one bedroom
    for b in samples("house"):
        baths = [r for r in b.rooms if r.function == "bathroom"]
        assert any(any(o is not None and o.label in (C, H) for o in _others(b, r.id)) for r in baths)
        for r in baths:
            others = _others(b, r.id)
            assert any(o is not None and (o.label in (C, H) or o.function == "bedroom") for o in others)


def test_house__a_bedroom_has_at_most_one_en_suite_bathroom(samples):
    for b in samples("house"):
        for r in b.rooms:
            if r.function == "bedroom":
                assert sum(o is not None and o.function == "bathroom" for o in _others(b, r.id)) <= 1


def test_house__kitchen_joined_to_the_living_or_dining_room(samples):
    for b in samples("house"):
        kitchen = next(r for r in b.rooms if r.function == "kitchen")
        assert any(
            o is not None and o.function in ("living room", "dining room") for o in _others(b, kitchen.id)
        ), b.metadata


def test_house__every_house_has_an_entrance_a_hallway_a_kitchen_a_bathroom_and_a_bedroom(samples):
    for b in samples("house"):
        functions = {r.function for r in b.rooms}
        assert {"entrance", "hallway", "kitchen", "bathroom", "bedroom", "living room"} <= functions


def test_house__the_front_door_opens_into_the_entrance(samples):
    for b in samples("house"):
        assert b.entrances[0].room_a == next(r.id for r in b.rooms if r.function == "entrance")


def test_house__hallways_are_short(samples):
    lengths = [
        max(r.bounds[2] - r.bounds[0], r.bounds[3] - r.bounds[1])
        for b in samples("house")
        for r in b.rooms
        if r.label is C
    ]
    assert sum(lengths) / len(lengths) <= 12.0


def test_house__compact_footprints_at_the_default_size(samples):
    # median footprint no more than twice as long as wide, fill >= 0.85 (200 seeds), few long ones
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


def test_house__day_rooms_open_onto_the_day_zone(samples):
    day = {"entrance", "kitchen", "living room", "dining room"}
    for b in samples("house"):
        for r in b.rooms:
            if r.function in ("living room", "dining room"):
                assert {o.function for o in _others(b, r.id) if o is not None} & day, b.metadata


def test_house__every_hallway_is_reached_from_the_entrance_through_circulation(samples):
    for b in samples("house"):
        circulation = {r.id for r in b.rooms if r.label in (C, H)}
        seen = {r.id for r in b.rooms if r.function == "entrance"}
        stack = list(seen)
        while stack:
            i = stack.pop()
            for d in b.doors_of[i]:
                j = d.other(i)
                if j in circulation and j not in seen:
                    seen.add(j)
                    stack.append(j)
        assert circulation <= seen, b.metadata


def test_house__large_houses_keep_their_day_rooms_in_proportion():
    # the day rooms fill columns: none of the 40 houses of 1,000 m2 has one over 5 times as long as wide
    gen = make_generator("house", 1000.0)
    worst = 0.0
    for seed in range(40):
        for r in gen(np.random.default_rng(seed)).rooms:
            if r.function in ("kitchen", "living room", "dining room"):
                x0, y0, x1, y1 = r.polygon.bounds
                worst = max(worst, max(x1 - x0, y1 - y0) / min(x1 - x0, y1 - y0))
    assert worst <= 5.0


@pytest.mark.parametrize("area", [150.0, 1000.0])
def test_house__one_kitchen(area):
    gen = make_generator("house", area)
    for seed in range(40):
        b = gen(np.random.default_rng(seed))
        assert sum(r.function == "kitchen" for r in b.rooms) == 1, seed


def _room(kind, area, least, small=False, function=None):
    return ProgrammeRoom(kind, function or kind, area, least, small)


def test_split__in_proportion_with_each_pieces_least():
    assert split(100, [1.0, 1.0, 2.0], [10, 10, 10]) == [25, 25, 50]
    # 2 / 12 of 60 is 10 < 15: held at 15, the other 45 shared 4:6
    assert split(60, [2.0, 4.0, 6.0], [15, 10, 10]) == [15, 18, 27]
    # the leasts exceed the total: in proportion
    assert split(20, [1.0, 1.0], [15, 15]) == [10, 10]


def test_widths__service_rooms_as_wide_as_their_area_needs():
    # a 6 m2 bathroom 40 units deep needs 15 units, at least its 16 for a door;
    # the two bedrooms share the other 100 - 16 = 84 units 12:9
    rooms = [_room("bedroom", 12.0, 22), _room("bathroom", 6.0, 16, True), _room("bedroom", 9.0, 22)]
    assert widths(rooms, 100, 40) == [48, 16, 36]


def test_tuck__a_service_room_takes_the_hallway_side_and_its_neighbour_wraps_behind():
    band = Band(0, 100, 0, 40, hallway_above=True)
    rooms = [_room("bedroom", 12.0, 22), _room("toilet", 2.0, 16, True)]
    rects = [[(0, 0, 80, 40)], [(80, 0, 100, 40)]]
    tuck(rects, rooms, band)
    # 200 square units / 20 wide = 10 deep, raised to the least 15; the bedroom takes the rest
    assert rects == [[(0, 0, 80, 40), (80, 0, 100, 25)], [(80, 25, 100, 40)]]


def test_band_order__every_service_room_beside_an_ordinary_room():
    rooms = [_room("bedroom", 12.0, 22), _room("toilet", 2.0, 16, True), _room("store", 3.0, 16, True)]
    rooms.append(_room("bedroom", 10.0, 22))
    for keys in ([0.1, 0.2, 0.3, 0.4], [0.9, 0.1, 0.15, 0.5], [0.5, 0.99, 0.98, 0.1]):
        order = band_order([r._replace(key=k) for r, k in zip(rooms, keys, strict=True)])
        assert sorted(r._replace(key=0.0) for r in order) == sorted(rooms)
        for k, r in enumerate(order):
            if r.small:
                assert any(not order[m].small for m in (k - 1, k + 1) if 0 <= m < len(order)), order
    # the bedrooms in the order of their keys (10 m2 at 0.2, 12 m2 at 0.7), leaving three gaps;
    # the toilet (0.1) in gap int(0.1 * 3) = 0, the store (0.5) in gap int(0.5 * 3) = 1
    keyed = [r._replace(key=k) for r, k in zip(rooms, [0.7, 0.1, 0.5, 0.2], strict=True)]
    assert [(r.kind, r.area_m2) for r in band_order(keyed)] == [
        ("toilet", 2.0),
        ("bedroom", 10.0),
        ("store", 3.0),
        ("bedroom", 12.0),
    ]


def test_deal__ordinary_rooms_first_to_the_band_with_most_room_left():
    bands = [Band(0, 100, 0, 40, True), Band(0, 100, 50, 90, False)]
    rooms = [_room("bedroom", 14.0, 22), _room("bedroom", 12.0, 22), _room("bathroom", 6.0, 16, True)]
    # 14 to the first band, 12 to the second, the bathroom to the second (12 < 14 taken)
    assert deal(rooms, bands) == [[rooms[0]], [rooms[1], rooms[2]]]
    # a room whose least width fits in no band, or a band left empty: no deal
    assert deal(rooms, [Band(0, 30, 0, 40, True)] * 2) is None
    assert deal(rooms[:1], bands) is None


def test_day_rects__the_first_room_at_the_south_east_corner_each_beside_the_one_before():
    rects = day_rects((0, 0, 50, 100), [30.0, 12.0, 10.0])
    assert rects == [[(0, 0, 50, 48)], [(0, 48, 50, 74)], [(0, 74, 50, 100)]]
    # a wide box: columns from the east side, the second and third down the next column
    rects = day_rects((0, 0, 120, 70), [25.0, 12.0, 10.0])
    assert rects == [[(56, 0, 120, 70)], [(0, 38, 56, 70)], [(0, 0, 56, 38)]]


def test_frame__zones_tile_the_footprint_and_the_entrance_opens_on_the_hallway():
    row = PROGRAMME[4]  # 150-190 m2
    day = (_room("living room", 25.0, 26), _room("kitchen", 12.0, 26))
    night = (*tuple(_room("bedroom", 12.0, 22) for _ in range(3)), _room("bathroom", 6.0, 16, True))
    prog = Programme(150.0, row, day, night, hallway_width_m=1.0, entrance_width_m=2.0)
    f = frame(prog, strips=1, band=40)
    assert f is not None
    # 90 units deep, 15,000 / 90 = 167 wide; the entrance beside the day zone under the hallway
    assert (f.depth, f.width) == (90, 167)
    x = f.day[2]
    assert f.entrance == (x, 0, x + 20, 40) and f.hallway == [(x, 40, 167, 50)]
    area = sum((b.x1 - b.x0) * (b.y1 - b.y0) for b in f.bands) + 20 * 40 + (167 - x) * 10 + x * 90
    assert area == 167 * 90
    assert sorted(r for rooms in f.rooms for r in rooms) == sorted(night)
