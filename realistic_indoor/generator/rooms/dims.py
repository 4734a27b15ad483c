"""Building-wide sizes of a layout: corridor width, depths of strips of rooms, hall area."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from realistic_indoor.generator.geometry import area_to_units, to_units
from realistic_indoor.generator.plan import C, H, M, S

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.rooms.style import TypeStyle
    from realistic_indoor.models.building_model import BuildingTypeModel

__all__ = ["Dims", "layout_dims"]


@dataclass(frozen=True)
class Dims:
    """Building-wide sizes (grid units).

    Attributes:
        corridor: Corridor width.
        depth: Depth of a strip of ordinary rooms.
        shallow: Depth of a strip of small rooms.
        hall_area: Mean hall area (square units).
    """

    corridor: int
    depth: int
    shallow: int
    hall_area: int


def _clamp(v: float, lo_hi: tuple[float, float]) -> float:
    return min(max(v, lo_hi[0]), lo_hi[1])


def layout_dims(rng: np.random.Generator, model: BuildingTypeModel, style: TypeStyle) -> Dims:
    """Corridor width and room depths from the model's corridors, medium and small rooms.

    A corridor of mean area ``a`` and axes ratio ``r`` is ``sqrt(a / r)`` wide; a strip of rooms
    is as deep as a square medium room, ``sqrt(a)`` (a strip of small rooms likewise); the
    style keeps both within the type's usual ranges.
    """
    c, m, s, h = (model.stats(lab) for lab in (C, M, S, H))
    corridor = _clamp(
        style.corridor_scale * math.sqrt(c.area_mean / max(c.axes_ratio_mean, 1.0)), style.corridor_width_m
    )
    depth = _clamp(style.depth_scale * math.sqrt(m.area_mean), style.room_depth_m)
    shallow = _clamp(math.sqrt(s.area_mean), style.shallow_depth_m)
    return Dims(
        corridor=to_units(corridor * rng.uniform(0.9, 1.1)),
        depth=to_units(depth * rng.uniform(0.92, 1.08)),
        shallow=to_units(shallow),
        hall_area=round(area_to_units(h.area_mean)),
    )
