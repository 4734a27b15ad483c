"""The files a subcommand writes: checked first, never over an input, replaced on request only.

Every subcommand that writes files (generate, convert, render, validate, evaluate, train) checks
all its outputs before it reads a plan or runs anything: an output path that names one of the
command's inputs (the same file by resolved path, symbolic link or hard link) is refused, and so
is an existing output unless ``--overwrite`` is given.
"""

from __future__ import annotations

import argparse
import os
from collections.abc import Iterable, Sequence
from pathlib import Path

from realistic_indoor.errors import ConfigError
from realistic_indoor.files import check_output_path

__all__ = ["add_overwrite_option", "check_new_outputs", "check_output", "companions", "input_named"]


def add_overwrite_option(parser: argparse.ArgumentParser, what: str = "output files") -> None:
    """Add ``--overwrite`` (unless the parser has it): replace ``what`` that exist already."""
    if "--overwrite" not in parser._option_string_actions:
        parser.add_argument(
            "--overwrite", action="store_true", help=f"replace {what} that exist already (default: refuse)"
        )


def same_file(a: Path, b: Path) -> bool:
    """Whether ``a`` and ``b`` name one file: the same resolved path, or the same inode (hard links)."""
    try:
        if a.exists() and b.exists():
            return os.path.samefile(a, b)
    except OSError:
        pass
    return a.resolve() == b.resolve()


def input_named(path: Path, inputs: Iterable[str | os.PathLike[str]]) -> Path | None:
    """The input ``path`` names, or ``None``.

    An input is a file given, or a plan below a folder given (a file with a plan's ending that
    the command reads from that folder).
    """
    from realistic_indoor.io.registry import FORMATS, READABLE

    plan_ends = tuple(e for f in READABLE for e in FORMATS[f][0])
    for source in _expanded(inputs):
        if same_file(path, source):
            return source
        inside = path.name.lower().endswith(plan_ends) and path.exists()
        if inside and source.is_dir() and path.resolve().is_relative_to(source.resolve()):
            return path
    return None


def _expanded(inputs: Iterable[str | os.PathLike[str]]) -> list[Path]:
    """The inputs as paths, quoted glob patterns (``'plans/*.xml'``) replaced by what they match."""
    import glob

    out: list[Path] = []
    for given in inputs:
        text = os.fspath(given)
        matches = glob.glob(text, recursive=True) if glob.has_magic(text) else []
        out += [Path(m) for m in matches] or [Path(text)]
    return out


def companions(path: Path) -> list[Path]:
    """The files a write to ``path`` makes: a ROS map writes ``.pgm`` and ``.yaml`` side by side."""
    name = path.name.lower()
    if name.endswith((".yaml", ".pgm")):
        return [path.with_suffix(".pgm"), path.with_suffix(".yaml")]
    return [path]


def check_output(
    path: str | os.PathLike[str],
    option: str,
    *,
    overwrite: bool,
    inputs: Iterable[str | os.PathLike[str]] = (),
    suffixes: Sequence[str] | None = None,
) -> Path:
    """Check an output file before any work: writable, not an input, new unless ``overwrite``.

    Args:
        path: The file to be written (a ROS map: either of its two files).
        option: How the user gave it (``"-o"``), named in the error.
        overwrite: Whether ``--overwrite`` was given.
        inputs: The command's input files and folders.
        suffixes: Endings accepted, or ``None`` for any.

    Returns:
        ``path`` as a :class:`~pathlib.Path`.

    Raises:
        ConfigError: One line naming the option and the path.
    """
    path = check_output_path(path, option, suffixes)
    check_new_outputs(companions(path), option, overwrite=overwrite, inputs=inputs)
    return path


def check_new_outputs(
    paths: Sequence[Path], option: str, *, overwrite: bool, inputs: Iterable[str | os.PathLike[str]] = ()
) -> None:
    """Refuse writing ``paths`` if one is an input, or (without ``overwrite``) exists already.

    Raises:
        ConfigError: Naming the first such path and, for a batch, how many there are.
    """
    sources = _expanded(inputs)  # globs expanded once, not once per output
    for p in paths:
        source = input_named(p, sources)
        if source is not None:
            raise ConfigError(f"{option} {p}: is an input of this command ({source}); choose another name")
    if overwrite:
        return
    taken = [p for p in paths if p.exists()]
    if taken:
        many = f" ({len(taken)} of the {len(paths)} files to write exist)" if len(paths) > 1 else ""
        raise ConfigError(
            f"{option} {taken[0]}: exists{many}; add --overwrite to replace it, or choose a new name"
        )
