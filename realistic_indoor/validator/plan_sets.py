"""Named sets of plans: read from files, folders or glob patterns, checked before they are measured.

Reading many plans survives bad members: a plan that cannot be read is left out with a
:class:`SkippedPlanWarning` naming it and recorded (:class:`PlanBatch`), unless ``strict`` asks
to stop at the first.
"""

from __future__ import annotations

import glob
import sys
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from realistic_indoor.errors import ConfigError, PlanFormatError, RealisticIndoorError

if TYPE_CHECKING:
    from collections.abc import Callable, Iterable, Iterator, Sequence

    from realistic_indoor.building.building import Building

__all__ = [
    "PlanBatch",
    "PlanSet",
    "SkippedPlan",
    "SkippedPlanWarning",
    "load_plan_set",
    "plan_files",
    "plan_problem",
    "read_plan",
    "show_progress",
    "skipped_summary",
]


class SkippedPlanWarning(UserWarning):
    """A plan of a batch (a folder, a glob) was left out because it cannot be read or used.

    The message is one line: ``skipped PLAN: REASON``.
    """


@dataclass(frozen=True)
class SkippedPlan:
    """A plan left out of a batch.

    Attributes:
        source: The plan's file (as given) or name.
        reason: Why, in words (the reader's error without the file name).
    """

    source: str
    reason: str

    def to_dict(self) -> dict[str, str]:
        """``{"source": ..., "reason": ...}``, as reports and results files record it."""
        return {"source": self.source, "reason": self.reason}


@dataclass(frozen=True)
class PlanSet:
    """Buildings to be measured together, with a name and where each came from.

    Attributes:
        name: The set's name in reports (``"generated"``, ``"real"``).
        buildings: The buildings.
        sources: One name per building (its file, or generator and seed).
        skipped: Plans of the set's files that could not be read, left out.
    """

    name: str
    buildings: tuple[Building, ...]
    sources: tuple[str, ...]
    skipped: tuple[SkippedPlan, ...] = ()

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


def read_plan(path: str | Path, *, strict: bool = False, infer_entrances: bool = False) -> Building:
    """Read one plan of a batch.

    Args:
        path: The plan file.
        strict: Refuse a floor-plan XML file that the reader would have to repair
            (``load(..., strict=True)``) instead of repairing it with warnings.
        infer_entrances: Add exterior doors to a floor-plan XML plan (real plans have none);
            ignored for other formats.

    Raises:
        PlanFormatError: If the plan cannot be read (or, under ``strict``, needs repair).
    """
    from realistic_indoor.io import format_of, load

    options = {"strict": True} if strict else {}  # only floor-plan XML is ever repaired
    if infer_entrances and format_of(path) == "floorplan":
        try:
            return load(path, infer_entrances=True, **options)
        except TypeError:  # a World Generator file named .xml: its reader has no such option
            pass
    return load(path, **options)


def _reason(error: RealisticIndoorError, source: str) -> str:
    """The error's message without the file name it starts with."""
    if isinstance(error, PlanFormatError):
        return f"{error.element}: {error.reason}" if error.element else error.reason
    text = str(error)
    return text[len(source) + 2 :] if text.startswith(f"{source}: ") else text


class PlanBatch:
    """Reads plans one by one; a plan that cannot be read is left out, warned about and recorded.

    ::

        batch = PlanBatch(plan_files("maps/"))
        for path, building in batch:
            ...
        print(batch.summary())        # "skipped 1 of 3 plans: broken.xml", or None

    Args:
        files: The plan files.
        strict: Stop at the first plan that cannot be read (its error is raised) instead.
        reader: Reads one file (default :func:`read_plan` with ``strict``).
        progress: Show a progress bar on stderr while reading (see :func:`show_progress`).
        desc: The progress bar's label.

    Attributes:
        files: The plan files.
        skipped: The plans left out so far, in order.
    """

    def __init__(
        self,
        files: Sequence[str | Path],
        *,
        strict: bool = False,
        reader: Callable[[Path], Building] | None = None,
        progress: bool = False,
        desc: str = "reading plans",
    ) -> None:
        self.files = [Path(f) for f in files]
        self.strict = strict
        self.skipped: list[SkippedPlan] = []
        self._reader = reader or (lambda p: read_plan(p, strict=strict))
        self._progress = progress
        self._desc = desc

    def __len__(self) -> int:
        return len(self.files)

    def __iter__(self) -> Iterator[tuple[Path, Building]]:
        from tqdm import tqdm

        for path in tqdm(self.files, desc=self._desc, unit="plan", disable=not self._progress, leave=False):
            try:
                building = self._reader(path)
            except RealisticIndoorError as e:
                self.skip(str(path), _reason(e, str(path)), e)
                continue
            yield path, building

    def skip(self, source: str, reason: str, error: BaseException | None = None) -> None:
        """Leave a plan out: warn and record it, or under ``strict`` raise.

        Args:
            source: The plan's file or name.
            reason: Why, in words.
            error: The error to raise under ``strict`` (default: a :class:`PlanFormatError`
                from ``source`` and ``reason``).

        Raises:
            RealisticIndoorError: Under ``strict``.
        """
        if self.strict:
            raise error if isinstance(error, RealisticIndoorError) else PlanFormatError(source, reason)
        self.skipped.append(SkippedPlan(source, reason))
        warnings.warn(f"skipped {source}: {reason}", SkippedPlanWarning, stacklevel=2)

    def summary(self) -> str | None:
        """``"skipped 1 of 3 plans: broken.xml"``, or ``None`` when none was skipped."""
        return skipped_summary(self.skipped, len(self.files))


def skipped_summary(skipped: Sequence[SkippedPlan], total: int) -> str | None:
    """``"skipped 2 of 9 plans: a.xml, b.json"`` (file names), or ``None`` when ``skipped`` is empty."""
    if not skipped:
        return None
    names = ", ".join(Path(s.source).name for s in skipped)
    return f"skipped {len(skipped)} of {total} plan{'' if total == 1 else 's'}: {names}"


def show_progress(quiet: bool = False) -> bool:
    """Whether to show progress bars: on a terminal (stderr), unless ``quiet``."""
    return not quiet and sys.stderr.isatty()


def load_plan_set(
    specs: str | Path | Sequence[str | Path],
    name: str | None = None,
    *,
    strict: bool = False,
    progress: bool = False,
) -> PlanSet:
    """Read every plan that ``specs`` name (files, folders, globs; see :func:`plan_files`).

    A plan that cannot be read is left out with a :class:`SkippedPlanWarning` and recorded in
    the set's ``skipped``.

    Args:
        specs: One or several files, folders or patterns (a folder's plans form one set).
        name: The set's name (default: the first spec's file or folder name).
        strict: Stop at the first plan that cannot be read (or that the floor-plan reader would
            have to repair) instead.
        progress: Show a progress bar on stderr while reading.

    Raises:
        ConfigError: If no readable plan is found, or none of the plans found can be read.
        PlanFormatError: Under ``strict``, if a plan cannot be read.
    """
    specs = [specs] if isinstance(specs, (str, Path)) else list(specs)
    name = name or (Path(str(specs[0])).stem if specs else "plans")
    files = list(dict.fromkeys(f for spec in specs for f in plan_files(spec)))
    if not files:
        where = ", ".join(str(s) for s in specs) or "nothing"
        raise ConfigError(f"set {name!r}: no readable plans in {where} (plans end in .json or .xml)")
    batch = PlanBatch(files, strict=strict, progress=progress, desc=f"reading {name}")
    read = list(batch)
    if not read:
        first = batch.skipped[0]
        raise ConfigError(
            f"set {name!r}: none of its {len(files)} plans can be read, e.g. {first.source}: {first.reason}"
        )
    return PlanSet(name, tuple(b for _, b in read), tuple(str(p) for p, _ in read), tuple(batch.skipped))


def plan_problem(b: Building) -> str | None:
    """Why a plan cannot be measured (no rooms, no doors), or ``None`` if it can."""
    if not b.rooms:
        return "the plan has no rooms"
    if not b.doors:
        return "the plan has no doors, so doorways and connectivity cannot be measured"
    return None
