"""Room outlines of a plan file: cleaned, trivially repaired, and every repair said."""

from __future__ import annotations

import math

__all__ = ["MAX_SLIVER_FRACTION", "OutlineError", "clean_ring", "polygon_pieces", "repair_outline"]

Point = tuple[float, float]

MAX_SLIVER_FRACTION = 0.05
"""Largest share of a self-crossing outline's area that may be dropped as slivers."""


class OutlineError(ValueError):
    """An outline that cannot be made a simple polygon without guessing.

    Attributes:
        degenerate: True when the outline encloses no area at all (fewer than 3 distinct points
            or all on a line).
    """

    def __init__(self, message: str, degenerate: bool = False) -> None:
        super().__init__(message)
        self.degenerate = degenerate


def _collinear(a: Point, b: Point, c: Point) -> bool:
    """Whether ``b`` lies on the line through ``a`` and ``c`` (relative tolerance 1e-9).

    That includes a spike that turns back on itself and a repeated point.
    """
    cross = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])
    return abs(cross) <= 1e-9 * math.hypot(b[0] - a[0], b[1] - a[1]) * math.hypot(c[0] - b[0], c[1] - b[1])


def clean_ring(points: list[Point]) -> list[Point]:
    """The ring without its closing repeat, repeated vertices and collinear vertices.

    A collinear vertex lies on a straight line between its neighbours; zero-area spikes are such
    vertices too.

    Args:
        points: Vertices in order, closed or not.

    Returns:
        The remaining vertices, in the same order (fewer than 3 when nothing is enclosed).
    """
    ring = [p for i, p in enumerate(points) if i == 0 or p != points[i - 1]]
    while len(ring) > 1 and ring[0] == ring[-1]:
        ring.pop()
    changed = True
    while changed and len(ring) >= 3:
        changed = False
        for i in range(len(ring)):
            if _collinear(ring[i - 1], ring[i], ring[(i + 1) % len(ring)]):
                del ring[i]
                changed = True
                break
    return ring


def repair_outline(
    points: list[Point], m_per_px: float, max_sliver_fraction: float = MAX_SLIVER_FRACTION
) -> tuple[list[Point], str | None]:
    """Clean an outline and, if it is still not a simple polygon, repair it when that is trivial.

    Trivial repairs: vertices repeated or on a straight line (zero-area spikes) are dropped; a
    ring that crosses itself becomes the union of the pieces it encloses when they form one
    polygon (nothing lost), or its main piece when the rest are slivers of at most
    ``max_sliver_fraction`` of its area (the note gives the area dropped).

    Args:
        points: Vertices in pixels, as in the file.
        m_per_px: Scale, only to state dropped areas in square metres.
        max_sliver_fraction: Largest share of the area that may be dropped.

    Returns:
        The vertices of a valid simple polygon (pixels), and a one-line note of the repair made
        (``None`` when the outline was valid as given).

    Raises:
        OutlineError: If the outline encloses nothing (``degenerate``) or is invalid in a way
            that needs a human (e.g. a figure eight of two equal lobes).
    """
    from shapely.geometry import Polygon
    from shapely.validation import explain_validity

    ring = clean_ring(points)
    if len(ring) < 3:
        raise OutlineError(f"the outline encloses no area ({len(set(points))} distinct points)", True)
    poly = Polygon(ring)
    if poly.is_valid:
        if _valid_as_given(points):
            return ring, None
        why = explain_validity(Polygon(points))
        dropped = len(points) - len(ring)
        return (
            ring,
            f"outline was invalid ({why}); dropped {dropped} repeated or collinear vertices (zero-area spikes)",
        )
    return _repair_crossing(poly, explain_validity(poly), m_per_px, max_sliver_fraction)


def _valid_as_given(points: list[Point]) -> bool:
    from shapely.geometry import Polygon

    return len(set(points)) >= 3 and Polygon(points).is_valid


def _repair_crossing(poly, why: str, m_per_px: float, max_fraction: float) -> tuple[list[Point], str]:
    import shapely
    from shapely.geometry import Polygon

    pieces = [g for g in polygon_pieces(shapely.make_valid(poly)) if g.area > 0]
    if not pieces:
        raise OutlineError(f"the outline is not a polygon ({why}) and encloses no area", True)
    merged = shapely.unary_union(pieces)
    if isinstance(merged, Polygon):
        holes = f", filled {len(merged.interiors)} holes" if merged.interiors else ""
        note = (
            f"outline crossed itself ({why}); kept the union of the {len(pieces)} pieces it encloses{holes}"
        )
        return clean_ring(list(merged.exterior.coords)), note
    total = sum(p.area for p in pieces)
    main = max(pieces, key=lambda p: p.area)
    rest = total - main.area
    if rest > max_fraction * total:
        areas = ", ".join(f"{p.area * m_per_px**2:.2f}" for p in sorted(pieces, key=lambda p: -p.area))
        raise OutlineError(
            f"the outline is not a simple polygon ({why}): it encloses {len(pieces)} separate pieces "
            f"({areas} m2); fix its <bounding_polygon> so that it goes once around the room"
        )
    note = (
        f"outline crossed itself ({why}); kept its main piece and dropped {len(pieces) - 1} slivers "
        f"of {rest * m_per_px**2:.2f} m2 ({100 * rest / total:.1f}% of the room)"
    )
    return clean_ring(list(main.exterior.coords)), note


def polygon_pieces(geom) -> list:
    """The polygons of a shapely geometry (itself, or those of a collection, recursively)."""
    if geom.geom_type == "Polygon":
        return [geom]
    return [p for g in getattr(geom, "geoms", []) for p in polygon_pieces(g)]
