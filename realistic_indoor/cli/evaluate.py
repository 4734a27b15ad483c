"""``realistic-indoor evaluate``: agents x environments x seeds, metrics with confidence intervals."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from realistic_indoor.errors import ConfigError

_TABLE_METRICS = (
    "coverage_auc",
    "final_coverage",
    "reached_target",
    "time_to_target_s",
    "path_length_m",
    "collisions",
)
_SEARCH_METRICS = ("victims_found_share", "time_to_all_victims_s")
_TEAM_METRICS = ("overlap", "messages", "linked_to_base_share", "rescue_score")


def register(sub: argparse._SubParsersAction) -> None:
    """Add the ``evaluate`` subcommand."""
    p = sub.add_parser(
        "evaluate",
        help="run agents in environments over many seeds; metrics, CSV/JSON, figures",
        description="Run every agent in every environment for --episodes seeds (the same seeds, hence "
        "the same buildings, for every agent), in parallel processes or on a Ray cluster. Appends each "
        "episode to episodes.jsonl in --out as it finishes (an interrupted run keeps them; --resume "
        "continues it), then writes episodes.csv, summary.csv (means with 95% confidence intervals), "
        "results.json and coverage figures, and prints the summary.",
        epilog="Environments are registered ids, or ID:PLAN to run a plan file (or every plan in a "
        "folder) as the fixed building, e.g. OfficeExplore-v0:../shared/data/real_floorplans/office. "
        "A plan that cannot be read is left out with a warning naming it, counted at the end and "
        "listed in results.json (meta.skipped); --strict stops at the first instead. "
        "Agents: random, wall, frontier, utility, structure, ppo:MODEL.zip, learned (the committed "
        "learned explorer) or learned:MODEL.zip. Model files are pickles that can run code when "
        "loaded: use only models you trust.",
    )
    p.add_argument("--agents", required=True, help="comma-separated agent names, e.g. frontier,random")
    p.add_argument(
        "--envs", required=True, help="comma-separated environments, e.g. OfficeExplore-v0,RandomExplore-v0"
    )
    p.add_argument("--episodes", type=int, default=20, help="seeds per agent and environment (default 20)")
    p.add_argument("--seed", type=int, default=0, help="first seed (default 0)")
    p.add_argument("--workers", type=int, default=None, help="parallel processes (default: one per CPU core)")
    p.add_argument(
        "--ray",
        nargs="?",
        const="",
        default=None,
        metavar="ADDRESS",
        help="run on a Ray cluster (pip install ray); optional address, default local",
    )
    p.add_argument(
        "--out",
        default="runs/evaluation",
        help="output folder (default runs/evaluation); one that holds an earlier run's results is "
        "refused unless --resume or --overwrite is given",
    )
    again = p.add_mutually_exclusive_group()
    again.add_argument(
        "--resume",
        action="store_true",
        help="continue the run in --out: episodes it finished (same agent, environment, seed and "
        "settings) are kept, the others run, and the outputs are written over all of them",
    )
    again.add_argument(
        "--overwrite", action="store_true", help="replace the results of an earlier run in --out"
    )
    p.add_argument(
        "--strict",
        action="store_true",
        help="stop at the first plan that cannot be read or has no rooms, or that the floor-plan reader "
        "would have to repair (default: leave it out with a warning)",
    )
    p.add_argument(
        "--robots",
        default=None,
        metavar="N,N,...",
        help="team sizes, e.g. 1,2,4,8: every agent (a team agent: frontier, coordinated, hungarian) runs "
        "as a team of each size in the id's team environment (wss links, maps merged while linked; "
        '--env-kwargs \'{"comm": "unlimited"}\' changes them); the '
        "summary adds speed-up and efficiency against one robot, and speedup.png",
    )
    p.add_argument("--max-steps", type=int, default=None, help="override every environment's step limit")
    p.add_argument(
        "--env-kwargs",
        default=None,
        metavar="JSON",
        help="more gym.make arguments as JSON, e.g. '{\"area_m2\": 800}'",
    )
    p.add_argument("--no-figures", action="store_true", help="skip the coverage figures")
    p.add_argument("--quiet", action="store_true", help="no progress bar (it shows only on a terminal)")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Run the evaluation, write the outputs, print the summary."""
    from realistic_indoor.evaluation import format_table, run_evaluation, summarize, summary_rows
    from realistic_indoor.validator.plan_sets import show_progress, skipped_summary

    agents = [a.strip() for a in args.agents.split(",") if a.strip()]
    envs = [e.strip() for e in args.envs.split(",") if e.strip()]
    for option, names in (("--agents", agents), ("--envs", envs)):
        if not names:
            raise ConfigError(f"{option} names nothing; give one or more names, comma-separated")
    robots = _robots(args.robots)
    kwargs = _env_kwargs(args.env_kwargs)
    if args.max_steps is not None:
        kwargs["max_steps"] = args.max_steps
    _check_out(args)
    try:
        evaluation = run_evaluation(
            agents,
            envs,
            episodes=args.episodes,
            seed=args.seed,
            workers=args.workers,
            out_dir=args.out,
            figures=not args.no_figures,
            use_ray=args.ray is not None,
            ray_address=args.ray or None,
            progress=show_progress(args.quiet),
            env_kwargs=kwargs,
            strict=args.strict,
            resume=args.resume,
            robots=robots,
        )
    except KeyboardInterrupt:
        log = Path(args.out) / "episodes.jsonl"
        if log.is_file():
            print(
                f"finished episodes are kept in {log}; add --resume to the same command to continue",
                file=sys.stderr,
            )
        raise
    results = evaluation.results
    searching = any(r.victims_total for r in results)
    metrics = _TABLE_METRICS + (_SEARCH_METRICS if searching else ())
    if robots is None:
        print(format_table(summarize(results), metrics))
    else:
        print(format_table(summary_rows(results), metrics + _TEAM_METRICS))
    figures = "" if args.no_figures else ", figures"
    print(f"results in {args.out}/ (episodes.jsonl, episodes.csv, summary.csv, results.json{figures})")
    if evaluation.resumed:
        print(
            f"resumed: {evaluation.resumed} of {len(results)} episodes taken from the earlier run",
            file=sys.stderr,
        )
    if line := skipped_summary(evaluation.skipped, evaluation.plans):
        print(f"{line} (listed in results.json under meta.skipped)", file=sys.stderr)
    return 0


def _check_out(args: argparse.Namespace) -> None:
    """Refuse an ``--out`` that is a file, or holds an earlier run's results, before any episode runs."""
    from realistic_indoor.evaluation import previous_results
    from realistic_indoor.files import check_output_dir

    check_output_dir(args.out, "--out")
    found = previous_results(args.out)
    if found and not (args.resume or args.overwrite):
        raise ConfigError(
            f"--out {args.out} holds the results of an earlier run ({', '.join(found)}); add --resume to "
            "continue it, --overwrite to replace it, or choose a new --out folder"
        )
    if args.resume and not found:
        print(f"--resume: no earlier run in {args.out}; starting a new one", file=sys.stderr)


def _env_kwargs(text: str | None) -> dict:
    if not text:
        return {}
    try:
        value = json.loads(text)
    except json.JSONDecodeError as e:
        raise ConfigError(f"--env-kwargs is not valid JSON ({e.msg}): {text!r}") from None
    if not isinstance(value, dict):
        raise ConfigError(f"--env-kwargs must be a JSON object of gym.make arguments, got {text!r}")
    return value


def _robots(text: str | None) -> list[int] | None:
    """``--robots``: team sizes, checked (integers from 1 to teams.MAX_ROBOTS, no repeat)."""
    if text is None:
        return None
    from realistic_indoor.evaluation.tasks import check_robots

    tokens = [t.strip() for t in text.split(",") if t.strip()]
    sizes = []
    for token in tokens:
        try:
            sizes.append(int(token))
        except ValueError:
            raise ConfigError(
                f"--robots takes team sizes (integers), comma-separated, got {token!r}"
            ) from None
    return check_robots(sizes)
