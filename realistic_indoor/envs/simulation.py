"""One robot in one building: the simulator's parts wired together for an environment."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, NamedTuple

from realistic_indoor.sim.lidar import Lidar, Scan
from realistic_indoor.sim.mapping import RobotMap
from realistic_indoor.sim.robot import Robot
from realistic_indoor.sim.world import World

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.building.building import Building
    from realistic_indoor.envs.config import EnvConfig

__all__ = ["Simulation", "StepOutcome"]


class StepOutcome(NamedTuple):
    """What one control step did.

    Attributes:
        collided: Whether the robot touched a wall.
        new_area_m2: Reachable floor observed for the first time (m2).
    """

    collided: bool
    new_area_m2: float


class Simulation:
    """The world, robot, laser and map of an episode, and the episode's running totals.

    The world, robot and map are built once per building and reused while the building stays
    the same (a fixed building resets in microseconds; a new one costs a rasterization).

    Args:
        config: The environment's configuration.

    Attributes:
        lidar: The laser scanner.
        world: The current world (``None`` before the first :meth:`reset`).
        robot: The robot in it.
        map: The robot's map.
        scan: The latest scan.
        path_length_m: Distance driven this episode (m).
        collisions: Control steps with a wall contact this episode.
        trajectory: Positions ``(x, y)`` at the start and after each step (m).
    """

    def __init__(self, config: EnvConfig) -> None:
        self.config = config
        self.lidar = Lidar(config.lidar)
        self.world: World | None = None
        self.robot: Robot
        self.map: RobotMap
        self.scan: Scan
        self.path_length_m = 0.0
        self.collisions = 0
        self.trajectory: list[tuple[float, float]] = []

    @property
    def building(self) -> Building | None:
        """The building of the current world."""
        return None if self.world is None else self.world.building

    @property
    def nbytes(self) -> int:
        """Memory held by the world's and the map's arrays (bytes)."""
        return 0 if self.world is None else self.world.nbytes + self.map.nbytes

    def load(self, building: Building) -> None:
        """Make ``building`` the current world (kept if it already is)."""
        if building is self.building:
            return
        self.world = World(building, self.config.world)
        self.robot = Robot.in_world(self.world, self.config.robot)
        self.map = RobotMap(self.world, self.config.local_map)

    def reset(self, rng: np.random.Generator) -> None:
        """Put the robot at the world's start pose with an empty map, then take the first scan."""
        assert self.world is not None, "load() a building before reset()"
        self.robot.reset(self.world.start_pose)
        self.map.reset()
        self.path_length_m = 0.0
        self.collisions = 0
        self.trajectory = [self.world.start_pose[:2]]
        self._sense(rng)

    def step(self, v_m_s: float, w_rad_s: float, rng: np.random.Generator) -> StepOutcome:
        """Drive one control step with the command ``(v, w)``, then scan and map."""
        motion = self.robot.step(v_m_s, w_rad_s)
        self.path_length_m += motion.distance_m
        self.collisions += motion.collided
        pose = self.robot.pose
        self.trajectory.append(pose[:2])
        return StepOutcome(motion.collided, self._sense(rng))

    def _sense(self, rng: np.random.Generator) -> float:
        self.scan = self.lidar.scan(self.world.raycaster, self.robot.pose, rng)
        return self.map.update(self.scan)

    def odometry(self) -> tuple[float, float, float]:
        """The robot's pose in its map frame: relative to its start pose (m, m, rad in [-pi, pi])."""
        x0, y0, t0 = self.world.start_pose
        x, y, t = self.robot.pose
        c, s = math.cos(t0), math.sin(t0)
        dx, dy = x - x0, y - y0
        return (c * dx + s * dy, -s * dx + c * dy, math.remainder(t - t0, math.tau))
