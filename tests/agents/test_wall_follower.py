"""The wall follower finds a wall from wherever it starts, then keeps to it."""

from __future__ import annotations

import math

import gymnasium as gym
import numpy as np
import pytest
from agent_helpers import empty_room, vestibule

from realistic_indoor.agents import make_agent
from realistic_indoor.building import Building, Door, Room

SIDE_M = 20.0


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
    env = gym.make("OfficeExplore-v0", building=empty_room(SIDE_M), max_steps=2000, coverage_target=1.0)
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


@pytest.mark.parametrize("side", ["right", "left"])
def test_wall_follower__leaves_a_small_entrance_room_by_its_door_by_a_corner(side):
    env = gym.make("OfficeExplore-v0", building=vestibule(), max_steps=2000, coverage_target=1.0)
    agent = make_agent("wall", env, side=side)
    xy = _positions(env, agent, 600)
    assert 0.0 < xy[0, 1] < 1.0  # the start: just inside the entrance
    # by hand: a lap of the vestibule is about 10 m at 0.8 m/s and four quarter turns (under
    # 100 steps); the robot is through the door into the large room within four laps
    inside = np.flatnonzero(xy[:, 1] > 4.0 + 0.25 + 0.5)
    assert len(inside) and inside[0] < 400, "never went through the door into the large room"
    assert np.abs(xy - xy[0]).max() > 5.0  # it leaves a 5 m box around its start
    env.close()


def _hall_with_wide_entrances(width_m: float) -> Building:
    """An 8 m x 8 m hall with two entrances ``width_m`` wide: in its east and its north wall."""
    hall = Room.rectangle("h", "hall", "lobby", (0.0, 0.0, 8.0, 8.0))
    doors = (
        Door("east", "h", None, 8.0, 2.0, width_m, math.pi / 2),
        Door("north", "h", None, 4.0, 8.0, width_m, 0.0),
    )
    return Building("office", (hall,), doors)


@pytest.mark.parametrize("side", ["right", "left"])
@pytest.mark.parametrize("width_m", [2.0, 3.0])
def test_wall_follower__goes_on_round_a_hall_past_its_wide_entrances(side, width_m):
    # the laser sees nothing through an entrance, the robot is stopped by a line it cannot see:
    # it must turn away from that line and go on round the hall, not push against it
    env = gym.make("OfficeExplore-v0", building=_hall_with_wide_entrances(width_m), max_steps=3000)
    agent = make_agent("wall", env, side=side)
    xy = _positions(env, agent, 2000)
    last = xy[-500:]  # 500 steps (100 s) are more than a lap of the hall's walls (about 22 m)
    assert (last.max(axis=0) - last.min(axis=0) > 5.0).all()
    env.close()
