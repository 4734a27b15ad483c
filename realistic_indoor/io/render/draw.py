"""``draw_plan``: a building drawn onto a matplotlib Axes."""

from __future__ import annotations

from typing import TYPE_CHECKING

from realistic_indoor.io.render.decorations import add_legend, add_scale_bar, auto_title
from realistic_indoor.io.render.layers import draw_doors, draw_functions, draw_rooms, draw_walls
from realistic_indoor.io.render.style import DEFAULT_STYLE, PlanStyle

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from realistic_indoor.building.building import Building

__all__ = ["draw_plan", "plan_limits"]

MARGIN = 0.02
"""Empty border around the plan, as a fraction of its longer side."""


def plan_limits(building: Building) -> tuple[float, float, float, float]:
    """The drawn extent ``(xmin, ymin, xmax, ymax)`` in metres: the rooms plus a small margin."""
    if not building.rooms:
        return (0.0, 0.0, 1.0, 1.0)
    x0, y0, x1, y1 = building.bounds
    pad = MARGIN * max(x1 - x0, y1 - y0, 1.0)
    return (x0 - pad, y0 - pad, x1 + pad, y1 + pad)


def draw_plan(
    building: Building,
    ax: Axes | None = None,
    *,
    show_functions: bool = False,
    title: str | bool = True,
    legend: bool = True,
    scale_bar: bool = True,
    style: PlanStyle | None = None,
) -> Axes:
    """Draw a plan: rooms coloured by semantic label, walls with their door gaps, door marks.

    Walls come from ``building.walls`` so openings show as gaps; interior doors are marked by a
    blue line across the opening, entrances by a thicker red one. Line widths follow the drawing
    scale (``style.wall_thickness_m`` on the plan), so large and small buildings both read well.

    Args:
        building: The building to draw.
        ax: Axes to draw on; ``None`` makes a new figure with the Agg canvas (no display needed).
        show_functions: Write each room's functional label inside it where the text fits.
        title: ``True`` for an automatic title (name, type, counts, area), a string for a
            custom one, ``False`` or ``""`` for none.
        legend: Add the legend of labels (with room counts), walls, doors and entrances.
        scale_bar: Add a scale bar in metres under the plan.
        style: Colours and line weights; :data:`~realistic_indoor.io.render.style.DEFAULT_STYLE`
            by default.

    Returns:
        The axes drawn on (equal aspect, axis lines hidden).
    """
    style = style or DEFAULT_STYLE
    if ax is None:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure

        fig = Figure(figsize=(8, 6), layout="constrained")
        FigureCanvasAgg(fig)
        ax = fig.add_subplot()
    x0, y0, x1, y1 = plan_limits(building)
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal")
    ax.set_axis_off()
    points_per_m = _points_per_metre(ax, x1 - x0, y1 - y0)
    lo, hi = style.wall_width_pt
    wall_pt = min(max(style.wall_thickness_m * points_per_m, lo), hi)
    if building.rooms:
        draw_rooms(ax, building, style)
        draw_walls(ax, building, style, wall_pt)
        draw_doors(ax, building, style, wall_pt)
        if show_functions:
            draw_functions(ax, building, style, points_per_m)
    if legend:
        add_legend(ax, building, style, wall_pt)
    if scale_bar:
        add_scale_bar(ax, max(x1 - x0, y1 - y0), style.wall_colour)
    text = auto_title(building) if title is True else (title or "")
    if text:
        ax.set_title(text, fontsize=10, loc="left")
    return ax


def _points_per_metre(ax: Axes, width_m: float, height_m: float) -> float:
    """The drawing scale the axes will have at its current size (points per metre)."""
    box = ax.get_position()
    fig_w, fig_h = ax.figure.get_size_inches()
    return 72.0 * min(box.width * fig_w / width_m, box.height * fig_h / height_m)
