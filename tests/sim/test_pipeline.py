import numpy as np
import pytest

from realistic_indoor.sim import Lidar, Robot, RobotMap, VictimSensor, World, place_victims


def _episode(building, seed):
    rng = np.random.default_rng(seed)
    world = World(building)
    robot, lidar, robot_map = Robot.in_world(world), Lidar(), RobotMap(world)
    victims = place_victims(world, rng)
    sensor = VictimSensor()
    found = np.zeros(len(victims), dtype=bool)
    rewards, ranges = [], []
    for _ in range(300):
        robot.step(rng.uniform(0.0, 1.0), rng.uniform(-2.0, 2.0))
        scan = lidar.scan(world.raycaster, robot.pose, rng)
        rewards.append(robot_map.update(scan))
        ranges.append(scan.ranges_m)
        found |= sensor.in_view(world.raycaster, robot.pose, victims)
    return robot.pose, np.array(rewards), np.concatenate(ranges), robot_map.grid.copy(), victims, found


def test_simulation__same_seed_same_episode_byte_for_byte(office):
    a, b = _episode(office, 11), _episode(office, 11)
    assert a[0] == b[0]
    for x, y in zip(a[1:], b[1:], strict=True):
        assert x.tobytes() == y.tobytes()
    c = _episode(office, 12)
    assert c[2].tobytes() != a[2].tobytes()


def test_simulation__rewards_add_up_to_the_observed_area(office):
    _, rewards, _, grid, _, _ = _episode(office, 3)
    assert rewards.sum() > 10.0
    world = World(office)
    observed = np.count_nonzero((grid == 1) & world.reachable) * world.raster.cell_area_m2
    assert rewards.sum() == pytest.approx(observed)
