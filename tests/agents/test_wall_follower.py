"""The wall follower finds a wall from wherever it starts, then keeps to it."""

from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest

from realistic_indoor.agents import make_agent
from realistic_indoor.building import Building, Room

SIDE_M = 20.0


def _empty_room() -> Building:
    """A 20 m x 20 m room without doors: the robot starts in its middle, 10 m from every wall."""
    return Building("office", (Room.rectangle("r", "big", "open space", (0, 0, SIDE_M, SIDE_M)),))


def _positions(env, agent, steps: int) -> np.ndarray:
    """Where the robot is at each step; it drives on after the room is seen whole."""
    obs, info = env.reset(seed=0)
    agent.reset(seed=0)
    xy = [env.unwrapped.simulation.robot.pose[:2]]
    for _ in range(steps):
        obs, _, _, _, info = env.step(agent.act(obs, info))
        xy.append(env.unwrapped.simulation.robot.pose[:2])  # on past the episode's end: seen all
    return np.array(xy)


@pytest.mark.parametrize("side", ["right", "left"])
def test_wall_follower__reaches_a_wall_from_the_middle_of_an_empty_room_then_goes_round(side):
    env = gym.make("OfficeExplore-v0", building=_empty_room(), max_steps=2000, coverage_target=1.0)
    agent = make_agent("wall", env, side=side)
    xy = _positions(env, agent, 1200)
    assert np.allclose(xy[0], SIDE_M / 2)  # the start: the middle, 10 m from every wall
    to_wall = np.minimum.reduce([xy[:, 0], xy[:, 1], SIDE_M - xy[:, 0], SIDE_M - xy[:, 1]])
    reached = int(np.argmax(to_wall < 1.0))
    assert to_wall[reached] < 1.0, "never came within 1 m of a wall"
    assert reached < 250  # 50 s for 10 m at 0.8 m/s (13 s) and turning to face a wall
    after = xy[reached:]
    # then it goes round: it passes within 1 m of each of the four walls, never straying inside
    for near_wall in (
        after[:, 0] < 1.2,
        after[:, 1] < 1.2,
        after[:, 0] > SIDE_M - 1.2,
        after[:, 1] > SIDE_M - 1.2,
    ):
        assert near_wall.any()
    assert (
        np.minimum.reduce([after[:, 0], after[:, 1], SIDE_M - after[:, 0], SIDE_M - after[:, 1]]) < 2.0
    ).all()
    env.close()
