"""Aggregates of episode results: means with confidence intervals, per agent and environment group."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from statistics import NormalDist
from typing import Any

import numpy as np

from realistic_indoor.evaluation.episode import TEAM_SCALARS, EpisodeResult

__all__ = [
    "SUMMARY_METRICS",
    "TEAM_METRICS",
    "Estimate",
    "add_speedup",
    "bootstrap_mean",
    "group_results",
    "mean_curve",
    "summarize",
    "wilson",
]

SUMMARY_METRICS = (
    "coverage_auc",
    "final_coverage",
    "reached_target",
    "time_to_target_s",
    "path_to_target_m",
    "path_length_m",
    "collisions",
    "episode_return",
    "victims_found_share",
    "time_to_first_victim_s",
    "time_to_all_victims_s",
    "agent_ms_per_step",
)
"""Metrics a summary reports. ``reached_target`` is a share (Wilson interval); times and
distances to the target or to victims average the episodes that got there."""

TEAM_METRICS = TEAM_SCALARS
"""Metrics a summary of team episodes reports too."""

_RESAMPLES = 2000
_SEED = 20_240_601  # the bootstrap's own fixed seed: summaries are reproducible byte for byte


@dataclass(frozen=True)
class Estimate:
    """A mean with its confidence interval.

    Attributes:
        mean: The mean (``NaN`` with no values).
        low: Lower bound of the interval.
        high: Upper bound.
        n: Number of values it rests on.
    """

    mean: float
    low: float
    high: float
    n: int


def bootstrap_mean(values: Sequence[float], level: float = 0.95, resamples: int = _RESAMPLES) -> Estimate:
    """Mean and percentile-bootstrap interval of the finite values (``NaN`` ones are left out).

    The resampling uses a fixed seed, so the same values give the same interval.
    """
    x = np.asarray(values, dtype=float)
    x = x[np.isfinite(x)]
    if len(x) == 0:
        return Estimate(math.nan, math.nan, math.nan, 0)
    if len(x) == 1 or np.all(x == x[0]):
        return Estimate(float(x.mean()), float(x[0]), float(x[0]), len(x))
    rng = np.random.default_rng(_SEED)
    means = x[rng.integers(0, len(x), (resamples, len(x)))].mean(axis=1)
    lo, hi = np.quantile(means, [(1 - level) / 2, (1 + level) / 2])
    return Estimate(float(x.mean()), float(lo), float(hi), len(x))


def wilson(successes: int, n: int, level: float = 0.95) -> Estimate:
    """A share with its Wilson score interval (good for small ``n`` and shares near 0 or 1)."""
    if n == 0:
        return Estimate(math.nan, math.nan, math.nan, 0)
    z = NormalDist().inv_cdf((1 + level) / 2)
    p = successes / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return Estimate(p, max(0.0, centre - half), min(1.0, centre + half), n)


def group_results(
    results: Sequence[EpisodeResult], by: tuple[str, ...] = ("agent", "group")
) -> dict[tuple[Any, ...], list[EpisodeResult]]:
    """Results keyed by the values of the fields ``by``, in order of first appearance."""
    groups: dict[tuple[Any, ...], list[EpisodeResult]] = {}
    for r in results:
        groups.setdefault(tuple(getattr(r, f) for f in by), []).append(r)
    return groups


def summarize(
    results: Sequence[EpisodeResult],
    by: tuple[str, ...] = ("agent", "group"),
    level: float = 0.95,
    metrics: Sequence[str] = SUMMARY_METRICS,
) -> list[dict[str, Any]]:
    """One row per group of results: ``episodes`` and, per metric, ``<m>``, ``<m>_low``, ``<m>_high``.

    Args:
        results: Episode results.
        by: Fields that define a group (agent and environment group by default).
        level: Confidence level of the intervals.
        metrics: The metrics (:data:`SUMMARY_METRICS` by default; add :data:`TEAM_METRICS`
            for teams).

    Returns:
        Rows (dicts) in order of first appearance of each group.
    """
    rows = []
    for key, group in group_results(results, by).items():
        row: dict[str, Any] = dict(zip(by, key, strict=True))
        row["episodes"] = len(group)
        for metric in metrics:
            est = _estimate(group, metric, level)
            row[metric], row[f"{metric}_low"], row[f"{metric}_high"] = est.mean, est.low, est.high
        rows.append(row)
    return rows


def add_speedup(rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """Add ``speedup`` and ``efficiency`` to summary rows grouped by agent, group and ``robots``.

    Speed-up of a team of ``n``: the mean time to the target of the same agent with one robot
    in the same environment group over the team's mean time (of the episodes that reached it);
    efficiency: speed-up over ``n``. ``NaN`` without a one-robot row or a time to compare.

    Returns:
        The same rows, changed in place.
    """
    alone = {(r["agent"], r["group"]): r["time_to_target_s"] for r in rows if r["robots"] == 1}
    for row in rows:
        one = alone.get((row["agent"], row["group"]), math.nan)
        team = row["time_to_target_s"]
        row["speedup"] = one / team if math.isfinite(one) and math.isfinite(team) and team > 0 else math.nan
        row["efficiency"] = row["speedup"] / row["robots"]
    return rows


def mean_curve(
    curves: Sequence[Sequence[float]], level: float = 0.95, length: int | None = None
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Mean of coverage curves with a pointwise bootstrap interval.

    Curves of episodes that ended early (the target reached, or a shorter drive) are held at
    their last value.

    Args:
        curves: The curves.
        level: Confidence level of the band.
        length: Points to return (at least the longest curve's); ``None``: the longest curve's.

    Returns:
        ``(mean, low, high)`` arrays of ``length`` points.
    """
    length = max([len(c) for c in curves] + [length or 0])
    m = np.array([list(c) + [c[-1]] * (length - len(c)) for c in curves], dtype=float)
    if len(m) == 1:
        return m[0], m[0], m[0]
    rng = np.random.default_rng(_SEED)
    means = m[rng.integers(0, len(m), (_RESAMPLES // 4, len(m)))].mean(axis=1)
    lo, hi = np.quantile(means, [(1 - level) / 2, (1 + level) / 2], axis=0)
    return m.mean(axis=0), lo, hi


def _estimate(group: Sequence[EpisodeResult], metric: str, level: float) -> Estimate:
    if metric == "reached_target":
        return wilson(sum(r.reached_target for r in group), len(group), level)
    if metric == "victims_found_share":
        searched = [r for r in group if r.victims_total > 0]
        return bootstrap_mean([r.victims_found / r.victims_total for r in searched], level)
    return bootstrap_mean([getattr(r, metric) for r in group], level)
