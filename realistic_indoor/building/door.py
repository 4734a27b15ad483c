"""A door: an opening of some width on the wall between two rooms, or to the outside."""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["DEFAULT_DOOR_WIDTH_M", "Door"]

DEFAULT_DOOR_WIDTH_M = 0.9
"""Width of a doorway whose plan gives none (m)."""


@dataclass(frozen=True)
class Door:
    """A doorway in a wall.

    Attributes:
        id: Identifier, unique within the building.
        room_a: Id of one room the door opens into.
        room_b: Id of the other room, or ``None`` for an exterior door (an entrance).
        x: Centre of the opening, metres.
        y: Centre of the opening, metres.
        width_m: Width of the opening, metres.
        angle_rad: Direction of the wall at the door, radians in ``[0, pi)``.
    """

    id: str
    room_a: str
    room_b: str | None
    x: float
    y: float
    width_m: float = DEFAULT_DOOR_WIDTH_M
    angle_rad: float = 0.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "x", float(self.x))
        object.__setattr__(self, "y", float(self.y))
        object.__setattr__(self, "width_m", float(self.width_m))
        object.__setattr__(self, "angle_rad", float(self.angle_rad) % math.pi)

    @property
    def is_exterior(self) -> bool:
        """Whether the door leads outside the building."""
        return self.room_b is None

    @property
    def rooms(self) -> tuple[str, ...]:
        """Ids of the rooms the door joins (one for an exterior door)."""
        return (self.room_a,) if self.room_b is None else (self.room_a, self.room_b)

    @property
    def direction(self) -> tuple[float, float]:
        """Unit vector along the wall."""
        return (math.cos(self.angle_rad), math.sin(self.angle_rad))

    @property
    def segment(self) -> tuple[tuple[float, float], tuple[float, float]]:
        """End points of the opening along the wall, metres."""
        dx, dy = self.direction
        h = self.width_m / 2
        return ((self.x - h * dx, self.y - h * dy), (self.x + h * dx, self.y + h * dy))

    def other(self, room_id: str) -> str | None:
        """The room on the other side of the door from ``room_id`` (``None``: outside)."""
        return self.room_b if room_id == self.room_a else self.room_a
