"""ROS ``map_server`` maps: an occupancy image (binary PGM) and its YAML description.

The pair loads unchanged in ROS 1 ``map_server`` and ROS 2 ``nav2_map_server`` (``mode: trinary``):
walls are black (0, occupied), floor inside rooms and doorways white (254, free), everything
outside the building grey (205, unknown). Row 0 of the image is the top of the plan (highest
``y``) and ``origin`` is the pose of the lower-left pixel's lower-left corner, so the world point
``(x, y)`` lies in image column ``floor((x - origin_x) / resolution)`` and row
``height - 1 - floor((y - origin_y) / resolution)``, as ``map_server`` reads it.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from realistic_indoor.checks import require_between
from realistic_indoor.files import write_bytes, write_text
from realistic_indoor.sim.raster import (
    DEFAULT_MARGIN_M,
    DEFAULT_RESOLUTION_M,
    DEFAULT_WALL_THICKNESS_M,
    RASTER_FREE,
    RASTER_OUTSIDE,
    RASTER_WALL,
    OccupancyRaster,
    rasterize,
)

if TYPE_CHECKING:
    from realistic_indoor.building.building import Building

__all__ = ["FREE_PIXEL", "OCCUPIED_PIXEL", "UNKNOWN_PIXEL", "map_image", "map_yaml", "write"]

OCCUPIED_PIXEL, FREE_PIXEL, UNKNOWN_PIXEL = 0, 254, 205
"""Grey levels ROS's ``map_saver`` writes for occupied, free and unknown cells."""

OCCUPIED_THRESH = 0.65
FREE_THRESH = 0.196


def map_image(raster: OccupancyRaster) -> np.ndarray:
    """The raster as a ROS map image: ``(H, W)`` uint8 grey levels, row 0 at the top (highest y)."""
    lut = np.full(256, UNKNOWN_PIXEL, dtype=np.uint8)
    lut[RASTER_FREE], lut[RASTER_WALL], lut[RASTER_OUTSIDE] = FREE_PIXEL, OCCUPIED_PIXEL, UNKNOWN_PIXEL
    return lut[raster.grid[::-1]]


def map_yaml(raster: OccupancyRaster, image_name: str, comment: str = "") -> str:
    """The ``map_server`` YAML text describing ``image_name`` (a path relative to the YAML file).

    Args:
        raster: The raster the image was made from (its resolution and origin).
        image_name: The image file, as written in the ``image`` field.
        comment: A line written as a YAML comment at the top (e.g. where the map came from).
    """
    x0, y0 = (round(v, 9) + 0.0 for v in raster.origin)
    lines = [f"# {comment}"] if comment else []
    lines += [
        f"image: {image_name}",
        "mode: trinary",
        f"resolution: {raster.resolution_m!r}",
        f"origin: [{x0!r}, {y0!r}, 0.0]",
        "negate: 0",
        f"occupied_thresh: {OCCUPIED_THRESH}",
        f"free_thresh: {FREE_THRESH}",
    ]
    return "\n".join(lines) + "\n"


def write(
    building: Building,
    path: str | Path,
    *,
    resolution_m: float = DEFAULT_RESOLUTION_M,
    wall_thickness_m: float = DEFAULT_WALL_THICKNESS_M,
    margin_m: float = DEFAULT_MARGIN_M,
) -> list[Path]:
    """Write ``<stem>.pgm`` and ``<stem>.yaml`` beside each other, whichever of the two ``path`` names.

    Interior doorways are free (the map is navigable from room to room); walls are at least one
    pixel thick and 4-connected, so a planner cannot slip through a diagonal gap.

    Args:
        building: The building.
        path: ``plan.yaml`` or ``plan.pgm``; both files are written.
        resolution_m: Side of a pixel, metres (ROS's usual 0.05), in [0.01, 1].
        wall_thickness_m: Thickness of walls on the map, metres (never less than one pixel), in
            [0, 1].
        margin_m: Unknown border kept around the building, metres, in [0, 10].

    Returns:
        ``[image path, yaml path]``.

    Raises:
        ConfigError: If a size is out of range (one line naming it and its range) or the
            building has no room.
    """
    require_between("ros_map", "resolution_m", resolution_m, 0.01, 1.0, "m")
    require_between("ros_map", "wall_thickness_m", wall_thickness_m, 0.0, 1.0, "m")
    require_between("ros_map", "margin_m", margin_m, 0.0, 10.0, "m")
    path = Path(path)
    raster = rasterize(
        building, resolution_m=resolution_m, wall_thickness_m=wall_thickness_m, margin_m=margin_m
    )
    image_path, yaml_path = path.with_name(path.stem + ".pgm"), path.with_name(path.stem + ".yaml")
    image = map_image(raster)
    header = f"P5\n{image.shape[1]} {image.shape[0]}\n255\n".encode("ascii")
    write_bytes(image_path, header + image.tobytes())
    source = str(building.metadata.get("source") or building.metadata.get("generator") or "a building")
    comment = f"ROS map_server map of {' '.join(source.split())}, written by realistic-indoor"
    write_text(yaml_path, map_yaml(raster, image_path.name, comment))
    return [image_path, yaml_path]
