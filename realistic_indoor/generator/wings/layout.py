"""The wing layout of offices and schools: skeleton, rooms, corridors, doors, functions."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from realistic_indoor.generator.geometry import area_to_units, to_metres, to_units
from realistic_indoor.generator.plan import H, Plan
from realistic_indoor.generator.rooms.annex import add_annex, draw_annex
from realistic_indoor.generator.rooms.connect_and_name import connect_and_name
from realistic_indoor.generator.rooms.dims import Dims, layout_dims
from realistic_indoor.generator.rooms.from_regions import rooms_from_regions
from realistic_indoor.generator.wings.paint import paint
from realistic_indoor.generator.wings.sizing import MIN_GAP_M, size_skeleton
from realistic_indoor.generator.wings.skeleton import Skeleton, sample_shape

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.wings.style import WingStyle
    from realistic_indoor.models.building_model import BuildingTypeModel

__all__ = ["wing_plan"]


def _skeleton(
    rng: np.random.Generator, area_m2: float, dims: Dims, model: BuildingTypeModel, style: WingStyle
) -> Skeleton:
    """A sized skeleton whose wings are of a plausible length and whose footprint is not too long.

    Draws up to a dozen shapes and keeps the first that fits, else the one that came closest.
    The longest side may be 2.6 times the side of a square of the same area (at least the
    style's ``max_extent_m``).
    """
    n_rooms = area_m2 / model.mean_room_area()
    across = to_metres(1.3 * dims.depth + dims.corridor)
    lo, hi = style.wing_length_m
    max_extent = to_units(max(style.max_extent_m, 2.6 * math.sqrt(area_m2)))
    best, best_cost = None, math.inf
    for _ in range(12):
        n_edges = max(1, round(area_m2 / across / rng.uniform(lo, hi)))
        sk = sample_shape(rng, n_edges, style.shapes)
        n_halls = int(model.shares()[H] * n_rooms + rng.random())
        gap = size_skeleton(
            sk, rng, dims, style, area_to_units(area_m2), (n_halls, model.structures.junction_halls)
        )
        extent = max(sum(map(sum, sk.cols)) + sum(sk.col_gaps), sum(map(sum, sk.rows)) + sum(sk.row_gaps))
        cost = max(0.0, 0.4 * lo - gap) + max(0.0, gap - 1.8 * hi) + max(0, extent - max_extent) / 2
        cost += 1000.0 if gap <= MIN_GAP_M else 0.0
        if cost < best_cost:
            best, best_cost = sk, cost
        if cost == 0:
            break
    return best


def wing_plan(
    rng: np.random.Generator, area_m2: float, model: BuildingTypeModel, style: WingStyle
) -> tuple[Plan, dict[str, str]]:
    """Lay out a wing building of about ``area_m2``.

    An annex (a school's gym) takes up to a quarter of the area (small buildings may have none,
    see ``draw_annex``); where it finds no free place beside the wings, the wings are laid out
    again over the whole area.

    Returns:
        The plan (rooms, doors, functions) and facts about the layout for the metadata
        (``shape``).
    """
    annex_m2, style = draw_annex(rng, area_m2, style)
    laid = _lay_out(rng, area_m2, model, style, annex_m2)
    if laid is None:
        laid = _lay_out(rng, area_m2, model, style, 0.0)
    plan, sk = laid
    connect_and_name(plan, rng, model, style)
    return plan, {"shape": sk.shape}


def _lay_out(
    rng: np.random.Generator, area_m2: float, model: BuildingTypeModel, style: WingStyle, annex_m2: float
) -> tuple[Plan, Skeleton] | None:
    """Rooms and corridors of the wings and the annex (``None`` if the annex found no place)."""
    dims = layout_dims(rng, model, style)
    sk = _skeleton(rng, area_m2 - annex_m2, dims, model, style)
    plan = rooms_from_regions(paint(sk), rng, model, style, dims)
    if annex_m2 and add_annex(plan, rng, style, annex_m2) < 0:
        return None
    return plan, sk
