"""Import one of the repository's scripts (``experiments/``, ``scripts/``) as a module, for its tests."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from types import ModuleType

ROOT = Path(__file__).resolve().parents[2]
"""The repository's root folder."""


def load_script(relative: str) -> ModuleType:
    """The script at ``ROOT / relative``, executed as a module named after its file.

    The module is registered in ``sys.modules`` first: dataclasses look their module up.
    """
    path = ROOT / relative
    spec = importlib.util.spec_from_file_location(path.stem, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module
