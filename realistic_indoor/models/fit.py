"""Learning a building-type model from a set of plans (real ones, or another generator's)."""

from __future__ import annotations

import math
from collections import Counter
from typing import TYPE_CHECKING

import numpy as np

from realistic_indoor.building.labels import (
    OUTSIDE,
    ROOM_LABELS,
    BuildingType,
    SemanticLabel,
    normalise_function,
)
from realistic_indoor.building.topology import circulation_loops
from realistic_indoor.errors import ConfigError
from realistic_indoor.models.building_model import (
    COMPOSED_FILL,
    BuildingTypeModel,
    DoorHabits,
    FootprintHabits,
    LabelStats,
    LocalStructures,
    RoomDensity,
    SizeScaling,
)

if TYPE_CHECKING:
    from collections.abc import Iterable

    from realistic_indoor.building.building import Building

__all__ = ["fit_model"]

C, H, S = SemanticLabel.CORRIDOR, SemanticLabel.HALL, SemanticLabel.SMALL


def fit_model(
    buildings: Iterable[Building], *, name: str | None = None, skip_misscaled: bool = True
) -> BuildingTypeModel:
    """Fit a building-type model to plans.

    Everything the generators use is measured: the share, area, axes ratio and door count of
    each semantic label; the labels each label's doorways lead to; each label's functional
    labels; and how often the recurring local structures occur (closets, connected room pairs,
    clustered small rooms, halls at junctions). A generator given the model
    (``make_generator(name, model=...)``) then builds buildings with these statistics.

    Args:
        buildings: The plans (with semantic labels; infer them first where they lack them).
        name: The type's name (default: the plans' common building type, else ``"unknown"``).
        skip_misscaled: Leave plans whose scale looks wrong out of the area statistics (see
            :func:`realistic_indoor.models.scale.scale_check`); their scale-free statistics
            (shares, doors, axes ratios, connections) still count.

    Returns:
        The fitted model. A label no plan has gets share 0 and the statistics of all real
        buildings (the paper's ``all_types``), so a generator can still size it.

    Raises:
        ConfigError: If the plans hold no rooms.

    Examples:
        >>> from realistic_indoor.generator import generate
        >>> model = fit_model([generate("office", 600, seed=s) for s in range(3)])
        >>> model.name, round(sum(s.share for s in model.labels.values()), 6)
        ('office', 1.0)
    """
    plans = list(buildings)
    rooms = [(b, r) for b in plans for r in b.rooms]
    if not rooms:
        raise ConfigError("cannot fit a model to plans without rooms; give at least one plan with rooms")
    scaled = _well_scaled(plans) if skip_misscaled else plans
    types = {b.building_type for b in plans}
    if name is None:
        name = next(iter(types)).value if len(types) == 1 else BuildingType.UNKNOWN.value
    return BuildingTypeModel(
        name=name,
        labels=_label_stats(plans, scaled),
        connections=_connections(plans),
        functions=_functions(plans),
        structures=_structures(plans),
        size_scaling=_size_scaling(scaled),
        door_habits=_door_habits(plans),
        density=_room_density(plans),
        footprint=_footprint_habits(plans),
        source=f"fitted to {len(plans)} plans ({len(scaled)} with plausible scales)",
    )


def _well_scaled(plans: list[Building]) -> list[Building]:
    from realistic_indoor.models.scale import scale_check

    kept = [b for b in plans if scale_check(b, reference="paper") is None]  # not judged by the fit itself
    return kept or plans


def _mean_std(values: list[float]) -> tuple[float, float]:
    arr = np.asarray(values, dtype=float)
    return float(arr.mean()), float(arr.std())


def _label_stats(plans: list[Building], scaled: list[Building]) -> dict[SemanticLabel, LabelStats]:
    from realistic_indoor.models.reference import reference_table

    fallback = reference_table("all_types")
    counts = Counter(r.label for b in plans for r in b.rooms)
    total = sum(counts.values())
    out = {}
    for lab in SemanticLabel:
        rows = [(b, r) for b in plans for r in b.rooms if r.label is lab]
        areas = [r.area for b in scaled for r in b.rooms if r.label is lab]
        if not rows:
            ref = {k: v for k, v in fallback[lab].items() if k != "share_pct"}
            out[lab] = LabelStats(share=0.0, **ref)
            continue
        area = _mean_std(areas or [r.area for _, r in rows])
        doors = _mean_std([len(b.doors_of[r.id]) for b, r in rows])
        ratio = _mean_std([min(r.axes_ratio, 50.0) for _, r in rows])
        out[lab] = LabelStats(counts[lab] / total, *area, *doors, *ratio)
    return out


def _size_scaling(plans: list[Building]) -> SizeScaling:
    """How each label's mean room area grows with the plan's floor area (log-log slope).

    One point per plan and label, ``(log floor area, log(the plan's mean area of the label /
    the label's mean over all plans))``, weighted by the plan's rooms of that label; the slope
    of the weighted least-squares line is the exponent, and the room-weighted mean log floor
    area the reference (where the pooled label means hold). Fewer than three plans, or plans all
    of one size, give no scaling.
    """
    if len({b.area for b in plans}) < 3:
        return SizeScaling()
    points = []
    for lab in SemanticLabel:
        pooled = [r.area for b in plans for r in b.rooms if r.label is lab]
        if not pooled:
            continue
        mean = float(np.mean(pooled))
        for b in plans:
            areas = [r.area for r in b.rooms if r.label is lab]
            if areas and b.area > 0:
                points.append((np.log(b.area), np.log(np.mean(areas) / mean), len(areas)))
    if not points:
        return SizeScaling()
    x, y, w = (np.array(v, dtype=float) for v in zip(*points, strict=True))
    x_ref = float(np.average(x, weights=w))
    dx = x - x_ref
    slope = float(np.sum(w * dx * (y - np.average(y, weights=w))) / np.sum(w * dx * dx))
    return SizeScaling(exponent=round(slope, 4), reference_area_m2=round(float(np.exp(x_ref)), 1))


DENSITY_EXPONENT_LIMITS = (-0.5, 0.0)
"""Range of the fitted slope of log rooms per hectare over log floor area. A larger building
does not have fewer rooms (slope above -1 at least), and its rooms grow at most as the square
root of its floor area, as the shared real schools' do (-0.50); the shared offices span too
narrow a range of sizes (1,000-3,800 m2) to pin the slope (-1.18 fitted), and a steeper one
would make a 10,000 m2 twin of rooms four times too large."""

OUTLIER_MADS = 3.0
"""Plans further than this many robust standard deviations (1.4826 median absolute deviations)
from the density line are left out of it: a plan drawn at the wrong scale (the shared
dentist's office: 27 rooms per hectare, 25 rooms on 9,261 m2) is not a habit of the type."""


def _footprint_habits(plans: list[Building]) -> FootprintHabits:
    """The plans' footprint aspect ratios (geometric mean, log spread) and composed share.

    None under 3 plans.
    """
    from realistic_indoor.building.footprint import aspect_ratio, footprint, footprint_fill

    shapes = [(b, footprint(b)) for b in plans if b.rooms]
    if len(shapes) < 3:
        return FootprintHabits()
    logs = [math.log(min(aspect_ratio(shape), 20.0)) for _, shape in shapes]
    composed = [footprint_fill(b, shape) < COMPOSED_FILL for b, shape in shapes]
    return FootprintHabits(
        aspect_median=round(max(math.exp(float(np.mean(logs))), 1.0), 4),
        aspect_spread=round(min(float(np.std(logs, ddof=1)), 3.0), 4),
        composed_share=round(float(np.mean(composed)), 4),
    )


def _room_density(plans: list[Building]) -> RoomDensity:
    """The line of log rooms per hectare on log floor area through the plans, and their spread.

    One point per plan. The slope is the least-squares slope limited to
    :data:`DENSITY_EXPONENT_LIMITS`, the reference area the plans' geometric mean floor area,
    and the line's density there the median of the plans' densities brought to that area along
    the slope (a median: the plans' densities are skewed, and the validator compares medians).
    Plans further than :data:`OUTLIER_MADS` from the line through all plans are left out, and
    the test is made once more against the line through those kept. The spread
    is the residual standard deviation of the plans kept (two degrees of freedom taken).
    Fewer than three plans, or plans all of one size, give no density.
    """
    points = [(math.log(b.area), math.log(len(b.rooms) * 10_000.0 / b.area)) for b in plans if b.area > 0]
    if len(points) < 3 or len({x for x, _ in points}) < 2:
        return RoomDensity()
    x, y = (np.array(v) for v in zip(*points, strict=True))
    keep = np.ones(len(x), dtype=bool)
    for _ in range(2):
        x_ref, y_ref, slope = _density_line(x[keep], y[keep])
        residual = y - y_ref - slope * (x - x_ref)
        mad = 1.4826 * float(np.median(np.abs(residual[keep] - np.median(residual[keep]))))
        if mad > 0 and np.sum(np.abs(residual) <= OUTLIER_MADS * mad) >= 3:
            keep = np.abs(residual) <= OUTLIER_MADS * mad
    x_ref, _mean, slope = _density_line(x[keep], y[keep])
    y_ref = float(np.median(y[keep] - slope * (x[keep] - x_ref)))
    residual = y[keep] - y_ref - slope * (x[keep] - x_ref)
    spread = float(np.sqrt(np.sum(residual**2) / (len(residual) - 2))) if len(residual) > 2 else 0.0
    return RoomDensity(
        per_hectare=round(float(np.exp(y_ref)), 3),
        reference_area_m2=round(float(np.exp(x_ref)), 1),
        exponent=round(slope, 4),
        spread=round(min(spread, 3.0), 4),
    )


def _density_line(x: np.ndarray, y: np.ndarray) -> tuple[float, float, float]:
    """Mean point and least-squares slope (limited) of ``y`` on ``x``; slope 0 when ``x`` is constant."""
    x_ref, y_ref = float(x.mean()), float(y.mean())
    spread_x = float(np.sum((x - x_ref) ** 2))
    slope = float(np.sum((x - x_ref) * (y - y_ref)) / spread_x) if spread_x > 0 else 0.0
    low, high = DENSITY_EXPONENT_LIMITS
    return x_ref, y_ref, min(max(slope, low), high)


NO_FURTHER_DOORS = 0.05
"""Further doors per ordinary room under which a plan counts as giving every room one door."""


def _door_habits(plans: list[Building]) -> DoorHabits:
    """Share of plans whose ordinary rooms have one door each, and the others' mean further doors.

    Plans with fewer than three ordinary rooms say little about habits and are left out; fewer
    than three plans left give no habits.
    """
    rates = []
    for b in plans:
        doors = [len(b.doors_of[r.id]) for r in b.rooms if r.label in ROOM_LABELS]
        if len(doors) >= 3:
            rates.append(float(np.mean(doors)) - 1.0)
    if len(rates) < 3:
        return DoorHabits()
    some = [r for r in rates if r >= NO_FURTHER_DOORS]
    none_share = 1.0 - len(some) / len(rates)
    return DoorHabits(round(none_share, 4), round(float(np.mean(some)), 4) if some else 0.0)


def _target(b: Building, rid: str, door) -> str:
    other = door.other(rid)
    return OUTSIDE if other is None or other not in b.room_by_id else b.room(other).label.value


def _fractions(counts: dict[SemanticLabel, Counter]) -> dict[SemanticLabel, dict[str, float]]:
    """Each label's counts as fractions of its total (labels without any are left out)."""
    out = {}
    for lab, c in counts.items():
        total = sum(c.values())
        if total:
            out[lab] = {k: v / total for k, v in sorted(c.items())}
    return out


def _connections(plans: list[Building]) -> dict[SemanticLabel, dict[str, float]]:
    counts: dict[SemanticLabel, Counter] = {lab: Counter() for lab in SemanticLabel}
    for b in plans:
        for r in b.rooms:
            for d in b.doors_of[r.id]:
                counts[r.label][_target(b, r.id, d)] += 1
    return _fractions(counts)


def _functions(plans: list[Building]) -> dict[SemanticLabel, dict[str, float]]:
    counts: dict[SemanticLabel, Counter] = {lab: Counter() for lab in SemanticLabel}
    for b in plans:
        for r in b.rooms:
            counts[r.label][normalise_function(r.function)] += 1
    return _fractions(counts)


def _structures(plans: list[Building]) -> LocalStructures:
    """How often each recurring local structure occurs (see :class:`LocalStructures`)."""
    default = LocalStructures()
    closets = medium_big = paired = small = clustered = halls = junction = 0
    for b in plans:
        labels = {r.id: r.label for r in b.rooms}
        for r in b.rooms:
            targets = [labels.get(d.other(r.id)) for d in b.doors_of[r.id]]
            if r.label in (SemanticLabel.MEDIUM, SemanticLabel.BIG):
                medium_big += 1
                paired += any(t in (SemanticLabel.MEDIUM, SemanticLabel.BIG) for t in targets)
            elif r.label is S:
                small += 1
                closets += bool(targets) and all(t in ROOM_LABELS for t in targets)
                clustered += _in_cluster(b, r.id, labels)
            elif r.label is H:
                halls += 1
                junction += sum(t is C for t in targets) >= 3
    return LocalStructures(
        closets_per_room=closets / medium_big if medium_big else default.closets_per_room,
        connected_room_pairs=paired / medium_big if medium_big else default.connected_room_pairs,
        clustered_small_rooms=clustered / small if small else default.clustered_small_rooms,
        junction_halls=junction / halls if halls else default.junction_halls,
        ring_share=round(float(np.mean([circulation_loops(b) > 0 for b in plans])), 4),
    )


def _in_cluster(b: Building, rid: str, labels: dict[str, SemanticLabel]) -> bool:
    """Whether a small room opens onto a corridor or hall that two other small rooms open onto."""
    for d in b.doors_of[rid]:
        hub = d.other(rid)
        if hub is None or labels.get(hub) not in (C, H):
            continue
        others = {d2.other(hub) for d2 in b.doors_of[hub]} - {rid, None}
        if sum(labels.get(o) is S for o in others) >= 2:
            return True
    return False
