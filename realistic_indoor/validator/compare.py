"""Compare sets of maps with each other and with a reference: tables, connectivity, scores, tests."""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from itertools import combinations
from typing import TYPE_CHECKING

from realistic_indoor.building.labels import BuildingType, SemanticLabel, parse_building_type
from realistic_indoor.errors import ConfigError, RealisticIndoorError
from realistic_indoor.models.scale import ScaleFlag, scale_check
from realistic_indoor.validator.building_measures import BuildingMeasures, building_measures, measure_summary
from realistic_indoor.validator.connectivity import set_connectivity
from realistic_indoor.validator.house_programme import HouseCheck, HouseSummary, house_check, house_summary
from realistic_indoor.validator.label_inference import infer_labels, lacks_labels
from realistic_indoor.validator.plan_sets import PlanSet, SkippedPlanWarning, plan_problem
from realistic_indoor.validator.reference import Reference, fitted_reference, paper_reference
from realistic_indoor.validator.score import RealismScore, ScoreConfig, score_statistics
from realistic_indoor.validator.tables import label_table

if TYPE_CHECKING:
    from collections.abc import Callable, Sequence

    from realistic_indoor.building.building import Building
    from realistic_indoor.validator.connectivity import Connectivity
    from realistic_indoor.validator.two_sample import TwoSampleResult

__all__ = [
    "INFER_MODES",
    "JUDGED_TYPES",
    "Comparison",
    "SetReport",
    "common_building_type",
    "compare_sets",
    "judged_type",
    "prepare_set",
]

INFER_MODES = ("auto", "always", "never")
"""When semantic labels are inferred: for plans that lack them, for every plan, or never."""

JUDGED_TYPES: tuple[BuildingType, ...] = tuple(t for t in BuildingType if t is not BuildingType.UNKNOWN)
"""The types plans can be judged as: those with a reference table (office, school, house)."""


@dataclass(frozen=True)
class SetReport:
    """Everything measured on one set of maps.

    Attributes:
        plans: The set as measured (labels inferred where they were, bad plans left out).
        table: Its Table 1 (:func:`~realistic_indoor.validator.tables.label_table`).
        connectivity: Its pooled connectivity.
        score: Its realism score against the comparison's reference.
        scale_flags: Plans whose scale looks wrong.
        inferred: Sources of the plans whose semantic labels were inferred.
        skipped: ``(source, reason)`` of plans left out: those of its files that could not be
            read, then those that cannot be measured.
        measures: The building-level measures of each plan, in the order of ``plans``.
        houses: Each plan measured against the house programme, in the order of ``plans``
            (sets judged as houses only).
    """

    plans: PlanSet
    table: dict[SemanticLabel, dict[str, float]]
    connectivity: Connectivity
    score: RealismScore
    scale_flags: tuple[ScaleFlag, ...]
    inferred: tuple[str, ...]
    skipped: tuple[tuple[str, str], ...]
    measures: tuple[BuildingMeasures, ...] = ()
    houses: tuple[HouseCheck, ...] = ()

    @property
    def house_summary(self) -> HouseSummary | None:
        """The share of the set's plans inside the house programme per item (``None``: not judged as houses)."""
        return house_summary(self.houses) if self.houses else None

    @property
    def measure_summary(self) -> dict[str, dict[str, float]]:
        """Median and quartiles of each building-level measure over the set's plans."""
        return measure_summary(self.measures)

    @property
    def name(self) -> str:
        """The set's name."""
        return self.plans.name

    @property
    def rooms(self) -> int:
        """Number of rooms over all its plans."""
        return sum(len(b.rooms) for b in self.plans.buildings)


@dataclass(frozen=True)
class Comparison:
    """Sets of maps measured against one reference.

    Attributes:
        building_type: The type the sets are judged as.
        reference: The reference statistics.
        sets: One report per set, in the order given.
        two_sample: Classifier two-sample tests between every two sets (and each set against a
            reference fitted from plans).
        notes: Things the reader should know (tests that could not run, ...).
        reference_set: The reference's plans, when it was fitted from plans.
        reference_skipped: ``(source, reason)`` of the reference's plans left out (also in
            ``notes``).
        reference_measures: The building-level measures of the reference's plans, when it was
            fitted from plans (the paper gives none).
    """

    building_type: BuildingType
    reference: Reference
    sets: tuple[SetReport, ...]
    two_sample: tuple[TwoSampleResult, ...]
    notes: tuple[str, ...] = ()
    reference_set: PlanSet | None = None
    reference_skipped: tuple[tuple[str, str], ...] = ()
    reference_measures: tuple[BuildingMeasures, ...] = ()


def judged_type(value: BuildingType | str) -> BuildingType:
    """The building type named by ``value``, as plans can be judged: office, school or house.

    Raises:
        ConfigError: If ``value`` names no type, or ``unknown`` (which has no reference); the
            message lists the valid types.
    """
    valid = ", ".join(t.value for t in JUDGED_TYPES)
    try:
        btype = parse_building_type(value)
    except ConfigError:
        raise ConfigError(f"unknown building type {value!r}; valid types: {valid}") from None
    if btype not in JUDGED_TYPES:
        raise ConfigError(f"plans cannot be judged as of type {btype.value!r}; choose one of: {valid}")
    return btype


def common_building_type(sets: Sequence[PlanSet]) -> BuildingType:
    """The one building type all plans of ``sets`` declare (plans of unknown type are ignored).

    Raises:
        ConfigError: If the plans declare several types, or none.
    """
    types = sorted({b.building_type.value for s in sets for b in s.buildings} - {BuildingType.UNKNOWN.value})
    if len(types) == 1:
        return BuildingType(types[0])
    valid = ", ".join(t.value for t in JUDGED_TYPES)
    if not types:
        raise ConfigError(
            f"the plans do not say what type of building they are; choose one with --type ({valid})"
        )
    raise ConfigError(
        f"the plans are of several types ({', '.join(types)}); choose one with --type ({valid})"
    )


def prepare_set(
    plans: PlanSet, building_type: BuildingType | str, infer: str = "auto", skip_bad: bool = False
) -> tuple[PlanSet, tuple[str, ...], tuple[tuple[str, str], ...]]:
    """Check a set's plans and infer semantic labels where ``infer`` says.

    Args:
        plans: The set.
        building_type: Type whose size thresholds label rooms by area.
        infer: ``"auto"`` (plans that lack labels, see
            :func:`~realistic_indoor.validator.label_inference.lacks_labels`), ``"always"`` or
            ``"never"``.
        skip_bad: Leave out plans that cannot be measured instead of raising.

    Returns:
        The prepared set, the sources of plans whose labels were inferred, and the
        ``(source, reason)`` of plans left out: the set's unreadable files (``plans.skipped``),
        then the plans that cannot be measured (each also warned about with a
        :class:`~realistic_indoor.validator.plan_sets.SkippedPlanWarning`).

    Raises:
        ConfigError: If the set is empty (or nothing is left after skipping), or ``infer`` is unknown.
        RealisticIndoorError: If a plan has no rooms or no doors and ``skip_bad`` is false.
    """
    if infer not in INFER_MODES:
        raise ConfigError(f"unknown label inference mode {infer!r}; valid: {', '.join(INFER_MODES)}")
    if not plans.buildings:
        raise ConfigError(f"set {plans.name!r} holds no plans")
    kept, sources, inferred = [], [], []
    skipped = [(s.source, s.reason) for s in plans.skipped]
    for b, src in zip(plans.buildings, plans.sources, strict=True):
        problem = plan_problem(b)
        if problem and not skip_bad:
            raise RealisticIndoorError(
                f"{src}: {problem}; fix or remove it (or leave such plans out: skip_bad=True in Python, "
                "or the command without --strict)"
            )
        if problem:
            skipped.append((src, problem))
            warnings.warn(f"skipped {src}: {problem}", SkippedPlanWarning, stacklevel=2)
            continue
        if infer == "always" or (infer == "auto" and lacks_labels(b)):
            b = infer_labels(b, building_type)
            inferred.append(src)
        kept.append(b)
        sources.append(src)
    if not kept:
        src, why = skipped[0]
        raise ConfigError(
            f"set {plans.name!r}: no plan left to measure; all {len(skipped)} left out, e.g. {src}: {why}"
        )
    return PlanSet(plans.name, tuple(kept), tuple(sources)), tuple(inferred), tuple(skipped)


def _own_type(b: Building, default: BuildingType) -> BuildingType:
    """The type a plan declares, or ``default`` for a plan of unknown type."""
    return default if b.building_type is BuildingType.UNKNOWN else b.building_type


def _report(
    plans: PlanSet, btype: BuildingType, reference: Reference, infer: str, skip_bad: bool, cfg: ScoreConfig
) -> SetReport:
    prepared, inferred, skipped = prepare_set(plans, btype, infer, skip_bad)
    table, conn = label_table(prepared.buildings), set_connectivity(prepared.buildings)
    flags = tuple(
        f
        for b, src in zip(prepared.buildings, prepared.sources, strict=True)
        if (f := scale_check(b, _own_type(b, btype), source=src)) is not None
    )
    score = score_statistics(table, conn, reference, cfg)
    measures = tuple(building_measures(b) for b in prepared.buildings)
    houses = tuple(house_check(b) for b in prepared.buildings) if btype is BuildingType.HOUSE else ()
    return SetReport(prepared, table, conn, score, flags, inferred, skipped, measures, houses)


def _reference(
    reference: str | Reference | PlanSet, btype: BuildingType, infer: str, skip_bad: bool
) -> tuple[Reference, PlanSet | None, tuple[tuple[str, str], ...]]:
    """The reference, its prepared plans (when fitted from plans) and its plans left out."""
    if isinstance(reference, Reference):
        return reference, None, ()
    if isinstance(reference, PlanSet):
        prepared, _inferred, skipped = prepare_set(reference, btype, infer, skip_bad)
        return fitted_reference(prepared.buildings, prepared.name, btype), prepared, skipped
    return paper_reference(btype if reference == "paper" else reference), None, ()


def _two_sample_tests(
    named: Sequence[PlanSet],
    seed: int,
    with_area: bool,
    groups: Sequence[str],
    tick: Callable[[str], object],
) -> tuple[list[TwoSampleResult], list[str]]:
    from realistic_indoor.validator.two_sample import two_sample_test

    results, notes = [], []
    for a, b in combinations(named, 2):
        if min(len(a), len(b)) < 2:
            notes.append(f"no two-sample test of {a.name} vs {b.name}: it needs at least 2 plans in each set")
            continue
        tick(f"two-sample test {a.name} vs {b.name}")
        results += [
            two_sample_test(
                a.buildings, b.buildings, names=(a.name, b.name), seed=seed, with_area=with_area, features=g
            )
            for g in groups
        ]
    return results, notes


def _steps(total: int, show: bool) -> tuple[Callable[[str], object], Callable[[], object]]:
    """A progress bar on stderr of ``total`` steps: ``tick(what)`` starts the next one; ``close()``."""
    from tqdm import tqdm

    bar = tqdm(total=total, unit="step", disable=not show, leave=False, bar_format="{desc} {n}/{total} {bar}")
    started = [False]

    def tick(what: str) -> None:
        if started[0]:
            bar.update(1)
        started[0] = True
        bar.set_description_str(what)

    return tick, bar.close


def compare_sets(
    sets: Sequence[PlanSet],
    building_type: BuildingType | str | None = None,
    reference: str | Reference | PlanSet = "paper",
    *,
    infer: str = "auto",
    skip_bad: bool = False,
    seed: int = 0,
    two_sample: bool = True,
    two_sample_area: bool = False,
    two_sample_features: Sequence[str] = ("room", "building", "all"),
    score_config: ScoreConfig | None = None,
    progress: bool = False,
) -> Comparison:
    """Measure every set against a reference, and the sets against each other.

    Args:
        sets: The sets of maps (at least one).
        building_type: Type they are judged as (default: the type their plans declare).
        reference: ``"paper"`` (the paper's Table 1 for ``building_type``), the name of another
            paper table (``"all_types"``, ``"robocup_2013_final_map"``), a set of plans to fit
            the reference from, or a :class:`~realistic_indoor.validator.reference.Reference`.
        infer: When to infer semantic labels (see :func:`prepare_set`).
        skip_bad: Leave out plans without rooms or doors instead of raising.
        seed: Seed of the two-sample tests' cross-validation.
        two_sample: Run the two-sample tests (they need scikit-learn and take about a second).
        two_sample_area: Let the two-sample tests use room areas too (default: scale-free
            features only).
        two_sample_features: The feature groups of the two-sample tests, one test per group
            and pair of sets (see :data:`~realistic_indoor.validator.two_sample.FEATURE_GROUPS`).
        score_config: Constants of the realism score (default :class:`ScoreConfig`).
        progress: Show on stderr which set or test is being measured (a tqdm bar).

    Raises:
        ConfigError: If there is no set, a set is empty, the type is unknown (or ``unknown``:
            see :func:`judged_type`) or ambiguous.
        RealisticIndoorError: If a plan cannot be measured and ``skip_bad`` is false.
    """
    if not sets:
        raise ConfigError("nothing to validate: give at least one set of plans")
    names = [s.name for s in sets]
    if len(set(names)) < len(names):
        raise ConfigError(f"two sets have the same name ({', '.join(names)}); name them with --labels")
    if building_type is None:
        ref_sets = [reference] if isinstance(reference, PlanSet) else []
        btype = common_building_type([*sets, *ref_sets])
    else:
        btype = judged_type(building_type)
    n_named = len(sets) + isinstance(reference, PlanSet)
    tick, close = _steps(
        len(sets) + isinstance(reference, PlanSet) + two_sample * math.comb(n_named, 2), progress
    )
    try:
        if isinstance(reference, PlanSet):
            tick(f"measuring reference {reference.name}")
        ref, ref_set, ref_skipped = _reference(reference, btype, infer, skip_bad)
        notes = [f"reference {ref.name}: left out {src}: {why}" for src, why in ref_skipped]
        cfg = score_config or ScoreConfig()
        reports = []
        for s in sets:
            tick(f"measuring {s.name}")
            reports.append(_report(s, btype, ref, infer, skip_bad, cfg))
        tests: list[TwoSampleResult] = []
        if two_sample:
            named = [r.plans for r in reports] + ([ref_set] if ref_set is not None else [])
            tests, test_notes = _two_sample_tests(named, seed, two_sample_area, two_sample_features, tick)
            notes += test_notes
            if len(named) < 2:
                notes.append(
                    "no two-sample test: it compares two sets of plans (give a second set or --reference DIR)"
                )
    finally:
        close()
    ref_measures = tuple(building_measures(b) for b in ref_set.buildings) if ref_set is not None else ()
    return Comparison(
        btype, ref, tuple(reports), tuple(tests), tuple(notes), ref_set, ref_skipped, ref_measures
    )
