"""The paper's Table 1 computed for any set of buildings."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from realistic_indoor.building.labels import SemanticLabel
from realistic_indoor.errors import RealisticIndoorError
from realistic_indoor.validator.features import all_room_features

if TYPE_CHECKING:
    from collections.abc import Iterable, Mapping

    from realistic_indoor.building.building import Building

__all__ = ["TABLE_FORMATS", "label_table", "label_table_records", "label_table_rows", "render_label_tables"]

TABLE_FORMATS = ("table", "markdown", "csv", "json")
"""Formats :func:`render_label_tables` writes."""

_STATS = (("area", "area (m2)"), ("doors", "doorways"), ("axes_ratio", "axes ratio"))
_CSV_KEYS = ("count", "share_pct", *(f"{f}_{s}" for f, _t in _STATS for s in ("mean", "std")))


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


def _mean_std(row: Mapping[str, float], name: str) -> str:
    mean, std = row.get(f"{name}_mean", float("nan")), row.get(f"{name}_std", float("nan"))
    if np.isnan(mean):
        return "-"
    return f"{mean:.1f} ± {std:.1f}" if not np.isnan(std) else f"{mean:.1f}"


def _share(row: Mapping[str, float]) -> str:
    share = row.get("share_pct", float("nan"))
    if np.isnan(share):
        return "-"
    count = row.get("count")
    return f"{share:.1f}%" + (f" ({int(count)})" if count is not None else "")


def label_table_rows(
    tables: Mapping[str, Mapping[SemanticLabel, Mapping[str, float]]],
) -> tuple[list[str], list[list[str]]]:
    """Several Table-1s side by side: a header and text rows, one row per label and statistic.

    Cells read ``"20.6% (12)"`` (share of rooms and count, where known) and ``"30.5 ± 25.7"``
    (mean ± standard deviation); ``"-"`` where a set has no room of that label.
    """
    header = ["label", "statistic", *tables]
    rows = []
    for lab in SemanticLabel:
        rows.append([lab.value, "rooms (%)", *(_share(t.get(lab, {})) for t in tables.values())])
        for key, title in _STATS:
            rows.append(["", title, *(_mean_std(t.get(lab, {}), key) for t in tables.values())])
    return header, rows


def _csv_number(x: float) -> str:
    """Full precision, empty for NaN."""
    return "" if np.isnan(x) else repr(float(x))


def label_table_records(tables: Mapping[str, Mapping[SemanticLabel, Mapping[str, float]]]) -> list[list[str]]:
    """Several Table-1s in long form: rows ``[set, label, statistic, value]`` (full precision, NaN empty)."""
    rows = []
    for name, t in tables.items():
        for lab in SemanticLabel:
            row = t.get(lab, {})
            rows += [[name, lab.value, key, _csv_number(row[key])] for key in _CSV_KEYS if key in row]
    return rows


def render_label_tables(
    tables: Mapping[str, Mapping[SemanticLabel, Mapping[str, float]]],
    fmt: str = "table",
    title: str | None = None,
) -> str:
    """Render one or more Table-1s (e.g. several map sets and a reference) side by side.

    Args:
        tables: Column name -> table (as :func:`label_table` or
            :func:`realistic_indoor.models.reference_table` return).
        fmt: ``"table"`` (terminal), ``"markdown"``, ``"csv"`` (long form: ``set,label,
            statistic,value`` with full precision) or ``"json"`` (``{set: {label: row}}``).
        title: A title above the table (table and Markdown only).

    Raises:
        ConfigError: If ``fmt`` is unknown.
    """
    import json

    from realistic_indoor.validator.grid import json_safe, render_grid

    if fmt == "json":
        return json.dumps(json_safe({name: dict(t) for name, t in tables.items()}), indent=1)
    if fmt == "csv":
        return render_grid(["set", "label", "statistic", "value"], label_table_records(tables), "csv")
    header, rows = label_table_rows(tables)
    return render_grid(header, rows, fmt, title)
