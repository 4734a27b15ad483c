"""Door geometry from a plan's portals: centre, width and wall direction of each doorway.

A portal names a ``<linesegment>`` that each of the two spaces it joins lists in its own
``<space_representation>``. In the shared real plans nearly every such segment has zero length;
when the two spaces' copies sit at different points at least a door's width apart along the
wall, they mark the two jambs of the opening (most are exactly one scale unit apart: the
annotators calibrated the scale on a door).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from realistic_indoor.building.check import MIN_DOOR_WIDTH_M

__all__ = ["DoorGeometry", "door_between", "door_from_copies", "nearest_edge_angle"]

Point = tuple[float, float]
Segment = tuple[Point, Point]

MIN_JAMB_GAP_M = MIN_DOOR_WIDTH_M
"""Two zero-length copies of a portal at least this far apart (the narrowest door) are its jambs (m)."""

MAX_JAMB_ANGLE_RAD = math.radians(20.0)
"""Largest angle between two jambs' line and the wall for them to count as jambs."""


@dataclass(frozen=True)
class DoorGeometry:
    """Where a doorway is.

    Attributes:
        x: Centre, metres.
        y: Centre, metres.
        width_m: Width of the opening, metres.
        angle_rad: Direction of the wall, radians in ``[0, pi)``.
        source: How it was found: ``"segment"`` (a portal segment of non-zero length),
            ``"jambs"`` (two copies marking the jambs), ``"point"`` (a zero-length portal; default
            width, wall direction from the nearest outline edge) or ``"placed"`` (no segment in
            the file; on the wall the two rooms share).
    """

    x: float
    y: float
    width_m: float
    angle_rad: float
    source: str


def nearest_edge_angle(outlines: list[np.ndarray], p: Point) -> float:
    """Direction (radians in ``[0, pi)``) of the outline edge nearest ``p``.

    Of edges equally near (a point at a corner), the one with the most room on both sides of the
    point's projection wins, as a door sits inside a wall, not at its end.
    """
    a = np.concatenate(outlines)
    b = np.concatenate([np.roll(o, -1, axis=0) for o in outlines])
    d = b - a
    length2 = np.maximum((d**2).sum(axis=1), 1e-300)
    t = np.clip(((np.asarray(p) - a) * d).sum(axis=1) / length2, 0.0, 1.0)
    dist = np.hypot(*(a + t[:, None] * d - np.asarray(p)).T)
    clearance = np.minimum(t, 1.0 - t) * np.sqrt(length2)
    candidates = np.flatnonzero(dist <= dist.min() + 1e-6)
    k = candidates[np.argmax(clearance[candidates])]
    return math.atan2(d[k, 1], d[k, 0]) % math.pi


def door_from_copies(
    copies: list[Segment], outlines: list[np.ndarray], default_width_m: float
) -> DoorGeometry:
    """The doorway given by the copies of one portal segment (metres).

    Args:
        copies: The segment as each space lists it (one or more).
        outlines: Outlines of the rooms the portal joins, ``(n, 2)`` arrays in metres.
        default_width_m: Width of a doorway whose segment has no length.
    """
    segs = np.asarray(copies, dtype=float)
    lengths = np.hypot(*(segs[:, 1] - segs[:, 0]).T)
    real = segs[lengths > 1e-9]
    if len(real):
        mid = real.mean(axis=1).mean(axis=0)
        d = real[0, 1] - real[0, 0]
        return DoorGeometry(
            mid[0], mid[1], float(lengths[lengths > 1e-9].mean()), math.atan2(d[1], d[0]) % math.pi, "segment"
        )
    pts = np.unique(segs[:, 0], axis=0)
    centre = pts.mean(axis=0)
    wall = nearest_edge_angle(outlines, (centre[0], centre[1]))
    if len(pts) == 2:
        gap = pts[1] - pts[0]
        along = math.atan2(gap[1], gap[0]) % math.pi
        off = min(abs(along - wall), math.pi - abs(along - wall))
        if math.hypot(*gap) >= MIN_JAMB_GAP_M and off <= MAX_JAMB_ANGLE_RAD:
            return DoorGeometry(centre[0], centre[1], math.hypot(*gap), along, "jambs")
    return DoorGeometry(centre[0], centre[1], default_width_m, wall, "point")


def door_between(outline_a: np.ndarray, outline_b: np.ndarray, default_width_m: float) -> DoorGeometry:
    """A doorway placed between two rooms when the file gives no segment for it.

    It goes at the middle of the longest stretch of wall the two outlines share (within 5 cm of
    each other, or of their gap if they do not touch); with nothing shared, at the midpoint of the
    nearest points of the two outlines.
    """
    from shapely.geometry import LineString, Polygon
    from shapely.ops import nearest_points

    pa, pb = Polygon(outline_a), Polygon(outline_b)
    gap = pa.distance(pb)
    shared = pa.exterior.intersection(pb.buffer(gap + 0.05))
    pieces = [g for g in getattr(shared, "geoms", [shared]) if isinstance(g, LineString) and g.length > 0]
    if pieces:
        mid = max(pieces, key=lambda g: g.length).interpolate(0.5, normalized=True)
        centre = (mid.x, mid.y)
    else:
        a, b = nearest_points(pa.exterior, pb.exterior)
        centre = ((a.x + b.x) / 2, (a.y + b.y) / 2)
    angle = nearest_edge_angle([outline_a, outline_b], centre)
    return DoorGeometry(centre[0], centre[1], default_width_m, angle, "placed")
