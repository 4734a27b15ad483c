"""realistic-indoor: structurally realistic buildings for exploration and search-and-rescue robots.

The main entry points are imported lazily, so ``import realistic_indoor`` stays fast:

- :class:`Building`, :class:`Room`, :class:`Door`, :func:`check_building`: the data model;
- :func:`load`, :func:`save`: files in every supported format;
- :func:`generate`: a realistic office, school or house (see :mod:`realistic_indoor.generator`).

Importing the package registers the Gymnasium ids (``OfficeExplore-v0``, ..., see
:mod:`realistic_indoor.envs`), so ``gym.make("OfficeExplore-v0")`` works after
``import realistic_indoor``; registration imports gymnasium only, not the simulator.
"""

from __future__ import annotations

import importlib
from pathlib import Path
from typing import Any

from realistic_indoor._kernel_sources import refresh_kernel_sources
from realistic_indoor.version import __version__

refresh_kernel_sources(Path(__file__).parent)  # before any numba kernel loads from its cache

_LAZY = {
    "Building": "realistic_indoor.building",
    "Room": "realistic_indoor.building",
    "Door": "realistic_indoor.building",
    "SemanticLabel": "realistic_indoor.building",
    "BuildingType": "realistic_indoor.building",
    "check_building": "realistic_indoor.building",
    "load": "realistic_indoor.io",
    "save": "realistic_indoor.io",
    "generate": "realistic_indoor.generator",
    "regenerate": "realistic_indoor.generator",
}

__all__ = ["__version__", *_LAZY]


def _register_envs() -> None:
    from realistic_indoor.envs.registration import register_envs

    register_envs()


_register_envs()


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'realistic_indoor' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(__all__)
