"""Building generators: realistic offices, schools and houses, and a World-Generator-like baseline.

A generator is an object called with a ``numpy.random.Generator`` that returns a
:class:`~realistic_indoor.building.Building` (:class:`Generator`); environments receive one and
draw a new building per episode. :func:`generate` is the one-line convenience::

    b = generate("office", area_m2=2000, seed=7)
    gen = make_generator("school", area_m2=3000)
    b = gen(np.random.default_rng(7))
    b2 = regenerate(b, rooms=["r12", "r13"], seed=3)
    twins = list(generate_like([("plan", real_plan)], "office"))   # same floor area as a plan
"""

from __future__ import annotations

from realistic_indoor.generator.base import DEFAULT_AREAS_M2, GENERATOR_NAMES, Generator
from realistic_indoor.generator.house import HouseGenerator
from realistic_indoor.generator.like import Twin, area_limits, generate_like
from realistic_indoor.generator.make import generate, generate_from, make_generator
from realistic_indoor.generator.random_grid import RandomGridGenerator
from realistic_indoor.generator.regenerate import regenerate
from realistic_indoor.generator.typed import OfficeGenerator, SchoolGenerator

__all__ = [
    "DEFAULT_AREAS_M2",
    "GENERATOR_NAMES",
    "Generator",
    "HouseGenerator",
    "OfficeGenerator",
    "RandomGridGenerator",
    "SchoolGenerator",
    "Twin",
    "area_limits",
    "generate",
    "generate_from",
    "generate_like",
    "make_generator",
    "regenerate",
]
