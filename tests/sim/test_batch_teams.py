"""Several robots in one building slot of a batch: shared, own and team maps."""

from __future__ import annotations

import numpy as np
import pytest

from realistic_indoor.errors import ConfigError
from realistic_indoor.generator import make_generator
from realistic_indoor.sim import World
from realistic_indoor.sim.batch import STEP, Batch, StepOutputs, step_batch_serial, step_constants
from realistic_indoor.sim.lidar import LidarConfig
from realistic_indoor.sim.mapping import MAPPED_UNKNOWN, LocalMapConfig
from realistic_indoor.sim.robot import RobotConfig
from realistic_indoor.sim.world import WorldConfig

LIDAR = LidarConfig(noise_std_m=0.0)


@pytest.fixture(scope="module")
def world():
    return World(make_generator("office", area_m2=600.0)(np.random.default_rng(3)))


def _team_batch(world, robot_map, map_scans):
    batch = Batch(2, robot_building=np.zeros(2, np.int64), robot_map=robot_map, map_scans=map_scans)
    constants = step_constants(RobotConfig(), WorldConfig(), LIDAR, LocalMapConfig())
    batch.load(0, world, constants.params[0], int(constants.local[0]))
    x, y, theta = world.start_pose
    batch.place(0, (x, y, theta))
    batch.place(1, (x, y, theta + np.pi))  # back to back: they see different floor
    return batch, constants


def _run(batch, constants, steps=40):
    out = StepOutputs.zeros(2, LIDAR.n_beams, 64)
    noise = np.zeros((2, LIDAR.n_beams))
    commands = np.array([[0.6, 0.3], [0.6, -0.4]])
    new_area = np.zeros(2)
    for t in range(steps):
        mode = np.full(2, 2 if t == 0 else STEP, dtype=np.int64)  # RESET (first scan), then steps
        batch.step(step_batch_serial, mode, commands, noise, constants, out)
        new_area += out.terms[:, 0]
    return new_area


def test_a_shared_map__is_the_union_of_the_two_robots_own_maps(world):
    shared, constants = _team_batch(world, [0, 0], [[0, 1]])
    own, _ = _team_batch(world, [0, 1], [[0], [1], [0, 1]])  # own maps, then a team map of both scans
    shared_area = _run(shared, constants)
    own_area = _run(own, constants)
    assert np.array_equal(shared.phys, own.phys)  # the maps do not change the motion
    union = np.maximum(own.grids[0], own.grids[1])  # free 1 and wall 2 never meet in one cell
    assert np.array_equal(shared.grids[0], union)
    assert np.array_equal(own.grids[2], union)
    assert shared.observed[0] == own.observed[2] < own.observed[0] + own.observed[1]  # they overlap
    cell_m2 = world.raster.resolution_m**2
    assert shared_area.sum() == pytest.approx(shared.observed[0] * cell_m2)  # each new cell credited once
    assert own_area == pytest.approx(own.observed[:2] * cell_m2)


def test_robots_of_one_map__see_the_same_cells(world):
    shared, constants = _team_batch(world, [0, 0], [[0, 1]])
    _run(shared, constants, steps=5)
    assert (shared.grids[0] != MAPPED_UNKNOWN).any()


@pytest.mark.parametrize(
    ("robot_building", "robot_map", "map_scans"),
    [
        ([0, 1], [0, 0], [[0, 1]]),  # one map across two buildings
        ([0, 0], [0, 1], [[0], [0]]),  # robot 1's map does not take its scans
        ([0, 0], [0, 2], [[0], [1]]),  # no map 2
    ],
)
def test_batch__refuses_an_inconsistent_layout(robot_building, robot_map, map_scans):
    with pytest.raises(ConfigError):
        Batch(2, robot_building=np.array(robot_building), robot_map=np.array(robot_map), map_scans=map_scans)


def test_merging_two_maps__gives_their_union_and_counts_the_new_floor_once(world):
    own, constants = _team_batch(world, [0, 1], [[0], [1], [0, 1]])
    _run(own, constants)
    union, observed = np.maximum(own.grids[0], own.grids[1]), own.observed[2]
    before = int(own.observed[0])
    new = own.merge_map(0, 1)
    assert np.array_equal(own.grids[0], union)
    assert own.observed[0] == observed == before + new
    assert own.merge_map(0, 1) == 0  # nothing left to add
    own.copy_map(1, 0)
    assert np.array_equal(own.grids[1], union) and own.observed[1] == observed
