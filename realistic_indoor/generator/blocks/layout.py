"""The block layout of offices and schools: compact deep plans, double-loaded and ring corridors."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from realistic_indoor.generator.blocks.compose import compose
from realistic_indoor.generator.blocks.paint import length_for_area, paint_block
from realistic_indoor.generator.blocks.section import Section, draw_section, mean_block_depth
from realistic_indoor.generator.connect import door_habit_scale
from realistic_indoor.generator.doors import exterior_walls
from realistic_indoor.generator.geometry import area_to_units, to_units
from realistic_indoor.generator.plan import B, H, Plan
from realistic_indoor.generator.rooms.annex import (
    ANNEX_SCALES,
    add_annex,
    comes_in,
    draw_annex,
    expected_service_rooms,
)
from realistic_indoor.generator.rooms.connect_and_name import connect_and_name
from realistic_indoor.generator.rooms.dims import layout_dims
from realistic_indoor.generator.rooms.from_regions import rooms_from_regions
from realistic_indoor.generator.rooms.suites import make_suites
from realistic_indoor.generator.sampling import choice_index

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.blocks.style import BlockStyle
    from realistic_indoor.generator.rooms.dims import Dims
    from realistic_indoor.generator.rooms.regions import FloorRegions
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

    An annex (a school's gym, a big room as the real school plans label it) takes up to a quarter
    of the area (small buildings may have none, see ``draw_annex``), and large buildings may
    get the style's ``more_annexes`` beside it (an auditorium, a canteen): see
    :func:`_lay_out_with_annexes`.

    Returns:
        The plan (rooms, doors, functions) and facts about the layout for the metadata
        (``shape``: ``"double-loaded"``, ``"ring"`` or ``"ring-k"`` for ``k`` cores across,
        with ``"+court"`` when a core section is a courtyard, for one block; ``"L"``, ``"T"`` or
        ``"U"`` for a main bar with wings).
    """
    if blocks.annex_area_m2 is not None:
        style = replace(style, annex_area_m2=blocks.annex_area_m2)
    annex_m2, style = draw_annex(rng, area_m2, style)
    annexes = [(style.annex, annex_m2), *_more_annexes(rng, area_m2, blocks)] if annex_m2 else []
    plan, shape = _lay_out_with_annexes(rng, area_m2, model, style, blocks, annexes)
    pairs = model.structures.connected_room_pairs
    scale = door_habit_scale(model, rng)
    if blocks.suites:
        make_suites(plan, rng, min(pairs / 2 * scale, 1.0))
    connect_and_name(
        plan,
        rng,
        model,
        style,
        core_on_facade=True,
        doors_per_room=blocks.doors_per_room,
        pairs=0.0 if blocks.suites else min(pairs * scale, 1.0),
        door_scale=scale,
    )
    return plan, {"shape": shape}


def _lay_out_with_annexes(
    rng: np.random.Generator,
    area_m2: float,
    model: BuildingTypeModel,
    style: WingStyle,
    blocks: BlockStyle,
    annexes: list[tuple[str, float]],
) -> tuple[Plan, str]:
    """The block and as many of ``annexes`` (``(function, area m2)``, the style's annex first) as find a place.

    The block is drawn for the floor area less the annexes', so the building keeps its floor
    area whatever is left out. Each time an annex finds no free place beside a newly drawn
    block, the next draw leaves out that one (a further annex) or makes the style's annex
    smaller (:data:`~realistic_indoor.generator.rooms.annex.ANNEX_SCALES`); once that has shrunk twice in vain, the block takes the whole
    area.

    Returns:
        The plan and the footprint's shape name.
    """
    gym_m2 = annexes[0][1] if annexes else 0.0
    scales = list(ANNEX_SCALES[1:])
    while True:  # ends: a draw without annexes always succeeds
        laid = _lay_out(rng, area_m2, model, style, blocks, annexes)
        if not isinstance(laid, int):
            return laid
        if laid > 0:
            annexes = annexes[:laid] + annexes[laid + 1 :]
        elif scales:
            annexes = [(annexes[0][0], gym_m2 * scales.pop(0)), *annexes[1:]]
        else:
            annexes = []


def _more_annexes(rng: np.random.Generator, area_m2: float, blocks: BlockStyle) -> list[tuple[str, float]]:
    """The style's further annexes a building gets, in the style's order.

    Nothing is drawn for an annex below its first floor area (smaller buildings keep their
    draws).

    Args:
        rng: The building's random generator.
        area_m2: The building's floor area (m2).
        blocks: The layout style (``more_annexes``, ``more_annex_share``).

    Returns:
        ``(function, area m2)`` of each annex that comes in.
    """
    out = []
    for function, area_range, from_m2 in blocks.more_annexes:
        if area_m2 <= from_m2[0]:
            continue
        area = min(rng.uniform(*area_range), blocks.more_annex_share * area_m2)
        if comes_in(rng, area_m2, from_m2):
            out.append((function, area))
    return out


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


def _lay_out(
    rng: np.random.Generator,
    area_m2: float,
    model: BuildingTypeModel,
    style: WingStyle,
    blocks: BlockStyle,
    annexes: list[tuple[str, float]],
) -> tuple[Plan, str] | int:
    """Rooms and corridors of the blocks and the annexes, and the footprint's shape name.

    ``annexes`` are ``(function, area m2)``, the style's annex first (with its service rooms).
    Returns the index in ``annexes`` of the first that found no place instead.
    """
    annex_m2 = sum(area for _, area in annexes)
    dims = layout_dims(rng, model, style)
    dims = replace(dims, corridor=round(dims.corridor * blocks.corridor_scale))
    area = round(area_to_units(area_m2 - annex_m2))
    n_halls = int(rng.poisson(model.shares()[H] * (area_m2 - annex_m2) / model.mean_room_area()))
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
        section, length = draw_section(rng, area, dims, blocks, n_halls, hall_area, bars=bars, aspect=aspect)
        regions, shape = paint_block(section, length_for_area(section, length, area)), _shape_name(section)
    plan = rooms_from_regions(
        regions,
        rng,
        model,
        style,
        dims,
        hall_rooms=False,
        corridor_cuts=blocks.corridor_cuts,
        max_axes_ratio=blocks.max_axes_ratio,
        widen_last_room=True,
        placed_small=expected_service_rooms(annexes[0][1], blocks.annex_room_m) if annexes else 0.0,
    )
    lobby = exterior_walls(plan, 0) if plan.rooms and plan.rooms[0].label is H else []
    for k, (function, area) in enumerate(annexes):
        placed = add_annex(
            plan,
            rng,
            style,
            area,
            label=B,
            keep_clear=lobby,
            room_m=blocks.annex_room_m,
            function=function,
            service_rooms=k == 0,
            scales=(1.0,),
        )
        if placed < 0:
            return k
    return plan, shape
