"""A team of robots in one building on the batched simulation: step, links, maps and victims."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from realistic_indoor.sim.batch import (
    RESET,
    STEP,
    Batch,
    StepOutputs,
    step_batch_serial,
    step_constants,
)
from realistic_indoor.sim.disc_physics import THETA, V, W, X, Y
from realistic_indoor.sim.mapping import coverage_share
from realistic_indoor.sim.raster import RASTER_WALL
from realistic_indoor.sim.victims import Victims, place_victims
from realistic_indoor.sim.world import World
from realistic_indoor.teams.links import connected
from realistic_indoor.teams.maps import TeamMaps
from realistic_indoor.teams.starts import base_station, start_poses

if TYPE_CHECKING:
    from realistic_indoor.building.building import Building
    from realistic_indoor.envs.config import EnvConfig
    from realistic_indoor.teams.config import TeamConfig

__all__ = ["TeamSimulation"]


class TeamSimulation:
    """The world, robots, maps, links and victims of a team's episode, and its running totals.

    Robots ``0..n-1`` share building slot 0 of a :class:`~realistic_indoor.sim.batch.Batch`
    (they collide with the walls and each other); the base station is node ``n`` of the link
    graph. Each step runs the batch's compiled step, then each robot's victim sensor (in robot
    order: a victim two robots see first at once is the lower robot's), then the links from the
    new positions, then the map merges the links allow (:class:`~realistic_indoor.teams.maps.TeamMaps`).

    Args:
        config: The environment's configuration (robot, laser, maps, victims).
        team: The team's configuration.
        victims: Whether episodes have victims (search).

    Attributes:
        world: The current world (``None`` before the first :meth:`load`).
        batch: The robots' batch.
        links: ``(n + 1, n + 1)`` bool direct links after the latest step (robots, then the base).
        components: ``(n + 1,)`` component of each node in the link graph.
        victims: The episode's victims (found by anyone), or ``None`` without victims.
        in_view: ``(n, n_victims)`` bool, the victims each robot's sensor saw at its latest look.
        known: ``(n, n_victims)`` bool, the findings each robot knows of (its own, and those of
            robots it has been connected to since they found them).
        reported: ``(n_victims,)`` bool, the findings that reached the base station.
    """

    def __init__(self, config: EnvConfig, team: TeamConfig, victims: bool = False) -> None:
        self.config = config
        self.team = team
        n = team.n_robots
        self.maps = TeamMaps(n, team.map_sharing)
        self.batch = Batch(n, np.zeros(n, dtype=np.int64), self.maps.robot_map, self.maps.map_scans())
        self.constants = step_constants(config.robot, config.world, config.lidar, config.local_map)
        s, n_beams = config.local_map.size_px, config.lidar.n_beams
        self._mode = np.zeros(n, dtype=np.int64)
        self._commands = np.zeros((n, 2))
        self._noise = np.zeros((n, n_beams))
        self.out = StepOutputs.zeros(n, n_beams, s)
        self.victims = Victims(config.victims) if victims else None
        self.world: World | None = None
        self.starts = np.zeros((n, 3))
        self.base_xy = (0.0, 0.0)
        self._reset_totals()

    @property
    def n(self) -> int:
        """Robots in the team."""
        return self.team.n_robots

    @property
    def poses(self) -> np.ndarray:
        """``(n, 3)`` robot poses ``(x m, y m, heading rad)``."""
        return self.batch.phys[:, [X, Y, THETA]].copy()

    @property
    def velocities(self) -> np.ndarray:
        """``(n, 2)`` speeds and turn rates after the limits (m/s, rad/s)."""
        return self.batch.phys[:, [V, W]].copy()

    @property
    def coverage(self) -> float:
        """Share of the reachable floor the team has observed (its team map)."""
        return float(
            coverage_share(self.batch.observed[self.maps.coverage_map], self.batch.building_meta[0, 3])
        )

    def own_coverage(self, i: int) -> float:
        """Share of the reachable floor robot ``i``'s map holds."""
        return float(
            coverage_share(self.batch.observed[self.batch.robot_map[i]], self.batch.building_meta[0, 3])
        )

    @property
    def returned_beams(self) -> np.ndarray:
        """``(n, n_beams)`` bool: which beams of each robot's latest scan returned from a wall."""
        return self.out.kinds == RASTER_WALL

    def load(self, building: Building) -> None:
        """Make ``building`` the current world (kept if it already is)."""
        if self.world is not None and building is self.world.building:
            return
        self.world = World(building, self.config.world)
        self.batch.load(0, self.world, self.constants.params[0], int(self.constants.local[0]))

    def reset(self, rng: np.random.Generator, victims_xy: np.ndarray | None = None) -> None:
        """Start an episode: the robots at rest at their starts, empty maps, the first scans.

        The first scans' laser noise is drawn from ``rng`` robot after robot, then the victims
        are placed (as the single environment draws them after its first scan).

        Raises:
            ConfigError: If the building has no room for the team at its entrance.
        """
        world = self.world
        r = self.config.robot.radius_m
        self.starts = np.array(start_poses(world, self.n, r, self.team.spacing_m))
        self.base_xy = base_station(world, self.team.base_offset_m)
        self.maps.reset()
        self.batch.set_maps(self.maps.robot_map, self.maps.map_scans())
        for m in range(self.batch.n_maps):
            self.batch.reset_map(m)
        for i in range(self.n):
            self.batch.place(i, tuple(self.starts[i]))
        self._reset_totals()
        self._run(RESET, rng)
        if self.victims is not None:
            xy = place_victims(world, rng, self.config.victims) if victims_xy is None else victims_xy
            self.victims.start(xy)
            self.known = np.zeros((self.n, len(self.victims.xy)), dtype=bool)
            self.reported = np.zeros(len(self.victims.xy), dtype=bool)
            self.look()
        self.relink()

    def step(self, commands: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        """Drive every robot one control step, scan, map, sense victims, relink and merge maps.

        Args:
            commands: ``(n, 2)`` ``(v m/s, w rad/s)``.
            rng: The laser noise's source.

        Returns:
            ``(n,)`` victims each robot found this step (zeros without victims).
        """
        self._commands[:] = commands
        self._run(STEP, rng)
        self.steps += 1
        self.path_length_m += self.out.motion
        self.collisions += self.out.terms[:, 1] > 0
        for i in range(self.n):
            self.trajectories[i].append((float(self.batch.phys[i, X]), float(self.batch.phys[i, Y])))
        found = self.look()
        self._count_shared_cells()
        self.relink()
        return found

    def look(self) -> np.ndarray:
        """Each robot's victim sensor looks, in robot order; ``(n,)`` victims each found first."""
        found = np.zeros(self.n, dtype=np.int64)
        if self.victims is None:
            return found
        self.in_view = np.zeros((self.n, len(self.victims.xy)), dtype=bool)
        for i in range(self.n):
            pose = tuple(float(v) for v in self.batch.phys[i, [X, Y, THETA]])
            found[i] = self.victims.look(self.world.raycaster, pose)
            self.in_view[i] = self.victims.in_view
            self.known[i] |= self.victims.in_view
        return found

    def relink(self) -> None:
        """Links from the robots' positions; knowledge of findings and maps shared as they allow."""
        nodes = np.vstack([self.batch.phys[:, [X, Y]], np.array(self.base_xy)[None]])
        self.links = self.team.links.linked(self.world, nodes)
        self.components = connected(self.links)
        self.messages += int(self.links[: self.n].sum())  # each robot to each node it reaches directly
        robots = self.components[: self.n]
        self.cells_sent += self.maps.relink(self.batch, robots)
        if self.victims is not None:
            for c in np.unique(robots):
                group = robots == c
                self.known[group] = self.known[group].any(axis=0)
            at_base = robots == self.components[self.n]
            self.reported |= self.known[at_base].any(axis=0)

    def _count_shared_cells(self) -> None:
        """Cells each robot's scan added to a map it shares: sent once to each robot sharing it."""
        if self.maps.sharing == "own":
            return
        cells = np.rint(self.out.terms[:, 0] / self.batch.building_meta[0, 2] ** 2).astype(np.int64)
        sharers = np.bincount(self.batch.robot_map, minlength=self.batch.n_maps)[self.batch.robot_map]
        self.cells_sent += int((cells * (sharers - 1)).sum())

    def _reset_totals(self) -> None:
        self.steps = 0
        self.path_length_m = np.zeros(self.n)
        self.collisions = np.zeros(self.n, dtype=np.int64)
        self.messages = 0
        self.cells_sent = 0
        self.trajectories = [[(float(x), float(y))] for x, y in self.starts[:, :2]]
        self.in_view = np.zeros((self.n, 0), dtype=bool)
        self.known = np.zeros((self.n, 0), dtype=bool)
        self.reported = np.zeros(0, dtype=bool)

    def _run(self, mode: int, rng: np.random.Generator) -> None:
        """One compiled step of every robot (``mode``), the laser noise drawn first."""
        self._mode[:] = mode
        if self.config.lidar.noise_std_m > 0:
            rng.standard_normal(out=self._noise)
        # one building: the parallel kernel would run it on one thread anyway
        self.batch.step(step_batch_serial, self._mode, self._commands, self._noise, self.constants, self.out)
