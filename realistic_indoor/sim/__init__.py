"""The simulator: occupancy raster, laser scanner, robot physics, mapping and victims."""

from realistic_indoor.sim.raster import FREE, OUTSIDE, WALL, OccupancyRaster, rasterize

__all__ = ["FREE", "OUTSIDE", "WALL", "OccupancyRaster", "rasterize"]
