"""Through the environment, the robot never leaves the building nor enters a wall."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from env_helpers import TEST_AREAS_M2, ToyOffice

from realistic_indoor.envs.explore import ExploreEnv

STEPS_PER_SOURCE = 20_000
"""Random control steps per building source; 100,000 over the five sources."""


SOURCES = [pytest.param({"generator": ToyOffice(n_rooms=3)}, id="toy")] + [
    pytest.param({"building_type": t, "area_m2": TEST_AREAS_M2[t]}, id=t)
    for t in ("office", "school", "house", "random")
]


def _check_episode(env: ExploreEnv, xy: np.ndarray) -> None:
    """The robot's centre stays on the floor; its disc may overlap a wall's face by at most one
    physics sub-step's travel (before pymunk pushes it back), never reaching the centre line."""
    building, robot = env.building, env.config.robot
    floor = shapely.union_all([r.polygon for r in building.rooms]).buffer(1e-6)
    inside = shapely.contains_xy(floor, xy[:, 0], xy[:, 1])
    assert inside.all(), f"robot left the building at {xy[~inside][0]}"
    walls = shapely.multilinestrings(np.asarray(building.walls))
    gap = shapely.distance(walls, shapely.points(xy)).min()
    travel = robot.max_speed_m_s / (robot.control_hz * robot.substeps)
    assert gap >= robot.radius_m + env.config.world.wall_thickness_m / 2 - travel - 1e-3
    assert gap >= robot.radius_m, f"the robot's disc reached a wall's centre line ({gap:.3f} m)"


@pytest.mark.slow
@pytest.mark.parametrize("source", SOURCES)
def test_robot__stays_on_the_floor_over_random_steps(source):
    env = ExploreEnv(max_steps=400, coverage_target=1.0, **source)
    rng = np.random.default_rng(0)
    env.reset(seed=0)
    xy = [env.simulation.robot.pose[:2]]
    collisions = 0
    for _ in range(STEPS_PER_SOURCE):
        action = rng.uniform(-1.0, 1.0, 2) if rng.random() < 0.3 else np.array([1.0, rng.uniform(-0.3, 0.3)])
        _, _, terminated, truncated, info = env.step(action)
        xy.append(env.simulation.robot.pose[:2])
        if terminated or truncated:
            collisions += info["collisions"]
            _check_episode(env, np.array(xy))
            env.reset()
            xy = [env.simulation.robot.pose[:2]]
    _check_episode(env, np.array(xy))
    assert collisions > 100  # the robot did push against walls
