"""The wing layout of offices and schools: a footprint painted as wings along a corridor skeleton."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from realistic_indoor.generator.geometry import area_to_units, to_metres, to_units
from realistic_indoor.generator.plan import H
from realistic_indoor.generator.rooms.annex import AnnexRules
from realistic_indoor.generator.rooms.connect_and_name import DoorRules
from realistic_indoor.generator.rooms.from_regions import RoomRules
from realistic_indoor.generator.rooms.region_layout import Painted, RegionLayout
from realistic_indoor.generator.wings.paint import paint
from realistic_indoor.generator.wings.sizing import MIN_GAP_M, size_skeleton
from realistic_indoor.generator.wings.skeleton import Skeleton, sample_shape

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.rooms.dims import Dims
    from realistic_indoor.generator.rooms.style import TypeStyle
    from realistic_indoor.generator.wings.style import WingStyle
    from realistic_indoor.models.building_model import BuildingTypeModel

__all__ = ["SkeletonPainter", "wing_layout"]


def wing_layout(model: BuildingTypeModel, style: TypeStyle, wings: WingStyle) -> RegionLayout:
    """The wing layout of a building type, for the layout template.

    The paper's conventions for the rest: an annex (a school's gym) is a hall with cubicles
    along its far side, tried smaller where it finds no place, and laid out without where even
    that fails; rooms keep every door the model's door counts ask for.

    Args:
        model: The building-type model, set to the building's size.
        style: The type's conventions.
        wings: The type's conventions for wings.
    """
    rooms = RoomRules(corridor_cuts=wings.corridor_cuts, hall_rooms_p=wings.hall_rooms_p)
    return RegionLayout(model, style, SkeletonPainter(wings), rooms, AnnexRules(), DoorRules())


@dataclass(frozen=True)
class SkeletonPainter:
    """Paints a footprint as wings along a corridor skeleton (a :class:`~realistic_indoor.generator.rooms.region_layout.Painter`).

    Attributes:
        wings: The type's conventions for wings.
    """

    wings: WingStyle

    def __call__(
        self, rng: np.random.Generator, area_m2: float, model: BuildingTypeModel, dims: Dims
    ) -> Painted:
        """A sized skeleton of about ``area_m2`` (m2), painted; its shape family names the footprint."""
        sk = _skeleton(rng, area_m2, dims, model, self.wings)
        return Painted(paint(sk), dims, sk.shape)


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
