"""Every planning explorer covers a building from an awkward start: the middle of a large empty
room, the middle of a corridor, and the dead end of one (the failures the wall follower had)."""

from __future__ import annotations

import math

import gymnasium as gym
import pytest

from realistic_indoor.agents import make_agent
from realistic_indoor.building import Building, Door, Room

CORRIDOR_M, ROOM_M = 24.0, 4.0


def _empty_room() -> Building:
    """A 20 m square room without doors: the robot starts in its middle, 10 m from every wall."""
    return Building("office", (Room.rectangle("r", "big", "open space", (0, 0, 20, 20)),))


def _corridor_offices(entrance_at_end: bool) -> Building:
    """A 24 m x 2 m corridor with six 4 m offices on each side.

    Without an entrance the robot starts in the middle of the corridor (the largest space); with
    one it starts at the corridor's west end, a dead end, facing east.
    """
    rooms = [Room.rectangle("c", "corridor", "corridor", (0, 0, CORRIDOR_M, 2))]
    doors = [Door("e", "c", None, 0.0, 1.0, 1.2, math.pi / 2)] if entrance_at_end else []
    for i in range(int(CORRIDOR_M / ROOM_M)):
        x0 = i * ROOM_M
        rooms += [
            Room.rectangle(f"s{i}", "medium", "office", (x0, -ROOM_M, x0 + ROOM_M, 0)),
            Room.rectangle(f"n{i}", "medium", "office", (x0, 2, x0 + ROOM_M, 2 + ROOM_M)),
        ]
        doors += [Door(f"ds{i}", f"s{i}", "c", x0 + 2, 0.0), Door(f"dn{i}", f"n{i}", "c", x0 + 2, 2.0)]
    return Building("office", tuple(rooms), tuple(doors))


STARTS = {
    "middle of an empty room": (_empty_room(), (10.0, 10.0)),
    "middle of a corridor": (_corridor_offices(False), (12.0, 1.0)),
    "dead end of a corridor": (_corridor_offices(True), None),
}


@pytest.mark.parametrize("agent_name", ["frontier", "utility", "structure"])
@pytest.mark.parametrize("start", list(STARTS))
def test_explorer__covers_the_building_from_an_awkward_start(agent_name, start):
    building, where = STARTS[start]
    env = gym.make("OfficeExplore-v0", building=building, max_steps=1500, coverage_target=0.9)
    agent = make_agent(agent_name, env)
    obs, info = env.reset(seed=0)
    agent.reset(seed=0)
    if where is not None:
        assert info["start_pose"][:2] == pytest.approx(where)
    else:
        assert info["start_pose"][0] < 1.0  # just inside the entrance at the west end
    terminated = truncated = False
    while not (terminated or truncated):
        obs, _, terminated, truncated, info = env.step(agent.act(obs, info))
    assert terminated, f"{agent_name} from the {start}: {info['coverage']:.0%} after 1,500 steps"
    env.close()
