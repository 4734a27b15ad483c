"""Helpers of the agents' tests: a hand-made building, small environments of every id, an episode loop.

A module of its own (not ``conftest``): test folders' conftest modules share one name.
"""

from __future__ import annotations

import math

import gymnasium as gym
import numpy as np

from realistic_indoor.building import Building, Door, Room
from realistic_indoor.errors import ConfigError

HALL, CORRIDOR_W, ROOM = 8.0, 2.0, 4.0


def hall_and_corridor(n_rooms: int = 3) -> Building:
    """An 8 m square hall with the entrance, a 2 m corridor east of it, rooms on both sides.

    The corridor runs along y in [3, 5]; rooms are 4 m squares with 0.9 m doors; the
    entrance is in the hall's west wall.
    """
    length = n_rooms * ROOM
    y0, y1 = (HALL - CORRIDOR_W) / 2, (HALL + CORRIDOR_W) / 2
    rooms = [
        Room.rectangle("hall", "hall", "lobby", (0.0, 0.0, HALL, HALL)),
        Room.rectangle("c", "corridor", "corridor", (HALL, y0, HALL + length, y1)),
    ]
    doors = [
        Door("entrance", "hall", None, 0.0, HALL / 2, 1.2, math.pi / 2),
        Door("hc", "hall", "c", HALL, HALL / 2, CORRIDOR_W, math.pi / 2),
    ]
    for i in range(n_rooms):
        xa, xb = HALL + i * ROOM, HALL + (i + 1) * ROOM
        for side, (ya, yb), y_door in (("s", (y0 - ROOM, y0), y0), ("n", (y1, y1 + ROOM), y1)):
            rid = f"{side}{i}"
            rooms.append(Room.rectangle(rid, "medium", "office", (xa, ya, xb, yb)))
            doors.append(Door(f"d{rid}", rid, "c", (xa + xb) / 2, y_door, 0.9, 0.0))
    return Building("office", tuple(rooms), tuple(doors), {"generator": "hand-made"})


def empty_room(side_m: float) -> Building:
    """A square room ``side_m`` across without doors: the robot starts in its middle."""
    return Building("office", (Room.rectangle("r", "big", "open space", (0, 0, side_m, side_m)),))


def vestibule() -> Building:
    """A 4 m x 4 m entrance vestibule whose only way on is a 0.9 m door by its north-east corner.

    The entrance (1.2 m) is in the middle of the vestibule's south wall, the door at x = 3.35 m
    in its north wall leads into a 12 m x 8 m room. Keeping the wall on its right, a robot
    goes round the vestibule anticlockwise and turns the north-east corner just as it passes
    the door, as in the small entrance rooms of several shared real plans.
    """
    rooms = (
        Room.rectangle("v", "hall", "entrance", (0.0, 0.0, 4.0, 4.0)),
        Room.rectangle("r", "big", "open space", (-4.0, 4.0, 8.0, 12.0)),
    )
    doors = (
        Door("entrance", "v", None, 2.0, 0.0, 1.2, 0.0),
        Door("d", "v", "r", 3.35, 4.0, 0.9, 0.0),
    )
    return Building("office", rooms, doors)


class HallOffices:
    """A generator of :func:`hall_and_corridor` buildings with 2 to 4 rooms a side (picklable)."""

    def __call__(self, rng: np.random.Generator) -> Building:
        return hall_and_corridor(int(rng.integers(2, 5)))


def drive(env, agent, seed: int = 0, steps: int | None = None) -> tuple[list, dict]:
    """Run one episode (or ``steps`` steps); return the actions taken and the last info."""
    obs, info = env.reset(seed=seed)
    agent.reset(seed=seed)
    actions = []
    while steps is None or len(actions) < steps:
        action = agent.act(obs, info)
        assert env.action_space.contains(action), action
        actions.append(action)
        obs, _, terminated, truncated, info = env.step(action)
        if terminated or truncated:
            break
    return actions, info


SMALL_AREAS_M2 = {"office": 300.0, "school": 800.0, "house": 100.0, "random": 300.0}
"""Small buildings (near each generator's smallest) keep episodes of every id fast."""


def generator_exists(building_type: str) -> bool:
    """Whether the package has a generator of this type yet (the toy one stands in otherwise)."""
    from realistic_indoor.generator import make_generator

    try:
        make_generator(building_type, area_m2=SMALL_AREAS_M2[building_type])
    except ConfigError as e:
        if "unknown generator" in str(e):
            return False
        raise
    return True


def small_env(env_id: str, max_steps: int = 40, **kwargs) -> gym.Env:
    """``gym.make(env_id)`` on a small building of the id's type, with a short step limit."""
    import realistic_indoor.envs  # noqa: F401 - registers the ids
    from realistic_indoor.envs import PRESETS

    building_type = PRESETS[env_id].building_type
    if not {"generator", "building", "plan_path"} & set(kwargs):
        if generator_exists(building_type):
            kwargs.setdefault("area_m2", SMALL_AREAS_M2[building_type])
        else:
            kwargs["generator"] = HallOffices()
    return gym.make(env_id, max_steps=max_steps, max_episode_steps=max_steps, **kwargs)


class AlwaysChoose:
    """A stand-in learned model: always chooses ``choice`` among 16 candidates; records what it saw."""

    def __init__(self, choice: int = 0) -> None:
        self.action_space = gym.spaces.Discrete(16)
        self.choice = choice
        self.seen: list[dict] = []

    def predict(self, obs, action_masks=None, deterministic=True):
        self.seen.append({"obs": obs, "mask": action_masks})
        return np.int64(self.choice), None


def team_actions(agent, env, seed, steps=None):
    """Run team ``agent`` on team ``env`` from ``seed``; each step's actions (``(steps, robots, ...)``)."""
    observations, infos = env.reset(seed=seed)
    agent.reset(seed=seed)
    out = []
    while env.agents and (steps is None or len(out) < steps):
        actions = agent.act(observations, infos)
        out.append([np.asarray(actions[a]) for a in sorted(actions)])
        observations, _, _, _, infos = env.step(actions)
    return np.array(out)
