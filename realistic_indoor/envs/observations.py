"""Observations: each part of the observation is a small class with a ``space`` and ``observe()``."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from gymnasium import spaces

from realistic_indoor.checks import require_between, require_int

if TYPE_CHECKING:
    from realistic_indoor.envs.config import EnvConfig
    from realistic_indoor.envs.simulation import Simulation

__all__ = [
    "EXTRA_OBSERVATIONS",
    "POSE_LIMIT_M",
    "TIME_LEFT_SPACE",
    "GlobalMapConfig",
    "GlobalMapObservation",
    "LocalMapObservation",
    "PoseObservation",
    "ScanObservation",
    "VelocityObservation",
    "batch_observations",
    "explore_observations",
    "mark_points",
    "time_left",
]

POSE_LIMIT_M = 1000.0
"""Bound of the odometry position in the observation space (m); positions are clipped to it."""

EXTRA_OBSERVATIONS = ("global_map", "candidates", "time_left")
"""Observation keys an environment adds on request (``EnvConfig.extra_observations``):
``candidates`` needs macro actions, which add it and ``time_left`` by default."""


@dataclass(frozen=True)
class GlobalMapConfig:
    """The ``global_map`` observation: the robot's whole map around it, in a fixed orientation.

    Attributes:
        size_px: Side of the image (pixels), an integer in [8, 1024].
        resolution_m: Side of a pixel (m), in [0.01, 5]; with the defaults the image covers
            64 m x 64 m.
    """

    size_px: int = 64
    resolution_m: float = 1.0

    def __post_init__(self) -> None:
        require_int("GlobalMapConfig", "size_px", self.size_px, 8, 1024)
        require_between("GlobalMapConfig", "resolution_m", self.resolution_m, 0.01, 5.0, "m")


class GlobalMapObservation:
    """The map around the robot, start heading up: ``(4, S, S)`` uint8 channels of 0 or 255.

    Channels: free floor, walls, unknown (neither), visited (the robot's centre passed through
    the pixel). The image is centred on the robot and turned so that the heading it started
    with points up (row 0), whatever its heading now; pixels are ``global_map.resolution_m``
    across. Nothing in it reveals the building's extent beyond what the robot has mapped.
    """

    def __init__(self, config: EnvConfig) -> None:
        self.config = config.global_map
        s = self.config.size_px
        self.space = spaces.Box(0, 255, (4, s, s), np.uint8)

    def observe(self, sim: Simulation) -> np.ndarray:
        """The image (a new array). Cost: a pass over the pooled map and the trajectory."""
        res = self.config.resolution_m
        image = np.zeros(self.space.shape, dtype=np.uint8)
        x, y, _ = sim.robot.pose
        up = sim.world.start_pose[2]
        sim.map.global_view((x, y), up, res, image[0], image[1])
        image[2][(image[0] == 0) & (image[1] == 0)] = 255
        mark_points(image[3], np.asarray(sim.trajectory, dtype=float), (x, y), up, res)
        return image


def mark_points(image: np.ndarray, xy: np.ndarray, centre_xy: tuple[float, float], up_rad: float,
                resolution_m: float) -> None:  # fmt: skip
    """Set to 255 the pixels of a fixed-orientation image that hold the points ``xy``.

    Args:
        image: ``(S, S)`` uint8, centred on ``centre_xy`` with the direction ``up_rad`` up
            (row 0), pixels ``resolution_m`` across; points outside it are left out.
        xy: ``(N, 2)`` points (m, plan frame).
        centre_xy: The image's centre (m).
        up_rad: The plan-frame direction shown up (rad).
        resolution_m: Side of a pixel (m).
    """
    s = image.shape[0]
    track = np.asarray(xy, dtype=float).reshape(-1, 2) - centre_xy
    c, si = np.cos(up_rad), np.sin(up_rad)
    ahead = (track[:, 0] * c + track[:, 1] * si) / resolution_m
    left = (track[:, 1] * c - track[:, 0] * si) / resolution_m
    rows = np.floor(s / 2 - ahead).astype(np.int64)
    cols = np.floor(s / 2 - left).astype(np.int64)
    inside = (rows >= 0) & (rows < s) & (cols >= 0) & (cols < s)
    image[rows[inside], cols[inside]] = 255


class ScanObservation:
    """The laser ranges divided by the maximum range: ``(n_beams,)`` float32 in ``[0, 1]``.

    Beams are ordered from the right end of the field of view to the left (counter-clockwise);
    a beam with no return reads 1.
    """

    def __init__(self, config: EnvConfig) -> None:
        self._scale = np.float32(1.0 / config.lidar.max_range_m)
        self.space = spaces.Box(0.0, 1.0, (config.lidar.n_beams,), np.float32)

    def observe(self, sim: Simulation) -> np.ndarray:
        """The normalised ranges of the latest scan (a new array)."""
        return np.minimum(sim.scan.ranges_m * self._scale, np.float32(1.0))


class LocalMapObservation:
    """The egocentric map image: ``(1, S, S)`` uint8, robot at the centre, heading up.

    Pixels are 0 (wall), 128 (unknown) or 255 (free floor): a channel-first image that
    stable-baselines3 recognises as one (``CnnPolicy``, ``MultiInputPolicy``).
    """

    def __init__(self, config: EnvConfig) -> None:
        s = config.local_map.size_px
        self.space = spaces.Box(0, 255, (1, s, s), np.uint8)

    def observe(self, sim: Simulation) -> np.ndarray:
        """The image around the robot's true pose (a new array)."""
        image = np.empty(self.space.shape, dtype=np.uint8)
        sim.local_view(image[0])
        return image


class VelocityObservation:
    """The robot's forward speed (m/s) and turn rate (rad/s), float32, within their limits."""

    def __init__(self, config: EnvConfig) -> None:
        r = config.robot
        self._v_max, self._w_max = r.max_speed_m_s, r.max_turn_rate_rad_s
        high = np.array([self._v_max, self._w_max], dtype=np.float32)
        self.space = spaces.Box(-high, high, (2,), np.float32)

    def observe(self, sim: Simulation) -> np.ndarray:
        """The current velocity (a new array)."""
        v, w = sim.robot.velocity
        v = max(-self._v_max, min(self._v_max, v))
        w = max(-self._w_max, min(self._w_max, w))
        return np.array((v, w), dtype=np.float32)


class PoseObservation:
    """Odometry: ``(x m, y m, heading rad)`` relative to the start pose, float32.

    ``x`` points along the start heading, ``y`` to its left; positions are clipped to
    :data:`POSE_LIMIT_M`, the heading lies in ``[-pi, pi]``.
    """

    def __init__(self, config: EnvConfig) -> None:
        high = np.array([POSE_LIMIT_M, POSE_LIMIT_M, np.pi], dtype=np.float32)
        self.space = spaces.Box(-high, high, (3,), np.float32)

    def observe(self, sim: Simulation) -> np.ndarray:
        """The pose in the robot's map frame (a new array)."""
        x, y, heading = sim.odometry()
        x = max(-POSE_LIMIT_M, min(POSE_LIMIT_M, x))
        y = max(-POSE_LIMIT_M, min(POSE_LIMIT_M, y))
        return np.array((x, y, heading), dtype=np.float32)


TIME_LEFT_SPACE = spaces.Box(0.0, 1.0, (1,), np.float32)
"""The space of the ``time_left`` observation."""


def time_left(steps: int, max_steps: int) -> np.ndarray:
    """The ``time_left`` observation: ``(1,)`` float32, the share of the step limit still to come."""
    return np.array([max(0.0, 1.0 - steps / max_steps)], dtype=np.float32)


def batch_observations(
    phys: np.ndarray,
    starts: np.ndarray,
    velocity_limits: np.ndarray,
    scan_m: np.ndarray,
    scan_scale: np.float32,
    local: np.ndarray,
) -> dict[str, np.ndarray]:
    """The exploration observation of a batch of robots, as the native vector environment builds it.

    Args:
        phys: ``(n, STATE_SIZE)`` physics states (:mod:`~realistic_indoor.sim.disc_physics`).
        starts: ``(n, 3)`` each robot's start pose ``(x m, y m, heading rad)``: its odometry's origin.
        velocity_limits: ``(2,)`` speed and turn-rate limits (m/s, rad/s).
        scan_m: ``(n, n_beams)`` float32 readings (m).
        scan_scale: ``1 / max range`` (1/m), float32.
        local: ``(n, 1, S, S)`` uint8 local views.

    Returns:
        ``scan``, ``local_map``, ``velocity`` and ``pose``, each with a leading robot axis (new
        arrays), equal to the bit to what :class:`ScanObservation`, :class:`LocalMapObservation`,
        :class:`VelocityObservation` and :class:`PoseObservation` give one robot (the heading
        wrapped by :func:`~realistic_indoor.sim.disc_physics.wrap_angle`, as the single robot's
        odometry wraps it).
    """
    from realistic_indoor.envs._vector_kernels import observe

    heading = np.ascontiguousarray(starts[:, 2])
    scan, local_map, velocity, pose = observe(
        phys, np.ascontiguousarray(starts[:, 0]), np.ascontiguousarray(starts[:, 1]), heading, np.cos(heading),
        np.sin(heading), velocity_limits, POSE_LIMIT_M, scan_m, scan_scale, local,
    )  # fmt: skip
    return {"scan": scan, "local_map": local_map, "velocity": velocity, "pose": pose}


def explore_observations(config: EnvConfig) -> dict[str, object]:
    """The parts of an exploration environment's observation, keyed by name."""
    return {
        "scan": ScanObservation(config),
        "local_map": LocalMapObservation(config),
        "velocity": VelocityObservation(config),
        "pose": PoseObservation(config),
    }
