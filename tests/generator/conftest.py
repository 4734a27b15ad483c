"""Samples of generated buildings shared by the generator tests (drawn once per session)."""

from __future__ import annotations

import numpy as np
import pytest

from realistic_indoor.generator import make_generator

SAMPLE_SIZE = 200
"""Buildings per type in the realism sample (the issue's acceptance size)."""


def draw(kind: str, n: int, area_m2: float | None = None, first_seed: int = 0, **options) -> list:
    """``n`` buildings of a generator at its default (or the given) size, seeds ``first_seed...``."""
    gen = make_generator(kind, area_m2, **options)
    return [gen(np.random.default_rng(seed)) for seed in range(first_seed, first_seed + n)]


@pytest.fixture(scope="session")
def samples():
    """``samples(kind, model=None)``: the session's 200 buildings of that generator at default size.

    ``model="paper"`` draws them with the paper's Table-1 model (and its wing layout) instead of
    the default fitted to real plans; houses have the paper's model either way.
    """
    cache: dict[tuple[str, str | None], list] = {}

    def get(kind: str, model: str | None = None) -> list:
        key = (kind, model if kind in ("office", "school") else None)
        if key not in cache:
            cache[key] = draw(kind, SAMPLE_SIZE, **({"model": key[1]} if key[1] else {}))
        return cache[key]

    return get
