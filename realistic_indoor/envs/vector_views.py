"""Top views of a native vector environment's sub-environments, for ``render()``.

A sub-environment's frame is the single environment's top view of the same episode
(:func:`~realistic_indoor.envs.render.draw`), pixel for pixel; ``render_mode="human"`` shows
every sub-environment's frame in one window (:func:`~realistic_indoor.envs.render.tile`).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from realistic_indoor.envs.render import Scene, draw, tile
from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.lidar import LidarConfig, beam_offsets
from realistic_indoor.sim.raycast import RayHits
from realistic_indoor.sim.world import World

__all__ = ["RENDER_MODES", "SubEnvViews", "require_render_mode"]

RENDER_MODES = ("rgb_array", "human")
"""What ``render_mode`` a native vector environment takes (besides ``None``)."""


def require_render_mode(render_mode: str | None) -> None:
    """Refuse a ``render_mode`` the native vector environments do not draw.

    Raises:
        ConfigError: If ``render_mode`` is neither ``None`` nor one of :data:`RENDER_MODES`.
    """
    if render_mode is not None and render_mode not in RENDER_MODES:
        raise ConfigError(f"render_mode must be one of {list(RENDER_MODES)} or None, got {render_mode!r}")


class SubEnvViews:
    """What the frames need beyond the batch's state: each trajectory, and the window.

    Args:
        num_envs: Number of sub-environments.
        lidar: The laser's settings (the beams drawn).
        radius_m: The robot's radius (m).
    """

    def __init__(self, num_envs: int, lidar: LidarConfig, radius_m: float) -> None:
        self._trajectories: list[list[tuple[float, float]]] = [[] for _ in range(num_envs)]
        self._lidar = lidar
        self._offsets = beam_offsets(lidar)
        self._cos = np.cos(self._offsets)
        self._sin = np.sin(self._offsets)
        self._radius_m = radius_m
        self._window = None

    def __getstate__(self) -> dict:
        """The state to pickle: all but the window (a copy opens its own when it shows frames)."""
        return {**self.__dict__, "_window": None}

    def start(self, k: int, xy: tuple[float, float]) -> None:
        """Sub-environment ``k`` starts an episode at ``xy`` (m)."""
        self._trajectories[k] = [xy]

    def moved(self, stepped: np.ndarray, xy: np.ndarray) -> None:
        """The sub-environments ``stepped`` (bool mask) are now at ``xy`` (``(num_envs, 2)`` m)."""
        for k in np.flatnonzero(stepped):
            self._trajectories[k].append((float(xy[k, 0]), float(xy[k, 1])))

    def frame(
        self,
        k: int,
        world: World,
        map_grid: np.ndarray,
        pose: tuple[float, float, float],
        scan_m: np.ndarray,
        victims: tuple[np.ndarray, np.ndarray] | None = None,
    ) -> np.ndarray:
        """Sub-environment ``k``'s top view: ``(H, W, 3)`` uint8, as the single environment's.

        Args:
            k: The sub-environment.
            world: Its world.
            map_grid: Its robot's map.
            pose: Its robot's pose ``(x m, y m, heading rad)``, where the latest scan was taken.
            scan_m: The latest scan's readings (m).
            victims: Victim positions ``(N, 2)`` (m) and found flags ``(N,)``, for search.
        """
        n = self._offsets.shape[0]
        true = RayHits(np.empty(n, np.float32), np.empty(n, np.uint8))  # which beams hit a wall
        world.raycaster.cast_into(*pose, self._cos, self._sin, self._lidar.max_range_m, true)
        xy, found = victims if victims is not None else (None, None)
        scene = Scene(
            raster=world.raster,
            map_grid=map_grid,
            trajectory_xy=np.asarray(self._trajectories[k]),
            pose=pose,
            scan_pose=pose,
            scan_ranges_m=scan_m,
            scan_offsets_rad=self._offsets,
            scan_returned=true.returned,
            radius_m=self._radius_m,
            victims_xy=xy,
            victims_found=found,
        )
        return draw(scene)

    def show(self, frames: Sequence[np.ndarray], title: str, fps: float) -> None:
        """Show the frames side by side in a window (opened on the first call; needs pygame)."""
        if self._window is None:
            from realistic_indoor.envs.window import Window

            self._window = Window(title, fps)
        self._window.show(tile(frames))

    def close(self) -> None:
        """Close the window, if one is open."""
        if self._window is not None:
            self._window.close()
            self._window = None
