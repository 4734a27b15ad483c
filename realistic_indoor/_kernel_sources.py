"""Keep numba's cached kernels in step with the package's sources.

numba stores a compiled kernel (``cache=True``) with a hash of the module that defines it, and
checks only that: a kernel that calls a kernel of another module, or reads a constant of another
module, keeps what it was compiled with after that other module changes. An editable install
updated by ``git pull`` would then run old code in one path and new code in another, silently
(the vector env's map update against the single env's, say). On import the package hashes its
kernel modules and the package modules they import from; when the hash differs from the one
recorded, it deletes the cached kernels of every kernel module, so that numba compiles them
again on their first call (once, some 15 s).
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import sys
from pathlib import Path

__all__ = ["KERNEL_MARK", "cache_subfolder", "refresh_kernel_sources"]

KERNEL_MARK = b"@njit"
"""What marks a module that defines numba kernels."""
_IMPORT = re.compile(rb"^from realistic_indoor\.([\w.]+) import", re.MULTILINE)
_RECORD = "numba_sources.json"


def refresh_kernel_sources(package: Path) -> list[Path]:
    """Drop the cached kernels of ``package`` if its kernel modules or what they import changed.

    The record holds a hash of the modules' time stamps and sizes, so that an unchanged install
    reads no file, and one of the contents that matter, computed again only when the time
    stamps moved. It is kept in the package's ``__pycache__``, or, for a package folder that
    cannot be written (an install whose new version may find the kernels of the old one in
    numba's user-wide cache), in the user's cache folder (``XDG_CACHE_HOME`` or ``~/.cache``).

    Args:
        package: The package's folder (the one holding ``__init__.py``).

    Returns:
        The cache files deleted: none when nothing that matters changed.
    """
    record_path = _record_path(package)
    record = _read(record_path)
    files = sorted(package.rglob("*.py"))
    stamps = _stamps(package, files)
    if record.get("stamps") == stamps:
        return []
    kernels, digest = _kernel_digest(package, files)
    dropped = [] if record.get("digest") == digest else _drop_cached(kernels)
    _write(record_path, {"digest": digest, "stamps": stamps})
    return dropped


def _drop_cached(kernels: list[Path]) -> list[Path]:
    """Delete the cached kernels of these modules wherever numba keeps them; the files deleted.

    numba names a module's cache files ``<module>.<function>-<line>.py<version>.nbi`` (index)
    and ``.nbc`` (code), in the module's ``__pycache__``, or under ``NUMBA_CACHE_DIR`` or the
    user's cache folder where that is not writable.
    """
    dropped = []
    for f in kernels:
        for folder in _cache_folders(f):
            for cached in (*folder.glob(f"{f.stem}.*.nbi"), *folder.glob(f"{f.stem}.*.nbc")):
                try:
                    cached.unlink()
                    dropped.append(cached)
                except OSError:
                    pass  # gone already (another process), or not ours to delete
    return dropped


def _cache_folders(module: Path) -> list[Path]:
    """Where numba may keep the cached kernels of ``module``, found as numba finds them.

    Written out rather than asked of numba, so that an import does not load numba:
    ``tests/test_kernel_sources.py`` holds the sub-folder's name to numba's own.
    """
    folders = [module.parent / "__pycache__", _user_cache() / "numba" / cache_subfolder(module)]
    if os.environ.get("NUMBA_CACHE_DIR"):
        folders.append(Path(os.environ["NUMBA_CACHE_DIR"]) / cache_subfolder(module))
    return folders


def cache_subfolder(module: Path) -> str:
    """The sub-folder of a cache folder that numba gives a module's kernels (folder name, SHA-1)."""
    folder = os.path.dirname(os.path.abspath(module))
    return f"{os.path.basename(folder)}_{hashlib.sha1(folder.encode()).hexdigest()}"


def _user_cache() -> Path:
    """The user's cache folder: ``XDG_CACHE_HOME`` or ``~/.cache`` (``~/Library/Caches`` on macOS)."""
    if sys.platform == "darwin":
        return Path.home() / "Library" / "Caches"
    return Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache")


def _record_path(package: Path) -> Path:
    """Where the record of ``package`` is kept (see :func:`refresh_kernel_sources`)."""
    if os.access(package, os.W_OK):
        return package / "__pycache__" / _RECORD
    base = (
        os.environ.get("NUMBA_CACHE_DIR") or os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    )
    key = hashlib.sha1(str(package.resolve()).encode()).hexdigest()[:16]
    return Path(base) / "realistic_indoor" / f"{key}-{_RECORD}"


def _stamps(package: Path, files: list[Path]) -> str:
    """A hash of the files' paths, time stamps and sizes."""
    h = hashlib.sha256()
    for f in files:
        st = f.stat()
        h.update(f"{f.relative_to(package)}:{st.st_mtime_ns}:{st.st_size};".encode())
    return h.hexdigest()


def _kernel_digest(package: Path, files: list[Path]) -> tuple[list[Path], str]:
    """The kernel modules, and a hash of their contents and of the package modules they import."""
    contents = {f: f.read_bytes() for f in files}
    kernels = [f for f, text in contents.items() if KERNEL_MARK in text]
    hashed = set(kernels)
    for f in kernels:
        for name in _IMPORT.findall(contents[f]):
            parts = name.decode().split(".")
            module = package.joinpath(*parts)
            hashed.update(c for c in (module.with_suffix(".py"), module / "__init__.py") if c in contents)
    digest = hashlib.sha256()
    for f in sorted(hashed):
        digest.update(str(f.relative_to(package)).encode() + b"\0" + contents[f] + b"\0")
    return kernels, digest.hexdigest()


def _read(path: Path) -> dict:
    try:
        return json.loads(path.read_text())
    except (OSError, ValueError):
        return {}


def _write(path: Path, record: dict) -> None:
    """Write the record through a temporary file, so that a reader never sees half of it."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(f".{os.getpid()}.tmp")
        tmp.write_text(json.dumps(record))
        os.replace(tmp, path)
    except OSError:
        pass  # not written: the check runs again on the next import
