"""Structures of real offices that random maps lack (checked on the session's 200 offices)."""

from collections import Counter

import networkx as nx

from realistic_indoor.building import ROOM_LABELS, SemanticLabel

C, H = SemanticLabel.CORRIDOR, SemanticLabel.HALL


def _partners(b, rid):
    return [None if d.other(rid) is None else b.room(d.other(rid)).label for d in b.doors_of[rid]]


def test_office__nearly_every_room_has_one_door_to_a_corridor(samples):
    counts = Counter()
    for b in samples("office"):
        for r in b.rooms:
            if r.label in ROOM_LABELS:
                counts["rooms"] += 1
                counts["one door to a corridor"] += _partners(b, r.id) == [C]
    assert counts["one door to a corridor"] / counts["rooms"] >= 0.55


def test_office__corridors_serve_many_rooms(samples):
    rooms_per_corridor = []
    for b in samples("office"):
        for r in b.rooms:
            if r.label is C:
                rooms_per_corridor.append(sum(lab in ROOM_LABELS for lab in _partners(b, r.id)))
    assert sum(rooms_per_corridor) / len(rooms_per_corridor) >= 3.0


def test_office__corridors_and_halls_form_one_network(samples):
    for b in samples("office"):
        circulation = [r.id for r in b.rooms if r.label in (C, H)]
        assert nx.is_connected(b.graph().subgraph(circulation)), b.metadata


def test_office__corridors_chain_into_each_other(samples):
    joined = total = 0
    for b in samples("office"):
        for r in b.rooms:
            if r.label is C:
                total += 1
                joined += any(lab in (C, H) for lab in _partners(b, r.id))
    assert joined == total


def test_office__halls_at_the_entrance_and_at_corridor_junctions(samples):
    entrance_halls = junction_halls = halls = 0
    for b in samples("office", "paper"):
        entrance_halls += any(b.room(d.room_a).label is H for d in b.entrances)
        for r in b.rooms:
            if r.label is H:
                halls += 1
                junction_halls += sum(lab is C for lab in _partners(b, r.id)) >= 2
    assert entrance_halls / 200 >= 0.8
    assert junction_halls / halls >= 0.7


def test_office__the_default_layout_enters_through_a_hall(samples):
    entrance_halls = sum(any(b.room(d.room_a).label is H for d in b.entrances) for b in samples("office"))
    assert entrance_halls / 200 >= 0.8


def test_office__toilets_and_storage_are_grouped(samples):
    lavatories = {"toilet", "washroom", "bathroom"}
    service = lavatories | {"storage", "stairs", "elevator", "closet"}
    grouped = toilets = 0
    for b in samples("office")[:60]:
        polys = {r.id: r.polygon for r in b.rooms}
        for r in b.rooms:
            if r.function not in lavatories:
                continue
            toilets += 1
            grouped += any(
                o.id != r.id and o.function in service and polys[r.id].intersection(polys[o.id]).length >= 1.0
                for o in b.rooms
            )
    assert toilets and grouped / toilets >= 0.8


def test_office__rooms_rarely_connect_to_each_other(samples):
    room_doors = doors = 0
    for b in samples("office"):
        for d in b.doors:
            if d.room_b is None:
                continue
            doors += 1
            room_doors += {b.room(d.room_a).label, b.room(d.room_b).label} <= set(ROOM_LABELS)
    assert room_doors / doors <= 0.1
