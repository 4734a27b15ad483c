import math

import gymnasium as gym
import numpy as np
from agent_helpers import drive

from realistic_indoor.agents import make_agent
from realistic_indoor.navigation.own_map import OwnMap
from realistic_indoor.sim.mapping import MAPPED_FREE, MAPPED_OCCUPIED, MAPPED_UNKNOWN
from realistic_indoor.sim.raster import RASTER_FREE, RASTER_OUTSIDE


def _to_world_cells(agent_map, env, state):
    """World raster cells (row, col) of the agent's map cells in ``state``, through the start pose."""
    world = env.unwrapped.simulation.world
    rows, cols = np.nonzero(agent_map.state == state)
    xy = agent_map.to_world(rows, cols)
    x0, y0, t0 = world.start_pose
    c, s = math.cos(t0), math.sin(t0)
    r, k = world.raster.world_to_cell(
        np.stack([x0 + c * xy[:, 0] - s * xy[:, 1], y0 + s * xy[:, 0] + c * xy[:, 1]], 1)
    )
    h, w = world.raster.shape
    inside = (r >= 0) & (r < h) & (k >= 0) & (k < w)
    return r[inside], k[inside]


def test_own_map__agrees_with_the_ground_truth(hall_office):
    env = gym.make("OfficeExplore-v0", building=hall_office, max_steps=600, max_episode_steps=600)
    agent = make_agent("frontier", env)
    _, info = drive(env, agent)
    world = env.unwrapped.simulation.world
    rows, cols = _to_world_cells(agent.map, env, MAPPED_FREE)
    inside = world.raster.grid[rows, cols] != RASTER_OUTSIDE  # the floor seen through the entrance is outside
    assert np.mean(world.raster.grid[rows, cols][inside] == RASTER_FREE) > 0.98
    cell_m2 = agent.map.resolution_m**2
    seen_m2 = np.count_nonzero(world.reachable[rows, cols]) * cell_m2
    assert abs(seen_m2 - info["observed_area_m2"]) < 0.05 * info["observed_area_m2"]
    rows, cols = _to_world_cells(agent.map, env, MAPPED_OCCUPIED)
    near_wall = world.clearance_m[rows, cols] <= agent.map.resolution_m
    assert np.mean(near_wall) > 0.95


def test_own_map__grows_as_the_robot_travels():
    offsets = np.linspace(-math.pi / 2, math.pi / 2, 31)
    m = OwnMap(offsets, max_range_m=5.0, resolution_m=0.1, grow_m=2.0)
    shape = m.state.shape
    ranges = np.full(31, 5.0)
    for x in np.arange(0.0, 40.0, 1.0):
        m.integrate((x, 0.0, 0.0), ranges)
    assert m.state.shape[1] > shape[1]
    r, c = m.to_cell(44.0, 0.0)
    assert m.state[r, c] == MAPPED_FREE
    r, c = m.to_cell(-2.0, 0.0)
    assert m.state[r, c] == MAPPED_UNKNOWN  # behind the first scan's field of view


def test_own_map__marks_the_end_of_returned_beams():
    offsets = np.array([-0.1, 0.0, 0.1])
    m = OwnMap(offsets, max_range_m=10.0)
    m.integrate((0.0, 0.0, 0.0), np.array([3.0, 3.0, 3.0]))
    r, c = m.to_cell(3.05, 0.0)
    assert m.state[r, c] == MAPPED_OCCUPIED
    r, c = m.to_cell(2.5, 0.0)
    assert m.state[r, c] == MAPPED_FREE


def test_own_map__search_sensor_sweeps_a_shorter_narrower_fan():
    offsets = np.linspace(-3 * math.pi / 4, 3 * math.pi / 4, 109)
    m = OwnMap(offsets, max_range_m=10.0, search_sensor=(3.0, math.radians(120)))
    m.integrate((0.0, 0.0, 0.0), np.full(109, 10.0))
    for (x, y), swept in (((2.0, 0.0), True), ((5.0, 0.0), False), ((0.0, 2.0), False)):
        r, c = m.to_cell(x, y)
        assert m.state[r, c] == MAPPED_FREE
        assert m.searched[r, c] == swept


def test_own_map__the_robots_footprint_is_free():
    offsets = np.linspace(-math.pi / 4, math.pi / 4, 9)  # a narrow laser: blind behind
    m = OwnMap(offsets, max_range_m=5.0)
    m.integrate((0.0, 0.0, 0.0), np.full(9, 5.0), footprint_m=0.25)
    for x, y, free in ((-0.2, 0.0, True), (0.0, -0.2, True), (-0.4, 0.0, False)):
        r, c = m.to_cell(x, y)
        assert (m.state[r, c] == MAPPED_FREE) == free
