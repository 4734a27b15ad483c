"""Where generated twins differ from real plans: one explorer's gap and the room statistics, by size.

A diagnostic for generator work (issue 12), cheaper and steadier than the full behaviour study
(``experiments/behaviour_realism.py``): it draws ``--twins`` twins per real plan (seeds
``--seed`` on, as :func:`~realistic_indoor.generator.generate_like` numbers them), runs one
agent once on every plan and every twin, and prints

- the twin-minus-real coverage AUC, each plan's twins averaged first, over all plans with its
  standard error, then by floor-area band and by the twins' layout shape;
- per band, the room statistics :func:`~realistic_indoor.models.fit_model` learns from the real
  plans and from the twins: rooms per hectare, share and mean area of each label.

One twin per plan (what the behaviour study draws) leaves the wall follower's mean gap with a
standard error of about 0.02: single plans swing by 0.3 between twins of one size.

The robot starts just inside a building's first entrance. Real plans have none drawn and get
them inferred (:func:`~realistic_indoor.io.floorplan.entrances.infer_entrances`: an
``entrance`` space, else the largest hall or lobby on the outer wall, else the largest
corridor); twins have the ones the generator placed. ``--infer-entrances`` gives the twins
theirs by the real plans' rule instead, so both sides start by the same rule: how much of a
gap comes from where the robot starts rather than from the building.

Usage (the wall follower on the shared schools, three twins each: about a minute per core)::

    .venv/bin/python scripts/twin_gap_by_size.py ../shared/data/real_floorplans/school \
        --type school --agent wall --twins 3 --seed 1000 --workers 2
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import warnings
from collections import defaultdict
from pathlib import Path

BANDS_M2 = (1200.0, 3000.0)
"""Floor areas (m2) where the bands split: under 1,200, 1,200-3,000, 3,000 and over."""


def band(area_m2: float) -> str:
    """Name of the floor-area band of a plan of ``area_m2``."""
    if area_m2 < BANDS_M2[0]:
        return f"< {BANDS_M2[0]:,.0f} m2"
    if area_m2 < BANDS_M2[1]:
        return f"{BANDS_M2[0]:,.0f}-{BANDS_M2[1]:,.0f} m2"
    return f">= {BANDS_M2[1]:,.0f} m2"


def parse_args(argv: list[str] | None) -> argparse.Namespace:
    """The command line's arguments."""
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("plans", help="folder (or file, or quoted glob) of real plans")
    p.add_argument("--type", default="school", help="building type of the plans and twins (default school)")
    p.add_argument("--agent", default="wall", help="explorer to run (default wall: the wall follower)")
    p.add_argument("--twins", type=int, default=3, help="twins per plan (default 3)")
    p.add_argument("--seed", type=int, default=1000, help="seed of the first twin (default 1000)")
    p.add_argument("--workers", type=int, default=None, help="processes (default: one per core)")
    p.add_argument("--per-plan", action="store_true", help="also list every plan: area, real and twins' AUC")
    p.add_argument(
        "--infer-entrances",
        action="store_true",
        help="replace the twins' exterior doors by the ones the real plans' rule infers (same start rule)",
    )
    return p.parse_args(argv)


def with_inferred_entrances(building):
    """``building`` with its exterior doors replaced by those the real plans' rule infers.

    Interior doors are kept; the new doors are as wide as the widest exterior door it had (1 m
    without one) and say which rule placed them in ``metadata["inferred_entrances"]``.
    """
    from dataclasses import replace

    from realistic_indoor.io.floorplan.entrances import infer_entrances

    inner = tuple(d for d in building.doors if d.room_b is not None)
    width = max((d.width_m for d in building.doors if d.room_b is None), default=1.0)
    doors, note = infer_entrances(list(building.rooms), {d.id for d in inner}, width)
    return replace(
        building, doors=inner + tuple(doors), metadata={**building.metadata, "inferred_entrances": note}
    )


def main(argv: list[str] | None = None) -> int:
    """Run the diagnostic; exit code 2, with one line on stderr, for bad arguments or plans."""
    args = parse_args(argv)
    from realistic_indoor.errors import RealisticIndoorError

    try:
        with tempfile.TemporaryDirectory() as folder:
            report(args, Path(folder))
    except RealisticIndoorError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    return 0


def report(args: argparse.Namespace, folder: Path) -> None:
    """Draw the twins into ``folder``, run the agent and print the two tables."""
    from realistic_indoor.errors import ConfigError
    from realistic_indoor.evaluation.twins import explore_id, read_plans
    from realistic_indoor.generator import generate_like
    from realistic_indoor.io import load, save

    if args.twins < 1:
        raise ConfigError(f"--twins must be >= 1, not {args.twins}")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        plans = read_plans(args.plans, args.type)[0]
    if not plans:
        raise ConfigError(f"no usable {args.type} plan in {args.plans}")
    twins: dict[str, list[Path]] = defaultdict(list)
    shapes: dict[Path, str] = {}
    pairs = ((p.name, p.building) for p in plans)
    for i, twin in enumerate(generate_like(pairs, args.type, args.twins, args.seed)):
        path = folder / f"{twin.name}.json"
        save(with_inferred_entrances(twin.building) if args.infer_entrances else twin.building, path)
        twins[plans[i // args.twins].name].append(path)
        shapes[path] = str(twin.building.metadata.get("shape", "-"))
    auc = _coverage_auc(args, explore_id(args.type), [p.path for p in plans], list(shapes))
    starts = ", entrances inferred as the real plans'" if args.infer_entrances else ""
    print(
        f"{args.agent} on {len(plans)} {args.type} plans, {args.twins} twin(s) each (seeds {args.seed} on{starts})"
    )
    _gap_table(plans, twins, shapes, auc)
    if args.per_plan:
        _plan_table(plans, twins, shapes, auc)
    _room_table(plans, {p.name: [load(t) for t in twins[p.name]] for p in plans}, args.type)


def _coverage_auc(
    args: argparse.Namespace, env_id: str, plans: list[str], twins: list[Path]
) -> dict[str, float]:
    """Coverage AUC of one episode (seed 0) on every plan and twin file, by file."""
    from realistic_indoor.evaluation.runner import run_tasks
    from realistic_indoor.evaluation.tasks import EnvSpec, EpisodeTask

    files = [*plans, *(str(t) for t in twins)]
    tasks = [EpisodeTask(args.agent, EnvSpec(env_id, f), 0) for f in files]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        results = run_tasks(tasks, workers=args.workers, progress=False)
    return {f: r.coverage_auc for f, r in zip(files, results, strict=True)}


def _gap_table(plans, twins, shapes, auc) -> None:
    """Twin minus real, each plan's twins averaged: overall, by band, by the twins' shape."""
    gaps = {p.name: statistics.mean(auc[str(t)] for t in twins[p.name]) - auc[p.path] for p in plans}
    spread = statistics.stdev(gaps.values()) / len(gaps) ** 0.5 if len(gaps) > 1 else float("nan")
    print(f"\ntwin - real coverage AUC: {statistics.mean(gaps.values()):+.3f} (standard error {spread:.3f})")
    by_band: dict[str, list[float]] = defaultdict(list)
    by_shape: dict[str, list[float]] = defaultdict(list)
    for p in plans:
        by_band[band(p.building.area)].append(gaps[p.name])
        for t in twins[p.name]:
            by_shape[shapes[t]].append(auc[str(t)] - auc[p.path])
    for name, values in by_band.items():
        print(f"  {name:16s} {statistics.mean(values):+.3f} over {len(values)} plans")
    for name, values in sorted(by_shape.items(), key=lambda kv: -len(kv[1])):
        print(f"  shape {name:16s} {statistics.mean(values):+.3f} over {len(values)} twins")


def _plan_table(plans, twins, shapes, auc) -> None:
    """Every plan by floor area: its coverage AUC, and each twin's with the twin's shape."""
    print("\nper plan (by floor area): real AUC | twins' AUC (shape)")
    for p in sorted(plans, key=lambda p: p.building.area):
        made = ", ".join(f"{auc[str(t)]:.2f} ({shapes[t]})" for t in twins[p.name])
        print(f"  {p.name[:32]:32s} {p.building.area:7,.0f} m2  {auc[p.path]:.2f} | {made}")


def _room_table(plans, twins, building_type: str) -> None:
    """Per band: rooms per hectare and each label's share and mean area, real against twins."""
    from realistic_indoor.models import fit_model

    print("\nrooms per ha; per label: share of rooms / mean area m2 (real | twins)")
    for name in {band(p.building.area): None for p in sorted(plans, key=lambda p: p.building.area)}:
        real = [p.building for p in plans if band(p.building.area) == name]
        made = [t for p in plans if band(p.building.area) == name for t in twins[p.name]]
        models = [fit_model(real, name=building_type), fit_model(made, name=building_type)]
        density = [1e4 * sum(len(b.rooms) for b in s) / sum(b.area for b in s) for s in (real, made)]
        print(f"  {name:16s} rooms/ha {density[0]:5.0f} | {density[1]:5.0f}")
        for label in models[0].labels:
            a, b = (m.stats(label) for m in models)
            print(
                f"      {label.value:9s} {a.share:.2f} / {a.area_mean:6.1f}"
                f" | {b.share:.2f} / {b.area_mean:6.1f}"
            )


if __name__ == "__main__":
    sys.exit(main())
