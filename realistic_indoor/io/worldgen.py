"""World Generator XML: the world files of NIST's USARSim World Generator (version 4).

A world is a grid of 3 m cells, ``<world depth= width= name=>``, holding rectangular room
modules ``<room name="FILE.t3d" x= y= theta=>`` and doors ``<door x= y= direction=>`` in the
middle of cell edges. Grid ``x`` counts rows from the top (the tool's north), ``y`` columns from
the left; a room's ``x``/``y`` is its top-left cell and ``theta`` the number of quarter turns
clockwise. A door with ``direction`` 0 (or 2) lies on the edge between cells ``(x-1, y)`` and
``(x, y)``; with 1 (or 3), between ``(x, y-1)`` and ``(x, y)``. Cells of the tool's
``hallway.t3d`` module open into each other. In plan coordinates (metres, y up) cell ``(x, y)``
spans ``[3y, 3y+3] x [3(depth-x-1), 3(depth-x)]``.

Reading needs each module's size: the tool's stock modules are known, this package's own
modules are named ``{label}_{depth}x{width}.t3d`` (``medium_2x3.t3d``), and others come from the
``modules`` argument (the tool's ``rooms.xml`` or a mapping). ``docs/formats.md`` lists what the
format cannot hold.
"""

from __future__ import annotations

import math
import re
import warnings
import xml.etree.ElementTree as ET
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from realistic_indoor.building import Building, Door, Room, SemanticLabel
from realistic_indoor.building.admit import MAX_SPAN_M
from realistic_indoor.checks import require_between
from realistic_indoor.errors import ConfigError, PlanFormatError
from realistic_indoor.files import atomic_path
from realistic_indoor.io.floorplan.xmlfile import parse_root

__all__ = ["DOOR_WIDTH_M", "GRID_M", "STOCK_MODULES", "LossyExportWarning", "read", "write"]

GRID_M = 3.0
"""Side of a grid cell (m): the tool's room unit (its cells are 3 m rooms 12.8 cm apart)."""

DOOR_WIDTH_M = 0.936
"""Width of the tool's doors (m), its default ``WorldGen.DoorSize``."""

HALLWAY = "hallway.t3d"

STOCK_MODULES: dict[str, tuple[int, int, str]] = {
    HALLWAY: (1, 1, "corridor"),
    "ComputerLab.t3d": (2, 2, "computer lab"),
    "ComputerLabDestroyed.t3d": (2, 2, "computer lab"),
    "ConcreteCages.t3d": (3, 3, "room with cages"),
    "ConcreteFuturistic.t3d": (2, 2, "reception"),
    "ConcreteRubble.t3d": (1, 1, "room with rubble"),
    "Cubicle.t3d": (4, 4, "cubicle"),
    "CubicleDestroyed.t3d": (4, 4, "cubicle"),
    "CubicleWood.t3d": (2, 2, "cubicle"),
    "DeskChairConcrete.t3d": (1, 1, "workstation room"),
    "DeskComputerWood.t3d": (1, 1, "computer desk"),
    "DestroyedWood.t3d": (2, 2, "cubicle"),
    "EmptyConcrete.t3d": (1, 1, "empty room"),
    "EmptyWood.t3d": (3, 3, "empty room"),
    "OfficeLit.t3d": (1, 1, "office"),
    "OfficeLitDestroyed.t3d": (1, 1, "office"),
    "PipelineConcrete.t3d": (2, 2, "pipeline room"),
    "RoadblocksWood.t3d": (3, 3, "room with roadblocks"),
    "SpaceOffice.t3d": (2, 1, "office"),
    "TightOffice.t3d": (2, 1, "office"),
    "TightOfficeDestroyed.t3d": (2, 1, "office"),
    "Victims.t3d": (1, 2, "victim room"),
}
"""The modules shipped with World Generator 4: file -> (depth, width in cells, function)."""

_OWN_MODULE = re.compile(r"^(corridor|hall|small|medium|big)_(\d+)x(\d+)\.t3d$", re.IGNORECASE)


class LossyExportWarning(UserWarning):
    """A building written as World Generator XML lost rooms, doors or area to the 3 m grid."""


# -- reading ----------------------------------------------------------------------------------


def read(
    path: str | Path,
    *,
    modules: Mapping[str, tuple[int, int]] | str | Path | None = None,
    grid_m: float = GRID_M,
    door_width_m: float = DOOR_WIDTH_M,
    building_type: str = "unknown",
) -> Building:
    """Read a World Generator world.

    Rooms become axis-aligned rectangles; hallway cells are merged into rectangular corridors
    (greedily, widest first), joined to each other by openings as wide as their shared wall. A
    door with a room on one side only is an exterior door.

    Args:
        path: The world file.
        modules: Sizes of modules other than the stock ones and this package's own: the path of
            the tool's ``rooms.xml`` or a mapping ``{file: (depth, width)}`` in cells.
        grid_m: Side of a cell (m), in [1, 10].
        door_width_m: Width given to every door (the format has none), in [0.6, 3] m.
        building_type: The building type to record (the format has none).

    Returns:
        The building. Room ids are ``room-X-Y`` (the module's top-left cell), corridor ids
        ``hallway-X-Y``, door ids ``door-X-Y-D``; semantic labels come from the module name
        (this package's modules) or from the area (9 m2 small, up to 27 m2 medium, larger big);
        ``metadata`` holds ``source``, ``name`` (the world's) and ``grid_m``.

    Raises:
        ConfigError: If ``grid_m`` or ``door_width_m`` is out of its range.
        PlanFormatError: If the file is missing or malformed, the world is larger than
            :data:`~realistic_indoor.building.admit.MAX_SPAN_M` a side, a module is unknown, a room leaves
            the world or overlaps another, or a door touches no room.
    """
    require_between("worldgen.read", "grid_m", grid_m, 1.0, 10.0, "m")
    require_between("worldgen.read", "door_width_m", door_width_m, 0.6, 3.0, "m")
    source, path = str(path), Path(path)
    sizes = _module_table(modules, path)
    root = parse_root(path)
    if root.tag != "world":
        raise PlanFormatError(path, f"root element is <{root.tag}>, not <world>: not a World Generator file")
    depth, width = (_int(root, k, path, "world", minimum=1) for k in ("depth", "width"))
    if max(depth, width) * grid_m > MAX_SPAN_M:
        raise PlanFormatError(
            path,
            f"a {depth} x {width} cell world is {depth * grid_m:g} m x {width * grid_m:g} m; "
            f"at most {MAX_SPAN_M:g} m a side is read",
            "world",
        )
    grid = np.full((depth, width), -1, dtype=int)
    rooms, hallway = _read_rooms(root, path, sizes, grid, grid_m)
    rooms, openings = _merge_hallways(hallway, grid, rooms, grid_m)
    doors, skipped = _read_doors(root, path, grid, rooms, grid_m, door_width_m)
    meta: dict[str, Any] = {"source": source, "name": root.get("name") or path.stem, "grid_m": grid_m}
    if skipped:
        meta["skipped_doors"] = skipped
    return Building(building_type, tuple(rooms), tuple(openings + doors), meta)


def _int(el: ET.Element, key: str, path: Path, where: str, minimum: int = 0) -> int:
    text = el.get(key)
    try:
        value = int(text)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise PlanFormatError(path, f"{key} must be an integer, not {text!r}", where) from None
    if value < minimum:
        raise PlanFormatError(path, f"{key} must be at least {minimum}, not {value}", where)
    return value


def _module_table(modules, path: Path) -> dict[str, tuple[int, int, str]]:
    table = {k.lower(): v for k, v in STOCK_MODULES.items()}
    if isinstance(modules, (str, Path)):
        modules = _rooms_xml(Path(modules))
    for name, size in (modules or {}).items():
        try:
            d, w = (int(v) for v in size[:2])
        except (TypeError, ValueError):
            raise ConfigError(
                f"module {name!r}: size must be (depth, width) in cells, not {size!r}"
            ) from None
        table[str(name).lower()] = (d, w, "room")
    return table


def _rooms_xml(path: Path) -> dict[str, tuple[int, int]]:
    """Module sizes from a World Generator ``rooms.xml`` (``<room src= size="d, w, h">``)."""
    out = {}
    for i, el in enumerate(parse_root(path).iter("room")):
        try:
            d, w, *_ = (int(v) for v in el.get("size", "").split(","))
        except ValueError:
            raise PlanFormatError(
                path, f"size {el.get('size')!r} is not 'depth, width, height'", f"room {i + 1}"
            ) from None
        out[el.get("src", "")] = (d, w)
    return out


def _module(name: str, sizes, path: Path, where: str) -> tuple[int, int, SemanticLabel, str]:
    own = _OWN_MODULE.match(name)
    if own:
        label = SemanticLabel(own.group(1).lower())
        return int(own.group(2)), int(own.group(3)), label, label.value
    if name.lower() not in sizes:
        raise PlanFormatError(
            path,
            f"unknown module {name!r}; pass modules=<your World Generator rooms.xml> or "
            f'modules={{"{name}": (depth, width)}}',
            where,
        )
    d, w, function = sizes[name.lower()]
    return d, w, _label_by_area(d * w, function), function


def _label_by_area(cells: int, function: str) -> SemanticLabel:
    if function == "corridor":
        return SemanticLabel.CORRIDOR
    if cells <= 1:
        return SemanticLabel.SMALL
    return SemanticLabel.MEDIUM if cells <= 3 else SemanticLabel.BIG


def _cell_box(x: int, y: int, d: int, w: int, depth: int, g: float) -> tuple[float, float, float, float]:
    """Plan box (xmin, ymin, xmax, ymax) in metres of ``d x w`` cells from top-left cell (x, y)."""
    return (y * g, (depth - x - d) * g, (y + w) * g, (depth - x) * g)


def _read_rooms(root, path, sizes, grid, g) -> tuple[list[Room], list[tuple[int, int]]]:
    depth, width = grid.shape
    rooms, hallway = [], []
    for el in root.findall("room"):
        name = el.get("name") or ""
        where = f'room name="{name}" x="{el.get("x")}" y="{el.get("y")}"'
        x, y, theta = (_int(el, k, path, where) for k in ("x", "y", "theta"))
        d, w, label, function = _module(name, sizes, path, where)
        d, w = (w, d) if theta % 2 else (d, w)
        if x + d > depth or y + w > width:
            raise PlanFormatError(path, f"the {d}x{w} module leaves the {depth}x{width} world", where)
        taken = grid[x : x + d, y : y + w]
        if (taken != -1).any():
            raise PlanFormatError(path, "overlaps another room", where)
        if name.lower() == HALLWAY:
            grid[x : x + d, y : y + w] = -2
            hallway.extend((i, j) for i in range(x, x + d) for j in range(y, y + w))
            continue
        grid[x : x + d, y : y + w] = len(rooms)
        rooms.append(Room.rectangle(f"room-{x}-{y}", label, function, _cell_box(x, y, d, w, depth, g)))
    return rooms, hallway


def _merge_hallways(cells, grid, rooms, g) -> tuple[list[Room], list[Door]]:
    """Hallway cells as rectangular corridors (rows first), and the openings between them."""
    depth = grid.shape[0]
    rooms = list(rooms)
    first = len(rooms)
    for x, y in sorted(cells):
        if grid[x, y] != -2:
            continue
        w = 1
        while y + w < grid.shape[1] and grid[x, y + w] == -2:
            w += 1
        d = 1
        while x + d < depth and (grid[x + d, y : y + w] == -2).all():
            d += 1
        grid[x : x + d, y : y + w] = len(rooms)
        rooms.append(
            Room.rectangle(f"hallway-{x}-{y}", "corridor", "corridor", _cell_box(x, y, d, w, depth, g))
        )
    return rooms, _openings(rooms[first:], g)


def _openings(corridors: list[Room], g: float) -> list[Door]:
    """One opening, as wide as the shared wall, between each two corridors that touch."""
    out = []
    for i, a in enumerate(corridors):
        for b in corridors[i + 1 :]:
            shared = a.polygon.intersection(b.polygon)
            if shared.length > 1e-9 and shared.geom_type == "LineString":
                (x0, y0), (x1, y1) = shared.coords[0], shared.coords[-1]
                angle = math.atan2(y1 - y0, x1 - x0)
                out.append(
                    Door(
                        f"open-{a.id}-{b.id}", a.id, b.id, (x0 + x1) / 2, (y0 + y1) / 2, shared.length, angle
                    )
                )
    return out


def _read_doors(root, path, grid, rooms, g, width_m) -> tuple[list[Door], list[str]]:
    depth, width = grid.shape
    doors, skipped, seen = [], [], set()
    for el in root.findall("door"):
        where = f'door x="{el.get("x")}" y="{el.get("y")}" direction="{el.get("direction")}"'
        x, y, direction = (_int(el, k, path, where) for k in ("x", "y", "direction"))
        if direction > 3:
            raise PlanFormatError(path, f"direction must be 0, 1, 2 or 3, not {direction}", where)
        horizontal = direction % 2 == 0
        a, b = ((x - 1, y), (x, y)) if horizontal else ((x, y - 1), (x, y))
        owners = [int(grid[c]) if 0 <= c[0] < depth and 0 <= c[1] < width else -1 for c in (a, b)]
        owners = [o for o in owners if o >= 0]
        if not owners:
            raise PlanFormatError(path, "has no room on either side", where)
        if (len(owners) == 2 and owners[0] == owners[1]) or (x, y, direction % 2) in seen:
            skipped.append(where)
            continue
        seen.add((x, y, direction % 2))
        cx, cy = ((y + 0.5) * g, (depth - x) * g) if horizontal else (y * g, (depth - x - 0.5) * g)
        ids = [rooms[o].id for o in owners]
        angle = 0.0 if horizontal else math.pi / 2
        doors.append(
            Door(
                f"door-{x}-{y}-{direction % 2}",
                ids[0],
                ids[1] if len(ids) > 1 else None,
                cx,
                cy,
                width_m,
                angle,
            )
        )
    return doors, skipped


# -- writing ----------------------------------------------------------------------------------


def write(
    building: Building, path: str | Path, *, grid_m: float = GRID_M, strict: bool = False
) -> list[Path]:
    """Write ``building`` as a World Generator world.

    Each room's bounding box is snapped to the grid (at least one cell; corridors first, then
    halls, then rooms from the largest, each shrunk to the largest free rectangle when it
    collides with those before) and becomes a module named ``{label}_{depth}x{width}.t3d``; each
    door goes to the free cell edge nearest to it on the wall its rooms share (an exterior door:
    on its room's outer wall). A building drawn on the grid is written exactly (door widths aside); any
    other loses area, and may lose rooms or doors: a :class:`LossyExportWarning` says what.

    Args:
        building: The building.
        path: The file to write (``.wg.xml``).
        grid_m: Side of a cell (m), in [1, 10].
        strict: Raise instead of warning when anything is lost.

    Returns:
        ``[path]``.

    Raises:
        ConfigError: If ``grid_m`` is out of its range, the building has no rooms, or ``strict``
            and something would be lost.
    """
    require_between("worldgen.write", "grid_m", grid_m, 1.0, 10.0, "m")
    if not building.rooms:
        raise ConfigError("cannot write a building without rooms")
    path = Path(path)
    x0, y0, x1, y1 = building.bounds
    shape = (max(1, math.ceil((y1 - y0) / grid_m - 1e-9)), max(1, math.ceil((x1 - x0) / grid_m - 1e-9)))
    rects = _snap_rooms(building, (x0, y0), shape, grid_m)
    placed, lost_doors = _place_doors(building, rects, shape, (x0, y0), grid_m)
    _report_losses(building, rects, lost_doors, grid_m, strict)
    name = str(building.metadata.get("name") or path.name.removesuffix(".xml").removesuffix(".wg"))
    _write_xml(path, name, building, rects, placed, shape)
    return [path]


_PRIORITY = {SemanticLabel.CORRIDOR: 0, SemanticLabel.HALL: 1}


def _snap_rooms(building: Building, origin, shape, g: float) -> list[tuple[int, int, int, int] | None]:
    """Each room's bounding box snapped to the grid.

    Returns ``(r0, c0, r1, c1)`` cells (end-exclusive, row 0 at the bottom) per room, or ``None``
    for a room left without a free cell.

    Corridors go first, then halls, then rooms from the largest: circulation keeps the topology
    together. A box that collides with cells already taken shrinks to the largest free rectangle
    inside it.
    """
    taken = np.zeros(shape, dtype=bool)
    rects: list[tuple[int, int, int, int] | None] = [None] * len(building.rooms)
    order = sorted(
        range(len(building.rooms)),
        key=lambda k: (_PRIORITY.get(building.rooms[k].label, 2), -building.rooms[k].area),
    )
    for k in order:
        bx0, by0, bx1, by1 = building.rooms[k].bounds
        c0, c1 = _span(bx0 - origin[0], bx1 - origin[0], g, shape[1])
        r0, r1 = _span(by0 - origin[1], by1 - origin[1], g, shape[0])
        free = np.zeros(shape, dtype=bool)
        free[r0:r1, c0:c1] = True
        rect = _largest_rectangle(free & ~taken)
        if rect is not None:
            taken[rect[0] : rect[2], rect[1] : rect[3]] = True
        rects[k] = rect
    return rects


def _span(lo: float, hi: float, g: float, n: int) -> tuple[int, int]:
    """Cells from ``lo`` to ``hi`` (m) with both ends rounded to grid lines, at least one cell."""
    a, b = math.floor(lo / g + 0.5), math.floor(hi / g + 0.5)
    if b <= a:
        a = min(n - 1, math.floor((lo + hi) / 2 / g))
        b = a + 1
    return max(0, a), min(n, b)


def _largest_rectangle(mask: np.ndarray) -> tuple[int, int, int, int] | None:
    """The largest all-true rectangle of ``mask`` (first found on ties), by the histogram method."""
    best_area, best = 0, None
    heights = np.zeros(mask.shape[1], dtype=int)
    for r in range(mask.shape[0]):
        heights = np.where(mask[r], heights + 1, 0)
        stack: list[tuple[int, int]] = []
        for c in range(mask.shape[1] + 1):
            h = int(heights[c]) if c < mask.shape[1] else 0
            start = c
            while stack and stack[-1][1] >= h:
                s, sh = stack.pop()
                if sh * (c - s) > best_area:
                    best_area, best = sh * (c - s), (r - sh + 1, s, r + 1, c)
                start = s
            stack.append((start, h))
    return best


def _edges_between(a, b) -> list[tuple[tuple[int, int], tuple[int, int]]]:
    """Unit cell edges shared by rectangles ``a`` and ``b``, as pairs (cell of a, cell of b)."""
    out = []
    for (ar0, ac0, ar1, ac1), (br0, bc0, br1, bc1), flip in ((a, b, False), (b, a, True)):
        pairs = []
        if ac1 == bc0:
            pairs = [((r, ac1 - 1), (r, bc0)) for r in range(max(ar0, br0), min(ar1, br1))]
        if ar1 == br0:
            pairs += [((ar1 - 1, c), (br0, c)) for c in range(max(ac0, bc0), min(ac1, bc1))]
        out += [(q, p) if flip else (p, q) for p, q in pairs]
    return out


def _outer_edges(rect, owner: np.ndarray) -> list[tuple[tuple[int, int], tuple[int, int]]]:
    """Unit edges of ``rect`` with no room beyond them, as (cell inside, cell outside)."""
    r0, c0, r1, c1 = rect
    rows, cols = owner.shape
    cells = [(r, c) for r in range(r0, r1) for c in range(c0, c1) if r in (r0, r1 - 1) or c in (c0, c1 - 1)]
    out = []
    for r, c in cells:
        for dr, dc in ((-1, 0), (1, 0), (0, -1), (0, 1)):
            q = (r + dr, c + dc)
            inside = r0 <= q[0] < r1 and c0 <= q[1] < c1
            if not inside and not (0 <= q[0] < rows and 0 <= q[1] < cols and owner[q] >= 0):
                out.append(((r, c), q))
    return out


def _edge_centre(edge, origin, g: float) -> tuple[float, float]:
    (r, c), (q, s) = edge
    return (origin[0] + ((c + s) / 2 + 0.5) * g, origin[1] + ((r + q) / 2 + 0.5) * g)


def _place_doors(building, rects, shape, origin, g):
    """Each door on the free shared cell edge nearest to it; returns placements and lost door ids."""
    index = {r.id: k for k, r in enumerate(building.rooms)}
    owner = np.full(shape, -1, dtype=int)
    for k, rect in enumerate(rects):
        if rect is not None:
            owner[rect[0] : rect[2], rect[1] : rect[3]] = k
    used, placed, lost = set(), [], []
    for door in building.doors:
        a = rects[index[door.room_a]] if door.room_a in index else None
        b = rects[index[door.room_b]] if door.room_b in index else None
        if a is None or (door.room_b is not None and b is None):
            lost.append(door.id)
            continue
        edges = _outer_edges(a, owner) if door.room_b is None else _edges_between(a, b)
        free = [e for e in edges if frozenset(e) not in used]
        if not free:
            lost.append(door.id)
            continue
        edge = min(free, key=lambda e: math.dist(_edge_centre(e, origin, g), (door.x, door.y)))
        used.add(frozenset(edge))
        placed.append(edge)
    return placed, lost


def _report_losses(building, rects, lost_doors, g: float, strict: bool) -> None:
    dropped = [r.id for r, rect in zip(building.rooms, rects, strict=True) if rect is None]
    changed = [
        r.id
        for r, rect in zip(building.rooms, rects, strict=True)
        if rect is not None
        and abs((rect[2] - rect[0]) * (rect[3] - rect[1]) * g * g - r.area) > 1e-6 * max(1.0, r.area)
    ]
    if not (dropped or changed or lost_doors):
        return
    parts = [
        f"{len(changed)} rooms changed area (e.g. {changed[0]!r})" if changed else "",
        f"{len(dropped)} rooms dropped (e.g. {dropped[0]!r})" if dropped else "",
        f"{len(lost_doors)} doors dropped (e.g. {lost_doors[0]!r})" if lost_doors else "",
    ]
    message = (
        f"the building does not fit World Generator's {g:g} m grid: {', '.join(p for p in parts if p)}; "
        "see docs/formats.md"
    )
    if strict:
        raise ConfigError(message)
    warnings.warn(message, LossyExportWarning, stacklevel=3)


def _write_xml(path, name, building, rects, placed, shape) -> None:
    rows, cols = shape
    root = ET.Element("world", depth=str(rows), width=str(cols), name=name)
    for room, rect in zip(building.rooms, rects, strict=True):
        if rect is not None:
            r0, c0, r1, c1 = rect
            module = f"{room.label.value}_{r1 - r0}x{c1 - c0}.t3d"
            ET.SubElement(root, "room", name=module, x=str(rows - r1), y=str(c0), theta="0")
    for (r, c), (q, s) in placed:
        if r == q:  # a wall between columns: direction 1, on the left edge of column max(c, s)
            attrs = {"x": str(rows - 1 - r), "y": str(max(c, s)), "direction": "1"}
        else:  # a wall between rows: direction 0, on the top edge of the lower row
            attrs = {"x": str(rows - max(r, q)), "y": str(c), "direction": "0"}
        ET.SubElement(root, "door", attrs)
    ET.indent(root, space="  ")
    with atomic_path(path) as tmp:
        ET.ElementTree(root).write(tmp, encoding="UTF-8", xml_declaration=True)
