"""The paper's per-room feature vector F = <a, rt, d, l_s, l_m, l_b, l_c, l_h>."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from realistic_indoor.building.labels import CIRCULATION_LABELS, ROOM_LABELS, SemanticLabel

if TYPE_CHECKING:
    from collections.abc import Iterable

    from realistic_indoor.building.building import Building

__all__ = ["RoomFeatures", "all_room_features", "room_features"]


@dataclass(frozen=True)
class RoomFeatures:
    """Features of one room, as in the paper.

    Attributes:
        room_id: The room.
        label: Its semantic label.
        function: Its functional label.
        area: Floor area, m2 (``a``).
        axes_ratio: Major over minor side of the bounding box, >= 1 (``rt``).
        doors: Number of doorways, exterior ones included (``d``).
        doors_to: Doorways leading to rooms of each semantic label (``l_s ... l_h``); exterior
            doors are in ``doors`` but in none of these.
    """

    room_id: str
    label: SemanticLabel
    function: str
    area: float
    axes_ratio: float
    doors: int
    doors_to: dict[SemanticLabel, int]

    def vector(self) -> tuple[float, ...]:
        """``(a, rt, d, l_s, l_m, l_b, l_c, l_h)`` as floats, in the paper's order."""
        order = (*ROOM_LABELS, *CIRCULATION_LABELS)
        return (self.area, self.axes_ratio, float(self.doors), *(float(self.doors_to[k]) for k in order))


def room_features(building: Building) -> list[RoomFeatures]:
    """The feature vector of every room of ``building``, in room order."""
    out = []
    for r in building.rooms:
        to = dict.fromkeys(SemanticLabel, 0)
        doors = building.doors_of[r.id]
        for d in doors:
            other = d.other(r.id)
            if other is not None and other in building.room_by_id:
                to[building.room(other).label] += 1
        out.append(RoomFeatures(r.id, r.label, r.function, r.area, r.axes_ratio, len(doors), to))
    return out


def all_room_features(buildings: Iterable[Building]) -> list[RoomFeatures]:
    """Features of every room of every building, concatenated."""
    return [f for b in buildings for f in room_features(b)]
