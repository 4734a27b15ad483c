"""A classifier two-sample test: can a simple model tell buildings of set A from set B?

Each building becomes a vector of per-label and connectivity statistics
(:func:`building_features`; by default without the areas, which depend on the plan's often
unreliable scale); a standardised logistic regression is trained to tell the sets
apart under repeated stratified cross-validation. The reported balanced accuracy is 0.5 when
the sets are indistinguishable to it and 1.0 when they are perfectly separable; balanced
accuracy (the mean of the recalls of both sets) keeps a large set against a small one from
looking separable just by always guessing the larger.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import TYPE_CHECKING

import numpy as np

from realistic_indoor.building.labels import SemanticLabel
from realistic_indoor.errors import ConfigError
from realistic_indoor.validator.connectivity import CONNECTIVITY_METRICS, connectivity
from realistic_indoor.validator.tables import label_table

if TYPE_CHECKING:
    from collections.abc import Sequence

    from sklearn.pipeline import Pipeline

    from realistic_indoor.building.building import Building

__all__ = [
    "BUILDING_FEATURE_NAMES",
    "FEATURE_GROUPS",
    "FEATURE_NAMES",
    "SCALE_FREE",
    "TwoSampleResult",
    "building_features",
    "building_level_features",
    "feature_matrix",
    "group_matrix",
    "split_half_accuracy",
    "two_sample_test",
]

_SHARE_METRICS = tuple(m for m in CONNECTIVITY_METRICS if m.unit == "%")

FEATURE_NAMES: tuple[str, ...] = (
    *(f"{lab.value} share" for lab in SemanticLabel),
    *(f"{lab.value} doorways" for lab in SemanticLabel),
    *(f"{lab.value} log area" for lab in SemanticLabel),
    *(f"{lab.value} axes ratio" for lab in SemanticLabel),
    *(m.title for m in _SHARE_METRICS),
)
"""Names of the building-level features, in vector order. Sizes of whole buildings (room count,
floor area, path lengths) are left out: they say how big a building is, not how it is built."""

SCALE_FREE = np.array(["log area" not in name for name in FEATURE_NAMES])
"""Mask of the features that do not depend on the plan's scale (all but the areas): real plans'
scales are often unreliable, so the two-sample test leaves areas out unless asked."""

BUILDING_FEATURE_NAMES: tuple[str, ...] = (
    "footprint fill",
    "isoperimetric quotient",
    "log aspect ratio",
    "circulation share",
    "door depth / sqrt(rooms)",
    "leaf share",
    "log rooms per hectare",
)
"""Names of the building-level features (from
:func:`~realistic_indoor.validator.building_measures.building_measures`), in vector order: a
compact probe of how a plan is organised (its shape, its circulation, how deep and how branched
its door graph is, and how finely its floor is divided). Seven features rather than every
measure: with 15 to 40 plans a set, a classifier over many features stays near chance under
cross-validation whatever the sets look like (docs/validator.md gives the figures). The room
density is a scale-dependent feature, kept because a plan cut into too many or too few rooms
is the plainest sign of a made-up one; a plan whose scale is wrong is flagged by
:func:`~realistic_indoor.models.scale.scale_check` before it is compared."""

FEATURE_GROUPS = ("room", "building", "all")
"""Feature groups a two-sample test can use: the room statistics of Table 1 and connectivity
(:data:`FEATURE_NAMES`), the building-level measures (:data:`BUILDING_FEATURE_NAMES`), or all."""


def building_features(b: Building) -> np.ndarray:
    """The building-level feature vector (see :data:`FEATURE_NAMES`).

    Label shares are fractions; per label the mean doorways, log of the mean area (m2) and
    mean axes ratio; the connectivity shares as fractions. A statistic with nothing to
    measure (no room of a label, no core room) is 0.
    """
    table = label_table([b])
    values = [table[lab]["share_pct"] / 100 for lab in SemanticLabel]
    values += [table[lab]["doors_mean"] for lab in SemanticLabel]
    values += [
        math.log(table[lab]["area_mean"]) if table[lab]["area_mean"] > 0 else math.nan
        for lab in SemanticLabel
    ]
    values += [table[lab]["axes_ratio_mean"] for lab in SemanticLabel]
    conn = connectivity(b).metrics()
    values += [conn[m.key] / 100 for m in _SHARE_METRICS]
    return np.nan_to_num(np.asarray(values, dtype=float), nan=0.0, posinf=0.0, neginf=0.0)


def building_level_features(b: Building) -> np.ndarray:
    """The building-level feature vector (see :data:`BUILDING_FEATURE_NAMES`); ``nan`` becomes 0."""
    from realistic_indoor.validator.building_measures import building_measures

    m = building_measures(b)
    values = (
        m.footprint_fill,
        m.isoperimetric_quotient,
        math.log(m.aspect_ratio),
        m.circulation_share,
        m.door_depth_norm,
        m.leaf_share,
        math.log(m.rooms_per_hectare),
    )
    return np.nan_to_num(np.asarray(values, dtype=float), nan=0.0, posinf=0.0, neginf=0.0)


def group_matrix(
    buildings: Sequence[Building], features: str, with_area: bool
) -> tuple[np.ndarray, list[str]]:
    """Feature vectors of a feature group as rows, and the names of their columns.

    Args:
        buildings: The buildings.
        features: ``"room"``, ``"building"`` or ``"all"`` (see :data:`FEATURE_GROUPS`).
        with_area: Keep the room-level features that depend on the plan's scale (the
            building level always has its room density, see :data:`BUILDING_FEATURE_NAMES`).

    Raises:
        ConfigError: For an unknown group.
    """
    if features not in FEATURE_GROUPS:
        raise ConfigError(f"unknown feature group {features!r}; groups: {', '.join(FEATURE_GROUPS)}")
    blocks, names = [], []
    if features in ("room", "all"):
        keep = np.ones(len(FEATURE_NAMES), dtype=bool) if with_area else SCALE_FREE
        blocks.append(feature_matrix(buildings)[:, keep])
        names += [n for n, k in zip(FEATURE_NAMES, keep, strict=True) if k]
    if features in ("building", "all"):
        rows = [building_level_features(b) for b in buildings]
        blocks.append(np.stack(rows) if rows else np.zeros((0, len(BUILDING_FEATURE_NAMES))))
        names += list(BUILDING_FEATURE_NAMES)
    return np.hstack(blocks), names


def feature_matrix(buildings: Sequence[Building]) -> np.ndarray:
    """Feature vectors of ``buildings`` as rows, shape ``(len(buildings), len(FEATURE_NAMES))``."""
    return (
        np.stack([building_features(b) for b in buildings])
        if buildings
        else np.zeros((0, len(FEATURE_NAMES)))
    )


@dataclass(frozen=True)
class TwoSampleResult:
    """Outcome of a two-sample test.

    Attributes:
        name_a: Name of the first set.
        name_b: Name of the second set.
        n_a: Buildings in the first set.
        n_b: Buildings in the second set.
        accuracy: Mean cross-validated balanced accuracy (0.5 = indistinguishable, 1 = separable).
        accuracy_std: Its standard deviation over the folds.
        folds: Number of train/test splits.
        telling_features: The features that separate the sets most (largest standardised
            coefficients of the model fitted on all buildings), with the sign: positive means
            higher in set B.
        features: The feature group used (see :data:`FEATURE_GROUPS`).
    """

    name_a: str
    name_b: str
    n_a: int
    n_b: int
    accuracy: float
    accuracy_std: float
    folds: int
    telling_features: tuple[tuple[str, float], ...]
    features: str = "room"

    def to_dict(self) -> dict:
        """Plain data."""
        return asdict(self)

    def sentence(self) -> str:
        """The result in words."""
        top = ", ".join(name for name, _c in self.telling_features) or "none"
        return (
            f"{self.name_a} vs {self.name_b}: balanced accuracy {self.accuracy:.2f} +/- {self.accuracy_std:.2f} "
            f"on {self.features} features ({self.folds} folds; 0.5 = indistinguishable); most telling: {top}"
        )


def two_sample_test(
    a: Sequence[Building],
    b: Sequence[Building],
    *,
    names: tuple[str, str] = ("A", "B"),
    seed: int = 0,
    n_splits: int = 5,
    n_repeats: int = 20,
    top: int = 3,
    with_area: bool = False,
    features: str = "room",
) -> TwoSampleResult:
    """Cross-validated accuracy of a logistic regression telling ``a`` from ``b``.

    Args:
        a: First set of buildings (at least 2).
        b: Second set of buildings (at least 2).
        names: Names of the two sets, for the report.
        seed: Seed of the fold shuffling (the result is deterministic given it).
        n_splits: Folds per repeat (reduced to the size of the smaller set).
        n_repeats: Repeats of the cross-validation with different shuffles.
        top: How many telling features to report.
        with_area: Also use the rooms' areas in the room-level features (by default only
            the scale-free ones, see :data:`SCALE_FREE`).
        features: The feature group: ``"room"`` (Table 1 and connectivity), ``"building"``
            (building-level measures) or ``"all"``.

    Raises:
        ConfigError: If a set has fewer than two buildings.
    """
    if min(len(a), len(b)) < 2:
        raise ConfigError(
            f"the two-sample test needs at least 2 buildings per set; "
            f"{names[0]!r} has {len(a)}, {names[1]!r} has {len(b)}"
        )
    x_a, names_used = group_matrix(a, features, with_area)
    x = np.vstack([x_a, group_matrix(b, features, with_area)[0]])
    y = np.r_[np.zeros(len(a), dtype=int), np.ones(len(b), dtype=int)]
    scores = _cross_validated(x, y, seed, n_splits, n_repeats)
    model = _classifier()
    coefs = model.fit(x, y)[-1].coef_[0]
    order = np.argsort(-np.abs(coefs), kind="stable")[:top]
    telling = tuple((names_used[i], float(coefs[i])) for i in order if abs(coefs[i]) > 1e-9)
    return TwoSampleResult(
        names[0],
        names[1],
        len(a),
        len(b),
        float(scores.mean()),
        float(scores.std()),
        len(scores),
        telling,
        features,
    )


def split_half_accuracy(
    buildings: Sequence[Building],
    *,
    features: str = "building",
    seed: int = 0,
    splits: int = 20,
    n_splits: int = 5,
    n_repeats: int = 5,
    with_area: bool = False,
) -> tuple[float, float]:
    """The two-sample test's accuracy on one set cut at random into two halves: its floor.

    Two halves of one set of real plans come from one population, so whatever the classifier
    scores on them above 0.5 is what small samples and many features give by chance; a set of
    generated buildings cannot be expected to score lower against the real ones.

    Args:
        buildings: The set (at least 4 buildings).
        features: The feature group (see :data:`FEATURE_GROUPS`).
        seed: Seed of the halvings and of the folds.
        splits: Random halvings to average over.
        n_splits: Folds per cross-validation.
        n_repeats: Repeats of each cross-validation.
        with_area: As in :func:`two_sample_test`.

    Returns:
        The mean balanced accuracy over the halvings and its standard deviation.

    Raises:
        ConfigError: If the set has fewer than 4 buildings.
    """
    if len(buildings) < 4:
        raise ConfigError(f"a split-half test needs at least 4 buildings; the set has {len(buildings)}")
    x = group_matrix(buildings, features, with_area)[0]
    rng = np.random.default_rng(seed)
    runs = []
    for k in range(splits):
        y = np.zeros(len(buildings), dtype=int)
        y[rng.permutation(len(buildings))[: len(buildings) // 2]] = 1
        runs.append(_cross_validated(x, y, seed + k, n_splits, n_repeats).mean())
    return float(np.mean(runs)), float(np.std(runs))


def _classifier() -> Pipeline:
    """The standardised, class-balanced logistic regression (C = 1) of the two-sample tests."""
    from sklearn.linear_model import LogisticRegression
    from sklearn.pipeline import make_pipeline
    from sklearn.preprocessing import StandardScaler

    return make_pipeline(StandardScaler(), LogisticRegression(C=1.0, max_iter=2000, class_weight="balanced"))


def _cross_validated(x: np.ndarray, y: np.ndarray, seed: int, n_splits: int, n_repeats: int) -> np.ndarray:
    """Balanced accuracies of :func:`_classifier` over repeated stratified k-fold splits."""
    from sklearn.model_selection import RepeatedStratifiedKFold, cross_val_score

    smaller = int(min(np.sum(y == 0), np.sum(y == 1)))
    cv = RepeatedStratifiedKFold(n_splits=min(n_splits, smaller), n_repeats=n_repeats, random_state=seed)
    return cross_val_score(_classifier(), x, y, cv=cv, scoring="balanced_accuracy")
