"""The compiled disc robot against the pymunk robot (the reference): same commands, same path."""

from __future__ import annotations

import math

import numpy as np
import pytest
from sim_buildings import corridor_office

from realistic_indoor.generator import make_generator
from realistic_indoor.sim import Robot, World
from realistic_indoor.sim.disc_physics import DiscRobot, segment_grid
from realistic_indoor.sim.robot import RobotConfig

STEPS = 1000
EXACT_M = 1e-9
"""Paths agree to this while the robot touches at most one wall at a time (m)."""
TOLERANCE_M = 0.05
"""Largest position difference allowed over :data:`STEPS` steps (m): where the robot touches
two walls at once, the solvers visit the contacts in different orders."""
MEDIAN_TOLERANCE_M = 0.005
"""Median position difference allowed over the same steps (m)."""


def _commands(seed: int, n: int) -> list[tuple[float, float]]:
    """Random commands held four steps, full speed ahead every tenth: many wall contacts."""
    rng = np.random.default_rng(seed)
    out = []
    for t in range(n):
        if t % 4 == 0:
            v, w = rng.uniform(-1.0, 1.0), rng.uniform(-2.0, 2.0)
        out.append((1.0 if t % 10 == 0 else v, w))
    return out


def _both(world: World, config: RobotConfig | None = None) -> tuple[Robot, DiscRobot]:
    pymunk_robot = Robot.in_world(world, config)
    disc = DiscRobot(world.collision_segments, config, world.config.wall_thickness_m, world.start_pose)
    return pymunk_robot, disc


def _drive(world: World, seed: int, config: RobotConfig | None = None) -> tuple[np.ndarray, float]:
    """Position differences per step (m) and the share of steps whose contact flags agree."""
    reference, disc = _both(world, config)
    errors, same = [], 0
    for v, w in _commands(seed, STEPS):
        a, b = reference.step(v, w), disc.step(v, w)
        same += a.collided == b.collided
        assert math.isclose(a.distance_m, b.distance_m, abs_tol=TOLERANCE_M)
        errors.append(math.dist(reference.pose[:2], disc.pose[:2]))
        assert abs(math.remainder(reference.pose[2] - disc.pose[2], math.tau)) < 1e-9
        assert reference.velocity == pytest.approx(disc.velocity, abs=1e-12)
    return np.array(errors), same / STEPS


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_disc_robot__follows_the_pymunk_robot_in_a_generated_building(seed):
    building = make_generator("random", area_m2=1000.0)(np.random.default_rng(seed))
    errors, agree = _drive(World(building), seed)
    assert errors.max() < TOLERANCE_M
    assert np.median(errors) < MEDIAN_TOLERANCE_M
    assert agree >= 0.99


def test_disc_robot__follows_the_pymunk_robot_exactly_against_one_wall():
    wall = np.array([[[-100.0, 0.0], [100.0, 0.0]]])
    reference, disc = Robot(wall, pose=(0.0, 1.0, -1.0)), DiscRobot(wall, pose=(0.0, 1.0, -1.0))
    contacts = 0
    for t, (v, w) in enumerate(_commands(5, 600)):
        w = -1.0 if t % 50 < 5 else w  # turn back to the wall now and then
        a, b = reference.step(v, w), disc.step(v, w)
        assert a.collided == b.collided
        contacts += a.collided
        assert math.dist(reference.pose[:2], disc.pose[:2]) < EXACT_M
    assert contacts > 20


def test_disc_robot__follows_the_pymunk_robot_with_other_limits(office):
    config = RobotConfig(radius_m=0.3, max_speed_m_s=1.5, max_accel_m_s2=1.0, substeps=6)
    errors, agree = _drive(World(office), 3, config)
    assert errors.max() < TOLERANCE_M and agree >= 0.99


def test_disc_robot__reset_puts_it_at_rest(office):
    world = World(office)
    _, disc = _both(world)
    for _ in range(10):
        disc.step(1.0, 1.0)
    disc.reset((3.0, 4.0, 7.0))
    assert disc.pose == pytest.approx((3.0, 4.0, math.remainder(7.0, math.tau)))
    assert disc.velocity == (0.0, 0.0)
    assert disc.step(0.0, 0.0).distance_m == 0.0


def test_disc_robot__never_leaves_the_building_nor_enters_a_wall():
    building = corridor_office(n_rooms=3)
    world = World(building)
    _, disc = _both(world)
    segments = world.collision_segments.reshape(-1, 4)
    rng = np.random.default_rng(9)
    for _ in range(3000):
        disc.step(rng.uniform(-1, 1), rng.uniform(-2, 2))
        assert _nearest_segment_m(disc.pose[:2], segments) >= 0.25
        assert world.clearance_at(disc.pose[:2]) > 0


def test_segment_grid__lists_every_segment_a_disc_can_touch():
    rng = np.random.default_rng(0)
    segments = rng.uniform(0, 20, (40, 2, 2))
    grid = segment_grid(segments, 0.3)
    x0, y0, side, nx, _ = grid.origin
    flat = segments.reshape(-1, 4)
    for p in rng.uniform(-1, 21, (2000, 2)):
        k = int((p[1] - y0) // side) * int(nx) + int((p[0] - x0) // side)
        listed = set(grid.items[grid.start[k] : grid.start[k + 1]].tolist())
        near = {i for i in range(len(flat)) if _nearest_segment_m(p, flat[i : i + 1]) < 0.3}
        assert near <= listed


def _nearest_segment_m(p, segments: np.ndarray) -> float:
    a, b = segments[:, :2], segments[:, 2:]
    d = b - a
    t = np.clip(np.einsum("ij,ij->i", np.asarray(p) - a, d) / np.einsum("ij,ij->i", d, d), 0, 1)
    return float(np.min(np.hypot(*(a + t[:, None] * d - p).T)))


def test_wrap_angle__equals_math_remainder_to_the_bit_over_three_half_turns_either_way():
    import math

    from realistic_indoor.sim.disc_physics import wrap_angle

    rng = np.random.default_rng(0)
    edges = [math.pi, 2 * math.pi, 3 * math.pi, math.pi / 2, 0.0, 1e-300]
    edges += [np.nextafter(e, big) for e in edges for big in (-np.inf, np.inf)]
    values = np.concatenate([rng.uniform(-3 * math.pi, 3 * math.pi, 20_000), edges, np.negative(edges)])
    expected = np.array([math.remainder(v, math.tau) for v in values])
    assert np.array_equal(wrap_angle(values), expected)  # the array form
    assert all(wrap_angle(float(v)) == e for v, e in zip(values[:500], expected[:500], strict=True))
    assert np.all(np.abs(expected) <= math.pi)
