"""What surrounds a plan: its title, the legend of labels, the scale bar."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from realistic_indoor.building.labels import SemanticLabel

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from realistic_indoor.building.building import Building
    from realistic_indoor.io.render.style import PlanStyle

__all__ = ["add_legend", "add_scale_bar", "auto_title", "nice_length"]

LEGEND_ORDER = (
    SemanticLabel.CORRIDOR,
    SemanticLabel.HALL,
    SemanticLabel.SMALL,
    SemanticLabel.MEDIUM,
    SemanticLabel.BIG,
)


def auto_title(building: Building) -> str:
    """Two lines: the plan's name (``name``, source file or generator) and its type and counts."""
    meta = building.metadata
    if meta.get("name"):
        name = str(meta["name"])
    elif meta.get("source"):
        name = Path(str(meta["source"])).stem
    elif meta.get("generator"):
        seed = meta.get("seed")
        name = f"generator: {meta['generator']}" + (f", seed {seed}" if seed is not None else "")
    else:
        name = "building"
    counts = (
        f"{building.building_type.value} · {len(building.rooms)} rooms · "
        f"{len(building.doors)} doors ({len(building.entrances)} exterior) · {building.area:,.0f} m²"
    )
    return f"{name}\n{counts}"


def add_legend(ax: Axes, building: Building, style: PlanStyle, wall_width_pt: float) -> None:
    """A legend right of the plan: every semantic label (with its room count), walls, doors."""
    from matplotlib.legend_handler import HandlerTuple
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    counts = building.label_counts()
    handles = [
        Patch(facecolor=style.label_colours[lab], edgecolor=style.wall_colour, linewidth=0.5)
        for lab in LEGEND_ORDER
    ]
    labels = [f"{lab.value} ({counts[lab]})" for lab in LEGEND_ORDER]
    handles.append(Line2D([], [], color=style.wall_colour, linewidth=wall_width_pt))
    labels.append("wall")
    handles.append(
        Line2D([], [], color=style.door_colour, linewidth=style.door_width_pt(wall_width_pt, False))
    )
    labels.append("door")
    entrance_line = Line2D(
        [], [], color=style.entrance_colour, linewidth=style.door_width_pt(wall_width_pt, True)
    )
    entrance_marker = Line2D(
        [],
        [],
        linestyle="none",
        marker="^",
        markersize=style.entrance_marker_pt,
        color=style.entrance_colour,
        markeredgecolor="white",
        markeredgewidth=0.5,
    )
    handles.append((entrance_line, entrance_marker))
    labels.append("entrance")
    ax.legend(
        handles,
        labels,
        loc="upper left",
        bbox_to_anchor=(1.01, 1.0),
        borderaxespad=0.0,
        frameon=False,
        fontsize=8,
        handler_map={tuple: HandlerTuple(ndivide=None, pad=0.0)},
    )


def nice_length(span_m: float) -> float:
    """A round scale-bar length (1, 2 or 5 times a power of ten) of about a fifth of ``span_m``."""
    import math

    target = max(span_m / 5, 1e-3)
    power = 10 ** math.floor(math.log10(target))
    return max(m * power for m in (1, 2, 5) if m * power <= target)


def add_scale_bar(ax: Axes, span_m: float, colour: str) -> None:
    """A scale bar in metres under the plan's lower-left corner."""
    from mpl_toolkits.axes_grid1.anchored_artists import AnchoredSizeBar

    length = nice_length(span_m)
    text = f"{length:g} m"
    bar = AnchoredSizeBar(
        ax.transData,
        length,
        text,
        loc="upper left",
        bbox_to_anchor=(0.0, 0.0),
        bbox_transform=ax.transAxes,
        borderpad=0.2,
        sep=3,
        frameon=False,
        size_vertical=span_m / 250,
        color=colour,
        fontproperties={"size": 8},
    )
    ax.add_artist(bar)
