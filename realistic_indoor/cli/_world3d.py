"""The 3D world options of ``convert`` and ``generate``: wall height and thickness, doors."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from realistic_indoor.errors import ConfigError

__all__ = ["WORLD_FORMATS", "add_world_options", "save_options", "world_options"]

WORLD_FORMATS = ("sdf", "mjcf", "glb", "obj")
"""Format names (of :data:`realistic_indoor.io.registry.FORMATS`) that are 3D worlds."""

_FLAGS = {
    "wall_height": ("--wall-height", "wall_height_m"),
    "wall_thickness": ("--wall-thickness", "wall_thickness_m"),
    "door_height": ("--door-height", "door_height_m"),
}


def add_world_options(parser: argparse.ArgumentParser) -> None:
    """Add ``--wall-height``, ``--wall-thickness``, ``--door-height`` and ``--closed-entrances``."""
    from realistic_indoor.io.world3d.scene import (
        DEFAULT_DOOR_HEIGHT_M,
        DEFAULT_WALL_HEIGHT_M,
        DEFAULT_WALL_THICKNESS_M,
    )

    group = parser.add_argument_group("3D worlds (.sdf, .world, .mjcf.xml, .glb, .obj)")
    group.add_argument(
        "--wall-height",
        type=float,
        metavar="M",
        help=f"wall height, metres (default {DEFAULT_WALL_HEIGHT_M:g})",
    )
    group.add_argument(
        "--wall-thickness",
        type=float,
        metavar="M",
        help=f"wall thickness, metres, centred on the plan's walls; ROS maps too (default {DEFAULT_WALL_THICKNESS_M:g})",
    )
    group.add_argument(
        "--door-height",
        type=float,
        metavar="M",
        help=f"doorway height, metres; a lintel fills the wall above (default {DEFAULT_DOOR_HEIGHT_M:g}, "
        "or the wall height if lower)",
    )
    group.add_argument(
        "--closed-entrances",
        action="store_true",
        help="close the exterior doors with a door box (default: open, as in the plan and the simulator)",
    )


def world_options(args: argparse.Namespace):
    """The :class:`~realistic_indoor.io.world3d.scene.WorldOptions` the flags give (checked now).

    Raises:
        ConfigError: If a value is out of range (named by its flag).
    """
    from realistic_indoor.io.world3d.scene import WorldOptions

    fields: dict[str, Any] = {
        f: getattr(args, a) for a, (_flag, f) in _FLAGS.items() if getattr(args, a) is not None
    }
    if args.closed_entrances:
        fields["exterior_doors_open"] = False
    try:
        return WorldOptions(**fields)
    except ConfigError as e:
        message = str(e)
        for flag, field in _FLAGS.values():
            message = message.replace(f"WorldOptions.{field}", flag).replace(field, flag)
        raise ConfigError(message) from None


def _given(args: argparse.Namespace) -> list[str]:
    """The 3D flags given on the command line."""
    given = [flag for a, (flag, _f) in _FLAGS.items() if getattr(args, a) is not None]
    return given + (["--closed-entrances"] if args.closed_entrances else [])


def save_options(
    args: argparse.Namespace, path: str | Path, resolution_m: float | None = None
) -> dict[str, Any]:
    """The keyword options ``save`` gets for ``path``: 3D world options, or a ROS map's resolution.

    Args:
        args: Parsed flags of :func:`add_world_options`.
        path: The output file; its ending picks the format.
        resolution_m: A ROS map's resolution (m per pixel), if the command has the option.

    Raises:
        ConfigError: If 3D flags are given for a format that is not a 3D world (a ROS map takes
            ``--wall-thickness``).
    """
    from realistic_indoor.io import format_of

    fmt = format_of(path)
    if fmt in WORLD_FORMATS:
        return {"options": world_options(args)}
    options: dict[str, Any] = {}
    given = _given(args)
    if fmt == "ros":
        if resolution_m is not None:
            options["resolution_m"] = resolution_m
        if args.wall_thickness is not None:
            options["wall_thickness_m"] = world_options(args).wall_thickness_m
        given = [g for g in given if g != "--wall-thickness"]
    if given:
        raise ConfigError(
            f"{given[0]} applies to 3D worlds (.sdf, .world, .mjcf.xml, .glb, .obj), not to {path}"
        )
    return options
