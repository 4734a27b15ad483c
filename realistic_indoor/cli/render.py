"""``realistic-indoor render PLAN -o plan.png``: a picture of a plan."""

from __future__ import annotations

import argparse

from realistic_indoor.cli._plans import add_infer_entrances, load_plan


def register(sub: argparse._SubParsersAction) -> None:
    """Add the ``render`` subcommand."""
    p = sub.add_parser(
        "render",
        help="draw a plan as PNG or SVG (rooms coloured by label, doors, legend, scale bar)",
        description="Draw a plan (any readable format) as a picture: rooms filled by semantic label "
        "(corridor, hall, small, medium, big), walls with their door gaps, doors in blue, entrances "
        "in red with a triangle pointing inside, a legend with room counts and a scale bar in metres. "
        "The output's extension (.png or .svg) picks the format.",
        epilog="example: realistic-indoor render office.json -o office.png --functions --dpi 200",
    )
    p.add_argument("plan", help="plan file (.json, floor-plan .xml, World Generator .wg.xml)")
    p.add_argument("-o", "--output", required=True, help="picture to write: .png or .svg")
    p.add_argument("--dpi", type=float, default=150.0, help="pixels per inch of a PNG (default 150)")
    p.add_argument(
        "--size",
        type=float,
        default=8.0,
        metavar="INCHES",
        help="length of the plan's longer side in the picture, inches (default 8)",
    )
    p.add_argument(
        "--functions", action="store_true", help="write each room's function inside it where it fits"
    )
    title = p.add_mutually_exclusive_group()
    title.add_argument("--title", help="title text (default: plan name, type, room and door counts, area)")
    title.add_argument("--no-title", action="store_true", help="no title")
    p.add_argument("--no-legend", action="store_true", help="leave out the legend")
    add_infer_entrances(p)
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Read the plan, draw it, and report the file written."""
    from realistic_indoor.errors import ConfigError
    from realistic_indoor.io import format_of, save

    if format_of(args.output) not in ("png", "svg"):
        raise ConfigError(
            f"{args.output}: render writes .png or .svg pictures (use convert for other formats)"
        )
    b = load_plan(args)
    written = save(
        b,
        args.output,
        dpi=args.dpi,
        size_in=args.size,
        show_functions=args.functions,
        title=False if args.no_title else (args.title if args.title is not None else True),
        legend=not args.no_legend,
    )
    for path in written:
        print(f"wrote {path}")
    return 0
