"""What a set of maps is compared with: the paper's tables, or statistics fitted from real plans."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from realistic_indoor.building.labels import BuildingType, SemanticLabel, parse_building_type
from realistic_indoor.validator.connectivity import CONNECTIVITY_METRICS, Connectivity, connectivity
from realistic_indoor.validator.tables import label_table

if TYPE_CHECKING:
    from collections.abc import Sequence

    from realistic_indoor.building.building import Building

__all__ = ["Reference", "fitted_reference", "paper_reference"]

_PAPER_SETS: dict[str, tuple[str, BuildingType]] = {
    "office": ("real offices", BuildingType.OFFICE),
    "school": ("real schools", BuildingType.SCHOOL),
    "house": ("real houses", BuildingType.HOUSE),
    "all_types": ("real buildings", BuildingType.UNKNOWN),
    "robocup_2013_final_map": ("the 2013 competition map", BuildingType.OFFICE),
}
"""Name in sentences and building type of each of the paper's tables."""

_PAPER_CONNECTIVITY = {
    "office": {
        "core_touching_corridor_pct": "office_real_offices_connected_to_a_corridor_pct",
        "only_to_corridors_pct": "office_real_rooms_connected_only_to_corridors_pct",
    },
    "robocup_2013_final_map": {
        "core_touching_corridor_pct": "robocup_2013_map_offices_connected_to_a_corridor_pct",
    },
}


@dataclass(frozen=True)
class Reference:
    """Statistics of the buildings a set of maps should resemble.

    Attributes:
        name: Words for the reference in sentences (``"real offices"``).
        column: Short column title in tables (``"paper: office"``).
        building_type: The type whose core function and size thresholds apply.
        table: Table 1: per semantic label ``share_pct``, ``area_mean``/``area_std`` (m2),
            ``doors_mean``/``doors_std``, ``axes_ratio_mean``/``axes_ratio_std``.
        connectivity: Reference value of each connectivity metric it knows
            (keys of :data:`~realistic_indoor.validator.connectivity.CONNECTIVITY_METRICS`).
        connectivity_std: Spread over buildings of those metrics, where known (fitted references).
        buildings: The buildings it was fitted from (empty for the paper's tables).
    """

    name: str
    column: str
    building_type: BuildingType
    table: dict[SemanticLabel, dict[str, float]]
    connectivity: dict[str, float] = field(default_factory=dict)
    connectivity_std: dict[str, float] = field(default_factory=dict)
    buildings: tuple[Building, ...] = ()


def paper_reference(name: str | BuildingType) -> Reference:
    """The paper's Table 1 for a building type (or ``"robocup_2013_final_map"``).

    Connectivity reference values are the paper's facts: for offices 98% of offices touch a
    corridor and about 70% of rooms connect only to corridors; for the 2013 competition map,
    27% of offices touch a corridor. Other types have none.

    Raises:
        ConfigError: If there is no such table; the message lists the valid names.
    """
    from realistic_indoor.models.reference import connectivity_facts, reference_table

    table = reference_table(name)
    key = name.value if isinstance(name, BuildingType) else str(name).lower()
    key = key if key in _PAPER_SETS else parse_building_type(key).value
    facts = connectivity_facts()
    conn = {metric: facts[fact] for metric, fact in _PAPER_CONNECTIVITY.get(key, {}).items()}
    words, btype = _PAPER_SETS[key]
    return Reference(words, f"paper: {key}", btype, table, conn)


def fitted_reference(
    buildings: Sequence[Building], name: str, building_type: BuildingType | str | None = None
) -> Reference:
    """Statistics of a set of (real) plans, to compare other sets with.

    Args:
        buildings: The plans, with semantic labels (infer them first where they lack them).
        name: What they are (``"real offices"``); also the column title.
        building_type: Their type (default: the type of the first plan).

    Returns:
        A reference whose connectivity values are pooled over the set and whose spreads are the
        standard deviations of the per-building values.

    Raises:
        RealisticIndoorError: If the set holds no rooms.
    """
    table = label_table(buildings)
    t = parse_building_type(building_type if building_type is not None else buildings[0].building_type)
    per_building = [connectivity(b) for b in buildings]
    pooled = Connectivity.combine(per_building).metrics()
    spread = {}
    for m in CONNECTIVITY_METRICS:
        values = np.asarray([c.metrics()[m.key] for c in per_building], dtype=float)
        values = values[~np.isnan(values)]
        spread[m.key] = float(values.std()) if len(values) > 1 else math.nan
    conn = {k: v for k, v in pooled.items() if not math.isnan(v)}
    return Reference(name, name, t, table, conn, spread, tuple(buildings))
