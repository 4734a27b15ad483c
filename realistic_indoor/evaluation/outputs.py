"""Writing and reading evaluation results: per-episode CSV, summary CSV, everything as JSON."""

from __future__ import annotations

import csv
import json
import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from realistic_indoor.errors import ConfigError
from realistic_indoor.evaluation.aggregate import summarize
from realistic_indoor.evaluation.episode import SCALARS, EpisodeResult

__all__ = ["EPISODE_COLUMNS", "format_table", "read_results", "write_results"]

EPISODE_COLUMNS = ("agent", "env", "group", "seed", *SCALARS)
"""Columns of ``episodes.csv``."""
_FORMAT = 1


def write_results(
    results: Sequence[EpisodeResult], out_dir: str | Path, meta: dict[str, Any] | None = None
) -> dict[str, Path]:
    """Write ``episodes.csv``, ``summary.csv`` and ``results.json`` (with the coverage curves).

    Args:
        results: Episode results.
        out_dir: Folder to write into (created if needed).
        meta: What produced the results (agents, environments, command), stored in the JSON.

    Returns:
        The files written, by name.
    """
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    summary = summarize(results)
    files = {"episodes": out / "episodes.csv", "summary": out / "summary.csv", "json": out / "results.json"}
    _write_csv(files["episodes"], [{c: getattr(r, c) for c in EPISODE_COLUMNS} for r in results])
    _write_csv(files["summary"], summary)
    payload = {
        "format": _FORMAT,
        "meta": meta or {},
        "summary": summary,
        "episodes": [r.to_dict() for r in results],
    }
    files["json"].write_text(json.dumps(_plain(payload), indent=1) + "\n", encoding="utf-8")
    return files


def read_results(path: str | Path) -> tuple[list[EpisodeResult], dict[str, Any]]:
    """The episodes and metadata of a ``results.json`` written by :func:`write_results`.

    Raises:
        ConfigError: If the file is missing or is not such a file.
    """
    path = Path(path)
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
        episodes = [EpisodeResult.from_dict(_unplain(e)) for e in data["episodes"]]
    except (OSError, ValueError, KeyError, TypeError) as e:
        raise ConfigError(f"{path}: not an evaluation results.json ({e})") from None
    return episodes, data.get("meta", {})


def format_table(rows: Sequence[dict[str, Any]], metrics: Sequence[str]) -> str:
    """A plain-text table of summary rows: agent, group, episodes, then ``mean [low, high]`` per metric."""
    header = ["agent", "env", "n", *metrics]
    lines = [header]
    for row in rows:
        cells = [str(row["agent"]), str(row["group"]), str(row["episodes"])]
        cells += [_interval(row[m], row[f"{m}_low"], row[f"{m}_high"]) for m in metrics]
        lines.append(cells)
    widths = [max(len(line[i]) for line in lines) for i in range(len(header))]
    return "\n".join("  ".join(cell.ljust(w) for cell, w in zip(line, widths, strict=True)) for line in lines)


def _interval(mean: float, low: float, high: float) -> str:
    if not math.isfinite(mean):
        return "-"
    digits = 3 if abs(mean) < 10 else 1
    return f"{mean:.{digits}f} [{low:.{digits}f}, {high:.{digits}f}]"


def _write_csv(path: Path, rows: list[dict[str, Any]]) -> None:
    with path.open("w", newline="", encoding="utf-8") as f:
        if not rows:
            return
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        for row in rows:
            writer.writerow({k: _cell(v) for k, v in row.items()})


def _cell(value: Any) -> Any:
    if isinstance(value, float):
        return "" if math.isnan(value) else f"{value:.6g}"
    return value


def _plain(value: Any) -> Any:
    """JSON-ready: NaN becomes null."""
    if isinstance(value, float) and math.isnan(value):
        return None
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    return value


def _unplain(data: dict[str, Any]) -> dict[str, Any]:
    """The inverse of :func:`_plain` for an episode: null scalars become NaN."""
    return {k: (math.nan if v is None else v) for k, v in data.items()}
