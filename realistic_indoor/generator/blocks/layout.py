"""The block layout of offices and schools: a footprint painted as compact blocks of bars.

Compact deep plans with double-loaded and ring corridors, and L, T, U and E shapes of bars.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

from realistic_indoor.generator.blocks.compose import compose
from realistic_indoor.generator.blocks.paint import length_for_area, paint_block
from realistic_indoor.generator.blocks.section import Section, draw_section, mean_block_depth
from realistic_indoor.generator.geometry import area_to_units, to_units
from realistic_indoor.generator.plan import B, H
from realistic_indoor.generator.rooms.annex import AnnexRules
from realistic_indoor.generator.rooms.connect_and_name import DoorRules
from realistic_indoor.generator.rooms.from_regions import RoomRules
from realistic_indoor.generator.rooms.region_layout import Painted, RegionLayout
from realistic_indoor.generator.sampling import choice_index

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.blocks.style import BlockStyle
    from realistic_indoor.generator.rooms.dims import Dims
    from realistic_indoor.generator.rooms.regions import FloorRegions
    from realistic_indoor.generator.rooms.style import TypeStyle
    from realistic_indoor.models.building_model import BuildingTypeModel

__all__ = ["BlockPainter", "block_layout"]


def block_layout(model: BuildingTypeModel, style: TypeStyle, blocks: BlockStyle) -> RegionLayout:
    """The block layout of a building type, for the layout template.

    An annex (a school's gym, a big room as the real school plans label it) takes up to a
    quarter of the area (small buildings may have none, see
    :func:`~realistic_indoor.generator.rooms.annex.draw_annex`), large buildings may get the
    style's ``more_annexes`` beside it (an auditorium, a canteen); each time one finds no place
    beside a newly drawn block, the next draw leaves out that one (a further annex) or makes
    the gym smaller, and the block takes the whole area once the gym has shrunk twice in vain.
    Rooms are suites and doors follow the building's drawn door habit.

    Args:
        model: The building-type model, set to the building's size.
        style: The type's conventions.
        blocks: The type's conventions for blocks.
    """
    if blocks.annex_area_m2 is not None:
        style = replace(style, annex_area_m2=blocks.annex_area_m2)
    rooms = RoomRules(
        corridor_cuts=blocks.corridor_cuts, max_axes_ratio=blocks.max_axes_ratio, widen_last_room=True
    )
    annexes = AnnexRules(
        label=B,
        room_m=blocks.annex_room_m,
        shrink_in_place=False,
        keep_lobby_clear=True,
        count_service_rooms=True,
        more=blocks.more_annexes,
        more_share=blocks.more_annex_share,
    )
    doors = DoorRules(
        core_on_facade=True, doors_per_room=blocks.doors_per_room, habits=True, suites=blocks.suites
    )
    return RegionLayout(model, style, BlockPainter(blocks), rooms, annexes, doors)


@dataclass(frozen=True)
class BlockPainter:
    """Paints a footprint as one block of bars or a main bar with wings (a :class:`~realistic_indoor.generator.rooms.region_layout.Painter`).

    Attributes:
        blocks: The type's conventions for blocks.
    """

    blocks: BlockStyle

    def __call__(
        self, rng: np.random.Generator, area_m2: float, model: BuildingTypeModel, dims: Dims
    ) -> Painted:
        """The regions of a footprint of about ``area_m2`` (m2) and its shape name.

        The shape: ``"double-loaded"``, ``"ring"`` or ``"ring-k"`` for ``k`` cores across, with
        ``"+court"`` when a core section is a courtyard, for one block; ``"L"``, ``"T"``,
        ``"U"`` or ``"E"`` for a main bar with wings. Corridors are the style's
        ``corridor_scale`` times as wide as ``dims`` says.
        """
        blocks = self.blocks
        dims = replace(dims, corridor=round(dims.corridor * blocks.corridor_scale))
        area = round(area_to_units(area_m2))
        n_halls = int(rng.poisson(model.shares()[H] * area_m2 / model.mean_room_area()))
        hall_area = area_to_units(model.stats(H).area_mean)
        shape = _draw_composition(rng, blocks, model.footprint.composed_share)
        regions = compose(rng, shape, area, dims, blocks, n_halls, hall_area) if shape != "I" else None
        bars = None
        if regions is None and blocks.ring_share and _no_ring(rng, model):
            if _one_bar_fits(area, dims, blocks):
                bars = 1
            else:
                regions, shape = _comb(rng, area, dims, blocks, n_halls, hall_area), "E"
        if regions is None:
            aspect = model.footprint.draw_aspect(rng) if model.footprint.aspect_median else None
            section, length = draw_section(
                rng, area, dims, blocks, n_halls, hall_area, bars=bars, aspect=aspect
            )
            regions, shape = (
                paint_block(section, length_for_area(section, length, area)),
                _shape_name(section),
            )
        return Painted(regions, dims, shape)


def _draw_composition(rng: np.random.Generator, blocks: BlockStyle, composed_share: float) -> str:
    """The footprint's composition: ``"I"`` (one block) or one of the style's L, T, U.

    With a model's share of composed footprints (``composed_share`` >= 0), one block comes
    with probability ``1 - composed_share`` and the style's weights choose among the others;
    otherwise the style's weights choose among all.
    """
    names = sorted(blocks.compositions)
    if composed_share >= 0:
        others = [n for n in names if n != "I"]
        if not others or rng.random() >= composed_share:
            return "I"
        names = others
    weights = [blocks.compositions[n] for n in names]
    return names[choice_index(rng, [w / sum(weights) for w in weights])]


def _shape_name(s: Section) -> str:
    name = "double-loaded" if s.bars == 1 else "ring" if s.bars == 2 else f"ring-{s.bars - 1}"
    return name + ("+court" if s.courts else "")


MAX_COMB_WINGS = 6
"""Most wings of a comb (an E) tried for a large building without a ring."""


def _no_ring(rng: np.random.Generator, model: BuildingTypeModel) -> bool:
    """Whether a building that is not an L, T or U is to have no ring corridor.

    Drawn with probability ``1 - ring_share`` (the model's share of buildings whose corridors
    close a loop); nothing is drawn for a model that leaves rings to the block's proportions.
    """
    ring_share = model.structures.ring_share
    return ring_share < 1.0 and rng.random() >= ring_share


def _one_bar_fits(area: int, dims: Dims, blocks: BlockStyle) -> bool:
    """Whether one double-loaded bar of the area is at most the style's ``max_bar_m`` long."""
    return area / mean_block_depth(dims, blocks, 1) <= to_units(blocks.max_bar_m)


def _comb(
    rng: np.random.Generator, area: int, dims: Dims, blocks: BlockStyle, n_halls: int, hall_area: float
) -> FloorRegions | None:
    """A main bar with 3 or more evenly spaced wings (an E), the fewest whose bars fit; or ``None``."""
    for wings in range(3, MAX_COMB_WINGS + 1):
        regions = compose(rng, "E", area, dims, blocks, n_halls, hall_area, wings=wings)
        if regions is not None:
            return regions
    return None
