"""Cached numba kernels are compiled again when a kernel module or what it imports changes."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from realistic_indoor._kernel_sources import cache_subfolder, refresh_kernel_sources

KERNEL = b"""from realistic_indoor.consts import LIMIT
from numba import njit


@njit(cache=True)
def clip(x):
    return min(x, LIMIT)
"""


@pytest.fixture
def package(tmp_path):
    """A package holding a kernel module, the module whose constant it reads, and another one."""
    root = tmp_path / "realistic_indoor"
    root.mkdir()
    (root / "__init__.py").write_bytes(b"")
    (root / "kernels.py").write_bytes(KERNEL)
    (root / "consts.py").write_bytes(b"LIMIT = 3\n")
    (root / "other.py").write_bytes(b"NAME = 'a'\n")
    return root


def _cache(root, name):
    """A cached kernel of module ``name`` in its ``__pycache__``, as numba names it."""
    folder = root / "__pycache__"
    folder.mkdir(exist_ok=True)
    files = [folder / f"{name}.clip-5.py311.nbi", folder / f"{name}.clip-5.py311.1.nbc"]
    for f in files:
        f.write_bytes(b"compiled")
    return files


def test_cached_kernels_are_dropped_when_a_kernel_module_or_what_it_imports_changes(package):
    first = _cache(package, "kernels")
    assert sorted(refresh_kernel_sources(package)) == sorted(first)  # no record yet: drop to be sure
    kept = _cache(package, "kernels") + _cache(package, "other")
    assert refresh_kernel_sources(package) == []
    (package / "other.py").write_bytes(b"NAME = 'b'\n")  # no kernel reads it
    assert refresh_kernel_sources(package) == []
    os.utime(package / "consts.py", ns=(0, 10**18))  # a checkout that rewrote it, same content
    assert refresh_kernel_sources(package) == []
    assert all(f.exists() for f in kept)
    (package / "consts.py").write_bytes(b"LIMIT = 4\n")  # the kernel's compiled constant
    assert sorted(refresh_kernel_sources(package)) == sorted(kept[:2])
    assert all(f.exists() for f in kept[2:])  # not a kernel module: its files stay


def test_a_read_only_install_keeps_its_record_in_the_user_cache(package, tmp_path, monkeypatch):
    monkeypatch.setattr(os, "access", lambda path, mode: False)  # as a folder this user cannot write
    monkeypatch.delenv("NUMBA_CACHE_DIR", raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    refresh_kernel_sources(package)
    assert not (package / "__pycache__").exists()
    assert len(list((tmp_path / "cache" / "realistic_indoor").glob("*-numba_sources.json"))) == 1
    (package / "consts.py").write_bytes(b"LIMIT = 5\n")
    cached = _cache(package, "kernels")
    assert sorted(refresh_kernel_sources(package)) == sorted(cached)


def test_cache_subfolder_is_numbas():
    from numba.core.caching import _CacheLocator

    for module in (Path(__file__), Path("/tmp/some where/pkg/mod.py")):
        assert cache_subfolder(module) == _CacheLocator.get_suitable_cache_subpath(str(module))
