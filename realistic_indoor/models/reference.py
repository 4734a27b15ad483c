"""The paper's reference statistics of real buildings (Table 1) and of the 2013 competition map."""

from __future__ import annotations

import json
from functools import lru_cache
from importlib import resources
from typing import Any

from realistic_indoor.building.labels import BuildingType, SemanticLabel, parse_building_type
from realistic_indoor.errors import ConfigError

__all__ = ["REFERENCE_SETS", "connectivity_facts", "paper_data", "reference_table"]

REFERENCE_SETS = ("office", "school", "house", "all_types", "robocup_2013_final_map")
"""Names of the statistics tables shipped with the package."""

STAT_KEYS = (
    "share_pct",
    "area_mean",
    "area_std",
    "doors_mean",
    "doors_std",
    "axes_ratio_mean",
    "axes_ratio_std",
)
"""Keys of one label's row in a statistics table."""


@lru_cache(maxsize=1)
def paper_data() -> dict[str, Any]:
    """The whole reference file (package data ``data/paper_tables.json``), parsed once."""
    text = resources.files("realistic_indoor").joinpath("data/paper_tables.json").read_text("utf-8")
    return json.loads(text)


def reference_table(name: str | BuildingType) -> dict[SemanticLabel, dict[str, float]]:
    """Table 1 of the paper for one building type (or ``"robocup_2013_final_map"``).

    Args:
        name: ``"office"``, ``"school"``, ``"house"``, ``"all_types"`` or
            ``"robocup_2013_final_map"`` (or a :class:`BuildingType`).

    Returns:
        Per semantic label: ``share_pct`` (% of rooms), ``area_mean``/``area_std`` (m2),
        ``doors_mean``/``doors_std`` (doorways per room), ``axes_ratio_mean``/``axes_ratio_std``.

    Raises:
        ConfigError: If no table has that name; the message lists the valid ones.
    """
    key = name.value if isinstance(name, BuildingType) else str(name).lower()
    if key not in REFERENCE_SETS:
        try:
            key = parse_building_type(key).value
        except ConfigError:
            key = ""
        if key not in REFERENCE_SETS:
            raise ConfigError(f"no reference table {name!r}; valid: {', '.join(REFERENCE_SETS)}")
    table = paper_data()["tables"][key]
    return {SemanticLabel(lab): {k: float(v) for k, v in row.items()} for lab, row in table.items()}


def connectivity_facts() -> dict[str, float]:
    """The paper's connectivity facts (percentages), e.g. real offices touching a corridor: 98."""
    facts = paper_data()["connectivity_facts"]
    return {k: float(v) for k, v in facts.items() if not k.startswith("_")}
