"""Samples of generated buildings shared by the generator tests (drawn once per session)."""

from __future__ import annotations

import numpy as np
import pytest

from realistic_indoor.generator import make_generator

SAMPLE_SIZE = 200
"""Buildings per type in the realism sample (the issue's acceptance size)."""


def draw(kind: str, n: int, area_m2: float | None = None, first_seed: int = 0) -> list:
    """``n`` buildings of a generator at its default (or the given) size, seeds ``first_seed...``."""
    gen = make_generator(kind, area_m2)
    return [gen(np.random.default_rng(seed)) for seed in range(first_seed, first_seed + n)]


@pytest.fixture(scope="session")
def samples():
    """``samples(kind)``: the session's 200 buildings of that generator at default size."""
    cache: dict[str, list] = {}

    def get(kind: str) -> list:
        if kind not in cache:
            cache[kind] = draw(kind, SAMPLE_SIZE)
        return cache[kind]

    return get
