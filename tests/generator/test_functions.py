"""Functional labels of generated rooms: rooms everyone walks to come once per building."""

from __future__ import annotations

from collections import Counter

import pytest

ONCE = ("gym", "library", "cafeteria", "reception", "conference hall", "canteen")
"""Functions none of the 55 shared real plans holds twice (bar one school of 13 with two
canteens, counted with ``realistic_indoor.io.load`` over ../shared/data/real_floorplans)."""


@pytest.mark.parametrize("kind", ["office", "school"])
@pytest.mark.parametrize("model", [None, "paper"])
def test_functions__a_public_room_is_one_per_building(samples, kind, model):
    most = Counter()
    for b in samples(kind, model):
        counts = Counter(r.function for r in b.rooms)
        for f in ONCE:
            most[f] = max(most[f], counts[f])
    assert all(most[f] <= 1 for f in ONCE), dict(most)
    # the functions still occur: the rule limits them, it does not remove them
    assert sum(most.values()) >= 2, dict(most)


def test_functions__ordinary_functions_still_repeat(samples):
    # a school has many classrooms and an office many offices: only public rooms are capped
    assert max(Counter(r.function for r in b.rooms)["classroom"] for b in samples("school")) > 1
    assert max(Counter(r.function for r in b.rooms)["office"] for b in samples("office")) > 1
