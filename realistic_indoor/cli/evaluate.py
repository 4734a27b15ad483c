"""``realistic-indoor evaluate``: agents x environments x seeds, metrics with confidence intervals."""

from __future__ import annotations

import argparse
import json

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


def register(sub: argparse._SubParsersAction) -> None:
    """Add the ``evaluate`` subcommand."""
    p = sub.add_parser(
        "evaluate",
        help="run agents in environments over many seeds; metrics, CSV/JSON, figures",
        description="Run every agent in every environment for --episodes seeds (the same seeds, hence "
        "the same buildings, for every agent), in parallel processes or on a Ray cluster. Writes "
        "episodes.csv, summary.csv (means with 95% confidence intervals), results.json and coverage "
        "figures to --out, and prints the summary.",
        epilog="Environments are registered ids, or ID:PLAN to run a plan file (or every plan in a "
        "folder) as the fixed building, e.g. OfficeExplore-v0:../shared/data/real_floorplans/office. "
        "Agents: random, wall, frontier, utility, structure, ppo:MODEL.zip.",
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
    p.add_argument("--out", default="evaluation", help="output folder (default ./evaluation)")
    p.add_argument("--max-steps", type=int, default=None, help="override every environment's step limit")
    p.add_argument(
        "--env-kwargs",
        default=None,
        metavar="JSON",
        help="more gym.make arguments as JSON, e.g. '{\"area_m2\": 800}'",
    )
    p.add_argument("--no-figures", action="store_true", help="skip the coverage figures")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Run the evaluation, write the outputs, print the summary."""
    from realistic_indoor.evaluation import evaluate, format_table, summarize

    agents = [a.strip() for a in args.agents.split(",") if a.strip()]
    envs = [e.strip() for e in args.envs.split(",") if e.strip()]
    kwargs = _env_kwargs(args.env_kwargs)
    if args.max_steps is not None:
        kwargs["max_steps"] = args.max_steps
    results = evaluate(
        agents,
        envs,
        episodes=args.episodes,
        seed=args.seed,
        workers=args.workers,
        out_dir=args.out,
        figures=not args.no_figures,
        use_ray=args.ray is not None,
        ray_address=args.ray or None,
        progress=not args.quiet,
        env_kwargs=kwargs,
    )
    searching = any(r.victims_total for r in results)
    print(format_table(summarize(results), _TABLE_METRICS + (_SEARCH_METRICS if searching else ())))
    print(
        f"results in {args.out}/ (episodes.csv, summary.csv, results.json{'' if args.no_figures else ', figures'})"
    )
    return 0


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
