"""A 2D laser scanner: a fan of beams cast on the building's raster, with Gaussian range noise."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
from numba import njit

from realistic_indoor.checks import require_between, require_int
from realistic_indoor.sim.raster import RASTER_WALL
from realistic_indoor.sim.raycast import Raycaster, RayHits

__all__ = ["Lidar", "LidarConfig", "Scan", "beam_offsets"]


@dataclass(frozen=True)
class LidarConfig:
    """Laser scanner settings.

    Every field has a plausible range, checked on construction; a value outside it raises a
    one-line ``ConfigError``.

    Attributes:
        fov_rad: Field of view (rad), in (0, 2 pi]; beams are spread evenly from ``-fov/2`` to
            ``+fov/2`` about the heading, both ends included (a full circle has no duplicate).
        n_beams: Number of beams, an integer in [1, 3600] (3600: one every 0.1 degree over a
            full circle). The default 109 gives a beam every 2.5 degrees over 270 degrees and
            one straight ahead.
        max_range_m: Readings stop at this range (m), in [0.1, 100]; a beam with no return
            reads it.
        noise_std_m: Standard deviation of the Gaussian noise added to returned ranges (m), in
            [0, 1].
    """

    fov_rad: float = math.radians(270.0)
    n_beams: int = 109
    max_range_m: float = 10.0
    noise_std_m: float = 0.01

    def __post_init__(self) -> None:
        require_between("LidarConfig", "fov_rad", self.fov_rad, 0.0, 2 * math.pi, "rad", low_open=True)
        require_int("LidarConfig", "n_beams", self.n_beams, 1, 3600)
        require_between("LidarConfig", "max_range_m", self.max_range_m, 0.1, 100.0, "m")
        require_between("LidarConfig", "noise_std_m", self.noise_std_m, 0.0, 1.0, "m")


def beam_offsets(config: LidarConfig) -> np.ndarray:
    """Directions of a scanner's beams relative to its heading.

    Beams are spread evenly over the field of view, from ``-fov/2`` (right) to ``+fov/2`` (left),
    both ends included; a full circle leaves out ``+fov/2``, the same direction as ``-fov/2``. A
    single beam points straight ahead.

    Args:
        config: The scanner's settings.

    Returns:
        ``(n_beams,)`` float64 angles (rad), increasing (counter-clockwise); a new array.
    """
    if config.n_beams == 1:
        return np.zeros(1)
    full_circle = math.isclose(config.fov_rad, 2 * math.pi)
    return np.linspace(-config.fov_rad / 2, config.fov_rad / 2, config.n_beams, endpoint=not full_circle)


class Scan(NamedTuple):
    """One laser scan.

    Attributes:
        pose: ``(x, y, theta)`` of the scanner when the scan was taken (m, m, rad).
        ranges_m: ``(n_beams,)`` float32 readings (m) in ``[0, max_range_m]``, with noise;
            ``max_range_m`` for a beam with no return (nothing within range, or a beam that left
            the building through an exterior door: the outside returns nothing).
        true: Noise-free distances and what each beam met (:class:`RayHits`); the beam ends
            where it entered a wall or left the building. Mapping uses these.
        offsets_rad: ``(n_beams,)`` beam directions relative to the heading (rad), the
            scanner's :attr:`Lidar.offsets_rad` (shared, read-only).
    """

    pose: tuple[float, float, float]
    ranges_m: np.ndarray
    true: RayHits
    offsets_rad: np.ndarray

    @property
    def returned(self) -> np.ndarray:
        """Which beams returned from a wall (bool, ``(n_beams,)``)."""
        return self.true.returned


class Lidar:
    """A laser scanner: precomputes its beam directions, then casts them from any pose.

    Args:
        config: The scanner's settings.

    Attributes:
        config: The scanner's settings.
        offsets_rad: ``(n_beams,)`` beam directions relative to the heading (rad, increasing,
            counter-clockwise): :func:`beam_offsets` of the config, read-only.
    """

    def __init__(self, config: LidarConfig | None = None) -> None:
        self.config = config or LidarConfig()
        offsets = beam_offsets(self.config)
        offsets.setflags(write=False)
        self.offsets_rad = offsets
        self._cos = np.cos(offsets)
        self._sin = np.sin(offsets)
        self._no_noise = np.zeros(0)

    def scan(
        self, raycaster: Raycaster, pose: tuple[float, float, float], rng: np.random.Generator | None = None
    ) -> Scan:
        """Take a scan from ``pose``.

        Args:
            raycaster: The building's raycaster.
            pose: ``(x, y, theta)`` of the scanner (m, m, rad).
            rng: Source of the range noise; no noise when ``None`` or ``noise_std_m`` is 0.

        Returns:
            The scan (new arrays). Cost: about 0.05-0.08 microsecond per beam plus a few microseconds.
        """
        c = self.config
        n = c.n_beams
        true = RayHits(np.empty(n, np.float32), np.empty(n, np.uint8))
        x, y, theta = pose
        raycaster.cast_into(x, y, theta, self._cos, self._sin, c.max_range_m, true)
        noise = rng.standard_normal(n) if rng is not None and c.noise_std_m > 0 else self._no_noise
        ranges = np.empty(n, np.float32)
        _readings(true.range_m, true.kind, noise, c.noise_std_m, c.max_range_m, ranges)
        return Scan((float(x), float(y), float(theta)), ranges, true, self.offsets_rad)


@njit(cache=True, nogil=True)
def _readings(true_m, kind, noise, noise_std_m, max_range_m, out):  # pragma: no cover - compiled
    """Readings: returned beams get their range plus noise, clipped to the range; others read max."""
    noisy = noise.shape[0] > 0
    for i in range(true_m.shape[0]):
        if kind[i] == RASTER_WALL:
            r = true_m[i] + noise_std_m * noise[i] if noisy else true_m[i]
            out[i] = min(max(r, 0.0), max_range_m)
        else:
            out[i] = max_range_m


@njit(cache=True, nogil=True)
def draw_noise(generators, chosen, out):  # pragma: no cover - compiled
    """Fill row ``i`` of ``out`` with standard normal draws from ``generators[i]`` where ``chosen[i]``.

    One compiled call for a batch of robots: the values and the generators' states after it are
    those of ``generators[i].standard_normal(out=out[i])`` for each chosen ``i`` (numba draws
    with NumPy's algorithm from the same bit generator), at a quarter of the cost of 64 calls.

    Args:
        generators: numba typed ``List`` of ``np.random.Generator``, one per row of ``out``.
        chosen: ``(N,)`` bool, the rows to fill.
        out: ``(N, n_beams)`` float64, written where chosen.
    """
    for i in range(out.shape[0]):
        if chosen[i]:
            g = generators[i]
            for j in range(out.shape[1]):
                out[i, j] = g.standard_normal()
