"""Scale sanity: flag plans whose rooms are far too large or too small for their building type.

Plans drawn in pixels carry a scale that is sometimes wrong (the shared real plans include a
25-room dentist office of 9,000 m2). A plan is flagged when the median area of its medium rooms
(or, where it has fewer than three medium rooms or its labels were inferred from area, of all
its small, medium and big rooms) is more than ``max_ratio`` times larger or smaller than the
reference mean for that type. Areas grow with the square of the length scale, so a factor of 3
in area is a factor of 1.7 in length; the flag suggests the length factor that would fix it.

The reference is, by default, real plans of the type: the model fitted to the shared real plans
(:func:`~realistic_indoor.models.building_model.real_model`) for offices and schools, whose
medium rooms (35 and 76 m2) are about twice the paper's Table 1 (18.5 and 55 m2); for houses and
unknown types, which have no such model, the paper's table. ``reference="paper"`` uses the
paper's table for every type (the fit of the real model itself does, so that it does not judge
plans by itself).
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
from realistic_indoor.errors import ConfigError

if TYPE_CHECKING:
    from realistic_indoor.building.building import Building

__all__ = [
    "MAX_AREA_RATIO",
    "SCALE_REFERENCES",
    "ScaleFlag",
    "expected_room_area",
    "scale_check",
    "scale_reference",
]

SCALE_REFERENCES = ("real", "paper")
"""What a plan's room sizes can be judged against: real plans of the type, or the paper's Table 1."""

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
        reference: What the expected area comes from, in words (``"real offices"``).
    """

    source: str
    measured: str
    median_m2: float
    expected_m2: float
    length_factor: float
    reference: str = "the paper's Table 1"

    @property
    def message(self) -> str:
        """The flag in words."""
        way = "large" if self.median_m2 > self.expected_m2 else "small"
        times = max(self.median_m2, self.expected_m2) / max(min(self.median_m2, self.expected_m2), 1e-9)
        return (
            f"{self.source}: scale looks wrong: {self.measured} have a median of {self.median_m2:.1f} m2, "
            f"{times:.1f}x too {way} (expected about {self.expected_m2:.1f} m2 in {self.reference}); "
            f"lengths x{self.length_factor:.2g} would fix it"
        )


def scale_reference(building_type: BuildingType | str, reference: str = "real") -> str:
    """What room sizes of ``building_type`` are judged against, in words.

    Raises:
        ConfigError: If ``reference`` is not one of :data:`SCALE_REFERENCES`.
    """
    from realistic_indoor.models.building_model import REAL_MODEL_TYPES

    if reference not in SCALE_REFERENCES:
        raise ConfigError(f"scale reference must be one of {', '.join(SCALE_REFERENCES)}, got {reference!r}")
    t = parse_building_type(building_type)
    if reference == "real" and t.value in REAL_MODEL_TYPES:
        return f"real {t.value}s"
    return "the paper's Table 1" if t is not BuildingType.UNKNOWN else "the paper's Table 1 (all types)"


def expected_room_area(
    building_type: BuildingType | str, label: SemanticLabel | None, reference: str = "real"
) -> float:
    """Reference mean area (m2) of rooms of ``label``, or of all ordinary rooms for ``None``.

    For ``None`` it is the mean of the small, medium and big means weighted by their shares.

    Args:
        building_type: The type.
        label: A room label, or ``None`` for small, medium and big rooms together.
        reference: ``"real"``: real plans of the type where a model fitted to them exists
            (offices, schools), else the paper's table; ``"paper"``: the paper's Table 1.
    """
    t = parse_building_type(building_type)
    if scale_reference(t, reference).startswith("real"):
        from realistic_indoor.models.building_model import real_model

        stats = real_model(t).labels
        means = {lab: stats[lab].area_mean for lab in stats}
        shares = {lab: stats[lab].share for lab in stats}
    else:
        from realistic_indoor.models.reference import reference_table

        table = reference_table("all_types" if t is BuildingType.UNKNOWN else t)
        means = {lab: table[lab]["area_mean"] for lab in table}
        shares = {lab: table[lab]["share_pct"] for lab in table}
    if label is not None:
        return means[label]
    weights = [shares[lab] for lab in ROOM_LABELS]
    return sum(w * means[lab] for w, lab in zip(weights, ROOM_LABELS, strict=True)) / sum(weights)


def scale_check(
    building: Building,
    building_type: BuildingType | str | None = None,
    *,
    max_ratio: float = MAX_AREA_RATIO,
    source: str | None = None,
    reference: str = "real",
) -> ScaleFlag | None:
    """Flag ``building`` if its typical room is far off the type's size (see the module docstring).

    Args:
        building: The plan.
        building_type: Type to compare with (default: the plan's own).
        max_ratio: Largest tolerated ratio between the median and the expected area.
        source: Name of the plan in the message (default: its metadata ``source`` or ``generator``).
        reference: ``"real"`` (real plans of the type, where a fitted model exists) or
            ``"paper"`` (the paper's Table 1); see the module docstring.

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
    observed, expected = median(areas), expected_room_area(t, label, reference)
    if observed <= 0 or 1 / max_ratio <= observed / expected <= max_ratio:
        return None
    name = source or str(building.metadata.get("source") or building.metadata.get("generator") or "plan")
    return ScaleFlag(
        name, measured, observed, expected, math.sqrt(expected / observed), scale_reference(t, reference)
    )
