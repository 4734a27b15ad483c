"""A whole picture of a plan: figure layout, PNG/SVG files and RGB arrays."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from realistic_indoor.checks import require_between
from realistic_indoor.errors import ConfigError
from realistic_indoor.files import atomic_path
from realistic_indoor.io.render.draw import draw_plan, plan_limits

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from realistic_indoor.building.building import Building
    from realistic_indoor.io.render.style import PlanStyle

__all__ = ["MAX_PICTURE_PIXELS", "plan_figure", "render_array", "write"]

PAD_IN = 0.15
TITLE_IN = 0.5
SCALE_BAR_IN = 0.4
LEGEND_IN = 1.6
MIN_LEGEND_HEIGHT_IN = 2.4
MIN_TITLED_WIDTH_IN = 4.6
SUFFIXES = (".png", ".svg")
MIN_SIZE_IN, MAX_SIZE_IN = 0.5, 200.0
"""Range of a picture's longer side (inches)."""
MIN_DPI, MAX_DPI = 10.0, 2400.0
"""Range of the pixels per inch of a raster picture."""
MAX_PICTURE_PIXELS = 64_000_000
"""Largest picture drawn (pixels, width times height): 8,000 x 8,000, about 250 MB while drawn."""


def plan_figure(
    building: Building,
    *,
    size_in: float = 8.0,
    dpi: float = 150.0,
    show_functions: bool = False,
    title: str | bool = True,
    legend: bool = True,
    scale_bar: bool = True,
    style: PlanStyle | None = None,
) -> Figure:
    """A figure holding the plan at a known scale, with room for its title, legend and scale bar.

    Args:
        building: The building.
        size_in: Length of the plan's longer side on the figure, inches, in [0.5, 200].
        dpi: Pixels per inch of raster output, in [10, 2400].
        show_functions: Write room functions inside the rooms where they fit.
        title: ``True`` for the automatic title, a string for a custom one, ``False`` for none.
        legend: Draw the legend right of the plan.
        scale_bar: Draw a scale bar under the plan.
        style: Colours and line weights (default style if ``None``).

    Returns:
        A matplotlib ``Figure`` on an Agg canvas (no display needed; not registered with pyplot).

    Raises:
        ConfigError: If ``size_in`` is outside [0.5, 200] inches or ``dpi`` outside [10, 2400],
            or the picture would exceed
            :data:`MAX_PICTURE_PIXELS`.
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    require_between("plan_figure", "size_in", size_in, MIN_SIZE_IN, MAX_SIZE_IN, "inches")
    require_between("plan_figure", "dpi", dpi, MIN_DPI, MAX_DPI, "pixels per inch")
    x0, y0, x1, y1 = plan_limits(building)
    scale = size_in / max(x1 - x0, y1 - y0)
    plan_w, plan_h = (x1 - x0) * scale, (y1 - y0) * scale
    top = PAD_IN + (TITLE_IN if title else 0.0)
    bottom = PAD_IN + (SCALE_BAR_IN if scale_bar else 0.0)
    fig_w = 2 * PAD_IN + plan_w + (LEGEND_IN if legend else 0.0)
    fig_h = top + plan_h + bottom
    fig_w = max(fig_w, MIN_TITLED_WIDTH_IN if title else 0.0)
    fig_h = max(fig_h, top + MIN_LEGEND_HEIGHT_IN if legend else 0.0)
    _check_pixels(fig_w * dpi, fig_h * dpi)
    fig = Figure(figsize=(fig_w, fig_h), dpi=dpi)
    FigureCanvasAgg(fig)
    ax = fig.add_axes((PAD_IN / fig_w, (fig_h - top - plan_h) / fig_h, plan_w / fig_w, plan_h / fig_h))
    draw_plan(
        building,
        ax,
        show_functions=show_functions,
        title=title,
        legend=legend,
        scale_bar=scale_bar,
        style=style,
    )
    return fig


def _check_pixels(width_px: float, height_px: float) -> None:
    if width_px * height_px > MAX_PICTURE_PIXELS:
        raise ConfigError(
            f"a picture of {width_px:,.0f} x {height_px:,.0f} pixels exceeds the limit of "
            f"{MAX_PICTURE_PIXELS:,} pixels; use a smaller size (inches) or dpi"
        )


def render_array(building: Building, **options: Any) -> np.ndarray:
    """The plan picture as an RGB image, the same pixels a PNG written with the same options holds.

    Args:
        building: The building.
        **options: Any argument of :func:`plan_figure` (``size_in``, ``dpi``, ``show_functions``,
            ``title``, ``legend``, ``scale_bar``, ``style``).

    Returns:
        A ``(H, W, 3)`` uint8 array, row 0 at the top of the picture.
    """
    fig = plan_figure(building, **options)
    fig.canvas.draw()
    return np.asarray(fig.canvas.buffer_rgba())[..., :3].copy()


def write(building: Building, path: str | Path, **options: Any) -> list[Path]:
    """Write the plan picture as PNG or SVG, chosen by the extension of ``path``.

    The output is deterministic: the same building and options give the same bytes (no time
    stamp, fixed SVG ids).

    Args:
        building: The building.
        path: Output file, ending in ``.png`` or ``.svg``.
        **options: Any argument of :func:`plan_figure`.

    Returns:
        ``[path]``.

    Raises:
        ConfigError: If the extension is neither ``.png`` nor ``.svg``.
    """
    import matplotlib

    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in SUFFIXES:
        raise ConfigError(f"{path}: pictures are written as {' or '.join(SUFFIXES)}, not {suffix!r}")
    fig = plan_figure(building, **options)
    fmt = suffix[1:]
    metadata = {"Date": None} if fmt == "svg" else {}
    with matplotlib.rc_context({"svg.hashsalt": "realistic-indoor"}), atomic_path(path) as tmp:
        fig.savefig(tmp, format=fmt, metadata=metadata)
    return [path]
