"""Semantic labels for plans that lack them: corridor/hall from function or shape, size from area.

A room is labelled, in this order:

1. **corridor** if its functional label is a corridor's (:data:`CORRIDOR_FUNCTIONS`), **hall**
   if it is a hall's (:data:`HALL_FUNCTIONS`);
2. if its function is unknown (:data:`UNKNOWN_FUNCTIONS`), from its shape and doors:
   **corridor** when it is elongated (:func:`elongation` at least
   ``corridor_min_elongation``) with at least ``corridor_min_doors`` doorways, or very
   elongated (``long_corridor_min_elongation``) with ``long_corridor_min_doors``; **hall** when
   it has at least ``hall_min_doors`` doorways and is larger than a small room;
3. otherwise **small**, **medium** or **big** by area, with thresholds per building type taken
   from the reference tables (:func:`size_thresholds`): the boundary between two size labels
   is the geometric mean of their mean areas in the paper's Table 1 (office: 9.1 and 24.1 m2,
   school: 23.4 and 75.1 m2, house: 10.2 and 24.2 m2).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from realistic_indoor.building.building import Building
from realistic_indoor.building.labels import (
    INFERRED,
    BuildingType,
    SemanticLabel,
    labels_inferred,
    normalise_function,
    parse_building_type,
)
from realistic_indoor.building.room import Room

if TYPE_CHECKING:
    from collections.abc import Mapping

__all__ = [
    "CORRIDOR_FUNCTIONS",
    "HALL_FUNCTIONS",
    "INFERRED",
    "UNKNOWN_FUNCTIONS",
    "InferenceRules",
    "SizeThresholds",
    "elongation",
    "infer_labels",
    "infer_room_label",
    "labels_inferred",
    "lacks_labels",
    "size_thresholds",
]

CORRIDOR_FUNCTIONS = frozenset({"corridor", "hallway", "passage", "passageway", "aisle"})
"""Functional labels (normalised) of corridors."""

HALL_FUNCTIONS = frozenset({"hall", "lobby", "entrance", "entrance hall", "foyer", "atrium"})
"""Functional labels (normalised) of halls."""

UNKNOWN_FUNCTIONS = frozenset({"", "unknown", "none", "room", "space", "unlabelled", "unlabeled"})
"""Functional labels that say nothing about a room's use."""


@dataclass(frozen=True)
class InferenceRules:
    """Shape rules that recognise corridors and halls among rooms of unknown function.

    Attributes:
        corridor_min_elongation: Elongation (length over width, >= 1) of a corridor.
        corridor_min_doors: Doorways of a corridor of that elongation.
        long_corridor_min_elongation: Elongation from which fewer doors suffice.
        long_corridor_min_doors: Doorways of such a very elongated corridor.
        hall_min_doors: Doorways of a hall (a room larger than a small room with this many doors).
    """

    corridor_min_elongation: float = 3.0
    corridor_min_doors: int = 3
    long_corridor_min_elongation: float = 6.0
    long_corridor_min_doors: int = 2
    hall_min_doors: int = 4


@dataclass(frozen=True)
class SizeThresholds:
    """Area boundaries between small, medium and big rooms of one building type.

    Attributes:
        small_max_m2: Rooms below this area are small (m2).
        medium_max_m2: Rooms below this area (and not small) are medium; the rest big (m2).
    """

    small_max_m2: float
    medium_max_m2: float

    @classmethod
    def from_table(cls, table: Mapping[SemanticLabel, Mapping[str, float]]) -> SizeThresholds:
        """Geometric means of the mean areas of small and medium, and of medium and big rooms."""
        s, m, b = (
            table[lab]["area_mean"] for lab in (SemanticLabel.SMALL, SemanticLabel.MEDIUM, SemanticLabel.BIG)
        )
        return cls(math.sqrt(s * m), math.sqrt(m * b))

    def label(self, area_m2: float) -> SemanticLabel:
        """The size label of a room of ``area_m2`` square metres."""
        if area_m2 < self.small_max_m2:
            return SemanticLabel.SMALL
        return SemanticLabel.MEDIUM if area_m2 < self.medium_max_m2 else SemanticLabel.BIG


def size_thresholds(building_type: BuildingType | str) -> SizeThresholds:
    """Size thresholds of ``building_type`` from the paper's Table 1 (all types pooled if unknown)."""
    from realistic_indoor.models.reference import reference_table

    t = parse_building_type(building_type)
    return SizeThresholds.from_table(reference_table("all_types" if t is BuildingType.UNKNOWN else t))


def elongation(room: Room) -> float:
    """Length over width of the rectangle with the room's area and perimeter (>= 1).

    Unlike the bounding-box axes ratio it sees that an L-shaped or a slanted corridor is long
    and thin. A shape more compact than any rectangle gives 1.
    """
    area, half_perimeter = room.polygon.area, room.polygon.length / 2
    disc = (half_perimeter / 2) ** 2 - area
    if area <= 0 or disc <= 0:
        return 1.0
    long_side = half_perimeter / 2 + math.sqrt(disc)
    return long_side / (half_perimeter - long_side)


def infer_room_label(
    room: Room, doors: int, thresholds: SizeThresholds, rules: InferenceRules = InferenceRules()
) -> SemanticLabel:
    """The semantic label of one room from its function, shape, doorways and area (see module doc)."""
    function = normalise_function(room.function)
    if function in CORRIDOR_FUNCTIONS:
        return SemanticLabel.CORRIDOR
    if function in HALL_FUNCTIONS:
        return SemanticLabel.HALL
    size = thresholds.label(room.area)
    if function not in UNKNOWN_FUNCTIONS:
        return size
    e = elongation(room)
    if (e >= rules.corridor_min_elongation and doors >= rules.corridor_min_doors) or (
        e >= rules.long_corridor_min_elongation and doors >= rules.long_corridor_min_doors
    ):
        return SemanticLabel.CORRIDOR
    if doors >= rules.hall_min_doors and size is not SemanticLabel.SMALL:
        return SemanticLabel.HALL
    return size


def infer_labels(
    building: Building,
    building_type: BuildingType | str | None = None,
    rules: InferenceRules = InferenceRules(),
) -> Building:
    """The same building with every room's semantic label inferred.

    Args:
        building: The plan; its rooms' current semantic labels are ignored.
        building_type: Type whose size thresholds apply (default: the building's own type).
        rules: Shape rules for corridors and halls.

    Returns:
        A new building, ``metadata["semantic_labels"] == "inferred"``.
    """
    t = parse_building_type(building.building_type if building_type is None else building_type)
    thresholds = size_thresholds(t)
    rooms = tuple(
        Room(
            r.id, infer_room_label(r, len(building.doors_of[r.id]), thresholds, rules), r.function, r.outline
        )
        for r in building.rooms
    )
    return Building(
        building.building_type, rooms, building.doors, {**building.metadata, "semantic_labels": INFERRED}
    )


def lacks_labels(building: Building) -> bool:
    """Whether a plan carries no real semantic labels.

    True when its metadata says so (``semantic_labels`` is ``"missing"``), or when it has at
    least three rooms that all share one semantic label (no real building is all corridors or
    all medium rooms: that is a reader's default).
    """
    if building.metadata.get("semantic_labels") == "missing":
        return True
    return len(building.rooms) >= 3 and len({r.label for r in building.rooms}) == 1
