"""Corridors, halls and rooms recognised on the robot's own map from the shape of its free space.

Doors are the narrow places of a building: cutting the known free floor where it is narrower
than a doorway splits it into regions (rooms, corridors, halls). Each region is then classified
by its shape, measured on its "core" (the cells farther than half a doorway from any wall): a
corridor is long and thin, a hall is wide, anything else is a room. This needs nothing but the
map, so it works the same on generated, random and real buildings, and on partly seen ones.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
from numba import njit
from scipy import ndimage

from realistic_indoor.checks import require_positive
from realistic_indoor.sim.mapping import MAPPED_FREE

__all__ = ["CORRIDOR_REGION", "HALL_REGION", "ROOM_REGION", "RegionConfig", "Regions", "find_regions"]

ROOM_REGION, CORRIDOR_REGION, HALL_REGION = 0, 1, 2
"""Classes of a region (:attr:`Regions.kinds`)."""

_EIGHT = np.ones((3, 3), dtype=bool)


@dataclass(frozen=True)
class RegionConfig:
    """Thresholds of the region classification (metres of the real building).

    Attributes:
        door_half_width_m: Free space narrower than twice this is a doorway: it separates
            regions (m).
        corridor_length_m: A corridor's core is at least this long (m).
        corridor_elongation: ... and at least this many times longer than wide.
        hall_half_width_m: A hall has a point this far from every wall (m) ...
        hall_area_m2: ... and a core of at least this area (m2).
    """

    door_half_width_m: float = 0.55
    corridor_length_m: float = 6.0
    corridor_elongation: float = 3.0
    hall_half_width_m: float = 2.5
    hall_area_m2: float = 30.0

    def __post_init__(self) -> None:
        for name, unit in (
            ("door_half_width_m", "m"),
            ("corridor_length_m", "m"),
            ("corridor_elongation", ""),
            ("hall_half_width_m", "m"),
            ("hall_area_m2", "m2"),
        ):
            require_positive("RegionConfig", name, getattr(self, name), unit)


class Regions(NamedTuple):
    """The regions of a map.

    Attributes:
        labels: ``(H, W)`` int32 region number (1..count) of each core cell, 0 elsewhere.
        kinds: ``(count + 1,)`` class of each region (:data:`ROOM_REGION`, :data:`CORRIDOR_REGION`,
            :data:`HALL_REGION`); entry 0 (no region) is :data:`ROOM_REGION`.
        length_m: ``(count + 1,)`` length of each region's core along its main axis (m).
        width_m: ``(count + 1,)`` width across it (m).
    """

    labels: np.ndarray
    kinds: np.ndarray
    length_m: np.ndarray
    width_m: np.ndarray

    @property
    def count(self) -> int:
        """Number of regions."""
        return len(self.kinds) - 1

    def circulation(self) -> np.ndarray:
        """Core cells of corridors and halls (bool)."""
        return self.kinds[self.labels] != ROOM_REGION


def find_regions(
    state: np.ndarray, clearance_m: np.ndarray, resolution_m: float, config: RegionConfig | None = None
) -> Regions:
    """Split the known free floor at doorways and classify the parts.

    Args:
        state: ``(H, W)`` cells of the agent's map.
        clearance_m: Distance from each cell to the nearest occupied cell (m).
        resolution_m: Side of a cell (m).
        config: Classification thresholds.

    Returns:
        The regions. Cost: a labelling and a few per-label sums over the map.
    """
    c = config or RegionConfig()
    core = (state == MAPPED_FREE) & (clearance_m >= c.door_half_width_m)
    labels, count = ndimage.label(core, structure=_EIGHT)
    sums, widest = _label_sums(labels, clearance_m, count)
    length, width, area = _shape(sums, resolution_m)
    kinds = np.full(count + 1, ROOM_REGION, dtype=np.int8)
    corridor = (length[1:] >= c.corridor_length_m) & (length[1:] >= c.corridor_elongation * width[1:])
    hall = (widest[1:] >= c.hall_half_width_m) & (area[1:] >= c.hall_area_m2)
    kinds[1:][corridor] = CORRIDOR_REGION
    kinds[1:][hall & ~corridor] = HALL_REGION
    return Regions(labels.astype(np.int32, copy=False), kinds, length, width)


def _shape(sums: np.ndarray, res: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Length and width along the principal axes (m) and area (m2) of each label, entry 0 unused.

    A uniform rectangle of sides ``L`` and ``W`` has variances ``L**2 / 12`` and ``W**2 / 12``
    along its axes: sides are ``sqrt(12 * eigenvalue)`` of its cells' coordinate covariance
    (plus a cell's own spread).

    Args:
        sums: :func:`_label_sums`' ``(6, count + 1)`` cell counts and coordinate sums.
        res: Side of a cell (m).
    """
    cells, s_r, s_c, s_rr, s_cc, s_rc = sums
    n = np.maximum(cells, 1.0)
    mr, mc = s_r / n, s_c / n
    var_r = s_rr / n - mr * mr + 1.0 / 12
    var_c = s_cc / n - mc * mc + 1.0 / 12
    cov = s_rc / n - mr * mc
    half_trace = (var_r + var_c) / 2
    spread = np.sqrt(((var_r - var_c) / 2) ** 2 + cov * cov)
    major = np.sqrt(12 * np.maximum(half_trace + spread, 0.0)) * res
    minor = np.sqrt(12 * np.maximum(half_trace - spread, 0.0)) * res
    major[0] = minor[0] = 0.0
    area = cells * res * res
    return major, minor, area


@njit(cache=True, nogil=True)
def _label_sums(labels, clearance, count):  # pragma: no cover - compiled
    """Per label of ``labels`` (0 left out): its cells, the sums of their coordinates, the widest clearance.

    One pass over the map in row order, so that each sum adds its terms in the order NumPy's
    ``bincount`` of the labelled cells would (the same floats to the bit).

    Returns:
        ``(sums, widest)``: ``(6, count + 1)`` float64 rows: cells, sum of rows, of columns, of
        rows squared, of columns squared, of rows times columns; ``(count + 1,)`` float64 the
        largest ``clearance`` of each label's cells (0 for none).
    """
    h, w = labels.shape
    sums = np.zeros((6, count + 1))
    widest = np.zeros(count + 1)
    for r in range(h):
        for c in range(w):
            lab = labels[r, c]
            if lab == 0:
                continue
            sums[0, lab] += 1.0
            sums[1, lab] += float(r)
            sums[2, lab] += float(c)
            sums[3, lab] += float(r * r)
            sums[4, lab] += float(c * c)
            sums[5, lab] += float(r * c)
            widest[lab] = max(widest[lab], float(clearance[r, c]))
    return sums, widest
