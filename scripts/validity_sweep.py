"""Generate many buildings per type and check every one (``check_building``), at the default size and across the limits.

The test suite samples this (``tests/generator/test_validity.py``); this script runs the full
count and prints, per type and size, how many buildings were checked and which seeds failed.
Exits with status 1 if any building is invalid.

Usage::

    .venv/bin/python scripts/validity_sweep.py [--seeds 10000] [--types office,school,house,random]
"""

from __future__ import annotations

import argparse
import sys
import time

import numpy as np

from realistic_indoor.building import check_building
from realistic_indoor.generator import area_limits, make_generator

SIZES_PER_TYPE = 8
"""Sizes swept between each type's smallest and largest area (log-spaced), besides the default."""


def _sizes(kind: str) -> list[float | None]:
    low, high = area_limits(kind)
    return [None, *np.geomspace(low, min(high, 20_000.0), SIZES_PER_TYPE).round().tolist()]


def sweep(kind: str, area: float | None, seeds: range) -> list[int]:
    """The seeds whose building fails ``check_building``."""
    gen = make_generator(kind, area)
    return [s for s in seeds if check_building(gen(np.random.default_rng(s)))]


def main(argv: list[str] | None = None) -> int:
    """Run the sweep; 0 if every building is valid."""
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--seeds", type=int, default=10_000, help="buildings at the default size per type")
    p.add_argument("--types", default="office,school,house,random", help="generator names")
    args = p.parse_args(argv)
    failed = 0
    for kind in args.types.split(","):
        for area in _sizes(kind):
            n = args.seeds if area is None else max(args.seeds // 20, 10)
            start = time.perf_counter()
            bad = sweep(kind, area, range(n))
            size = "default size" if area is None else f"{area:,.0f} m2"
            print(
                f"{kind:7s} {size:>13s}: {n - len(bad)} of {n} valid ({time.perf_counter() - start:.0f} s)"
                + (f"; failing seeds {bad[:10]}" if bad else ""),
                flush=True,
            )
            failed += len(bad)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
