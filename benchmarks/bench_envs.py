"""Benchmark of the Gymnasium environments on one core: prints Markdown tables.

Measures, in one process with random actions:

1. every registered id with its default config (``gym.make(id)``, all wrappers): steps per
   second (stepping only, and wall clock including the resets at episode ends), the time of a
   reset that draws a new building (generation plus world build) and of the world build alone,
   and memory per environment;
2. how these grow with the building's area: ``OfficeExplore-v0`` with ``area_m2`` from 250 to
   4,000 m2 (or, with ``--source plans``, fixed real plans of growing size).

Memory per environment is what eight environments allocate when made, reset and stepped
(``tracemalloc``), divided by eight; "world + map" is the part held by the world's and the
robot map's arrays.

Usage::

    .venv/bin/python benchmarks/bench_envs.py           # about three minutes
    .venv/bin/python benchmarks/bench_envs.py --quick   # about a minute
"""

from __future__ import annotations

import argparse
import gc
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
        f"| {key} | area m2 | steps/s | steps/s incl. resets | reset ms | world build ms "
        "| world + map MB | memory per env MB |"
    )
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for label, env_id, kwargs in rows:
        rate, rate_all = _step_rates(env_id, kwargs, args)
        reset_ms, build_ms, area, nbytes = _reset_cost(env_id, kwargs, args)
        memory = _memory_per_env(env_id, kwargs, args.seed)
        print(
            f"| {label} | {area:,.0f} | {rate:,.0f} | {rate_all:,.0f} | {reset_ms:.1f} | {build_ms:.1f} "
            f"| {nbytes / 1e6:.1f} | {memory:.1f} |"
        )
    print()


def _step_rates(env_id: str, kwargs: dict, args: argparse.Namespace) -> tuple[float, float]:
    """Steps per second with random actions: stepping only, and wall clock with the resets."""
    env = gym.make(env_id, **kwargs)
    env.action_space.seed(args.seed)
    actions = [env.action_space.sample() for _ in range(args.steps)]
    env.reset(seed=args.seed)
    for a in actions[:200]:  # compile the numba kernels, warm the caches
        _, _, terminated, truncated, _ = env.step(a)
        if terminated or truncated:
            env.reset()
    stepping = 0.0
    start = time.perf_counter()
    for a in actions:
        t = time.perf_counter()
        _, _, terminated, truncated, _ = env.step(a)
        stepping += time.perf_counter() - t
        if terminated or truncated:
            env.reset()
    total = time.perf_counter() - start
    env.close()
    return len(actions) / stepping, len(actions) / total


def _reset_cost(env_id: str, kwargs: dict, args: argparse.Namespace) -> tuple[float, float, float, int]:
    """Reset cost: mean seeded reset, world build, mean floor area, bytes of the arrays.

    A seeded reset draws a new building unless the source is fixed; the world build is the
    time to make the world, robot and map of the last building.
    """
    env = gym.make(env_id, **kwargs)
    env.reset(seed=args.seed)
    areas = []
    start = time.perf_counter()
    for i in range(args.resets):
        env.reset(seed=args.seed + 1 + i)
        areas.append(env.unwrapped.building.area)
    reset_ms = (time.perf_counter() - start) / args.resets * 1e3
    sim = Simulation(env.unwrapped.config)
    start = time.perf_counter()
    sim.load(env.unwrapped.building)
    build_ms = (time.perf_counter() - start) * 1e3
    nbytes = env.unwrapped.simulation.nbytes
    env.close()
    return reset_ms, build_ms, sum(areas) / len(areas), nbytes


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
