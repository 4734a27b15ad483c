"""The simulator: occupancy raster, laser scanner, robot physics, mapping and victims.

Typical use, one building::

    world = World(building)                      # raster, raycaster, start pose, reachable floor
    robot = robot_in_world(world)                # compiled disc at the start pose
    lidar, robot_map = Lidar(), RobotMap(world)
    motion = robot.step(0.5, 0.2)                # one control step: (v m/s, w rad/s)
    scan = lidar.scan(world.raycaster, robot.pose, rng)
    new_area_m2 = robot_map.update(scan)
    image = robot_map.local_view(robot.pose)     # egocentric uint8 map, heading up

See ``docs/simulator.md``.

Names are imported on first use, so ``from realistic_indoor.sim.raster import rasterize``
(e.g. for a map export) does not load pymunk, nor numba until it rasterizes.
"""

from __future__ import annotations

import importlib
from typing import Any

_WHERE = {
    "disc_physics": ("DiscRobot", "robot_in_world"),
    "fields": ("distance_field",),
    "lidar": ("Lidar", "LidarConfig", "Scan", "beam_offsets"),
    "mapping": (
        "MAPPED_FREE",
        "MAPPED_OCCUPIED",
        "PIXEL_FREE",
        "PIXEL_OCCUPIED",
        "PIXEL_UNKNOWN",
        "MAPPED_UNKNOWN",
        "FreeSpaceMarker",
        "LocalMapConfig",
        "RobotMap",
    ),
    "raster": ("RASTER_FREE", "RASTER_OUTSIDE", "RASTER_WALL", "OccupancyRaster", "rasterize"),
    "raycast": ("RayHits", "Raycaster"),
    "robot": ("Motion", "Robot", "RobotConfig"),
    "victims": ("VictimConfig", "VictimSensor", "Victims", "place_victims", "relative_polar"),
    "world": ("World", "WorldConfig"),
}
_MODULE_OF = {name: module for module, names in _WHERE.items() for name in names}

__all__ = [
    "MAPPED_FREE",
    "MAPPED_OCCUPIED",
    "MAPPED_UNKNOWN",
    "PIXEL_FREE",
    "PIXEL_OCCUPIED",
    "PIXEL_UNKNOWN",
    "RASTER_FREE",
    "RASTER_OUTSIDE",
    "RASTER_WALL",
    "DiscRobot",
    "FreeSpaceMarker",
    "Lidar",
    "LidarConfig",
    "LocalMapConfig",
    "Motion",
    "OccupancyRaster",
    "RayHits",
    "Raycaster",
    "Robot",
    "RobotConfig",
    "RobotMap",
    "Scan",
    "VictimConfig",
    "VictimSensor",
    "Victims",
    "World",
    "WorldConfig",
    "beam_offsets",
    "distance_field",
    "place_victims",
    "rasterize",
    "relative_polar",
    "robot_in_world",
]


def __getattr__(name: str) -> Any:
    module = _MODULE_OF.get(name)
    if module is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(f"{__name__}.{module}"), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(__all__)
