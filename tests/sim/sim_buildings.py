"""Hand-made buildings for the simulator's tests: a corridor office of any size, rotated copies.

A module of its own (not ``conftest``): test folders' conftest modules share one name.
"""

from __future__ import annotations

import math

from realistic_indoor.building import Building, Door, Room

ROOM_W, ROOM_D, CORRIDOR_W = 4.0, 5.0, 2.5
WING_H = 2 * ROOM_D + CORRIDOR_W


def corridor_office(n_rooms: int = 6, n_wings: int = 1) -> Building:
    """Wings of offices on both sides of a corridor, joined by a spine corridor with an entrance.

    Args:
        n_rooms: Rooms along each side of each wing.
        n_wings: Wings stacked north of each other; their corridors meet the spine at x = 2.5.
    """
    rooms = [Room.rectangle("spine", "corridor", "corridor", (0, 0, CORRIDOR_W, n_wings * WING_H))]
    doors = [Door("entrance", "spine", None, CORRIDOR_W / 2, 0.0, 1.2, 0.0)]
    x0 = CORRIDOR_W
    for k in range(n_wings):
        yb = k * WING_H
        cid = f"c{k}"
        cy0, cy1 = yb + ROOM_D, yb + ROOM_D + CORRIDOR_W
        rooms.append(Room.rectangle(cid, "corridor", "corridor", (x0, cy0, x0 + n_rooms * ROOM_W, cy1)))
        doors.append(Door(f"s{k}", cid, "spine", x0, (cy0 + cy1) / 2, 1.2, math.pi / 2))
        for i in range(n_rooms):
            xa, xb = x0 + i * ROOM_W, x0 + (i + 1) * ROOM_W
            for side, (ya, yb_) in (("s", (yb, cy0)), ("n", (cy1, cy1 + ROOM_D))):
                rid = f"r{k}{side}{i}"
                rooms.append(Room.rectangle(rid, "medium", "office", (xa, ya, xb, yb_)))
                y_door = cy0 if side == "s" else cy1
                doors.append(Door(f"d{rid}", rid, cid, (xa + xb) / 2, y_door, 0.9, 0.0))
    return Building("office", tuple(rooms), tuple(doors), {"generator": "hand-made"})


def rotated(building: Building, angle_rad: float, shift: tuple[float, float] = (0.0, 0.0)) -> Building:
    """A copy of ``building`` turned by ``angle_rad`` about the origin, then moved by ``shift``."""
    c, s = math.cos(angle_rad), math.sin(angle_rad)

    def move(x: float, y: float) -> tuple[float, float]:
        return (c * x - s * y + shift[0], s * x + c * y + shift[1])

    rooms = tuple(Room(r.id, r.label, r.function, tuple(move(*p) for p in r.outline)) for r in building.rooms)
    doors = tuple(
        Door(d.id, d.room_a, d.room_b, *move(d.x, d.y), d.width_m, d.angle_rad + angle_rad)
        for d in building.doors
    )
    return Building(building.building_type, rooms, doors, dict(building.metadata))
