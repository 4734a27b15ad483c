"""Outputs of a behavioural-realism study (:mod:`.twins`): report, tables, JSON and figure.

Everything is made from the study's ``data`` (``behaviour_realism.json``), so the report and
figure can be made again from that file alone (:func:`load_study`, :func:`write_outputs`).
"""

from __future__ import annotations

import csv
import json
import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from realistic_indoor.errors import ConfigError
from realistic_indoor.files import atomic_path, atomic_write, write_text

__all__ = ["CONNECTED", "FORMAT", "NAME", "draw_figure", "load_study", "render_report", "write_outputs"]

CONNECTED = 0.9
"""Share of the floor area the robot's start must reach for a plan and its twin to count as
connected; pairs below it are reported, and left out of the paired differences of connected pairs."""

FORMAT = 1
"""Version of the ``behaviour_realism.json`` layout."""

NAME = "behaviour_realism"
"""Stem of the report, figure and JSON file."""

_SET_LABELS = {"real": "real plans", "twins": "twins"}


def write_outputs(data: dict[str, Any], out_dir: str | Path) -> dict[str, Path]:
    """Write the report, figure, JSON and CSV tables of a study into ``out_dir``.

    Files: ``behaviour_realism.md`` (report), ``behaviour_realism.png`` (coverage AUC per agent,
    real against twins, and the paired differences, with 95% intervals),
    ``behaviour_realism.json`` (``data``, ``NaN`` as ``null``), ``episodes.csv`` (one row per
    episode), ``summary.csv`` (per agent and set) and ``paired.csv`` (per agent). Each file is
    written whole or not at all.

    Returns:
        The files written, by name.
    """
    out = Path(out_dir)
    files = {
        "json": write_text(out / f"{NAME}.json", json.dumps(_plain(data), indent=1) + "\n"),
        "episodes": _write_csv(out / "episodes.csv", data["episodes"]),
        "summary": _write_csv(out / "summary.csv", data["summary"]),
        "paired": _write_csv(out / "paired.csv", data["paired"]),
        "report": write_text(out / f"{NAME}.md", render_report(data)),
        "figure": draw_figure(data, out / f"{NAME}.png"),
    }
    return files


def load_study(path: str | Path) -> dict[str, Any]:
    """The data of a ``behaviour_realism.json`` (``null`` values become ``NaN``).

    Raises:
        ConfigError: If the file is missing or is not such a file.
    """
    path = Path(path)
    try:
        data = json.loads(path.read_text(encoding="utf-8"), object_hook=_unplain)
        missing = {"meta", "plans", "skipped", "episodes", "summary", "paired"} - set(data)
    except (OSError, ValueError, TypeError) as e:
        raise ConfigError(f"{path}: not a {NAME}.json ({e})") from None
    if missing or data.get("format") != FORMAT:
        raise ConfigError(f"{path}: not a {NAME}.json of format {FORMAT} (missing {sorted(missing)})")
    return data


# -- report ----------------------------------------------------------------------------------------


def render_report(data: dict[str, Any]) -> str:
    """The Markdown report of a study."""
    meta = data["meta"]
    lines = [
        f"# Behavioural realism: real {meta['building_type']} plans against their generated twins",
        "",
        *([f"Regenerate with `{meta['command']}`.", ""] if meta.get("command") else []),
        *_setup(data),
        "",
        "## Coverage AUC",
        "",
        "Mean coverage over the step limit (1 = everything seen at once), with 95% bootstrap "
        "intervals over the buildings. *Twins − real* is paired by plan: each plan's "
        f"{'twin' if _twins_per_plan(data) == 1 else 'twins (their mean)'} minus the "
        "plan, so the spread between plans drops out (* the interval excludes 0).",
        "",
        *_auc_table(data),
        *_connected_table(data),
        "",
        "## Steps to 90% coverage per 100 m² of floor",
        "",
        "Median over the buildings, per 100 m² of the floor reachable from the start (the floor the "
        "coverage is a share of). An episode that did not reach 90% coverage within the step limit "
        "counts as slower than any that did, so the median is *not reached* when half the episodes or "
        "more did not get there.",
        "",
        *_steps_table(data),
        "",
        "## What it shows",
        "",
        *_findings(data),
        "",
        "## Per plan",
        "",
        *_plan_table(data),
    ]
    return "\n".join(lines) + "\n"


def _setup(data: dict[str, Any]) -> list[str]:
    """What ran: the plans, the skipped ones, the twins, the clamped areas, agents and limits."""
    meta, pairs = data["meta"], data["plans"]
    kind = meta["building_type"]
    low, high = meta["generator_area_limits_m2"]
    per_plan = _twins_per_plan(data)
    seeds = (
        f"seed {meta['seed']}"
        if len(pairs) == 1
        else f"seeds {meta['seed']} to {meta['seed'] + len(pairs) - 1}"
    )
    plans = list(dict.fromkeys(p["name"] for p in pairs))
    clamped = list({p["name"]: p for p in pairs if p["clamped"]}.values())
    twins = (
        f"one generated {kind} building per plan"
        if per_plan == 1
        else f"{per_plan} generated {kind} buildings per plan, averaged per plan in the paired differences,"
    )
    lines = [
        f"- Real plans: {len(plans)} {kind} plans from {', '.join(f'`{p}`' for p in meta['plans_given'])} "
        f"({meta['plan_files']} plan files; {len(data['skipped'])} left out).",
        *[f"  - left out `{s['source']}`: {s['reason']}" for s in data["skipped"]],
        f"- Twins: {twins} with the plan's floor area (the `{kind}` generator, "
        f"{seeds}). Plan areas outside the generator's limits of {low:,.0f}-{high:,.0f} m² are clamped "
        f"to the nearest limit: {len(clamped)} of {len(plans)}.",
        *[
            f"  - clamped `{p['name']}`: {p['plan_area_m2']:,.0f} m² plan, {p['twin_area_m2']:,.0f} m² twin"
            for p in clamped
        ],
        *_cut_off_lines(data),
        f"- Agents: {', '.join(meta['agents'].values())}; one episode each on every plan and twin "
        f"(seed {meta['seed']}), starting just inside the first usable entrance (real plans get "
        f"their entrances inferred), for at most {meta['max_steps']:,} steps of 0.2 s "
        f"(`{meta['env_id']}`).",
    ]
    return lines


def _cut_off_lines(data: dict[str, Any]) -> list[str]:
    """The plans whose start, or a twin's, reaches less than the connected share of the floor.

    With one twin per plan these are the cut-off pairs; with several, a line per plan gives its
    twins' shares together.
    """
    one = _twins_per_plan(data) == 1
    names = _cut_names(data)
    plans = list(dict.fromkeys(p["name"] for p in data["plans"]))
    lines = [
        f"- Reachable floor: the robot's start reaches less than {CONNECTED:.0%} of the floor in "
        f"{len(names)} of the {len(plans)} {'pairs' if one else 'plans or their twins'} (the start lies "
        "in a part cut off from the rest; coverage, a share of the reachable floor, then measures only "
        "that part)."
    ]
    whose = "the twin's" if one else "its twins'"
    for name in names:
        pairs = [p for p in data["plans"] if p["name"] == name]
        twins = ", ".join(_share(p, "twin") for p in pairs)
        lines.append(
            f"  - cut off `{name}`: the start reaches {_share(pairs[0], 'plan')} of the plan's floor "
            f"and {twins} of {whose}"
        )
    return lines


def _twins_per_plan(data: dict[str, Any]) -> int:
    """Twins drawn per plan (1 in studies written before the option)."""
    return data["meta"].get("twins_per_plan", 1)


def _cut_names(data: dict[str, Any]) -> list[str]:
    """The plans with a cut-off pair (the plan's start or a twin's), each once, in order."""
    return list(dict.fromkeys(p["name"] for p in data["plans"] if p["cut_off"]))


def _cut_noun(data: dict[str, Any]) -> str:
    """What the differences without cut-off starts leave out: pairs, or plans with several twins."""
    return "cut-off pair" if _twins_per_plan(data) == 1 else "cut-off plan"


def _share(pair: dict[str, Any], kind: str) -> str:
    """Reachable share of the floor of the plan or twin of a pair, as ``97%`` (``-``: not measured)."""
    share = pair[f"{kind}_reachable_m2"] / pair[f"{kind}_area_m2"]
    return f"{share:.0%}" if math.isfinite(share) else "-"


def _connected_table(data: dict[str, Any]) -> list[str]:
    """Twin minus real without the cut-off pairs (nothing when there are none)."""
    cut = _cut_names(data)  # with one twin per plan, the plans of the cut-off pairs
    if not cut:
        return []
    lines = [
        "",
        f"Without the {_count(len(cut), _cut_noun(data))} ({', '.join(f'`{c}`' for c in cut)}):",
        "",
        "| agent | pairs | twins − real (paired) |",
        "|---|---|---|",
    ]
    for p in data["paired"]:
        lines.append(f"| {p['label']} | {p['connected_pairs']} | {_difference(_connected(p))} |")
    return lines


def _connected(paired: dict[str, Any]) -> dict[str, Any]:
    """The ``connected_`` columns of a paired row, named as the columns over all pairs."""
    return {k.removeprefix("connected_"): v for k, v in paired.items() if k.startswith("connected_")}


def _count(n: int, noun: str) -> str:
    """``"1 plan area"``, ``"2 plan areas"``."""
    return f"{n} {noun}{'' if n == 1 else 's'}"


def _auc_table(data: dict[str, Any]) -> list[str]:
    cell = {(r["agent"], r["set"]): r for r in data["summary"]}
    lines = ["| agent | real plans | twins | twins − real (paired) | twin higher |", "|---|---|---|---|---|"]
    for p in data["paired"]:
        real, twins = cell.get((p["agent"], "real")), cell.get((p["agent"], "twins"))
        lines.append(
            f"| {p['label']} | {_auc(real)} | {_auc(twins)} | {_difference(p)} | "
            f"{p['twin_higher']} of {p['pairs']} |"
        )
    return lines


def _auc(row: dict[str, Any] | None) -> str:
    if row is None:
        return "-"
    return (
        f"{row['coverage_auc']:.2f} [{row['coverage_auc_low']:.2f}, {row['coverage_auc_high']:.2f}] "
        f"(n={row['episodes']})"
    )


def _difference(p: dict[str, Any]) -> str:
    if not p["pairs"]:
        return "-"
    star = " *" if _apart(p) else ""
    return f"{p['difference']:+.3f} [{p['difference_low']:+.3f}, {p['difference_high']:+.3f}]{star}"


def _apart(p: dict[str, Any]) -> bool:
    """Whether the paired interval excludes 0 (over at least two plans)."""
    return p["pairs"] > 1 and (p["difference_low"] > 0 or p["difference_high"] < 0)


def _steps_table(data: dict[str, Any]) -> list[str]:
    cell = {(r["agent"], r["set"]): r for r in data["summary"]}
    lines = ["| agent | real plans | twins |", "|---|---|---|"]
    for agent, label in data["meta"]["agents"].items():
        cells = [_steps(cell.get((agent, kind))) for kind in ("real", "twins")]
        lines.append(f"| {label} | {' | '.join(cells)} |")
    return lines


def _steps(row: dict[str, Any] | None) -> str:
    if row is None:
        return "-"
    median = row["steps_to_90_per_100m2_median"]
    value = "not reached" if not math.isfinite(median) else f"{median:,.0f}"
    return f"{value} ({row['reached_90']} of {row['episodes']} reached 90%)"


def _findings(data: dict[str, Any]) -> list[str]:
    """A sentence per agent on twin minus real, then the agents' order in each set."""
    lines = []
    for p in data["paired"]:
        if p["pairs"] < 2:
            lines.append(f"- {p['label']}: {p['pairs']} plan with a twin, too few to tell.")
            continue
        diff = f"{p['difference']:+.3f} [{p['difference_low']:+.3f}, {p['difference_high']:+.3f}]"
        if _apart(p):
            easier = "easier" if p["difference"] > 0 else "harder"
            lines.append(
                f"- {p['label']}: the twins are {easier} for it than the real plans: coverage AUC "
                f"{p['twins']:.2f} against {p['real']:.2f}, twin minus real {diff}, "
                f"twin higher on {p['twin_higher']} of {p['pairs']} plans."
            )
        else:
            lines.append(
                f"- {p['label']}: no difference shown over {p['pairs']} plans: coverage AUC {p['twins']:.2f} "
                f"on the twins against {p['real']:.2f}, twin minus real {diff} (the interval holds 0)."
            )
    cut = len(_cut_names(data))
    if cut:
        parts = [f"{p['label']} {_difference(_connected(p))}" for p in data["paired"]]
        lines.append(f"- Without the {_count(cut, _cut_noun(data))}, twin minus real: {'; '.join(parts)}.")
    orders = {kind: _order(data["summary"], kind) for kind in ("real", "twins")}
    same = "the same order" if orders["real"] == orders["twins"] else "a different order"
    lines.append(
        f"- Ranking by coverage AUC: real plans {' > '.join(orders['real'])}; twins "
        f"{' > '.join(orders['twins'])} ({same})."
    )
    return lines


def _order(rows: Sequence[dict[str, Any]], kind: str) -> list[str]:
    """Agent labels of one set, by mean coverage AUC, best first."""
    ranked = sorted((r for r in rows if r["set"] == kind), key=lambda r: -r["coverage_auc"])
    return [r["label"] for r in ranked]


def _plan_table(data: dict[str, Any]) -> list[str]:
    agents = data["meta"]["agents"]
    auc = {(e["agent"], e["set"], e.get("twin") or e["plan"]): e["coverage_auc"] for e in data["episodes"]}
    head = "| plan | floor m² | twin m² | reachable | " + " | ".join(
        f"{a} real | {a} twin" for a in agents.values()
    )
    lines = [
        "Reachable: share of the floor reachable from the start, plan / twin. Coverage AUC per episode.",
        "",
        head + " |",
        "|---" * (4 + 2 * len(agents)) + "|",
    ]
    for p in data["plans"]:
        twin = p.get("twin_name") or p["name"]
        cells = [
            _value(auc.get((agent, kind, p["name"] if kind == "real" else twin)))
            for agent in agents
            for kind in ("real", "twins")
        ]
        notes = [note for note, flag in (("clamped", p["clamped"]), ("cut off", p["cut_off"])) if flag]
        name = twin + (f" ({', '.join(notes)})" if notes else "")
        reach = f"{_share(p, 'plan')} / {_share(p, 'twin')}"
        lines.append(
            f"| {name} | {p['plan_area_m2']:,.0f} | {p['twin_area_m2']:,.0f} | {reach} | {' | '.join(cells)} |"
        )
    return lines


def _value(x: float | None) -> str:
    return "-" if x is None or not math.isfinite(x) else f"{x:.2f}"


# -- figure ----------------------------------------------------------------------------------------


def draw_figure(data: dict[str, Any], path: str | Path) -> Path:
    """Coverage AUC per agent, real plans against twins, and twin minus real per agent.

    Left: bars of the mean coverage AUC per agent and set with 95% intervals. Right: the
    paired difference (twin minus real) per agent with its 95% interval, and the zero line.

    Returns:
        The path written (whole or not at all).
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    agents = data["meta"]["agents"]
    cell = {(r["agent"], r["set"]): r for r in data["summary"]}
    x = np.arange(len(agents))
    fig, (left, right) = plt.subplots(
        1, 2, figsize=(4.0 + 1.6 * len(agents), 3.8), gridspec_kw={"width_ratios": [3, 2]}
    )
    for i, kind in enumerate(("real", "twins")):
        rows = [cell.get((a, kind)) for a in agents]
        mean = np.array([r["coverage_auc"] if r else np.nan for r in rows])
        low = np.array([r["coverage_auc_low"] if r else np.nan for r in rows])
        high = np.array([r["coverage_auc_high"] if r else np.nan for r in rows])
        n = max((r["episodes"] for r in rows if r), default=0)
        left.bar(
            x + (i - 0.5) * 0.38, mean, 0.38, yerr=[mean - low, high - mean], capsize=3,
            label=f"{_SET_LABELS[kind]} (n={n})", error_kw={"lw": 0.8},
        )  # fmt: skip
    left.set_xticks(x, list(agents.values()), fontsize=8)
    left.set_ylabel("coverage AUC (mean coverage over the step limit)", fontsize=8)
    left.set_ylim(0, 1)
    left.legend(fontsize=7)
    left.grid(axis="y", alpha=0.3)
    paired = {p["agent"]: p for p in data["paired"]}
    cut = len(_cut_names(data))
    variants = [("", "all pairs", "o", 0.0)]
    if cut:
        variants = [("", "all pairs", "o", -0.1), ("connected_", f"without {cut} cut off", "s", 0.1)]
    for prefix, label, marker, shift in variants:
        d, lo, hi = (
            np.array([paired[a][f"{prefix}difference{end}"] for a in agents], dtype=float)
            for end in ("", "_low", "_high")
        )
        n = max(paired[a][f"{prefix}pairs"] for a in agents)
        right.errorbar(
            x + shift, d, yerr=[d - lo, hi - d], fmt=marker, capsize=4, color="black",
            mfc="black" if not prefix else "white", label=f"{label} (n={n})",
        )  # fmt: skip
    right.legend(fontsize=7)
    right.axhline(0.0, color="grey", lw=0.8)
    right.set_xticks(x, list(agents.values()), fontsize=8)
    right.set_xlim(-0.5, len(agents) - 0.5)
    right.set_ylabel("twin − real coverage AUC (paired by plan)", fontsize=8)
    right.grid(axis="y", alpha=0.3)
    fig.suptitle(f"Real {data['meta']['building_type']} plans and their generated twins", fontsize=9)
    fig.tight_layout()
    path = Path(path)
    try:
        with atomic_path(path) as tmp:
            fig.savefig(tmp, dpi=120)
    finally:
        plt.close(fig)
    return path


# -- files -----------------------------------------------------------------------------------------


def _write_csv(path: Path, rows: Sequence[dict[str, Any]]) -> Path:
    """Rows as CSV (``NaN`` as an empty cell, floats to 6 significant digits)."""
    with atomic_write(path, "w", newline="") as f:
        if rows:
            writer = csv.DictWriter(f, fieldnames=list(rows[0]))
            writer.writeheader()
            for row in rows:
                writer.writerow({k: _cell(v) for k, v in row.items()})
    return path


def _cell(value: Any) -> Any:
    if isinstance(value, float):
        return "" if math.isnan(value) else f"{value:.6g}"
    return value


def _plain(value: Any) -> Any:
    """JSON-ready: ``NaN`` becomes ``null``."""
    if isinstance(value, float) and math.isnan(value):
        return None
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    return value


_NUMBERS = (
    "coverage_auc",
    "steps_to_90",
    "steps_to_90_per_100m2",
    "steps_to_90_per_100m2_median",
    "difference",
    "connected_difference",
    "plan_reachable_m2",
    "twin_reachable_m2",
    "reachable_m2",
    "real",
    "twins",
)


def _unplain(obj: dict[str, Any]) -> dict[str, Any]:
    """The inverse of :func:`_plain` for the numeric fields of a row: ``null`` becomes ``NaN``."""
    return {
        k: (math.nan if v is None and (k in _NUMBERS or k.startswith(_NUMBERS)) else v)
        for k, v in obj.items()
    }
