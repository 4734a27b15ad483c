"""Benchmark of the building generators on one core: prints Markdown tables.

1. Speed: median time to generate one building (``gen(rng)``, the call environments make each
   episode) at 500, 2,000 and 8,000 m2 for offices, schools (default block layout, and the
   paper's model with the wing layout) and the random baseline, and at 150, 500 and 1,000 m2
   for houses (their largest size), with the median ``check_building`` time beside it for scale.
   Each time is also given in CartPole-v1 steps (``gym.make``, random actions) measured in the
   same run, and the machine is named, because absolute figures differ between machines.
2. Realism: Table 1 of the paper next to the same statistics over generated buildings at
   default size (the paper's model, the default model fitted to real plans, and the
   World-Generator-like baseline), with the paper's connectivity facts.

Usage::

    .venv/bin/python benchmarks/bench_generate.py           # about two minutes
    .venv/bin/python benchmarks/bench_generate.py --quick   # about half a minute
"""

from __future__ import annotations

import argparse
import platform
import statistics
import time

import gymnasium as gym
import numpy as np
from bench_envs import machine

from realistic_indoor.building import SemanticLabel, check_building
from realistic_indoor.generator import make_generator
from realistic_indoor.models import connectivity_facts, reference_table
from realistic_indoor.validator.connectivity import Connectivity, connectivity
from realistic_indoor.validator.tables import label_table

SIZES_M2 = {
    "office": (500, 2000, 8000),
    "school": (500, 2000, 8000),
    "random": (500, 2000, 8000),
    "house": (150, 500, 1000),
}


def main(argv: list[str] | None = None) -> None:
    """Run the benchmark and print its tables."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer buildings per measurement")
    args = parser.parse_args(argv)
    runs, sample = (15, 60) if args.quick else (40, 200)
    print(f"# Generator benchmark ({'quick' if args.quick else 'full'}; one process, one core)\n")
    print(f"Python {platform.python_version()}, NumPy {np.__version__}, {machine()}\n")
    yardstick = _cartpole_rate()
    print(f"CartPole-v1 (gym.make, random actions): {yardstick:,.0f} steps/s in this run.\n")
    _speed(runs, yardstick)
    for kind in ("office", "school", "house"):
        _realism(kind, sample)


def _median_ms(fn, runs: int) -> float:
    times = []
    for seed in range(runs):
        t = time.perf_counter()
        fn(seed)
        times.append(time.perf_counter() - t)
    return 1000 * statistics.median(times)


def _cartpole_rate(steps: int = 20_000) -> float:
    """CartPole-v1 steps per second with random actions: the yardstick measured in this run."""
    env = gym.make("CartPole-v1")
    env.action_space.seed(0)
    actions = [env.action_space.sample() for _ in range(steps)]
    env.reset(seed=0)
    start = time.perf_counter()
    for a in actions:
        _, _, terminated, truncated, _ = env.step(a)
        if terminated or truncated:
            env.reset()
    return steps / (time.perf_counter() - start)


def _speed(runs: int, yardstick: float) -> None:
    print(f"## Time per building (median of {runs} seeds, ms)\n")
    print(
        "| generator | area m2 | rooms | generate ms | ms per 1000 m2 | in CartPole steps | check_building ms |"
    )
    print("|---|---|---|---|---|---|---|")
    variants = [(k, {}) for k in SIZES_M2] + [("office", {"model": "paper"}), ("school", {"model": "paper"})]
    for kind, options in variants:
        for area in SIZES_M2[kind]:
            gen = make_generator(kind, area, **options)
            gen(np.random.default_rng(10_000))
            built = [gen(np.random.default_rng(s)) for s in range(runs)]
            ms = _median_ms(lambda s, g=gen: g(np.random.default_rng(s)), runs)
            check = _median_ms(lambda s, b=built: check_building(b[s]), runs)
            real_area = statistics.median(b.area for b in built)
            rooms = statistics.median(len(b.rooms) for b in built)
            name = f"{kind} (paper, wings)" if options else kind
            print(
                f"| {name} | {real_area:,.0f} | {rooms:.0f} | {ms:.1f} | {ms / real_area * 1000:.1f} "
                f"| {ms / 1000 * yardstick:,.0f} | {check:.1f} |"
            )
    print()


def _row(table: dict, lab: SemanticLabel) -> list[str]:
    r = table[lab]
    return [
        f"{r['share_pct']:.1f}",
        f"{r['area_mean']:.1f}",
        f"{r['doors_mean']:.2f}",
        f"{r['axes_ratio_mean']:.1f}",
    ]


def _realism(kind: str, sample: int) -> None:
    paper = reference_table(kind)
    sets = {"paper": paper}
    conn = {}
    generators = [(kind, make_generator(kind))]
    if kind != "house":
        generators = [
            (f"{kind} (paper)", make_generator(kind, model="paper")),
            (f"{kind} (default)", generators[0][1]),
        ]
    if kind == "office":
        generators.append(("random", make_generator("random")))
    for name, gen in generators:
        built = [gen(np.random.default_rng(s)) for s in range(sample)]
        sets[name] = label_table(built)
        conn[name] = Connectivity.combine([connectivity(b) for b in built])
    names = list(sets)
    print(f"## {kind.capitalize()}: Table 1 of the paper and {sample} generated buildings at default size\n")
    print("share %, mean area m2, mean doors, mean axes ratio per label; columns: " + ", ".join(names) + "\n")
    print("| label | " + " | ".join(f"{n} share | {n} area | {n} doors | {n} ratio" for n in names) + " |")
    print("|---|" + "---|" * (4 * len(names)))
    for lab in SemanticLabel:
        cells = [c for n in names for c in _row(sets[n], lab)]
        print(f"| {lab.value} | " + " | ".join(cells) + " |")
    if conn:
        facts = connectivity_facts() if kind == "office" else {}
        print("\n| connectivity | " + " | ".join(conn) + (" | paper |" if facts else " |"))
        print("|---|" + "---|" * (len(conn) + bool(facts)))
        rows = [
            (
                "core rooms touching a corridor %",
                "core_touching_corridor_pct",
                "office_real_offices_connected_to_a_corridor_pct",
            ),
            (
                "rooms connected only to corridors %",
                "only_to_corridors_pct",
                "office_real_rooms_connected_only_to_corridors_pct",
            ),
            ("rooms in room mazes %", "maze_rooms_pct", None),
            ("mean path between rooms (doors)", "mean_path_doors", None),
        ]
        for title, key, fact in rows:
            values = " | ".join(f"{getattr(c, key):.1f}" for c in conn.values())
            paper_value = f" | {facts[fact]:.0f}" if facts and fact else (" | -" if facts else "")
            print(f"| {title} | {values}{paper_value} |")
    print()


if __name__ == "__main__":
    main()
