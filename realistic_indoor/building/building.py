"""The building: typed rooms joined by doors, the object every other part consumes."""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from functools import cached_property
from typing import TYPE_CHECKING, Any

from realistic_indoor.building.door import Door
from realistic_indoor.building.labels import BuildingType, SemanticLabel, parse_building_type
from realistic_indoor.building.room import Room

if TYPE_CHECKING:
    import networkx as nx
    import numpy as np

__all__ = ["Building"]


@dataclass(frozen=True)
class Building:
    """A single-floor building.

    Attributes:
        building_type: Office, school, house or unknown.
        rooms: The rooms, in a fixed order (ids unique).
        doors: The doors, interior and exterior (ids unique).
        metadata: Where the building came from: ``source`` (a file) or ``generator`` (a name),
            ``params`` (generator parameters), ``seed``, and any notes. Kept by every format
            that can hold it.
    """

    building_type: BuildingType
    rooms: tuple[Room, ...]
    doors: tuple[Door, ...] = ()
    metadata: dict[str, Any] = field(default_factory=dict, compare=True, hash=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "building_type", parse_building_type(self.building_type))
        object.__setattr__(self, "rooms", tuple(self.rooms))
        object.__setattr__(self, "doors", tuple(self.doors))

    # -- lookup -----------------------------------------------------------------------------
    @cached_property
    def room_by_id(self) -> dict[str, Room]:
        """Rooms keyed by id."""
        return {r.id: r for r in self.rooms}

    def room(self, room_id: str) -> Room:
        """The room with id ``room_id`` (``KeyError`` if there is none)."""
        return self.room_by_id[room_id]

    @cached_property
    def doors_of(self) -> dict[str, tuple[Door, ...]]:
        """Doors of each room, keyed by room id (every room has an entry)."""
        out: dict[str, list[Door]] = {r.id: [] for r in self.rooms}
        for d in self.doors:
            for rid in d.rooms:
                if rid in out:
                    out[rid].append(d)
        return {k: tuple(v) for k, v in out.items()}

    @property
    def entrances(self) -> tuple[Door, ...]:
        """Exterior doors."""
        return tuple(d for d in self.doors if d.is_exterior)

    # -- summary ----------------------------------------------------------------------------
    @property
    def area(self) -> float:
        """Total floor area of the rooms, square metres."""
        return float(sum(r.area for r in self.rooms))

    @property
    def bounds(self) -> tuple[float, float, float, float]:
        """Bounding box of all rooms ``(xmin, ymin, xmax, ymax)``, metres."""
        boxes = [r.bounds for r in self.rooms]
        return (
            min(b[0] for b in boxes),
            min(b[1] for b in boxes),
            max(b[2] for b in boxes),
            max(b[3] for b in boxes),
        )

    def label_counts(self) -> dict[SemanticLabel, int]:
        """Number of rooms per semantic label (every label present, possibly 0)."""
        counts = Counter(r.label for r in self.rooms)
        return {lab: counts.get(lab, 0) for lab in SemanticLabel}

    # -- derived structures -------------------------------------------------------------------
    def graph(self, include_outside: bool = False) -> nx.MultiGraph:
        """The topology: a node per room, an edge per door.

        Args:
            include_outside: Add a node ``"outside"`` joined to the rooms by the exterior doors.

        Returns:
            A ``networkx.MultiGraph``; nodes carry ``label``, ``function`` and ``area``
            (m2), edges are keyed by door id and carry ``width_m``.
        """
        from realistic_indoor.building.topology import building_graph

        return building_graph(self, include_outside=include_outside)

    @cached_property
    def walls(self) -> np.ndarray:
        """Wall segments with gaps at the doors: a read-only ``(N, 2, 2)`` array of end points (m).

        Computed once per building (see :func:`realistic_indoor.building.walls.wall_segments`).
        """
        from realistic_indoor.building.walls import wall_segments

        return wall_segments(self)

    def validate(self, **kwargs: Any) -> list:
        """Violated invariants, as :func:`realistic_indoor.building.check_building` finds them."""
        from realistic_indoor.building.check import check_building

        return check_building(self, **kwargs)

    def _type_text(self) -> str:
        kind = self.building_type.value
        if self.metadata.get("generator") == "random":
            return f"{kind} (random baseline map, World Generator rules)"
        return kind

    def summary(self) -> str:
        """A few human-readable lines: type, rooms by label, area, doors."""
        counts = self.label_counts()
        by_label = ", ".join(f"{n} {lab.value}" for lab, n in counts.items() if n)
        x0, y0, x1, y1 = self.bounds
        return "\n".join(
            [
                f"type: {self._type_text()}",
                f"rooms: {len(self.rooms)} ({by_label})",
                f"area: {self.area:.1f} m2 in a {x1 - x0:.1f} m x {y1 - y0:.1f} m footprint",
                f"doors: {len(self.doors)} ({len(self.entrances)} exterior)",
            ]
        )
