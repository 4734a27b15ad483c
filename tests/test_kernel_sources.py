"""Cached numba kernels are dropped when a kernel module or what it imports changes."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

import realistic_indoor._kernel_sources as kernel_sources
from realistic_indoor._kernel_sources import cache_subfolder, numba_user_cache, refresh_kernel_sources

KERNEL = """{imports}
from numba import njit


@{decorator}
def clip(x):
    return min(x, {limit})
"""


def _package(root: Path, imports: str, limit: str, decorator: str = "njit(cache=True)") -> Path:
    """A package: a kernel module reading ``LIMIT`` of ``consts.py``, a re-export, another module."""
    package = root / "realistic_indoor"
    (package / "sub").mkdir(parents=True)
    (package / "__init__.py").write_text("")
    (package / "sub" / "__init__.py").write_text("from realistic_indoor.sub.values import LIMIT\n")
    (package / "sub" / "values.py").write_text("from realistic_indoor.consts import LIMIT\n")
    (package / "sub" / "kernels.py").write_text(
        KERNEL.format(imports=imports, limit=limit, decorator=decorator)
    )
    (package / "consts.py").write_text("LIMIT = 3\n")
    (package / "other.py").write_text("NAME = 'a'\n")
    return package


def _cache(folder: Path, name: str) -> list[Path]:
    """A cached kernel of module ``name`` in ``folder``, as numba names its files."""
    folder.mkdir(parents=True, exist_ok=True)
    files = [folder / f"{name}.clip-5.py311.nbi", folder / f"{name}.clip-5.py311.1.nbc"]
    for f in files:
        f.write_bytes(b"compiled")
    return files


@pytest.fixture(autouse=True)
def _user_cache(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "user-cache"))
    monkeypatch.delenv("NUMBA_CACHE_DIR", raising=False)


@pytest.mark.parametrize(
    ("imports", "limit", "decorator"),
    [
        ("from realistic_indoor.consts import LIMIT", "LIMIT", "njit(cache=True)"),
        ("import realistic_indoor.consts as c", "c.LIMIT", "njit(cache=True)"),
        ("from ..consts import LIMIT", "LIMIT", "njit(cache=True)"),
        ("from realistic_indoor import consts", "consts.LIMIT", "njit(cache=True)"),
        ("from realistic_indoor.sub import LIMIT", "LIMIT", "njit(cache=True)"),  # re-exported twice
        ("from .values import LIMIT", "LIMIT", "numba.njit(cache=True)"),
        (
            "import numba\nfrom realistic_indoor.consts import LIMIT",
            "LIMIT",
            "jit(nopython=True, cache=True)",
        ),
        ("def _late():\n    from realistic_indoor.consts import LIMIT", "3", "njit(cache=True)"),
    ],
)
def test_a_change_of_a_module_a_kernel_imports_drops_its_cached_kernels(tmp_path, imports, limit, decorator):
    package = _package(tmp_path, imports, limit, decorator)
    first = _cache(package / "sub" / "__pycache__", "kernels")
    assert sorted(refresh_kernel_sources(package)) == sorted(first)  # no record yet: drop to be sure
    kept = _cache(package / "sub" / "__pycache__", "kernels") + _cache(package / "__pycache__", "other")
    assert refresh_kernel_sources(package) == []
    (package / "other.py").write_text("NAME = 'b'\n")  # no kernel reads it
    assert refresh_kernel_sources(package) == []
    os.utime(package / "consts.py", ns=(0, 10**18))  # a checkout that rewrote it, same content
    assert refresh_kernel_sources(package) == []
    assert all(f.exists() for f in kept)
    (package / "consts.py").write_text("LIMIT = 4\n")  # the kernel's compiled constant
    assert sorted(refresh_kernel_sources(package)) == sorted(kept[:2])
    assert all(f.exists() for f in kept[2:])  # not a kernel module: its files stay


def test_kernels_are_dropped_from_numbas_user_cache_and_numba_cache_dir_too(tmp_path, monkeypatch):
    package = _package(tmp_path, "from realistic_indoor.consts import LIMIT", "LIMIT")
    module = package / "sub" / "kernels.py"
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path / "numba-dir"))
    refresh_kernel_sources(package)
    cached = _cache(tmp_path / "user-cache" / "numba" / cache_subfolder(module), "kernels")
    cached += _cache(tmp_path / "numba-dir" / cache_subfolder(module), "kernels")
    (package / "consts.py").write_text("LIMIT = 4\n")
    assert sorted(refresh_kernel_sources(package)) == sorted(cached)


def test_each_numba_cache_dir_keeps_its_own_record(tmp_path, monkeypatch):
    package = _package(tmp_path, "from realistic_indoor.consts import LIMIT", "LIMIT")
    module = package / "sub" / "kernels.py"
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path / "numba-dir"))
    refresh_kernel_sources(package)
    cached = _cache(tmp_path / "numba-dir" / cache_subfolder(module), "kernels")
    monkeypatch.delenv("NUMBA_CACHE_DIR")
    (package / "consts.py").write_text("LIMIT = 4\n")
    refresh_kernel_sources(package)  # an import without the setting: its own caches
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path / "numba-dir"))
    assert sorted(refresh_kernel_sources(package)) == sorted(cached)  # this setting's are stale too


def test_a_read_only_install_keeps_its_record_in_the_user_cache(tmp_path, monkeypatch):
    package = _package(tmp_path, "from realistic_indoor.consts import LIMIT", "LIMIT")
    monkeypatch.setattr(os, "access", lambda path, mode: False)  # as a folder this user cannot write
    refresh_kernel_sources(package)
    assert not (package / "__pycache__").exists()
    assert len(list((tmp_path / "user-cache" / "realistic_indoor").glob("*.json"))) == 1
    (package / "consts.py").write_text("LIMIT = 5\n")
    cached = _cache(
        tmp_path / "user-cache" / "numba" / cache_subfolder(package / "sub" / "kernels.py"), "kernels"
    )
    assert sorted(refresh_kernel_sources(package)) == sorted(cached)


def test_a_broken_package_or_record_never_breaks_the_import(tmp_path, monkeypatch):
    package = _package(tmp_path, "from realistic_indoor.consts import LIMIT", "LIMIT")
    (package / ".#kernels.py").symlink_to(tmp_path / "nowhere")  # an editor's lock file
    (package / "broken.py").write_text("@njit\ndef f(:\n")  # being edited
    refresh_kernel_sources(package)
    next(package.glob("__pycache__/*.json")).write_text("[]")
    real_read = Path.read_bytes
    monkeypatch.setattr(
        Path,
        "read_bytes",
        lambda p: (_ for _ in ()).throw(PermissionError(p)) if p.name == "consts.py" else real_read(p),
    )
    (package / "consts.py").write_text("LIMIT = 4\n")
    refresh_kernel_sources(package)  # no exception
    monkeypatch.setattr(kernel_sources, "numba_user_cache", lambda: None)  # no home folder
    monkeypatch.setattr(os, "access", lambda path, mode: False)
    assert refresh_kernel_sources(package) == []


def test_the_folders_are_numbas(tmp_path, monkeypatch):
    from numba.core.caching import _CacheLocator
    from numba.misc.appdirs import AppDirs

    for module in (Path(__file__), Path("/tmp/some where/pkg/mod.py")):
        assert cache_subfolder(module) == _CacheLocator.get_suitable_cache_subpath(str(module))
    for xdg in (str(tmp_path), None):
        if xdg is None:
            monkeypatch.delenv("XDG_CACHE_HOME", raising=False)
        else:
            monkeypatch.setenv("XDG_CACHE_HOME", xdg)
        assert numba_user_cache() == Path(AppDirs(appname="numba", appauthor=False).user_cache_dir)
