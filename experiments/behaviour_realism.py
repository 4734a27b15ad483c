r"""Do robots explore generated buildings as they explore real buildings of the same size?

Behavioural realism (issue 11, item 4): the wall follower, the nearest-frontier and the
structure-aware explorers run once on every real plan of a folder and once on its like-for-like
twin, a generated building of the same type with the plan's floor area, all with the registered
id's step limit (``OfficeExplore-v0``: 6,000 steps of 0.2 s). The report gives the coverage AUC
per agent and set with 95% intervals, the twin-minus-real difference per agent paired by plan,
and the median steps to 90% coverage per 100 m2 of floor. The core is
:func:`realistic_indoor.evaluation.twins.behaviour_realism`.

Full run on the shared real offices (8 to 9 minutes on 2 cores)::

    .venv/bin/python experiments/behaviour_realism.py ../shared/data/real_floorplans/office \
        --type office --workers 2 --out experiments/results/behaviour_realism

writes into ``--out`` (default ``runs/behaviour_realism/TYPE``): ``behaviour_realism.md``
(report), ``behaviour_realism.png`` (figure), ``behaviour_realism.json``, ``episodes.csv``,
``summary.csv``, ``paired.csv``, the twins in ``twins/`` and the evaluation's raw results with
the coverage curves in ``evaluation/``. ``--small`` runs the whole pipeline in seconds on two
tiny generated plans (or the first two of PLANS), with 60-step episodes (the tests do).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
RUNS = ROOT / "runs" / "behaviour_realism"
SMALL_PLANS = 2
SMALL_STEPS = 60
SMALL_AREA_FACTOR = 1.2
"""Tiny plans of ``--small`` have 1.2 times the smallest area the generator makes."""


def parse_args(argv: list[str] | None) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument(
        "plans",
        nargs="*",
        metavar="PLANS",
        help="real plans: folders, files or quoted globs (needed unless --small or --report-only)",
    )
    p.add_argument("--type", default="office", help="building type of the plans and twins (default office)")
    p.add_argument(
        "--seed", type=int, default=0, help="seed of the first twin and of every episode (default 0)"
    )
    p.add_argument(
        "--max-steps",
        type=int,
        default=None,
        help="step limit of every episode (default: the registered id's)",
    )
    p.add_argument(
        "--plans", dest="max_plans", type=int, default=None, help="use the first N usable plans only"
    )
    p.add_argument(
        "--twins",
        type=int,
        default=1,
        help="twins per plan, averaged per plan in the paired differences (default 1)",
    )
    p.add_argument("--workers", type=int, default=None, help="processes (default: one per core)")
    p.add_argument("--ray", action="store_true", help="run the episodes on Ray (pip install ray)")
    p.add_argument("--ray-address", default=None, help="address of a Ray cluster (default: a local one)")
    p.add_argument("--strict", action="store_true", help="stop at the first plan that cannot be read")
    p.add_argument(
        "--resume", action="store_true", help="keep the episodes an earlier run into --out finished"
    )
    p.add_argument(
        "--out",
        default=None,
        help="output folder (default runs/behaviour_realism/TYPE; with --small a new temporary one)",
    )
    p.add_argument("--small", action="store_true", help="tiny plans, 60-step episodes: seconds, for tests")
    p.add_argument(
        "--report-only", action="store_true", help="write the report and figure again from --out's JSON"
    )
    return p.parse_args(argv)


def main(argv: list[str] | None = None) -> int:
    from realistic_indoor.cli import checkout_commit, run_folder, script_command
    from realistic_indoor.errors import ConfigError
    from realistic_indoor.evaluation.twins import behaviour_realism, shown_path
    from realistic_indoor.validator.plan_sets import show_progress

    args = parse_args(argv)
    out = run_folder(
        args.out, RUNS / args.type, small=args.small, report_only=args.report_only, name="behaviour_realism"
    )
    if args.report_only:
        return report_only(out)
    plans = args.plans
    if not plans and not args.small:
        raise ConfigError("give the real plans: a folder, files or a quoted glob (or --small)")
    if args.small and not plans:
        plans = [str(tiny_plans(out / "plans", args.type))]
    study = behaviour_realism(
        plans,
        args.type,
        out,
        seed=args.seed,
        max_steps=_given(args.max_steps, SMALL_STEPS if args.small else None),
        max_plans=_given(args.max_plans, SMALL_PLANS if args.small else None),
        workers=_given(args.workers, 1 if args.small else None),
        use_ray=args.ray,
        ray_address=args.ray_address,
        strict=args.strict,
        resume=args.resume,
        progress=show_progress(),
        meta={
            "command": script_command("experiments/behaviour_realism.py", argv),
            "commit": checkout_commit(ROOT),
        },
        twins_per_plan=args.twins,
    )
    print((out / "behaviour_realism.md").read_text(encoding="utf-8"))
    print(f"wrote {', '.join(shown_path(p) for p in study.files.values() if p.parent == out)}")
    return 0


def _given(value: int | None, default: int | None) -> int | None:
    """An option's value, or ``default`` when it was not given."""
    return default if value is None else value


def tiny_plans(folder: Path, building_type: str) -> Path:
    """Two small generated buildings of ``building_type`` saved as plans in ``folder``.

    Stand-ins for real plans in ``--small`` runs (seeds 1000 and 1001, so that they are not
    their own twins), of 1.2 times the generator's smallest area.
    """
    from realistic_indoor.generator import area_limits, generate_from, make_generator
    from realistic_indoor.io import save

    low, _high = area_limits(building_type)
    generator = make_generator(building_type, low * SMALL_AREA_FACTOR)
    for i in range(SMALL_PLANS):
        save(generate_from(generator, 1000 + i), folder / f"tiny-{building_type}-{i}.json")
    return folder


def report_only(out: Path) -> int:
    """Write the report, tables and figure again from ``out/behaviour_realism.json``."""
    from realistic_indoor.evaluation.twins_report import load_study, write_outputs

    write_outputs(load_study(out / "behaviour_realism.json"), out)
    print((out / "behaviour_realism.md").read_text(encoding="utf-8"))
    return 0


if __name__ == "__main__":
    from realistic_indoor.cli import run_script

    sys.exit(run_script(main, "behaviour_realism.py"))
