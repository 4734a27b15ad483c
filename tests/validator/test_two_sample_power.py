"""The building-level two-sample test has power: it tells real plans from buildings unlike them.

A test that cannot tell the shared real plans from the paper model's wing layout (thin wings
around courts, half the floor on corridors, twice the real room density: docs/realism.md,
"The baseline") would pass any generator; one that tells real plans from real plans would
fail every generator. Both ends are checked on the shared plans.
"""

from __future__ import annotations

import warnings

import pytest

from realistic_indoor.generator import generate_like
from realistic_indoor.io import load
from realistic_indoor.validator.two_sample import split_half_accuracy, two_sample_test


def _real(folder):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # repaired real plans say so; not what is tested here
        return [(f.stem, load(f)) for f in sorted(folder.glob("*.xml"))]


@pytest.mark.parametrize("kind", ["office", "school"])
def test_building_probe__tells_real_plans_from_paper_wing_twins(real_plans_dir, kind):
    plans = _real(real_plans_dir / kind)
    twins = [t.building for t in generate_like(plans, kind, 4, seed=0, model="paper", layout="wings")]
    result = two_sample_test([b for _, b in plans], twins, features="building", names=("real", "paper"))
    assert result.accuracy >= 0.85, result.sentence()


@pytest.mark.parametrize("kind", ["office", "school"])
def test_building_probe__real_plans_against_real_plans_stay_near_chance(real_plans_dir, kind):
    mean, _spread = split_half_accuracy([b for _, b in _real(real_plans_dir / kind)], features="building")
    assert mean <= 0.6
