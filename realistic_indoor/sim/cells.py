"""The values of a world raster's cells: one definition, for the raster and the kernels that fill it."""

from __future__ import annotations

__all__ = ["RASTER_FREE", "RASTER_OUTSIDE", "RASTER_WALL"]

RASTER_FREE, RASTER_WALL, RASTER_OUTSIDE = 0, 1, 2
"""Cell values (uint8): floor inside a room or doorway, wall, outside the building."""
