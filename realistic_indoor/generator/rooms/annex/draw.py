"""Which annexes a building gets: large rooms beside it (a school's gym, auditorium, canteen)."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING, NamedTuple

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.rooms.annex.rules import AnnexRules
    from realistic_indoor.generator.rooms.style import TypeStyle

__all__ = ["Annex", "comes_in", "draw_annex", "draw_annexes", "more_annexes"]


class Annex(NamedTuple):
    """A large room to stand beside the building.

    Attributes:
        function: Its function (``"gym"``, ``"conference"``, ``"canteen"``).
        drawn_m2: The area drawn for it (m2).
        scale: The share of that area it is tried at (see
            :data:`~realistic_indoor.generator.rooms.annex.place.ANNEX_SCALES`).
    """

    function: str
    drawn_m2: float
    scale: float = 1.0

    @property
    def area_m2(self) -> float:
        """The area it is tried at (m2)."""
        return self.drawn_m2 * self.scale


def draw_annexes(
    rng: np.random.Generator, area_m2: float, style: TypeStyle, rules: AnnexRules
) -> tuple[TypeStyle, list[Annex]]:
    """The annexes of a building of ``area_m2`` (m2), the style's first, and the style to lay it out with.

    The style's annex (see :func:`draw_annex`) and, where it comes in, the rules' further
    annexes (see :func:`more_annexes`).
    """
    annex_m2, style = draw_annex(rng, area_m2, style)
    if not annex_m2:
        return style, []
    return style, [Annex(style.annex, annex_m2), *more_annexes(rng, area_m2, rules.more, rules.more_share)]


def draw_annex(rng: np.random.Generator, area_m2: float, style: TypeStyle) -> tuple[float, TypeStyle]:
    """The annex's area for a building of ``area_m2`` (m2) and the style to lay it out with.

    The annex takes the style's range of area, at most a quarter of the building's. A building
    smaller than the style's ``annex_from_m2`` may have none (certainly none below its first
    value): its area is then 0, and the style returned no longer requires the annex's function
    of another room (a small school has no gym, where a larger one whose annex found no place
    gives the name to a hall).
    """
    if not style.annex:
        return 0.0, style
    area = min(rng.uniform(*style.annex_area_m2), 0.25 * area_m2)
    if comes_in(rng, area_m2, style.annex_from_m2):
        return area, style
    required = tuple(f for f in style.required_functions if f != style.annex)
    return 0.0, replace(style, required_functions=required)


def comes_in(rng: np.random.Generator, area_m2: float, from_m2: tuple[float, float]) -> bool:
    """Whether a building gets something that comes in over a range of floor areas.

    Args:
        rng: The building's random generator; one number is drawn below ``from_m2[1]`` only.
        area_m2: The building's floor area (m2).
        from_m2: Floor areas (m2): none at the first, certainly from the second, and in
            between with a probability growing linearly.

    Returns:
        Whether it comes in.
    """
    low, high = from_m2
    return area_m2 >= high or rng.random() < (area_m2 - low) / (high - low)


def more_annexes(
    rng: np.random.Generator,
    area_m2: float,
    more: tuple[tuple[str, tuple[float, float], tuple[float, float]], ...],
    share: float,
) -> list[Annex]:
    """The further annexes a building gets, in the order given.

    Nothing is drawn for an annex below its first floor area (smaller buildings keep their
    draws).

    Args:
        rng: The building's random generator.
        area_m2: The building's floor area (m2).
        more: ``(function, area range (m2), floor areas over which it comes in (m2))`` of each
            annex (see :func:`comes_in`).
        share: Largest share of the floor area one of them takes.

    Returns:
        Each annex that comes in.
    """
    out = []
    for function, area_range, from_m2 in more:
        if area_m2 <= from_m2[0]:
            continue
        area = min(rng.uniform(*area_range), share * area_m2)
        if comes_in(rng, area_m2, from_m2):
            out.append(Annex(function, area))
    return out
