"""Overlapping room outlines of a plan file: the overlap is cut out of the larger room.

Annotators trace each room on its own, so neighbouring outlines often cross by a few
centimetres, and a small room (a closet, a washroom) is sometimes drawn inside the outline of
the big one around it. The small room's outline is the more careful one, and losing the overlap
costs the large room the smaller share of its area, so the large room gives it up.
"""

from __future__ import annotations

import numpy as np

from realistic_indoor.building.check import OVERLAP_TOLERANCE_M2
from realistic_indoor.io.floorplan.outline import MAX_SLIVER_FRACTION, clean_ring, polygon_pieces
from realistic_indoor.io.floorplan.repairs import RepairLog

__all__ = ["cut_overlaps"]

Point = tuple[float, float]


def cut_overlaps(
    ids: list[str],
    rings: list[list[Point]],
    m_per_px: float,
    log: RepairLog,
    *,
    tolerance_m2: float = OVERLAP_TOLERANCE_M2,
    max_sliver_fraction: float = MAX_SLIVER_FRACTION,
) -> list[list[Point]]:
    """Cut every overlap larger than ``tolerance_m2`` out of the larger of the two rooms.

    Pairs are taken in file order (of the first space, then the second), each on the outlines
    as earlier cuts left them. Of two rooms of equal area, the later one in the file gives up
    the overlap. A cut that would leave the larger room with a hole (the smaller lies wholly
    inside it, touching none of its walls) or split it into pieces of which the rest exceed
    ``max_sliver_fraction`` of its area is not made: both outlines are kept as given.
    Every overlap is reported through ``log`` as an ``overlap`` defect.

    Args:
        ids: Space ids, in file order.
        rings: Their outlines (pixels), simple polygons.
        m_per_px: Scale (m per pixel), for areas in square metres.
        log: Where repairs are recorded (raises under ``strict``).
        tolerance_m2: Overlaps up to this area count as rooms touching (m2), as in
            :func:`realistic_indoor.building.check_building`.
        max_sliver_fraction: Largest share of the larger room's area that may be dropped as
            slivers left over by a cut.

    Returns:
        The outlines after the cuts (the same list objects where nothing changed).
    """
    import shapely
    from shapely.geometry import Polygon

    polys = [Polygon(r) for r in rings]
    area_m2 = m_per_px**2
    hits = shapely.STRtree(polys).query(polys, predicate="intersects")
    first, second = hits[:, hits[0] < hits[1]]
    given = np.asarray(polys, dtype=object)
    shared_m2 = shapely.area(shapely.intersection(given[first], given[second])) * area_m2
    # Cuts only shrink rooms: a pair under the tolerance as given stays under it.
    big = shared_m2 > tolerance_m2
    pairs = sorted(zip(first[big].tolist(), second[big].tolist(), strict=True))
    out = list(rings)
    for i, j in pairs:
        shared = polys[i].intersection(polys[j]).area * area_m2
        if shared <= tolerance_m2:
            continue
        small, large = (j, i) if polys[i].area > polys[j].area else (i, j)
        element = f'space id="{ids[small]}" and space id="{ids[large]}"'
        problem = f"the outlines overlap by {shared:.2f} m2"
        ring, why_not = _cut(polys[large], polys[small], max_sliver_fraction)
        if ring is None:
            log.defect("overlap", element, problem, f"kept both outlines as given: {why_not}")
            continue
        before = polys[large].area * area_m2
        polys[large], out[large] = Polygon(ring), ring
        action = (
            f'cut the overlap out of the larger space "{ids[large]}" '
            f"({before:.2f} m2 -> {polys[large].area * area_m2:.2f} m2)"
        )
        log.defect("overlap", element, problem, action)
    return out


def _cut(large, small, max_fraction: float) -> tuple[list[Point] | None, str]:
    """``large`` without ``small`` as a simple ring, or ``None`` and why that is impossible."""
    from shapely.geometry import Polygon

    rest = large.difference(small)
    pieces = sorted((p for p in polygon_pieces(rest) if p.area > 0), key=lambda p: -p.area)
    if not pieces:
        return None, "the larger outline lies wholly inside the smaller"
    main, dropped = pieces[0], sum(p.area for p in pieces[1:])
    if dropped > max_fraction * large.area:
        return None, f"the cut would split the larger space into {len(pieces)} pieces"
    if main.interiors:
        return None, "the smaller space lies inside the larger without touching its walls"
    coords = list(main.exterior.coords)[:-1]
    ring = clean_ring(coords)
    if len(ring) < 3 or not Polygon(ring).is_valid:
        ring = coords
    return ring, ""
