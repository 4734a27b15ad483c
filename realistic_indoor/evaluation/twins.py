"""Behavioural realism: the reference explorers on real plans and on their like-for-like twins.

A generated building is realistic for a robot when robots behave in it as they do in real
buildings of the same size. :func:`behaviour_realism` reads a set of real plans, generates one
twin per plan (or several) with the plan's floor area
(:func:`~realistic_indoor.generator.generate_like`), runs the wall follower, the
nearest-frontier and the structure-aware explorers once on every plan and every twin, with one step limit for all (through :func:`run_evaluation`: parallel
processes, or Ray), and measures per agent and set (``"real"``, ``"twins"``):

- the coverage AUC (mean coverage over the step limit, in ``[0, 1]``) with a 95% bootstrap
  interval over the buildings;
- the twin-minus-real difference in coverage AUC, paired by plan, with a 95% bootstrap interval
  (pairing removes the spread between plans: it compares each plan with its own twins, their
  mean where there are several);
- the steps to 90% coverage per 100 m2 of floor, as a median over the buildings. An episode
  that never got there counts as slower than any that did, so the median is "not reached"
  (``NaN``) when half the episodes or more did not get there.

Real plans and twins start by the same rule: just inside the first usable entrance (real
floor-plan XML plans, which have no exterior doors, get their entrances inferred, as in every
evaluation; see :class:`~realistic_indoor.envs.explore.ExploreEnv`).

::

    from realistic_indoor.evaluation.twins import behaviour_realism

    study = behaviour_realism("../shared/data/real_floorplans/office", "office", "runs/behaviour")
    for row in study.paired:
        print(row["agent"], row["difference"], row["difference_low"], row["difference_high"])

``experiments/behaviour_realism.py`` is its command line; :mod:`.twins_report` writes the
report, tables and figure.
"""

from __future__ import annotations

import functools
import math
import os
import warnings
from collections.abc import Sequence
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from realistic_indoor.checks import require_int
from realistic_indoor.errors import ConfigError
from realistic_indoor.evaluation.aggregate import bootstrap_mean, wilson
from realistic_indoor.evaluation.twins_report import CONNECTED, FORMAT, write_outputs

if TYPE_CHECKING:
    from realistic_indoor.building.building import Building
    from realistic_indoor.evaluation.episode import EpisodeResult
    from realistic_indoor.validator.plan_sets import SkippedPlan

__all__ = [
    "AGENTS",
    "SETS",
    "BehaviourStudy",
    "ClampedAreaWarning",
    "PlanPair",
    "RealPlan",
    "behaviour_realism",
    "censored_median",
    "episode_rows",
    "explore_id",
    "make_twins",
    "paired_rows",
    "read_plans",
    "summary_rows",
    "twin_specs",
    "with_reachable_floor",
]

AGENTS: dict[str, str] = {
    "wall": "wall follower",
    "frontier": "nearest frontier",
    "structure": "structure-aware",
}
"""The reference explorers (agent name: label in reports)."""

SETS = ("real", "twins")
"""The two sets compared: the real plans and their generated twins."""

TARGET = 0.9
"""Coverage whose first crossing is timed (the evaluation's default target)."""


class ClampedAreaWarning(UserWarning):
    """A plan's floor area lies outside the generator's limits: its twin has the nearest limit's."""


@dataclass(frozen=True)
class RealPlan:
    """A real plan of the study.

    Attributes:
        name: Its file's stem (made unique with ``-2``, ``-3``, ... where stems repeat).
        path: Its file, as shown in outputs (relative to the working folder where it lies
            beside it).
        building: The plan, read with entrances inferred.
    """

    name: str
    path: str
    building: Building


@dataclass(frozen=True)
class PlanPair:
    """A real plan and one of its generated twins.

    Attributes:
        name: The plan's name (:attr:`RealPlan.name`); the twin's file is ``NAME.json`` (with
            several twins per plan, ``NAME_0.json``, ``NAME_1.json``, ...: see :attr:`twin_label`).
        plan: The real plan's file.
        twin: The twin's file.
        plan_area_m2: The plan's floor area (m2).
        twin_area_m2: The twin's floor area (m2).
        clamped: Whether the plan's area lay outside the generator's limits (the twin then has
            the nearest limit's area).
        seed: The generator seed of the twin.
        plan_reachable_m2: Floor of the plan reachable from the robot's start (m2), the floor
            its coverage is a share of (``NaN``: not measured).
        twin_reachable_m2: The same for the twin (m2).
        twin_name: The twin's own name where a plan has several (``NAME_0``, ``NAME_1``, ...);
            empty for a plan's only twin.
    """

    name: str
    plan: str
    twin: str
    plan_area_m2: float
    twin_area_m2: float
    clamped: bool
    seed: int
    plan_reachable_m2: float = math.nan
    twin_reachable_m2: float = math.nan
    twin_name: str = ""

    @property
    def twin_label(self) -> str:
        """The twin's name: :attr:`twin_name`, or the plan's name for a plan's only twin."""
        return self.twin_name or self.name

    @property
    def cut_off(self) -> bool:
        """Whether the start of the plan or of the twin reaches less than :data:`CONNECTED` of its floor.

        Such a start lies in a part of the building cut off from the rest (a plan drawn without
        some doors): coverage, a share of the reachable floor, then measures only that part.
        """
        shares = (self.plan_reachable_m2 / self.plan_area_m2, self.twin_reachable_m2 / self.twin_area_m2)
        return any(share < CONNECTED for share in shares)  # False where not measured (NaN)

    def to_dict(self) -> dict[str, Any]:
        """The pair as plain JSON-ready values, with :attr:`cut_off`."""
        return {**asdict(self), "cut_off": self.cut_off}


@dataclass
class BehaviourStudy:
    """What :func:`behaviour_realism` ran and measured.

    Attributes:
        data: Everything the report is made from, JSON-ready (``NaN`` where a value does not
            apply): ``meta``, ``plans`` (the pairs), ``skipped``, ``episodes``, ``summary``,
            ``paired``; written as ``behaviour_realism.json``.
        results: The episode results (with their coverage curves).
        files: The files written, by name.
    """

    data: dict[str, Any]
    results: list[EpisodeResult] = field(default_factory=list)
    files: dict[str, Path] = field(default_factory=dict)

    @property
    def summary(self) -> list[dict[str, Any]]:
        """One row per agent and set (see :func:`summary_rows`)."""
        return self.data["summary"]

    @property
    def paired(self) -> list[dict[str, Any]]:
        """One row per agent: twin minus real, paired by plan (see :func:`paired_rows`)."""
        return self.data["paired"]


def explore_id(building_type: str) -> str:
    """The registered exploration id of a building type (``"office"``: ``OfficeExplore-v0``).

    Raises:
        ConfigError: For a type without one.
    """
    from realistic_indoor.envs.presets import PRESETS

    env_id = f"{str(building_type).capitalize()}Explore-v0"
    if env_id not in PRESETS:
        types = sorted(k.removesuffix("Explore-v0").lower() for k in PRESETS if k.endswith("Explore-v0"))
        raise ConfigError(f"unknown building type {building_type!r}; valid: {', '.join(types)}")
    return env_id


def shown_path(path: str | Path) -> str:
    """``path`` as outputs show it: relative to the working folder when it lies within its parent.

    Relative paths are kept as they are; an absolute path elsewhere stays absolute. Either way
    it can be opened from the working folder.
    """
    p = Path(path)
    if not p.is_absolute():
        return str(p)
    cwd = Path.cwd()
    if not p.is_relative_to(cwd.parent):
        return str(p)
    return os.path.relpath(p, cwd)


# -- input -----------------------------------------------------------------------------------------


def read_plans(
    specs: str | Path | Sequence[str | Path], building_type: str, strict: bool = False
) -> tuple[list[RealPlan], list[SkippedPlan], int]:
    """The usable plans of ``building_type`` among the files that ``specs`` name.

    A plan that cannot be read, or has no rooms, is left out with a
    :class:`~realistic_indoor.validator.plan_sets.SkippedPlanWarning` naming it (under
    ``strict``, its error is raised instead). A plan of another declared type is left out the
    same way, also under ``strict``; plans of unknown type are taken.

    Args:
        specs: Files, folders (searched recursively) or glob patterns of plans.
        building_type: The type the plans must be (``"office"``, ``"school"``, ...).
        strict: Stop at the first plan that cannot be read (or that the floor-plan reader
            would have to repair).

    Returns:
        The plans (in file order), the plans left out, and the number of plan files found.

    Raises:
        ConfigError: If no plan file is found, or none of them is a usable plan of the type.
        PlanFormatError: Under ``strict``, for the first plan that cannot be read.
    """
    from realistic_indoor.evaluation.tasks import _load_plan
    from realistic_indoor.validator.plan_sets import PlanBatch, plan_files

    specs = [specs] if isinstance(specs, (str, Path)) else list(specs)
    where = ", ".join(str(s) for s in specs) or "no plans given"
    files = list(dict.fromkeys(Path(shown_path(f)) for spec in specs for f in plan_files(spec)))
    if not files:
        raise ConfigError(f"{where}: no plans there (plans end in .json or .xml)")
    batch = PlanBatch(files, strict=strict, reader=lambda p: _load_plan(str(p), strict))
    plans: list[RealPlan] = []
    for path, building in batch:
        reason = _unfit(building, building_type)
        if reason is None:
            plans.append(RealPlan(path.stem, str(path), building))
        elif strict and not building.rooms:
            batch.skip(str(path), reason)  # raises
        else:
            _skip_quietly(batch, str(path), reason)
    if not plans:
        first = batch.skipped[0]
        raise ConfigError(
            f"{where}: none of its {len(files)} plans is a usable {building_type} plan, "
            f"e.g. {first.source}: {first.reason}"
        )
    return _unique_names(plans), list(batch.skipped), len(files)


def _unfit(building: Building, building_type: str) -> str | None:
    """Why a plan cannot be a real plan of ``building_type`` (no rooms, another type), or ``None``."""
    if not building.rooms:
        return "the plan has no rooms"
    declared = building.building_type.value
    if building_type != "random" and declared not in (building_type, "unknown"):
        return f"its type is {declared}, not {building_type}"
    return None


def _skip_quietly(batch: Any, source: str, reason: str) -> None:
    """Leave a plan out with a warning even under ``strict`` (a plan of another type is readable)."""
    from realistic_indoor.validator.plan_sets import SkippedPlan, SkippedPlanWarning

    batch.skipped.append(SkippedPlan(source, reason))
    warnings.warn(f"skipped {source}: {reason}", SkippedPlanWarning, stacklevel=3)


def _unique_names(plans: list[RealPlan]) -> list[RealPlan]:
    """The plans with repeated stems numbered (``a``, ``a-2``, ``a-3``), in order."""
    seen: dict[str, int] = {}
    out = []
    for plan in plans:
        seen[plan.name] = seen.get(plan.name, 0) + 1
        name = plan.name if seen[plan.name] == 1 else f"{plan.name}-{seen[plan.name]}"
        out.append(RealPlan(name, plan.path, plan.building))
    return out


def make_twins(
    plans: Sequence[RealPlan], building_type: str, folder: str | Path, seed: int = 0, count: int = 1
) -> list[PlanPair]:
    """Generate and save ``count`` twins per plan: ``building_type`` buildings of the plan's floor area.

    The ``k``-th twin of the ``i``-th plan is drawn with seed ``seed + i * count + k`` (as
    :func:`~realistic_indoor.generator.generate_like` numbers them) and written to
    ``folder/NAME.json`` (one twin) or ``folder/NAME_K.json`` (several, ``K`` from 0). A plan whose area lies
    outside the generator's limits gets twins of the nearest limit's area, with a
    :class:`ClampedAreaWarning`.

    Args:
        plans: The real plans.
        building_type: The generator (``"office"``, ``"school"``, ...).
        folder: Where the twins are written (created if missing).
        seed: Seed of the first twin, >= 0.
        count: Twins per plan, >= 1.

    Returns:
        One pair per twin, plan by plan.

    Raises:
        ConfigError: For an unknown generator, a negative seed, a count under 1, or a folder
            that cannot be written.
    """
    from realistic_indoor.generator import generate_like
    from realistic_indoor.io import save

    require_int("make_twins", "count", count, 1)
    twins = iter(generate_like(((p.name, p.building) for p in plans), building_type, count, seed))
    pairs = []
    for i, plan in enumerate(plans):
        for k in range(count):
            twin = next(twins)
            path = Path(folder) / f"{twin.name}.json"
            save(twin.building, path)
            if twin.clamped and k == 0:
                warnings.warn(
                    f"{plan.path}: its {twin.plan_area_m2:,.0f} m2 lie outside the {building_type} "
                    f"generator's limits; its twin has {twin.building.area:,.0f} m2",
                    ClampedAreaWarning,
                    stacklevel=2,
                )
            pairs.append(
                PlanPair(
                    plan.name,
                    plan.path,
                    shown_path(path),
                    round(float(plan.building.area), 3),
                    round(float(twin.building.area), 3),
                    twin.clamped,
                    seed + i * count + k,
                    twin_name=twin.name if count > 1 else "",
                )
            )
    return pairs


def with_reachable_floor(pairs: Sequence[PlanPair], env_id: str) -> list[PlanPair]:
    """The pairs with the floor reachable from the robot's start measured in the plan and the twin.

    The start and the reachable floor are those of the environment ``env_id`` (its raster
    resolution and start rule): the floor the coverage of an episode is a share of.
    """
    from realistic_indoor.envs.presets import preset_config
    from realistic_indoor.evaluation.tasks import _load_plan
    from realistic_indoor.sim.world import World

    config = preset_config(env_id).world

    @functools.cache
    def reachable(path: str) -> float:  # a plan with several twins is measured once
        return round(World(_load_plan(path, False), config).reachable_area_m2, 3)

    return [
        replace(p, plan_reachable_m2=reachable(p.plan), twin_reachable_m2=reachable(p.twin)) for p in pairs
    ]


def twin_specs(pairs: Sequence[PlanPair], env_id: str, max_steps: int) -> list:
    """The environments of a study: every real plan (set ``real``) and every twin (set ``twins``).

    Labelled ``real:NAME`` (once per plan) and ``twin:`` and the twin's :attr:`PlanPair.twin_label`,
    all with the step limit ``max_steps``.
    """
    from realistic_indoor.evaluation.tasks import EnvSpec

    kwargs = {"max_steps": max_steps}
    plans = dict.fromkeys((p.name, p.plan) for p in pairs)
    real = [EnvSpec(env_id, plan, dict(kwargs), label=f"real:{name}", group="real") for name, plan in plans]
    twins = [
        EnvSpec(env_id, p.twin, dict(kwargs), label=f"twin:{p.twin_label}", group="twins") for p in pairs
    ]
    return real + twins


# -- the study -------------------------------------------------------------------------------------


def behaviour_realism(
    plans: str | Path | Sequence[str | Path],
    building_type: str,
    out_dir: str | Path,
    *,
    seed: int = 0,
    max_steps: int | None = None,
    max_plans: int | None = None,
    agents: dict[str, str] | None = None,
    workers: int | None = None,
    use_ray: bool = False,
    ray_address: str | None = None,
    strict: bool = False,
    resume: bool = False,
    progress: bool = False,
    meta: dict[str, Any] | None = None,
    twins_per_plan: int = 1,
) -> BehaviourStudy:
    """Run the reference explorers on real plans and on their twins; write and return the comparison.

    Writes into ``out_dir``: ``twins/`` (the twins, ``NAME.json``), ``evaluation/`` (the
    evaluation's episode log, ``episodes.csv``, ``summary.csv``, ``results.json`` with the
    coverage curves, coverage figures), and the study's ``behaviour_realism.md`` (report),
    ``behaviour_realism.png`` (figure), ``behaviour_realism.json``, ``episodes.csv``,
    ``summary.csv`` and ``paired.csv`` (see :func:`.twins_report.write_outputs`).

    Args:
        plans: Files, folders or glob patterns of real plans.
        building_type: Their type, which is also the twins' generator and picks the registered
            id (``office``: ``OfficeExplore-v0``).
        out_dir: The output folder.
        seed: Seed of the first twin (the ``k``-th twin of the ``i``-th plan gets
            ``seed + i * twins_per_plan + k``) and of every episode.
        max_steps: Step limit of every episode (0.2 s steps); ``None``: the registered id's.
        max_plans: Use only the first this many usable plans (``None``: all).
        agents: Agent names and their labels (default :data:`AGENTS`).
        workers: Parallel processes (``None``: one per core).
        use_ray: Run the episodes on Ray.
        ray_address: The Ray cluster's address (``None``: local).
        strict: Stop at the first plan that cannot be read instead of leaving it out.
        resume: Keep the episodes an earlier run into ``out_dir`` finished; run the others.
        progress: Show progress bars.
        meta: More to record in the outputs (the command that ran, the commit).
        twins_per_plan: Twins generated per plan; each plan's twins are averaged before the
            paired difference, so more twins take the draw of the twins out of it (one twin
            leaves the wall follower's mean gap with a standard error of about 0.02).

    Returns:
        The study.

    Raises:
        ConfigError: For no usable plan, a bad type, step limit or output folder (before any
            episode runs).
        PlanFormatError: Under ``strict``, for the first plan that cannot be read.
    """
    from realistic_indoor.evaluation import run_evaluation
    from realistic_indoor.files import check_output_dir
    from realistic_indoor.generator import area_limits

    env_id = explore_id(building_type)
    steps = _step_limit(env_id, max_steps)
    out = check_output_dir(out_dir, "output folder")
    agents = dict(agents or AGENTS)
    if max_plans is not None and (
        isinstance(max_plans, bool) or not isinstance(max_plans, int) or max_plans < 1
    ):
        raise ConfigError(f"max_plans must be an integer >= 1, not {max_plans!r}")
    require_int("behaviour_realism", "twins_per_plan", twins_per_plan, 1)
    real, skipped, found = read_plans(plans, building_type, strict)
    real = real[:max_plans] if max_plans is not None else real
    twins = make_twins(real, building_type, out / "twins", seed, twins_per_plan)
    pairs = with_reachable_floor(twins, env_id)
    evaluation = run_evaluation(
        list(agents),
        twin_specs(pairs, env_id, steps),
        episodes=1,
        seed=seed,
        workers=workers,
        out_dir=out / "evaluation",
        use_ray=use_ray,
        ray_address=ray_address,
        progress=progress,
        strict=strict,
        resume=resume,
    )
    rows = episode_rows(evaluation.results, pairs)
    low, high = area_limits(building_type)
    data = {
        "format": FORMAT,
        "meta": {
            **(meta or {}),
            "building_type": building_type,
            "env_id": env_id,
            "max_steps": steps,
            "seed": seed,
            "twins_per_plan": twins_per_plan,
            "agents": agents,
            "plans_given": [shown_path(p) for p in ([plans] if isinstance(plans, (str, Path)) else plans)],
            "plan_files": found,
            "generator_area_limits_m2": [low, high],
            "target": TARGET,
        },
        "plans": [p.to_dict() for p in pairs],
        "skipped": [s.to_dict() for s in [*skipped, *evaluation.skipped]],
        "episodes": rows,
        "summary": summary_rows(rows, agents),
        "paired": paired_rows(rows, agents),
    }
    study = BehaviourStudy(data, evaluation.results)
    study.files = {**write_outputs(data, out), **{f"evaluation_{k}": v for k, v in evaluation.files.items()}}
    return study


def _step_limit(env_id: str, max_steps: int | None) -> int:
    """``max_steps``, or the registered id's step limit.

    Raises:
        ConfigError: If ``max_steps`` is not an integer >= 1.
    """
    from realistic_indoor.envs.presets import PRESETS

    if max_steps is None:
        return PRESETS[env_id].max_episode_steps
    if isinstance(max_steps, bool) or not isinstance(max_steps, int) or max_steps < 1:
        raise ConfigError(f"max_steps must be an integer >= 1, not {max_steps!r}")
    return max_steps


# -- analysis --------------------------------------------------------------------------------------


def episode_rows(results: Sequence[EpisodeResult], pairs: Sequence[PlanPair]) -> list[dict[str, Any]]:
    """One row per episode: agent, set, plan, floor areas and what the episode measured.

    ``area_m2`` is the building's floor area, ``reachable_m2`` the floor reachable from the
    start (the floor the coverage is a share of; the floor area where it was not measured),
    ``cut_off`` the pair's :attr:`PlanPair.cut_off`. ``steps_to_90`` is the first step at
    which the coverage reached 90% (``NaN`` if it never did), ``steps_to_90_per_100m2`` that
    divided by the reachable floor in hundreds of m2.

    Args:
        results: Results of environments labelled as :func:`twin_specs` labels them.
        pairs: The plans and twins.
    """
    cut = {p.name for p in pairs if p.cut_off}  # a plan is cut off if it or one of its twins is
    where = {f"real:{p.name}": ("real", p, p.plan_area_m2, p.plan_reachable_m2) for p in pairs}
    where |= {f"twin:{p.twin_label}": ("twins", p, p.twin_area_m2, p.twin_reachable_m2) for p in pairs}
    rows = []
    for r in results:
        kind, pair, area, reachable = where[r.env]
        reachable = reachable if math.isfinite(reachable) else area
        steps_to = round(r.time_to_target_s / r.dt_s) if r.reached_target else math.nan
        rows.append(
            {
                "agent": r.agent,
                "set": kind,
                "plan": pair.name,
                "twin": pair.twin_label if kind == "twins" else "",
                "file": pair.plan if kind == "real" else pair.twin,
                "area_m2": area,
                "reachable_m2": reachable,
                "cut_off": pair.name in cut if kind == "real" else pair.cut_off,
                "seed": r.seed,
                "steps": r.steps,
                "max_steps": r.max_steps,
                "coverage_auc": round(r.coverage_auc, 6),
                "final_coverage": round(r.final_coverage, 6),
                "reached_90": r.reached_target,
                "steps_to_90": steps_to,
                "steps_to_90_per_100m2": steps_to / (reachable / 100.0) if r.reached_target else math.nan,
                "path_length_m": round(r.path_length_m, 3),
                "collisions": r.collisions,
            }
        )
    return rows


def censored_median(values: Sequence[float]) -> float:
    """Median where ``NaN`` marks "never got there", i.e. slower than any finite value.

    Returns:
        The median; ``NaN`` when it falls on (or, for an even count, half on) an episode that
        never got there, or when ``values`` is empty.
    """
    x = np.asarray(values, dtype=float)
    if len(x) == 0:
        return math.nan
    m = float(np.median(np.where(np.isnan(x), np.inf, x)))
    return m if math.isfinite(m) else math.nan


def summary_rows(rows: Sequence[dict[str, Any]], agents: dict[str, str]) -> list[dict[str, Any]]:
    """One row per agent and set, agents in the order given, ``real`` before ``twins``.

    Columns: ``agent``, ``label``, ``set``, ``episodes``; ``coverage_auc`` with ``_low`` and
    ``_high`` (95% bootstrap interval of the mean); ``final_coverage`` (mean); ``reached_90``
    (episodes that reached 90% coverage) with ``reached_90_share`` and its Wilson interval;
    ``steps_to_90_per_100m2_median`` (:func:`censored_median`; ``NaN``: not reached by half).
    Agent and set pairs without episodes are left out.
    """
    out = []
    for agent, label in agents.items():
        for kind in SETS:
            group = [r for r in rows if r["agent"] == agent and r["set"] == kind]
            if not group:
                continue
            auc = bootstrap_mean([r["coverage_auc"] for r in group])
            reached = sum(int(r["reached_90"]) for r in group)
            share = wilson(reached, len(group))
            out.append(
                {
                    "agent": agent,
                    "label": label,
                    "set": kind,
                    "episodes": len(group),
                    "coverage_auc": auc.mean,
                    "coverage_auc_low": auc.low,
                    "coverage_auc_high": auc.high,
                    "final_coverage": float(np.mean([r["final_coverage"] for r in group])),
                    "reached_90": reached,
                    "reached_90_share": share.mean,
                    "reached_90_share_low": share.low,
                    "reached_90_share_high": share.high,
                    "steps_to_90_per_100m2_median": censored_median(
                        [r["steps_to_90_per_100m2"] for r in group]
                    ),
                }
            )
    return out


def paired_rows(rows: Sequence[dict[str, Any]], agents: dict[str, str]) -> list[dict[str, Any]]:
    """Per agent: coverage AUC on each plan's twins (their mean) minus on the plan, over the plans.

    Only plans with episodes in both sets count. Columns: ``agent``, ``label``, ``pairs``; ``real`` and ``twins`` (mean coverage AUC over
    those plans); ``difference`` (mean of twin minus real) with ``_low`` and ``_high`` (95%
    bootstrap interval over the plans); ``twin_higher`` (plans whose twin scored higher); and
    ``connected_pairs``, ``connected_difference`` with ``_low`` and ``_high``: the same over
    the pairs that are not ``cut_off``.
    """
    out = []
    for agent, label in agents.items():
        real = {r["plan"]: r["coverage_auc"] for r in rows if r["agent"] == agent and r["set"] == "real"}
        twins: dict[str, list[float]] = {}
        for r in rows:
            if r["agent"] == agent and r["set"] == "twins":
                twins.setdefault(r["plan"], []).append(r["coverage_auc"])
        twin = {plan: float(np.mean(aucs)) for plan, aucs in twins.items()}
        cut = {r["plan"] for r in rows if r["cut_off"]}
        plans = [p for p in real if p in twin]
        d = bootstrap_mean([twin[p] - real[p] for p in plans])
        connected = bootstrap_mean([twin[p] - real[p] for p in plans if p not in cut])
        out.append(
            {
                "agent": agent,
                "label": label,
                "pairs": len(plans),
                "real": float(np.mean([real[p] for p in plans])) if plans else math.nan,
                "twins": float(np.mean([twin[p] for p in plans])) if plans else math.nan,
                "difference": d.mean,
                "difference_low": d.low,
                "difference_high": d.high,
                "twin_higher": sum(twin[p] > real[p] for p in plans),
                "connected_pairs": connected.n,
                "connected_difference": connected.mean,
                "connected_difference_low": connected.low,
                "connected_difference_high": connected.high,
            }
        )
    return out
