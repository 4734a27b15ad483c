"""Render a grid of text cells as a terminal table, Markdown or CSV; JSON-safe numbers."""

from __future__ import annotations

import csv
import io
import math
from typing import TYPE_CHECKING, Any

from realistic_indoor.errors import ConfigError

if TYPE_CHECKING:
    from collections.abc import Sequence

__all__ = ["GRID_FORMATS", "json_safe", "render_grid"]

GRID_FORMATS = ("table", "markdown", "csv")
"""Formats :func:`render_grid` writes."""


def _is_number(cell: str) -> bool:
    head = cell.split(" ")[0].rstrip("%")
    try:
        float(head)
    except ValueError:
        return head in ("-", "n/a")
    return True


def _table(header: Sequence[str], rows: Sequence[Sequence[str]], title: str | None) -> str:
    widths = [max(len(str(r[i])) for r in (header, *rows)) for i in range(len(header))]
    right = [i > 0 and all(_is_number(r[i]) or not r[i] for r in rows) for i in range(len(header))]

    def line(cells: Sequence[str]) -> str:
        parts = [c.rjust(w) if r else c.ljust(w) for c, w, r in zip(cells, widths, right, strict=True)]
        return "  ".join(parts).rstrip()

    out = [title, "=" * len(title)] if title else []
    out += [line(header), line(["-" * w for w in widths])]
    out += [line(r) for r in rows]
    return "\n".join(out)


def _markdown(header: Sequence[str], rows: Sequence[Sequence[str]], title: str | None) -> str:
    right = [i > 0 and all(_is_number(r[i]) or not r[i] for r in rows) for i in range(len(header))]

    def line(cells: Sequence[str]) -> str:
        return "| " + " | ".join(c.replace("|", "\\|") for c in cells) + " |"

    out = [f"### {title}", ""] if title else []
    out += [line(header), "|" + "|".join("---:" if r else "---" for r in right) + "|"]
    out += [line(r) for r in rows]
    return "\n".join(out)


def _csv(header: Sequence[str], rows: Sequence[Sequence[str]]) -> str:
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(header)
    writer.writerows(rows)
    return buf.getvalue().rstrip("\n")


def render_grid(
    header: Sequence[str], rows: Sequence[Sequence[str]], fmt: str = "table", title: str | None = None
) -> str:
    """Render rows of text cells.

    Args:
        header: Column titles.
        rows: Cells, one list per row, as many as ``header``.
        fmt: ``"table"`` (aligned plain text; numeric columns right-aligned), ``"markdown"``
            (a GitHub table under a ``###`` title) or ``"csv"`` (no title).
        title: A title above the table.

    Raises:
        ConfigError: If ``fmt`` is not one of :data:`GRID_FORMATS`.
    """
    if fmt == "table":
        return _table(header, rows, title)
    if fmt == "markdown":
        return _markdown(header, rows, title)
    if fmt == "csv":
        return _csv(header, rows)
    raise ConfigError(f"unknown table format {fmt!r}; valid: {', '.join(GRID_FORMATS)}, json")


def json_safe(value: Any) -> Any:
    """``value`` with NaN and infinities replaced by ``None``, enums by their values, tuples by lists."""
    from enum import Enum

    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, Enum):
        return value.value
    if isinstance(value, dict):
        return {str(json_safe(k)): json_safe(v) for k, v in value.items()}
    if isinstance(value, (list, tuple, frozenset, set)):
        items = sorted(value) if isinstance(value, (set, frozenset)) else value
        return [json_safe(v) for v in items]
    return value
