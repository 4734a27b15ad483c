"""A :class:`~realistic_indoor.validator.compare.Comparison` as a terminal report, Markdown, CSV or JSON."""

from __future__ import annotations

import json
import math
from typing import TYPE_CHECKING, Any

from realistic_indoor.errors import ConfigError
from realistic_indoor.validator.building_measures import BUILDING_MEASURES, deviations, measure_summary
from realistic_indoor.validator.connectivity import CONNECTIVITY_METRICS
from realistic_indoor.validator.grid import json_safe, render_grid
from realistic_indoor.validator.house_programme import (
    COUNTED_FUNCTIONS,
    FIXED_COUNTS,
    HOUSE_ITEMS,
    HOUSE_REFERENCE,
    HOUSE_RULES,
    bands_near,
    house_reference,
)
from realistic_indoor.validator.tables import TABLE_FORMATS, label_table_records, label_table_rows

if TYPE_CHECKING:
    from realistic_indoor.validator.compare import Comparison, SetReport

__all__ = ["REPORT_FORMATS", "comparison_to_dict", "render_comparison"]

REPORT_FORMATS = TABLE_FORMATS
"""Formats :func:`render_comparison` writes: ``table``, ``markdown``, ``csv``, ``json``."""

SCORE_SCALE = "0 = identical to the reference; below 0.5 hard to tell apart, 0.5-1 close, 1-2 visibly different, above 2 structurally different"
TWO_SAMPLE_SCALE = (
    "balanced accuracy of a classifier telling two sets apart; 0.5 = indistinguishable, 1 = always told apart"
)


OUTSIDE_SHOWN = 10
"""How many houses outside the programme the text report names (JSON names them all)."""


def _num(x: float, digits: int = 1) -> str:
    return "-" if x is None or math.isnan(x) else f"{x:.{digits}f}"


def _connectivity_rows(c: Comparison) -> tuple[list[str], list[list[str]]]:
    header = ["metric", *(s.name for s in c.sets), c.reference.column]
    rows = []
    for m in CONNECTIVITY_METRICS:
        title = f"{m.title} ({m.unit})" if m.unit == "%" else m.title
        ref = c.reference.connectivity.get(m.key, math.nan)
        spread = c.reference.connectivity_std.get(m.key, math.nan)
        ref_cell = _num(ref) + (f" ± {spread:.1f}" if not math.isnan(ref) and not math.isnan(spread) else "")
        rows.append([title, *(_num(s.connectivity.metrics()[m.key]) for s in c.sets), ref_cell])
    rows.append(["room mazes (count)", *(str(s.connectivity.mazes) for s in c.sets), "-"])
    return header, rows


def _score_rows(c: Comparison) -> tuple[list[str], list[list[str]]]:
    header = ["set", "overall", "features", "label shares", "connectivity", "TV distance"]
    rows = [
        [
            s.name,
            *(
                _num(getattr(s.score, k), 2)
                for k in ("overall", "features", "shares", "connectivity", "tv_distance")
            ),
        ]
        for s in c.sets
    ]
    return header, rows


def _measure_columns(c: Comparison) -> dict[str, dict[str, dict[str, float]]]:
    """Summaries of the building-level measures per set, and of the reference's plans if any."""
    columns = {s.name: s.measure_summary for s in c.sets}
    if c.reference_measures:
        columns[c.reference.column] = measure_summary(c.reference_measures)
    return columns


def _measure_rows(c: Comparison) -> tuple[list[str], list[list[str]]]:
    columns = _measure_columns(c)
    header = ["measure (median [interquartile range] spread: range / median)", *columns]
    rows = [
        [text, *(_median_iqr(summary[name]) for summary in columns.values())]
        for name, text in BUILDING_MEASURES.items()
    ]
    return header, rows


def _median_iqr(stat: dict[str, float]) -> str:
    if math.isnan(stat["median"]):
        return "-"
    text = f"{stat['median']:.3g} [{stat['q1']:.3g}-{stat['q3']:.3g}]"
    return text if math.isnan(stat["spread"]) else f"{text} {stat['spread']:.2f}"


_HOUSE_MEDIAN = {"hallway_width": "{:.2f}", "corridor_share": "{:.1%}"}
"""Formats of the medians of the house programme's items that are not counts."""


def _house_rows(c: Comparison) -> tuple[list[str], list[list[str]]]:
    """Per item of the house programme: the share of each set's plans inside it (median)."""
    sets = [s for s in c.sets if s.houses]
    header = ["item (share of plans inside [median])", *(s.name for s in sets), "programme"]
    summaries = [s.house_summary for s in sets]
    rows = []
    for key, words in HOUSE_ITEMS.items():
        cells = []
        for summary in summaries:
            share, median = summary.inside[key], summary.medians.get(key, math.nan)
            cell = "-" if math.isnan(share) else f"{100 * share:.0f}%"
            cells.append(
                cell if math.isnan(median) else f"{cell} [{_HOUSE_MEDIAN.get(key, '{:g}').format(median)}]"
            )
        rows.append([words, *cells, _house_rule(key, sets)])
    rows.append(["every item", *(f"{100 * x.all_inside:.0f}%" for x in summaries), ""])
    return header, rows


def _house_rule(key: str, sets: list[SetReport]) -> str:
    """What the programme asks of an item: its counts at the bands of the sets' plans, where few."""
    rows = {r for s in sets for h in s.houses for r in bands_near(h.floor_area_m2)}
    if key in FIXED_COUNTS or key not in COUNTED_FUNCTIONS or len(rows) > 3:
        return HOUSE_RULES[key]
    return "; ".join(f"{getattr(r, key)} at {r.band}" for r in sorted(rows, key=lambda r: r.min_area_m2))


def _building_worst(c: Comparison, s: SetReport, worst: int) -> list[str]:
    """The measures whose median lies farthest outside the reference plans' interquartile range."""
    if not c.reference_measures:
        return []
    rows = deviations(s.measure_summary, measure_summary(c.reference_measures))
    return [sentence for _name, distance, sentence in rows[:worst] if distance > 0]


def _two_sample_rows(c: Comparison) -> tuple[list[str], list[list[str]]]:
    header = [
        "sets",
        "features",
        "plans",
        "balanced accuracy",
        "most telling features (+: higher in the second set)",
    ]
    rows = [
        [
            f"{t.name_a} vs {t.name_b}",
            t.features,
            f"{t.n_a} + {t.n_b}",
            f"{t.accuracy:.2f} ± {t.accuracy_std:.2f}",
            ", ".join(f"{name} ({coef:+.1f})" for name, coef in t.telling_features) or "none",
        ]
        for t in c.two_sample
    ]
    return header, rows


def _set_line(s: SetReport) -> str:
    line = f"{s.name}: {len(s.plans)} plans, {s.rooms} rooms"
    if s.inferred:
        line += f"; semantic labels inferred for {len(s.inferred)} plans"
    if s.skipped:
        line += f"; {len(s.skipped)} plans left out"
    return line


def _lists(c: Comparison) -> list[tuple[str, list[str]]]:
    """Titled bullet lists: scale flags, plans left out, labels inferred, notes."""
    out = []
    flags = [f.message for s in c.sets for f in s.scale_flags]
    if flags:
        out.append(("Plans whose scale looks wrong", flags))
    outside = [
        f"{s.name}: {src}: {'; '.join(h.problems())}"
        for s in c.sets
        if s.houses
        for src, h in zip(s.plans.sources, s.houses, strict=True)
        if not h.inside
    ]
    if outside:
        shown = outside[:OUTSIDE_SHOWN]
        more = len(outside) - len(shown)
        out.append(("Houses outside the programme", shown + ([f"... and {more} more"] if more else [])))
    left = [f"{s.name}: {src}: {why}" for s in c.sets for src, why in s.skipped]
    if left:
        out.append(("Plans left out", left))
    inferred = [f"{s.name}: {src}" for s in c.sets for src in s.inferred]
    if inferred:
        out.append(("Semantic labels inferred (from function, shape and area)", inferred))
    if c.notes:
        out.append(("Notes", list(c.notes)))
    return out


def _titled(title: str, lines: list[str], md: bool) -> str:
    return (f"### {title}\n\n" if md else f"{title}:\n") + "\n".join(lines)


def _text(c: Comparison, fmt: str, worst: int) -> str:
    md = fmt == "markdown"
    sets = f"{len(c.sets)} set{'s' if len(c.sets) > 1 else ''}"
    heading = f"Realism of {sets} of {c.building_type.value} plans against {c.reference.name} ({c.reference.column})"
    parts = [f"## {heading}" if md else heading]
    parts.append("\n".join(("- " if md else "  ") + _set_line(s) for s in c.sets))
    tables = {s.name: s.table for s in c.sets} | {c.reference.column: c.reference.table}
    parts.append(render_grid(*label_table_rows(tables), fmt, "Table 1: rooms per semantic label"))
    parts.append(render_grid(*_connectivity_rows(c), fmt, "Connectivity"))
    parts.append(render_grid(*_measure_rows(c), fmt, "Building-level measures (docs/validator.md)"))
    if any(s.houses for s in c.sets):
        parts.append(render_grid(*_house_rows(c), fmt, f"House programme: against {HOUSE_REFERENCE}"))
    parts.append(render_grid(*_score_rows(c), fmt, f"Realism score ({SCORE_SCALE})"))
    if c.two_sample:
        parts.append(render_grid(*_two_sample_rows(c), fmt, f"Two-sample tests ({TWO_SAMPLE_SCALE})"))
    worst_lines = []
    for s in c.sets:
        worst_lines.append(f"- **{s.name}**" if md else f"  {s.name}:")
        worst_lines += [("  - " if md else "    - ") + w for w in s.score.worst(worst)]
        worst_lines += [("  - " if md else "    - ") + w for w in _building_worst(c, s, worst)]
    parts.append(_titled("Worst deviations", worst_lines, md))
    for title, items in _lists(c):
        parts.append(_titled(title, [("- " if md else "  ") + i for i in items], md))
    return "\n\n".join(parts) + "\n"


def comparison_to_dict(c: Comparison) -> dict[str, Any]:
    """The whole comparison as JSON-ready data (NaN as ``None``)."""
    ref = c.reference
    data = {
        "building_type": c.building_type.value,
        "reference": {
            "name": ref.name,
            "column": ref.column,
            "plans": len(ref.buildings),
            "table": ref.table,
            "connectivity": ref.connectivity,
            "connectivity_std": ref.connectivity_std,
            "building_measures": measure_summary(c.reference_measures) if c.reference_measures else None,
        },
        "sets": [
            {
                "name": s.name,
                "plans": len(s.plans),
                "rooms": s.rooms,
                "sources": list(s.plans.sources),
                "labels_inferred": list(s.inferred),
                "skipped": [{"source": src, "reason": why} for src, why in s.skipped],
                "table": s.table,
                "connectivity": s.connectivity.to_dict(),
                "score": {**s.score.to_dict(), "worst": s.score.worst(5)},
                "building_measures": s.measure_summary,
                "plan_measures": [
                    {"source": src, **m.as_dict()} for src, m in zip(s.plans.sources, s.measures, strict=True)
                ],
                "building_worst": _building_worst(c, s, 5),
                "scale_flags": [{**vars(f), "message": f.message} for f in s.scale_flags],
                "house_programme": _house_dict(s) if s.houses else None,
            }
            for s in c.sets
        ],
        "two_sample": [{**t.to_dict(), "sentence": t.sentence()} for t in c.two_sample],
        "notes": list(c.notes),
    }
    if any(s.houses for s in c.sets):
        data["house_reference"] = house_reference()
    return json_safe(data)


def _house_dict(s: SetReport) -> dict[str, Any]:
    """A set's plans against the house programme: the summary, and each plan's measures and problems."""
    plans = [{"source": src, **h.to_dict()} for src, h in zip(s.plans.sources, s.houses, strict=True)]
    return {"summary": vars(s.house_summary), "plans": plans}


def _csv(c: Comparison) -> str:
    rows = []
    tables = {s.name: s.table for s in c.sets} | {c.reference.column: c.reference.table}
    rows += [["table", *r] for r in label_table_records(tables)]
    for s in c.sets:
        rows += [["connectivity", s.name, k, "value", repr(v)] for k, v in s.connectivity.metrics().items()]
        rows += [
            ["score", s.name, "", k, repr(getattr(s.score, k))]
            for k in ("overall", "features", "shares", "connectivity", "tv_distance")
        ]
        rows += [["scale", s.name, f.source, "length_factor", repr(f.length_factor)] for f in s.scale_flags]
        if s.houses:
            summary = s.house_summary
            rows += [["house", s.name, k, "share_inside", repr(v)] for k, v in summary.inside.items()]
            rows += [["house", s.name, k, "median", repr(v)] for k, v in summary.medians.items()]
            rows.append(["house", s.name, "every_item", "share_inside", repr(summary.all_inside)])
    rows += [
        ["connectivity", c.reference.column, k, "value", repr(v)] for k, v in c.reference.connectivity.items()
    ]
    for name, summary in _measure_columns(c).items():
        rows += [
            ["building", name, measure, stat, repr(float(value))]
            for measure, stats in summary.items()
            for stat, value in stats.items()
        ]
    for t in c.two_sample:
        pair = f"{t.name_a} vs {t.name_b}"
        rows += [
            ["two_sample", pair, t.features, "balanced_accuracy", repr(t.accuracy)],
            ["two_sample", pair, t.features, "balanced_accuracy_std", repr(t.accuracy_std)],
        ]
    rows = [[cell if cell != "nan" else "" for cell in r] for r in rows]
    return render_grid(["section", "set", "subject", "statistic", "value"], rows, "csv") + "\n"


def render_comparison(c: Comparison, fmt: str = "table", worst: int = 3) -> str:
    """Render a comparison.

    Args:
        c: The comparison.
        fmt: ``"table"`` (terminal), ``"markdown"``, ``"csv"`` (long form: ``section, set,
            subject, statistic, value``) or ``"json"``.
        worst: How many worst deviations to name per set (table and Markdown).

    Raises:
        ConfigError: If ``fmt`` is unknown.
    """
    if fmt == "json":
        return json.dumps(comparison_to_dict(c), indent=1) + "\n"
    if fmt == "csv":
        return _csv(c)
    if fmt in ("table", "markdown"):
        return _text(c, fmt, worst)
    raise ConfigError(f"unknown report format {fmt!r}; valid: {', '.join(REPORT_FORMATS)}")
