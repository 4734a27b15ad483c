"""What does a lighter robot-step change in what the baseline explorers measure?

A step's cost is mostly its laser beams and its map cells (docs/benchmarks.md): 37 beams instead
of 109 make a step 1.4-2.0 times faster, 0.1 m cells on top of that 1.03-1.3 times more (the more
robots in a batch, the more). With 0.1 m cells coverage is also counted on 0.1 m cells: that
column changes what is measured as well as what the robot senses.
Whether a user may take the faster step depends on what it changes. This experiment runs the
baseline explorers (random, wall follower, nearest frontier, utility frontier, structure-aware)
on random maps, generated offices and generated schools, with the same seeds (hence the same
buildings and starts) under the default step and under lighter ones, and reports:

1. each agent's coverage AUC under each definition, and its paired difference to the default
   (same building, same start) with a 95% bootstrap interval;
2. the agents' rankings per set under each definition, and Kendall's tau to the default's;
3. where the time of the episodes went: the agents' own thinking against the rest (the
   environment, the episode's bookkeeping).

Full run (about 11 minutes on 2 cores)::

    .venv/bin/python experiments/step_definition.py

writes ``runs/step_definition/step_definition.md`` and the raw results in
``runs/step_definition/step_definition/``; ``--out experiments/results`` regenerates the
committed results. ``--small`` runs the whole pipeline on tiny buildings in seconds (the test
suite does).
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from statistics import fmean
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
RUNS = ROOT / "runs" / "step_definition"

AGENTS = {
    "random": "random",
    "wall follower": "wall",
    "frontier": "frontier",
    "utility": "utility",
    "structure": "structure",
}
MAP_EXPLORERS = ("frontier", "utility", "structure")
"""The agents (by label) that plan on their own map and end an episode at the coverage target."""
SETS = {"random maps": "RandomExplore-v0", "offices": "OfficeExplore-v0", "schools": "SchoolExplore-v0"}
DEFINITIONS: dict[str, dict[str, Any]] = {
    "default": {},
    "37 beams": {"lidar": {"n_beams": 37}},
    "37 beams, 0.1 m cells": {"lidar": {"n_beams": 37}, "world": {"resolution_m": 0.1}},
}
"""Step definitions by label: ``gym.make`` arguments over the registered id's (``default``: none)."""
REFERENCE = "default"
METRIC = "coverage_auc"


@dataclass(frozen=True)
class Setup:
    """Size of a run.

    Attributes:
        episodes: Seeds per set (every agent and definition meets the same buildings).
        env_kwargs: ``gym.make`` arguments of every environment, under each definition's.
        area_m2: Generator area per set (``None``: the id's default).
        workers: Default number of processes.
    """

    episodes: int
    env_kwargs: dict[str, Any] = field(default_factory=dict)
    area_m2: dict[str, float] = field(default_factory=dict)
    workers: int | None = None


FULL = Setup(episodes=10)
SMALL = Setup(
    episodes=2,
    env_kwargs={"max_steps": 60},
    area_m2={"random maps": 300.0, "offices": 300.0, "schools": 800.0},
    workers=1,
)


def parse_args(argv: list[str] | None) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--small", action="store_true", help="tiny buildings, short episodes: seconds, for tests")
    p.add_argument(
        "--out",
        default=None,
        help="output folder (default runs/step_definition; with --small a new temporary one); "
        "--out experiments/results regenerates the committed results",
    )
    p.add_argument("--episodes", type=int, default=None, help="seeds per set (default 10)")
    p.add_argument("--workers", type=int, default=None, help="processes (default: one per core)")
    p.add_argument("--report-only", action="store_true", help="redo the report from the saved results")
    return p.parse_args(argv)


def main(argv: list[str] | None = None) -> int:
    from realistic_indoor.cli import checkout_commit, run_folder, script_command, write_report
    from realistic_indoor.evaluation import make_tasks, run_tasks, write_results

    args = parse_args(argv)
    setup = SMALL if args.small else FULL
    out = run_folder(args.out, RUNS, small=args.small, report_only=args.report_only, name="step_definition")
    if args.report_only:
        return write_report(out, "step_definition", analyse)
    episodes = args.episodes or setup.episodes
    results, wall_s = [], {}
    for definition in DEFINITIONS:
        tasks = make_tasks(list(AGENTS.values()), env_specs(setup, definition), episodes)
        start = time.perf_counter()
        results += run_tasks(tasks, workers=args.workers or setup.workers)
        wall_s[definition] = time.perf_counter() - start
    names = {name: label for label, name in AGENTS.items()}
    for r in results:
        r.agent = names[r.agent]
    meta = {
        "command": script_command("experiments/step_definition.py", argv),
        "commit": checkout_commit(ROOT),
        "episodes": episodes,
        "definitions": DEFINITIONS,
        "wall_s": wall_s,
        "workers": args.workers or setup.workers,
    }
    write_results(results, out / "step_definition", meta)
    return write_report(out, "step_definition", analyse, results, meta)


def env_specs(setup: Setup, definition: str) -> list:
    """One environment per set under ``definition``, grouped as ``set / definition``."""
    from realistic_indoor.evaluation import EnvSpec

    specs = []
    for label, env_id in SETS.items():
        kwargs = {**setup.env_kwargs, **DEFINITIONS[definition]}
        if label in setup.area_m2:
            kwargs["area_m2"] = setup.area_m2[label]
        name = group_name(label, definition)
        specs.append(EnvSpec(env_id, kwargs=kwargs, label=name, group=name))
    return specs


def group_name(set_label: str, definition: str) -> str:
    """The results' group of a set under a definition."""
    return f"{set_label} / {definition}"


# -- analysis ------------------------------------------------------------------------------------


def analyse(results: list, meta: dict[str, Any]) -> str:
    """The report: coverage AUC and paired differences, rankings, where the time went."""
    definitions = list(meta["definitions"])
    lighter = [d for d in definitions if d != REFERENCE]
    places = {group_name(s, d): (s, d) for s in SETS for d in definitions}
    lines = [
        "# A lighter robot-step: what it changes",
        "",
        f"Regenerate with `{meta['command']}`.",
        "",
        f"Agents: {', '.join(AGENTS)}. Sets: {', '.join(SETS)}; {meta['episodes']} seeds each, the same "
        "buildings and starts for every agent and definition. Definitions (`gym.make` arguments): "
        + "; ".join(f"{d}: `{_kwargs_text(meta['definitions'][d])}`" for d in definitions)
        + ". A definition with other cells also counts coverage on those cells (its column changes "
        "what is measured as well as what the robot senses); the explorers' own maps keep their "
        "0.1 m cells under every definition. Coverage AUC is the mean coverage over the step limit; "
        "a difference is the lighter "
        "definition's minus the default's on the same building and seed, mean and 95% bootstrap "
        "interval (* the interval excludes 0).",
        "",
        "## Coverage AUC",
        "",
        *_auc_table(results, places, lighter),
        "",
        "## Rankings by coverage AUC",
        "",
        *_rankings(results, definitions),
        "",
        "## Where the time went",
        "",
        *_time_table(results, meta, definitions, places),
    ]
    return "\n".join(lines) + "\n"


def _kwargs_text(kwargs: dict[str, Any]) -> str:
    return ", ".join(f"{k}={v}" for k, v in kwargs.items()) or "(none)"


def _auc_table(results: list, places: dict[str, tuple[str, str]], lighter: list[str]) -> list[str]:
    from realistic_indoor.evaluation.aggregate import bootstrap_mean

    head = ["set", "agent", REFERENCE]
    for d in lighter:
        head += [d, "difference"]
    lines = ["| " + " | ".join(head) + " |", "|---" * len(head) + "|"]
    values = _values(results, places)
    for set_label in SETS:
        for agent in AGENTS:
            base = values.get((set_label, REFERENCE, agent), {})
            if not base:
                continue
            cells = [set_label, agent, f"{fmean(base.values()):.3f}"]
            for d in lighter:
                other = values.get((set_label, d, agent), {})
                seeds = [s for s in base if s in other]
                if not seeds:
                    cells += ["-", "-"]
                    continue
                diff = bootstrap_mean([other[s] - base[s] for s in seeds])
                apart = diff.n > 1 and (diff.low > 0 or diff.high < 0)
                cells += [
                    f"{fmean(other.values()):.3f}",
                    f"{diff.mean:+.3f} [{diff.low:+.3f}, {diff.high:+.3f}]{' *' if apart else ''}",
                ]
            lines.append("| " + " | ".join(cells) + " |")
    return lines


def _values(
    results: list, places: dict[str, tuple[str, str]]
) -> dict[tuple[str, str, str], dict[int, float]]:
    """Coverage AUC by ``(set, definition, agent)`` and seed.

    Args:
        results: The episodes.
        places: ``(set, definition)`` of each group (:func:`group_name`); other groups are left out.
    """
    out: dict[tuple[str, str, str], dict[int, float]] = {}
    for r in results:
        if r.group in places:
            out.setdefault((*places[r.group], r.agent), {})[r.seed] = float(getattr(r, METRIC))
    return out


def _rankings(results: list, definitions: list[str]) -> list[str]:
    from realistic_indoor.evaluation import summarize
    from realistic_indoor.evaluation.ranking import kendall_tau, rankings

    order = rankings(summarize(results), METRIC)
    lines = []
    for set_label in SETS:
        reference = order.get(group_name(set_label, REFERENCE))
        for d in definitions:
            ranked = order.get(group_name(set_label, d))
            if ranked is None:
                continue
            tau = kendall_tau(reference, ranked) if reference and d != REFERENCE else math.nan
            versus = f" (Kendall tau to the default's: {tau:+.2f})" if math.isfinite(tau) else ""
            lines.append(f"- **{set_label}, {d}**: {' > '.join(ranked)}{versus}")
    return lines


def _time_table(
    results: list, meta: dict[str, Any], definitions: list[str], places: dict[str, tuple[str, str]]
) -> list[str]:
    workers = meta.get("workers")
    lines = [
        "Steps of every episode (and of the map-based explorers', which stop at 90% coverage; the "
        "others always drive the whole step limit), the agents' own thinking (the sum of their wall "
        "time per step), and the wall clock of the definition's episodes, run by "
        f"{'one process per core' if workers is None else f'--workers {workers}'}. Times depend on "
        "the machine and its load; the steps do not.",
        "",
        "| definition | steps | of the map-based explorers | agents' thinking s | wall clock s |",
        "|---|---:|---:|---:|---:|",
    ]
    for d in definitions:
        mine = [r for r in results if r.group in places and places[r.group][1] == d]
        steps = sum(r.steps for r in mine)
        explorers = sum(r.steps for r in mine if r.agent in MAP_EXPLORERS)
        thinking = sum(r.agent_ms_per_step * r.steps for r in mine) / 1000.0
        wall = meta.get("wall_s", {}).get(d, math.nan)
        lines.append(f"| {d} | {steps:,} | {explorers:,} | {thinking:,.0f} | {wall:,.0f} |")
    return lines


if __name__ == "__main__":
    from realistic_indoor.cli import run_script

    sys.exit(run_script(main, "step_definition.py"))
