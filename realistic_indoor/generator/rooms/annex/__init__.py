"""Annexes: large rooms beside the building (a school's gym, an auditorium, a canteen).

- :mod:`~realistic_indoor.generator.rooms.annex.draw`: which annexes a building gets;
- :mod:`~realistic_indoor.generator.rooms.annex.place`: where one stands, with its service rooms;
- :mod:`~realistic_indoor.generator.rooms.annex.rules`: a layout's conventions for them, and
  what it draws again when one finds no place.
"""

from realistic_indoor.generator.rooms.annex.draw import (
    Annex,
    comes_in,
    draw_annex,
    draw_annexes,
    more_annexes,
)
from realistic_indoor.generator.rooms.annex.place import (
    ANNEX_RATIO,
    ANNEX_SCALES,
    add_annex,
    expected_service_rooms,
)
from realistic_indoor.generator.rooms.annex.rules import AnnexRules, fewer_annexes, place_annexes

__all__ = [
    "ANNEX_RATIO",
    "ANNEX_SCALES",
    "Annex",
    "AnnexRules",
    "add_annex",
    "comes_in",
    "draw_annex",
    "draw_annexes",
    "expected_service_rooms",
    "fewer_annexes",
    "more_annexes",
    "place_annexes",
]
