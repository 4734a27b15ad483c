"""The generator's working plan: rooms as grid rectangles, doors as wall positions.

Generators fill a :class:`Plan` with plain integers and build the ``Building`` once at the end
(:meth:`Plan.to_building`), which keeps the inner loops free of shapely and of object churn.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from realistic_indoor.building import CIRCULATION_LABELS, Building, Door, Room, SemanticLabel
from realistic_indoor.generator.geometry import Contact, Rect, contacts_by_pair, outline, to_metres

__all__ = ["B", "C", "H", "M", "Plan", "PlanDoor", "PlanRoom", "S", "build_door"]

C, H, S, M, B = (
    SemanticLabel.CORRIDOR,
    SemanticLabel.HALL,
    SemanticLabel.SMALL,
    SemanticLabel.MEDIUM,
    SemanticLabel.BIG,
)
"""Short names of the semantic labels, as in the paper (C, H, S, M, B)."""


@dataclass
class PlanRoom:
    """A room being generated.

    Attributes:
        rects: The rectangles whose union is the room (one for a rectangle, two for an L).
        label: Semantic label.
        function: Functional label (filled in late, once doors are known).
        role: What the layout made it for (``"corridor"``, ``"stub"``, ``"hall"``, ``"lobby"``,
            ``"room"``, ``"core"``, ``"closet"``, ``"back"``, ``"end"``, ``"annex"``, ...).
        host: Index of the room a closet or back room is entered through, or -1.
        group: Index shared by the rooms of one service core (-1: none).
    """

    rects: list[Rect]
    label: SemanticLabel
    function: str = ""
    role: str = "room"
    host: int = -1
    group: int = -1

    @property
    def area(self) -> int:
        """Floor area in square units."""
        return sum((r[2] - r[0]) * (r[3] - r[1]) for r in self.rects)

    @property
    def bounds(self) -> Rect:
        """Bounding box (units)."""
        return (
            min(r[0] for r in self.rects),
            min(r[1] for r in self.rects),
            max(r[2] for r in self.rects),
            max(r[3] for r in self.rects),
        )

    @property
    def is_circulation(self) -> bool:
        """Whether the room is a corridor or a hall."""
        return self.label in CIRCULATION_LABELS


@dataclass
class PlanDoor:
    """A door on a wall piece shared by rooms ``a`` and ``b`` (``b`` is ``None`` outside).

    Attributes:
        a: Index of one room.
        b: Index of the other room, or ``None`` for an exterior door.
        axis: ``"v"`` (wall at ``x = coord``) or ``"h"`` (wall at ``y = coord``).
        coord: The wall's fixed coordinate (units).
        centre2: Twice the door centre's position along the wall (units; doubled to stay whole).
        width: Door width (units).
    """

    a: int
    b: int | None
    axis: str
    coord: int
    centre2: int
    width: int


@dataclass
class Plan:
    """Rooms and doors of a building under construction.

    Attributes:
        rooms: The rooms; their index is their identity until :meth:`to_building`.
        doors: The doors.
        exterior_holes: Rectangles of outside space enclosed by the building (courtyards);
            entrances are never placed towards them.
    """

    rooms: list[PlanRoom] = field(default_factory=list)
    doors: list[PlanDoor] = field(default_factory=list)
    exterior_holes: list[Rect] = field(default_factory=list)
    _contacts: dict[tuple[int, int], list[Contact]] | None = field(default=None, repr=False)
    _walls: dict[int, list[Contact]] = field(default_factory=dict, repr=False)
    _door_index: tuple[int, int, dict[tuple[str, int], list[PlanDoor]]] | None = field(
        default=None, repr=False
    )

    def add(self, room: PlanRoom) -> int:
        """Append a room and return its index."""
        self.rooms.append(room)
        self._contacts = None
        return len(self.rooms) - 1

    def invalidate(self) -> None:
        """Forget cached wall contacts after rooms were changed in place."""
        self._contacts = None

    # -- adjacency ------------------------------------------------------------------------------
    def contacts(self) -> dict[tuple[int, int], list[Contact]]:
        """Shared wall pieces between every pair of touching rooms, keyed ``(i, j)`` with ``i < j``."""
        if self._contacts is None:
            self._contacts = contacts_by_pair([r.rects for r in self.rooms])
            self._walls = {}
            for (i, j), walls in self._contacts.items():
                self._walls.setdefault(i, []).extend(walls)
                self._walls.setdefault(j, []).extend(walls)
        return self._contacts

    def walls_of(self, i: int) -> list[Contact]:
        """Every wall piece room ``i`` shares with another room."""
        self.contacts()
        return self._walls.get(i, [])

    def doors_on(self, axis: str, coord: int) -> list[PlanDoor]:
        """The doors on the wall line ``axis``/``coord``.

        The index catches up with doors appended since the last call, and is rebuilt if the
        door list was replaced or shortened.
        """
        if (
            self._door_index is None
            or self._door_index[0] != id(self.doors)
            or self._door_index[1] > len(self.doors)
        ):
            self._door_index = (id(self.doors), 0, {})
        _, seen, index = self._door_index
        for d in self.doors[seen:]:
            index.setdefault((d.axis, d.coord), []).append(d)
        self._door_index = (id(self.doors), len(self.doors), index)
        return index.get((axis, coord), [])

    def shared(self, i: int, j: int) -> list[Contact]:
        """Wall pieces rooms ``i`` and ``j`` share (empty if they do not touch)."""
        return self.contacts().get((i, j) if i < j else (j, i), [])

    def neighbours(self) -> list[list[int]]:
        """For each room, the rooms it shares a wall with (ascending)."""
        out: list[list[int]] = [[] for _ in self.rooms]
        for i, j in sorted(self.contacts()):
            out[i].append(j)
            out[j].append(i)
        return out

    def door_count(self) -> list[int]:
        """Number of doors of each room."""
        n = [0] * len(self.rooms)
        for d in self.doors:
            n[d.a] += 1
            if d.b is not None:
                n[d.b] += 1
        return n

    def door_partners(self) -> list[list[int | None]]:
        """For each room, the room behind each of its doors (``None``: outside)."""
        out: list[list[int | None]] = [[] for _ in self.rooms]
        for d in self.doors:
            out[d.a].append(d.b)
            if d.b is not None:
                out[d.b].append(d.a)
        return out

    def reachable(self) -> list[bool]:
        """Which rooms can be reached through doors from the first exterior door (the main entrance).

        Rooms behind another exterior door but cut off from the main entrance count as
        unreachable, so that the building comes out in one piece. Rooms without rectangles (taken
        out of the plan) count as reached.
        """
        adj: list[list[int]] = [[] for _ in self.rooms]
        frontier = []
        for d in self.doors:
            if d.b is None:
                frontier = frontier or [d.a]
            else:
                adj[d.a].append(d.b)
                adj[d.b].append(d.a)
        seen = [not r.rects for r in self.rooms]
        for s in frontier:
            seen[s] = True
        while frontier:
            i = frontier.pop()
            for j in adj[i]:
                if not seen[j]:
                    seen[j] = True
                    frontier.append(j)
        return seen

    def transform(self, swap: bool, flip_x: bool, flip_y: bool) -> None:
        """Mirror and/or transpose the whole plan in place; its bounding box starts at ``(0, 0)``."""
        boxes = [r.bounds for r in self.rooms]
        x0, y0 = min(b[0] for b in boxes), min(b[1] for b in boxes)
        x1, y1 = max(b[2] for b in boxes), max(b[3] for b in boxes)

        def point2(x2: int, y2: int) -> tuple[int, int]:
            x2 = 2 * x1 - x2 if flip_x else x2 - 2 * x0
            y2 = 2 * y1 - y2 if flip_y else y2 - 2 * y0
            return (y2, x2) if swap else (x2, y2)

        def rect(r: Rect) -> Rect:
            ax, ay = point2(2 * r[0], 2 * r[1])
            bx, by = point2(2 * r[2], 2 * r[3])
            return (min(ax, bx) // 2, min(ay, by) // 2, max(ax, bx) // 2, max(ay, by) // 2)

        for room in self.rooms:
            room.rects = [rect(r) for r in room.rects]
        self.exterior_holes = [rect(r) for r in self.exterior_holes]
        for d in self.doors:
            x2, y2 = (2 * d.coord, d.centre2) if d.axis == "v" else (d.centre2, 2 * d.coord)
            x2, y2 = point2(x2, y2)
            vertical = (d.axis == "v") != swap
            d.axis = "v" if vertical else "h"
            d.coord, d.centre2 = (x2 // 2, y2) if vertical else (y2 // 2, x2)
        self._contacts = None

    # -- output ---------------------------------------------------------------------------------
    def to_building(self, building_type: str, metadata: dict[str, Any]) -> Building:
        """Build the immutable ``Building`` (metres), rooms ``r0, r1, ...`` and doors ``d0, d1, ...``."""
        ids = [f"r{i}" for i in range(len(self.rooms))]
        rooms = tuple(
            Room(
                ids[i], r.label, r.function, tuple((to_metres(x), to_metres(y)) for x, y in outline(r.rects))
            )
            for i, r in enumerate(self.rooms)
        )
        doors = tuple(build_door(f"d{k}", d, ids) for k, d in enumerate(self.doors))
        return Building(building_type, rooms, doors, metadata)


def build_door(door_id: str, d: PlanDoor, ids: list[str]) -> Door:
    """The ``Door`` (metres) of a plan door, rooms named by ``ids``."""
    along = to_metres(d.centre2 / 2)
    fixed = to_metres(d.coord)
    x, y = (fixed, along) if d.axis == "v" else (along, fixed)
    angle = math.pi / 2 if d.axis == "v" else 0.0
    return Door(
        door_id,
        ids[d.a],
        ids[d.b] if d.b is not None else None,
        x,
        y,
        to_metres(d.width),
        angle,
    )
