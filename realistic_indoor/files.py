"""Output files that are written whole or not at all, and output paths checked before long work.

Every writer of the package writes to a temporary file beside its target and renames it into
place when the write has succeeded, so a write that fails half way (a full disk, an error, an
interrupt) leaves the previous file intact and no half-written file behind.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Iterable, Iterator
from pathlib import Path
from typing import IO, Any

from realistic_indoor.errors import ConfigError

__all__ = [
    "atomic_path",
    "atomic_write",
    "check_output_dir",
    "check_output_path",
    "write_bytes",
    "write_text",
]


@contextlib.contextmanager
def atomic_path(path: str | Path) -> Iterator[Path]:
    """A temporary path beside ``path`` that replaces ``path`` when the block succeeds.

    For libraries that write to a file name themselves (matplotlib, ElementTree, Stable-Baselines3):
    they write to the temporary path, which keeps ``path``'s suffix so they pick the same format.
    On any exception the temporary file is removed and ``path`` is left as it was.

    Args:
        path: The file to write; its folder is created if missing.

    Yields:
        The temporary path to write to.
    """
    path = Path(path)
    _make_parent(path)
    fd, tmp_name = tempfile.mkstemp(prefix=f".{path.stem}.", suffix=f".tmp{path.suffix}", dir=path.parent)
    os.close(fd)
    tmp = Path(tmp_name)
    try:
        yield tmp
        _commit(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


@contextlib.contextmanager
def atomic_write(path: str | Path, mode: str = "w", **open_args: Any) -> Iterator[IO[Any]]:
    """Open a temporary file beside ``path`` for writing; it replaces ``path`` on success.

    Args:
        path: The file to write; its folder is created if missing.
        mode: ``"w"`` for text or ``"wb"`` for bytes.
        **open_args: Passed to :func:`open` (``encoding``, ``newline``).

    Yields:
        The open file.
    """
    if mode not in ("w", "wb"):
        raise ValueError(f"atomic_write opens files for writing ('w' or 'wb'), not {mode!r}")
    if mode == "w":
        open_args.setdefault("encoding", "utf-8")
    with atomic_path(path) as tmp, open(tmp, mode, **open_args) as f:
        yield f
        f.flush()
        os.fsync(f.fileno())


def write_text(path: str | Path, text: str) -> Path:
    """Write ``text`` (UTF-8) to ``path`` whole or not at all; returns ``path``."""
    with atomic_write(path, "w") as f:
        f.write(text)
    return Path(path)


def write_bytes(path: str | Path, data: bytes) -> Path:
    """Write ``data`` to ``path`` whole or not at all; returns ``path``."""
    with atomic_write(path, "wb") as f:
        f.write(data)
    return Path(path)


def check_output_path(
    path: str | Path,
    option: str = "output",
    suffixes: Iterable[str] | None = None,
    exist_ok: bool = True,
) -> Path:
    """Check, before any long work, that a file can be written at ``path``.

    Args:
        path: The file to be written.
        option: How the user gave the path (``"-o"``, ``"--plot"``), named in the error.
        suffixes: File endings accepted (``".png"``), or ``None`` for any.
        exist_ok: Whether an existing file may be replaced.

    Returns:
        ``path`` as a :class:`~pathlib.Path`.

    Raises:
        ConfigError: If ``path`` is a folder, has an ending not in ``suffixes``, exists while
            ``exist_ok`` is false, or lies in a folder that cannot be created or written.
    """
    path = Path(path)
    if path.is_dir():
        raise ConfigError(f"{option} {path}: is a folder; give a file name inside it")
    if suffixes is not None:
        ends = tuple(s.lower() for s in suffixes)
        if not path.name.lower().endswith(ends):
            raise ConfigError(f"{option} {path}: unknown file type; use one of {', '.join(ends)}")
    if not exist_ok and path.exists():
        raise ConfigError(f"{option} {path}: exists; choose a new name or remove it first")
    check_output_dir(path.parent, option)
    return path


def check_output_dir(folder: str | Path, option: str = "output folder") -> Path:
    """Check that files can be written in ``folder`` (existing, or creatable where it is missing).

    Raises:
        ConfigError: If ``folder`` or an ancestor is a file, or the nearest existing ancestor is not
            writable.
    """
    folder = Path(folder)
    existing = folder
    while not existing.exists() and existing != existing.parent:
        existing = existing.parent
    if not existing.is_dir():
        raise ConfigError(f"{option} {folder}: {existing} is a file, not a folder")
    if not os.access(existing, os.W_OK | os.X_OK):
        raise ConfigError(f"{option} {folder}: no permission to write in {existing}")
    return folder


def _make_parent(path: Path) -> None:
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
    except (FileExistsError, NotADirectoryError):
        raise ConfigError(f"{path}: {path.parent} is not a folder") from None
    except PermissionError:
        raise ConfigError(f"{path}: no permission to create the folder {path.parent}") from None


def _commit(tmp: Path, path: Path) -> None:
    """Give ``tmp`` the permissions a new file gets, then rename it to ``path``."""
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(tmp, 0o666 & ~umask)
    if path.is_dir():
        raise ConfigError(f"{path}: is a folder; give a file name inside it")
    os.replace(tmp, path)
