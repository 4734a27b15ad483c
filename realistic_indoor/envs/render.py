"""A top view of an episode drawn with NumPy on the raster: fast, and needing no display."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from realistic_indoor.sim.mapping import MAPPED_FREE, MAPPED_OCCUPIED

if TYPE_CHECKING:
    from realistic_indoor.envs.simulation import Simulation
    from realistic_indoor.sim.raster import OccupancyRaster

__all__ = [
    "COLOURS",
    "MAX_SIDE_PX",
    "Scene",
    "ViewFrame",
    "draw",
    "draw_team",
    "map_image",
    "plan_image",
    "scan_end_points",
    "tile",
    "top_view",
]

MAX_SIDE_PX = 1024
"""Longest side of a rendered image (pixels); larger rasters are pooled by a whole factor."""

COLOURS: dict[str, tuple[int, int, int]] = {
    "outside": (255, 255, 255),
    "floor": (225, 225, 225),
    "wall": (90, 90, 90),
    "mapped_floor": (190, 220, 250),
    "mapped_wall": (20, 50, 140),
    "trajectory": (245, 130, 20),
    "ray": (120, 200, 120),
    "hit": (200, 30, 30),
    "robot": (30, 110, 200),
    "heading": (255, 255, 255),
    "victim": (220, 20, 60),
    "victim_found": (20, 160, 60),
    "candidate": (170, 60, 200),
    "goal": (255, 200, 0),
}
"""RGB colour of each element of the view."""

_PLAN_RANK = np.array([1, 2, 0], dtype=np.uint8)  # RASTER_FREE, RASTER_WALL, RASTER_OUTSIDE -> pooling rank
_MAP_RANK = np.array([0, 1, 2], dtype=np.uint8)  # MAPPED_UNKNOWN, MAPPED_FREE, MAPPED_OCCUPIED
_VICTIM_HALF_M = 0.2
_CANDIDATE_HALF_M = 0.15
_GOAL_HALF_M = 0.3


@dataclass(frozen=True)
class Scene:
    """What a top view shows of one robot's episode (world units: metres, radians).

    Attributes:
        raster: The world's raster.
        map_grid: ``(H, W)`` uint8 the robot's map (``MAPPED_*`` states) on the raster's cells.
        trajectory_xy: ``(T, 2)`` positions (m), the start first.
        pose: The robot's ``(x, y, heading)`` (m, m, rad).
        scan_pose: Where the latest scan was taken, ``(x, y, heading)``.
        scan_ranges_m: ``(n_beams,)`` the latest scan's readings (m).
        scan_offsets_rad: ``(n_beams,)`` beam directions relative to the heading (rad).
        scan_returned: ``(n_beams,)`` bool, the beams that returned from a wall.
        radius_m: The robot's radius (m).
        victims_xy: ``(N, 2)`` victim positions (m), or ``None``.
        victims_found: ``(N,)`` bool, which victims have been found, or ``None``.
        candidates_xy: ``(K, 2)`` candidate goals of a pending macro decision (m), or ``None``.
        goal_xy: ``(2,)`` the goal being driven to (m), or ``None``.
    """

    raster: OccupancyRaster
    map_grid: np.ndarray
    trajectory_xy: np.ndarray
    pose: tuple[float, float, float]
    scan_pose: tuple[float, float, float]
    scan_ranges_m: np.ndarray
    scan_offsets_rad: np.ndarray
    scan_returned: np.ndarray
    radius_m: float
    victims_xy: np.ndarray | None = None
    victims_found: np.ndarray | None = None
    candidates_xy: np.ndarray | None = None
    goal_xy: np.ndarray | None = None


def top_view(
    sim: Simulation,
    victims_xy: np.ndarray | None = None,
    victims_found: np.ndarray | None = None,
    candidates_xy: np.ndarray | None = None,
    goal_xy: np.ndarray | None = None,
) -> np.ndarray:
    """The top view (:func:`draw`) of a single environment's episode.

    Args:
        sim: The episode's simulation (after a reset).
        victims_xy: ``(N, 2)`` victim positions (m), if any.
        victims_found: ``(N,)`` bool, which victims have been found.
        candidates_xy: ``(K, 2)`` candidate goals of a pending macro decision (m, plan frame).
        goal_xy: ``(2,)`` the goal of the last macro decision (m, plan frame).

    Returns:
        An ``(H, W, 3)`` uint8 image (:func:`draw`).
    """
    scene = Scene(
        raster=sim.world.raster,
        map_grid=sim.map.grid,
        trajectory_xy=np.asarray(sim.trajectory),
        pose=sim.robot.pose,
        scan_pose=sim.scan.pose,
        scan_ranges_m=sim.scan.ranges_m,
        scan_offsets_rad=sim.lidar.offsets_rad,
        scan_returned=sim.scan.returned,
        radius_m=sim.config.robot.radius_m,
        victims_xy=victims_xy,
        victims_found=victims_found,
        candidates_xy=candidates_xy,
        goal_xy=goal_xy,
    )
    return draw(scene)


def draw(scene: Scene) -> np.ndarray:
    """Draw the plan, the robot's map, the trajectory, the latest scan, victims and the robot.

    North (+y) is up. Unseen floor is light grey, walls dark grey; what the robot has mapped is
    light blue (floor) and dark blue (walls); the trajectory is orange, the beams green with red
    returns, victims red squares (green once found), the robot a blue disc with a white
    heading line; with macro actions, the candidate goals small purple squares and the goal being
    driven to a yellow one.

    Returns:
        An ``(H, W, 3)`` uint8 image, one pixel per raster cell (fewer when the raster is
        larger than :data:`MAX_SIDE_PX`). Cost: a few milliseconds for a 2,000 m2 office.
    """
    return draw_team([scene])


def draw_team(scenes: Sequence[Scene], base_xy: tuple[float, float] | None = None) -> np.ndarray:
    """Draw several robots of one building, as :func:`draw` draws one.

    The plan, the map and the victims are the first scene's (a team's map); every scene's
    trajectory, scan, macro marks and robot are drawn, then the base station (a goal-yellow
    square) if given.

    Args:
        scenes: One per robot, all of one raster, at least one.
        base_xy: The base station's position (m), or ``None``.

    Returns:
        An ``(H, W, 3)`` uint8 image (as :func:`draw`).
    """
    first = scenes[0]
    frame = ViewFrame(first.raster)
    image = plan_image(frame, first.raster.grid)
    mapped = frame.pool(_MAP_RANK[first.map_grid])
    image[mapped == _MAP_RANK[MAPPED_FREE]] = COLOURS["mapped_floor"]
    image[mapped == _MAP_RANK[MAPPED_OCCUPIED]] = COLOURS["mapped_wall"]
    for scene in scenes:
        _draw_trajectory(image, frame, np.asarray(scene.trajectory_xy))
    for scene in scenes:
        _draw_scan(image, frame, scene)
    if first.victims_xy is not None and len(first.victims_xy):
        _draw_victims(image, frame, np.asarray(first.victims_xy), first.victims_found)
    for scene in scenes:
        _draw_marks(image, frame, scene)
    for scene in scenes:
        _draw_robot(image, frame, scene.pose, scene.radius_m)
    if base_xy is not None:
        _draw_square(image, frame, np.asarray(base_xy, dtype=float), _GOAL_HALF_M, COLOURS["goal"])
    return image


def _draw_marks(image: np.ndarray, frame: ViewFrame, scene: Scene) -> None:
    """A pending macro decision's goal and candidate goals."""
    if scene.goal_xy is not None:
        _draw_square(image, frame, np.asarray(scene.goal_xy, dtype=float), _GOAL_HALF_M, COLOURS["goal"])
    if scene.candidates_xy is not None:
        for xy in np.asarray(scene.candidates_xy, dtype=float).reshape(-1, 2):
            _draw_square(image, frame, xy, _CANDIDATE_HALF_M, COLOURS["candidate"])


def tile(frames: Sequence[np.ndarray], gap_px: int = 4) -> np.ndarray:
    """Frames of any sizes side by side in one image, in rows of ``ceil(sqrt(n))``.

    Each frame sits at the top left of a cell as large as the largest frame; what a frame does
    not cover, and a gap of ``gap_px`` between cells, is white (:data:`COLOURS` ``"outside"``).

    Args:
        frames: ``(H_i, W_i, 3)`` uint8 images, at least one.
        gap_px: Pixels between neighbouring cells.

    Returns:
        ``(rows * (H + gap) - gap, cols * (W + gap) - gap, 3)`` uint8, ``H`` and ``W`` the
        largest height and width, frame ``i`` in row ``i // cols`` and column ``i % cols``.
    """
    n = len(frames)
    cols = math.ceil(math.sqrt(n))
    rows = -(-n // cols)
    h = max(f.shape[0] for f in frames)
    w = max(f.shape[1] for f in frames)
    out = np.empty((rows * (h + gap_px) - gap_px, cols * (w + gap_px) - gap_px, 3), dtype=np.uint8)
    out[...] = COLOURS["outside"]
    for i, f in enumerate(frames):
        top, left = (i // cols) * (h + gap_px), (i % cols) * (w + gap_px)
        out[top : top + f.shape[0], left : left + f.shape[1]] = f
    return out


class ViewFrame:
    """The pixel grid of a top view: raster cells pooled by a whole factor, north up.

    Args:
        raster: The world's raster.

    Attributes:
        pool_factor: Raster cells per pixel side.
        pixel_m: Side of a pixel (m).
        shape: ``(rows, cols)`` of the image.
    """

    def __init__(self, raster: OccupancyRaster) -> None:
        self.pool_factor = max(1, math.ceil(max(raster.shape) / MAX_SIDE_PX))
        self.pixel_m = raster.resolution_m * self.pool_factor
        h, w = raster.shape
        self.shape = (-(-h // self.pool_factor), -(-w // self.pool_factor))
        self._origin = np.asarray(raster.origin, dtype=float)

    def xy_px(self, xy: np.ndarray) -> np.ndarray:
        """``(N, 2)`` image coordinates ``(x right, y down)`` in pixels of world points (m)."""
        p = (np.asarray(xy, dtype=float).reshape(-1, 2) - self._origin) / self.pixel_m
        return np.stack([p[:, 0], self.shape[0] - p[:, 1]], axis=1)

    def rc(self, xy: np.ndarray) -> np.ndarray:
        """``(N, 2)`` float ``(row, col)`` of world points (m)."""
        return self.xy_px(xy)[:, ::-1]

    def pool(self, ranks: np.ndarray) -> np.ndarray:
        """Pool a raster-shaped array by its maximum over each pixel, flipped north up."""
        k = self.pool_factor
        if k > 1:
            h, w = ranks.shape
            padded = np.zeros((self.shape[0] * k, self.shape[1] * k), dtype=ranks.dtype)
            padded[:h, :w] = ranks
            ranks = padded.reshape(self.shape[0], k, self.shape[1], k).max(axis=(1, 3))
        return ranks[::-1]


def plan_image(frame: ViewFrame, plan: np.ndarray) -> np.ndarray:
    """The plan alone, ``(H, W, 3)`` uint8: outside white, floor light grey, walls dark grey."""
    lut = np.array([COLOURS["outside"], COLOURS["floor"], COLOURS["wall"]], dtype=np.uint8)
    return lut[frame.pool(_PLAN_RANK[plan])]


def map_image(frame: ViewFrame, robot_map: np.ndarray) -> np.ndarray:
    """The robot's map, ``(H, W)`` uint8: 0 unknown, 1 free, 2 wall (walls win when pooled)."""
    return frame.pool(_MAP_RANK[robot_map])


def _put(image: np.ndarray, rc: np.ndarray, colour: tuple[int, int, int]) -> None:
    """Colour the pixels at float coordinates ``rc`` (``(N, 2)``) that lie in the image."""
    r = np.floor(rc[:, 0]).astype(np.int64)
    c = np.floor(rc[:, 1]).astype(np.int64)
    ok = (r >= 0) & (r < image.shape[0]) & (c >= 0) & (c < image.shape[1])
    image[r[ok], c[ok]] = colour


def _draw_segments(image: np.ndarray, a: np.ndarray, b: np.ndarray, colour: tuple[int, int, int]) -> None:
    """Draw straight lines from pixel points ``a`` to ``b`` (``(N, 2)`` each), half a pixel apart."""
    if not len(a):
        return
    n = np.ceil(2 * np.hypot(*(b - a).T)).astype(np.int64) + 1
    seg = np.repeat(np.arange(len(a)), n)
    t = (np.arange(n.sum()) - np.repeat(np.cumsum(n) - n, n)) / np.repeat(np.maximum(n - 1, 1), n)
    _put(image, a[seg] + t[:, None] * (b - a)[seg], colour)


def _draw_trajectory(image: np.ndarray, frame: ViewFrame, xy: np.ndarray) -> None:
    if len(xy) > 1:
        p = frame.rc(xy)
        _draw_segments(image, p[:-1], p[1:], COLOURS["trajectory"])


def scan_end_points(sim: Simulation) -> np.ndarray:
    """``(n_beams, 2)`` world points (m) where the latest scan's beams end."""
    return _beam_ends(sim.scan.pose, sim.scan.ranges_m, sim.lidar.offsets_rad)


def _beam_ends(pose: tuple[float, float, float], ranges_m: np.ndarray, offsets_rad: np.ndarray) -> np.ndarray:
    x, y, theta = pose
    angles = theta + offsets_rad
    r = ranges_m.astype(float)
    return np.stack([x + r * np.cos(angles), y + r * np.sin(angles)], axis=1)


def _draw_scan(image: np.ndarray, frame: ViewFrame, scene: Scene) -> None:
    centre = frame.rc(np.array(scene.scan_pose[:2]))
    tips = frame.rc(_beam_ends(scene.scan_pose, scene.scan_ranges_m, scene.scan_offsets_rad))
    _draw_segments(image, np.repeat(centre, len(tips), axis=0), tips, COLOURS["ray"])
    _put(image, tips[scene.scan_returned], COLOURS["hit"])


def _draw_disc(image: np.ndarray, centre: np.ndarray, radius_px: float, colour: tuple[int, int, int]) -> None:
    r0, c0 = centre
    rows = np.arange(math.floor(r0 - radius_px), math.ceil(r0 + radius_px) + 1)
    cols = np.arange(math.floor(c0 - radius_px), math.ceil(c0 + radius_px) + 1)
    rr, cc = np.meshgrid(rows, cols, indexing="ij")
    inside = (rr + 0.5 - r0) ** 2 + (cc + 0.5 - c0) ** 2 <= max(radius_px, 0.5) ** 2
    _put(image, np.stack([rr[inside], cc[inside]], axis=1).astype(float), colour)


def _draw_robot(
    image: np.ndarray, frame: ViewFrame, pose: tuple[float, float, float], radius_m: float
) -> None:
    x, y, theta = pose
    centre = frame.rc(np.array([x, y]))[0]
    _draw_disc(image, centre, radius_m / frame.pixel_m, COLOURS["robot"])
    nose = frame.rc(np.array([x + radius_m * math.cos(theta), y + radius_m * math.sin(theta)]))
    _draw_segments(image, centre[None], nose, COLOURS["heading"])


def _draw_victims(image: np.ndarray, frame: ViewFrame, xy: np.ndarray, found: np.ndarray | None) -> None:
    found = np.zeros(len(xy), bool) if found is None else np.asarray(found, bool)
    for p, is_found in zip(xy, found, strict=True):
        _draw_square(image, frame, p, _VICTIM_HALF_M, COLOURS["victim_found" if is_found else "victim"])


def _draw_square(
    image: np.ndarray, frame: ViewFrame, xy: np.ndarray, half_m: float, colour: tuple[int, int, int]
) -> None:
    """A filled square ``2 * half_m`` across centred on the point ``xy`` (m)."""
    p = frame.rc(np.asarray(xy, dtype=float).reshape(1, 2))[0]
    half = half_m / frame.pixel_m
    rows = np.arange(math.floor(p[0] - half), math.ceil(p[0] + half))
    cols = np.arange(math.floor(p[1] - half), math.ceil(p[1] + half))
    rr, cc = np.meshgrid(rows, cols, indexing="ij")
    square = np.stack([rr.ravel(), cc.ravel()], axis=1).astype(float)
    _put(image, square, colour)
