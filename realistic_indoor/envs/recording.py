"""Record episodes to a rerun ``.rrd`` file: plan, map, scans, trajectory, victims, metrics."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import gymnasium as gym
import numpy as np

from realistic_indoor.envs.render import COLOURS, ViewFrame, map_image, plan_image, scan_end_points
from realistic_indoor.errors import ConfigError

if TYPE_CHECKING:
    from realistic_indoor.envs.explore import ExploreEnv

__all__ = ["RerunRecorder", "record_rerun"]

_MAP_CLASSES = [
    (1, "free", (*COLOURS["mapped_floor"], 255)),
    (2, "wall", (*COLOURS["mapped_wall"], 255)),
]


def _import_rerun() -> Any:
    try:
        import rerun
    except ImportError as e:
        raise gym.error.DependencyNotInstalled(
            'recording episodes needs rerun-sdk: pip install "realistic-indoor[viz]"'
        ) from e
    return rerun


class RerunRecorder(gym.Wrapper):
    """Record every step of an environment to a rerun file, to replay in the rerun viewer.

    Everything is drawn in the pixels of the environment's top view (north up, x right, y
    down, :class:`~realistic_indoor.envs.render.ViewFrame`): the plan (``world/plan``), the
    robot's map (``world/map``, every ``map_every`` steps and at the end of an episode), the
    scan (``world/scan``), the trajectory (``world/trajectory``, with the map), the robot
    (``world/robot``), the victims of search environments (``world/victims``, green once
    found), and coverage and reward over time (``metrics/...``). Timelines: ``step`` (across
    episodes) and ``episode``. Open the file with ``rerun path.rrd``.

    Args:
        env: A realistic-indoor environment (wrapped or not).
        path: The ``.rrd`` file to write (replaced if it exists).
        map_every: Steps between two logged maps (a map costs about a byte per raster cell).
        application_id: Name of the recording in the viewer.

    Raises:
        DependencyNotInstalled: If rerun-sdk is missing.
        ConfigError: If ``env`` is not a realistic-indoor environment, or ``map_every < 1``.

    Example:
        >>> import gymnasium as gym, realistic_indoor.envs
        >>> from realistic_indoor.envs import record_rerun
        >>> env = record_rerun(gym.make("OfficeExplore-v0"), "episode.rrd")  # doctest: +SKIP
    """

    def __init__(
        self, env: gym.Env, path: str | Path, map_every: int = 10, application_id: str = "realistic_indoor"
    ) -> None:
        super().__init__(env)
        if not hasattr(env.unwrapped, "simulation"):
            raise ConfigError(f"RerunRecorder records realistic-indoor environments, got {env.unwrapped!r}")
        if not (isinstance(map_every, int) and map_every >= 1):
            raise ConfigError(f"map_every must be an integer >= 1, got {map_every!r}")
        rr = _import_rerun()
        self._rr = rr
        self.path = Path(path)
        self.map_every = map_every
        self._rec = rr.RecordingStream(application_id)
        self._rec.save(self.path)
        self._rec.log("world", rr.AnnotationContext(_MAP_CLASSES), static=True)
        self._frame: ViewFrame | None = None
        self._building: object = None
        self._episode = -1
        self._global_step = 0
        self._episode_step = 0

    def reset(self, **kwargs: Any) -> tuple[Any, dict[str, Any]]:
        """Reset the environment and log the new episode's plan and first scan."""
        obs, info = self.env.reset(**kwargs)
        self._episode += 1
        self._episode_step = 0
        self._log_step(info, reward=None, force_map=True)
        return obs, info

    def step(self, action: Any) -> tuple[Any, float, bool, bool, dict[str, Any]]:
        """Step the environment and log what happened."""
        obs, reward, terminated, truncated, info = self.env.step(action)
        self._global_step += 1
        self._episode_step += 1
        self._log_step(info, reward=float(reward), force_map=terminated or truncated)
        return obs, reward, terminated, truncated, info

    def close(self) -> None:
        """Close the environment and finish the file."""
        if self._rec is not None:
            self._rec.flush()
            self._rec.disconnect()
            self._rec = None
        super().close()

    def _log_step(self, info: dict[str, Any], reward: float | None, force_map: bool) -> None:
        rr, rec = self._rr, self._rec
        env: ExploreEnv = self.env.unwrapped  # type: ignore[assignment]
        sim = env.simulation
        rec.set_time("step", sequence=self._global_step)
        rec.set_time("episode", sequence=self._episode)
        if sim.building is not self._building:
            self._building = sim.building
            self._frame = ViewFrame(sim.world.raster)
            rec.log("world/plan", rr.Image(plan_image(self._frame, sim.world.raster.grid), draw_order=-10.0))
        frame = self._frame
        if force_map or self._episode_step % self.map_every == 0:
            rec.log(
                "world/map",
                rr.SegmentationImage(map_image(frame, sim.map.grid), opacity=0.6, draw_order=-5.0),
            )
            path = frame.xy_px(np.asarray(sim.trajectory))
            rec.log("world/trajectory", rr.LineStrips2D([path], colors=COLOURS["trajectory"]))
        robot = frame.xy_px(np.array(sim.robot.pose[:2]))
        ends = frame.xy_px(scan_end_points(sim))
        rec.log(
            "world/scan", rr.LineStrips2D([[robot[0], e] for e in ends], colors=COLOURS["ray"], radii=0.3)
        )
        radius_px = sim.config.robot.radius_m / frame.pixel_m
        rec.log("world/robot", rr.Points2D(robot, radii=radius_px, colors=COLOURS["robot"], draw_order=10.0))
        if env.victims is not None:
            xy, found = env.victims
            colours = np.where(found[:, None], COLOURS["victim_found"], COLOURS["victim"]).astype(np.uint8)
            rec.log("world/victims", rr.Points2D(frame.xy_px(xy), radii=0.2 / frame.pixel_m, colors=colours))
        rec.log("metrics/coverage", rr.Scalars(info["coverage"]))
        if reward is not None:
            rec.log("metrics/reward", rr.Scalars(reward))


def record_rerun(env: gym.Env, path: str | Path, **kwargs: Any) -> RerunRecorder:
    """Wrap ``env`` so that its episodes are recorded to the rerun file ``path`` (see :class:`RerunRecorder`)."""
    return RerunRecorder(env, path, **kwargs)
