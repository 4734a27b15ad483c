"""MuJoCo models (``.mjcf.xml``): the walls as box geoms of the worldbody on a floor plane.

Orientations are quaternions, so the file means the same whatever ``<compiler angle>`` a model
including it sets. The robot's start is a site, ``robot_start``; room labels and the building's
metadata are XML comments (MuJoCo drops them when it compiles the model).
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import TYPE_CHECKING, Any

from realistic_indoor.io.world3d._xml import add_comment, xml_text
from realistic_indoor.io.world3d.scene import (
    WorldOptions,
    building_boxes,
    comment_lines,
    fmt,
    room_notes,
    start_pose,
    world_name,
    write_world,
)

if TYPE_CHECKING:
    from realistic_indoor.building import Building

__all__ = ["START_SITE", "mjcf_text", "model_element", "write"]

START_SITE = "robot_start"
FLOOR_MARGIN_M = 5.0
"""How far the drawn floor reaches beyond the building on each side (m); it collides everywhere."""

_MATERIALS = {
    "floor": "0.7 0.7 0.7 1",
    "wall": "0.85 0.85 0.82 1",
    "lintel": "0.85 0.85 0.82 1",
    "door": "0.55 0.38 0.22 1",
}


def write(
    building: Building, path: str | Path, *, options: WorldOptions | None = None, **fields: Any
) -> list[Path]:
    """Write ``building`` as a MuJoCo model (``.mjcf.xml``).

    The model is named after the building's ``name`` metadata, else the file. ``options`` (or
    its fields as keywords) and errors are those of
    :func:`~realistic_indoor.io.world3d.scene.write_world`.
    """
    return write_world(building, path, mjcf_text, options, fields)


def mjcf_text(building: Building, options: WorldOptions, path: Path) -> str:
    """The model file's text."""
    root = model_element(building, options, world_name(building, path))
    return xml_text(root, comment_lines(building, options, "MuJoCo model (MJCF)"))


def _quat(yaw: float) -> str:
    """The quaternion ``w x y z`` of a turn by ``yaw`` (rad) about +z."""
    return f"{fmt(math.cos(yaw / 2))} 0 0 {fmt(math.sin(yaw / 2))}"


def model_element(building: Building, options: WorldOptions, name: str) -> ET.Element:
    """The ``<mujoco>`` element of the model ``name``."""
    x0, y0, x1, y1 = building.bounds
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    root = ET.Element("mujoco", model=name)
    extent = max(x1 - x0, y1 - y0, options.wall_height_m)
    ET.SubElement(
        root, "statistic", center=f"{fmt(cx)} {fmt(cy)} {fmt(options.wall_height_m / 2)}", extent=fmt(extent)
    )
    asset = ET.SubElement(root, "asset")
    for material, rgba in _MATERIALS.items():
        ET.SubElement(asset, "material", name=material, rgba=rgba)
    body = ET.SubElement(root, "worldbody")
    half = f"{fmt((x1 - x0) / 2 + FLOOR_MARGIN_M)} {fmt((y1 - y0) / 2 + FLOOR_MARGIN_M)} 1"
    ET.SubElement(
        body, "geom", name="floor", type="plane", pos=f"{fmt(cx)} {fmt(cy)} 0", size=half, material="floor"
    )
    for box in building_boxes(building, options):
        ET.SubElement(
            body,
            "geom",
            name=box.name,
            type="box",
            pos=" ".join(fmt(v) for v in box.centre),
            size=" ".join(fmt(v / 2) for v in box.size),
            quat=_quat(box.yaw_rad),
            material=box.kind,
        )
    for note in room_notes(building):
        add_comment(body, note.text)
    _start_site(body, building)
    return root


def _start_site(body: ET.Element, building: Building) -> None:
    pose = start_pose(building)
    if pose is None:
        add_comment(body, "no robot start: no free floor is clear enough of walls for the simulator's robot")
        return
    x, y, yaw = pose
    add_comment(body, "the simulator's robot start (x forward, facing the site's +x axis)")
    ET.SubElement(
        body,
        "site",
        name=START_SITE,
        pos=f"{fmt(x)} {fmt(y)} 0",
        quat=_quat(yaw),
        size="0.1",
        rgba="0.1 0.6 0.1 0.5",
    )
