"""A footprint painted into regions: corridor pieces, halls, strips of rooms, end rooms, courtyards.

Every layout of offices and schools (:mod:`~realistic_indoor.generator.blocks`,
:mod:`~realistic_indoor.generator.wings`) paints its footprint into :class:`FloorRegions`; the
rest of :mod:`~realistic_indoor.generator.rooms` turns them into rooms. All in grid units.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from realistic_indoor.generator.geometry import Rect

__all__ = ["Bay", "FloorRegions"]


@dataclass
class Bay:
    """A strip of rooms along a corridor.

    Attributes:
        rect: The strip (units).
        axis: ``"x"`` if the strip runs along x, ``"y"`` if along y.
        access: Side facing the corridor: ``"S"``, ``"N"``, ``"W"`` or ``"E"``.
    """

    rect: Rect
    axis: str
    access: str

    @property
    def length(self) -> int:
        """Extent along the corridor (units)."""
        x0, y0, x1, y1 = self.rect
        return x1 - x0 if self.axis == "x" else y1 - y0

    @property
    def depth(self) -> int:
        """Extent away from the corridor (units)."""
        x0, y0, x1, y1 = self.rect
        return y1 - y0 if self.axis == "x" else x1 - x0

    def local(self, t0: int, t1: int, u0: int, u1: int) -> Rect:
        """The rectangle at ``t0..t1`` along the strip and ``u0..u1`` from the corridor (units)."""
        x0, y0, x1, y1 = self.rect
        if self.access == "S":
            return (x0 + t0, y0 + u0, x0 + t1, y0 + u1)
        if self.access == "N":
            return (x0 + t0, y1 - u1, x0 + t1, y1 - u0)
        if self.access == "W":
            return (x0 + u0, y0 + t0, x0 + u1, y0 + t1)
        return (x1 - u1, y0 + t0, x1 - u0, y0 + t1)


@dataclass
class FloorRegions:
    """A footprint painted into regions: what a layout hands to the room toolkit.

    Attributes:
        corridors: Straight corridor pieces (rectangles), before cutting into segments.
        halls: ``(key, rectangles)`` of every hall (one rectangle until rooms are set into it);
            the key names the hall in its layout (a skeleton node, a block's hall number).
        bays: Room strips.
        ends: Small rooms closing dead-end corridors (rectangles).
        holes: Courtyards: outside cells enclosed by the building.
        area: Footprint area (square units).
    """

    corridors: list[Rect] = field(default_factory=list)
    halls: list[tuple[tuple[object, ...], list[Rect]]] = field(default_factory=list)
    bays: list[Bay] = field(default_factory=list)
    ends: list[Rect] = field(default_factory=list)
    holes: list[Rect] = field(default_factory=list)
    area: int = 0
