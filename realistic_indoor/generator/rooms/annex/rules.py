"""How a layout's annexes stand beside its rooms, and what it draws again when one finds no place."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from realistic_indoor.building.labels import SemanticLabel
from realistic_indoor.generator.doors import exterior_walls
from realistic_indoor.generator.plan import H
from realistic_indoor.generator.rooms.annex.place import ANNEX_SCALES, add_annex

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.plan import Plan
    from realistic_indoor.generator.rooms.annex.draw import Annex
    from realistic_indoor.generator.rooms.style import TypeStyle

__all__ = ["AnnexRules", "fewer_annexes", "place_annexes"]


@dataclass(frozen=True)
class AnnexRules:
    """A layout's conventions for annexes; the defaults are the paper's (the wing layout's).

    Attributes:
        label: Semantic label of an annex: a hall (the paper's convention) or a big room (as
            the real school plans label their gyms).
        room_m: Range of the depth of the service rooms along the first annex's far side, and
            the length along it each takes (m).
        shrink_in_place: Where the first annex finds no place, try it smaller beside the same
            rooms (:data:`~realistic_indoor.generator.rooms.annex.place.ANNEX_SCALES`), then
            lay out again without annexes; else lay out again with it smaller, and without
            annexes once it is at its smallest.
        keep_lobby_clear: Keep annexes off the lobby's facade (the lobby is the first room
            when it is a hall), where the main entrance goes.
        count_service_rooms: Count the first annex's service rooms against the small rooms
            the model asks for (else they come on top).
        more: Further annexes of large buildings: ``(function, area range (m2), floor areas
            over which it comes in (m2))`` each (see
            :func:`~realistic_indoor.generator.rooms.annex.draw.more_annexes`).
        more_share: Largest share of the floor area one of ``more`` takes.
    """

    label: SemanticLabel = H
    room_m: tuple[tuple[float, float], float] = ((2.6, 3.4), 3.5)
    shrink_in_place: bool = True
    keep_lobby_clear: bool = False
    count_service_rooms: bool = False
    more: tuple[tuple[str, tuple[float, float], tuple[float, float]], ...] = ()
    more_share: float = 0.0


def place_annexes(
    plan: Plan, rng: np.random.Generator, style: TypeStyle, annexes: list[Annex], rules: AnnexRules
) -> int:
    """Stand ``annexes`` beside the plan's rooms in turn, service rooms along the first only.

    Returns:
        The index of the first annex that found no place (it and the later ones are not
        added), or -1 when all stand.
    """
    lobby = (
        exterior_walls(plan, 0) if rules.keep_lobby_clear and plan.rooms and plan.rooms[0].label is H else []
    )
    scales = ANNEX_SCALES if rules.shrink_in_place else (1.0,)
    for k, annex in enumerate(annexes):
        placed = add_annex(
            plan,
            rng,
            style,
            annex.area_m2,
            label=rules.label,
            keep_clear=lobby,
            room_m=rules.room_m,
            function=annex.function,
            service_rooms=k == 0,
            scales=scales,
        )
        if placed < 0:
            return k
    return -1


def fewer_annexes(annexes: list[Annex], failed: int, rules: AnnexRules) -> list[Annex]:
    """The annexes to lay the building out again with, after annex ``failed`` found no place.

    A further annex is left out; the first is tried smaller (unless the rules shrink it in
    place), and once it is at its smallest, every annex is left out.
    """
    if failed > 0:
        return annexes[:failed] + annexes[failed + 1 :]
    first = annexes[0]
    smaller = [s for s in ANNEX_SCALES if s < first.scale]
    if rules.shrink_in_place or not smaller:
        return []
    return [first._replace(scale=smaller[0]), *annexes[1:]]
