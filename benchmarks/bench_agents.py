"""Benchmark of the explorers on default offices: how often they reach 90% coverage in time.

For ``OfficeExplore-v0`` with its default config (offices of the generator's default size, the
registered step limit), prints for each agent the share of seeds whose episode reached 90%
coverage within the step limit (with a 95% Wilson interval), the steps it took (median over the
episodes that got there), the coverage at the end, the agent's thinking time per step, and for
agents that choose goals (the map-based and learned explorers) the steps per decision and the
thinking time per decision (decisions/s is its inverse). The
target of the project: the frontier explorer reaches 90% in at least 90% of seeds; the random
agent much less often.

``--max-steps`` runs longer episodes to show the steps the agents need; ``--env`` benchmarks
another id (in a search id the goal is finding every victim).

Usage::

    .venv/bin/python benchmarks/bench_agents.py                     # 20 seeds, a few minutes
    .venv/bin/python benchmarks/bench_agents.py --episodes 5 --agents frontier,structure
"""

from __future__ import annotations

import argparse
import math
import statistics

from realistic_indoor.evaluation import EpisodeResult, evaluate, wilson

TARGET_SHARE = 0.9


def main(argv: list[str] | None = None) -> None:
    """Run the benchmark and print its table."""
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--env", default="OfficeExplore-v0", help="registered id (default OfficeExplore-v0)")
    p.add_argument(
        "--agents", default="frontier,random", help="comma-separated agents (default frontier,random)"
    )
    p.add_argument("--episodes", type=int, default=20, help="seeds (default 20)")
    p.add_argument("--max-steps", type=int, default=None, help="step limit (default: the id's)")
    p.add_argument("--workers", type=int, default=None, help="processes (default: one per core)")
    args = p.parse_args(argv)
    kwargs = {} if args.max_steps is None else {"max_steps": args.max_steps}
    agents = [a.strip() for a in args.agents.split(",") if a.strip()]
    results = evaluate(agents, [args.env], episodes=args.episodes, workers=args.workers, env_kwargs=kwargs)
    limit = results[0].max_steps
    search = any(r.victims_total for r in results)
    goal = "found all victims" if search else "reached 90%"
    print(f"# Agents on {args.env}, default buildings, {args.episodes} seeds, step limit {limit}\n")
    print(
        f"| agent | {goal} | steps to it (min / median / max) | final coverage (mean) | agent ms/step "
        "| steps per decision | agent ms/decision |"
    )
    print("|---|---|---|---|---|---|---|")
    for agent in agents:
        mine = [r for r in results if r.agent == agent]
        steps = [s for s in map(_steps_to_goal, mine) if s is not None]
        share = wilson(len(steps), len(mine))
        spread = f"{min(steps)} / {statistics.median(steps):.0f} / {max(steps)}" if steps else "-"
        coverage = statistics.mean(r.final_coverage for r in mine)
        ms = statistics.mean(r.agent_ms_per_step for r in mine)
        decisions = sum(r.decisions for r in mine)
        per = sum(r.steps for r in mine) / decisions if decisions else float("nan")
        ms_decision = (
            sum(r.agent_ms_per_step * r.steps for r in mine) / decisions if decisions else float("nan")
        )
        print(
            f"| {agent} | {share.mean:.0%} [{share.low:.0%}, {share.high:.0%}] | {spread} | {coverage:.3f} | {ms:.2f} "
            f"| {per:.1f} | {ms_decision:.1f} |"
        )
    frontier = [r for r in results if r.agent == "frontier"]
    if frontier:
        share = sum(_steps_to_goal(r) is not None for r in frontier) / len(frontier)
        verdict = "meets" if share >= TARGET_SHARE else "misses"
        print(f"\nfrontier {goal} in {share:.0%} of seeds: {verdict} the target of {TARGET_SHARE:.0%}")


def _steps_to_goal(result: EpisodeResult) -> int | None:
    """Steps until the episode's goal (90% coverage; in search, every victim found), or None."""
    seconds = result.time_to_all_victims_s if result.victims_total else result.time_to_target_s
    return round(seconds / result.dt_s) if math.isfinite(seconds) else None


if __name__ == "__main__":
    main()
