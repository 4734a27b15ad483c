"""Simulation: a batch of one that steps as its parts composed by hand; victims found as sensed."""

from __future__ import annotations

import copy
import pickle
from dataclasses import replace

import numpy as np
import pytest

from realistic_indoor.building import Building, Room
from realistic_indoor.envs.config import EnvConfig
from realistic_indoor.envs.simulation import Simulation
from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.disc_physics import DiscRobot
from realistic_indoor.sim.lidar import Lidar
from realistic_indoor.sim.mapping import RobotMap
from realistic_indoor.sim.victims import VictimConfig, place_victims

RANGE_M = 3.0
VICTIMS = VictimConfig(n_victims=3, sensor_range_m=RANGE_M)


@pytest.fixture
def hall() -> Building:
    """One 10 m x 4 m room and no door: the robot starts at its centre (5, 2), heading +x."""
    room = Room.rectangle("r", "medium", "office", (0.0, 0.0, 10.0, 4.0))
    return Building("office", (room,), (), {"generator": "hand-made"})


def _sim(building: Building, victims: bool = True) -> Simulation:
    config = EnvConfig(victims=VICTIMS)
    sim = Simulation(config, victims=victims)
    sim.load(building)
    return sim


def test_step__reports_the_victim_the_sensor_comes_to_see(hall):
    sim = _sim(hall)
    rng = np.random.default_rng(0)
    assert sim.world.start_pose == pytest.approx((5.0, 2.0, 0.0))
    # 2.5 m ahead (in view from the start), 4.5 m ahead (in view once within 3 m), 4 m behind
    ahead, far, behind = (7.5, 2.0), (9.5, 2.0), (1.0, 2.0)
    sim.reset(rng, victims_xy=np.array([ahead, far, behind]))
    assert sim.victims.found.tolist() == [True, False, False]
    assert sim.victims.in_view.tolist() == [True, False, False]

    reported = [sim.step(1.0, 0.0, rng).victims_found for _ in range(10)]

    xs = [x for x, _ in sim.trajectory[1:]]
    first_near = next(k for k, x in enumerate(xs) if far[0] - x <= RANGE_M)  # straight ahead
    assert reported == [int(k == first_near) for k in range(10)]
    assert sim.victims.found.tolist() == [True, True, False]
    assert sim.victims.in_view.tolist() == [True, True, False]


def test_step__without_victims_senses_none(hall):
    sim = _sim(hall, victims=False)
    rng = np.random.default_rng(0)
    sim.reset(rng)
    outcome = sim.step(1.0, 0.0, rng)
    assert sim.victims is None and outcome.victims_found is None
    with pytest.raises(ConfigError, match="without victims"):
        sim.reset(rng, victims_xy=np.zeros((3, 2)))


def test_reset__draws_victims_after_the_first_scan(hall):
    """Placement draws from the generator after the first scan's noise (the recorded order)."""
    sim, rng = _sim(hall), np.random.default_rng(3)
    sim.reset(rng)
    explore, rng_explore = _sim(hall, victims=False), np.random.default_rng(3)
    explore.reset(rng_explore)
    assert np.array_equal(sim.scan.ranges_m, explore.scan.ranges_m)
    assert np.array_equal(sim.victims.xy, place_victims(explore.world, rng_explore, VICTIMS))
    assert rng.random() == rng_explore.random()


def _by_hand(world, config):
    """The single robot's parts composed one after the other: robot, laser, map, local view."""
    robot = DiscRobot.in_world(world, config.robot)
    return robot, Lidar(config.lidar), RobotMap(world, config.local_map)


COMMANDS = [(0.6, 0.0)] * 30 + [(0.3, 1.0)] * 15 + [(0.6, -0.4)] * 40 + [(-0.2, 0.0)] * 5


def _episode_by_hand(sim, config, rng, rng_hand):
    """Reset ``sim`` and drive it; the parts composed by hand do the same: compare every step."""
    robot, lidar, robot_map = _by_hand(sim.world, config)
    sim.reset(rng)
    robot.reset(sim.world.start_pose)
    scan = lidar.scan(sim.world.raycaster, robot.pose, rng_hand)
    robot_map.update(scan)
    assert np.array_equal(sim.map.grid, robot_map.grid) and sim.map.coverage == robot_map.coverage
    view, view_hand = np.empty((64, 64), np.uint8), np.empty((64, 64), np.uint8)
    for v, w in COMMANDS:
        outcome = sim.step(v, w, rng)
        motion = robot.step(v, w)
        scan = lidar.scan(sim.world.raycaster, robot.pose, rng_hand)
        new_m2 = robot_map.update(scan)
        assert sim.robot.pose == robot.pose and sim.robot.velocity == robot.velocity
        assert (outcome.collided, outcome.new_area_m2) == (motion.collided, new_m2)
        assert np.array_equal(sim.scan.ranges_m, scan.ranges_m)
        assert np.array_equal(sim.scan.true.range_m, scan.true.range_m)
        assert np.array_equal(sim.scan.returned, scan.returned)
        assert np.array_equal(sim.map.grid, robot_map.grid) and sim.map.coverage == robot_map.coverage
        sim.local_view(view)
        assert np.array_equal(view, robot_map.local_view(robot.pose, out=view_hand))
    assert rng.random() == rng_hand.random()  # the same noise draws, in the same order


@pytest.mark.parametrize("noise_m", [0.0, 0.02])
def test_batch_of_one__steps_as_the_robot_laser_and_map_composed_by_hand(toy_building, hall, noise_m):
    """The compiled physics runs on a batch of one; it must do exactly what the classes do.

    Two buildings in turn, then the second again (a reset only) and the first again: the batch's
    arrays and the views on them follow each new building.
    """
    config = EnvConfig().replace(lidar=replace(EnvConfig().lidar, noise_std_m=noise_m))
    sim = Simulation(config)
    rng, rng_hand = np.random.default_rng(5), np.random.default_rng(5)
    for building in (toy_building, hall, hall, toy_building):
        new = building is not sim.building
        sim.load(building)
        assert sim.batch is not None and sim.batch.n == 1
        if new:  # loading puts the robot at rest at the start, as a new robot would be
            assert sim.robot.pose == sim.world.start_pose and sim.robot.velocity == (0.0, 0.0)
        _episode_by_hand(sim, config, rng, rng_hand)
    assert sim.collisions > 0  # the drive met a wall: contacts were compared too


def test_batch_of_one__robot_and_map_are_views_of_the_batch(hall):
    sim = _sim(hall, victims=False)
    sim.reset(np.random.default_rng(0))
    sim.robot.reset((3.0, 2.0, 0.5))  # the robot's state is the batch's row
    assert tuple(sim.batch.phys[0, :3]) == (3.0, 2.0, 0.5)
    sim.step(0.5, 0.0, np.random.default_rng(0))
    assert np.shares_memory(sim.map.grid, sim.batch.grids[0])
    reachable = np.count_nonzero(sim.world.reachable)
    assert sim.map.coverage == sim.batch.observed[0] / reachable > 0


def test_batch_of_one__a_copy_steps_on_its_own_batch(hall):
    sim = _sim(hall, victims=False)
    rng = np.random.default_rng(0)
    sim.reset(rng)
    for copied in (copy.deepcopy(sim), pickle.loads(pickle.dumps(sim))):
        before = sim.map.coverage
        copied.step(0.6, 1.0, np.random.default_rng(1))
        copied.step(0.6, 1.0, np.random.default_rng(1))
        assert copied.map.coverage > before == sim.map.coverage  # the original did not move
        assert np.shares_memory(copied.map.grid, copied.batch.grids[0])
        assert copied.robot.pose == tuple(copied.batch.phys[0, :3]) != sim.robot.pose


def test_pymunk_physics__follows_the_batch_of_one_within_the_physics_tolerance(toy_building):
    """pymunk runs the classes in turn; the compiled physics is held to it (tests/sim/test_disc_physics.py)."""
    pymunk = Simulation(EnvConfig().replace(robot=replace(EnvConfig().robot, physics="pymunk")))
    compiled = Simulation(EnvConfig())
    for sim in (pymunk, compiled):
        sim.load(toy_building)
        sim.reset(np.random.default_rng(0))
    assert pymunk.batch is None
    for v, w in COMMANDS[:60]:
        pymunk.step(v, w, np.random.default_rng(0))
        compiled.step(v, w, np.random.default_rng(0))
    assert np.hypot(*np.subtract(pymunk.robot.pose[:2], compiled.robot.pose[:2])) < 0.05
    assert pymunk.map.coverage == pytest.approx(compiled.map.coverage, abs=0.02) and pymunk.map.coverage > 0.1
    with pytest.raises(ConfigError, match="C-contiguous"):
        compiled.local_view(np.empty((32, 32), np.uint8))
