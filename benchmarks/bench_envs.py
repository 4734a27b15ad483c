"""Benchmark of the Gymnasium environments on one core: prints Markdown tables.

Measures, in one process with random actions, after ``CartPole-v1`` (``gym.make``, random
actions, the same loop) as the yardstick: every rate is also given as a ratio to CartPole-v1's
steps/s measured in the same run, and every reset in CartPole steps, so that figures from
different machines compare (the header names the CPU model, its cores and the load):

1. every registered id with its default config (``gym.make(id)``, all wrappers): steps per
   second (stepping only: the median of five blocks; and including the resets, from the median
   reset time and the mean length of the random-action episodes), the median time of a reset
   that draws a new building (generation, world build, victims) and of the world build alone,
   and memory per environment;
2. how these grow with the building's area: ``OfficeExplore-v0`` with ``area_m2`` from 250 to
   4,000 m2 (or, with ``--source plans``, fixed real plans of growing size);
3. a reset of ``OfficeExplore-v0`` with a new default office, split into generating the
   building and building its world (raster, distance transform, reachable floor, physics, map),
   side by side in one run;
4. the native vector environment (``gym.make_vec("OfficeExplore-v0", num_envs=N)``): total
   robot-steps per second over all N default offices, on one thread and on every core, by wall
   clock (threads share the process's CPU time), after 100 warm-up steps; memory per sub-env.

Times are CPU seconds of the benchmark's process (``time.process_time``), so that other jobs on
a shared machine do not count; on a quiet machine wall clock agrees. Memory per environment is
what eight environments allocate when made, reset and stepped (``tracemalloc``), divided by
eight; "world + map" is the part held by the world's and the robot map's arrays.

Usage::

    .venv/bin/python benchmarks/bench_envs.py           # about three minutes
    .venv/bin/python benchmarks/bench_envs.py --quick   # about a minute
    .venv/bin/python benchmarks/bench_envs.py --skip-growth --ids OfficeExplore-v0 \
        --env-kwargs '{"lidar": {"n_beams": 37}, "world": {"resolution_m": 0.1}}'   # another definition

``--env-kwargs`` gives every environment made here (both tables of ids, the reset split, the
vector env) the same config changes, as ``gym.make(id, **kwargs)`` takes them.
"""

from __future__ import annotations

import argparse
import gc
import json
import statistics
import time
import tracemalloc
from pathlib import Path

import gymnasium as gym
import numpy as np
from bench_sim import PLAN_FILES, PLANS  # the simulator benchmark's plans, spanning sizes

import realistic_indoor.envs  # noqa: F401  (registers the ids)
from realistic_indoor.envs import PRESETS, preset_config
from realistic_indoor.envs.simulation import Simulation
from realistic_indoor.envs.vector import step_threads
from realistic_indoor.errors import ConfigError
from realistic_indoor.machine import describe_machine

AREAS_M2 = (250, 500, 1000, 2000, 4000)
YARDSTICK = "CartPole-v1"
MEMORY_ENVS = 8
BLOCKS = 5

_clock = time.process_time
"""Times are CPU time of this process: on a shared machine, other processes taking the core
stretch wall-clock times but not this one (as long as it fits in the caches)."""


def main(argv: list[str] | None = None) -> None:
    """Run the benchmark and print its tables."""
    args = _parse(argv)
    print(f"# Environment benchmark ({'quick' if args.quick else 'full'}; one process, one core)\n")
    print(f"Machine: {machine()}\n")
    if args.env_kwargs:
        print(f"Every environment made with the config changes {json.dumps(args.env_kwargs)}.\n")
    args.yardstick = step_rate(YARDSTICK, {}, args)[0]
    print(
        f"Yardstick: {YARDSTICK} (gym.make, random actions, the same loop) steps at "
        f"{args.yardstick:,.0f} steps/s; ratios below are to this.\n"
    )
    if args.source == "generator":
        _table(
            "Registered environments, default config",
            "id",
            [(env_id, env_id, dict(args.env_kwargs)) for env_id in args.ids],
            args,
        )
        rows = [(f"{a} m2", "OfficeExplore-v0", {**args.env_kwargs, "area_m2": float(a)}) for a in AREAS_M2]
        if not args.skip_growth:
            _table("Growth with area: OfficeExplore-v0, area_m2 asked of the generator", "area", rows, args)
        _reset_split_table("OfficeExplore-v0", args)
        _vector_table("OfficeExplore-v0", args)
    else:
        from realistic_indoor.io import load

        rows = []
        for name in PLAN_FILES:
            building = load(args.plans_dir / name)
            rows.append((Path(name).stem, "OfficeExplore-v0", {**args.env_kwargs, "building": building}))
        _table("Growth with area: OfficeExplore-v0 on fixed real plans", "plan", rows, args)


def _parse(argv: list[str] | None) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument(
        "--source", choices=("generator", "plans"), default="generator", help="where buildings come from"
    )
    p.add_argument("--plans-dir", type=Path, default=PLANS, help="folder of the real floor plans")
    p.add_argument("--ids", nargs="+", default=sorted(PRESETS), help="registered ids to measure")
    p.add_argument("--quick", action="store_true", help="fewer steps and resets")
    p.add_argument("--skip-growth", action="store_true", help="leave out the growth-with-area table")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument(
        "--env-kwargs",
        type=_json_object,
        default={},
        metavar="JSON",
        help='config changes for every environment, e.g. \'{"lidar": {"n_beams": 37}}\'',
    )
    args = p.parse_args(argv)
    try:
        preset_config("OfficeExplore-v0", **args.env_kwargs)
    except ConfigError as e:
        p.error(f"--env-kwargs: {e}")
    args.steps = 5_000 if args.quick else 20_000
    args.resets = 5 if args.quick else 20
    return args


def _json_object(text: str) -> dict:
    """``text`` parsed as a JSON object (argparse reports the error otherwise)."""
    try:
        value = json.loads(text)
    except json.JSONDecodeError as e:
        raise argparse.ArgumentTypeError(f"not JSON ({e.msg}): {text!r}") from None
    if not isinstance(value, dict):
        raise argparse.ArgumentTypeError(f"not a JSON object of config changes: {text!r}")
    return value


def machine() -> str:
    """CPU model, logical cores and the load average: what the absolute figures depend on."""
    return describe_machine()


def _table(title: str, key: str, rows: list[tuple[str, str, dict]], args: argparse.Namespace) -> None:
    print(f"## {title}\n")
    print(
        f"| {key} | area m2 | steps/s | x {YARDSTICK} | steps/s incl. resets | x {YARDSTICK} "
        "| episode steps | reset ms | reset in CartPole steps | world build ms | world + map MB "
        "| memory per env MB |"
    )
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    ys = args.yardstick
    for label, env_id, kwargs in rows:
        rate, episode_steps = step_rate(env_id, kwargs, args)
        reset_ms, build_ms, area, nbytes = _reset_cost(env_id, kwargs, args)
        with_resets = 1.0 / (1.0 / rate + reset_ms / 1e3 / episode_steps)
        memory = _memory_per_env(env_id, kwargs, args.seed)
        print(
            f"| {label} | {area:,.0f} | {rate:,.0f} | {rate / ys:.3f} | {with_resets:,.0f} | {with_resets / ys:.3f} "
            f"| {episode_steps:,.0f} | {reset_ms:.1f} | {reset_ms / 1e3 * ys:,.0f} | {build_ms:.1f} "
            f"| {nbytes / 1e6:.1f} | {memory:.1f} |"
        )
    print()


def _reset_split_table(env_id: str, args: argparse.Namespace) -> None:
    """Median time to generate a new building and to build its world, side by side (ms)."""
    env = gym.make(env_id, **args.env_kwargs)
    config = env.unwrapped.config
    env.close()
    generate = config.source.generator()
    generate(np.random.default_rng(args.seed))  # warm the kernels and caches
    gen_ms, build_ms, areas = [], [], []
    for i in range(args.resets):
        rng = np.random.default_rng(args.seed + 1 + i)
        start = _clock()
        building = generate(rng)
        gen_ms.append(1e3 * (_clock() - start))
        sim = Simulation(config)
        start = _clock()
        sim.load(building)
        build_ms.append(1e3 * (_clock() - start))
        areas.append(building.area)
    gen, build = statistics.median(gen_ms), statistics.median(build_ms)
    ys = args.yardstick
    print(f"## Reset of {env_id} with a new default building: generation and world build\n")
    print(f"Median of {args.resets} seeds; mean floor area {statistics.mean(areas):,.0f} m2.\n")
    print("| part | ms | in CartPole steps |")
    print("|---|---:|---:|")
    for name, ms in (("generation", gen), ("world build", build), ("total", gen + build)):
        print(f"| {name} | {ms:.1f} | {ms / 1e3 * ys:,.0f} |")
    print()


def _vector_table(env_id: str, args: argparse.Namespace) -> None:
    """Robot-steps per second of the native vector env, by N and threads (wall clock)."""
    import numba

    ys = args.yardstick
    print(f"## Native vector environment: gym.make_vec({env_id!r}, num_envs=N)\n")
    print(f"Wall clock, median of {BLOCKS} blocks of 100 steps; random actions.\n")
    print(f"| N | threads | robot-steps/s | x {YARDSTICK} | MB per sub-env |")
    print("|---:|---:|---:|---:|---:|")
    for n in (1, 8) if args.quick else (1, 8, 64):
        envs = gym.make_vec(env_id, num_envs=n, **args.env_kwargs)
        envs.reset(seed=args.seed)
        actions = np.random.default_rng(args.seed).uniform(-1, 1, (100, n, 2)).astype(np.float32)
        for a in actions:
            envs.step(a)
        for used in sorted({step_threads(n, t) for t in (1, numba.config.NUMBA_NUM_THREADS)}):
            numba.set_num_threads(used)
            rates = []
            for _ in range(BLOCKS):
                start = time.perf_counter()
                for a in actions:
                    envs.step(a)
                rates.append(n * len(actions) / (time.perf_counter() - start))
            rate = statistics.median(rates)
            print(f"| {n} | {used} | {rate:,.0f} | {rate / ys:.3f} | {envs.nbytes / n / 1e6:.1f} |")
        numba.set_num_threads(numba.config.NUMBA_NUM_THREADS)
        envs.close()
    print()


def step_rate(env_id: str, kwargs: dict, args: argparse.Namespace) -> tuple[float, float]:
    """Steps per second with random actions (resets not timed), and the mean episode length.

    The steps run in five blocks; the rate is the median block's (each block's time less its
    resets, timed apart). The same loop measures the yardstick, CartPole-v1.
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
    times, lengths, length = [], [], 0
    for k in range(BLOCKS):
        resetting = 0.0
        start = _clock()
        for a in actions[k * block : (k + 1) * block]:
            _, _, terminated, truncated, _ = env.step(a)
            length += 1
            if terminated or truncated:
                lengths.append(length)
                length = 0
                t = _clock()
                env.reset()
                resetting += _clock() - t
        times.append(_clock() - start - resetting)
    max_steps = env.spec.max_episode_steps or args.steps
    env.close()
    return block / statistics.median(times), (statistics.mean(lengths) if lengths else max_steps)


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
