"""``realistic-indoor render PLAN -o plan.png`` or ``render PLANS --out-dir DIR``: pictures of plans."""

from __future__ import annotations

import argparse
import textwrap
from pathlib import Path
from typing import TYPE_CHECKING

from realistic_indoor.cli._batch import add_output_options, run_batch
from realistic_indoor.cli._outputs import check_output
from realistic_indoor.cli._plans import add_infer_entrances, load_plan

if TYPE_CHECKING:
    from realistic_indoor.building import Building

EPILOG = """\
examples:
  realistic-indoor render office.json -o office.png --functions --dpi 200
  realistic-indoor render ../shared/data/real_floorplans/office --out-dir pictures/ --infer-entrances

With --out-dir, PLAN is a file, a folder (every readable plan below it, recursively) or a quoted
glob ('plans/*.xml'); each plan is drawn to DIR under its own name (and sub-folder). A plan that
cannot be read or drawn is left out with a warning naming it, and the count is printed at the
end ("skipped 1 of 15 plans: broken.xml"); --strict stops at the first.
"""


def register(sub: argparse._SubParsersAction) -> None:
    """Add the ``render`` subcommand."""
    p = sub.add_parser(
        "render",
        help="draw a plan, or every plan of a folder, as PNG or SVG (rooms coloured by label, doors, legend)",
        description=textwrap.fill(
            "Draw a plan (any readable format) as a picture: rooms filled by semantic label "
            "(corridor, hall, small, medium, big), walls with their door gaps, doors in blue, entrances "
            "in red with a triangle pointing inside, a legend with room counts and a scale bar in metres. "
            "The output's extension (.png or .svg) picks the format."
        ),
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument(
        "plan",
        help="plan file (.json, floor-plan .xml, World Generator .wg.xml); with --out-dir also a folder "
        "or a quoted glob",
    )
    add_output_options(p, ["png", "svg"], "png", "picture")
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
    """Read the plan(s), draw each, and report the files written."""
    from realistic_indoor.errors import ConfigError
    from realistic_indoor.io import format_of

    if args.out_dir:
        return run_batch(args, lambda b, path: _draw(b, path, args), "drawn")
    if Path(args.plan).is_dir():
        raise ConfigError(f"{args.plan} is a folder; draw its plans with --out-dir DIR")
    if format_of(args.output) not in ("png", "svg"):
        raise ConfigError(
            f"{args.output}: render writes .png or .svg pictures (use convert for other formats)"
        )
    check_output(args.output, "-o", overwrite=args.overwrite, inputs=[args.plan])
    b = load_plan(args)
    for path in _draw(b, Path(args.output), args):
        print(f"wrote {path}")
    return 0


def _draw(building: Building, path: Path, args: argparse.Namespace) -> list[Path]:
    """Draw ``building`` to ``path`` with the picture options of ``args``."""
    from realistic_indoor.io import save

    return save(
        building,
        path,
        dpi=args.dpi,
        size_in=args.size,
        show_functions=args.functions,
        title=False if args.no_title else (args.title if args.title is not None else True),
        legend=not args.no_legend,
    )
