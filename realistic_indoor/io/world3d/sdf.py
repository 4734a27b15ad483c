"""Gazebo worlds (``.sdf``, ``.world``): SDFormat 1.9, for gz-sim (Fortress and newer) and ROS 2.

One static model ``building`` holds one link whose collisions and visuals are the wall boxes
(:func:`~realistic_indoor.io.world3d.scene.building_boxes`), beside a ground plane and a sun.
The world has no ``<plugin>``: gz-sim then loads its default systems (physics, user commands,
scene broadcaster). Room labels and the building's metadata are XML comments; the robot's start
is a named frame, ``robot_start``, that an ``<include>`` can be posed relative to.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import TYPE_CHECKING, Any

from realistic_indoor.io.world3d._xml import add_comment, xml_text
from realistic_indoor.io.world3d.scene import (
    Box,
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

__all__ = ["SDF_VERSION", "START_FRAME", "sdf_text", "world_element", "write"]

SDF_VERSION = "1.9"
"""The SDFormat version written: read by libsdformat 12 (gz Fortress) and every newer one."""
START_FRAME = "robot_start"
GROUND_MARGIN_M = 5.0
"""How far the ground plane's visual reaches beyond the building on each side (m)."""

_WALL_RGBA = {"wall": "0.85 0.85 0.82 1", "lintel": "0.85 0.85 0.82 1", "door": "0.55 0.38 0.22 1"}


def write(
    building: Building, path: str | Path, *, options: WorldOptions | None = None, **fields: Any
) -> list[Path]:
    """Write ``building`` as a Gazebo world (``.sdf`` or ``.world``).

    The world is named after the building's ``name`` metadata, else the file. ``options`` (or
    its fields as keywords, ``wall_height_m=3.0``) and errors are those of
    :func:`~realistic_indoor.io.world3d.scene.write_world`.
    """
    return write_world(building, path, sdf_text, options, fields)


def sdf_text(building: Building, options: WorldOptions, path: Path) -> str:
    """The world file's text."""
    root = world_element(building, options, world_name(building, path))
    return xml_text(root, comment_lines(building, options, f"Gazebo world (SDFormat {SDF_VERSION})"))


def world_element(building: Building, options: WorldOptions, name: str) -> ET.Element:
    """The ``<sdf>`` element of the world ``name``."""
    sdf = ET.Element("sdf", version=SDF_VERSION)
    world = ET.SubElement(sdf, "world", name=name)
    _sun(world, building)
    _ground(world, building)
    _building_model(world, building_boxes(building, options))
    for note in room_notes(building):
        add_comment(world, note.text)
    _start_frame(world, building, name)
    return sdf


def _text(parent: ET.Element, tag: str, text: str, **attrs: str) -> ET.Element:
    el = ET.SubElement(parent, tag, attrs)
    el.text = text
    return el


def _pose(x: float, y: float, z: float, yaw: float = 0.0) -> str:
    return f"{fmt(x)} {fmt(y)} {fmt(z)} 0 0 {fmt(yaw)}"


def _centre(building: Building) -> tuple[float, float, float, float]:
    """Centre ``(x, y)`` of the plan's bounding box and its size ``(w, h)`` (m)."""
    x0, y0, x1, y1 = building.bounds
    return (x0 + x1) / 2, (y0 + y1) / 2, x1 - x0, y1 - y0


def _sun(world: ET.Element, building: Building) -> None:
    cx, cy, _w, _h = _centre(building)
    light = ET.SubElement(world, "light", type="directional", name="sun")
    _text(light, "cast_shadows", "true")
    _text(light, "pose", _pose(cx, cy, 10.0))
    _text(light, "diffuse", "0.8 0.8 0.8 1")
    _text(light, "specular", "0.2 0.2 0.2 1")
    _text(light, "direction", "-0.5 0.1 -0.9")


def _ground(world: ET.Element, building: Building) -> None:
    cx, cy, w, h = _centre(building)
    model = ET.SubElement(world, "model", name="ground_plane")
    _text(model, "static", "true")
    _text(model, "pose", _pose(cx, cy, 0.0))
    link = ET.SubElement(model, "link", name="link")
    size = f"{fmt(w + 2 * GROUND_MARGIN_M)} {fmt(h + 2 * GROUND_MARGIN_M)}"
    for tag in ("collision", "visual"):
        el = ET.SubElement(link, tag, name=tag)
        plane = ET.SubElement(ET.SubElement(el, "geometry"), "plane")
        _text(plane, "normal", "0 0 1")
        _text(plane, "size", size)
        if tag == "visual":
            _material(el, "0.7 0.7 0.7 1")


def _material(visual: ET.Element, rgba: str) -> None:
    material = ET.SubElement(visual, "material")
    _text(material, "ambient", rgba)
    _text(material, "diffuse", rgba)
    _text(material, "specular", "0.1 0.1 0.1 1")


def _building_model(world: ET.Element, boxes: list[Box]) -> None:
    model = ET.SubElement(world, "model", name="building")
    _text(model, "static", "true")
    link = ET.SubElement(model, "link", name="walls")
    for box in boxes:
        pose = _pose(*box.centre, box.yaw_rad)
        size = " ".join(fmt(v) for v in box.size)
        for tag in ("collision", "visual"):
            el = ET.SubElement(link, tag, name=f"{box.name}_{tag}")
            _text(el, "pose", pose)
            _text(ET.SubElement(ET.SubElement(el, "geometry"), "box"), "size", size)
            if tag == "visual":
                _material(el, _WALL_RGBA[box.kind])


def _start_frame(world: ET.Element, building: Building, name: str) -> None:
    pose = start_pose(building)
    if pose is None:
        add_comment(world, "no robot start: no free floor is clear enough of walls for the simulator's robot")
        return
    x, y, yaw = pose[0], pose[1], math.remainder(pose[2], 2 * math.pi)
    add_comment(
        world,
        f"the simulator's robot start; spawn a robot there with <include><uri>...</uri><pose "
        f'relative_to="{START_FRAME}">0 0 0 0 0 0</pose></include>, or: ros2 launch ros_gz_sim '
        f"gz_spawn_model.launch.py world:={name} file:=robot.sdf x:={fmt(x)} y:={fmt(y)} z:=0 yaw:={fmt(yaw)}",
    )
    frame = ET.SubElement(world, "frame", name=START_FRAME)
    _text(frame, "pose", _pose(x, y, 0.0, yaw))
