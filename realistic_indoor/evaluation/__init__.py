"""Evaluation of agents: agents x environments x seeds in parallel, metrics, summaries, figures.

::

    from realistic_indoor.evaluation import evaluate

    results = evaluate(["frontier", "random"], ["OfficeExplore-v0", "RandomExplore-v0"], episodes=20,
                       out_dir="results/")

appends each episode to ``episodes.jsonl`` as it finishes (so an interrupted run keeps them and
``resume=True`` continues it), then writes ``episodes.csv`` (one row per episode), ``summary.csv``
(means with 95% confidence intervals per agent and environment group), ``results.json`` (both,
with the coverage curves, and the plans left out) and the figures ``coverage_time.png`` and
``coverage_distance.png``. A plan that cannot be read is left out with a warning. The command
line is ``realistic-indoor evaluate``; see ``docs/agents.md``.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from realistic_indoor.evaluation.aggregate import SUMMARY_METRICS, Estimate, bootstrap_mean, summarize, wilson
from realistic_indoor.evaluation.episode import SCALARS, EpisodeResult, run_episode
from realistic_indoor.evaluation.outputs import (
    EpisodeLog,
    finished_episodes,
    format_table,
    previous_results,
    read_results,
    summary_rows,
    write_results,
)
from realistic_indoor.evaluation.runner import check_tasks, run_tasks
from realistic_indoor.evaluation.tasks import EnvSpec, EpisodeTask, make_tasks, parse_envs, readable_envs
from realistic_indoor.validator.plan_sets import SkippedPlan

__all__ = [
    "SCALARS",
    "SUMMARY_METRICS",
    "EnvSpec",
    "EpisodeResult",
    "EpisodeTask",
    "Estimate",
    "Evaluation",
    "bootstrap_mean",
    "evaluate",
    "format_table",
    "make_tasks",
    "parse_envs",
    "previous_results",
    "read_results",
    "readable_envs",
    "run_episode",
    "run_evaluation",
    "run_tasks",
    "summarize",
    "wilson",
    "write_results",
]


@dataclass(frozen=True)
class Evaluation:
    """What an evaluation ran, what it left out, and where it wrote.

    Attributes:
        results: The episode results, ordered by agent, environment and seed.
        envs: The environments run.
        skipped: The plans left out (unreadable, or without rooms).
        plans: Plan files named by the environments (run or left out).
        resumed: Episodes taken from an earlier run's log instead of being run again.
        files: The files written, by name (none without an output folder).
    """

    results: list[EpisodeResult]
    envs: list[EnvSpec]
    skipped: list[SkippedPlan] = field(default_factory=list)
    plans: int = 0
    resumed: int = 0
    files: dict[str, Path] = field(default_factory=dict)


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
    *,
    strict: bool = False,
    resume: bool = False,
    robots: Sequence[int] | None = None,
) -> list[EpisodeResult]:
    """Run every agent in every environment for ``episodes`` seeds; optionally write the outputs.

    The episode results of :func:`run_evaluation`, which takes the same arguments.
    """
    return run_evaluation(
        agents,
        envs,
        episodes,
        seed,
        workers,
        out_dir,
        figures,
        use_ray,
        ray_address,
        progress,
        env_kwargs,
        strict=strict,
        resume=resume,
        robots=robots,
    ).results


def run_evaluation(
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
    *,
    strict: bool = False,
    resume: bool = False,
    robots: Sequence[int] | None = None,
) -> Evaluation:
    """Run every agent in every environment for ``episodes`` seeds; optionally write the outputs.

    Plans that cannot be read (or have no rooms) are left out with a warning naming each, and
    recorded in ``results.json`` (``meta["skipped"]``). With ``out_dir``, each episode is
    appended to ``episodes.jsonl`` as it finishes; the other outputs are written at the end.

    Args:
        agents: Agent names (:func:`realistic_indoor.agents.make_agent`).
        envs: Registered ids, ``"ID:plan-or-folder"`` strings, or :class:`EnvSpec` objects.
        episodes: Episodes (seeds) per agent and environment.
        seed: First seed.
        workers: Parallel processes (``None``: one per core).
        out_dir: Folder for the episode log, CSV, JSON and figures; ``None`` writes nothing.
            Earlier outputs in it are replaced, unless ``resume``.
        figures: Also draw the coverage curves (with ``out_dir``).
        use_ray: Run on a Ray cluster (``pip install ray``).
        ray_address: The cluster's address (``None``: local).
        progress: Show a progress bar.
        env_kwargs: Keyword arguments of ``gym.make`` for the string environments.
        strict: Stop at the first plan that cannot be read or used (or that the floor-plan
            reader would have to repair) instead of leaving it out.
        resume: Continue the run whose episode log is in ``out_dir``: the episodes it finished
            (same agent, environment and seed) are taken from it, the others are run, and the
            outputs are written over all of them.
        robots: Team sizes: every agent (a team agent,
            :data:`realistic_indoor.agents.team.TEAM_AGENTS`) runs as a team of each size in
            the id's team environment (default links and map sharing); ``None`` runs each agent
            alone in the single environment. The summary then adds the team metrics, the
            speed-up and the efficiency, and ``speedup.png`` is drawn.

    Returns:
        The evaluation.

    Raises:
        ConfigError: For bad names, ids, plans, arguments or ``out_dir`` (before any episode
            runs), or an episode log in ``out_dir`` written with other settings (``resume``).
        PlanFormatError: Under ``strict``, for the first plan that cannot be read.
    """
    from realistic_indoor.evaluation.runner import check_run_options
    from realistic_indoor.files import check_output_dir

    check_run_options(workers, use_ray)
    if out_dir is not None:
        check_output_dir(out_dir, "output folder")
    specs = [e for e in envs if isinstance(e, EnvSpec)]
    specs += parse_envs([e for e in envs if not isinstance(e, EnvSpec)], env_kwargs)
    plans = len({s.plan for s in specs if s.plan is not None})
    specs, skipped = readable_envs(specs, strict)
    tasks = make_tasks(list(agents), specs, episodes, seed, robots=robots)
    done = finished_episodes(out_dir, tasks) if resume and out_dir is not None else {}
    todo = [i for i in range(len(tasks)) if i not in done]
    check_tasks([tasks[i] for i in todo])
    new = _run_logged([tasks[i] for i in todo], out_dir, resume, workers, use_ray, ray_address, progress)
    done.update(zip(todo, new, strict=True))
    results = [done[i] for i in range(len(tasks))]
    files: dict[str, Path] = {}
    if out_dir is not None:
        meta = {
            "agents": list(agents),
            "envs": [s.label for s in specs],
            "episodes": episodes,
            "seed": seed,
            "robots": None if robots is None else list(robots),
            "skipped": [p.to_dict() for p in skipped],
            "resumed": len(tasks) - len(todo),
        }
        files = _write_outputs(results, Path(out_dir), meta, figures)
    return Evaluation(results, specs, skipped, plans, len(tasks) - len(todo), files)


def _run_logged(
    tasks: list[EpisodeTask],
    out_dir: str | Path | None,
    append: bool,
    workers: int | None,
    use_ray: bool,
    ray_address: str | None,
    progress: bool,
) -> list[EpisodeResult]:
    """Run ``tasks``, appending each result to the episode log of ``out_dir`` as it finishes."""
    if out_dir is None:
        return run_tasks(tasks, workers, ray_address, use_ray, progress, check=False)
    with EpisodeLog(out_dir, append=append) as log:
        return run_tasks(
            tasks,
            workers,
            ray_address,
            use_ray,
            progress,
            on_result=lambda i, r: log.write(tasks[i], r),
            check=False,
        )


def _write_outputs(
    results: list[EpisodeResult], out: Path, meta: dict[str, Any], figures: bool
) -> dict[str, Path]:
    """The CSV, JSON and figures; figures of an earlier run are removed when none are drawn."""
    from realistic_indoor.evaluation.figures import plot_coverage, plot_speedup

    files = write_results(results, out, meta)
    for x in ("time", "distance"):
        path = out / f"coverage_{x}.png"
        if figures:
            files[f"coverage_{x}"] = plot_coverage(results, path, x)
        else:
            path.unlink(missing_ok=True)
    path = out / "speedup.png"
    if figures and meta.get("robots"):
        files["speedup"] = plot_speedup(summary_rows(results), path)
    else:
        path.unlink(missing_ok=True)
    files["log"] = out / "episodes.jsonl"
    return files
