"""A room: an outline in metres with a semantic and a functional label."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING

from realistic_indoor.building.labels import SemanticLabel, parse_label

if TYPE_CHECKING:
    from shapely.geometry import Polygon

__all__ = ["Room"]

Point = tuple[float, float]


@dataclass(frozen=True, eq=True)
class Room:
    """One room (or corridor, or hall) of a building.

    Attributes:
        id: Identifier, unique within the building.
        label: Semantic label (corridor, hall, small, medium, big).
        function: Functional label in lower case (``"office"``, ``"classroom"``, ``"toilet"``, ...).
        outline: Vertices of the outline in metres, counter-clockwise, without repeating the
            first vertex. Generated rooms are rectilinear; real rooms may be any simple polygon.
    """

    id: str
    label: SemanticLabel
    function: str
    outline: tuple[Point, ...]

    def __post_init__(self) -> None:
        object.__setattr__(self, "label", parse_label(self.label))
        object.__setattr__(self, "outline", _normalise_outline(self.outline))

    @classmethod
    def from_polygon(cls, id: str, label: SemanticLabel | str, function: str, polygon: Polygon) -> Room:
        """Build a room from a shapely polygon (its exterior ring; holes are not kept)."""
        return cls(id, label, function, tuple(polygon.exterior.coords))

    @classmethod
    def rectangle(
        cls, id: str, label: SemanticLabel | str, function: str, box: tuple[float, float, float, float]
    ) -> Room:
        """Build an axis-aligned rectangular room from ``(xmin, ymin, xmax, ymax)`` in metres."""
        x0, y0, x1, y1 = box
        return cls(id, label, function, ((x0, y0), (x1, y0), (x1, y1), (x0, y1)))

    @cached_property
    def polygon(self) -> Polygon:
        """The outline as a shapely polygon (metres)."""
        from shapely.geometry import Polygon

        return Polygon(self.outline)

    @property
    def area(self) -> float:
        """Floor area in square metres."""
        return float(self.polygon.area)

    @property
    def bounds(self) -> tuple[float, float, float, float]:
        """Bounding box ``(xmin, ymin, xmax, ymax)`` in metres."""
        xs = [p[0] for p in self.outline]
        ys = [p[1] for p in self.outline]
        return (min(xs), min(ys), max(xs), max(ys))

    @property
    def axes_ratio(self) -> float:
        """Major over minor side of the axis-aligned bounding box (>= 1), as in the paper."""
        x0, y0, x1, y1 = self.bounds
        major, minor = max(x1 - x0, y1 - y0), min(x1 - x0, y1 - y0)
        return float(major / minor) if minor > 0 else float("inf")

    @property
    def is_rectangle(self) -> bool:
        """Whether the outline is an axis-aligned rectangle."""
        x0, y0, x1, y1 = self.bounds
        return abs(self.area - (x1 - x0) * (y1 - y0)) < 1e-9 * max(1.0, self.area)

    def __hash__(self) -> int:
        return hash((self.id, self.label, self.function, self.outline))


def _normalise_outline(outline: object) -> tuple[Point, ...]:
    """Return the vertices as float pairs, without a closing repeat, counter-clockwise."""
    pts = [(float(x), float(y)) for x, y in outline]  # type: ignore[attr-defined]
    if len(pts) > 1 and pts[0] == pts[-1]:
        pts.pop()
    twice_area = sum(
        pts[i][0] * pts[(i + 1) % len(pts)][1] - pts[(i + 1) % len(pts)][0] * pts[i][1]
        for i in range(len(pts))
    )
    if twice_area < 0:
        pts.reverse()
    return tuple(pts)
