"""Does the learned explorer beat the classical ones? Paired, on generated and on real buildings.

The learned explorer (``learned``: a trained policy choosing among candidate goals, the
explorers' navigator driving) runs beside the nearest-frontier, utility and structure explorers
on generated offices, schools and houses (their default sizes and step limits, seeds from 1000:
never trained or tuned on) and on the shared real plans (offices and schools, one episode each).
The report gives each agent's mean coverage AUC per set and the learned explorer's paired
difference from each classical one (the same building and start), with 95% bootstrap intervals.

Full run (about 25 minutes on 2 cores)::

    .venv/bin/python experiments/learned_explorer.py --out experiments/results

writes ``learned_explorer.md`` and the raw results in ``learned_explorer/``. ``--model`` evaluates
another model (``learned:PATH``); ``--small`` runs the pipeline on houses in seconds (the tests do).
"""

from __future__ import annotations

import argparse
import sys
from dataclasses import dataclass, field
from pathlib import Path
from statistics import fmean
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
REAL_PLANS = ROOT.parent / "shared" / "data" / "real_floorplans"
RUNS = ROOT / "runs" / "learned_explorer"

BASELINES = {"frontier": "frontier", "utility": "utility", "structure": "structure"}
GENERATED = {"offices": "OfficeExplore-v0", "schools": "SchoolExplore-v0", "houses": "HouseExplore-v0"}
REAL = {"real offices": ("OfficeExplore-v0", "office"), "real schools": ("SchoolExplore-v0", "school")}
LEARNED = "learned"
METRIC = "coverage_auc"


@dataclass(frozen=True)
class Setup:
    """Size of a run.

    Attributes:
        episodes: Seeds per generated set.
        seed: First seed.
        sets: The generated sets run.
        real: Whether the real plans run.
        env_kwargs: ``gym.make`` arguments of every environment.
        workers: Default number of processes.
    """

    episodes: int
    seed: int = 1000
    sets: tuple[str, ...] = tuple(GENERATED)
    real: bool = True
    env_kwargs: dict[str, Any] = field(default_factory=dict)
    workers: int | None = None


FULL = Setup(episodes=10)
SMALL = Setup(episodes=2, sets=("houses",), real=False, env_kwargs={"max_steps": 60}, workers=1)


def parse_args(argv: list[str] | None) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--small", action="store_true", help="houses, short episodes: seconds, for tests")
    p.add_argument(
        "--out",
        default=None,
        help="output folder (default runs/learned_explorer; with --small a new temporary one); "
        "--out experiments/results regenerates the committed results",
    )
    p.add_argument("--model", default=None, help="the learned model (.zip; default: the committed one)")
    p.add_argument("--episodes", type=int, default=None, help="seeds per generated set (default 10)")
    p.add_argument("--workers", type=int, default=None, help="processes (default: one per core)")
    p.add_argument("--report-only", action="store_true", help="redo the report from the saved results")
    return p.parse_args(argv)


def main(argv: list[str] | None = None) -> int:
    from realistic_indoor.cli import checkout_commit, run_folder, script_command, write_report
    from realistic_indoor.evaluation import make_tasks, run_tasks, write_results

    args = parse_args(argv)
    setup = SMALL if args.small else FULL
    out = run_folder(args.out, RUNS, small=args.small, report_only=args.report_only, name="learned_explorer")
    if args.report_only:
        return write_report(out, "learned_explorer", analyse)
    learned = f"learned:{args.model}" if args.model else "learned"
    agents = {LEARNED: learned, **BASELINES}
    episodes = args.episodes or setup.episodes
    generated, real = env_sets(setup)
    tasks = make_tasks(list(agents.values()), generated, episodes, seed=setup.seed)
    if real:
        tasks += make_tasks(list(agents.values()), real, 1, seed=setup.seed)
    results = run_tasks(tasks, workers=args.workers or setup.workers)
    names = {name: label for label, name in agents.items()}
    for r in results:
        r.agent = names[r.agent]
    meta = {
        "command": script_command("experiments/learned_explorer.py", argv),
        "commit": checkout_commit(ROOT),
        "model": args.model or "the committed model (realistic_indoor/data/learned_explorer.zip)",
        "episodes": episodes,
        "seed": setup.seed,
        "sets": [*setup.sets, *(REAL if real else ())],
    }
    write_results(results, out / "learned_explorer", meta)
    return write_report(out, "learned_explorer", analyse, results, meta)


def env_sets(setup: Setup) -> tuple[list, list]:
    """The generated sets (one spec each) and the real plans (one spec per plan)."""
    from realistic_indoor.evaluation import EnvSpec

    generated = [
        EnvSpec(GENERATED[label], kwargs=dict(setup.env_kwargs), label=label, group=label)
        for label in setup.sets
    ]
    real = []
    for label, (env_id, folder) in REAL.items() if setup.real else ():
        plans = sorted((REAL_PLANS / folder).glob("*.xml")) if (REAL_PLANS / folder).is_dir() else []
        real += [
            EnvSpec(env_id, str(plan), dict(setup.env_kwargs), label=f"{label}: {plan.stem}", group=label)
            for plan in plans
        ]
    if setup.real and not real:
        print(f"no real plans at {REAL_PLANS}: the real-buildings sets are left out", flush=True)
    return generated, real


def analyse(results: list, meta: dict[str, Any]) -> str:
    """The report: coverage AUC per agent and set, and the learned explorer's paired differences."""
    from realistic_indoor.evaluation.aggregate import bootstrap_mean

    values: dict[tuple[str, str], dict[tuple[str, int], float]] = {}
    for r in results:
        values.setdefault((r.group, r.agent), {})[(r.env, r.seed)] = float(getattr(r, METRIC))
    sets = [s for s in meta["sets"] if any(g == s for g, _ in values)]
    agents = [LEARNED, *BASELINES]
    head = ["set", "episodes", *agents, *(f"learned - {b}" for b in BASELINES)]
    lines = [
        "# The learned explorer against the classical ones",
        "",
        f"Regenerate with `{meta['command']}` (commit {meta['commit']}; model: {meta['model']}).",
        "",
        f"Coverage AUC (mean coverage over the step limit). Generated sets: {meta['episodes']} seeds each "
        f"from {meta['seed']}, default sizes and step limits; real sets: every shared plan, one episode. "
        "A difference is the learned explorer's AUC minus the other's on the same building and start, "
        "mean and 95% bootstrap interval (* the interval excludes 0).",
        "",
        "| " + " | ".join(head) + " |",
        "|---" * len(head) + "|",
    ]
    for s in sets:
        mine = values.get((s, LEARNED), {})
        cells = [s, str(len(mine))]
        cells += [f"{fmean(values[(s, a)].values()):.3f}" if values.get((s, a)) else "-" for a in agents]
        for b in BASELINES:
            other = values.get((s, b), {})
            keys = [k for k in mine if k in other]
            if not keys:
                cells.append("-")
                continue
            d = bootstrap_mean([mine[k] - other[k] for k in keys])
            apart = d.n > 1 and (d.low > 0 or d.high < 0)
            cells.append(f"{d.mean:+.3f} [{d.low:+.3f}, {d.high:+.3f}]{' *' if apart else ''}")
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    from realistic_indoor.cli import run_script

    sys.exit(run_script(main, "learned_explorer.py"))
