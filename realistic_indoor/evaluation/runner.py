"""Running many episodes: in this process, in parallel processes, or on a Ray cluster."""

from __future__ import annotations

import os
import signal
import warnings
from collections.abc import Callable, Sequence
from concurrent.futures import Future, ProcessPoolExecutor, as_completed

from realistic_indoor.errors import ConfigError, RealisticIndoorError
from realistic_indoor.evaluation.episode import EpisodeResult, run_episode
from realistic_indoor.evaluation.tasks import EnvSpec, EpisodeTask, make_env, make_team_env
from realistic_indoor.evaluation.team_episode import run_team_episode

__all__ = ["check_tasks", "run_tasks"]

OnResult = Callable[[int, EpisodeResult], object]
"""Called in this process as each episode finishes: ``on_result(index in tasks, result)``."""


def run_tasks(
    tasks: Sequence[EpisodeTask],
    workers: int | None = None,
    ray_address: str | None = None,
    use_ray: bool = False,
    progress: bool = True,
    on_result: OnResult | None = None,
    check: bool = True,
) -> list[EpisodeResult]:
    """Run episodes and return their results in the order of ``tasks``.

    Every episode is independent and seeded, so the results do not depend on the number of
    workers or on the order in which they finish. Warnings are shown once, when the
    environments are checked in this process: worker processes do not repeat them.

    Args:
        tasks: The episodes.
        workers: Parallel processes; ``None`` for one per CPU core, 1 runs in this process.
        ray_address: Address of a Ray cluster (``ray://host:10001``); ``None`` starts or joins
            a local one. Used with ``use_ray``.
        use_ray: Run the episodes as Ray tasks (needs ``pip install ray``).
        progress: Show a progress bar (tqdm, on stderr).
        on_result: Called with each episode's index and result as soon as it finishes (to
            save it), in the order they finish.
        check: Check the agents and environments first (:func:`check_tasks`); ``False`` when
            the caller has.

    Raises:
        ConfigError: If an agent or environment is invalid (checked before any episode runs),
            or Ray is asked for but not installed.
        KeyboardInterrupt: When interrupted; worker processes are stopped first, and every
            episode finished before has been passed to ``on_result``.
    """
    check_run_options(workers, use_ray)
    if check:
        check_tasks(tasks)
    if not tasks:
        return []
    done = on_result or (lambda _i, _r: None)
    if use_ray:
        return _run_ray(tasks, ray_address, progress, done)
    workers = (os.cpu_count() or 1) if workers is None else workers
    bar = _progress(len(tasks), progress)
    try:
        if workers == 1 or len(tasks) == 1:
            results = []
            for i, task in enumerate(tasks):
                results.append(_run(task))
                done(i, results[-1])
                bar.update(1)
            return results
        return _run_pool(tasks, workers, done, bar.update)
    finally:
        bar.close()


def check_tasks(tasks: Sequence[EpisodeTask]) -> None:
    """Build each environment and agent once, so that a bad name or plan fails before the runs.

    Raises:
        ConfigError: For an unknown agent, id, or bad environment argument.
        PlanFormatError: For a plan that cannot be read.
    """
    from realistic_indoor.agents import agent_observations, make_agent

    envs = {t.env.label: t.env for t in tasks}
    team_agents = list(dict.fromkeys(t.agent for t in tasks if t.robots is not None))
    by_extras: dict[tuple[str, ...], list[str]] = {}  # agents grouped by the observations they add
    for agent in dict.fromkeys(t.agent for t in tasks if t.robots is None):
        by_extras.setdefault(agent_observations(agent), []).append(agent)
    for spec in envs.values():
        if team_agents:
            _check_team_agents(spec, team_agents)
        for extras, agents in by_extras.items():
            env = make_env(spec, extras)
            for agent in agents:
                make_agent(agent, env)
            env.close()


def _check_team_agents(spec: EnvSpec, agents: list[str]) -> None:
    """Build the team agents for a team of one in the environment ``spec``."""
    from realistic_indoor.agents.team import make_team_agent

    env = make_team_env(spec, 1)
    for agent in agents:
        make_team_agent(agent, env)
    env.close()


def _run(task: EpisodeTask) -> EpisodeResult:
    """One episode; user errors come back as a picklable ``ConfigError`` naming the episode."""
    try:
        return run_episode(task) if task.robots is None else run_team_episode(task)
    except RealisticIndoorError as e:
        raise ConfigError(f"{task.agent} on {task.env.label}, seed {task.seed}: {e}") from None


def _run_quietly(task: EpisodeTask) -> EpisodeResult:
    """:func:`_run` without warnings: in a worker, where this process has shown them already."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return _run(task)


def _worker_init() -> None:
    """Leave Ctrl-C to the main process, which stops the workers itself."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)


def _run_pool(
    tasks: Sequence[EpisodeTask], workers: int, done: OnResult, tick: Callable[[int], object]
) -> list[EpisodeResult]:
    results: list[EpisodeResult | None] = [None] * len(tasks)
    pool = ProcessPoolExecutor(max_workers=min(workers, len(tasks)), initializer=_worker_init)
    try:
        futures: dict[Future[EpisodeResult], int] = {
            pool.submit(_run_quietly, task): i for i, task in enumerate(tasks)
        }
        for future in as_completed(futures):
            results[futures[future]] = future.result()
            done(futures[future], future.result())
            tick(1)
    except BaseException:
        _stop(pool)
        raise
    pool.shutdown()
    return results  # type: ignore[return-value]


def _stop(pool: ProcessPoolExecutor) -> None:
    """Cancel the episodes not started and end the running ones (an error or Ctrl-C)."""
    processes = list((getattr(pool, "_processes", None) or {}).values())
    pool.shutdown(wait=False, cancel_futures=True)
    for process in processes:
        if process.is_alive():
            process.terminate()
    for process in processes:
        process.join(timeout=5)


def check_run_options(workers: int | None, use_ray: bool) -> None:
    """Refuse a bad worker count, or Ray when it is not installed, before anything runs or is written.

    Raises:
        ConfigError: If ``workers`` is not ``None`` or an integer >= 1, or ``use_ray`` without
            the ray package.
    """
    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, int) or workers < 1):
        raise ConfigError(f"workers must be an integer >= 1, got {workers!r}")
    if use_ray:
        import importlib.util

        if importlib.util.find_spec("ray") is None:
            raise ConfigError(
                "--ray needs the ray package: pip install ray (or leave out --ray to use local processes)"
            )


def _run_ray(
    tasks: Sequence[EpisodeTask], address: str | None, progress: bool, done: OnResult
) -> list[EpisodeResult]:
    try:
        import ray
    except ImportError:
        raise ConfigError(
            "--ray needs the ray package: pip install ray (or leave out --ray to use local processes)"
        ) from None
    ray.init(address=address, ignore_reinit_error=True)
    remote = ray.remote(_run_quietly)
    refs = [remote.remote(task) for task in tasks]
    index = {ref: i for i, ref in enumerate(refs)}
    results: list[EpisodeResult | None] = [None] * len(tasks)
    bar = _progress(len(tasks), progress)
    pending = list(refs)
    try:
        while pending:
            finished, pending = ray.wait(pending, num_returns=1)
            for ref in finished:
                results[index[ref]] = ray.get(ref)
                done(index[ref], results[index[ref]])
            bar.update(len(finished))
    except BaseException:
        for ref in pending:
            ray.cancel(ref)
        raise
    finally:
        bar.close()
    return results  # type: ignore[return-value]


def _progress(total: int, show: bool):
    from tqdm.auto import tqdm

    return tqdm(total=total, unit="episode", disable=not show, dynamic_ncols=True)
