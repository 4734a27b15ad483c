"""``realistic-indoor convert PLAN -o OUT``: change a plan's format."""

from __future__ import annotations

import argparse

from realistic_indoor.cli._plans import add_infer_entrances, load_plan


def register(sub: argparse._SubParsersAction) -> None:
    """Add the ``convert`` subcommand."""
    from realistic_indoor.io.registry import FORMATS

    ends = ", ".join(f"{e} ({name})" for name, (es, _m, _r, w) in FORMATS.items() if w for e in es)
    p = sub.add_parser(
        "convert",
        help="convert a plan to another format (chosen from the output's extension)",
        description=f"Convert a plan. Output formats by extension: {ends}.",
    )
    p.add_argument("plan", help="input plan file")
    p.add_argument("-o", "--output", required=True, help="output file; its extension picks the format")
    p.add_argument(
        "--resolution", type=float, default=0.05, help="ROS map resolution, metres per pixel (default 0.05)"
    )
    add_infer_entrances(p)
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Read, write, and report the files written."""
    from realistic_indoor.io import format_of, save

    b = load_plan(args)
    options = {"resolution_m": args.resolution} if format_of(args.output) == "ros" else {}
    for path in save(b, args.output, **options):
        print(f"wrote {path}")
    return 0
