"""Figures of an evaluation: mean coverage curves per agent, one panel per environment group."""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from realistic_indoor.evaluation.aggregate import group_results, mean_curve
from realistic_indoor.evaluation.episode import EpisodeResult
from realistic_indoor.files import atomic_path

__all__ = ["plot_coverage", "plot_speedup"]

_AXES = {
    "time": ("coverage_t", "curve_dt_s", "time (s)"),
    "distance": ("coverage_d", "curve_dd_m", "distance driven (m)"),
}


def plot_coverage(results: Sequence[EpisodeResult], path: str | Path, x: str = "time") -> Path:
    """Draw mean coverage against time or distance, with 95% bootstrap bands, and save it.

    One panel per environment group, one line per agent (and team size, for teams). Episodes that ended early are held at
    their final coverage: over time up to the step limit, over distance up to the longest drive.

    Args:
        results: Episode results.
        path: Image file to write (PNG, SVG or PDF by its ending).
        x: ``"time"`` or ``"distance"``.

    Returns:
        The path written (whole or not at all: drawn to a temporary file renamed into place).
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    curve_field, step_field, label = _AXES[x]
    groups = list(dict.fromkeys(r.group for r in results))
    fig, axes = _panels(plt, len(groups), sharey=True)
    by_agent_group = group_results(results, ("group", "agent", "robots"))
    teams = any(r.robots > 1 for r in results)
    for ax, group in zip(axes.flat, groups, strict=False):
        for (g, agent, robots), episodes in by_agent_group.items():
            if g != group:
                continue
            name = f"{agent}, {robots} robot{'s' if robots > 1 else ''}" if teams else agent
            mean, low, high = mean_curve(
                [getattr(e, curve_field) for e in episodes], length=_horizon(episodes, x)
            )
            t = np.arange(len(mean)) * getattr(episodes[0], step_field)
            (line,) = ax.plot(t, mean, label=f"{name} (n={len(episodes)})", lw=1.5)
            ax.fill_between(t, low, high, color=line.get_color(), alpha=0.2, lw=0)
        ax.set_title(group, fontsize=9)
        ax.set_xlabel(label)
        ax.set_ylim(0, 1)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="lower right")
    for ax in axes[:, 0]:
        ax.set_ylabel("coverage")
    return _save(fig, axes, len(groups), path)


def plot_speedup(rows: Sequence[dict], path: str | Path) -> Path:
    """Draw each agent's speed-up against team size, one panel per environment group, and save it.

    Args:
        rows: Summary rows with ``robots`` and ``speedup``
            (:func:`~realistic_indoor.evaluation.outputs.summary_rows`).
        path: Image file to write (PNG, SVG or PDF by its ending).

    Returns:
        The path written (whole or not at all). The dashed line is the ideal, speed-up = team size.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    groups = list(dict.fromkeys(r["group"] for r in rows))
    fig, axes = _panels(plt, len(groups))
    sizes = sorted({r["robots"] for r in rows})
    for ax, group in zip(axes.flat, groups, strict=False):
        ax.plot(sizes, sizes, "--", color="grey", lw=1, label="ideal")
        for agent in dict.fromkeys(r["agent"] for r in rows if r["group"] == group):
            mine = sorted(
                (r["robots"], r["speedup"]) for r in rows if r["group"] == group and r["agent"] == agent
            )
            ax.plot([n for n, _ in mine], [v for _, v in mine], "o-", lw=1.5, label=agent)
        ax.set_title(group, fontsize=9)
        ax.set_xlabel("robots")
        ax.set_xticks(sizes)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper left")
    for ax in axes[:, 0]:
        ax.set_ylabel("speed-up to 90% coverage")
    return _save(fig, axes, len(groups), path)


def _panels(plt, n: int, sharey: bool = False):
    """A figure of ``n`` panels, three to a row: ``(figure, 2-D array of axes)``."""
    cols = min(3, n)
    rows = math.ceil(n / cols)
    return plt.subplots(rows, cols, figsize=(4.5 * cols, 3.4 * rows), squeeze=False, sharey=sharey)


def _save(fig, axes, used: int, path: str | Path) -> Path:
    """Hide the panels after the first ``used``, save ``fig`` whole or not at all, close it."""
    import matplotlib.pyplot as plt

    for ax in list(axes.flat)[used:]:
        ax.set_visible(False)
    fig.tight_layout()
    path = Path(path)
    try:
        with atomic_path(path) as tmp:
            fig.savefig(tmp, dpi=120)
    finally:
        plt.close(fig)
    return path


def _horizon(episodes: Sequence[EpisodeResult], x: str) -> int | None:
    """Points of a time curve up to the step limit (``None`` for distance: the longest drive)."""
    if x != "time":
        return None
    return max(round(e.max_steps * e.dt_s / e.curve_dt_s) + 1 for e in episodes)
