"""Generated buildings are byte-identical to their recording (made before issue 16's refactor).

Regenerate with ``python tests/generator/recorded_buildings.py`` only when a change is meant to
alter buildings, and say so in the commit.
"""

from __future__ import annotations

import json

import pytest
from recorded_buildings import CASES, DATA, SEEDS, digest

RECORDED = json.loads(DATA.read_text())


@pytest.mark.parametrize("name", sorted(CASES))
def test_generated_building__matches_its_recording(name):
    assert [digest(CASES[name], seed) for seed in SEEDS] == RECORDED[name]


def test_recording__distinguishes_seeds():
    """A recording that gave every seed the same building would not detect a change."""
    for name, digests in RECORDED.items():
        assert len(set(digests)) == len(digests), name
