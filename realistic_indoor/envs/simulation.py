"""One robot in one building: the simulator's parts wired together for an environment."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, NamedTuple

from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.disc_physics import DiscRobot, odometry, robot_in_world
from realistic_indoor.sim.lidar import Lidar, Scan
from realistic_indoor.sim.mapping import RobotMap
from realistic_indoor.sim.victims import Victims, place_victims
from realistic_indoor.sim.world import World

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.building.building import Building
    from realistic_indoor.envs.config import EnvConfig
    from realistic_indoor.sim.robot import Robot

__all__ = ["Simulation", "StepOutcome"]


class StepOutcome(NamedTuple):
    """What one control step did.

    Attributes:
        collided: Whether the robot touched a wall.
        new_area_m2: Reachable floor observed for the first time (m2).
        victims_found: Victims the victim sensor saw for the first time; ``None`` in a
            simulation without victims.
    """

    collided: bool
    new_area_m2: float
    victims_found: int | None = None


class Simulation:
    """The world, robot, laser, map and victims of an episode, and the episode's running totals.

    The world, robot and map are built once per building and reused while the building stays
    the same (a fixed building resets in microseconds; a new one costs a rasterization).

    With victims, every :meth:`reset` places them and every :meth:`step` senses them after the
    scan: this is where victims are found, whatever the task then makes of it (reward,
    termination, observation). Without victims (exploration) nothing is placed or sensed.

    Args:
        config: The environment's configuration.
        victims: Whether episodes have victims (placed and sensed as ``config.victims`` says).

    Attributes:
        lidar: The laser scanner.
        world: The current world (``None`` before the first :meth:`reset`).
        robot: The robot in it.
        map: The robot's map.
        scan: The latest scan.
        victims: The episode's victims (positions, in view, found); ``None`` without victims.
        path_length_m: Distance driven this episode (m).
        collisions: Control steps with a wall contact this episode.
        trajectory: Positions ``(x, y)`` at the start and after each step (m).
    """

    def __init__(self, config: EnvConfig, victims: bool = False) -> None:
        self.config = config
        self.lidar = Lidar(config.lidar)
        self.victims = Victims(config.victims) if victims else None
        self.world: World | None = None
        self.robot: DiscRobot | Robot
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
        self.robot = robot_in_world(self.world, self.config.robot)
        self.map = RobotMap(self.world, self.config.local_map)

    def reset(self, rng: np.random.Generator, victims_xy: np.ndarray | None = None) -> None:
        """Start an episode: the robot at rest at the start pose, an empty map, the first scan.

        With victims, they are then placed (drawn from ``rng`` after the scan's noise, or put
        at ``victims_xy``) and sensed once: those in view from the start count as found.

        Args:
            rng: The random generator (laser noise, victim placement).
            victims_xy: ``(n_victims, 2)`` victim positions (m) instead of drawn ones.

        Raises:
            ConfigError: If ``victims_xy`` is given to a simulation without victims.
        """
        assert self.world is not None, "load() a building before reset()"
        if victims_xy is not None and self.victims is None:
            raise ConfigError("victim positions given to a simulation without victims (victims=False)")
        self.robot.reset(self.world.start_pose)
        self.map.reset()
        self.path_length_m = 0.0
        self.collisions = 0
        self.trajectory = [self.world.start_pose[:2]]
        self._sense(rng)
        if self.victims is not None:
            if victims_xy is None:
                victims_xy = place_victims(self.world, rng, self.config.victims)
            self.victims.reset(victims_xy, self.world.raycaster, self.robot.pose)

    def step(self, v_m_s: float, w_rad_s: float, rng: np.random.Generator) -> StepOutcome:
        """Drive one control step with the command ``(v, w)``, then scan, map and sense victims."""
        motion = self.robot.step(v_m_s, w_rad_s)
        self.path_length_m += motion.distance_m
        self.collisions += motion.collided
        pose = self.robot.pose
        self.trajectory.append(pose[:2])
        new_area_m2 = self._sense(rng)
        found = None if self.victims is None else self.victims.look(self.world.raycaster, pose)
        return StepOutcome(motion.collided, new_area_m2, found)

    def _sense(self, rng: np.random.Generator) -> float:
        self.scan = self.lidar.scan(self.world.raycaster, self.robot.pose, rng)
        return self.map.update(self.scan)

    def odometry(self) -> tuple[float, float, float]:
        """The robot's pose in its map frame: relative to its start pose (m, m, rad in [-pi, pi])."""
        x0, y0, t0 = self.world.start_pose
        x, y, t = self.robot.pose
        ox, oy, heading = odometry(x, y, t, x0, y0, t0, math.cos(t0), math.sin(t0))
        return float(ox), float(oy), float(heading)
