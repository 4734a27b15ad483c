"""Running many episodes: in this process, in parallel processes, or on a Ray cluster."""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from concurrent.futures import ProcessPoolExecutor, as_completed

from realistic_indoor.errors import ConfigError, RealisticIndoorError
from realistic_indoor.evaluation.episode import EpisodeResult, run_episode
from realistic_indoor.evaluation.tasks import EpisodeTask, make_env

__all__ = ["check_tasks", "run_tasks"]


def run_tasks(
    tasks: Sequence[EpisodeTask],
    workers: int | None = None,
    ray_address: str | None = None,
    use_ray: bool = False,
    progress: bool = True,
) -> list[EpisodeResult]:
    """Run episodes and return their results in the order of ``tasks``.

    Every episode is independent and seeded, so the results do not depend on the number of
    workers or on the order in which they finish.

    Args:
        tasks: The episodes.
        workers: Parallel processes; ``None`` for one per CPU core, 1 runs in this process.
        ray_address: Address of a Ray cluster (``ray://host:10001``); ``None`` starts or joins
            a local one. Used with ``use_ray``.
        use_ray: Run the episodes as Ray tasks (needs ``pip install ray``).
        progress: Show a progress bar (tqdm, on stderr).

    Raises:
        ConfigError: If an agent or environment is invalid (checked before any episode runs),
            or Ray is asked for but not installed.
    """
    check_tasks(tasks)
    if use_ray:
        return _run_ray(tasks, ray_address, progress)
    workers = (os.cpu_count() or 1) if workers is None else workers
    if isinstance(workers, bool) or not isinstance(workers, int) or workers < 1:
        raise ConfigError(f"workers must be an integer >= 1, got {workers!r}")
    bar = _progress(len(tasks), progress)
    try:
        if workers == 1 or len(tasks) == 1:
            results = []
            for task in tasks:
                results.append(_run(task))
                bar.update(1)
            return results
        return _run_pool(tasks, workers, bar.update)
    finally:
        bar.close()


def check_tasks(tasks: Sequence[EpisodeTask]) -> None:
    """Build each environment and agent once, so that a bad name or plan fails before the runs.

    Raises:
        ConfigError: For an unknown agent, id, or bad environment argument.
        PlanFormatError: For a plan that cannot be read.
    """
    from realistic_indoor.agents import make_agent

    envs = {t.env.label: t.env for t in tasks}
    agents = {t.agent: None for t in tasks}
    for spec in envs.values():
        env = make_env(spec)
        for agent in agents:
            make_agent(agent, env)
        env.close()


def _run(task: EpisodeTask) -> EpisodeResult:
    """One episode; user errors come back as a picklable ``ConfigError`` naming the episode."""
    try:
        return run_episode(task)
    except RealisticIndoorError as e:
        raise ConfigError(f"{task.agent} on {task.env.label}, seed {task.seed}: {e}") from None


def _run_pool(
    tasks: Sequence[EpisodeTask], workers: int, tick: Callable[[int], object]
) -> list[EpisodeResult]:
    results: list[EpisodeResult | None] = [None] * len(tasks)
    with ProcessPoolExecutor(max_workers=min(workers, len(tasks))) as pool:
        futures = {pool.submit(_run, task): i for i, task in enumerate(tasks)}
        for future in as_completed(futures):
            results[futures[future]] = future.result()
            tick(1)
    return results  # type: ignore[return-value]


def _run_ray(tasks: Sequence[EpisodeTask], address: str | None, progress: bool) -> list[EpisodeResult]:
    try:
        import ray
    except ImportError:
        raise ConfigError(
            "--ray needs the ray package: pip install ray (or leave out --ray to use local processes)"
        ) from None
    ray.init(address=address, ignore_reinit_error=True)
    remote = ray.remote(_run)
    refs = [remote.remote(task) for task in tasks]
    index = {ref: i for i, ref in enumerate(refs)}
    results: list[EpisodeResult | None] = [None] * len(tasks)
    bar = _progress(len(tasks), progress)
    pending = list(refs)
    try:
        while pending:
            done, pending = ray.wait(pending, num_returns=1)
            for ref in done:
                results[index[ref]] = ray.get(ref)
            bar.update(len(done))
    finally:
        bar.close()
    return results  # type: ignore[return-value]


def _progress(total: int, show: bool):
    from tqdm.auto import tqdm

    return tqdm(total=total, unit="episode", disable=not show, dynamic_ncols=True)
