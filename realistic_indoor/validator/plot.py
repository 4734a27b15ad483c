"""One figure comparing sets of maps with a reference: the picture a user looks at first.

Six panels: label shares; room area, axes ratio and doorways per semantic label (box plots per
set, the reference's mean +/- standard deviation as a black diamond with a bar); the
connectivity shares; the realism scores. Drawn with matplotlib's object API (no pyplot, no
display needed), imported only when a figure is asked for.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING, Any, NamedTuple

from realistic_indoor.building.labels import SemanticLabel
from realistic_indoor.files import atomic_path, check_output_path
from realistic_indoor.validator.connectivity import CONNECTIVITY_METRICS
from realistic_indoor.validator.features import all_room_features

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from realistic_indoor.validator.compare import Comparison
    from realistic_indoor.validator.features import RoomFeatures

__all__ = ["PLOT_SUFFIXES", "comparison_figure", "plot_comparison"]

PLOT_SUFFIXES = (".png", ".svg", ".pdf")
"""File endings :func:`plot_comparison` writes (the format follows the ending)."""

_LABELS = tuple(SemanticLabel)
_REF_STYLE = {
    "color": "black",
    "marker": "D",
    "markersize": 5,
    "capsize": 3,
    "linestyle": "none",
    "zorder": 5,
}


class _Group(NamedTuple):
    name: str
    features: list[RoomFeatures]
    colour: Any
    plans: int


def _groups(c: Comparison) -> list[_Group]:
    """Every set, plus the reference's plans if it was fitted from plans (in grey)."""
    from matplotlib import colormaps

    cmap = colormaps["tab10"]
    out = [
        _Group(s.name, all_room_features(s.plans.buildings), cmap(i % 10), len(s.plans))
        for i, s in enumerate(c.sets)
    ]
    if c.reference.buildings:
        ref = c.reference
        out.append(_Group(ref.column, all_room_features(ref.buildings), "0.55", len(ref.buildings)))
    return out


def _offsets(n: int, width: float = 0.8) -> list[float]:
    step = width / max(n, 1)
    return [-width / 2 + step * (i + 0.5) for i in range(n)]


def _label_axis(ax: Axes, title: str, ylabel: str) -> None:
    ax.set_xticks(range(len(_LABELS)), [lab.value for lab in _LABELS])
    ax.set_title(title, fontsize=11, loc="left")
    ax.set_ylabel(ylabel)
    ax.grid(axis="y", alpha=0.3)


def _reference_marks(ax: Axes, c: Comparison, key: str, offset: float) -> None:
    """The paper's mean +/- std per label, beside the sets' boxes."""
    xs, means, stds = [], [], []
    for i, lab in enumerate(_LABELS):
        row = c.reference.table.get(lab, {})
        if not math.isnan(row.get(f"{key}_mean", math.nan)):
            xs.append(i + offset)
            means.append(row[f"{key}_mean"])
            stds.append(row[f"{key}_std"])
    ax.errorbar(xs, means, yerr=stds, **_REF_STYLE)


def _boxes(ax: Axes, data: list[list[float]], offset: float, width: float, colour: Any) -> None:
    """One box per non-empty list of ``data``, the ``i``-th at ``i + offset``, in one set's colour."""
    pos = [i + offset for i, d in enumerate(data) if d]
    if pos:
        ax.boxplot(
            [d for d in data if d],
            positions=pos,
            widths=width * 0.85,
            patch_artist=True,
            showfliers=False,
            boxprops={"facecolor": colour, "alpha": 0.6, "edgecolor": colour},
            medianprops={"color": "black"},
            whiskerprops={"color": colour},
            capprops={"color": colour},
        )


def _box_panel(ax: Axes, c: Comparison, groups: list[_Group], key: str, title: str, ylabel: str) -> None:
    paper = not c.reference.buildings
    offsets = _offsets(len(groups) + paper)
    width = 0.8 / (len(groups) + paper)
    for off, g in zip(offsets, groups, strict=False):
        data = [[float(getattr(f, key)) for f in g.features if f.label is lab] for lab in _LABELS]
        _boxes(ax, data, off, width, g.colour)
    if paper:
        _reference_marks(ax, c, key, offsets[-1])
    _label_axis(ax, title, ylabel)


def _shares_panel(ax: Axes, c: Comparison, groups: list[_Group]) -> None:
    width = 0.8 / (len(c.sets) + 1)
    offsets = _offsets(len(c.sets) + 1)
    for off, s, g in zip(offsets, c.sets, groups, strict=False):
        ax.bar(
            [i + off for i in range(len(_LABELS))],
            [s.table[lab]["share_pct"] for lab in _LABELS],
            width,
            color=g.colour,
            label=s.name,
        )
    ref = [c.reference.table.get(lab, {}).get("share_pct", 0.0) for lab in _LABELS]
    style = (
        {"color": "0.55"}
        if c.reference.buildings
        else {"color": "white", "edgecolor": "black", "hatch": "//"}
    )
    ax.bar([i + offsets[-1] for i in range(len(_LABELS))], ref, width, label=c.reference.column, **style)
    _label_axis(ax, "Share of rooms per label", "% of rooms")


def _connectivity_panel(ax: Axes, c: Comparison, groups: list[_Group]) -> None:
    metrics = [m for m in CONNECTIVITY_METRICS if m.unit == "%"]
    height = 0.8 / len(c.sets)
    offsets = _offsets(len(c.sets))
    for off, s, g in zip(offsets, c.sets, groups, strict=False):
        values = [s.connectivity.metrics()[m.key] for m in metrics]
        ax.barh(
            [i + off for i in range(len(metrics))],
            [0 if math.isnan(v) else v for v in values],
            height,
            color=g.colour,
        )
    ref = [
        (i, c.reference.connectivity[m.key])
        for i, m in enumerate(metrics)
        if m.key in c.reference.connectivity
    ]
    if ref:
        ax.plot(
            [v for _i, v in ref],
            [i for i, _v in ref],
            "D",
            color="black",
            markersize=6,
            label=c.reference.column,
            zorder=5,
        )
    ax.set_yticks(range(len(metrics)), [m.title for m in metrics], fontsize=8)
    ax.invert_yaxis()
    ax.set_xlim(0, 100)
    ax.set_xlabel("%")
    ax.set_title("Connectivity", fontsize=11, loc="left")
    ax.grid(axis="x", alpha=0.3)


def _score_panel(ax: Axes, c: Comparison, groups: list[_Group]) -> None:
    terms = ("overall", "features", "shares", "connectivity")
    width = 0.8 / len(c.sets)
    for off, s, g in zip(_offsets(len(c.sets)), c.sets, groups, strict=False):
        values = [getattr(s.score, t) for t in terms]
        ax.bar(
            [i + off for i in range(len(terms))],
            [0 if math.isnan(v) else v for v in values],
            width,
            color=g.colour,
        )
    ax.set_xticks(range(len(terms)), ["overall", "features", "label shares", "connectivity"])
    ax.axhline(0.5, color="0.4", linestyle=":", linewidth=1)
    ax.set_ylabel("deviation (0 = reference)")
    ax.set_title(f"Realism score vs {c.reference.column}", fontsize=11, loc="left")
    ax.grid(axis="y", alpha=0.3)
    lines = [f"{t.name_a} vs {t.name_b}: {t.accuracy:.2f}" for t in c.two_sample]
    if lines:
        ax.set_ylim(0, ax.get_ylim()[1] * (1.25 + 0.06 * len(lines)))
        text = "two-sample accuracy\n(0.5 = indistinguishable)\n" + "\n".join(lines)
        ax.text(
            0.98,
            0.97,
            text,
            transform=ax.transAxes,
            ha="right",
            va="top",
            fontsize=8,
            bbox={"facecolor": "white", "alpha": 0.8, "edgecolor": "0.7"},
        )


_SHAPE_MEASURES = {
    "footprint_fill": "fill",
    "isoperimetric_quotient": "4πA/P²",
    "circulation_share": "circulation",
    "door_depth_norm": "depth/√rooms",
    "one_door_share": "one door",
    "core_facade_share": "core facade",
}
"""Building-level measures drawn in the shape panel (all between 0 and about 1), short names."""


def _measure_sets(c: Comparison, groups: list[_Group]) -> list[tuple[_Group, list]]:
    """Each group with its plans' building-level measures (the reference's when fitted from plans)."""
    pairs = [(g, list(s.measures)) for g, s in zip(groups, c.sets, strict=False)]
    if c.reference_measures:
        pairs.append((groups[-1], list(c.reference_measures)))
    return pairs


def _measure_boxes(ax: Axes, pairs: list[tuple[_Group, list]], keys: list[str]) -> None:
    offsets = _offsets(len(pairs))
    width = 0.8 / max(len(pairs), 1)
    for off, (g, measures) in zip(offsets, pairs, strict=True):
        data = [[v for m in measures if not math.isnan(v := float(getattr(m, k)))] for k in keys]
        _boxes(ax, data, off, width, g.colour)
    ax.grid(axis="y", alpha=0.3)


def _building_panels(shape_ax: Axes, density_ax: Axes, c: Comparison, groups: list[_Group]) -> None:
    """Building-level measures per set: footprint and circulation shares, and room density."""
    pairs = _measure_sets(c, groups)
    _measure_boxes(shape_ax, pairs, list(_SHAPE_MEASURES))
    shape_ax.set_xticks(range(len(_SHAPE_MEASURES)), list(_SHAPE_MEASURES.values()), fontsize=8, rotation=20)
    shape_ax.set_title("Building: footprint, circulation, depth", fontsize=11, loc="left")
    shape_ax.set_ylabel("share / ratio")
    _measure_boxes(density_ax, pairs, ["rooms_per_hectare"])
    density_ax.set_xticks([0], ["rooms per hectare of floor"])
    density_ax.set_title("Building: room density", fontsize=11, loc="left")
    density_ax.set_ylabel("rooms / 10,000 m²")


def _legend_handles(c: Comparison, groups: list[_Group]) -> list:
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    handles = [Patch(facecolor=g.colour, alpha=0.7, label=f"{g.name} ({g.plans})") for g in groups]
    if c.reference.buildings:
        label = f"{c.reference.column}: connectivity"
        handles.append(Line2D([], [], color="black", marker="D", linestyle="none", label=label))
    else:
        handles.append(
            Patch(facecolor="white", edgecolor="black", hatch="//", label=f"{c.reference.column}: shares")
        )
        handles.append(
            Line2D(
                [], [], color="black", marker="D", linestyle="none", label=f"{c.reference.column}: mean ± std"
            )
        )
    return handles


def comparison_figure(c: Comparison) -> Figure:
    """The comparison's figure (a matplotlib ``Figure``, not shown; see :func:`plot_comparison`)."""
    from matplotlib.figure import Figure

    groups = _groups(c)
    fig = Figure(figsize=(22, 10), layout="constrained")
    axes = fig.subplots(2, 4)
    _shares_panel(axes[0, 0], c, groups)
    _box_panel(axes[0, 1], c, groups, "area", "Room area per label", "m² (log scale)")
    axes[0, 1].set_yscale("log")
    _box_panel(axes[0, 2], c, groups, "axes_ratio", "Axes ratio per label", "major / minor side")
    _connectivity_panel(axes[1, 0], c, groups)
    _box_panel(axes[1, 1], c, groups, "doors", "Doorways per label", "doorways per room")
    _score_panel(axes[1, 2], c, groups)
    _building_panels(axes[0, 3], axes[1, 3], c, groups)
    fig.legend(
        handles=_legend_handles(c, groups), loc="outside lower center", ncols=6, fontsize=10, frameon=False
    )
    fig.suptitle(
        f"{c.building_type.value} plans vs {c.reference.name}  (boxes: quartiles, whiskers 1.5 IQR; plans in brackets)",
        fontsize=13,
    )
    return fig


def plot_comparison(c: Comparison, path: str | Path, dpi: int = 110) -> Path:
    """Draw :func:`comparison_figure` and save it (PNG, SVG or PDF from the file name).

    Returns:
        The file written.
    """
    path = check_output_path(path, "--plot", PLOT_SUFFIXES)
    with atomic_path(path) as tmp:
        comparison_figure(c).savefig(tmp, dpi=dpi)
    return path
