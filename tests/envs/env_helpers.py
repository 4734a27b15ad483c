"""Helpers of the environment tests: a toy generator (Jumanji style) and ``make_env`` for registered ids.

Not in ``conftest.py``: every test folder has a ``conftest`` module, and importing one by name
breaks runs over several folders.
"""

from __future__ import annotations

import numpy as np

from realistic_indoor.building import Building, Door, Room

CORRIDOR_W, ROOM_D = 2.0, 4.0


class ToyOffice:
    """Offices on both sides of a corridor with an entrance at its west end.

    Args:
        n_rooms: Rooms on each side.
        jitter_m: Each room's width is 4 m plus a uniform draw in ``[0, jitter_m)``; 0 makes
            every building the same.
    """

    def __init__(self, n_rooms: int = 2, jitter_m: float = 1.0) -> None:
        self.n_rooms = n_rooms
        self.jitter_m = jitter_m

    def __call__(self, rng: np.random.Generator) -> Building:
        widths = (
            4.0 + rng.uniform(0.0, self.jitter_m, self.n_rooms)
            if self.jitter_m
            else np.full(self.n_rooms, 4.0)
        )
        xs = np.concatenate([[0.0], np.cumsum(widths)])
        length = float(xs[-1])
        rooms = [Room.rectangle("c", "corridor", "corridor", (0, ROOM_D, length, ROOM_D + CORRIDOR_W))]
        doors = [Door("entrance", "c", None, 0.0, ROOM_D + CORRIDOR_W / 2, 1.2, np.pi / 2)]
        for i in range(self.n_rooms):
            x0, x1 = float(xs[i]), float(xs[i + 1])
            for side, (y0, y1), y_door in (
                ("s", (0.0, ROOM_D), ROOM_D),
                ("n", (ROOM_D + CORRIDOR_W, 2 * ROOM_D + CORRIDOR_W), ROOM_D + CORRIDOR_W),
            ):
                rid = f"{side}{i}"
                rooms.append(Room.rectangle(rid, "medium", "office", (x0, y0, x1, y1)))
                doors.append(Door(f"d{rid}", rid, "c", (x0 + x1) / 2, y_door, 0.9, 0.0))
        return Building("office", tuple(rooms), tuple(doors), {"generator": "toy"})


TEST_AREAS_M2 = {"office": 300.0, "school": 800.0, "house": 100.0, "random": 300.0}
"""Small buildings (near each generator's smallest) keep the tests of registered ids fast."""


def make_env(env_id: str, **kwargs):
    """``gym.make(env_id)`` on a small building of the id's type, with a short step limit."""
    import gymnasium as gym

    from realistic_indoor.envs import PRESETS

    kwargs.setdefault("max_steps", 50)
    if not {"generator", "building", "plan_path"} & set(kwargs):
        building_type = kwargs.get("building_type", PRESETS[env_id].building_type)
        kwargs.setdefault("area_m2", TEST_AREAS_M2[building_type])
    return gym.make(env_id, **kwargs)
