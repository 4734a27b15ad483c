"""``realistic-indoor validate SET [SET ...]``: how realistic are these maps?"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from realistic_indoor.cli._outputs import add_overwrite_option
from realistic_indoor.errors import ConfigError

if TYPE_CHECKING:
    from realistic_indoor.validator.compare import Comparison

EPILOG = """\
Each SET is one set of plans: a file, a folder (every readable plan inside, recursively) or a
quoted glob pattern ('maps/*.json'); unquoted patterns are expanded by the shell into one set
per file. Examples:

  realistic-indoor validate ../shared/data/real_floorplans/office --type office
  realistic-indoor validate gen/ random/ real/ --type office --labels generated,random,real --plot cmp.png
  realistic-indoor validate gen/ --reference real/ --format markdown -o report.md

A plan that cannot be read (a malformed or empty file) or measured (no rooms or no doors) is
left out with a warning naming it, listed in the report under "Plans left out", and counted at
the end ("skipped 1 of 16 plans"); --strict stops at the first such plan instead (exit 1).

The realism score is 0 for a set identical to the reference; below 0.5 hard to tell apart,
above 2 structurally different. The two-sample accuracy is 0.5 when a classifier cannot tell
two sets apart. See docs/validator.md for every definition.
"""


def register(sub: argparse._SubParsersAction) -> None:
    """Add the ``validate`` subcommand."""
    p = sub.add_parser(
        "validate",
        help="measure sets of maps against real buildings: Table 1, connectivity, realism scores",
        description="Compare sets of maps with each other and with a reference: the paper's Table 1 "
        "per set side by side, connectivity facts, realism scores with the worst deviations in words, "
        "classifier two-sample tests, plans whose scale looks wrong.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("sets", nargs="+", metavar="SET", help="a plan file, a folder of plans or a quoted glob")
    p.add_argument(
        "--type", help="building type to judge the plans as: office, school, house (default: theirs)"
    )
    p.add_argument(
        "--labels", help="comma-separated names of the sets, in order (default: folder/file names)"
    )
    p.add_argument(
        "--reference",
        default="paper",
        help="'paper' (the paper's Table 1 for the type, default), another paper table "
        "('all_types', 'robocup_2013_final_map'), or a folder/file/glob of real plans to fit it from",
    )
    p.add_argument(
        "--format",
        default="table",
        choices=("table", "markdown", "csv", "json"),
        help="report format (default table)",
    )
    p.add_argument("-o", "--output", help="write the report to this file instead of the terminal")
    add_overwrite_option(p, "the report and the figure")
    p.add_argument("--plot", metavar="OUT.png", help="also draw the comparison figure (PNG, SVG or PDF)")
    p.add_argument(
        "--infer-labels",
        default="auto",
        choices=("auto", "always", "never"),
        help="infer semantic labels from function, shape and area: for plans that lack them (auto), "
        "for all plans, or never",
    )
    bad = p.add_mutually_exclusive_group()
    bad.add_argument(
        "--strict",
        action="store_true",
        help="stop at the first plan that cannot be read or measured, or that the floor-plan reader "
        "would have to repair (default: leave such plans out with a warning and list them in the report)",
    )
    bad.add_argument(
        "--skip-bad",
        action="store_true",
        help="leave out plans that cannot be read or have no rooms or doors: the default now, kept for "
        "old scripts",
    )
    p.add_argument("--no-two-sample", action="store_true", help="skip the classifier two-sample tests")
    p.add_argument(
        "--two-sample-area",
        action="store_true",
        help="let the room-level two-sample tests use room areas (default: scale-free room features; the building level always has the room density)",
    )
    p.add_argument(
        "--two-sample-features",
        default="room,building,all",
        metavar="GROUPS",
        help="comma-separated feature groups of the two-sample tests, one test per group: room (Table 1 "
        "and connectivity), building (building-level measures), all (both together); default all three",
    )
    p.add_argument(
        "--seed", type=int, default=0, help="seed of the two-sample tests' cross-validation (default 0)"
    )
    p.add_argument(
        "--worst", type=int, default=3, help="worst deviations named per set, 0 to 100 (default 3)"
    )
    p.add_argument("--quiet", action="store_true", help="no progress bars (they show only on a terminal)")
    p.set_defaults(func=run)


def _names(args: argparse.Namespace) -> list[str | None]:
    if args.labels is None:
        return [None] * len(args.sets)
    names = [n.strip() for n in args.labels.split(",")]
    if len(names) != len(args.sets) or not all(names):
        raise ConfigError(
            f"--labels names {len(names)} sets but {len(args.sets)} were given; give one name per set, "
            "comma-separated (quote glob patterns so the shell does not split them into sets)"
        )
    return names


def _reference(args: argparse.Namespace, names: list[str]):
    import glob

    from realistic_indoor.models.reference import REFERENCE_SETS
    from realistic_indoor.validator.plan_sets import load_plan_set, show_progress

    ref = args.reference
    if ref == "paper" or (ref in REFERENCE_SETS and not Path(ref).exists()):
        return ref
    if not Path(ref).exists() and not glob.has_magic(ref):
        raise ConfigError(
            f"--reference {ref!r} is neither a folder, file or pattern of plans nor a paper table "
            f"(paper, {', '.join(REFERENCE_SETS)})"
        )
    return load_plan_set(
        ref, _reference_name(ref, names), strict=args.strict, progress=show_progress(args.quiet)
    )


def _reference_name(spec: str, set_names: list[str]) -> str:
    """The reference's name in the report: its folder's name, or more of its path where a set has it.

    A set named the same (``gen/office`` against ``real/office``) would make the tables read
    ``office vs office``; then the reference is named by its last two parts (``real/office``), and
    ``reference`` is put before a name that still collides.
    """
    parts = Path(spec.rstrip("/")).parts
    name = Path(parts[-1]).stem if parts else spec
    if name in set_names and len(parts) >= 2 and parts[-2] not in ("..", "."):
        name = f"{parts[-2]}/{name}"
    return f"reference {name}" if name in set_names else name


def _feature_groups(text: str) -> tuple[str, ...]:
    from realistic_indoor.validator.two_sample import FEATURE_GROUPS

    groups = tuple(dict.fromkeys(g.strip() for g in text.split(",") if g.strip()))
    unknown = [g for g in groups if g not in FEATURE_GROUPS]
    if unknown or not groups:
        raise ConfigError(
            f"--two-sample-features {text!r}: give one or more of {', '.join(FEATURE_GROUPS)}, comma-separated"
        )
    return groups


def _check_arguments(args: argparse.Namespace) -> None:
    """Refuse a bad ``--type`` and unwritable, existing or input ``-o`` and ``--plot`` paths first."""
    from realistic_indoor.cli._outputs import check_output
    from realistic_indoor.validator.compare import judged_type
    from realistic_indoor.validator.plot import PLOT_SUFFIXES

    if args.seed < 0:
        raise ConfigError(f"--seed must be an integer >= 0, got {args.seed}")
    if args.type is not None:
        judged_type(args.type)
    _feature_groups(args.two_sample_features)
    inputs = [*args.sets, *([args.reference] if getattr(args, "reference", None) else [])]
    if args.output:
        check_output(args.output, "-o", overwrite=args.overwrite, inputs=inputs)
    if args.plot:
        check_output(args.plot, "--plot", overwrite=args.overwrite, inputs=inputs, suffixes=PLOT_SUFFIXES)
    if args.output and args.plot and Path(args.output).resolve() == Path(args.plot).resolve():
        raise ConfigError(f"-o and --plot name the same file {args.output}; give them different names")


def _skipped_line(comparison: Comparison) -> str | None:
    """``"skipped 1 of 3 plans: broken.xml"`` over every set and a reference fitted from plans."""
    from realistic_indoor.validator.plan_sets import SkippedPlan, skipped_summary

    pairs = [*(p for s in comparison.sets for p in s.skipped), *comparison.reference_skipped]
    total = sum(len(s.plans) + len(s.skipped) for s in comparison.sets) + len(comparison.reference_skipped)
    if comparison.reference_set is not None:
        total += len(comparison.reference_set)
    return skipped_summary([SkippedPlan(src, why) for src, why in pairs], total)


def run(args: argparse.Namespace) -> int:
    """Load the sets, compare them, print the report, draw the figure."""
    from realistic_indoor.checks import require_int
    from realistic_indoor.files import write_text
    from realistic_indoor.validator.compare import compare_sets
    from realistic_indoor.validator.plan_sets import load_plan_set, show_progress
    from realistic_indoor.validator.report import render_comparison

    require_int("", "--worst", args.worst, 0, 100)
    names = _names(args)
    _check_arguments(args)
    progress = show_progress(args.quiet)
    reference = _reference(
        args, [n or Path(str(spec).rstrip("/")).stem for spec, n in zip(args.sets, names, strict=True)]
    )
    sets = [
        load_plan_set(spec, name, strict=args.strict, progress=progress)
        for spec, name in zip(args.sets, names, strict=True)
    ]
    if len(sets) > 6 and all(len(s) == 1 for s in sets) and args.labels is None:
        print(
            f"note: {len(sets)} sets of one plan each; quote a glob pattern to make it one set",
            file=sys.stderr,
        )
    comparison = compare_sets(
        sets,
        args.type,
        reference,
        infer=args.infer_labels,
        skip_bad=not args.strict,
        seed=args.seed,
        two_sample=not args.no_two_sample,
        two_sample_area=args.two_sample_area,
        two_sample_features=_feature_groups(args.two_sample_features),
        progress=progress,
    )
    text = render_comparison(comparison, args.format, worst=args.worst)
    if args.output:
        write_text(args.output, text)
        print(f"wrote {args.output}", file=sys.stderr)
    else:
        sys.stdout.write(text)
    if args.plot:
        from realistic_indoor.validator.plot import plot_comparison

        print(f"wrote {plot_comparison(comparison, args.plot)}", file=sys.stderr)
    if line := _skipped_line(comparison):
        print(f"{line} (listed in the report under 'Plans left out' or 'Notes')", file=sys.stderr)
    return 0
