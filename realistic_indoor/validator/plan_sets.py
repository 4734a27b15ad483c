"""Named sets of plans: read from files, folders or glob patterns, checked before they are measured."""

from __future__ import annotations

import glob
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from realistic_indoor.errors import ConfigError, RealisticIndoorError

if TYPE_CHECKING:
    from collections.abc import Iterable, Sequence

    from realistic_indoor.building.building import Building

__all__ = ["PlanSet", "load_plan_set", "plan_files", "plan_problem"]


@dataclass(frozen=True)
class PlanSet:
    """Buildings to be measured together, with a name and where each came from.

    Attributes:
        name: The set's name in reports (``"generated"``, ``"real"``).
        buildings: The buildings.
        sources: One name per building (its file, or generator and seed).
    """

    name: str
    buildings: tuple[Building, ...]
    sources: tuple[str, ...]

    @classmethod
    def of(cls, name: str, buildings: Iterable[Building]) -> PlanSet:
        """A set of buildings in memory; sources from their metadata (``source``, ``generator``/``seed``)."""
        buildings = tuple(buildings)
        return cls(name, buildings, tuple(_source_of(b, f"{name}[{i}]") for i, b in enumerate(buildings)))

    def __len__(self) -> int:
        return len(self.buildings)


def _source_of(b: Building, default: str) -> str:
    meta = b.metadata
    if meta.get("source"):
        return str(meta["source"])
    if meta.get("generator"):
        seed = f" seed {meta['seed']}" if "seed" in meta else ""
        return f"{meta['generator']}{seed}"
    return default


def _readable(path: Path) -> bool:
    from realistic_indoor.io.registry import FORMATS, format_of

    try:
        return FORMATS[format_of(path)][2]
    except RealisticIndoorError:
        return False


def plan_files(spec: str | Path) -> list[Path]:
    """The plan files a command-line argument names.

    Args:
        spec: A file (taken as is; reading it reports a wrong format), a folder (every readable
            plan below it, recursively, hidden files left out) or a glob pattern (``maps/*.json``,
            ``**`` allowed; readable files only).

    Returns:
        The files, sorted by path.

    Raises:
        ConfigError: If ``spec`` is neither a file, a folder nor a pattern matching a plan.
    """
    path = Path(spec)
    if path.is_file():
        return [path]
    if path.is_dir():
        found: Iterable[Path] = path.rglob("*")
    elif glob.has_magic(str(spec)):
        found = (Path(p) for p in glob.glob(str(spec), recursive=True))
    else:
        raise ConfigError(f"{spec}: no such file or folder")
    return sorted(p for p in found if p.is_file() and not p.name.startswith(".") and _readable(p))


def load_plan_set(specs: str | Path | Sequence[str | Path], name: str | None = None) -> PlanSet:
    """Read every plan that ``specs`` name (files, folders, globs; see :func:`plan_files`).

    Args:
        specs: One or several files, folders or patterns (a folder's plans form one set).
        name: The set's name (default: the first spec's file or folder name).

    Raises:
        ConfigError: If no readable plan is found.
        PlanFormatError: If a plan cannot be read.
    """
    from realistic_indoor.io import load

    specs = [specs] if isinstance(specs, (str, Path)) else list(specs)
    name = name or (Path(str(specs[0])).stem if specs else "plans")
    files = list(dict.fromkeys(f for spec in specs for f in plan_files(spec)))
    if not files:
        where = ", ".join(str(s) for s in specs) or "nothing"
        raise ConfigError(f"set {name!r}: no readable plans in {where} (plans end in .json or .xml)")
    return PlanSet(name, tuple(load(f) for f in files), tuple(str(f) for f in files))


def plan_problem(b: Building) -> str | None:
    """Why a plan cannot be measured (no rooms, no doors), or ``None`` if it can."""
    if not b.rooms:
        return "the plan has no rooms"
    if not b.doors:
        return "the plan has no doors, so doorways and connectivity cannot be measured"
    return None
