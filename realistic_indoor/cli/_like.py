"""``realistic-indoor generate --like PLANS``: one generated twin per plan, with its floor area."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path


def add_like_options(parser: argparse.ArgumentParser) -> None:
    """Add ``--like`` and ``--strict`` to the ``generate`` parser."""
    parser.add_argument(
        "--like",
        metavar="PLANS",
        help="a folder, file or quoted glob of plans: write --count buildings (default 1) per plan with "
        "its floor area into --out-dir, named after the plan (like-for-like sets for validate)",
    )
    parser.add_argument(
        "--strict", action="store_true", help="with --like: stop at the first plan that cannot be read"
    )


def run_like(args: argparse.Namespace, options: dict) -> int:
    """Write the twins of every readable plan of ``args.like``; skip and count the others."""
    from tqdm import tqdm

    from realistic_indoor.cli._outputs import check_new_outputs, companions
    from realistic_indoor.cli._world3d import save_options
    from realistic_indoor.errors import ConfigError
    from realistic_indoor.files import check_output_dir
    from realistic_indoor.generator import generate_like
    from realistic_indoor.io import save
    from realistic_indoor.validator.plan_sets import PlanBatch, plan_files, show_progress

    if args.output or args.png or args.area is not None:
        raise ConfigError(
            "--like takes each plan's floor area and writes into --out-dir (not -o, --png, --area)"
        )
    if not args.out_dir:
        raise ConfigError("--like writes one file per plan and twin into --out-dir DIR")
    count = 1 if args.count is None else args.count
    if count < 1:
        raise ConfigError(f"--count must be at least 1, not {count}")
    out = check_output_dir(args.out_dir, "--out-dir")
    ext = "." + args.format.lstrip(".")
    written_as = save_options(args, f"x{ext}")
    files = plan_files(args.like)
    if not files:
        raise ConfigError(f"--like {args.like}: no plans there (plans end in .json or .xml)")
    names = [f.stem if count == 1 else f"{f.stem}_{k}" for f in files for k in range(count)]
    targets = [c for n in names for c in companions(out / f"{n}{ext}")]
    check_new_outputs(targets, "--out-dir", overwrite=args.overwrite, inputs=[args.like, *files])
    batch = PlanBatch(files, strict=args.strict)
    plans = ((path.stem, b) for path, b in batch if _of_type(batch, path, b, args.type))
    twins = generate_like(plans, args.type, count, args.seed or 0, **options)
    written = clamped = 0
    for twin in tqdm(twins, desc=f"{args.type} twins", unit="building", disable=not show_progress()):
        save(twin.building, out / f"{twin.name}{ext}", **written_as)
        written += 1
        if twin.clamped:
            clamped += 1
            area = twin.building.metadata["params"]["area_m2"]
            print(
                f"{twin.name}: its {twin.plan_area_m2:,.0f} m2 lie outside the {args.type} generator's "
                f"limits; generated at {area:,.0f} m2",
                file=sys.stderr,
            )
    if not written:
        raise ConfigError(
            f"--like {args.like}: none of its {len(files)} plans can be used as {args.type} plans"
        )
    print(
        f"wrote {written} {args.type} buildings like {len(files) - len(batch.skipped)} plans to {out}"
        + (f" ({clamped} at the generator's area limits)" if clamped else "")
    )
    if batch.summary():
        print(batch.summary(), file=sys.stderr)
    return 0


def _of_type(batch, path: Path, building, building_type: str) -> bool:
    """Whether a plan can have a twin of ``building_type``; plans of another known type are skipped."""
    declared = building.building_type.value
    if building_type in ("random", declared) or declared == "unknown":
        return True
    batch.skip(str(path), f"it is a {declared} plan, not a {building_type} one")
    return False
