"""Structures of real houses: a hall or short corridors serving the rooms; kitchen and living room joined."""

from realistic_indoor.building import SemanticLabel

C, H = SemanticLabel.CORRIDOR, SemanticLabel.HALL


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
