"""Pictures of plans: PNG and SVG files, RGB arrays, and drawing onto your own matplotlib Axes.

Rooms are filled by semantic label (a colour-blind-safe palette), walls drawn with their door
gaps, doors and entrances marked, with a legend, a scale bar in metres and a title. matplotlib
is imported only when something is drawn, and always with the Agg canvas (no display).

Examples:
    >>> from realistic_indoor.io.render import write, render_array, draw_plan
    >>> write(building, "plan.png", dpi=150, show_functions=True)  # doctest: +SKIP
    >>> rgb = render_array(building, size_in=4, dpi=100, legend=False)  # doctest: +SKIP
    >>> draw_plan(building, ax=my_axes, title=False)  # doctest: +SKIP
"""

from realistic_indoor.io.render.draw import draw_plan
from realistic_indoor.io.render.figure import plan_figure, render_array, write
from realistic_indoor.io.render.style import DEFAULT_STYLE, LABEL_COLOURS, PlanStyle

__all__ = ["DEFAULT_STYLE", "LABEL_COLOURS", "PlanStyle", "draw_plan", "plan_figure", "render_array", "write"]
