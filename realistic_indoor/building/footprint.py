"""A building's footprint and its outline measures: the shape a user sees first on a plan.

The footprint is the union of the room outlines with wall gaps closed and shafts filled; its
fill (floor over convex hull), compactness and aspect ratio say whether a building is a compact
block, a bar, or wings around courts. The generator's models are fitted to these measures of
real plans and the validator compares them, so they live below both.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from shapely.geometry.base import BaseGeometry

    from realistic_indoor.building.building import Building

__all__ = ["CLOSING_M", "SHAFT_MAX_M2", "aspect_ratio", "footprint", "footprint_fill"]

CLOSING_M = 0.25
"""Gaps between room outlines up to twice this (m) are closed in the footprint (walls, slop)."""

SHAFT_MAX_M2 = 25.0
"""Holes of the footprint up to this area (m2) are filled: shafts and unlabelled spaces, not courts."""


def footprint(building: Building) -> BaseGeometry:
    """The building's footprint: the union of its room outlines.

    Gaps between outlines narrower than ``2 * CLOSING_M`` are closed (real plans draw rooms up to
    the faces of walls), and holes up to :data:`SHAFT_MAX_M2` are filled; larger holes are
    courtyards and stay.

    Raises:
        ValueError: If the building has no room.
    """
    from shapely import Polygon, unary_union

    if not building.rooms:
        raise ValueError("a building without rooms has no footprint")
    union = unary_union([r.polygon for r in building.rooms])
    closed = union.buffer(CLOSING_M, join_style="mitre").buffer(-CLOSING_M, join_style="mitre")
    if closed.is_empty:
        closed = union
    parts = [
        Polygon(p.exterior, [h for h in p.interiors if Polygon(h).area > SHAFT_MAX_M2])
        for p in getattr(closed, "geoms", [closed])
    ]
    return unary_union(parts)


def footprint_fill(building: Building, shape: BaseGeometry | None = None) -> float:
    """Floor area over the area of the footprint's convex hull, in ``(0, 1]`` (1 for a convex block).

    Args:
        building: The building (at least one room).
        shape: Its :func:`footprint`, where already computed.
    """
    shape = footprint(building) if shape is None else shape
    return sum(r.area for r in building.rooms) / shape.convex_hull.area


def aspect_ratio(shape: BaseGeometry) -> float:
    """Long over short side of the smallest rectangle (any orientation) around ``shape``, >= 1."""
    rect = np.asarray(shape.minimum_rotated_rectangle.exterior.coords)
    sides = np.hypot(*np.diff(rect[:3], axis=0).T)
    return float(sides.max() / sides.min()) if sides.min() > 0 else math.inf
