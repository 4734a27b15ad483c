"""The robot's motion, the same for the compiled disc (the default) and the pymunk reference."""

import dataclasses
import math
import pickle

import numpy as np
import pytest
import shapely
from sim_buildings import corridor_office, rotated

from realistic_indoor.building.walls import door_gap
from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.disc_physics import DiscRobot, robot_in_world
from realistic_indoor.sim.robot import PHYSICS, Robot, RobotConfig
from realistic_indoor.sim.world import World


@pytest.fixture(params=PHYSICS)
def physics(request):
    return request.param


def _robot(world, physics, config=None):
    return robot_in_world(world, dataclasses.replace(config or RobotConfig(), physics=physics))


@pytest.fixture
def tiny_world(tiny_office):
    return World(tiny_office)


def _drive(robot, v, w, n):
    return [robot.step(v, w) for _ in range(n)]


def test_robot__drives_straight_at_the_speed_limit_once_accelerated(tiny_world, physics):
    robot = _robot(tiny_world, physics)
    robot.reset((1.0, 4.0, 0.0))
    first = robot.step(5.0, 0.0)
    assert robot.velocity == pytest.approx((0.4, 0.0))  # 2 m/s2 for 0.2 s
    assert 0.0 < first.distance_m < 0.4 * 0.2
    _drive(robot, 1.0, 0.0, 3)
    x0 = robot.pose[0]
    motion = robot.step(1.0, 0.0)
    assert motion.distance_m == pytest.approx(0.2) and not motion.collided
    assert robot.pose == pytest.approx((x0 + 0.2, 4.0, 0.0))


def test_robot__turns_at_the_turn_rate_limit(tiny_world, physics):
    robot = _robot(tiny_world, physics)
    robot.reset((2.5, 4.0, 0.0))
    _drive(robot, 0.0, 10.0, 5)
    assert robot.velocity == (0.0, pytest.approx(2.0))
    theta = robot.pose[2]
    robot.step(0.0, 10.0)
    assert math.remainder(robot.pose[2] - theta, math.tau) == pytest.approx(0.4)
    assert robot.pose[:2] == pytest.approx((2.5, 4.0))


def test_robot__stops_at_a_wall_and_reports_the_contact(tiny_world, physics):
    robot = _robot(tiny_world, physics)
    robot.reset((3.5, 4.0, 0.0))  # room a; the wall between a and b is at x = 5
    motions = _drive(robot, 1.0, 0.0, 20)
    assert motions[-1].collided and not motions[0].collided
    # touching: radius 0.25 m + half the wall's 0.1 m
    assert robot.pose[0] == pytest.approx(5.0 - 0.3, abs=0.01)


def test_robot__slides_along_a_wall_it_meets_at_an_angle(tiny_world, physics):
    robot = _robot(tiny_world, physics)
    robot.reset((4.2, 3.0, math.radians(30)))
    motions = _drive(robot, 1.0, 0.0, 10)
    x, y, _ = robot.pose
    assert x == pytest.approx(4.7, abs=0.01)
    # without friction the speed along the wall is kept: sin(30 deg) of the 1.8 m driven
    assert y - 3.0 == pytest.approx(0.5 * 1.8, abs=0.05)
    assert motions[-1].collided and motions[-1].distance_m == pytest.approx(0.1, abs=0.005)


def test_robot__reset_puts_it_at_rest(tiny_world, physics):
    robot = _robot(tiny_world, physics)
    _drive(robot, 1.0, 1.0, 5)
    robot.reset((2.0, 3.0, 7.0))
    assert robot.pose == pytest.approx((2.0, 3.0, 7.0 - 2 * math.pi))
    assert robot.velocity == (0.0, 0.0)
    assert robot.step(0.0, 0.0).distance_m == pytest.approx(0.0)


def test_robot__same_commands_give_the_same_path_also_after_pickling(tiny_world, rng, physics):
    a = _robot(tiny_world, physics)
    commands = rng.uniform(-1, 1, (200, 2)) * (1.0, 2.0)
    for v, w in commands[:100]:
        a.step(v, w)
    b = pickle.loads(pickle.dumps(a))
    for v, w in commands[100:]:
        ma, mb = a.step(v, w), b.step(v, w)
        assert ma == mb
    assert a.pose == b.pose


@pytest.mark.parametrize(
    "kwargs",
    [
        {"radius_m": 0.0},
        {"max_speed_m_s": -1.0},
        {"control_hz": 0.0},
        {"substeps": 0},
        {"max_accel_m_s2": math.inf},
        {"max_speed_m_s": 3.0, "substeps": 2},  # 0.3 m per sub-step: could tunnel through walls
        {"physics": "box2d"},
    ],
)
def test_robot_config__bad_values_raise_config_error(kwargs):
    with pytest.raises(ConfigError, match="RobotConfig"):
        RobotConfig(**kwargs)


def test_robot_in_world__builds_the_physics_the_config_names(tiny_world):
    assert isinstance(robot_in_world(tiny_world), DiscRobot)  # the default
    assert isinstance(robot_in_world(tiny_world, RobotConfig(physics="pymunk")), Robot)
    assert robot_in_world(tiny_world).pose == tiny_world.start_pose


def _random_valid_position(world, rng, clearance):
    free = np.argwhere(world.clearance_m >= clearance)
    return world.raster.cell_to_world(*free[rng.integers(len(free))])


def _safety_run(world, rng, n_steps, config, physics):
    """Random driving (commands held a few steps, random restarts); poses after every step."""
    robot = _robot(world, physics, config)
    poses = np.empty((n_steps, 2))
    v = w = 0.0
    for i in range(n_steps):
        if i % 300 == 0:
            x, y = _random_valid_position(world, rng, config.radius_m + 0.05)
            robot.reset((x, y, rng.uniform(-math.pi, math.pi)))
        if i % 4 == 0:
            v = rng.uniform(-0.3, 1.0) * config.max_speed_m_s
            w = rng.uniform(-1.0, 1.0) * config.max_turn_rate_rad_s
        robot.step(v, w)
        poses[i] = robot.pose[:2]
    return poses


def _generated_office(request):
    from realistic_indoor.generator import generate

    return generate("office", area_m2=800, seed=3)


def _real_school(request):
    from realistic_indoor.io import load

    return load(request.getfixturevalue("real_plans_dir") / "school" / "Vipiteno2_updated.xml")


SAFETY_BUILDINGS = {
    "corridor office": lambda request: corridor_office(4, 2),
    "rotated office": lambda request: rotated(corridor_office(3, 2), math.radians(23), (1.0, 2.0)),
    "real school": _real_school,
    "generated office": _generated_office,
}


@pytest.mark.parametrize("name", SAFETY_BUILDINGS)
@pytest.mark.parametrize(
    "config", [RobotConfig(), RobotConfig(max_speed_m_s=2.0, substeps=5)], ids=["default", "fast"]
)
def test_robot__never_leaves_the_building_nor_enters_a_wall(name, config, rng, request, physics):
    building = SAFETY_BUILDINGS[name](request)
    poses = _safety_run(World(building), rng, 8000, config, physics)
    walls = shapely.MultiLineString([list(map(tuple, s)) for s in building.walls])
    floor = shapely.union_all([r.polygon for r in building.rooms] + [door_gap(d) for d in building.doors])
    floor = floor.buffer(1e-6)
    points = shapely.points(poses)
    # a wall is touched at radius + half its thickness (0.3 m); on first contact the robot may
    # overlap it by one sub-step's travel, for that sub-step, before pymunk pushes it back
    travel = config.max_speed_m_s / (config.control_hz * config.substeps)
    assert shapely.distance(points, walls).min() >= config.radius_m + 0.05 - travel - 1e-3
    if travel <= 0.05:
        assert shapely.distance(points, walls).min() >= config.radius_m
    assert shapely.contains(floor, points).all()
    interior = shapely.union_all([r.polygon for r in building.rooms]).buffer(1e-6)
    assert shapely.contains(interior, points).all()  # not even into an entrance's doorway outside
    assert np.ptp(poses, axis=0).min() > 5.0  # the runs did go places
