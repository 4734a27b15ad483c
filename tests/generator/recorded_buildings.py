"""Digests of generated buildings, to show a refactor leaves every building byte-identical.

``python tests/generator/recorded_buildings.py`` writes ``tests/generator/data/recorded_buildings.json``
(recorded at commit 746c667, before the one-home refactor of issue 16);
``test_recorded_buildings.py`` regenerates each building and compares.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Any

DATA = Path(__file__).parent / "data" / "recorded_buildings.json"

CASES: dict[str, dict[str, Any]] = {
    "office": {"building_type": "office"},
    "office-2500": {"building_type": "office", "area_m2": 2500.0},
    "office-wings": {"building_type": "office", "layout": "wings"},
    "office-paper": {"building_type": "office", "model": "paper"},
    "school": {"building_type": "school"},
    "school-6000": {"building_type": "school", "area_m2": 6000.0},
    "school-paper": {"building_type": "school", "model": "paper"},
    "house": {"building_type": "house"},
    "house-220": {"building_type": "house", "area_m2": 220.0},
    "random": {"building_type": "random"},
}
"""Each case: the keywords of :func:`realistic_indoor.generator.generate`, without the seed."""

SEEDS = range(4)


def digest(case: dict[str, Any], seed: int) -> str:
    """SHA-256 of the generated building's JSON text."""
    from realistic_indoor.generator import generate
    from realistic_indoor.io.json_format import dumps

    params = dict(case)
    building_type = params.pop("building_type")
    return hashlib.sha256(dumps(generate(building_type, seed=seed, **params)).encode()).hexdigest()


def record() -> None:
    """Write every case's digests."""
    DATA.parent.mkdir(parents=True, exist_ok=True)
    out = {name: [digest(case, seed) for seed in SEEDS] for name, case in CASES.items()}
    DATA.write_text(json.dumps(out, indent=1) + "\n")


if __name__ == "__main__":
    record()
