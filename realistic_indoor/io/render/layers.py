"""The drawn layers of a plan: room fills, walls, door marks, function labels.

Each layer is one matplotlib collection, so a plan of a thousand rooms draws in a few calls.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from realistic_indoor.building.building import Building
    from realistic_indoor.building.door import Door
    from realistic_indoor.io.render.style import PlanStyle

__all__ = ["draw_doors", "draw_functions", "draw_rooms", "draw_walls"]


def draw_rooms(ax: Axes, building: Building, style: PlanStyle) -> None:
    """Fill every room with its semantic label's colour (one ``PolyCollection``)."""
    from matplotlib.collections import PolyCollection

    verts = [np.asarray(r.outline, dtype=float) for r in building.rooms]
    colours = [style.label_colours[r.label] for r in building.rooms]
    ax.add_collection(PolyCollection(verts, facecolors=colours, edgecolors="none", zorder=1), autolim=False)


def draw_walls(ax: Axes, building: Building, style: PlanStyle, width_pt: float) -> None:
    """Draw ``building.walls`` (door gaps included) as one ``LineCollection``."""
    from matplotlib.collections import LineCollection

    ax.add_collection(
        LineCollection(
            building.walls, colors=style.wall_colour, linewidths=width_pt, capstyle="round", zorder=2
        ),
        autolim=False,
    )


def draw_doors(ax: Axes, building: Building, style: PlanStyle, wall_width_pt: float) -> None:
    """Mark each doorway with a coloured line across its opening.

    Entrances get a thicker line in their own colour and a triangle pointing into the building,
    so they stay visible on the plan of a whole school.
    """
    from matplotlib.collections import LineCollection

    for exterior, colour in ((False, style.door_colour), (True, style.entrance_colour)):
        segments = [d.segment for d in building.doors if d.is_exterior == exterior]
        if segments:
            ax.add_collection(
                LineCollection(
                    np.asarray(segments, dtype=float),
                    colors=colour,
                    linewidths=style.door_width_pt(wall_width_pt, exterior),
                    capstyle="butt",
                    zorder=3,
                ),
                autolim=False,
            )
    line_pt = style.door_width_pt(wall_width_pt, True)
    for door in building.entrances:
        inward = _inward_normal(building, door)
        if inward is not None:
            _entrance_marker(ax, door, inward, line_pt, style)


def _entrance_marker(
    ax: Axes, door: Door, inward: tuple[float, float], line_pt: float, style: PlanStyle
) -> None:
    """A triangle just inside an entrance, pointing into the building."""
    import math

    from matplotlib.transforms import offset_copy

    size = style.entrance_marker_pt
    shift = line_pt / 2 + size / 2
    nx, ny = inward
    ax.plot(
        door.x,
        door.y,
        marker=(3, 0, math.degrees(math.atan2(ny, nx)) - 90.0),
        markersize=size,
        color=style.entrance_colour,
        markeredgecolor="white",
        markeredgewidth=0.5,
        zorder=5,
        transform=offset_copy(ax.transData, fig=ax.figure, x=shift * nx, y=shift * ny, units="points"),
    )


def _inward_normal(building: Building, door: Door) -> tuple[float, float] | None:
    """Unit normal of an exterior door's wall pointing into its room.

    ``None`` when the door's room is unknown or neither side of the door is inside it.
    """
    from shapely.geometry import Point

    room = building.room_by_id.get(door.room_a)
    if room is None:
        return None
    dx, dy = door.direction
    probe = max(0.25, door.width_m / 2)
    for nx, ny in ((-dy, dx), (dy, -dx)):
        if room.polygon.contains(Point(door.x + probe * nx, door.y + probe * ny)):
            return (nx, ny)
    return None


def draw_functions(ax: Axes, building: Building, style: PlanStyle, points_per_m: float) -> int:
    """Write each room's function inside it where the text fits (turned 90 degrees in narrow rooms).

    Args:
        ax: The axes.
        building: The building.
        style: Font size and colours.
        points_per_m: Drawing scale, points per metre, to know which labels fit.

    Returns:
        The number of labels written.
    """
    from shapely.geometry import box

    size_pt = style.function_font_pt
    written = 0
    for room in building.rooms:
        text = room.function.replace("_", " ")
        if not text:
            continue
        poly = room.polygon
        anchor = poly.centroid if poly.contains(poly.centroid) else poly.representative_point()
        long_m = (0.6 * size_pt * len(text) + 2) / points_per_m
        short_m = 1.3 * size_pt / points_per_m
        for rotation, (w, h) in ((0, (long_m, short_m)), (90, (short_m, long_m))):
            if poly.contains(box(anchor.x - w / 2, anchor.y - h / 2, anchor.x + w / 2, anchor.y + h / 2)):
                ax.text(
                    anchor.x,
                    anchor.y,
                    text,
                    fontsize=size_pt,
                    rotation=rotation,
                    ha="center",
                    va="center",
                    color=style.wall_colour,
                    zorder=4,
                )
                written += 1
                break
    return written
