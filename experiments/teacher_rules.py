"""Which rule should the learned explorer clone? The teacher rules on a block of tuning seeds.

Each rule of :data:`realistic_indoor.agents.rl.teachers.TEACHERS` drives the learned explorer's
agent in place of a trained policy: the same candidate goals (the K = 16 nearest frontiers), the
same decisions and the same navigator; only the choice differs. They run on generated offices,
schools and houses at their default sizes and step limits, seeds 900-909: a tuning block, never
evaluated on (the studies use seeds from 1000) and not the training episodes (those come from
the random streams of seeds 0 and 1). The ``frontier`` rule drives exactly as the
nearest-frontier explorer.

The report gives each rule's mean coverage AUC per set and its paired difference (same building
and start) from the ``frontier`` and ``structure`` rules, with 95% bootstrap intervals.

Full run (about 8 minutes per rule on 2 idle cores)::

    .venv/bin/python experiments/teacher_rules.py --out experiments/results

writes ``teacher_rules.md`` and each rule's episodes in ``teacher_rules/<rule>/``; a rule whose
results are there already is not run again (one saved with other weights under the same name is
refused). ``--extra NAME=COST,ROOM,LENGTH,GAIN[,TURN[,SHORT[,SHORT_M]]]`` (repeatable) runs a
rule that is not registered, with those weights of
:class:`~realistic_indoor.agents.rl.teachers.TeacherRule`, as the registered rules were searched
for (``--extra area=1,1,0,2`` is the information gain alone; give the same option again to keep
it in a later report; a fifth number is the heading term ``turn_weight``, ``--extra
su-turn=3,2,1,0,1.5``; a sixth and seventh are ``short_factor`` and ``short_m``, ``--extra
short=1,1,0,0,0,2,1``). ``--episodes N`` runs N tuning seeds per set (900 on) and ``--sets``
some of the sets: results are read back only for the same seeds and sets, so a longer run goes to
its own ``--out``, as the recipe's rule was chosen on 30 seeds::

    .venv/bin/python experiments/teacher_rules.py --out experiments/results/tuning_30 --episodes 30 \
        --sets schools,houses --rules structure-utility-area,structure-utility-area-short

``--small`` runs the pipeline on houses in seconds (the tests do).
"""

from __future__ import annotations

import argparse
import math
import sys
from dataclasses import asdict, dataclass, field, replace
from multiprocessing import get_context
from pathlib import Path
from statistics import fmean
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
RUNS = ROOT / "runs" / "teacher_rules"
SETS = {"offices": "OfficeExplore-v0", "schools": "SchoolExplore-v0", "houses": "HouseExplore-v0"}
METRIC = "coverage_auc"
REFERENCES = ("frontier", "structure")


@dataclass(frozen=True)
class Setup:
    """Size of a run.

    Attributes:
        seed: First tuning seed.
        episodes: Seeds per set.
        sets: Labels of :data:`SETS` run.
        env_kwargs: More ``gym.make`` keywords.
        workers: Processes.
    """

    seed: int = 900
    episodes: int = 10
    sets: tuple[str, ...] = tuple(SETS)
    env_kwargs: dict[str, Any] = field(default_factory=dict)
    workers: int = 2


FULL = Setup()
SMALL = Setup(episodes=2, sets=("houses",), env_kwargs={"max_steps": 60}, workers=1)


def parse_args(argv: list[str] | None) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--small", action="store_true", help="houses, short episodes: seconds, for tests")
    p.add_argument("--out", default=None, help="output folder (default runs/teacher_rules)")
    p.add_argument("--rules", default=None, help="comma-separated rules (default: every rule)")
    p.add_argument(
        "--extra",
        action="append",
        default=[],
        metavar="NAME=COST,ROOM,LENGTH,GAIN[,TURN[,SHORT[,SHORT_M]]]",
        help="also run an unregistered rule with these TeacherRule weights (repeatable)",
    )
    p.add_argument(
        "--episodes",
        type=int,
        default=None,
        help="tuning seeds per set, from 900 (default 10; 2 with --small)",
    )
    p.add_argument("--sets", default=None, help=f"comma-separated sets of {', '.join(SETS)} (default: all)")
    p.add_argument("--workers", type=int, default=None, help="processes (default 2)")
    p.add_argument("--report-only", action="store_true", help="redo the report from the saved results")
    return p.parse_args(argv)


def sized(base: Setup, episodes: int | None, sets: str | None) -> Setup:
    """``base`` with the ``--episodes`` and ``--sets`` of the command line.

    Raises:
        ConfigError: For a count below 1 or an unknown set.
    """
    from realistic_indoor.errors import ConfigError

    if episodes is not None and episodes < 1:
        raise ConfigError(f"--episodes must be an integer >= 1, not {episodes}")
    if sets is None:
        return replace(base, episodes=episodes or base.episodes)
    asked = [s for s in sets.split(",") if s]
    unknown = [s for s in asked if s not in SETS]
    if unknown or not asked:
        raise ConfigError(f"--sets: unknown {unknown or [sets]}; sets: {', '.join(SETS)}")
    # in the order of SETS, each once: the same sets always read back as the same run
    return replace(base, episodes=episodes or base.episodes, sets=tuple(s for s in SETS if s in asked))


def rerun_options(args: argparse.Namespace) -> list[str]:
    """The options that say what ran (all but ``--workers``, ``--report-only``), for the report."""
    given = ["--small"] if args.small else []
    given += [
        f"--{k} {getattr(args, k)}"
        for k in ("out", "episodes", "sets", "rules")
        if getattr(args, k) is not None
    ]
    return given + [f"--extra {e}" for e in args.extra]


def main(argv: list[str] | None = None) -> int:
    from realistic_indoor.agents.rl.teachers import TEACHERS
    from realistic_indoor.cli import checkout_commit, run_folder, script_command
    from realistic_indoor.errors import ConfigError
    from realistic_indoor.evaluation import write_results
    from realistic_indoor.files import write_text

    args = parse_args(argv)
    setup = sized(SMALL if args.small else FULL, args.episodes, args.sets)
    out = run_folder(args.out, RUNS, small=args.small, report_only=args.report_only, name="teacher_rules")
    if args.workers is not None and args.workers < 1:
        raise ConfigError(f"--workers must be an integer >= 1, not {args.workers}")
    rules = args.rules.split(",") if args.rules else list(TEACHERS)
    unknown = [r for r in rules if r not in TEACHERS]
    if unknown:
        raise ConfigError(f"--rules: unknown {unknown}; rules: {', '.join(TEACHERS)}")
    known = {name: TEACHERS[name] for name in (*REFERENCES, *rules)}
    known.update(parse_extra(args.extra, TEACHERS))
    folders = {rule: out / "teacher_rules" / rule for rule in known}
    # every saved rule is checked before any is run: a mismatch costs no minutes of running
    saved = {rule: read_back(folders[rule], rule, w, setup) for rule, w in known.items()}
    results: list = []
    for rule, weights in known.items():
        folder = folders[rule]
        if saved[rule] is not None:
            results += saved[rule]
            continue
        if args.report_only:
            continue
        print(f"running the {rule} rule", flush=True)
        ran = run_rule(rule, weights, setup, args.workers or setup.workers)
        meta = {
            "command": script_command("experiments/teacher_rules.py", argv),
            "commit": checkout_commit(ROOT),
            "rule": rule,
            "weights": asdict(weights),
            "seeds": [setup.seed, setup.seed + setup.episodes - 1],
            "sets": list(setup.sets),
            "env_kwargs": dict(setup.env_kwargs),
        }
        write_results(ran, folder, meta)
        results += ran
    report = analyse(results, rerun_options(args))
    write_text(out / "teacher_rules.md", report)
    print(report)
    return 0


def read_back(folder: Path, rule: str, weights: Any, setup: Setup) -> list | None:
    """The saved episodes of ``rule`` in ``folder`` (``None`` if none are saved).

    Raises:
        ConfigError: If they were run with other weights, or on other seeds, sets or episode
            settings than ``setup``'s.
    """
    from realistic_indoor.agents.rl.teachers import TeacherRule
    from realistic_indoor.errors import ConfigError
    from realistic_indoor.evaluation import read_results

    if not (folder / "results.json").is_file():
        return None
    episodes, saved = read_results(folder / "results.json")
    if {**asdict(TeacherRule()), **saved.get("weights", asdict(weights))} != asdict(weights):
        raise ConfigError(
            f"{folder}: results of the rule {rule!r} with other weights ({saved['weights']}); "
            "give this one another name, or remove the folder to run it again"
        )
    ran_on = (saved.get("seeds"), saved.get("sets"), saved.get("env_kwargs", {}))
    wanted = ([setup.seed, setup.seed + setup.episodes - 1], list(setup.sets), dict(setup.env_kwargs))
    if ran_on != wanted:
        raise ConfigError(
            f"{folder}: results of the rule {rule!r} on seeds {ran_on[0]} of {ran_on[1]} "
            f"(episode settings {ran_on[2]}), not {setup.episodes} seeds of {list(setup.sets)} "
            f"({wanted[2]}); give the --episodes and --sets they ran with, or another --out"
        )
    return episodes


def parse_extra(specs: list[str], registered: dict[str, Any]) -> dict[str, Any]:
    """The rules of ``--extra NAME=COST,ROOM,LENGTH,GAIN[,TURN[,SHORT[,SHORT_M]]]`` options, by name.

    Raises:
        ConfigError: For a malformed option, a name already registered or a name given twice.
    """
    from realistic_indoor.agents.rl.teachers import TeacherRule
    from realistic_indoor.errors import ConfigError

    out = {}
    for spec in specs:
        name, _, weights = spec.partition("=")
        try:
            values = [float(v) for v in weights.split(",")]
        except ValueError:
            values = []
        if (
            not name
            or name in registered
            or not 4 <= len(values) <= 7
            or not all(math.isfinite(v) for v in values)
        ):
            raise ConfigError(
                f"--extra {spec!r}: give a new name and four to seven numbers, "
                "NAME=COST,ROOM,LENGTH,GAIN[,TURN[,SHORT[,SHORT_M]]] (e.g. area=1,1,0,2); "
                "registered names are taken"
            )
        if name in out:
            raise ConfigError(f"--extra {name!r} is given twice; give each rule one name")
        out[name] = TeacherRule(*values)
    return out


def run_rule(rule: str, weights: Any, setup: Setup, workers: int) -> list:
    """Every episode of the rule ``weights`` (a ``TeacherRule``) called ``rule``, by set, then seed."""
    from realistic_indoor.evaluation import EnvSpec, EpisodeTask

    tasks = [
        (
            EpisodeTask(
                f"rule:{rule}",
                EnvSpec(SETS[label], kwargs=dict(setup.env_kwargs), label=label, group=label),
                s,
            ),
            weights,
        )
        for label in setup.sets
        for s in range(setup.seed, setup.seed + setup.episodes)
    ]
    if workers <= 1:
        return [_episode(t) for t in tasks]
    with get_context("spawn").Pool(workers) as pool:
        return pool.map(_episode, tasks, chunksize=1)


def _episode(job: tuple[Any, Any]) -> Any:
    """One episode: ``(task, rule)``, the rule behind the learned agent."""
    from realistic_indoor.agents import make_agent
    from realistic_indoor.agents.rl.teachers import TeacherPolicy
    from realistic_indoor.evaluation.episode import play_episode
    from realistic_indoor.evaluation.tasks import make_env

    task, rule = job
    env = make_env(task.env)
    try:
        agent = make_agent("learned", env, model=TeacherPolicy(rule))
        return play_episode(env, agent, task)
    finally:
        env.close()


def analyse(results: list, options: list[str] | tuple[str, ...] = ()) -> str:
    """The report: mean AUC per rule and set, paired differences from the reference rules.

    Args:
        results: The episodes of every rule.
        options: The run's options (``--out experiments/results``, ``--episodes 30``, ``--extra
            NAME=...``), for the command that regenerates the report.
    """
    from realistic_indoor.evaluation.aggregate import bootstrap_mean

    options = "".join(f" {o}" for o in options)

    values: dict[tuple[str, str], dict[int, float]] = {}
    for r in results:
        values.setdefault((r.agent.split(":", 1)[1], r.group), {})[r.seed] = getattr(r, METRIC)
    rules = list(dict.fromkeys(k[0] for k in values))
    sets = [s for s in SETS if any(k[1] == s for k in values)]
    lines = [
        "# The teacher rules on the tuning seeds",
        "",
        f"Regenerate with `.venv/bin/python experiments/teacher_rules.py{options}` "
        "(a rule already run is read back; `--report-only` only rewrites this report).",
        "",
        "Coverage AUC of each rule of `agents.rl.teachers.TEACHERS` (and of the `--extra` weights) behind "
        "the learned explorer's agent "
        "(the same candidates, decisions and navigator), generated buildings at their default sizes and "
        "step limits, tuning seeds from 900 (the episodes column counts them). A difference is paired "
        "by building: mean and 95% bootstrap interval (* the interval excludes 0).",
        "",
        "| set | rule | episodes | AUC | minus frontier | minus structure |",
        "|---|---|---|---|---|---|",
    ]
    for s in sets:
        for rule in rules:
            mine = values.get((rule, s), {})
            if not mine:
                continue
            cells = []
            for ref in REFERENCES:
                theirs = values.get((ref, s), {})
                seeds = sorted(set(mine) & set(theirs))
                if ref == rule or not seeds:
                    cells.append("")
                    continue
                e = bootstrap_mean([mine[k] - theirs[k] for k in seeds])
                star = " *" if e.low > 0 or e.high < 0 else ""
                cells.append(f"{e.mean:+.3f} [{e.low:+.3f}, {e.high:+.3f}]{star}")
            lines.append(
                f"| {s} | {rule} | {len(mine)} | {fmean(mine.values()):.3f} | {cells[0]} | {cells[1]} |"
            )
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    from realistic_indoor.cli import run_script

    sys.exit(run_script(main, "teacher_rules"))
