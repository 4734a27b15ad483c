import numpy as np
import pytest

from realistic_indoor.building import ROOM_LABELS, Building, Door, Room, check_building
from realistic_indoor.errors import ConfigError
from realistic_indoor.generator import generate, regenerate
from realistic_indoor.io.json_format import dumps

TYPES = ["office", "school", "house", "random"]


def _pick(b, seed, n=6):
    rng = np.random.default_rng(seed)
    return [
        str(r) for r in rng.choice([r.id for r in b.rooms], size=min(n, len(b.rooms) // 3), replace=False)
    ]


@pytest.mark.parametrize("kind", TYPES)
def test_regenerate__result_is_valid_and_keeps_every_other_room_and_door(kind):
    for seed in range(8):
        b = generate(kind, seed=seed)
        picked = _pick(b, seed)
        b2 = regenerate(b, rooms=picked, seed=seed)
        assert check_building(b2) == [], seed
        kept = [r for r in b.rooms if r.id not in picked]
        assert all(b2.room(r.id) == r for r in kept)
        untouched = [d for d in b.doors if d.room_a not in picked and d.room_b not in picked]
        assert set(untouched) <= set(b2.doors)
        assert b2.area == pytest.approx(b.area)


def test_regenerate__resamples_the_portion():
    b = generate("office", seed=4)
    picked = [r.id for r in b.rooms if r.label in ROOM_LABELS][:10]
    b2 = regenerate(b, rooms=picked, seed=1)
    assert not any(rid in b2.room_by_id for rid in picked)
    new = [r for r in b2.rooms if r.id not in b.room_by_id]
    assert new and all(r.function for r in new)
    assert sum(r.area for r in new) == pytest.approx(sum(b.room(rid).area for rid in picked))


def test_regenerate__region_selects_rooms_by_their_centre():
    b = generate("office", seed=5)
    x0, y0, x1, y1 = b.bounds
    box = (x0, y0, (x0 + x1) / 2, (y0 + y1) / 2)
    b2 = regenerate(b, region=box, seed=2)
    inside = [
        r.id
        for r in b.rooms
        if box[0] <= r.polygon.centroid.x <= box[2] and box[1] <= r.polygon.centroid.y <= box[3]
    ]
    outside = [r for r in b.rooms if r.id not in inside]
    assert all(b2.room(r.id) == r for r in outside)
    assert check_building(b2) == []
    assert b2.metadata["regenerated"] == [{"rooms": inside, "seed": 2}]


def test_regenerate__corridors_in_the_portion_are_cut_anew_in_place():
    b = generate("office", seed=6)
    corridors = [r.id for r in b.rooms if r.label.value == "corridor"][:3]
    b2 = regenerate(b, rooms=corridors, seed=0)
    assert check_building(b2) == []
    before = sum(b.room(c).area for c in corridors)
    after = sum(r.area for r in b2.rooms if r.id not in b.room_by_id)
    assert after == pytest.approx(before)


def test_regenerate__same_seed_same_result_other_seed_differs():
    b = generate("school", seed=2)
    picked = _pick(b, 1, 8)
    assert dumps(regenerate(b, rooms=picked, seed=9)) == dumps(regenerate(b, rooms=picked, seed=9))
    assert dumps(regenerate(b, rooms=picked, seed=9)) != dumps(regenerate(b, rooms=picked, seed=10))


def test_regenerate__bad_selections_are_config_errors():
    b = generate("house", seed=1)
    with pytest.raises(ConfigError, match="either rooms"):
        regenerate(b)
    with pytest.raises(ConfigError, match="no room with id 'nope'"):
        regenerate(b, rooms=["nope"])
    with pytest.raises(ConfigError, match="xmin < xmax"):
        regenerate(b, region=(5, 5, 1, 1))
    with pytest.raises(ConfigError, match="no room has its centre"):
        regenerate(b, region=(1000, 1000, 1001, 1001))
    with pytest.raises(ConfigError, match="seed"):
        regenerate(b, rooms=[b.rooms[0].id], seed=-3)


def test_regenerate__plans_that_are_not_rectilinear_are_refused():
    rooms = (
        Room("c", "corridor", "corridor", ((0, 0), (10, 0), (10, 2), (0, 2))),
        Room("a", "medium", "office", ((0, 2), (5, 2), (4, 6), (0, 6))),
    )
    doors = (Door("d", "a", "c", 2.0, 2.0), Door("e", "c", None, 0.0, 1.0, 1.0, np.pi / 2))
    with pytest.raises(ConfigError, match="not rectilinear"):
        regenerate(Building("office", rooms, doors), rooms=["a"], seed=0)
