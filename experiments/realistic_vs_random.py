"""Do exploration results on random maps carry over to realistic and to real buildings?

The paper's claim is that robots tested on random (World-Generator-like) maps are tested on the
wrong thing. This experiment measures it:

1. Ranking: the baseline explorers (random, wall follower, nearest frontier, utility frontier,
   structure-aware) and two PPO policies run on random maps, on realistic offices, schools and
   houses, and on the shared real plans (offices and schools, entrances inferred). Agents are
   ranked per set by coverage AUC (mean coverage over the step limit: exploring fast); the
   report says where the rankings and the metrics differ from those on random maps.
2. Transfer: PPO trained on random maps and PPO trained on realistic maps (same budget) are
   compared, episode by episode, on realistic maps and on the real plans.

Full run (PPO models are trained first if missing, about 20 minutes each; then about an hour of
episodes on 2 cores)::

    .venv/bin/python experiments/realistic_vs_random.py

writes ``runs/realistic_vs_random/realistic_vs_random.md`` (tables and findings),
``realistic_vs_random.png`` (coverage AUC per agent and set), ``realistic_vs_random_curves.png``
and the raw results in ``runs/realistic_vs_random/realistic_vs_random/``; ``--out
experiments/results`` regenerates the committed results. ``--small`` runs the whole
pipeline on tiny buildings in seconds (the test suite does).
"""

from __future__ import annotations

import argparse
import math
import os
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
REAL_PLANS = ROOT.parent / "shared" / "data" / "real_floorplans"
RESULTS = ROOT / "experiments" / "results"
RUNS = ROOT / "runs" / "realistic_vs_random"

BASELINES = {
    "random": "random",
    "wall follower": "wall",
    "frontier": "frontier",
    "utility": "utility",
    "structure": "structure",
}
PPO_MODELS = {"PPO (random maps)": "ppo_random", "PPO (realistic maps)": "ppo_realistic"}
GENERATED = {
    "random maps": "RandomExplore-v0",
    "offices": "OfficeExplore-v0",
    "schools": "SchoolExplore-v0",
    "houses": "HouseExplore-v0",
}
REAL = {"real offices": ("OfficeExplore-v0", "office"), "real schools": ("SchoolExplore-v0", "school")}
TRAIN_SETS = {"ppo_random": "random", "ppo_realistic": "realistic"}
RANK_METRIC = "coverage_auc"


@dataclass(frozen=True)
class Setup:
    """Size of a run.

    Attributes:
        episodes: Seeds per generated set (every agent meets the same buildings).
        plans_per_set: Real plans per set (``None``: all of them), one episode each.
        env_kwargs: ``gym.make`` arguments of every environment (areas, step limits).
        area_m2: Generator area per generated set (``None``: the id's default).
        ppo_preset: Training preset of missing PPO models.
        workers: Default number of processes.
    """

    episodes: int
    plans_per_set: int | None
    env_kwargs: dict[str, Any] = field(default_factory=dict)
    area_m2: dict[str, float] = field(default_factory=dict)
    ppo_preset: str = "default"
    workers: int | None = None


FULL = Setup(episodes=10, plans_per_set=None)
SMALL = Setup(
    episodes=1,
    plans_per_set=1,
    env_kwargs={"max_steps": 60},
    area_m2={"random maps": 300.0, "offices": 300.0, "schools": 800.0, "houses": 100.0},
    ppo_preset="smoke",
    workers=1,
)


def parse_args(argv: list[str] | None) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--small", action="store_true", help="tiny buildings, short episodes: seconds, for tests")
    p.add_argument(
        "--out",
        default=None,
        help="output folder (default runs/realistic_vs_random; with --small a new temporary one); "
        "--out experiments/results regenerates the committed results",
    )
    p.add_argument("--episodes", type=int, default=None, help="seeds per generated set (default 10)")
    p.add_argument("--plans", type=int, default=None, help="real plans per set (default all)")
    p.add_argument("--workers", type=int, default=None, help="processes (default: one per core)")
    p.add_argument(
        "--models",
        default=None,
        help="folder of ppo_random.zip and ppo_realistic.zip (default: the committed models in "
        "experiments/results; with --small, --out); missing models are trained there",
    )
    p.add_argument("--no-ppo", action="store_true", help="leave the PPO agents out")
    p.add_argument(
        "--report-only", action="store_true", help="redo the report and figures from the saved results"
    )
    return p.parse_args(argv)


def main(argv: list[str] | None = None) -> int:
    from realistic_indoor.cli import checkout_commit, run_folder, script_command
    from realistic_indoor.evaluation import make_tasks, run_tasks, write_results
    from realistic_indoor.files import write_text

    args = parse_args(argv)
    setup = SMALL if args.small else FULL
    out = run_folder(
        args.out, RUNS, small=args.small, report_only=args.report_only, name="realistic_vs_random"
    )
    if args.report_only:
        return report_only(out)
    agents = dict(BASELINES)
    if not args.no_ppo:
        models = Path(args.models) if args.models else (out if args.small else RESULTS)
        agents |= ensure_models(models, setup.ppo_preset, args.small)
    episodes = args.episodes or setup.episodes
    generated, real = env_sets(setup, args.plans if args.plans is not None else setup.plans_per_set)
    tasks = make_tasks(list(agents.values()), generated, episodes) if generated else []
    tasks += make_tasks(list(agents.values()), real, 1) if real else []
    results = run_tasks(tasks, workers=args.workers or setup.workers)
    relabel(results, agents)
    command = script_command("experiments/realistic_vs_random.py", argv)
    meta = {
        "command": command,
        "commit": checkout_commit(ROOT),
        "agents": {label: _portable(name) for label, name in agents.items()},
        "episodes": episodes,
        "real_plans": [_portable(s.plan) for s in real],
    }
    write_results(results, out / "realistic_vs_random", meta)
    report = analyse(results, list(agents), command, episodes, len(real))
    write_text(out / "realistic_vs_random.md", report)
    draw(results, list(agents), out)
    print(report)
    return 0


def report_only(out: Path) -> int:
    """Write the report and figures again from ``out/realistic_vs_random/results.json``."""
    from realistic_indoor.evaluation import read_results
    from realistic_indoor.files import write_text

    results, meta = read_results(out / "realistic_vs_random" / "results.json")
    report = analyse(
        results, list(meta["agents"]), meta["command"], meta["episodes"], len(meta["real_plans"])
    )
    write_text(out / "realistic_vs_random.md", report)
    draw(results, list(meta["agents"]), out)
    print(report)
    return 0


def ensure_models(folder: Path, preset: str, small: bool) -> dict[str, str]:
    """Agent names of the two PPO policies, training each one that is missing."""
    from realistic_indoor.agents.rl import ppo_preset, train_ppo
    from realistic_indoor.agents.rl.config import RANDOM_IDS, REALISTIC_IDS

    ids = {"random": RANDOM_IDS, "realistic": REALISTIC_IDS}
    names = {}
    for label, stem in PPO_MODELS.items():
        path = folder / f"{stem}.zip"
        if not path.is_file():
            print(f"training {path} ({preset} preset)", flush=True)
            train_ppo(
                ppo_preset(preset, env_ids=ids[TRAIN_SETS[stem]]),
                path,
                log=lambda line: None if small else print(line, flush=True),
            )
        names[label] = f"ppo:{path}"
    return names


def _portable(text: str) -> str:
    """``text`` with absolute paths inside the project's parent folder made relative to the project."""
    return text.replace(f"{ROOT}{os.sep}", "").replace(f"{ROOT.parent}{os.sep}", f"..{os.sep}")


def env_sets(setup: Setup, plans_per_set: int | None) -> tuple[list, list]:
    """The generated sets (one spec each) and the real plans (one spec per plan)."""
    from realistic_indoor.evaluation import EnvSpec

    generated = []
    for label, env_id in GENERATED.items():
        kwargs = dict(setup.env_kwargs)
        if label in setup.area_m2:
            kwargs["area_m2"] = setup.area_m2[label]
        generated.append(EnvSpec(env_id, kwargs=kwargs, label=label, group=label))
    real = []
    for label, (env_id, folder) in REAL.items():
        plans = sorted((REAL_PLANS / folder).glob("*.xml")) if (REAL_PLANS / folder).is_dir() else []
        for plan in plans[:plans_per_set]:
            real.append(
                EnvSpec(env_id, str(plan), dict(setup.env_kwargs), label=f"{label}: {plan.stem}", group=label)
            )
    if not real:
        print(f"no real plans at {REAL_PLANS}: the real-buildings set is left out", flush=True)
    return generated, real


def relabel(results: list, agents: dict[str, str]) -> None:
    """Name agents by their label (``PPO (random maps)`` rather than a model path)."""
    names = {name: label for label, name in agents.items()}
    for r in results:
        r.agent = names[r.agent]


# -- analysis ------------------------------------------------------------------------------------


def analyse(results: list, agents: list[str], command: str, episodes: int, n_plans: int) -> str:
    """The report: tables per set, rankings and where they differ, metric shifts, PPO transfer."""
    from realistic_indoor.evaluation import summarize
    from realistic_indoor.evaluation.ranking import kendall_tau, rankings

    rows = summarize(results)
    groups = list(dict.fromkeys(r.group for r in results))
    order = rankings(rows, RANK_METRIC)
    lines = [
        "# Realistic versus random maps",
        "",
        f"Regenerate with `{command}`.",
        "",
        f"Agents: {', '.join(agents)}. Generated sets: {episodes} seeds each (the same buildings for every "
        f"agent); real plans: {n_plans}, one episode each. Step limits and robot as in the registered ids. "
        "Coverage AUC is the mean coverage over the step limit (1 = everything seen at once); "
        "intervals are 95% bootstrap (Wilson for shares).",
        "",
        "## Coverage AUC (rank)",
        "",
        _table(rows, agents, groups, RANK_METRIC, order),
        "",
        "## Share of episodes reaching 90% coverage",
        "",
        _table(rows, agents, groups, "reached_target", None),
        "",
        "## Collisions per episode (steps touching a wall)",
        "",
        _table(rows, agents, groups, "collisions", None),
        "",
        "## Rankings compared with random maps",
        "",
    ]
    reference = "random maps"
    for g in groups:
        tau = kendall_tau(order[reference], order[g]) if reference in order and g != reference else math.nan
        versus = f" (Kendall tau vs random maps: {tau:+.2f})" if math.isfinite(tau) else ""
        lines.append(f"- **{g}**: {' > '.join(order[g])}{versus}")
    lines += ["", "## Where the metrics differ", "", *_shifts(rows, agents, groups, reference)]
    lines += [
        "",
        "## Paired differences against the frontier explorer",
        "",
        *_paired(results, agents, groups),
    ]
    lines += ["", "## Transfer of PPO to realistic and real buildings", "", *_transfer(results, groups)]
    return "\n".join(lines) + "\n"


def _table(rows: list, agents: list[str], groups: list[str], metric: str, order: dict | None) -> str:
    cell = {(r["agent"], r["group"]): r for r in rows}
    out = ["| agent | " + " | ".join(groups) + " |", "|---" * (len(groups) + 1) + "|"]
    for a in agents:
        cells = []
        for g in groups:
            r = cell.get((a, g))
            if r is None or not math.isfinite(r[metric]):
                cells.append("-")
                continue
            rank = f" ({order[g].index(a) + 1})" if order else ""
            cells.append(f"{r[metric]:.2f} [{r[f'{metric}_low']:.2f}, {r[f'{metric}_high']:.2f}]{rank}")
        out.append(f"| {a} | " + " | ".join(cells) + " |")
    return "\n".join(out)


def _shifts(rows: list, agents: list[str], groups: list[str], reference: str) -> list[str]:
    """Per agent: its coverage AUC elsewhere against random maps, flagged when the intervals part."""
    cell = {(r["agent"], r["group"]): r for r in rows}
    lines = []
    for a in agents:
        base = cell.get((a, reference))
        if base is None:
            continue
        parts = []
        for g in groups:
            r = cell.get((a, g))
            if g == reference or r is None:
                continue
            apart = min(r["episodes"], base["episodes"]) > 1 and (
                r[f"{RANK_METRIC}_high"] < base[f"{RANK_METRIC}_low"]
                or r[f"{RANK_METRIC}_low"] > base[f"{RANK_METRIC}_high"]
            )
            parts.append(f"{g} {r[RANK_METRIC] - base[RANK_METRIC]:+.2f}{' *' if apart else ''}")
        lines.append(f"- {a}: random maps {base[RANK_METRIC]:.2f}; " + ", ".join(parts))
    lines.append("")
    lines.append("(* the 95% intervals do not overlap.)")
    return lines


def _paired(results: list, agents: list[str], groups: list[str], baseline: str = "frontier") -> list[str]:
    """Each agent's coverage AUC minus the frontier explorer's, episode by episode, per set."""
    from realistic_indoor.evaluation.ranking import paired_difference

    if baseline not in agents:
        return [f"({baseline} left out.)"]
    lines = [
        f"Coverage AUC of each agent minus {baseline}'s on the same buildings and seeds, mean and 95% "
        "interval (* the interval excludes 0). Pairing removes the spread between buildings, so this "
        "separates agents that the tables above cannot.",
        "",
        "| agent | " + " | ".join(groups) + " |",
        "|---" * (len(groups) + 1) + "|",
    ]
    for a in agents:
        if a == baseline:
            continue
        cells = []
        for g in groups:
            d = paired_difference(results, a, baseline, g)
            apart = d.n > 1 and (d.low > 0 or d.high < 0)
            cells.append(
                f"{d.mean:+.3f} [{d.low:+.3f}, {d.high:+.3f}]{' *' if apart else ''}" if d.n else "-"
            )
        lines.append(f"| {a} | " + " | ".join(cells) + " |")
    return lines


def _transfer(results: list, groups: list[str]) -> list[str]:
    from realistic_indoor.evaluation.ranking import paired_difference

    first, second = "PPO (realistic maps)", "PPO (random maps)"
    if not any(r.agent == first for r in results):
        return ["(PPO agents left out.)"]
    lines = [f"Paired difference {first} minus {second} in coverage AUC (same buildings and seeds):", ""]
    for g in groups:
        d = paired_difference(results, first, second, g)
        if d.n > 1:
            better = first if d.low > 0 else second if d.high < 0 else "neither (the interval holds 0)"
            lines.append(
                f"- {g}: {d.mean:+.3f} [{d.low:+.3f}, {d.high:+.3f}] over {d.n} episodes; better: {better}"
            )
        elif d.n == 1:
            lines.append(f"- {g}: {d.mean:+.3f} over 1 episode (too few to tell)")
    return lines


# -- figures --------------------------------------------------------------------------------------


def draw(results: list, agents: list[str], out: Path) -> None:
    """Coverage AUC per agent and set (bars with intervals), and the coverage curves."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    from realistic_indoor.evaluation import summarize
    from realistic_indoor.evaluation.figures import plot_coverage
    from realistic_indoor.files import atomic_path

    rows = {(r["agent"], r["group"]): r for r in summarize(results)}
    groups = list(dict.fromkeys(r.group for r in results))
    fig, ax = plt.subplots(figsize=(1.6 + 1.4 * len(groups), 4.0))
    width = 0.8 / len(agents)
    for i, a in enumerate(agents):
        x = np.arange(len(groups)) + (i - (len(agents) - 1) / 2) * width
        mean = np.array([rows[(a, g)][RANK_METRIC] if (a, g) in rows else np.nan for g in groups])
        low = np.array([rows[(a, g)][f"{RANK_METRIC}_low"] if (a, g) in rows else np.nan for g in groups])
        high = np.array([rows[(a, g)][f"{RANK_METRIC}_high"] if (a, g) in rows else np.nan for g in groups])
        ax.bar(x, mean, width, label=a, yerr=[mean - low, high - mean], capsize=2, error_kw={"lw": 0.8})
    ax.set_xticks(np.arange(len(groups)), groups, fontsize=8)
    ax.set_ylabel("coverage AUC (mean coverage over the step limit)")
    ax.set_ylim(0, 1)
    ax.legend(fontsize=7, ncol=2)
    ax.grid(axis="y", alpha=0.3)
    fig.tight_layout()
    with atomic_path(out / "realistic_vs_random.png") as tmp:
        fig.savefig(tmp, dpi=120)
    plt.close(fig)
    plot_coverage(results, out / "realistic_vs_random_curves.png", "time")


if __name__ == "__main__":
    from realistic_indoor.cli import run_script

    sys.exit(run_script(main, "realistic_vs_random.py"))
