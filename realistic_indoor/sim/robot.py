"""A differential-drive disc robot as a pymunk body that collides with the walls and slides along them."""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, NamedTuple

import numpy as np
import pymunk

from realistic_indoor.checks import require_between, require_int
from realistic_indoor.errors import ConfigError

if TYPE_CHECKING:
    from realistic_indoor.sim.world import World

__all__ = ["PHYSICS", "Motion", "Robot", "RobotConfig", "RobotTeam"]

PHYSICS = ("compiled", "pymunk")
"""How a robot's motion is computed: the compiled disc of
:mod:`~realistic_indoor.sim.disc_physics` (fast, the default, and the only one the batched
simulation runs) or pymunk (:class:`Robot`, the reference the compiled disc is tested against)."""

_ROBOT, _WALL = 1, 2  # pymunk collision types
_MASS_KG = 10.0
_COLLISION_SLOP_M = 0.002
"""Overlap pymunk tolerates before pushing bodies apart (its default, 0.1, is 10 cm here)."""
_COLLISION_BIAS = 1e-6
"""Share of an overlap pymunk leaves after one second: a robot that touched a wall is pushed
clear within a few sub-steps (pymunk's default leaves 0.2 %)."""

_ROBOT_BOUNDS = (
    ("radius_m", 0.05, 2.0, "m"),
    ("max_speed_m_s", 0.05, 5.0, "m/s"),
    ("max_turn_rate_rad_s", 0.1, 10.0, "rad/s"),
    ("max_accel_m_s2", 0.1, 10.0, "m/s2"),
    ("max_angular_accel_rad_s2", 0.1, 50.0, "rad/s2"),
    ("control_hz", 1.0, 100.0, "Hz"),
)
"""Plausible range of each physical setting of :class:`RobotConfig`: field, low, high, unit."""


@dataclass(frozen=True)
class RobotConfig:
    """The robot's body, limits and control rate.

    Every field has a plausible range, checked on construction (a robot of radius 100 m is
    refused, not simulated); a value outside it raises a one-line ``ConfigError``.

    Attributes:
        radius_m: Radius of the disc (m), in [0.05, 2]; 0.25 m is a small search robot.
        max_speed_m_s: Largest forward or backward speed (m/s), in [0.05, 5].
        max_turn_rate_rad_s: Largest turning rate (rad/s), in [0.1, 10].
        max_accel_m_s2: Largest change of speed per second (m/s2), in [0.1, 10].
        max_angular_accel_rad_s2: Largest change of turning rate per second (rad/s2), in
            [0.1, 50].
        control_hz: Commands per second (Hz), in [1, 100]; one :meth:`Robot.step` lasts
            ``1 / control_hz`` s.
        substeps: Physics steps per control step, an integer in [1, 1000]. A sub-step must not
            move the robot more than half its radius (no tunnelling through walls); the config
            checks it.
        physics: ``"compiled"`` (default) or ``"pymunk"``, see :data:`PHYSICS`. Both move the
            robot the same way, to within millimetres where it touches two walls at once.
    """

    radius_m: float = 0.25
    max_speed_m_s: float = 1.0
    max_turn_rate_rad_s: float = 2.0
    max_accel_m_s2: float = 2.0
    max_angular_accel_rad_s2: float = 8.0
    control_hz: float = 5.0
    substeps: int = 4
    physics: str = "compiled"

    def __post_init__(self) -> None:
        if self.physics not in PHYSICS:
            raise ConfigError(
                f"RobotConfig.physics must be one of {', '.join(PHYSICS)}, got {self.physics!r}"
            )
        for name, low, high, unit in _ROBOT_BOUNDS:
            require_between("RobotConfig", name, getattr(self, name), low, high, unit)
        require_int("RobotConfig", "substeps", self.substeps, 1, 1000)
        travel = self.max_speed_m_s / (self.control_hz * self.substeps)
        if travel > self.radius_m / 2:
            need = math.ceil(2 * self.max_speed_m_s / (self.control_hz * self.radius_m))
            raise ConfigError(
                f"RobotConfig: at {self.max_speed_m_s} m/s a physics sub-step moves the robot {travel:.3f} m, "
                f"more than half its radius; use substeps >= {need} or a higher control_hz"
            )

    @property
    def dt_s(self) -> float:
        """Duration of one control step (s)."""
        return 1.0 / self.control_hz


class Motion(NamedTuple):
    """What one control step did.

    Attributes:
        collided: Whether the robot touched a wall during the step.
        distance_m: Straight-line distance between the poses before and after the step (m).
    """

    collided: bool
    distance_m: float


class Robot:
    """A differential-drive disc in a pymunk space whose static shapes are the walls.

    The space is built once per building (the walls never move); :meth:`reset` only moves the
    robot. Each :meth:`step` applies the acceleration and speed limits to the command, then runs
    ``substeps`` physics steps in which the body is driven at the limited speed along its
    heading; walls stop it and it slides along them (no friction). It is a
    :class:`RobotTeam` of one.

    The robot touches a wall when its centre is ``radius_m`` plus half the wall's thickness
    from the wall's centre line. On first contact it may overlap the wall by up to one sub-step's
    travel (``max_speed_m_s / (control_hz * substeps)``, 5 cm by default) during that sub-step,
    before pymunk pushes it out; with the default 0.1 m walls its centre therefore never comes
    within ``radius_m`` of a wall's centre line.

    Args:
        segments: ``(N, 2, 2)`` wall segments (m), e.g. :attr:`World.collision_segments`.
        config: Body, limits and control rate.
        wall_thickness_m: Thickness given to the wall segments (m).
        pose: Initial ``(x, y, theta)`` (m, m, rad).
    """

    def __init__(
        self,
        segments: np.ndarray,
        config: RobotConfig | None = None,
        wall_thickness_m: float = 0.1,
        pose: tuple[float, float, float] = (0.0, 0.0, 0.0),
    ) -> None:
        self._team = RobotTeam(segments, config, wall_thickness_m, [pose])
        self.config = self._team.config

    @classmethod
    def in_world(cls, world: World, config: RobotConfig | None = None) -> Robot:
        """A robot among ``world``'s walls, at its start pose."""
        return cls(world.collision_segments, config, world.config.wall_thickness_m, world.start_pose)

    def reset(self, pose: tuple[float, float, float]) -> None:
        """Put the robot at ``pose`` ``(x, y, theta)``, at rest."""
        self._team.reset([pose])

    @property
    def pose(self) -> tuple[float, float, float]:
        """``(x, y, theta)``: position (m) and heading (rad, in ``[-pi, pi]``)."""
        return self._team.poses[0]

    @property
    def velocity(self) -> tuple[float, float]:
        """``(v, w)``: current forward speed (m/s) and turning rate (rad/s), after limits."""
        return self._team.velocities[0]

    def step(self, v_m_s: float, w_rad_s: float) -> Motion:
        """Drive for one control step (``1 / control_hz`` s).

        Args:
            v_m_s: Commanded forward speed (m/s); clipped to the speed limit, and reached only
                as fast as the acceleration limit allows.
            w_rad_s: Commanded turning rate (rad/s, counter-clockwise); limited likewise.

        Returns:
            Whether a wall was touched, and the distance covered. Cost: about 10 microseconds
            with the default 4 sub-steps.
        """
        return self._team.step([(v_m_s, w_rad_s)])[0]


class RobotTeam:
    """Several differential-drive discs in one pymunk space: they collide with the walls and each other.

    The reference for the compiled :func:`~realistic_indoor.sim.disc_physics.drive_group`. Each
    robot is a body of the same mass and infinite moment, driven as :class:`Robot` drives one;
    two robots that meet push each other apart (no friction, no bounce).

    Args:
        segments: ``(N, 2, 2)`` wall segments (m), e.g. :attr:`World.collision_segments`.
        config: Body, limits and control rate (the same for every robot).
        wall_thickness_m: Thickness given to the wall segments (m).
        poses: Initial ``(x, y, theta)`` of each robot (m, m, rad), at least one.
    """

    def __init__(
        self,
        segments: np.ndarray,
        config: RobotConfig | None = None,
        wall_thickness_m: float = 0.1,
        poses: list[tuple[float, float, float]] | None = None,
    ) -> None:
        self.config = config or RobotConfig()
        poses = poses or [(0.0, 0.0, 0.0)]
        self._space = pymunk.Space()
        self._space.collision_slop = _COLLISION_SLOP_M
        self._space.collision_bias = _COLLISION_BIAS
        self._add_walls(np.asarray(segments, dtype=float).reshape(-1, 2, 2), wall_thickness_m / 2)
        self._bodies = [self._add_body(k) for k in range(len(poses))]
        self._wanted = [(0.0, 0.0)] * len(poses)
        self._space.on_collision(_ROBOT, _WALL, pre_solve=self._on_contact)
        self._space.on_collision(_ROBOT, _ROBOT, pre_solve=self._on_contact)
        self._touching = [False] * len(poses)
        self.reset(poses)

    def _add_walls(self, segments: np.ndarray, radius_m: float) -> None:
        static = self._space.static_body
        shapes = []
        for (ax, ay), (bx, by) in segments:
            s = pymunk.Segment(static, (float(ax), float(ay)), (float(bx), float(by)), radius_m)
            s.friction = 0.0
            s.collision_type = _WALL
            shapes.append(s)
        self._space.add(*shapes)

    def _add_body(self, k: int) -> pymunk.Body:
        body = pymunk.Body(_MASS_KG, math.inf)
        body.velocity_func = functools.partial(self._drive, k)
        disc = pymunk.Circle(body, self.config.radius_m)
        disc.friction = 0.0
        disc.collision_type = _ROBOT
        self._space.add(body, disc)
        return body

    def _drive(self, k: int, body: pymunk.Body, gravity: object, damping: float, dt: float) -> None:
        # Runs before pymunk's contact solver: the solver then takes away any speed into a wall,
        # and the next sub-step moves the body with what is left (it slides).
        body.velocity = self._wanted[k]

    def _on_contact(self, arbiter: pymunk.Arbiter, space: pymunk.Space, data: object) -> None:
        for shape in arbiter.shapes:
            if shape.collision_type == _ROBOT:
                self._touching[self._bodies.index(shape.body)] = True

    def reset(self, poses: list[tuple[float, float, float]]) -> None:
        """Put the robots at ``poses`` (``(x, y, theta)`` each, one per robot), at rest."""
        self._theta, self._v, self._w = [], [], []
        for k, (body, pose) in enumerate(zip(self._bodies, poses, strict=True)):
            x, y, theta = (float(v) for v in pose)
            body.position = (x, y)
            body.velocity = (0.0, 0.0)
            self._wanted[k] = (0.0, 0.0)
            self._space.reindex_shapes_for_body(body)
            self._theta.append(math.remainder(theta, math.tau))
            self._v.append(0.0)
            self._w.append(0.0)

    @property
    def poses(self) -> list[tuple[float, float, float]]:
        """``(x, y, theta)`` of each robot: position (m) and heading (rad, in ``[-pi, pi]``)."""
        return [(b.position.x, b.position.y, t) for b, t in zip(self._bodies, self._theta, strict=True)]

    @property
    def velocities(self) -> list[tuple[float, float]]:
        """``(v, w)`` of each robot: forward speed (m/s) and turning rate (rad/s), after limits."""
        return list(zip(self._v, self._w, strict=True))

    def step(self, commands: list[tuple[float, float]]) -> list[Motion]:
        """Drive every robot for one control step (``1 / control_hz`` s), as :meth:`Robot.step`.

        Args:
            commands: ``(v m/s, w rad/s)`` of each robot.

        Returns:
            Each robot's motion; ``collided`` is whether it touched a wall or another robot.
        """
        c = self.config
        dt = c.dt_s
        h = dt / c.substeps
        for k, (v_m_s, w_rad_s) in enumerate(commands):
            self._v[k] = _approach(self._v[k], _clip(v_m_s, c.max_speed_m_s), c.max_accel_m_s2 * dt)
            self._w[k] = _approach(
                self._w[k], _clip(w_rad_s, c.max_turn_rate_rad_s), c.max_angular_accel_rad_s2 * dt
            )
        starts = [b.position for b in self._bodies]
        theta = list(self._theta)
        self._touching = [False] * len(self._bodies)
        for _ in range(c.substeps):
            for k, (v, w) in enumerate(zip(self._v, self._w, strict=True)):
                mid = theta[k] + 0.5 * w * h
                self._wanted[k] = (v * math.cos(mid), v * math.sin(mid))
                theta[k] += w * h
            self._space.step(h)
        self._theta = [math.remainder(t, math.tau) for t in theta]
        return [
            Motion(touching, math.hypot(b.position.x - s.x, b.position.y - s.y))
            for b, s, touching in zip(self._bodies, starts, self._touching, strict=True)
        ]


def _clip(value: float, limit: float) -> float:
    return max(-limit, min(limit, float(value)))


def _approach(current: float, target: float, max_change: float) -> float:
    return current + max(-max_change, min(max_change, target - current))
