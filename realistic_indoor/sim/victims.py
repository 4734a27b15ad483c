"""Victims for search tasks: placed in rooms, found when the victim sensor sees them."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from realistic_indoor.building.labels import ROOM_LABELS, SemanticLabel, parse_label
from realistic_indoor.checks import require_between, require_int
from realistic_indoor.errors import ConfigError

if TYPE_CHECKING:
    from realistic_indoor.building.room import Room
    from realistic_indoor.sim.raycast import Raycaster
    from realistic_indoor.sim.world import World

__all__ = ["VictimConfig", "VictimSensor", "Victims", "place_victims", "relative_polar"]

_BATCH = 64
"""Candidate points drawn at a time per room when placing a victim."""
_TRIES = 20
"""Batches tried in a room before giving up on it (a room too cramped for the clearance)."""


@dataclass(frozen=True)
class VictimConfig:
    """Where victims go and how they are sensed.

    The numbers have plausible ranges, checked on construction; a value outside one raises a
    one-line ``ConfigError``.

    Attributes:
        n_victims: Number of victims, an integer in [1, 1000].
        labels: Semantic labels of the rooms victims may be in; by default the ordinary rooms
            (small, medium, big), not corridors or halls.
        functions: Functional labels allowed (``"office"``, ``"classroom"``, ...); ``None``
            allows any.
        min_clearance_m: Least distance from a victim to any wall (m), in [0, 5].
        sensor_range_m: Victims farther than this are not seen (m), in [0.1, 50].
        sensor_fov_rad: Field of view of the victim sensor, centred on the heading (rad), in
            (0, 2 pi].
    """

    n_victims: int = 3
    labels: tuple[SemanticLabel, ...] = ROOM_LABELS
    functions: tuple[str, ...] | None = None
    min_clearance_m: float = 0.3
    sensor_range_m: float = 3.0
    sensor_fov_rad: float = math.radians(120.0)

    def __post_init__(self) -> None:
        require_int("VictimConfig", "n_victims", self.n_victims, 1, 1000)
        object.__setattr__(self, "labels", tuple(parse_label(lab) for lab in self.labels))
        if not self.labels:
            raise ConfigError("VictimConfig.labels must name at least one room label")
        if self.functions is not None:
            object.__setattr__(self, "functions", tuple(f.strip().lower() for f in self.functions))
        require_between("VictimConfig", "min_clearance_m", self.min_clearance_m, 0.0, 5.0, "m")
        require_between("VictimConfig", "sensor_range_m", self.sensor_range_m, 0.1, 50.0, "m")
        require_between(
            "VictimConfig", "sensor_fov_rad", self.sensor_fov_rad, 0.0, 2 * math.pi, "rad", low_open=True
        )

    def accepts(self, room: Room) -> bool:
        """Whether victims may be placed in ``room``."""
        return room.label in self.labels and (self.functions is None or room.function in self.functions)


def place_victims(world: World, rng: np.random.Generator, config: VictimConfig | None = None) -> np.ndarray:
    """Place victims uniformly over the floor of the allowed rooms.

    Each victim picks a room with probability proportional to its area, then a point in it
    that is on reachable floor and at least ``min_clearance_m`` from walls. Several victims
    may share a room.

    Args:
        world: The world (its reachable floor and clearance are used).
        rng: The random generator (the only source of randomness).
        config: Number of victims and allowed rooms.

    Returns:
        ``(n_victims, 2)`` float64 positions (m).

    Raises:
        ConfigError: If no reachable room matches the labels and functions, or none has room
            for a victim that far from walls.
    """
    config = config or VictimConfig()
    rooms = [r for r in world.building.rooms if config.accepts(r)]
    if not rooms:
        allowed = ", ".join(lab.value for lab in config.labels)
        raise ConfigError(
            f"no room can hold victims: none has a label in ({allowed})"
            + (f" and a function in {config.functions}" if config.functions else "")
            + "; widen VictimConfig.labels or functions"
        )
    out = np.empty((config.n_victims, 2))
    for i in range(config.n_victims):
        out[i] = _one_victim(world, rooms, rng, config.min_clearance_m)
    return out


def _one_victim(world: World, rooms: list[Room], rng: np.random.Generator, clearance_m: float) -> np.ndarray:
    import shapely

    rooms = list(rooms)
    while rooms:
        areas = np.array([r.area for r in rooms])
        room = rooms[rng.choice(len(rooms), p=areas / areas.sum())]
        x0, y0, x1, y1 = room.bounds
        for _ in range(_TRIES):
            pts = rng.uniform((x0, y0), (x1, y1), size=(_BATCH, 2))
            ok = shapely.contains_xy(room.polygon, pts[:, 0], pts[:, 1])
            ok &= world.is_clear(pts, clearance_m)
            row, col = world.raster.world_to_cell(pts)
            ok &= world.reachable[row, col]  # the raster covers every room's bounds
            if ok.any():
                return pts[np.argmax(ok)]
        rooms.remove(room)
    raise ConfigError(
        f"no allowed room has reachable floor {clearance_m} m clear of walls for a victim; "
        "lower VictimConfig.min_clearance_m or widen the allowed rooms"
    )


def relative_polar(pose: tuple[float, float, float], points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Ranges (m) and bearings of ``(N, 2)`` points seen from ``pose``.

    Bearings are in rad, in ``[-pi, pi]``: 0 straight ahead, positive to the left.
    """
    x, y, theta = pose
    d = np.asarray(points, dtype=float).reshape(-1, 2) - (x, y)
    bearing = np.arctan2(d[:, 1], d[:, 0]) - theta
    return np.hypot(d[:, 0], d[:, 1]), (bearing + math.pi) % (2 * math.pi) - math.pi


class VictimSensor:
    """Sees victims within its range and field of view, in line of sight (walls block it).

    Args:
        config: Range and field of view (``sensor_range_m``, ``sensor_fov_rad``).
    """

    def __init__(self, config: VictimConfig | None = None) -> None:
        self.config = config or VictimConfig()

    def in_view(
        self, raycaster: Raycaster, pose: tuple[float, float, float], victims: np.ndarray
    ) -> np.ndarray:
        """Which victims the sensor sees from ``pose``.

        Args:
            raycaster: The world's raycaster (line of sight).
            pose: ``(x, y, theta)`` of the sensor (m, m, rad).
            victims: ``(N, 2)`` victim positions (m).

        Returns:
            ``(N,)`` bool array. Cost: a few microseconds for a handful of victims.
        """
        c = self.config
        rng_m, bearing = relative_polar(pose, victims)
        near = (rng_m <= c.sensor_range_m) & (np.abs(bearing) <= c.sensor_fov_rad / 2)
        seen = np.zeros(len(rng_m), dtype=bool)
        if near.any():
            seen[near] = raycaster.visible(pose[:2], np.asarray(victims, dtype=float).reshape(-1, 2)[near])
        return seen


class Victims:
    """The victims of one episode: where they are, which the sensor sees, which it has found.

    A victim is found the first time the sensor sees it; :meth:`look` is the only place that
    marks victims found. Until the first :meth:`reset`, there are ``n_victims`` victims at the
    origin, none seen or found.

    Args:
        config: Number of victims and the sensor's range and field of view.

    Attributes:
        sensor: The victim sensor.
        xy: ``(N, 2)`` float64 victim positions (m).
        in_view: ``(N,)`` bool, the victims the sensor saw at the latest look.
        found: ``(N,)`` bool, the victims seen at least once this episode.
    """

    def __init__(self, config: VictimConfig | None = None) -> None:
        self.sensor = VictimSensor(config)
        n = self.sensor.config.n_victims
        self.xy = np.zeros((n, 2))
        self.in_view = np.zeros(n, dtype=bool)
        self.found = np.zeros(n, dtype=bool)

    def reset(self, xy: np.ndarray, raycaster: Raycaster, pose: tuple[float, float, float]) -> None:
        """Start an episode with victims at ``xy`` (m); those in view from ``pose`` count as found.

        Args:
            xy: ``(N, 2)`` victim positions (m), ``N`` being ``config.n_victims``.
            raycaster: The world's raycaster (line of sight).
            pose: ``(x, y, theta)`` of the sensor at the start (m, m, rad).
        """
        self.start(xy)
        self.look(raycaster, pose)

    def start(self, xy: np.ndarray) -> None:
        """Put the victims at ``xy`` (``(N, 2)`` m), none found yet, without looking.

        For a team, whose robots all look (:meth:`reset` is one robot's start).
        """
        self.xy = np.asarray(xy, dtype=float).reshape(-1, 2)
        self.found = np.zeros(len(self.xy), dtype=bool)
        self.in_view = np.zeros(len(self.xy), dtype=bool)

    @property
    def all_found(self) -> bool:
        """Whether every victim has been found: what ends a search episode (single, vector or team)."""
        return bool(self.found.all())

    def counts(self) -> dict[str, int]:
        """The environments' ``info`` entries of a search: ``victims_found`` and ``victims_total``."""
        return {"victims_found": int(self.found.sum()), "victims_total": len(self.found)}

    def look(self, raycaster: Raycaster, pose: tuple[float, float, float]) -> int:
        """Sense the victims from ``pose`` and mark those seen for the first time found.

        Args:
            raycaster: The world's raycaster (line of sight).
            pose: ``(x, y, theta)`` of the sensor (m, m, rad).

        Returns:
            The number of victims found by this look (seen now, never before).
        """
        self.in_view = self.sensor.in_view(raycaster, pose, self.xy)
        new = self.in_view & ~self.found
        self.found |= new
        return int(new.sum())
