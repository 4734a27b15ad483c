"""One realism score for a set of maps against a reference, and the deviations behind it, in words.

The score has three terms, each 0 when the set matches the reference and capped at
``ScoreConfig.cap`` (5) so one broken statistic cannot swamp the rest:

- **features**: for every semantic label the reference has and every feature f in (area,
  doorways, axes ratio), ``z = |mean_set - mean_ref| / max(std_ref, floor_f)``; the term is
  the plain mean of ``min(z, cap)`` over those cells. A label the set lacks scores ``cap`` on
  all three features. Floors keep nearly constant reference features (small rooms' doorways:
  1.0 +/- 0.1) from turning tiny differences into huge ones: area ``max(1 m2, 10% of the
  mean)``, doorways 0.25, axes ratio 0.25.
- **shares**: the total variation distance between the label shares of the set and of the
  reference (0..1, half the sum of absolute differences), divided by 0.1: one unit per ten
  percentage points of rooms that would have to change label.
- **connectivity**: for each connectivity metric the reference knows,
  ``|value - ref| / max(spread_ref, floor)`` with a floor of 10 percentage points for shares
  and 1 door for path lengths; the term is their mean. The paper's office reference knows two
  metrics (98% of offices touch a corridor, about 70% of rooms connect only to corridors); a
  reference fitted from real plans knows all of them.

``overall`` is the mean of the terms present. All terms are in "reference standard deviations"
(or tolerance units), so: 0 identical, below 0.5 hard to tell apart, 0.5-1 close,
1-2 visibly different, above 2 structurally different.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import TYPE_CHECKING

from realistic_indoor.building.labels import BuildingType, SemanticLabel
from realistic_indoor.validator.connectivity import CONNECTIVITY_METRICS, set_connectivity
from realistic_indoor.validator.tables import label_table

if TYPE_CHECKING:
    from collections.abc import Mapping, Sequence

    from realistic_indoor.building.building import Building
    from realistic_indoor.validator.connectivity import Connectivity
    from realistic_indoor.validator.reference import Reference

__all__ = [
    "FEATURES",
    "PLURALS",
    "Deviation",
    "RealismScore",
    "ScoreConfig",
    "realism_score",
    "score_statistics",
]

FEATURES = ("area", "doors", "axes_ratio")
"""The per-room features of Table 1, as key prefixes of its rows."""

PLURALS = {
    SemanticLabel.CORRIDOR: "corridors",
    SemanticLabel.HALL: "halls",
    SemanticLabel.SMALL: "small rooms",
    SemanticLabel.MEDIUM: "medium rooms",
    SemanticLabel.BIG: "big rooms",
}
"""How each label's rooms are named in sentences."""

_CORE_NOUNS = {
    BuildingType.OFFICE: "offices",
    BuildingType.SCHOOL: "classrooms",
    BuildingType.HOUSE: "bedrooms",
    BuildingType.UNKNOWN: "core rooms",
}


@dataclass(frozen=True)
class ScoreConfig:
    """Constants of the realism score (see the module docstring).

    Attributes:
        cap: Largest contribution of one statistic, and the score of a missing label.
        share_unit: Total variation distance worth one unit (0.1: ten percentage points).
        area_floor_m2: Smallest area spread, m2.
        area_floor_rel: Smallest area spread relative to the reference mean.
        doors_floor: Smallest doorway spread.
        axes_ratio_floor: Smallest axes-ratio spread.
        pct_floor: Smallest spread of a connectivity share, percentage points.
        path_floor_doors: Smallest spread of a path length, doors.
    """

    cap: float = 5.0
    share_unit: float = 0.1
    area_floor_m2: float = 1.0
    area_floor_rel: float = 0.1
    doors_floor: float = 0.25
    axes_ratio_floor: float = 0.25
    pct_floor: float = 10.0
    path_floor_doors: float = 1.0

    def feature_scale(self, feature: str, ref_mean: float, ref_std: float) -> float:
        """The spread a feature's deviation is divided by."""
        floor = {
            "area": max(self.area_floor_m2, self.area_floor_rel * abs(ref_mean)),
            "doors": self.doors_floor,
            "axes_ratio": self.axes_ratio_floor,
        }[feature]
        return max(ref_std if not math.isnan(ref_std) else 0.0, floor)


@dataclass(frozen=True)
class Deviation:
    """How far one statistic of the set is from the reference.

    Attributes:
        kind: ``"feature"``, ``"share"`` or ``"connectivity"``.
        subject: A label (``"corridor"``) or a connectivity metric key.
        feature: ``"area"``, ``"doors"``, ``"axes_ratio"``, ``"missing"`` (the set has no room of
            that label), ``"share_pct"`` or the metric key.
        value: The set's value (NaN if the set has nothing to measure; for ``feature ==
            "missing"``, a label the set lacks, its share 0).
        ref_mean: The reference value.
        ref_std: The reference spread (NaN if unknown).
        z: ``|value - ref_mean| / scale``, capped (the cap if ``value`` is NaN).
        sentence: The deviation in words.
    """

    kind: str
    subject: str
    feature: str
    value: float
    ref_mean: float
    ref_std: float
    z: float
    sentence: str


@dataclass(frozen=True)
class RealismScore:
    """The realism score of a set of maps against a reference (see the module docstring).

    Attributes:
        overall: Mean of the terms present; 0 means identical to the reference.
        features: Mean capped normalised deviation of area, doorways and axes ratio per label.
        shares: Total variation distance of label shares over ``share_unit``, capped.
        connectivity: Mean capped deviation of the connectivity metrics (NaN if none compared).
        tv_distance: Total variation distance between label shares (0..1).
        deviations: Every compared statistic, worst first.
    """

    overall: float
    features: float
    shares: float
    connectivity: float
    tv_distance: float
    deviations: tuple[Deviation, ...]

    def worst(self, n: int = 3) -> list[str]:
        """Sentences describing the ``n`` largest deviations."""
        return [d.sentence for d in self.deviations[:n]]

    def to_dict(self) -> dict:
        """Plain data (NaN kept as float NaN)."""
        return asdict(self)


def _fmt(x: float, digits: int = 1) -> str:
    return f"{x:.{digits}f}"


def _feature_sentence(
    label: SemanticLabel, feature: str, value: float, mean: float, std: float, ref: str
) -> str:
    subject = PLURALS[label]
    spread = f" +/- {_fmt(std)}" if not math.isnan(std) else ""
    if feature == "area":
        return f"{subject} have {_fmt(value)} m2; {ref} {_fmt(mean)}{spread} m2"
    if feature == "doors":
        return f"{subject} have {_fmt(value)} doorways; {ref} {_fmt(mean)}{spread}"
    return f"{subject} have axes ratio {_fmt(value)}; {ref} {_fmt(mean)}{spread}"


def _feature_deviations(
    table: Mapping[SemanticLabel, Mapping[str, float]], reference: Reference, cfg: ScoreConfig
) -> tuple[list[float], list[Deviation]]:
    """Capped z of every (label, feature) cell, and the deviations (one per missing label)."""
    cells, out = [], []
    for label, ref_row in reference.table.items():
        if not ref_row.get("share_pct") or math.isnan(ref_row.get("area_mean", math.nan)):
            continue
        row = table[label]
        if not row["count"]:
            cells += [cfg.cap] * len(FEATURES)
            words = (
                f"there are no {PLURALS[label]} ({_fmt(ref_row['share_pct'])}% of rooms in {reference.name})"
            )
            out.append(
                Deviation(
                    "feature", label.value, "missing", 0.0, ref_row["share_pct"], math.nan, cfg.cap, words
                )
            )
            continue
        for feature in FEATURES:
            mean, std, value = ref_row[f"{feature}_mean"], ref_row[f"{feature}_std"], row[f"{feature}_mean"]
            z = min(abs(value - mean) / cfg.feature_scale(feature, mean, std), cfg.cap)
            cells.append(z)
            words = _feature_sentence(label, feature, value, mean, std, reference.name)
            out.append(Deviation("feature", label.value, feature, value, mean, std, z, words))
    return cells, out


def _share_deviations(
    table: Mapping[SemanticLabel, Mapping[str, float]], reference: Reference, cfg: ScoreConfig
) -> tuple[float, list[Deviation]]:
    out, total = [], 0.0
    for label in SemanticLabel:
        value, ref = table[label]["share_pct"], reference.table.get(label, {}).get("share_pct", 0.0)
        total += abs(value - ref)
        words = f"{PLURALS[label]} are {_fmt(value)}% of rooms; {reference.name} {_fmt(ref)}%"
        z = min(abs(value - ref) / cfg.pct_floor, cfg.cap)
        out.append(Deviation("share", label.value, "share_pct", value, ref, math.nan, z, words))
    return total / 200.0, out


def _connectivity_deviations(conn: Connectivity, reference: Reference, cfg: ScoreConfig) -> list[Deviation]:
    values = conn.metrics()
    noun = _CORE_NOUNS[reference.building_type]
    out = []
    for m in CONNECTIVITY_METRICS:
        if m.key not in reference.connectivity:
            continue
        ref, spread = reference.connectivity[m.key], reference.connectivity_std.get(m.key, math.nan)
        floor = cfg.pct_floor if m.unit == "%" else cfg.path_floor_doors
        scale = max(0.0 if math.isnan(spread) else spread, floor)
        phrase = m.phrase.replace("core rooms", noun)
        value = values[m.key]
        digits = 0 if m.unit == "%" else 1
        unit = "%" if m.unit == "%" else ""
        if math.isnan(value):
            z, words = cfg.cap, f"nothing to measure: {m.title} ({reference.name} {_fmt(ref, digits)}{unit})"
        else:
            z = min(abs(value - ref) / scale, cfg.cap)
            words = f"{_fmt(value, digits)}{unit} {phrase}; {reference.name} {_fmt(ref, digits)}{unit}"
        out.append(Deviation("connectivity", m.key, m.key, value, ref, spread, z, words))
    return out


def _mean(values: Sequence[float]) -> float:
    return sum(values) / len(values) if values else math.nan


def score_statistics(
    table: Mapping[SemanticLabel, Mapping[str, float]],
    conn: Connectivity,
    reference: Reference,
    config: ScoreConfig = ScoreConfig(),
) -> RealismScore:
    """The realism score from precomputed statistics of a set.

    Args:
        table: The set's Table 1 (:func:`~realistic_indoor.validator.tables.label_table`).
        conn: The set's pooled connectivity.
        reference: What to compare with.
        config: Constants of the score.

    Returns:
        The score and its deviations, worst first.
    """
    cells, feats = _feature_deviations(table, reference, config)
    tv, shares = _share_deviations(table, reference, config)
    conns = _connectivity_deviations(conn, reference, config)
    terms = {
        "features": _mean(cells),
        "shares": min(tv / config.share_unit, config.cap),
        "connectivity": _mean([d.z for d in conns]),
    }
    present = [v for v in terms.values() if not math.isnan(v)]
    deviations = sorted(feats + shares + conns, key=lambda d: -d.z)
    return RealismScore(
        _mean(present), terms["features"], terms["shares"], terms["connectivity"], tv, tuple(deviations)
    )


def realism_score(
    buildings: Sequence[Building], reference: Reference, config: ScoreConfig = ScoreConfig()
) -> RealismScore:
    """How far a set of buildings is from ``reference`` (0 = identical; see the module docstring).

    Raises:
        RealisticIndoorError: If the set holds no rooms.
    """
    return score_statistics(label_table(buildings), set_connectivity(buildings), reference, config)
