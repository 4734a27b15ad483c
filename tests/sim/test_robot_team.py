"""Robots of one building collide with each other: the compiled group against pymunk's team."""

from __future__ import annotations

import math

import numpy as np
import pytest

from realistic_indoor.generator import make_generator
from realistic_indoor.sim import World
from realistic_indoor.sim.disc_physics import STATE_SIZE, THETA, X, Y, drive_group, drive_params, segment_grid
from realistic_indoor.sim.robot import RobotConfig, RobotTeam

FAR_WALL = np.array([[[-100.0, -100.0], [100.0, -100.0]]])
"""One wall far from the robots: open floor."""
CONTACT_TOLERANCE_M = 0.01
"""How far two discs pressed together may sit from touching (m): pymunk's slop (2 mm) and the
overlap one sub-step's travel leaves before the bias pushes them apart."""
TEAM_TOLERANCE_M = 0.05
"""Largest position difference between the compiled team and pymunk's over the drive (m)."""


class CompiledTeam:
    """The robots of one building moved by :func:`drive_group`, as pymunk's :class:`RobotTeam` is."""

    def __init__(self, segments, config, wall_thickness_m, poses):
        self.params = drive_params(config, wall_thickness_m)
        self.grid = segment_grid(segments, self.params[0])
        self.phys = np.zeros((len(poses), STATE_SIZE))
        for k, (x, y, theta) in enumerate(poses):
            self.phys[k, [X, Y, THETA]] = (x, y, theta)

    def step(self, commands):
        g = self.grid
        robots = np.arange(len(self.phys), dtype=np.int64)
        touched, _ = drive_group(
            self.phys,
            robots,
            np.asarray(commands, float),
            g.segments,
            g.start,
            g.items,
            g.origin,
            self.params,
        )
        return touched

    @property
    def xy(self):
        return self.phys[:, [X, Y]].copy()


def _both(segments, poses, config=None, wall_thickness_m=0.1):
    config = config or RobotConfig()
    return RobotTeam(segments, config, wall_thickness_m, poses), CompiledTeam(
        segments, config, wall_thickness_m, poses
    )


def _gap(xy):
    return float(np.hypot(*(xy[0] - xy[1])))


def test_two_robots_driven_into_each_other__stop_at_contact_distance():
    """Head on at full speed for 4 s: the centres end two radii apart (0.5 m), in both physics."""
    poses = [(-2.0, 0.0, 0.0), (2.0, 0.0, math.pi)]
    reference, compiled = _both(FAR_WALL, poses)
    for _ in range(20):
        motions = reference.step([(1.0, 0.0), (1.0, 0.0)])
        touched = compiled.step([(1.0, 0.0), (1.0, 0.0)])
    pymunk_xy = np.array([p[:2] for p in reference.poses])
    assert _gap(pymunk_xy) == pytest.approx(0.5, abs=CONTACT_TOLERANCE_M)
    assert _gap(compiled.xy) == pytest.approx(0.5, abs=CONTACT_TOLERANCE_M)
    assert all(m.collided for m in motions) and touched.all()
    assert np.abs(compiled.xy[:, 0]).max() == pytest.approx(0.25, abs=CONTACT_TOLERANCE_M)  # symmetric


def test_a_robot_pushing_a_stopped_one__moves_it_at_half_speed():
    """Equal masses: each sub-step the contact splits the closing speed between the two."""
    poses = [(0.0, 0.0, 0.0), (0.5, 0.0, 0.0)]
    reference, compiled = _both(FAR_WALL, poses)
    for _ in range(15):  # reach full speed (1 m/s after 0.5 s), then push
        reference.step([(1.0, 0.0), (0.0, 0.0)])
        compiled.step([(1.0, 0.0), (0.0, 0.0)])
    before = compiled.xy[1, 0]
    pymunk_before = reference.poses[1][0]
    for _ in range(10):  # 2 s
        reference.step([(1.0, 0.0), (0.0, 0.0)])
        compiled.step([(1.0, 0.0), (0.0, 0.0)])
    assert compiled.xy[1, 0] - before == pytest.approx(1.0, abs=0.05)  # 0.5 m/s for 2 s
    assert reference.poses[1][0] - pymunk_before == pytest.approx(1.0, abs=0.05)


def test_robots_apart__move_exactly_as_each_would_alone():
    poses = [(0.0, 0.0, 0.0), (10.0, 0.0, 1.0)]
    config = RobotConfig()
    _, team = _both(FAR_WALL, poses, config)
    alone = [CompiledTeam(FAR_WALL, config, 0.1, [p]) for p in poses]
    rng = np.random.default_rng(0)
    for _ in range(50):
        commands = rng.uniform(-1, 1, (2, 2))
        team.step(commands)
        for k in range(2):
            alone[k].step(commands[k : k + 1])
    assert np.array_equal(team.phys, np.concatenate([a.phys for a in alone]))


@pytest.mark.parametrize("seed", [0, 1])
def test_compiled_team__follows_pymunk_in_a_building(seed):
    """Three robots from the entrance with random commands: walls and each other, both physics."""
    building = make_generator("random", area_m2=400.0)(np.random.default_rng(seed))
    world = World(building)
    x, y, theta = world.start_pose
    side = np.array([-math.sin(theta), math.cos(theta)])
    ahead = np.array([math.cos(theta), math.sin(theta)])
    poses = [(x, y, theta)] + [
        (*(np.array([x, y]) + 0.6 * ahead + d * 0.6 * side), theta) for d in (-0.5, 0.5)
    ]
    poses = [p for p in poses if world.is_clear(p[:2], 0.3)]
    reference, compiled = _both(world.collision_segments, poses)
    rng = np.random.default_rng(seed)
    worst, robot_contacts = 0.0, 0
    for t in range(300):
        if t % 4 == 0:
            commands = [(1.0 if t % 20 else -1.0, w) for w in rng.uniform(-2.0, 2.0, len(poses))]
        reference.step(commands)
        compiled.step(commands)
        pymunk_xy = np.array([p[:2] for p in reference.poses])
        worst = max(worst, float(np.hypot(*(pymunk_xy - compiled.xy).T).max()))
        gaps = [_gap(compiled.xy[[a, b]]) for a in range(len(poses)) for b in range(a + 1, len(poses))]
        robot_contacts += min(gaps) < 0.51
    assert worst < TEAM_TOLERANCE_M
    assert robot_contacts > 10
