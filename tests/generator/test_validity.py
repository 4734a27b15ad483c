"""Generated buildings are valid, tile their footprint and have usable doors, at every size."""

import numpy as np
import pytest
from shapely.geometry import Point
from shapely.ops import unary_union

from realistic_indoor.building import check_building
from realistic_indoor.generator import make_generator
from realistic_indoor.validator.connectivity import room_mazes

TYPES = ["office", "school", "house", "random"]
REALISTIC = ["office", "school", "house"]
SIZES = {
    "office": [250, 600, 1200, 3500, 6000, 10_000],
    "school": [300, 800, 1500, 3000, 6000, 10_000],
    "house": [50, 100, 300, 600, 1000],
    "random": [225, 1000, 5000, 10_000],
}
SLOW_SEEDS = 1000


def _problems(b):
    return [str(f) for f in check_building(b)]


@pytest.mark.parametrize("kind", TYPES)
def test_validity__every_building_of_the_sample_passes_check_building(kind, samples):
    bad = {i: _problems(b) for i, b in enumerate(samples(kind))}
    assert {i: p for i, p in bad.items() if p} == {}


@pytest.mark.slow
@pytest.mark.parametrize("kind", TYPES)
def test_validity__a_thousand_seeds_at_default_size_pass_check_building(kind):
    gen = make_generator(kind)
    bad = {}
    for seed in range(200, 200 + SLOW_SEEDS):
        problems = _problems(gen(np.random.default_rng(seed)))
        if problems:
            bad[seed] = problems
    assert bad == {}


@pytest.mark.parametrize(("kind", "area"), [(k, a) for k in TYPES for a in SIZES[k]])
def test_validity__sizes_from_the_smallest_to_10000_m2_pass_check_building(kind, area):
    gen = make_generator(kind, area)
    for seed in range(8):
        b = gen(np.random.default_rng(seed))
        assert _problems(b) == [], f"seed {seed}"
        assert b.area == pytest.approx(area, rel=0.1)


def _edges(room):
    pts = room.outline
    return [(pts[k], pts[(k + 1) % len(pts)]) for k in range(len(pts))]


@pytest.mark.parametrize("kind", TYPES)
def test_geometry__rooms_are_rectilinear_on_a_10_cm_grid(kind, samples):
    for b in samples(kind)[:40]:
        for r in b.rooms:
            for (x0, y0), (x1, y1) in _edges(r):
                assert x0 == x1 or y0 == y1, r.id
                for v in (x0, y0):
                    assert abs(v * 10 - round(v * 10)) < 1e-6


@pytest.mark.parametrize("kind", TYPES)
def test_geometry__rooms_tile_the_footprint_without_slivers_of_void(kind, samples):
    for b in samples(kind)[:40]:
        union = unary_union([r.polygon for r in b.rooms])
        assert union.geom_type == "Polygon", "the building is in one piece"
        assert union.area == pytest.approx(b.area, rel=1e-6)
        for hole in union.interiors:
            court = hole.envelope
            x0, y0, x1, y1 = court.bounds
            assert min(x1 - x0, y1 - y0) >= 5.0, "an enclosed void is a courtyard, not a gap"


def _door_clear_of_corners(b, door, clearance):
    dx, dy = door.direction
    h = door.width_m / 2 + clearance
    ends = [Point(door.x - h * dx, door.y - h * dy), Point(door.x + h * dx, door.y + h * dy)]
    return all(b.room(rid).polygon.exterior.distance(p) < 1e-6 for rid in door.rooms for p in ends)


@pytest.mark.parametrize("kind", TYPES)
def test_doors__room_doors_are_0_9_m_and_clear_of_wall_corners(kind, samples):
    for b in samples(kind)[:40]:
        for d in b.doors:
            labels = {b.room(r).label.value for r in d.rooms}
            if d.is_exterior or labels <= {"corridor", "hall"}:
                assert d.width_m >= 0.6
                assert _door_clear_of_corners(b, d, 0.1), d.id
            else:
                assert d.width_m == pytest.approx(0.9)
                assert _door_clear_of_corners(b, d, 0.25), d.id


@pytest.mark.parametrize("kind", TYPES)
def test_doors__openings_into_halls_are_wider_than_room_doors(kind, samples):
    widths = [
        d.width_m
        for b in samples(kind)[:40]
        for d in b.doors
        if any(b.room(r).label.value == "hall" for r in d.rooms)
        and all(b.room(r).label.value in ("corridor", "hall") for r in d.rooms)
    ]
    wide = [w for w in widths if w > 0.95]
    assert len(wide) >= 0.95 * len(widths)
    assert sum(widths) / len(widths) >= 1.3


@pytest.mark.parametrize("kind", TYPES)
def test_entrances__in_a_hall_or_at_a_corridor(kind, samples):
    for b in samples(kind):
        assert b.entrances
        assert any(b.room(d.room_a).label.value in ("hall", "corridor") for d in b.entrances)


@pytest.mark.parametrize(("kind", "long"), [("office", 2.2), ("school", 2.2), ("house", 1.6)])
def test_footprint__long_narrow_and_compact_buildings_both_occur(kind, long, samples):
    # houses are compact (rarely more than twice as long as wide), yet not all square
    aspect = []
    for b in samples(kind)[:100]:
        x0, y0, x1, y1 = b.bounds
        aspect.append(max(x1 - x0, y1 - y0) / min(x1 - x0, y1 - y0))
    assert min(aspect) < 1.4
    assert max(aspect) > long


def _is_suite(b, maze):
    """Whether ``maze`` is one big room and small rooms whose every door leads into it."""
    doors = {rid: [d.other(rid) for d in b.doors if rid in d.rooms] for rid in maze}
    heads = [rid for rid in maze if any(o not in maze for o in doors[rid])]
    if len(heads) != 1 or b.room(heads[0]).label.value != "big":
        return False
    return all(
        b.room(rid).label.value == "small" and set(doors[rid]) == {heads[0]}
        for rid in maze
        if rid != heads[0]
    )


@pytest.mark.parametrize("kind", ["office", "house"])
def test_structure__no_rooms_reachable_only_through_each_other(kind, samples):
    assert sum(len(room_mazes(b)) for b in samples(kind)) == 0


def test_structure__schools_reach_rooms_through_rooms_only_in_a_big_rooms_suite(samples):
    # a gym's changing rooms and stores open onto the gym alone, as in real schools; any other
    # group of rooms reached only through each other would be an office maze
    mazes = [(b, m) for b in samples("school") for m in room_mazes(b)]
    assert mazes  # the gyms' suites occur
    assert [sorted(m) for b, m in mazes if not _is_suite(b, m)] == []
