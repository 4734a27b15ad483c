"""The paper's Table 1 computed for any set of buildings."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from realistic_indoor.building.labels import SemanticLabel
from realistic_indoor.errors import RealisticIndoorError
from realistic_indoor.validator.features import all_room_features

if TYPE_CHECKING:
    from collections.abc import Iterable

    from realistic_indoor.building.building import Building

__all__ = ["label_table"]


def label_table(buildings: Iterable[Building]) -> dict[SemanticLabel, dict[str, float]]:
    """Per semantic label: share of rooms and mean/std of area, doorways and axes ratio.

    The keys of each row match :func:`realistic_indoor.models.reference_table`
    (``share_pct``, ``area_mean``, ``area_std``, ``doors_mean``, ``doors_std``,
    ``axes_ratio_mean``, ``axes_ratio_std``) plus ``count``. Standard deviations are over
    rooms (population, ``ddof=0``). A label with no rooms has share 0 and NaN statistics.

    Raises:
        RealisticIndoorError: If the set holds no rooms.
    """
    feats = all_room_features(buildings)
    if not feats:
        raise RealisticIndoorError("no rooms to compute statistics over: the set of plans is empty")
    table: dict[SemanticLabel, dict[str, float]] = {}
    for lab in SemanticLabel:
        rows = [f for f in feats if f.label is lab]
        row: dict[str, float] = {"count": float(len(rows)), "share_pct": 100.0 * len(rows) / len(feats)}
        for name, values in (
            ("area", [f.area for f in rows]),
            ("doors", [f.doors for f in rows]),
            ("axes_ratio", [f.axes_ratio for f in rows]),
        ):
            arr = np.asarray(values, dtype=float)
            row[f"{name}_mean"] = float(arr.mean()) if len(arr) else float("nan")
            row[f"{name}_std"] = float(arr.std()) if len(arr) else float("nan")
        table[lab] = row
    return table
