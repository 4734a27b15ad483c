"""Writing and reading evaluation results: per-episode CSV, summary CSV, everything as JSON.

While an evaluation runs, each finished episode is appended to ``episodes.jsonl`` (the episode
log, :class:`EpisodeLog`), so an interrupted run keeps every finished episode and can be resumed
(:func:`finished_episodes`). The other files are written whole at the end, each to a temporary
file renamed into place (:mod:`realistic_indoor.files`).
"""

from __future__ import annotations

import csv
import json
import math
import os
from collections.abc import Sequence
from pathlib import Path
from typing import IO, Any

from realistic_indoor.errors import ConfigError
from realistic_indoor.evaluation.aggregate import SUMMARY_METRICS, TEAM_METRICS, add_speedup, summarize
from realistic_indoor.evaluation.episode import SCALARS, TEAM_SCALARS, EpisodeResult
from realistic_indoor.evaluation.tasks import EpisodeTask, task_key
from realistic_indoor.files import atomic_write, write_text

__all__ = [
    "EPISODE_COLUMNS",
    "LOG_NAME",
    "RESULT_FILES",
    "TEAM_EPISODE_COLUMNS",
    "EpisodeLog",
    "finished_episodes",
    "format_table",
    "has_teams",
    "previous_results",
    "read_results",
    "summary_rows",
    "write_results",
]

EPISODE_COLUMNS = ("agent", "env", "group", "seed", *SCALARS)
"""Columns of ``episodes.csv``."""
TEAM_EPISODE_COLUMNS = ("agent", "env", "group", "seed", "robots", *SCALARS, *TEAM_SCALARS)
"""Columns of ``episodes.csv`` when the results hold teams (:func:`has_teams`)."""
LOG_NAME = "episodes.jsonl"
"""The episode log in an output folder: one JSON line per finished episode."""
RESULT_FILES = (
    LOG_NAME,
    "episodes.csv",
    "summary.csv",
    "results.json",
    "coverage_time.png",
    "coverage_distance.png",
    "speedup.png",
)
"""The files an evaluation writes in its output folder."""
_FORMAT = 1
_SETTINGS = ("env_id", "kwargs", "curve_every_steps", "curve_every_m", "target")
"""What a resumed episode must share with the run it continues."""


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
    summary = summary_rows(results)
    files = {"episodes": out / "episodes.csv", "summary": out / "summary.csv", "json": out / "results.json"}
    columns = TEAM_EPISODE_COLUMNS if has_teams(results) else EPISODE_COLUMNS
    _write_csv(files["episodes"], [{c: getattr(r, c) for c in columns} for r in results])
    _write_csv(files["summary"], summary)
    payload = {
        "format": _FORMAT,
        "meta": meta or {},
        "summary": summary,
        "episodes": [r.to_dict() for r in results],
    }
    write_text(files["json"], json.dumps(_plain(payload), indent=1) + "\n")
    return files


def has_teams(results: Sequence[EpisodeResult]) -> bool:
    """Whether any result is a team's (a team agent in a team environment, of any size)."""
    return any(r.robots > 1 or math.isfinite(r.linked_to_base_share) for r in results)


def summary_rows(results: Sequence[EpisodeResult]) -> list[dict[str, Any]]:
    """``summary.csv``'s rows: per agent and environment group, and team size with teams.

    With teams (:func:`has_teams`) the rows are per agent, group and ``robots``, with the team
    metrics (:data:`~realistic_indoor.evaluation.aggregate.TEAM_METRICS`), ``speedup`` and
    ``efficiency`` (:func:`~realistic_indoor.evaluation.aggregate.add_speedup`).
    """
    if not has_teams(results):
        return summarize(results)
    by = ("agent", "group", "robots")
    return add_speedup(summarize(results, by, metrics=SUMMARY_METRICS + TEAM_METRICS))


def previous_results(out_dir: str | Path) -> list[str]:
    """The names of the evaluation files (:data:`RESULT_FILES`) already in ``out_dir``."""
    return [name for name in RESULT_FILES if (Path(out_dir) / name).is_file()]


class EpisodeLog:
    """The episode log of an output folder, appended to as episodes finish.

    Each line is one JSON object ``{"task": ..., "result": ...}``: the task's agent, environment
    label and seed with the settings that shape its result, and :meth:`EpisodeResult.to_dict`.
    Each line is flushed to disk when written, so an interrupt or a crash loses at most the
    line being written, which :func:`finished_episodes` ignores. (An append-only log is not
    rewritten whole, unlike the other outputs.)

    Args:
        out_dir: The output folder (created if missing).
        append: Continue an existing log (``--resume``) instead of starting a new one.
    """

    def __init__(self, out_dir: str | Path, append: bool = False) -> None:
        self.path = Path(out_dir) / LOG_NAME
        self.path.parent.mkdir(parents=True, exist_ok=True)
        if not append and self.path.is_symlink():
            self.path.unlink()  # a new log replaces the link, never the file it points to
        if append and _ends_torn(self.path):
            with self.path.open("a", encoding="utf-8") as f:
                f.write("\n")  # end a line torn by an interrupt, so the next record starts clean
        self._file: IO[str] | None = self.path.open("a" if append else "w", encoding="utf-8")

    def write(self, task: EpisodeTask, result: EpisodeResult) -> None:
        """Append one finished episode and flush it to disk."""
        if self._file is None:
            raise ValueError(f"{self.path}: the episode log is closed")
        record = {"task": _task_record(task), "result": _plain(result.to_dict())}
        self._file.write(json.dumps(record, separators=(",", ":")) + "\n")
        self._file.flush()
        os.fsync(self._file.fileno())

    def close(self) -> None:
        """Close the file."""
        if self._file is not None:
            self._file.close()
            self._file = None

    def __enter__(self) -> EpisodeLog:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def finished_episodes(out_dir: str | Path, tasks: Sequence[EpisodeTask]) -> dict[int, EpisodeResult]:
    """The episodes of ``tasks`` that an earlier run into ``out_dir`` finished (its episode log).

    Episodes are matched by agent, environment label and seed; a line torn by an interrupt is
    ignored; episodes of the log that are not among ``tasks`` are left out.

    Args:
        out_dir: The output folder of the earlier run.
        tasks: The episodes to run now.

    Returns:
        ``{index in tasks: result}`` of the episodes already finished.

    Raises:
        ConfigError: If an episode was finished with other settings (``max_steps``, another
            environment id, ...) than the task asks for now: the results would not be comparable.
    """
    path = Path(out_dir) / LOG_NAME
    if not path.is_file():
        return {}
    by_key = {task_key(t): i for i, t in enumerate(tasks)}
    done: dict[int, EpisodeResult] = {}
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        raise ConfigError(
            f"{path}: not an episode log (not UTF-8 text); add --overwrite to replace it or choose "
            "another --out folder"
        ) from None
    for number, line in enumerate(text.splitlines(), 1):
        record = _parse_line(line)
        if record is None:
            continue
        old, result = record
        i = by_key.get((old.get("agent"), old.get("env"), old.get("seed"), old.get("robots")))
        if i is None:
            continue
        _check_same_settings(old, _task_record(tasks[i]), path, number)
        done[i] = result
    return done


def _task_record(task: EpisodeTask) -> dict[str, Any]:
    """What identifies an episode and shapes its result, as JSON-ready values."""
    record = {
        "agent": task.agent,
        "env": task.env.label,
        "seed": task.seed,
        "robots": task.robots,
        "env_id": task.env.env_id,
        "plan": task.env.plan,
        "kwargs": task.env.kwargs,
        "curve_every_steps": task.curve_every_steps,
        "curve_every_m": task.curve_every_m,
        "target": task.target,
    }
    return json.loads(json.dumps(record, default=repr))


def _parse_line(line: str) -> tuple[dict[str, Any], EpisodeResult] | None:
    """A log line's task and result, or ``None`` for a blank or torn line."""
    try:
        data = json.loads(line)
        task, result = data["task"], EpisodeResult.from_dict(_unplain(data["result"]))
    except (ValueError, KeyError, TypeError, AttributeError, RecursionError):
        return None
    return (task, result) if isinstance(task, dict) else None


def _check_same_settings(old: dict[str, Any], new: dict[str, Any], path: Path, line: int) -> None:
    changed = [k for k in _SETTINGS if old.get(k) != new[k]]
    if _plan_name(old.get("plan")) != _plan_name(new["plan"]):
        changed.append("plan")
    if changed:
        was = ", ".join(f"{k} {old.get(k)!r} (now {new[k]!r})" for k in changed)
        raise ConfigError(
            f"{path}, line {line}: {old['agent']} on {old['env']}, seed {old['seed']} ran with other "
            f"settings: {was}; resume with the same options, or use a new --out folder"
        )


def _plan_name(plan: str | None) -> str | None:
    """A plan's file name: the same plan resumed from another folder keeps it."""
    return None if plan is None else Path(plan).name


def _ends_torn(path: Path) -> bool:
    """Whether ``path`` exists and does not end with a line break."""
    if not path.is_file() or path.stat().st_size == 0:
        return False
    with path.open("rb") as f:
        f.seek(-1, os.SEEK_END)
        return f.read(1) != b"\n"


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
    team = any("speedup" in row for row in rows)
    header = ["agent", "env", *(["robots"] if team else []), "n", *metrics, *(["speedup"] if team else [])]
    lines = [header]
    for row in rows:
        cells = [str(row["agent"]), str(row["group"]), *([str(row["robots"])] if team else [])]
        cells.append(str(row["episodes"]))
        cells += [_interval(row[m], row[f"{m}_low"], row[f"{m}_high"]) for m in metrics]
        if team:
            cells.append("-" if not math.isfinite(row["speedup"]) else f"{row['speedup']:.2f}")
        lines.append(cells)
    widths = [max(len(line[i]) for line in lines) for i in range(len(header))]
    return "\n".join("  ".join(cell.ljust(w) for cell, w in zip(line, widths, strict=True)) for line in lines)


def _interval(mean: float, low: float, high: float) -> str:
    if not math.isfinite(mean):
        return "-"
    digits = 3 if abs(mean) < 10 else 1
    return f"{mean:.{digits}f} [{low:.{digits}f}, {high:.{digits}f}]"


def _write_csv(path: Path, rows: list[dict[str, Any]]) -> None:
    with atomic_write(path, "w", newline="") as f:
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
