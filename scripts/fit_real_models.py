"""Fit the generator's default office and school models to the shared real plans.

Writes ``realistic_indoor/data/real_models.json``: for each type, the model
:func:`realistic_indoor.models.fit_model` learns from every plan of
``../shared/data/real_floorplans/<type>/`` (plans with implausible scales are left out of the
area statistics, as ``fit_model`` does). The generators read it through
:func:`realistic_indoor.models.real_model`. Realism figures are reported on plans held out of
the fit (``experiments/layout_realism.py``), never on this all-plans model.

Usage::

    .venv/bin/python scripts/fit_real_models.py [--plans ../shared/data/real_floorplans]
"""

from __future__ import annotations

import argparse
import json
import warnings
from pathlib import Path

from realistic_indoor.files import write_text
from realistic_indoor.io import load
from realistic_indoor.models import fit_model

ROOT = Path(__file__).resolve().parents[1]
TYPES = ("office", "school")


def main(argv: list[str] | None = None) -> None:
    """Fit and write the models."""
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--plans", type=Path, default=ROOT.parent / "shared" / "data" / "real_floorplans")
    p.add_argument("--out", type=Path, default=ROOT / "realistic_indoor" / "data" / "real_models.json")
    args = p.parse_args(argv)
    out = {"_about": "Building-type models fitted to the shared real plans by scripts/fit_real_models.py."}
    for t in TYPES:
        files = sorted((args.plans / t).glob("*.xml"))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            model = fit_model([load(f) for f in files], name=t)
        data = model.to_dict()
        data["source"] = f"fitted to the {len(files)} shared real {t} plans ({model.source})"
        out[t] = data
        print(f"{t}: {data['source']}")
    write_text(args.out, json.dumps(out, indent=1, sort_keys=True) + "\n")


if __name__ == "__main__":
    main()
