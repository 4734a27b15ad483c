"""Keep numba's cached kernels in step with the package's sources.

numba stores a compiled kernel (``cache=True``) with a hash of the module that defines it, and
checks only that: a kernel that calls a kernel of another module, or reads a constant of another
module, keeps what it was compiled with after that other module changes. An editable install
updated by ``git pull`` would then run old code in one path and new code in another, silently
(the vector env's map update against the single env's, say). On import the package hashes its
kernel modules and every package module they import, directly or through others; when the hash
differs from the one recorded, it deletes the cached kernels of every kernel module, so that
numba compiles them again on their first call (once, 15-17 s on a 2-core machine).

A process that imported the package before an update and compiles a kernel only after it can
still store the old kernel again: restart such processes after updating.
"""

from __future__ import annotations

import ast
import hashlib
import json
import os
import re
import sys
from pathlib import Path

__all__ = ["KERNEL_MARK", "cache_subfolder", "numba_user_cache", "refresh_kernel_sources"]

KERNEL_MARK = re.compile(rb"@(?:numba\.)?(?:njit|jit|vectorize|guvectorize|cfunc|stencil)\b")
"""What marks a module that defines numba kernels: one of numba's compiling decorators."""
_RECORD = "numba_sources"


def refresh_kernel_sources(package: Path) -> list[Path]:
    """Drop the cached kernels of ``package`` if its kernel modules or what they import changed.

    Never raises: a file that cannot be read counts as empty, and a folder that cannot be
    written is left as it is (the check runs again on the next import).

    The record holds a hash of the modules' time stamps and sizes, so that an unchanged install
    reads no file, and one of the contents that matter, computed again only when the time
    stamps moved. It is kept in the package's ``__pycache__``, or, for a package folder that
    cannot be written (an install whose new version may find the kernels of the old one in
    numba's user-wide cache), in :func:`numba_user_cache`'s parent. Each ``NUMBA_CACHE_DIR`` has
    its own record, as it has its own cached kernels.

    Args:
        package: The package's folder (the one holding ``__init__.py``).

    Returns:
        The cache files deleted: none when nothing that matters changed.
    """
    try:
        record_path = _record_path(package)
        record = _read(record_path)
        files = sorted(f for f in package.rglob("*.py") if not f.name.startswith("."))  # not editors' locks
        stamps = _stamps(package, files)
        if record.get("stamps") == stamps:
            return []
        kernels, digest = _kernel_digest(package, files)
        dropped = [] if record.get("digest") == digest else _drop_cached(kernels)
        _write(record_path, {"digest": digest, "stamps": stamps})
        return dropped
    except (OSError, RuntimeError, ValueError, KeyError):  # e.g. no home folder to find a cache in
        return []


def _stamps(package: Path, files: list[Path]) -> str:
    """A hash of the files' paths, time stamps and sizes (a file gone meanwhile counts as none)."""
    h = hashlib.sha256()
    for f in files:
        try:
            st = f.stat()
            h.update(f"{f.relative_to(package)}:{st.st_mtime_ns}:{st.st_size};".encode())
        except OSError:
            h.update(f"{f.relative_to(package)}:gone;".encode())
    return h.hexdigest()


def _kernel_digest(package: Path, files: list[Path]) -> tuple[list[Path], str]:
    """The kernel modules, and a hash of their contents and of every package module they import."""
    contents = {f: _read_bytes(f) for f in files}
    kernels = [f for f, text in contents.items() if KERNEL_MARK.search(text)]
    hashed = set(kernels)
    pending = list(kernels)
    while pending:  # through the imports, transitively: a constant may be re-exported
        for dep in _imports(package, pending.pop(), contents):
            if dep not in hashed:
                hashed.add(dep)
                pending.append(dep)
    digest = hashlib.sha256()
    for f in sorted(hashed):
        digest.update(str(f.relative_to(package)).encode() + b"\0" + contents[f] + b"\0")
    return kernels, digest.hexdigest()


def _imports(package: Path, module: Path, contents: dict[Path, bytes]) -> set[Path]:
    """The package's modules that ``module`` imports (absolute or relative, anywhere in it)."""
    try:
        tree = ast.parse(contents[module])
    except (SyntaxError, ValueError):
        return set()  # being edited: its text is hashed all the same
    here = module.relative_to(package).parent.parts
    names: list[tuple[str, ...]] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names += [tuple(a.name.split(".")) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = (package.name, *here[: len(here) - node.level + 1])
                base += tuple(node.module.split(".")) if node.module else ()
            else:
                base = tuple((node.module or "").split("."))
            names.append(base)
            names += [(*base, a.name) for a in node.names]  # a name may be a sub-module
    found = set()
    for parts in names:
        if parts[:1] != (package.name,):
            continue
        target = package.joinpath(*parts[1:])
        for candidate in (target.with_suffix(".py"), target / "__init__.py"):
            if candidate in contents:
                found.add(candidate)
        for i in range(2, len(parts)):  # importing a.b.c runs a/__init__ and a/b/__init__
            init = package.joinpath(*parts[1:i], "__init__.py")
            if init in contents:
                found.add(init)
    return found


def _drop_cached(kernels: list[Path]) -> list[Path]:
    """Delete the cached kernels of these modules wherever numba keeps them; the files deleted.

    numba names a module's cache files ``<module>.<function>-<line>.py<version>.nbi`` (index)
    and ``.nbc`` (code), in the module's ``__pycache__``, under ``NUMBA_CACHE_DIR``, or in the
    user's cache folder where the package's folder is not writable.
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
    ``tests/test_kernel_sources.py`` holds them to numba's own.
    """
    folders = [module.parent / "__pycache__"]
    user = numba_user_cache()
    if user is not None:
        folders.append(user / cache_subfolder(module))
    if os.environ.get("NUMBA_CACHE_DIR"):
        folders.append(Path(os.environ["NUMBA_CACHE_DIR"]) / cache_subfolder(module))
    return folders


def cache_subfolder(module: Path) -> str:
    """The sub-folder of a cache folder that numba gives a module's kernels (folder name, SHA-1)."""
    folder = os.path.dirname(os.path.abspath(module))
    return f"{os.path.basename(folder)}_{hashlib.sha1(folder.encode()).hexdigest()}"


def numba_user_cache() -> Path | None:
    """Numba's user-wide cache folder (its ``AppDirs("numba").user_cache_dir``); ``None`` if no home."""
    try:
        if sys.platform == "win32":
            local = os.environ.get("LOCALAPPDATA") or str(Path.home() / "AppData" / "Local")
            return Path(local) / "numba" / "Cache"
        if sys.platform == "darwin":
            return Path.home() / "Library" / "Caches" / "numba"
        return Path(os.getenv("XDG_CACHE_HOME", os.path.expanduser("~/.cache"))) / "numba"
    except (RuntimeError, KeyError):
        return None


def _record_path(package: Path) -> Path:
    """Where the record of ``package`` is kept (see :func:`refresh_kernel_sources`)."""
    setting = hashlib.sha1(os.environ.get("NUMBA_CACHE_DIR", "").encode()).hexdigest()[:12]
    if os.access(package, os.W_OK):
        return package / "__pycache__" / f"{_RECORD}-{setting}.json"
    user = numba_user_cache()
    if user is None:
        raise RuntimeError("no user cache folder for the record")
    key = hashlib.sha1(str(package.resolve()).encode()).hexdigest()[:16]
    return user.parent / "realistic_indoor" / f"{key}-{_RECORD}-{setting}.json"


def _read_bytes(path: Path) -> bytes:
    try:
        return path.read_bytes()
    except OSError:
        return b""


def _read(path: Path) -> dict:
    try:
        record = json.loads(path.read_text())
    except (OSError, ValueError):
        return {}
    return record if isinstance(record, dict) else {}


def _write(path: Path, record: dict) -> None:
    """Write the record through a temporary file, so that a reader never sees half of it."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(f".{os.getpid()}.tmp")
        tmp.write_text(json.dumps(record))
        os.replace(tmp, path)
    except OSError:
        pass  # not written: the check runs again on the next import
