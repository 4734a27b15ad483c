"""One robot in one building: the simulator's parts wired together for an environment.

With the compiled physics (the default) the robot is a batch of one: each step is the compiled
step of :mod:`realistic_indoor.sim.batch` that the native vector environment and the teams run
(physics, laser, map update and local view in one call), and the robot, map and scan this
module offers are views of that batch's arrays. With ``RobotConfig(physics="pymunk")``, the
reference the compiled physics is held to, the same rules run one part after the other.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, NamedTuple

import numpy as np

from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.batch import RESET, STEP, Batch, StepOutputs, step_batch_serial, step_constants
from realistic_indoor.sim.disc_physics import DiscRobot, odometry, robot_in_world
from realistic_indoor.sim.lidar import Lidar, Scan
from realistic_indoor.sim.mapping import RobotMap, require_view_out
from realistic_indoor.sim.raycast import RayHits
from realistic_indoor.sim.victims import Victims, place_victims
from realistic_indoor.sim.world import World

if TYPE_CHECKING:
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

    With the compiled physics the simulation runs on :attr:`batch`, a
    :class:`~realistic_indoor.sim.batch.Batch` of one robot: :attr:`robot` is a view of its
    physics state and :attr:`map` of its map, and a step is one call of the batch's compiled
    step, the one the native vector environment and the teams run.

    Args:
        config: The environment's configuration.
        victims: Whether episodes have victims (placed and sensed as ``config.victims`` says).

    Attributes:
        lidar: The laser scanner.
        batch: The batch of one the compiled physics runs in; ``None`` with pymunk.
        world: The current world (``None`` before the first :meth:`reset`).
        robot: The robot in it.
        map: The robot's map.
        scan: The latest scan (its own arrays).
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
        self.batch = Batch(1) if config.robot.physics == "compiled" else None
        if self.batch is not None:
            self._constants = step_constants(config.robot, config.world, config.lidar, config.local_map)
            self._out = StepOutputs.zeros(1, config.lidar.n_beams, config.local_map.size_px)
            self._mode = np.zeros(1, dtype=np.int64)
            self._commands = np.zeros((1, 2))
            self._noise = np.zeros((1, config.lidar.n_beams))

    @property
    def building(self) -> Building | None:
        """The building of the current world."""
        return None if self.world is None else self.world.building

    @property
    def nbytes(self) -> int:
        """Memory held by the world's and the map's arrays (bytes); with a batch, all of its arrays.

        The batch adds the robot's physics state and the walls' contact grid to the world and map.
        """
        if self.world is None:
            return 0
        return self.batch.nbytes if self.batch is not None else self.world.nbytes + self.map.nbytes

    def load(self, building: Building) -> None:
        """Make ``building`` the current world (kept if it already is), the robot at rest at its start."""
        if building is self.building:
            return
        self.world = World(building, self.config.world)
        if self.batch is None:
            self.robot = robot_in_world(self.world, self.config.robot)
            self.map = RobotMap(self.world, self.config.local_map)
            return
        c = self._constants
        self.batch.load(0, self.world, c.params[0], int(c.local[0]))
        self.batch.place(0)
        self._views()

    def _views(self) -> None:
        """The robot and map as views of the batch's arrays."""
        self.robot = self.batch.robot(0, self.config.robot, self._constants.params)
        self.map = RobotMap(self.world, self.config.local_map, self.batch.map_storage(0))

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
        if self.batch is None:
            self._sense(rng)
        else:
            self._run(RESET, rng)
        if self.victims is not None:
            if victims_xy is None:
                victims_xy = place_victims(self.world, rng, self.config.victims)
            self.victims.reset(victims_xy, self.world.raycaster, self.robot.pose)

    def step(self, v_m_s: float, w_rad_s: float, rng: np.random.Generator) -> StepOutcome:
        """Drive one control step with the command ``(v, w)``, then scan, map and sense victims."""
        if self.batch is None:
            motion = self.robot.step(v_m_s, w_rad_s)
            collided, distance_m = motion.collided, motion.distance_m
            new_area_m2 = self._sense(rng)
        else:
            self._commands[0, 0], self._commands[0, 1] = v_m_s, w_rad_s
            self._run(STEP, rng)
            out = self._out
            collided, distance_m, new_area_m2 = (
                bool(out.terms[0, 1] > 0),
                float(out.motion[0]),
                float(out.terms[0, 0]),
            )
        self.path_length_m += distance_m
        self.collisions += collided
        pose = self.robot.pose
        self.trajectory.append(pose[:2])
        found = None if self.victims is None else self.victims.look(self.world.raycaster, pose)
        return StepOutcome(collided, new_area_m2, found)

    def local_view(self, out: np.ndarray) -> None:
        """The map around the robot, heading up, into ``out``: :meth:`RobotMap.local_view`'s image.

        With the compiled physics it is the view the latest step (or reset) rendered, at the pose
        the robot had then.

        Raises:
            ConfigError: If ``out`` is not a C-contiguous ``(size_px, size_px)`` uint8 array.
        """
        if self.batch is None:
            self.map.local_view(self.robot.pose, out=out)
            return
        require_view_out(out, self.config.local_map.size_px)
        out[...] = self._out.local[0, 0]

    def _sense(self, rng: np.random.Generator) -> float:
        """The pymunk robot's scan and map update, one after the other."""
        self.scan = self.lidar.scan(self.world.raycaster, self.robot.pose, rng)
        return self.map.update(self.scan)

    def _run(self, mode: int, rng: np.random.Generator) -> None:
        """The batch's compiled step (``mode``: a control step or a reset's first scan), noise drawn first.

        The noise is drawn as :meth:`Lidar.scan` draws it, so both physics see the same readings.
        """
        self._mode[0] = mode
        if self.config.lidar.noise_std_m > 0:
            rng.standard_normal(out=self._noise[0])
        self.batch.step(
            step_batch_serial, self._mode, self._commands, self._noise, self._constants, self._out
        )
        out = self._out
        true = RayHits(out.true_m[0].copy(), out.kinds[0].copy())
        self.scan = Scan(self.robot.pose, out.scan[0].copy(), true, self.lidar.offsets_rad)

    def __getstate__(self) -> dict[str, Any]:
        """The state to pickle: the robot and map views are made again from the batch on unpickling."""
        state = self.__dict__.copy()
        if self.batch is not None:
            state.pop("robot", None)
            state.pop("map", None)
        return state

    def __setstate__(self, state: dict[str, Any]) -> None:
        """Restore the state and, with a batch, its views."""
        self.__dict__.update(state)
        if self.batch is not None and self.world is not None:
            self._views()

    def odometry(self) -> tuple[float, float, float]:
        """The robot's pose in its map frame: relative to its start pose (m, m, rad in [-pi, pi])."""
        x0, y0, t0 = self.world.start_pose
        x, y, t = self.robot.pose
        ox, oy, heading = odometry(x, y, t, x0, y0, t0, math.cos(t0), math.sin(t0))
        return float(ox), float(oy), float(heading)
