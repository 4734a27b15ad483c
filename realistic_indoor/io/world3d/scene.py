"""What every 3D export holds: the options, the wall boxes, the room labels and the start pose.

All exports share the plan's frame: metres, x and y as in the plan (its origin, y up on the
plan), z up from the floor at ``z = 0``; the ROS map export uses the same x and y. A wall is a
box centred on its wall segment of :attr:`Building.walls` (the segments with gaps at the doors):
half its thickness lies on either side of the boundary the two rooms share.
"""

from __future__ import annotations

import functools
import json
import math
import re
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, NamedTuple

import numpy as np

from realistic_indoor.checks import require_between, require_bool
from realistic_indoor.errors import ConfigError
from realistic_indoor.files import write_bytes, write_text
from realistic_indoor.sim.raster import DEFAULT_WALL_THICKNESS_M  # as the simulator and ROS map draw walls

if TYPE_CHECKING:
    from realistic_indoor.building import Building, Door, Room

__all__ = [
    "DEFAULT_DOOR_HEIGHT_M",
    "DEFAULT_WALL_HEIGHT_M",
    "DEFAULT_WALL_THICKNESS_M",
    "Box",
    "RoomNote",
    "WorldOptions",
    "building_boxes",
    "comment_lines",
    "fmt",
    "options_from",
    "room_notes",
    "safe_name",
    "start_pose",
    "world_name",
    "write_world",
]

DEFAULT_WALL_HEIGHT_M = 2.5
DEFAULT_DOOR_HEIGHT_M = 2.1


@dataclass(frozen=True)
class WorldOptions:
    """How a plan becomes a 3D world.

    The sizes have plausible ranges, checked on construction; a value outside one raises a
    one-line ``ConfigError``.

    Attributes:
        wall_height_m: Height of the walls above the floor (m), in [0.1, 10] (low walls suffice
            for a 2D laser; 10 m is a sports hall).
        wall_thickness_m: Thickness of the walls (m), in [0.01, 1]. Plans have no wall
            thickness: each wall box is centred on its segment, half on either side of the
            boundary the rooms share (rooms lose ``wall_thickness_m / 2`` of floor along each
            wall).
        door_height_m: Height of the doorways (m), in [0.1, 10] and at most ``wall_height_m``; a
            lintel box fills the wall above each doorway. Equal to ``wall_height_m``: no
            lintels. ``None`` (the default): 2.1 m, or the wall height if the walls are lower.
        exterior_doors_open: Whether entrances are open gaps (the default, as in the plan and
            the simulator) or closed by a door leaf, a box as thick as the walls filling the
            doorway up to ``door_height_m``.
    """

    wall_height_m: float = DEFAULT_WALL_HEIGHT_M
    wall_thickness_m: float = DEFAULT_WALL_THICKNESS_M
    door_height_m: float | None = None
    exterior_doors_open: bool = True

    def __post_init__(self) -> None:
        require_between("WorldOptions", "wall_height_m", self.wall_height_m, 0.1, 10.0, "m")
        require_between("WorldOptions", "wall_thickness_m", self.wall_thickness_m, 0.01, 1.0, "m")
        if self.door_height_m is None:
            object.__setattr__(self, "door_height_m", min(DEFAULT_DOOR_HEIGHT_M, self.wall_height_m))
        require_between("WorldOptions", "door_height_m", self.door_height_m, 0.1, 10.0, "m")
        if self.door_height_m > self.wall_height_m:
            raise ConfigError(
                f"WorldOptions.door_height_m must be at most wall_height_m ({self.wall_height_m!r} m), "
                f"got {self.door_height_m!r}"
            )
        require_bool("WorldOptions", "exterior_doors_open", self.exterior_doors_open)


def write_world(
    building: Building,
    path: str | Path,
    render: Callable[[Building, WorldOptions, Path], str | bytes],
    options: WorldOptions | None = None,
    fields: dict[str, Any] | None = None,
) -> list[Path]:
    """Render ``building`` with ``render`` and write the result to ``path`` whole or not at all.

    The ``write`` function of every 3D format calls this.

    Args:
        building: The building (at least one room).
        path: The file to write.
        render: Makes the file's text or bytes from the building, the options and the path.
        options: Wall height and thickness, door height, whether entrances are open.
        fields: :class:`WorldOptions` fields instead of ``options`` (``{"wall_height_m": 3.0}``).

    Returns:
        ``[path]``.

    Raises:
        ConfigError: If the building has no room, both ``options`` and ``fields`` are given, a
            field is unknown or a value is out of range.
    """
    opts = options_from(options, fields or {})
    if not building.rooms:
        raise ConfigError("cannot write a 3D world of a building without rooms")
    path = Path(path)
    data = render(building, opts, path)
    return [write_text(path, data) if isinstance(data, str) else write_bytes(path, data)]


def options_from(options: WorldOptions | None, fields: dict[str, Any]) -> WorldOptions:
    """``options``, or :class:`WorldOptions` built from keyword ``fields`` (not both).

    Raises:
        ConfigError: If both are given, a field is unknown, or a value is out of range.
    """
    if options is not None and fields:
        raise ConfigError("give either options=WorldOptions(...) or its fields as keywords, not both")
    if options is not None:
        return options
    known = WorldOptions.__dataclass_fields__
    unknown = sorted(set(fields) - set(known))
    if unknown:
        raise ConfigError(f"unknown 3D world option {unknown[0]!r}; known: {', '.join(known)}")
    return WorldOptions(**fields)


class Box(NamedTuple):
    """A box standing upright, turned about the vertical axis.

    Attributes:
        name: Unique name (``wall_3``, ``lintel_<door id>``, ``door_<door id>``).
        kind: ``"wall"``, ``"lintel"`` or ``"door"`` (a closed entrance's leaf).
        centre: ``(x, y, z)`` centre (m).
        size: ``(length, thickness, height)`` (m): along the wall, across it, upwards.
        yaw_rad: Direction of the length from +x, counter-clockwise (rad).
        segment: ``((x0, y0), (x1, y1))`` the plan segment the box stands on (m). A wall box
            reaches ``thickness / 2`` beyond both ends (its footprint is the segment buffered
            with square caps), so walls meeting at a corner overlap and close it, as the
            simulator's raster and the ROS map draw walls.
    """

    name: str
    kind: str
    centre: tuple[float, float, float]
    size: tuple[float, float, float]
    yaw_rad: float
    segment: tuple[tuple[float, float], tuple[float, float]]

    def corners(self) -> np.ndarray:
        """The 8 corners ``(8, 3)`` (m): bottom 4 counter-clockwise seen from above, then the top 4."""
        (cx, cy, cz), (sx, sy, sz) = self.centre, self.size
        c, s = math.cos(self.yaw_rad), math.sin(self.yaw_rad)
        local = np.array([(-1, -1), (1, -1), (1, 1), (-1, 1)], dtype=float) * (sx / 2, sy / 2)
        xy = local @ np.array([[c, s], [-s, c]]) + (cx, cy)
        bottom = np.column_stack([xy, np.full(4, cz - sz / 2)])
        top = np.column_stack([xy, np.full(4, cz + sz / 2)])
        return np.vstack([bottom, top])


def building_boxes(building: Building, options: WorldOptions) -> list[Box]:
    """The boxes of a building: its walls, then a lintel over each doorway, then closed entrances.

    Args:
        building: The building.
        options: Heights, thickness and whether entrances are open.

    Returns:
        Walls named ``wall_0``, ``wall_1``, ... in the order of :attr:`Building.walls`; a
        ``lintel_<door id>`` per door when ``door_height_m < wall_height_m``; a
        ``door_<door id>`` per exterior door when they are closed. Door boxes lie along the door's
        opening (its centre, width and direction).
    """
    walls = np.asarray(building.walls, dtype=float).reshape(-1, 2, 2)
    boxes = _wall_boxes(walls, options)
    names = _door_names(building.doors)
    o = options
    if o.door_height_m < o.wall_height_m:
        boxes += [
            _door_box(f"lintel_{names[d.id]}", "lintel", d, o, o.door_height_m, o.wall_height_m)
            for d in building.doors
        ]
    if not o.exterior_doors_open:
        boxes += [
            _door_box(f"door_{names[d.id]}", "door", d, o, 0.0, o.door_height_m) for d in building.entrances
        ]
    return boxes


def _wall_boxes(walls: np.ndarray, options: WorldOptions) -> list[Box]:
    """One box per wall segment, reaching half the thickness past both ends (square caps)."""
    half_t, h = options.wall_thickness_m / 2, options.wall_height_m
    boxes = []
    for i, (a, b) in enumerate(walls):
        d = b - a
        mid = (a + b) / 2
        boxes.append(
            Box(
                f"wall_{i}",
                "wall",
                (float(mid[0]), float(mid[1]), h / 2),
                (float(math.hypot(*d)) + 2 * half_t, options.wall_thickness_m, h),
                math.atan2(d[1], d[0]),
                ((float(a[0]), float(a[1])), (float(b[0]), float(b[1]))),
            )
        )
    return boxes


def _door_box(name: str, kind: str, door: Door, options: WorldOptions, z0: float, z1: float) -> Box:
    a, b = door.segment
    return Box(
        name,
        kind,
        (door.x, door.y, (z0 + z1) / 2),
        (door.width_m, options.wall_thickness_m, z1 - z0),
        door.angle_rad,
        (a, b),
    )


def world_name(building: Building, path: Path) -> str:
    """The world's name: the building's ``name`` metadata, else the file name before its first dot."""
    return safe_name(str(building.metadata.get("name") or path.name.split(".")[0]))


def safe_name(text: str) -> str:
    """``text`` with every character other than letters, digits, ``_``, ``-`` and ``.`` as ``_``."""
    return re.sub(r"[^A-Za-z0-9_.-]", "_", text) or "_"


def _door_names(doors: tuple[Door, ...]) -> dict[str, str]:
    """Each door's id made safe for element names, kept unique (a clash gets ``_<index>``)."""
    out: dict[str, str] = {}
    taken: set[str] = set()
    for i, door in enumerate(doors):
        name = safe_name(door.id)
        if name in taken:
            name = f"{name}_{i}"
        taken.add(name)
        out[door.id] = name
    return out


class RoomNote(NamedTuple):
    """A room's label for the 3D files.

    Attributes:
        room: The room.
        point: ``(x, y)`` a point inside the room (m): shapely's representative point.
        text: One line: id, function, semantic label, area and that point.
    """

    room: Room
    point: tuple[float, float]
    text: str


def room_notes(building: Building) -> list[RoomNote]:
    """A :class:`RoomNote` per room, in the building's order."""
    out = []
    for room in building.rooms:
        p = room.polygon.representative_point()
        point = (float(p.x), float(p.y))
        text = (
            f"room {room.id}: {room.function} ({room.label.value}), {room.area:.2f} m2, "
            f"inside at ({point[0]:.2f}, {point[1]:.2f})"
        )
        out.append(RoomNote(room, point, text))
    return out


@functools.lru_cache(maxsize=4)
def start_pose(building: Building) -> tuple[float, float, float] | None:
    """Where the simulator starts the robot: ``(x, y, yaw)`` (m, m, rad), or ``None`` if it cannot.

    The pose of :meth:`realistic_indoor.sim.World.default_start_pose` (just inside the first
    entrance, else in the middle of the largest hall or room), so a robot spawned there in a
    3D simulator starts where the 2D environments start it. Building the world takes about
    0.1 s for a real plan; the last few buildings' poses are kept, so writing one building in
    several formats builds it once.
    """
    from realistic_indoor.sim.world import World

    try:
        return World(building).start_pose
    except ConfigError:
        return None


def comment_lines(building: Building, options: WorldOptions, fmt_name: str) -> list[str]:
    """Lines describing the file, the frame, the options and the building's metadata.

    Args:
        building: The building.
        options: The options the file was written with.
        fmt_name: What the file is (``"Gazebo world (SDFormat 1.9)"``).
    """
    from realistic_indoor.version import __version__

    x0, y0, x1, y1 = building.bounds
    o = options
    lines = [
        f"{fmt_name} written by realistic-indoor {__version__}",
        f"building: {building.building_type.value}, {len(building.rooms)} rooms, "
        f"{len(building.doors)} doors ({len(building.entrances)} exterior), {building.area:.2f} m2",
        f"frame: metres, the plan's x and y (as the ROS map export), z up from the floor at z = 0; "
        f"plan bounds x {fmt(x0)} to {fmt(x1)}, y {fmt(y0)} to {fmt(y1)}",
        f"walls: boxes {fmt(o.wall_height_m)} m high and {fmt(o.wall_thickness_m)} m thick centred on the "
        f"plan's wall segments (with gaps at the doors); doorways {fmt(o.door_height_m)} m high; "
        f"entrances {'open' if o.exterior_doors_open else 'closed by a door box'}",
    ]
    lines += [f"metadata {key}: {_meta_text(value)}" for key, value in sorted(building.metadata.items())]
    return lines


def _meta_text(value: Any) -> str:
    if isinstance(value, str):
        return " ".join(value.split())
    return json.dumps(value, sort_keys=True, default=str, ensure_ascii=False)


def fmt(value: float) -> str:
    """A number as text with at most 6 decimals (micrometres), no trailing zeros, never ``-0``."""
    text = f"{round(float(value), 6) + 0.0:.6f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text
