"""Real plans beside their held-out twins, drawn at one scale: what the realism figures measure.

For each building type, a few shared real plans are chosen by floor area (:func:`pick_by_area`:
the plan in the middle of each of ``k`` equal-count groups of the plans sorted by floor area) and
each is drawn beside one of its twins. The twins come from
:func:`layout_realism.held_out_twins`, the path of ``experiments/layout_realism.py``: the plans
are split into folds, a model is fitted to the other folds' plans and four twins of the plan's
type and floor area are generated with it; the picture shows the first of them. A real plan and
its twin share one drawing scale (the metres per pixel are written above the pair, and both
carry the same scale bar); pairs of different sizes have different scales. Each plan is labelled
with its type, floor area, rooms per hectare and footprint aspect ratio
(:func:`~realistic_indoor.validator.building_measures.building_measures`).

The pictures are those of the package this script imports: run it in an older worktree, with
that worktree on ``PYTHONPATH``, to draw the twins of an older generator (docs/realism.md,
"Side by side").

Usage::

    .venv/bin/python experiments/realism_pictures.py --out docs/images/realism/after
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import warnings
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from layout_realism import PLANS, held_out_twins

import realistic_indoor
from realistic_indoor.io import load
from realistic_indoor.io.render import DEFAULT_STYLE, draw_plan
from realistic_indoor.io.render.decorations import LEGEND_ORDER, add_scale_bar
from realistic_indoor.io.render.draw import plan_limits
from realistic_indoor.validator.building_measures import building_measures

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from realistic_indoor.building.building import Building

ROOT = Path(__file__).resolve().parents[1]
FOLDS = 5
"""Folds of the cross-validation (``layout_realism.py``'s default)."""
DPI = 100.0
"""Pixels per inch of the pictures."""

FIG_WIDTH_IN = 10.0
"""Width of a picture (inches): two plans side by side."""
PAD_IN = 0.25
"""Margin around and between the plans (inches)."""
PLAN_HEIGHT_IN = 2.7
"""Height a pair's plans may take (inches)."""
LABEL_IN = 0.55
"""Room above a plan for its two-line label (inches)."""
SCALE_BAR_IN = 0.35
"""Room under a plan for its scale bar (inches)."""
HEADER_IN = 0.85
"""Room at the top for the picture's title and the legend of labels (inches)."""


@dataclass(frozen=True)
class Pair:
    """A real plan and one of its held-out twins.

    Attributes:
        name: The plan's file stem.
        real: The real plan.
        twin: Its twin: same type and floor area, from a model fitted without the plan's fold.
    """

    name: str
    real: Building
    twin: Building


def pick_by_area(areas: Sequence[float], count: int) -> list[int]:
    """Indices of ``count`` plans spread over floor area, smallest first.

    The plans are sorted by floor area (ties by index) and cut into ``count`` groups of equal
    size; the plan at the middle rank of each group is chosen: rank ``floor((i + 0.5) n / count)``
    of ``n``, i.e. the plans at the 12.5th, 37.5th, 62.5th and 87.5th percentiles for four. With
    at least twice as many plans as ``count``, the smallest and the largest are never chosen, so
    a single mis-scaled extreme does not set a picture's scale.

    Args:
        areas: Floor area of each plan (m2).
        count: How many to choose, >= 1; all the plans when there are no more than this.

    Returns:
        Indices into ``areas``, in increasing floor area.

    Raises:
        ValueError: If ``count`` < 1.
    """
    if count < 1:
        raise ValueError(f"count must be >= 1, not {count}")
    order = sorted(range(len(areas)), key=lambda i: (areas[i], i))
    n = len(order)
    if n <= count:
        return order
    return [order[(2 * i + 1) * n // (2 * count)] for i in range(count)]


def make_pairs(plans: list[tuple[str, Building]], kind: str, count: int, folds: int, seed: int) -> list[Pair]:
    """The chosen plans (:func:`pick_by_area`) with the first of their held-out twins.

    Twins are made for every plan, as in ``experiments/layout_realism.py`` (four per plan, so
    the twin shown is one that its figures measure at the same seed), and the chosen plans' first
    twins kept.

    Args:
        plans: Plan names and plans.
        kind: Their building type.
        count: Plans to draw.
        folds: Folds of the cross-validation.
        seed: Seed of the split and of the twins (``layout_realism.py --seed``).

    Returns:
        The pairs, in increasing floor area.
    """
    twins = held_out_twins(plans, kind, folds, seed)  # its default count, as layout_realism.py's
    per_plan = len(twins) // len(plans)
    chosen = pick_by_area([b.area for _, b in plans], count)
    return [Pair(plans[i][0], plans[i][1], twins[i * per_plan]) for i in chosen]


def describe(building: Building) -> str:
    """Type, floor area, rooms per hectare and footprint aspect ratio, on one line."""
    m = building_measures(building)
    return (
        f"{building.building_type.value} · {building.area:,.0f} m² · "
        f"{m.rooms_per_hectare:.0f} rooms/ha · aspect {m.aspect_ratio:.2f}"
    )


def pair_scale(real: Building, twin: Building) -> tuple[float, float]:
    """Inches per metre that fit both plans of a pair in their slots (half the width each).

    Returns:
        The scale (inches per metre) and the height the taller plan takes at it (inches).
    """
    slot_w = (FIG_WIDTH_IN - 3 * PAD_IN) / 2
    spans = [plan_limits(b) for b in (real, twin)]
    widest = max(x1 - x0 for x0, _y0, x1, _y1 in spans)
    tallest = max(y1 - y0 for _x0, y0, _x1, y1 in spans)
    scale = min(slot_w / widest, PLAN_HEIGHT_IN / tallest)
    return scale, tallest * scale


def pairs_figure(pairs: Sequence[Pair], title: str, dpi: float) -> Figure:
    """Each pair on a row, the real plan left and its twin right, both at the pair's scale.

    Args:
        pairs: The pairs, one row each.
        title: The picture's title.
        dpi: Pixels per inch (the stated metres per pixel assume it).

    Returns:
        A matplotlib figure on an Agg canvas.
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    from matplotlib.patches import Patch

    scales = [pair_scale(pair.real, pair.twin) for pair in pairs]
    fig_h = HEADER_IN + sum(LABEL_IN + h + SCALE_BAR_IN for _s, h in scales) + PAD_IN
    fig = Figure(figsize=(FIG_WIDTH_IN, fig_h), dpi=dpi)
    FigureCanvasAgg(fig)
    fig.text(PAD_IN / FIG_WIDTH_IN, 1 - 0.12 / fig_h, title, va="top", fontsize=11)
    fig.legend(
        [
            Patch(facecolor=DEFAULT_STYLE.label_colours[lab], edgecolor="black", lw=0.5)
            for lab in LEGEND_ORDER
        ],
        [lab.value for lab in LEGEND_ORDER],
        loc="upper left",
        bbox_to_anchor=(PAD_IN / FIG_WIDTH_IN, 1 - 0.45 / fig_h),
        ncols=len(LEGEND_ORDER),
        frameon=False,
        fontsize=8,
        borderaxespad=0.0,
    )
    slot_w = (FIG_WIDTH_IN - 3 * PAD_IN) / 2
    top = fig_h - HEADER_IN
    for pair, (scale, row_h) in zip(pairs, scales, strict=True):
        top -= LABEL_IN
        spans = [plan_limits(b) for b in (pair.real, pair.twin)]
        span_m = max(max(x1 - x0, y1 - y0) for x0, y0, x1, y1 in spans)
        labels = (
            f"real: {pair.name} ({1 / (scale * dpi):.2f} m/px, both)\n{describe(pair.real)}",
            f"twin: seed {pair.twin.metadata.get('seed')}, model fitted without this plan\n"
            f"{describe(pair.twin)}",
        )
        for col, (building, label) in enumerate(zip((pair.real, pair.twin), labels, strict=True)):
            x0, y0, x1, y1 = spans[col]
            w, h = (x1 - x0) * scale, (y1 - y0) * scale
            left = PAD_IN + col * (slot_w + PAD_IN)
            ax = fig.add_axes((left / FIG_WIDTH_IN, (top - h) / fig_h, w / FIG_WIDTH_IN, h / fig_h))
            draw_plan(building, ax, title=False, legend=False, scale_bar=False)
            ax.text(0.0, 1.0 + 0.06 / h, label, transform=ax.transAxes, va="bottom", fontsize=8)
            add_scale_bar(ax, span_m, DEFAULT_STYLE.wall_colour)
        top -= row_h + SCALE_BAR_IN
    return fig


def generator_version() -> str:
    """The commit of the package drawn (short hash), and whether its tree has changes."""

    def git(*args: str) -> str:
        run = subprocess.run(["git", "-C", str(ROOT), *args], capture_output=True, text=True, check=False)
        return run.stdout.strip()

    commit = git("rev-parse", "--short", "HEAD") or "unknown commit"
    changed = git("status", "--porcelain", "--", "realistic_indoor")
    return commit + (" with uncommitted changes" if changed else "")


def write_png(fig: Figure, path: Path) -> None:
    """Save ``fig`` as a PNG without metadata that changes from run to run."""
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, format="png", metadata={"Software": None})


def main(argv: list[str] | None = None) -> int:
    """Draw one picture per building type, ``OUT/TYPE_pairs.png``.

    Returns:
        0; 2 when the imported package is not this script's tree's.
    """
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--types", default="office,school", help="building types (default office,school)")
    p.add_argument("--count", type=int, default=4, help="plans per type, spread by floor area (default 4)")
    p.add_argument("--seed", type=int, default=0, help="seed of the split and the twins (default 0)")
    p.add_argument("--plans", type=Path, default=PLANS, help="folder with one sub-folder of plans per type")
    p.add_argument("--out", type=Path, default=Path("runs/realism_pictures"), help="output folder")
    args = p.parse_args(argv)
    package = Path(realistic_indoor.__file__).resolve().parent
    if package != ROOT / "realistic_indoor":
        print(
            f"error: imported {package}, not {ROOT / 'realistic_indoor'}: run with PYTHONPATH={ROOT}",
            file=sys.stderr,
        )
        return 2
    version = generator_version()
    for kind in args.types.split(","):
        files = sorted((args.plans / kind).glob("*.xml"))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            plans = [(f.stem, load(f)) for f in files]
            pairs = make_pairs(plans, kind, args.count, FOLDS, args.seed)
        title = (
            f"{kind.capitalize()}s: real plans (left) and held-out twins (right), "
            f"generator at {version}, seed {args.seed}"
        )
        path = args.out / f"{kind}_pairs.png"
        write_png(pairs_figure(pairs, title, DPI), path)
        print(f"{kind}: {', '.join(pair.name for pair in pairs)} -> {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
