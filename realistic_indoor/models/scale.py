"""Scale sanity: flag plans whose rooms are far too large or too small for their building type.

Plans drawn in pixels carry a scale that is sometimes wrong (the shared real plans include a
25-room dentist office of 9,000 m2). A plan is flagged when the median area of its medium rooms
(or, where it has fewer than three medium rooms or its labels were inferred from area, of all
its small, medium and big rooms) is more than ``max_ratio`` times larger or smaller than the
reference mean for that type. Areas grow with the square of the length scale, so a factor of 3
in area is a factor of 1.7 in length; the flag suggests the length factor that would fix it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from statistics import median
from typing import TYPE_CHECKING

from realistic_indoor.building.labels import (
    ROOM_LABELS,
    BuildingType,
    SemanticLabel,
    labels_inferred,
    parse_building_type,
)

if TYPE_CHECKING:
    from realistic_indoor.building.building import Building

__all__ = ["MAX_AREA_RATIO", "ScaleFlag", "expected_room_area", "scale_check"]

MAX_AREA_RATIO = 3.0
"""How many times larger or smaller than expected a plan's typical room may be before it is flagged."""


@dataclass(frozen=True)
class ScaleFlag:
    """A plan whose scale looks wrong.

    Attributes:
        source: The plan (file name or generator).
        measured: Which rooms were measured (``"medium rooms"``, ``"small/medium/big rooms"``).
        median_m2: Their median area, m2.
        expected_m2: The reference mean area of such rooms for the type, m2.
        length_factor: Factor to multiply the plan's coordinates by to bring the median to the
            expected area (``sqrt(expected / median)``).
    """

    source: str
    measured: str
    median_m2: float
    expected_m2: float
    length_factor: float

    @property
    def message(self) -> str:
        """The flag in words."""
        way = "large" if self.median_m2 > self.expected_m2 else "small"
        times = max(self.median_m2, self.expected_m2) / max(min(self.median_m2, self.expected_m2), 1e-9)
        return (
            f"{self.source}: scale looks wrong: {self.measured} have a median of {self.median_m2:.1f} m2, "
            f"{times:.1f}x too {way} (expected about {self.expected_m2:.1f} m2); "
            f"lengths x{self.length_factor:.2g} would fix it"
        )


def expected_room_area(building_type: BuildingType | str, label: SemanticLabel | None) -> float:
    """Reference mean area (m2) of rooms of ``label``, or of all ordinary rooms for ``None``.

    For ``None`` it is the mean of the small, medium and big means weighted by their shares.
    """
    from realistic_indoor.models.reference import reference_table

    t = parse_building_type(building_type)
    table = reference_table("all_types" if t is BuildingType.UNKNOWN else t)
    if label is not None:
        return table[label]["area_mean"]
    weights = [table[lab]["share_pct"] for lab in ROOM_LABELS]
    return sum(w * table[lab]["area_mean"] for w, lab in zip(weights, ROOM_LABELS, strict=True)) / sum(
        weights
    )


def scale_check(
    building: Building,
    building_type: BuildingType | str | None = None,
    *,
    max_ratio: float = MAX_AREA_RATIO,
    source: str | None = None,
) -> ScaleFlag | None:
    """Flag ``building`` if its typical room is far off the type's size (see the module docstring).

    Args:
        building: The plan.
        building_type: Type to compare with (default: the plan's own).
        max_ratio: Largest tolerated ratio between the median and the expected area.
        source: Name of the plan in the message (default: its metadata ``source`` or ``generator``).

    Returns:
        A flag, or ``None`` if the scale looks plausible or there is nothing to measure.
    """
    t = parse_building_type(building.building_type if building_type is None else building_type)
    medium = [r.area for r in building.rooms if r.label is SemanticLabel.MEDIUM]
    if len(medium) >= 3 and not labels_inferred(building):
        measured, areas, label = "medium rooms", medium, SemanticLabel.MEDIUM
    else:
        measured, label = "small/medium/big rooms", None
        areas = [r.area for r in building.rooms if r.label in ROOM_LABELS] or [r.area for r in building.rooms]
    if not areas:
        return None
    observed, expected = median(areas), expected_room_area(t, label)
    if observed <= 0 or 1 / max_ratio <= observed / expected <= max_ratio:
        return None
    name = source or str(building.metadata.get("source") or building.metadata.get("generator") or "plan")
    return ScaleFlag(name, measured, observed, expected, math.sqrt(expected / observed))
