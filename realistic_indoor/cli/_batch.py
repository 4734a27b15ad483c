"""One plan or many: the ``-o FILE`` / ``--out-dir DIR`` options of ``convert`` and ``render``.

``PLAN -o FILE`` writes one file. ``PLANS --out-dir DIR --format EXT`` takes a plan file, a
folder (every readable plan below it, recursively) or a quoted glob pattern and writes one file
per plan into ``DIR``, keeping the folder's sub-folders and each plan's name with the new
ending. A plan that cannot be read or written is left out with a warning naming it and counted
at the end; ``--strict`` stops at the first instead.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from realistic_indoor.cli._outputs import add_overwrite_option, check_new_outputs, companions
from realistic_indoor.errors import ConfigError, RealisticIndoorError

if TYPE_CHECKING:
    from realistic_indoor.building import Building

__all__ = ["add_output_options", "output_names", "run_batch"]

Writer = Callable[["Building", Path], list[Path]]
"""Writes a building to a file; returns the files written."""


def add_output_options(
    parser: argparse.ArgumentParser, formats: Sequence[str], default_format: str | None, what: str
) -> None:
    """Add ``-o``, ``--out-dir``, ``--format``, ``--overwrite`` and ``--strict``.

    Args:
        parser: The subcommand's parser.
        formats: The endings ``--format`` accepts, without the dot (``png``, ``wg.xml``).
        default_format: ``--format``'s default (``None``: required with ``--out-dir``).
        what: What one output is, for the help (``"picture"``).
    """
    out = parser.add_mutually_exclusive_group(required=True)
    out.add_argument("-o", "--output", help=f"the {what} to write for one plan; its ending picks the format")
    out.add_argument(
        "--out-dir",
        metavar="DIR",
        help=f"write one {what} per plan into DIR (PLAN may be a folder or a quoted glob); names keep "
        "the plans' names and sub-folders, with the ending of --format",
    )
    default = f" (default {default_format})" if default_format else ""
    parser.add_argument(
        "--format",
        choices=list(formats),
        default=default_format,
        help=f"ending of the files written with --out-dir{default}",
    )
    add_overwrite_option(parser, f"{what}s")
    parser.add_argument(
        "--strict",
        action="store_true",
        help="stop at the first plan that cannot be read or written, or whose floor-plan XML would "
        "need repair (default: repair it with a warning; with --out-dir leave out an unreadable plan "
        "with a warning)",
    )


def output_names(spec: str, files: Sequence[Path], out_dir: Path, ending: str) -> list[Path]:
    """The file each plan is written to: its path below the folder ``spec`` (or its name), new ending.

    Raises:
        ConfigError: If two plans would be written to the same file (``a.json`` and ``a.xml``),
            or a plan would be written over itself.
    """
    from realistic_indoor.io.registry import FORMATS, READABLE

    folder = Path(spec) if Path(spec).is_dir() else None
    reading_ends = sorted((e for f in READABLE for e in FORMATS[f][0]), key=len, reverse=True)
    names = []
    for f in files:
        rel = f.relative_to(folder) if folder is not None else Path(f.name)
        end = next((e for e in reading_ends if rel.name.lower().endswith(e)), rel.suffix)
        names.append(out_dir / rel.with_name(rel.name[: len(rel.name) - len(end)] + ending))
    seen: dict[Path, Path] = {}
    for f, name in zip(files, names, strict=True):
        if name.resolve() == f.resolve():
            raise ConfigError(f"--out-dir {out_dir}: {f} would be written over itself; choose another folder")
        if name in seen:
            raise ConfigError(f"{seen[name]} and {f} would both be written to {name}; rename one of them")
        seen[name] = f
    return names


def run_batch(args: argparse.Namespace, write: Writer, verb: str) -> int:
    """Read every plan ``args.plan`` names and write each into ``args.out_dir``.

    Args:
        args: With ``plan``, ``out_dir``, ``format``, ``strict`` and ``infer_entrances``.
        write: Writes one building to one file (checked options bound).
        verb: What is done, for the final line (``"converted"``).

    Returns:
        0 when at least one plan was written.

    Raises:
        ConfigError: If the output folder cannot be written, names collide, or no plan could
            be read and written.
        RealisticIndoorError: Under ``--strict``, the first plan's error.
    """
    from realistic_indoor.files import check_output_dir
    from realistic_indoor.validator.plan_sets import PlanBatch, plan_files, read_plan

    if args.format is None:
        raise ConfigError("--out-dir needs --format: the ending of the files to write")
    out = check_output_dir(args.out_dir, "--out-dir")
    files = plan_files(args.plan)
    if not files:
        raise ConfigError(f"{args.plan}: no readable plans (plans end in .json or .xml)")
    targets = dict(zip(files, output_names(args.plan, files, out, "." + args.format), strict=True))
    written = [c for t in targets.values() for c in companions(t)]
    check_new_outputs(written, "--out-dir", overwrite=args.overwrite, inputs=files)

    def reader(path: Path) -> Building:
        return read_plan(path, strict=args.strict, infer_entrances=args.infer_entrances)

    batch = PlanBatch(files, strict=args.strict, reader=reader)
    done = 0
    for path, building in batch:
        try:
            written = write(building, targets[path])
        except RealisticIndoorError as e:
            batch.skip(str(path), _without(str(e), str(targets[path])), e)
            continue
        for w in written:
            print(f"wrote {w}")
        done += 1
    if not done:
        first = batch.skipped[0]
        raise ConfigError(
            f"none of the {len(files)} plans could be {verb}, e.g. {first.source}: {first.reason}"
        )
    line = f"{verb} {done} of {len(files)} plans into {out}"
    if summary := batch.summary():
        line += f"; {summary}"
    print(line, file=sys.stderr)
    return 0


def _without(message: str, target: str) -> str:
    """An error's message without the output file it starts with."""
    return message[len(target) + 2 :] if message.startswith(f"{target}: ") else message
