"""Rankings of agents per environment group, how they agree, and paired differences between agents."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from realistic_indoor.evaluation.aggregate import Estimate, bootstrap_mean
from realistic_indoor.evaluation.episode import EpisodeResult

__all__ = ["kendall_tau", "paired_difference", "rankings"]


def rankings(
    rows: Sequence[dict[str, Any]], metric: str = "coverage_auc", higher_is_better: bool = True
) -> dict[str, list[str]]:
    """Agents of each group of a summary, best first by the mean of ``metric``.

    Args:
        rows: Summary rows (:func:`~realistic_indoor.evaluation.summarize`), with ``agent``
            and ``group``.
        metric: The metric to rank by; agents without a value come last.
        higher_is_better: Whether a higher mean ranks higher.

    Returns:
        ``{group: [agent, ...]}`` in order of first appearance of the groups.
    """
    by_group: dict[str, list[tuple[float, str]]] = {}
    for row in rows:
        value = float(row[metric])
        key = -value if higher_is_better else value
        by_group.setdefault(row["group"], []).append((np.inf if np.isnan(key) else key, row["agent"]))
    return {g: [a for _, a in sorted(pairs, key=lambda p: p[0])] for g, pairs in by_group.items()}


def kendall_tau(first: Sequence[str], second: Sequence[str]) -> float:
    """Kendall's rank correlation of two orders of the same agents (1 same order, -1 reversed).

    Agents missing from either order are left out; ``NaN`` with fewer than two in common.
    """
    from scipy.stats import kendalltau

    common = [a for a in first if a in second]
    if len(common) < 2:
        return float("nan")
    tau = kendalltau(range(len(common)), [list(second).index(a) for a in common]).statistic
    return float(tau)


def paired_difference(
    results: Sequence[EpisodeResult], first: str, second: str, group: str, metric: str = "coverage_auc"
) -> Estimate:
    """Mean of ``metric(first) - metric(second)`` over the episodes both agents ran in ``group``.

    Episodes are paired by environment and seed (the same building and start), which removes
    the building-to-building spread from the comparison; the interval is a bootstrap over the
    pairs.
    """

    def values(agent: str) -> dict[tuple[str, int], float]:
        return {
            (r.env, r.seed): float(getattr(r, metric))
            for r in results
            if r.agent == agent and r.group == group
        }

    a, b = values(first), values(second)
    return bootstrap_mean([a[k] - b[k] for k in a if k in b])
