"""``realistic-indoor info PLAN``: a summary of a plan."""

from __future__ import annotations

import argparse

from realistic_indoor.cli._plans import add_plan_options, load_plan


def register(sub: argparse._SubParsersAction) -> None:
    """Add the ``info`` subcommand."""
    p = sub.add_parser(
        "info",
        help="summarise a plan: rooms by label, area, doors",
        description="Print a summary of a plan (any readable format): type, rooms by label, area, "
        "doors, and the invariants it violates.",
    )
    p.add_argument("plan", help="plan file (.json, floor-plan .xml, World Generator .wg.xml)")
    p.add_argument("--check", action="store_true", help="also list violated invariants")
    add_plan_options(p)
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Print the summary; exit code 1 if ``--check`` found problems."""
    b = load_plan(args)
    print(f"plan: {args.plan}")
    print(b.summary())
    if args.check:
        findings = b.validate()
        print(f"invariants: {'all hold' if not findings else f'{len(findings)} violated'}")
        if "wall_tolerance_m" in b.metadata:
            print(
                f"  (doors checked within {b.metadata['wall_tolerance_m']} m of their rooms' outlines: "
                "this plan draws walls as gaps between rooms)"
            )
        for f in findings:
            print(f"  {f}")
        return 1 if findings else 0
    return 0
