"""Evaluation of agents: agents x environments x seeds in parallel, metrics, summaries, figures.

::

    from realistic_indoor.evaluation import evaluate

    results = evaluate(["frontier", "random"], ["OfficeExplore-v0", "RandomExplore-v0"], episodes=20,
                       out_dir="results/")

writes ``episodes.csv`` (one row per episode), ``summary.csv`` (means with 95% confidence
intervals per agent and environment group), ``results.json`` (both, with the coverage curves)
and the figures ``coverage_time.png`` and ``coverage_distance.png``. The command line is
``realistic-indoor evaluate``; see ``docs/agents.md``.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

from realistic_indoor.evaluation.aggregate import SUMMARY_METRICS, Estimate, bootstrap_mean, summarize, wilson
from realistic_indoor.evaluation.episode import SCALARS, EpisodeResult, run_episode
from realistic_indoor.evaluation.outputs import format_table, read_results, write_results
from realistic_indoor.evaluation.runner import run_tasks
from realistic_indoor.evaluation.tasks import EnvSpec, EpisodeTask, make_tasks, parse_envs

__all__ = [
    "SCALARS",
    "SUMMARY_METRICS",
    "EnvSpec",
    "EpisodeResult",
    "EpisodeTask",
    "Estimate",
    "bootstrap_mean",
    "evaluate",
    "format_table",
    "make_tasks",
    "parse_envs",
    "read_results",
    "run_episode",
    "run_tasks",
    "summarize",
    "wilson",
    "write_results",
]


def evaluate(
    agents: Sequence[str],
    envs: Sequence[str | EnvSpec],
    episodes: int = 20,
    seed: int = 0,
    workers: int | None = None,
    out_dir: str | Path | None = None,
    figures: bool = True,
    use_ray: bool = False,
    ray_address: str | None = None,
    progress: bool = True,
    env_kwargs: dict[str, Any] | None = None,
) -> list[EpisodeResult]:
    """Run every agent in every environment for ``episodes`` seeds; optionally write the outputs.

    Args:
        agents: Agent names (:func:`realistic_indoor.agents.make_agent`).
        envs: Registered ids, ``"ID:plan-or-folder"`` strings, or :class:`EnvSpec` objects.
        episodes: Episodes (seeds) per agent and environment.
        seed: First seed.
        workers: Parallel processes (``None``: one per core).
        out_dir: Folder for the CSV, JSON and figures; ``None`` writes nothing.
        figures: Also draw the coverage curves (with ``out_dir``).
        use_ray: Run on a Ray cluster (``pip install ray``).
        ray_address: The cluster's address (``None``: local).
        progress: Show a progress bar.
        env_kwargs: Keyword arguments of ``gym.make`` for the string environments.

    Returns:
        The episode results, ordered by agent, environment and seed.

    Raises:
        ConfigError: For bad names, ids, plans or arguments (before any episode runs).
    """
    specs = [e for e in envs if isinstance(e, EnvSpec)]
    specs += parse_envs([e for e in envs if not isinstance(e, EnvSpec)], env_kwargs)
    tasks = make_tasks(list(agents), specs, episodes, seed)
    results = run_tasks(tasks, workers=workers, use_ray=use_ray, ray_address=ray_address, progress=progress)
    if out_dir is not None:
        meta = {"agents": list(agents), "envs": [s.label for s in specs], "episodes": episodes, "seed": seed}
        write_results(results, out_dir, meta)
        if figures:
            from realistic_indoor.evaluation.figures import plot_coverage

            plot_coverage(results, Path(out_dir) / "coverage_time.png", "time")
            plot_coverage(results, Path(out_dir) / "coverage_distance.png", "distance")
    return results
