"""A building-type model: what the generator samples rooms, doors and functions from."""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field, replace
from functools import cache, lru_cache
from importlib import resources
from typing import TYPE_CHECKING, Any

from realistic_indoor.building.labels import BuildingType, SemanticLabel, parse_building_type, parse_label
from realistic_indoor.checks import require_between
from realistic_indoor.errors import ConfigError

if TYPE_CHECKING:
    from collections.abc import Mapping

    import numpy as np

__all__ = [
    "COMPOSED_FILL",
    "REAL_MODEL_TYPES",
    "BuildingTypeModel",
    "DoorHabits",
    "FootprintHabits",
    "LabelStats",
    "LocalStructures",
    "RoomDensity",
    "SizeScaling",
    "default_model",
    "real_model",
]


_LABEL_STATS_RANGES = (
    ("share", 0.0, 1.0),
    ("area_mean", 0.0, 100_000.0),
    ("area_std", 0.0, 100_000.0),
    ("doors_mean", 0.0, 1_000.0),
    ("doors_std", 0.0, 1_000.0),
    ("axes_ratio_mean", 0.0, 1_000.0),
    ("axes_ratio_std", 0.0, 1_000.0),
)
"""Plausible range of each field of :class:`LabelStats` (NaN and infinities are refused)."""


@dataclass(frozen=True)
class LabelStats:
    """Statistics of the rooms of one semantic label (one row of the paper's Table 1).

    Attributes:
        share: Fraction of the building's rooms with this label (0-1).
        area_mean: Mean floor area, m2.
        area_std: Standard deviation of the area, m2.
        doors_mean: Mean number of doorways (exterior ones included).
        doors_std: Standard deviation of the number of doorways.
        axes_ratio_mean: Mean ratio of the bounding box's major to minor side (>= 1).
        axes_ratio_std: Standard deviation of the axes ratio.

    Every field is a finite number within :data:`_LABEL_STATS_RANGES` (areas up to 100,000 m2,
    door counts and axes ratios up to 1,000); a model file with other values is refused.
    """

    share: float
    area_mean: float
    area_std: float
    doors_mean: float
    doors_std: float
    axes_ratio_mean: float
    axes_ratio_std: float

    def __post_init__(self) -> None:
        for name, low, high in _LABEL_STATS_RANGES:
            value = getattr(self, name)
            ok = isinstance(value, (int, float)) and not isinstance(value, bool) and low <= value <= high
            if not ok:
                raise ConfigError(f"LabelStats.{name} must be a number in [{low:g}, {high:g}], got {value!r}")

    def sample_area(self, rng: np.random.Generator, low: float = 0.0, high: float = math.inf) -> float:
        """An area drawn from a log-normal with this mean and standard deviation, clipped (m2)."""
        return float(min(max(_lognormal(rng, self.area_mean, self.area_std), low), high))


@dataclass(frozen=True)
class LocalStructures:
    """How often the recurring local structures of a building type occur (fractions 0-1).

    Attributes:
        closets_per_room: Small rooms entered only through a medium or big room (closets,
            storage inside an office), per medium or big room.
        connected_room_pairs: Share of medium and big rooms with a door to another medium or
            big room (connecting doors between neighbouring rooms).
        clustered_small_rooms: Share of small rooms that open onto the same corridor or hall as
            at least two other small rooms (service cores: toilets, storage, stairs together).
        junction_halls: Share of halls with doors to three or more corridors (halls at corridor
            junctions rather than at the end of one corridor).
        ring_share: Share of buildings whose corridors and halls close at least one loop (a
            ring round a core); 1 leaves the choice to the layout's proportions.
    """

    closets_per_room: float = 0.08
    connected_room_pairs: float = 0.08
    clustered_small_rooms: float = 0.6
    junction_halls: float = 0.4
    ring_share: float = 1.0


@dataclass(frozen=True)
class DoorHabits:
    """How many doors beyond the first the ordinary rooms of one building have, building by building.

    Buildings of one type differ in this more than in anything else the real plans show: a
    third of the shared real schools give every room one door, others connect neighbouring
    classrooms and stores throughout. A pooled mean door count gives every generated building
    the same middling habit; a model with habits draws each building's own rate: none with
    probability :attr:`none_share`, else exponentially distributed with mean :attr:`mean_rate`.

    Attributes:
        none_share: Share of buildings whose ordinary rooms (small, medium, big) have one door
            each (under 0.05 further doors per room).
        mean_rate: Mean further doors per ordinary room over the other buildings; 0 for no
            habits (the pooled per-label door counts alone).
    """

    none_share: float = 0.0
    mean_rate: float = 0.0

    def draw(self, rng: np.random.Generator) -> float:
        """One building's further doors per ordinary room (at most 2)."""
        if rng.random() < self.none_share:
            return 0.0
        return float(min(rng.exponential(self.mean_rate), 2.0))


@dataclass(frozen=True)
class SizeScaling:
    """How room sizes grow with the building's floor area.

    Real buildings of one type do not keep their rooms' sizes as they grow: in the shared real
    schools every label's mean area grows about as the square root of the floor area (larger
    schools have larger classrooms, halls and gyms), so rooms per hectare fall. A model with a
    scaling multiplies every label's mean and standard deviation of area by
    ``(area_m2 / reference_area_m2) ** exponent``, clipped to ``[low, high]``.

    Attributes:
        exponent: Growth of room areas with floor area (log-log slope); 0 for none.
        reference_area_m2: Floor area at which the label statistics hold unscaled (m2).
        low: Smallest factor applied.
        high: Largest factor applied.
    """

    exponent: float = 0.0
    reference_area_m2: float = 1000.0
    low: float = 0.5
    high: float = 2.0

    def factor(self, area_m2: float) -> float:
        """The factor on room areas for a building of ``area_m2`` (1 without scaling).

        Examples:
            >>> SizeScaling(0.5, 1000.0).factor(4000.0)
            2.0
            >>> SizeScaling(0.5, 1000.0).factor(100.0)
            0.5
        """
        if self.exponent == 0.0:
            return 1.0
        return float(min(max((area_m2 / self.reference_area_m2) ** self.exponent, self.low), self.high))


@dataclass(frozen=True)
class RoomDensity:
    """How finely real plans of a type divide their floor: rooms per hectare against floor area.

    Fitted plan by plan (:func:`~realistic_indoor.models.fit_model`): the least-squares line of
    log rooms per hectare on log floor area, and the spread of the plans about it. Pooled room
    statistics count every room once, so the plans with many small rooms weigh most in a
    label's mean area and a generator following them divides the floor more finely than the
    typical plan (19% more rooms per hectare than the median shared real office). A model
    with a density sizes each building's rooms for a density drawn for it, so buildings of
    one size differ as much as the plans do.

    Attributes:
        per_hectare: Rooms per hectare on the line at :attr:`reference_area_m2`; 0 for none
            (the paper's tables, which give one mean area per label).
        reference_area_m2: Floor area where the line gives :attr:`per_hectare` (m2).
        exponent: Slope of log rooms per hectare over log floor area (negative: larger
            buildings have larger rooms).
        spread: Standard deviation of the plans' log rooms per hectare about the line.
    """

    per_hectare: float = 0.0
    reference_area_m2: float = 1000.0
    exponent: float = 0.0
    spread: float = 0.0

    def __post_init__(self) -> None:
        require_between("RoomDensity", "per_hectare", self.per_hectare, 0.0, 10_000.0, "rooms/ha")
        require_between(
            "RoomDensity", "reference_area_m2", self.reference_area_m2, 0.0, 1e7, "m2", low_open=True
        )
        require_between("RoomDensity", "exponent", self.exponent, -3.0, 3.0, "")
        require_between("RoomDensity", "spread", self.spread, 0.0, 3.0, "")

    def at(self, area_m2: float) -> float:
        """Rooms per hectare on the line for a building of ``area_m2``.

        Examples:
            >>> RoomDensity(200.0, 1000.0, -0.5).at(4000.0)
            100.0
        """
        return float(self.per_hectare * (area_m2 / self.reference_area_m2) ** self.exponent)

    def draw(self, rng: np.random.Generator, area_m2: float) -> float:
        """One building's rooms per hectare: the line's, times a log-normal spread (within 2 sigma)."""
        deviation = _within_two_sigma(rng) * self.spread if self.spread > 0 else 0.0
        return self.at(area_m2) * math.exp(deviation)


COMPOSED_FILL = 0.9
"""Convex fill below which a footprint counts as composed (wings, an L, T or U) rather than one
block: the block layout's single blocks, steps and notches included, keep 0.86 or more."""


@dataclass(frozen=True)
class FootprintHabits:
    """How elongated the footprints of real plans of a type are: their aspect ratios, plan by plan.

    The aspect ratio is the long over the short side of the smallest rectangle around the
    footprint (:func:`~realistic_indoor.building.footprint.aspect_ratio`); fitted as a
    log-normal (:func:`~realistic_indoor.models.fit_model`). A layout that draws each
    building's proportions from it makes bars as often as the type's real plans are bars, not
    only the square blocks that pack a floor area most easily.

    Attributes:
        aspect_median: Geometric mean aspect ratio of the plans (>= 1); 0 for none (the
            layout's own range).
        aspect_spread: Standard deviation of the plans' log aspect ratios.
        composed_share: Share of the plans whose footprint is not one compact block: convex
            fill (floor over convex hull area) below :data:`COMPOSED_FILL`, as an L, T, U or a
            cluster of wings has; -1 for none (the layout's own frequencies).
    """

    aspect_median: float = 0.0
    aspect_spread: float = 0.0
    composed_share: float = -1.0

    def __post_init__(self) -> None:
        if self.aspect_median != 0.0:
            require_between("FootprintHabits", "aspect_median", self.aspect_median, 1.0, 20.0, "")
        require_between("FootprintHabits", "aspect_spread", self.aspect_spread, 0.0, 3.0, "")
        if self.composed_share != -1.0:
            require_between("FootprintHabits", "composed_share", self.composed_share, 0.0, 1.0, "")

    def draw_aspect(self, rng: np.random.Generator) -> float:
        """One building's aspect ratio: log-normal about the median, within 2 sigma, at least 1."""
        return max(self.aspect_median * math.exp(_within_two_sigma(rng) * self.aspect_spread), 1.0)


def _within_two_sigma(rng: np.random.Generator) -> float:
    """A standard normal draw clipped to [-2, 2]: how far one building lies from its type's line."""
    return min(max(float(rng.normal(0.0, 1.0)), -2.0), 2.0)


DENSITY_FACTOR_LIMITS = (0.25, 4.0)
"""Range of the factor on room areas that a drawn room density may ask for."""


@dataclass(frozen=True)
class BuildingTypeModel:
    """Statistics of one building type, from the paper's tables or fitted to real plans.

    Attributes:
        name: The type's name (``"office"``, ``"school"``, ``"house"``, or a user's ``"hospital"``).
        labels: Statistics of each semantic label (every label present).
        connections: Per semantic label, the fraction of its doorways that lead to rooms of each
            label (keys are label values, plus :data:`~realistic_indoor.building.labels.OUTSIDE` for exterior doors).
        functions: Per semantic label, the relative frequency of each functional label.
        structures: Frequencies of the recurring local structures.
        source: Where the numbers come from, in words.
        size_scaling: How room areas grow with the floor area (:meth:`at_area`); none for the
            paper's tables, which give one mean per label.
        door_habits: How buildings differ in further doors per room; none for the paper's
            tables (every building then follows the pooled per-label door counts).
        density: Rooms per hectare by floor area (:class:`RoomDensity`); where given, it sizes
            the rooms of each building in place of :attr:`size_scaling`.
        footprint: The plans' aspect ratios (:class:`FootprintHabits`); where given, the block
            layout draws each building's proportions from them.
    """

    name: str
    labels: Mapping[SemanticLabel, LabelStats]
    connections: Mapping[SemanticLabel, Mapping[str, float]]
    functions: Mapping[SemanticLabel, Mapping[str, float]]
    structures: LocalStructures = field(default_factory=LocalStructures)
    source: str = ""
    size_scaling: SizeScaling = field(default_factory=SizeScaling)
    door_habits: DoorHabits = field(default_factory=DoorHabits)
    density: RoomDensity = field(default_factory=RoomDensity)
    footprint: FootprintHabits = field(default_factory=FootprintHabits)

    def __post_init__(self) -> None:
        missing = [lab.value for lab in SemanticLabel if lab not in self.labels]
        if missing:
            raise ConfigError(f"model {self.name!r} has no statistics for {', '.join(missing)}")
        if sum(s.share for s in self.labels.values()) <= 0:
            raise ConfigError(f"model {self.name!r}: label shares must not all be zero")

    @property
    def building_type(self) -> BuildingType:
        """The :class:`BuildingType` named by :attr:`name` (``UNKNOWN`` for other types)."""
        try:
            return parse_building_type(self.name)
        except ConfigError:
            return BuildingType.UNKNOWN

    def stats(self, label: SemanticLabel | str) -> LabelStats:
        """Statistics of one semantic label."""
        return self.labels[parse_label(label)]

    def shares(self) -> dict[SemanticLabel, float]:
        """Label shares normalised to sum to one."""
        total = sum(s.share for s in self.labels.values())
        return {lab: self.labels[lab].share / total for lab in SemanticLabel}

    def mean_room_area(self) -> float:
        """Expected floor area per room over all labels, m2 (total area / number of rooms)."""
        return sum(p * self.labels[lab].area_mean for lab, p in self.shares().items())

    def at_area(self, area_m2: float, rng: np.random.Generator | None = None) -> BuildingTypeModel:
        """The model for a building of ``area_m2``, its room areas scaled.

        With a :attr:`density`, every label's mean and standard deviation of area are scaled so
        the mean room area gives the building's rooms per hectare: drawn with ``rng``
        (:meth:`RoomDensity.draw`), or the line's without it. Otherwise by :attr:`size_scaling`.
        Returns the model itself when the factor is 1.
        """
        if self.density.per_hectare > 0:
            per_hectare = self.density.draw(rng, area_m2) if rng is not None else self.density.at(area_m2)
            low, high = DENSITY_FACTOR_LIMITS
            f = min(max(10_000.0 / (per_hectare * self.mean_room_area()), low), high)
        else:
            f = self.size_scaling.factor(area_m2)
        if f == 1.0:
            return self
        labels = {
            lab: replace(s, area_mean=s.area_mean * f, area_std=s.area_std * f)
            for lab, s in self.labels.items()
        }
        return replace(self, labels=labels)

    def connection(self, label: SemanticLabel, target: str) -> float:
        """Fraction of the doorways of ``label`` rooms that lead to ``target`` (a label value or ``outside``)."""
        return float(self.connections.get(label, {}).get(target, 0.0))

    def function_weights(self, label: SemanticLabel) -> dict[str, float]:
        """Functional labels of ``label`` rooms with their weights (``{label value: 1}`` if unknown)."""
        weights = {k: float(v) for k, v in self.functions.get(label, {}).items() if v > 0}
        return weights or {label.value: 1.0}

    def table(self) -> dict[SemanticLabel, dict[str, float]]:
        """The model as a Table-1 style dict (keys of :func:`realistic_indoor.models.reference_table`)."""
        out = {}
        for lab, s in self.labels.items():
            out[lab] = {
                "share_pct": 100.0 * self.shares()[lab],
                "area_mean": s.area_mean,
                "area_std": s.area_std,
                "doors_mean": s.doors_mean,
                "doors_std": s.doors_std,
                "axes_ratio_mean": s.axes_ratio_mean,
                "axes_ratio_std": s.axes_ratio_std,
            }
        return out

    def to_dict(self) -> dict[str, Any]:
        """The model as plain JSON-ready data (see :meth:`from_dict`)."""
        return {
            "name": self.name,
            "source": self.source,
            "labels": {lab.value: vars(s).copy() for lab, s in self.labels.items()},
            "connections": {lab.value: dict(c) for lab, c in self.connections.items()},
            "functions": {lab.value: dict(f) for lab, f in self.functions.items()},
            "structures": vars(self.structures).copy(),
            "size_scaling": vars(self.size_scaling).copy(),
            "door_habits": vars(self.door_habits).copy(),
            "density": vars(self.density).copy(),
            "footprint": vars(self.footprint).copy(),
        }

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> BuildingTypeModel:
        """Rebuild a model from :meth:`to_dict` output.

        Raises:
            ConfigError: If a field is missing or malformed.
        """
        try:
            labels = {parse_label(k): LabelStats(**v) for k, v in data["labels"].items()}
            return cls(
                name=str(data["name"]),
                labels=labels,
                connections={parse_label(k): dict(v) for k, v in data.get("connections", {}).items()},
                functions={parse_label(k): dict(v) for k, v in data.get("functions", {}).items()},
                structures=LocalStructures(**data.get("structures", {})),
                source=str(data.get("source", "")),
                size_scaling=SizeScaling(**data.get("size_scaling", {})),
                door_habits=DoorHabits(**data.get("door_habits", {})),
                density=RoomDensity(**data.get("density", {})),
                footprint=FootprintHabits(**data.get("footprint", {})),
            )
        except KeyError as e:
            raise ConfigError(
                f"malformed building-type model: no field {e}; a model file is what "
                "BuildingTypeModel.to_dict() writes (see fit_model in docs/generator.md)"
            ) from None
        except (AttributeError, TypeError) as e:
            raise ConfigError(
                f"malformed building-type model ({e}); a model file is what BuildingTypeModel.to_dict() "
                "writes (see fit_model in docs/generator.md)"
            ) from None


def _lognormal(rng: np.random.Generator, mean: float, std: float) -> float:
    """A draw from the log-normal with the given mean and standard deviation."""
    if std <= 0:
        return mean
    sigma2 = math.log1p((std / mean) ** 2)
    return float(rng.lognormal(math.log(mean) - sigma2 / 2, math.sqrt(sigma2)))


@lru_cache(maxsize=1)
def _model_data() -> dict[str, Any]:
    text = resources.files("realistic_indoor").joinpath("data/building_models.json").read_text("utf-8")
    return json.loads(text)


@cache
def default_model(building_type: str | BuildingType) -> BuildingTypeModel:
    """The model of a paper type: Table 1 of the paper plus the package's function mixes.

    Label statistics come from :func:`realistic_indoor.models.reference_table`; connections,
    functional mixes and local-structure frequencies from package data
    (``data/building_models.json``), estimated from the paper's facts and the shared real plans.

    Args:
        building_type: ``"office"``, ``"school"`` or ``"house"``.

    Raises:
        ConfigError: For any other type; the message lists the valid ones.
    """
    from realistic_indoor.models.reference import reference_table

    key = parse_building_type(building_type).value
    data = _model_data()["types"]
    if key not in data:
        raise ConfigError(f"no default model for {key!r}; valid: {', '.join(data)}")
    table = reference_table(key)
    labels = {
        lab: LabelStats(
            share=row["share_pct"] / 100.0,
            area_mean=row["area_mean"],
            area_std=row["area_std"],
            doors_mean=row["doors_mean"],
            doors_std=row["doors_std"],
            axes_ratio_mean=row["axes_ratio_mean"],
            axes_ratio_std=row["axes_ratio_std"],
        )
        for lab, row in table.items()
    }
    spec = data[key]
    return BuildingTypeModel(
        name=key,
        labels=labels,
        connections={parse_label(k): dict(v) for k, v in spec["connections"].items()},
        functions={parse_label(k): dict(v) for k, v in spec["functions"].items()},
        structures=LocalStructures(**spec["structures"]),
        source="paper Table 1 (Amigoni et al., RoboCup 2014) + package function mixes",
    )


REAL_MODEL_TYPES = ("office", "school")
"""Types with a model fitted to real plans shipped as package data (no real house plans are)."""


@cache
def real_model(building_type: str | BuildingType) -> BuildingTypeModel:
    """The model fitted to the shared real plans of a type: the generators' default for it.

    Read from package data (``data/real_models.json``, written by
    ``scripts/fit_real_models.py`` with :func:`realistic_indoor.models.fit_model` over every
    shared real plan of the type). Where the paper's Table 1 and the real plans disagree (room
    areas, hence circulation share and room density), this model follows the real plans.

    Args:
        building_type: ``"office"`` or ``"school"`` (see :data:`REAL_MODEL_TYPES`).

    Raises:
        ConfigError: For any other type; the message lists the valid ones.
    """
    key = parse_building_type(building_type).value
    if key not in REAL_MODEL_TYPES:
        raise ConfigError(f"no model fitted to real plans for {key!r}; valid: {', '.join(REAL_MODEL_TYPES)}")
    text = resources.files("realistic_indoor").joinpath("data/real_models.json").read_text("utf-8")
    return BuildingTypeModel.from_dict(json.loads(text)[key])
