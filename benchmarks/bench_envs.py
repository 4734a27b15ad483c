"""Benchmark of the Gymnasium environments on one core: prints Markdown tables.

Measures, in one process with random actions:

1. every registered id with its default config (``gym.make(id)``, all wrappers): steps per
   second (stepping only: the best of five blocks; and including the resets, from the median
   reset time and the mean length of the random-action episodes), the median time of a reset
   that draws a new building (generation, world build, victims) and of the world build alone,
   and memory per environment;
2. how these grow with the building's area: ``OfficeExplore-v0`` with ``area_m2`` from 250 to
   4,000 m2 (or, with ``--source plans``, fixed real plans of growing size).

Times are CPU seconds of the benchmark's process (``time.process_time``), so that other jobs on
a shared machine do not count; on a quiet machine wall clock agrees. Memory per environment is
what eight environments allocate when made, reset and stepped (``tracemalloc``), divided by
eight; "world + map" is the part held by the world's and the robot map's arrays.

Usage::

    .venv/bin/python benchmarks/bench_envs.py           # about three minutes
    .venv/bin/python benchmarks/bench_envs.py --quick   # about a minute
"""

from __future__ import annotations

import argparse
import gc
import statistics
import time
import tracemalloc
from pathlib import Path

import gymnasium as gym
from bench_sim import PLAN_FILES, PLANS  # the simulator benchmark's plans, spanning sizes

import realistic_indoor.envs  # noqa: F401  (registers the ids)
from realistic_indoor.envs import PRESETS
from realistic_indoor.envs.simulation import Simulation

AREAS_M2 = (250, 500, 1000, 2000, 4000)
MEMORY_ENVS = 8
BLOCKS = 5

_clock = time.process_time
"""Times are CPU time of this process: on a shared machine, other processes taking the core
stretch wall-clock times but not this one (as long as it fits in the caches)."""


def main(argv: list[str] | None = None) -> None:
    """Run the benchmark and print its tables."""
    args = _parse(argv)
    print(f"# Environment benchmark ({'quick' if args.quick else 'full'}; one process, one core)\n")
    if args.source == "generator":
        _table(
            "Registered environments, default config",
            "id",
            [(env_id, env_id, {}) for env_id in args.ids],
            args,
        )
        rows = [(f"{a} m2", "OfficeExplore-v0", {"area_m2": float(a)}) for a in AREAS_M2]
        _table("Growth with area: OfficeExplore-v0, area_m2 asked of the generator", "area", rows, args)
    else:
        from realistic_indoor.io import load

        rows = []
        for name in PLAN_FILES:
            building = load(args.plans_dir / name)
            rows.append((Path(name).stem, "OfficeExplore-v0", {"building": building}))
        _table("Growth with area: OfficeExplore-v0 on fixed real plans", "plan", rows, args)


def _parse(argv: list[str] | None) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument(
        "--source", choices=("generator", "plans"), default="generator", help="where buildings come from"
    )
    p.add_argument("--plans-dir", type=Path, default=PLANS, help="folder of the real floor plans")
    p.add_argument("--ids", nargs="+", default=sorted(PRESETS), help="registered ids to measure")
    p.add_argument("--quick", action="store_true", help="fewer steps and resets")
    p.add_argument("--seed", type=int, default=0)
    args = p.parse_args(argv)
    args.steps = 5_000 if args.quick else 20_000
    args.resets = 5 if args.quick else 20
    return args


def _table(title: str, key: str, rows: list[tuple[str, str, dict]], args: argparse.Namespace) -> None:
    print(f"## {title}\n")
    print(
        f"| {key} | area m2 | steps/s | steps/s incl. resets | episode steps | reset ms | world build ms "
        "| world + map MB | memory per env MB |"
    )
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for label, env_id, kwargs in rows:
        rate, episode_steps = _step_rate(env_id, kwargs, args)
        reset_ms, build_ms, area, nbytes = _reset_cost(env_id, kwargs, args)
        with_resets = 1.0 / (1.0 / rate + reset_ms / 1e3 / episode_steps)
        memory = _memory_per_env(env_id, kwargs, args.seed)
        print(
            f"| {label} | {area:,.0f} | {rate:,.0f} | {with_resets:,.0f} | {episode_steps:,.0f} | {reset_ms:.1f} "
            f"| {build_ms:.1f} | {nbytes / 1e6:.1f} | {memory:.1f} |"
        )
    print()


def _step_rate(env_id: str, kwargs: dict, args: argparse.Namespace) -> tuple[float, float]:
    """Steps per second with random actions (resets not timed), and the mean episode length.

    The steps run in five blocks; the rate is the best block's, as ``timeit`` reports the
    best repeat: other processes on a shared machine only ever slow a block down.
    """
    env = gym.make(env_id, **kwargs)
    env.action_space.seed(args.seed)
    actions = [env.action_space.sample() for _ in range(args.steps)]
    env.reset(seed=args.seed)
    for a in actions[:200]:  # compile the numba kernels, warm the caches
        _, _, terminated, truncated, _ = env.step(a)
        if terminated or truncated:
            env.reset()
    env.reset()
    block = len(actions) // BLOCKS
    best, lengths, length = float("inf"), [], 0
    for k in range(BLOCKS):
        stepping = 0.0
        for a in actions[k * block : (k + 1) * block]:
            t = _clock()
            _, _, terminated, truncated, _ = env.step(a)
            stepping += _clock() - t
            length += 1
            if terminated or truncated:
                lengths.append(length)
                length = 0
                env.reset()
        best = min(best, stepping)
    max_steps = env.unwrapped.config.max_steps
    env.close()
    return block / best, (statistics.mean(lengths) if lengths else max_steps)


def _reset_cost(env_id: str, kwargs: dict, args: argparse.Namespace) -> tuple[float, float, float, int]:
    """Median seeded reset and world build (ms), mean floor area (m2), bytes of the arrays.

    A seeded reset draws a new building (unless the source is fixed); the world build is the
    part of it that makes the world, robot and map of that building, timed on its own.
    """
    env = gym.make(env_id, **kwargs)
    env.reset(seed=args.seed)
    resets, builds, areas = [], [], []
    for i in range(args.resets):
        start = _clock()
        env.reset(seed=args.seed + 1 + i)
        resets.append(_clock() - start)
        building = env.unwrapped.building
        areas.append(building.area)
        sim = Simulation(env.unwrapped.config)
        start = _clock()
        sim.load(building)
        builds.append(_clock() - start)
    nbytes = env.unwrapped.simulation.nbytes
    env.close()
    return 1e3 * statistics.median(resets), 1e3 * statistics.median(builds), statistics.mean(areas), nbytes


def _memory_per_env(env_id: str, kwargs: dict, seed: int) -> float:
    """Memory allocated per environment made, reset and stepped once (MB).

    Counted with ``tracemalloc``, which sees Python objects and NumPy arrays (not pymunk's
    C structures, a few hundred bytes per wall segment).
    """
    gc.collect()
    tracemalloc.start()
    before = tracemalloc.get_traced_memory()[0]
    envs = [gym.make(env_id, **kwargs) for _ in range(MEMORY_ENVS)]
    for i, env in enumerate(envs):
        env.reset(seed=seed + i)
        env.step(env.action_space.sample())
    grown = tracemalloc.get_traced_memory()[0] - before
    tracemalloc.stop()
    for env in envs:
        env.close()
    return grown / MEMORY_ENVS / 1e6


if __name__ == "__main__":
    main()
