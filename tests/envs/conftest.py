"""A toy generator for the environment tests (Jumanji style): small corridor offices, exact and fast."""

from __future__ import annotations

import numpy as np
import pytest

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


@pytest.fixture
def toy_generator() -> ToyOffice:
    """A generator of small offices (about 80 m2) that differ from seed to seed."""
    return ToyOffice()


@pytest.fixture
def toy_building() -> Building:
    """One fixed small office."""
    return ToyOffice(jitter_m=0.0)(np.random.default_rng(0))


def make_env(env_id: str, **kwargs):
    """``gym.make(env_id)`` on small toy buildings with a short step limit, for fast tests."""
    import gymnasium as gym

    import realistic_indoor.envs  # noqa: F401  (registers the ids)

    kwargs.setdefault("generator", ToyOffice())
    kwargs.setdefault("max_steps", 50)
    return gym.make(env_id, **kwargs)
