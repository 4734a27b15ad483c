"""Where a team starts: its robots at the entrance, beside the base station.

Robot 0 starts where the single environment's robot starts (the world's start pose: just inside
the first entrance, facing inward; without one, in the largest hall or room), so a team of one
runs the single environment's episode. The others stand on a lattice around it, as near as it
allows: points ``2 * radius + spacing_m`` apart along the start heading and across it, in order
of distance from robot 0 (ahead before behind, left before right at equal distance), each
``start_clearance_m`` clear of walls, on the reachable floor, in sight of robot 0 and as far
from every robot already placed. Where the entrance has no room for them all within
:data:`SEARCH_RADIUS_M` (a narrow corridor, a small lobby), the rest take the nearest clear
reachable lattice points that are not in sight of robot 0 (round a corner, through a door); if
even those are too few, the team is refused.

The base station stands outside the entrance robot 0 starts at, ``base_offset_m`` from the
door's centre; without such an entrance, at robot 0's start.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from realistic_indoor.errors import ConfigError
from realistic_indoor.teams.links import walls_crossed

if TYPE_CHECKING:
    from realistic_indoor.sim.world import World

__all__ = ["SEARCH_RADIUS_M", "base_station", "start_poses"]

SEARCH_RADIUS_M = 15.0
"""How far from robot 0 the lattice of start points reaches (m)."""

Pose = tuple[float, float, float]


def start_poses(world: World, n: int, radius_m: float, spacing_m: float) -> list[Pose]:
    """The start poses of a team of ``n`` robots (all facing robot 0's heading).

    Args:
        world: The world; robot 0 starts at its start pose.
        n: Robots.
        radius_m: A robot's radius (m).
        spacing_m: Gap between two robots' discs (m).

    Returns:
        ``n`` poses ``(x m, y m, heading rad)``, robot 0's first.

    Raises:
        ConfigError: If the reachable floor within :data:`SEARCH_RADIUS_M` has no room for them.
    """
    x, y, theta = world.start_pose
    if n == 1:
        return [world.start_pose]
    step = 2 * radius_m + spacing_m
    points = _lattice((x, y), theta, step)
    points = points[_usable(world, points)]
    seen = walls_crossed(world, np.vstack([[x, y], points]))[0, 1:] == 0
    chosen = [np.array([x, y])]
    for candidates in (points[seen], points[~seen]):
        for p in candidates:
            if len(chosen) == n:
                break
            if min(math.dist(p, q) for q in chosen) >= step - 1e-9:
                chosen.append(p)
    if len(chosen) < n:
        raise ConfigError(
            f"no room for {n} robots within {SEARCH_RADIUS_M:g} m of the start in this building "
            f"(found {len(chosen)}); use fewer robots or a smaller TeamConfig.spacing_m"
        )
    return [world.start_pose] + [(float(p[0]), float(p[1]), theta) for p in chosen[1:]]


def _lattice(centre: tuple[float, float], heading: float, step: float) -> np.ndarray:
    """``(N, 2)`` lattice points around ``centre`` (m), nearest first, ahead before behind, left before right."""
    reach = int(SEARCH_RADIUS_M / step)
    a, b = np.meshgrid(np.arange(-reach, reach + 1), np.arange(-reach, reach + 1), indexing="ij")
    a, b = a.ravel(), b.ravel()
    keep = (a != 0) | (b != 0)
    a, b = a[keep], b[keep]
    order = np.lexsort((-b, a < 0, np.abs(b), np.hypot(a, b)))
    a, b = a[order] * step, b[order] * step
    c, s = math.cos(heading), math.sin(heading)
    return np.stack([centre[0] + a * c - b * s, centre[1] + a * s + b * c], axis=1)


def _usable(world: World, points: np.ndarray) -> np.ndarray:
    """Which points are clear of walls by the start clearance and on the reachable floor."""
    row, col = world.raster.world_to_cell(points)
    inside = world.raster.in_bounds(row, col)
    reachable = np.zeros(len(points), dtype=bool)
    reachable[inside] = world.reachable[row[inside], col[inside]]
    clear = np.zeros(len(points), dtype=bool)
    clear[reachable] = world.is_clear(points[reachable], world.config.start_clearance_m)
    return clear


def base_station(world: World, offset_m: float) -> tuple[float, float]:
    """Where the base station stands (m): outside the entrance robot 0 starts at, or at its start.

    The entrance is the exterior door on whose centre line, behind the start, robot 0 stands
    (how :meth:`~realistic_indoor.sim.world.World.default_start_pose` places it).
    """
    x, y, theta = world.start_pose
    ahead = np.array([math.cos(theta), math.sin(theta)])
    for door in world.building.entrances:
        back = np.array([door.x - x, door.y - y])
        if abs(back[0] * ahead[1] - back[1] * ahead[0]) < 1e-6 and back @ ahead < 0:
            base = np.array([door.x, door.y]) - offset_m * ahead
            return (float(base[0]), float(base[1]))
    return (x, y)
