"""``realistic-indoor convert PLAN -o OUT`` or ``convert PLANS --out-dir DIR --format EXT``: change formats."""

from __future__ import annotations

import argparse
import textwrap
from pathlib import Path
from typing import TYPE_CHECKING

from realistic_indoor.cli._batch import add_output_options, run_batch
from realistic_indoor.cli._outputs import check_output
from realistic_indoor.cli._plans import add_infer_entrances, load_plan
from realistic_indoor.cli._world3d import add_world_options, save_options

if TYPE_CHECKING:
    from realistic_indoor.building import Building

EPILOG = """\
examples:
  realistic-indoor convert office.json -o office.yaml --resolution 0.05
  realistic-indoor convert office.json -o office.sdf --wall-height 3 --closed-entrances   # Gazebo world
  realistic-indoor convert ../shared/data/real_floorplans/office --out-dir maps/ --format yaml --infer-entrances

With --out-dir, PLAN is a file, a folder (every readable plan below it, recursively) or a quoted
glob ('plans/*.xml'); each plan is written to DIR under its own name (and sub-folder) with the
new ending. A plan that cannot be read or written is left out with a warning naming it, and the
count is printed at the end ("skipped 1 of 15 plans: broken.xml"); --strict stops at the first.
--infer-entrances applies to the floor-plan XML plans of a batch and is ignored for the others.
"""


def _endings() -> list[str]:
    """The first ending of each writable format, without the dot (``json``, ``wg.xml``, ``yaml``)."""
    from realistic_indoor.io.registry import FORMATS

    return [ends[0].lstrip(".") for ends, _m, _r, w in FORMATS.values() if w]


def register(sub: argparse._SubParsersAction) -> None:
    """Add the ``convert`` subcommand."""
    from realistic_indoor.io.registry import FORMATS

    ends = ", ".join(f"{e} ({name})" for name, (es, _m, _r, w) in FORMATS.items() if w for e in es)
    p = sub.add_parser(
        "convert",
        help="convert a plan, or a folder of plans, to another format (chosen by the ending)",
        description=textwrap.fill(
            f"Convert a plan, or every plan of a folder. Output formats by ending: {ends}."
        ),
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("plan", help="input plan file; with --out-dir also a folder or a quoted glob")
    add_output_options(p, _endings(), None, "file")
    p.add_argument(
        "--resolution",
        type=float,
        default=0.05,
        help="ROS map resolution, metres per pixel, 0.01 to 1 (default 0.05)",
    )
    add_world_options(p)
    add_infer_entrances(p)
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Read, write, and report the files written."""
    from realistic_indoor.checks import require_between
    from realistic_indoor.errors import ConfigError

    require_between("", "--resolution", args.resolution, 0.01, 1.0, "m")  # as ros_map.write's
    if args.out_dir:
        if args.format is not None:
            save_options(args, f"plan.{args.format}", args.resolution)
        return run_batch(args, lambda b, path: _save(b, path, args), "converted")
    if Path(args.plan).is_dir():
        raise ConfigError(f"{args.plan} is a folder; convert its plans with --out-dir DIR --format EXT")
    if args.format is not None:
        raise ConfigError("--format goes with --out-dir; with -o the output's ending picks the format")
    save_options(args, args.output, args.resolution)
    check_output(args.output, "-o", overwrite=args.overwrite, inputs=[args.plan])
    b = load_plan(args)
    for path in _save(b, Path(args.output), args):
        print(f"wrote {path}")
    return 0


def _save(building: Building, path: Path, args: argparse.Namespace) -> list[Path]:
    """Write ``building`` to ``path`` with the options its format takes (resolution, 3D walls)."""
    from realistic_indoor.io import save

    return save(building, path, **save_options(args, path, args.resolution))
