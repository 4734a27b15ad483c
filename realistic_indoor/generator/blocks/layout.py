"""The block layout of offices and schools: compact deep plans, double-loaded and ring corridors."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from realistic_indoor.generator.blocks.paint import paint_block
from realistic_indoor.generator.blocks.section import Section, draw_section
from realistic_indoor.generator.furnish import connect_and_name, layout_dims, rooms_from_regions
from realistic_indoor.generator.plan import H, Plan
from realistic_indoor.generator.wings.annex import add_annex

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.blocks.style import BlockStyle
    from realistic_indoor.generator.wings.style import WingStyle
    from realistic_indoor.models.building_model import BuildingTypeModel

__all__ = ["block_plan"]


def block_plan(
    rng: np.random.Generator,
    area_m2: float,
    model: BuildingTypeModel,
    style: WingStyle,
    blocks: BlockStyle,
) -> tuple[Plan, dict[str, str]]:
    """Lay out a compact building of about ``area_m2`` as one block of bars.

    An annex (a school's gym) takes up to a quarter of the area; where it finds no free place
    beside the block, the block is drawn again (three tries), then laid out over the whole area.

    Returns:
        The plan (rooms, doors, functions) and facts about the layout for the metadata
        (``shape``: ``"double-loaded"``, ``"ring"`` or ``"ring-k"`` for ``k`` cores across,
        with ``"+court"`` when a core section is a courtyard).
    """
    annex_m2 = min(rng.uniform(*style.annex_area_m2), 0.25 * area_m2) if style.annex else 0.0
    laid = None
    for _ in range(3 if annex_m2 else 0):
        laid = _lay_out(rng, area_m2, model, style, blocks, annex_m2)
        if laid is not None:
            break
    if laid is None:
        laid = _lay_out(rng, area_m2, model, style, blocks, 0.0)
    plan, section = laid
    connect_and_name(plan, rng, model, style, core_on_facade=True, doors_per_room=blocks.doors_per_room)
    return plan, {"shape": _shape_name(section)}


def _shape_name(s: Section) -> str:
    name = "double-loaded" if s.bars == 1 else "ring" if s.bars == 2 else f"ring-{s.bars - 1}"
    return name + ("+court" if s.courts else "")


def _lay_out(
    rng: np.random.Generator,
    area_m2: float,
    model: BuildingTypeModel,
    style: WingStyle,
    blocks: BlockStyle,
    annex_m2: float,
) -> tuple[Plan, Section] | None:
    """Rooms and corridors of the block and the annex (``None`` if the annex found no place)."""
    dims = layout_dims(rng, model, style)
    dims = replace(dims, corridor=round(dims.corridor * blocks.corridor_scale))
    area = round((area_m2 - annex_m2) * 100)
    n_halls = int(model.shares()[H] * (area_m2 - annex_m2) / model.mean_room_area() + rng.random())
    section, length = draw_section(rng, area, dims, blocks, n_halls, model.stats(H).area_mean * 100)
    regions = paint_block(section, _length_for(section, length, area))
    plan = rooms_from_regions(
        regions, rng, model, style, dims, hall_rooms=False, corridor_cuts=blocks.corridor_cuts
    )
    if annex_m2 and add_annex(plan, rng, style, annex_m2) < 0:
        return None
    return plan, section


def _length_for(section: Section, guess: int, area: int) -> int:
    """The block length whose painted floor area is nearest ``area`` (units).

    The area grows with the length (in steps, where a hall or a strip's piece appears), so the
    length is bracketed from the guess and then found by bisection.
    """

    def painted(length: int) -> int:
        return paint_block(section, length).area

    lo, hi = max(guess // 2, 2 * section.corridor), max(guess, 2 * section.corridor + 1)
    while painted(hi) < area:
        lo, hi = hi, hi * 2
    while lo > 2 * section.corridor and painted(lo) > area:
        lo = max(lo // 2, 2 * section.corridor)
    while hi - lo > 1:
        mid = (lo + hi) // 2
        lo, hi = (mid, hi) if painted(mid) < area else (lo, mid)
    return min((lo, hi), key=lambda n: abs(painted(n) - area))
