"""Fixed buildings of the team tests, whose walls are known by heart."""

from __future__ import annotations

import numpy as np

from realistic_indoor.building import Building, Door, Room

ROOM_M = 4.0
"""Side of each square room (m)."""


def rooms_in_a_row(n: int = 4) -> Building:
    """``n`` square rooms of 4 m in a row along x (south), each opening north onto one corridor.

    Room ``i`` spans ``x`` in ``[4i, 4i + 4]``, ``y`` in ``[0, 4]``; walls at ``x = 4, 8, ...``
    separate them, so the straight line between the centres of rooms ``i`` and ``j`` crosses
    ``|i - j|`` walls. The corridor (``y`` in ``[4, 6]``) has the entrance at its west end.
    """
    length = n * ROOM_M
    rooms = [Room.rectangle("c", "corridor", "corridor", (0.0, ROOM_M, length, ROOM_M + 2.0))]
    doors = [Door("entrance", "c", None, 0.0, ROOM_M + 1.0, 1.2, np.pi / 2)]
    for i in range(n):
        rooms.append(Room.rectangle(f"r{i}", "medium", "office", (ROOM_M * i, 0.0, ROOM_M * (i + 1), ROOM_M)))
        doors.append(Door(f"d{i}", f"r{i}", "c", ROOM_M * i + 2.0, ROOM_M, 0.9, 0.0))
    return Building("office", tuple(rooms), tuple(doors), {"generator": "team tests"})


def centre(i: int) -> tuple[float, float]:
    """The centre of room ``i`` of :func:`rooms_in_a_row` (m)."""
    return (ROOM_M * i + 2.0, 2.0)
