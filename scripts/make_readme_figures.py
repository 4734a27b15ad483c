"""Draw the README's pictures into ``docs/images/``.

Writes ``real_office.png`` (a real office from ``../shared``) and, once the generator exists,
``generated_office.png``, ``generated_school.png``, ``generated_house.png`` and
``random_baseline.png`` (the World-Generator-like random map). What cannot be made yet (no shared data, no generator) is skipped and
said so. Every picture is checked to stay under the README's size budget.

Usage::

    .venv/bin/python scripts/make_readme_figures.py [--out docs/images] [--seed 7]
"""

from __future__ import annotations

import argparse
import importlib
import sys
from collections.abc import Callable
from pathlib import Path

from realistic_indoor.io import save

ROOT = Path(__file__).resolve().parents[1]
REAL_OFFICE = ROOT.parent / "shared" / "data" / "real_floorplans" / "office" / "floor-1024x523.xml"
MAX_BYTES = 300_000
PICTURE = {"dpi": 130, "size_in": 9.0, "show_functions": True}


def real_office(seed: int):
    """A real office floor (entrances inferred: the files have none)."""
    from realistic_indoor.io.floorplan_xml import read

    if not REAL_OFFICE.is_file():
        raise LookupError(f"shared plans not found at {REAL_OFFICE}")
    return read(REAL_OFFICE, infer_entrances=True)


def _generated(name: str) -> Callable[[int], object]:
    """A maker of a generated building (``name``: office, school, house, or random)."""

    def make(seed: int):
        from realistic_indoor.errors import ConfigError

        try:
            generate = importlib.import_module("realistic_indoor.generator").generate
        except (ImportError, AttributeError) as e:
            raise LookupError(f"realistic_indoor.generator.generate is not there yet ({e})") from None
        try:
            return generate(name, seed=seed)
        except ConfigError as e:
            raise LookupError(str(e)) from None

    return make


FIGURES: dict[str, Callable[[int], object]] = {
    "real_office.png": real_office,
    "generated_office.png": _generated("office"),
    "generated_school.png": _generated("school"),
    "generated_house.png": _generated("house"),
    "random_baseline.png": _generated("random"),
}


def main(argv: list[str] | None = None) -> int:
    """Write every picture that can be made; exit code 1 if one is over the size budget."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=ROOT / "docs" / "images", help="output folder")
    parser.add_argument("--seed", type=int, default=7, help="seed of the generated buildings")
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    too_big = []
    for name, make in FIGURES.items():
        try:
            building = make(args.seed)
        except LookupError as e:
            print(f"skipped {name}: {e}")
            continue
        (path,) = save(building, args.out / name, **PICTURE)
        size = path.stat().st_size
        print(f"wrote {path} ({size / 1000:.0f} kB, {len(building.rooms)} rooms)")
        if size > MAX_BYTES:
            too_big.append(name)
    if too_big:
        print(f"over {MAX_BYTES / 1000:.0f} kB: {', '.join(too_big)}", file=sys.stderr)
    return 1 if too_big else 0


if __name__ == "__main__":
    sys.exit(main())
