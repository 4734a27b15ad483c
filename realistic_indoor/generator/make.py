"""Generators by name: :func:`make_generator`, and :func:`generate` / :func:`generate_from` for one building."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING, Any

import numpy as np

from realistic_indoor.errors import ConfigError
from realistic_indoor.generator.base import DEFAULT_AREAS_M2, GENERATOR_NAMES, Generator
from realistic_indoor.generator.house import HouseGenerator
from realistic_indoor.generator.random_grid import RandomGridGenerator
from realistic_indoor.generator.typed import OfficeGenerator, SchoolGenerator

if TYPE_CHECKING:
    from realistic_indoor.building.building import Building

__all__ = ["generate", "generate_from", "make_generator"]


def make_generator(name: str, area_m2: float | None = None, **options: Any) -> Generator:
    """The generator called ``name`` with its configuration.

    Args:
        name: ``"office"``, ``"school"``, ``"house"`` or ``"random"`` (see
            :data:`GENERATOR_NAMES`); with ``model=`` any other name (``"hospital"``) gives an
            office-like layout driven by that model.
        area_m2: Floor area wanted (m2); default per type (:data:`DEFAULT_AREAS_M2`).
        **options: Further fields of the generator (``model=`` a fitted
            :class:`~realistic_indoor.models.BuildingTypeModel`; for ``"random"``,
            ``width_units=``/``height_units=`` instead of an area).

    Raises:
        ConfigError: For an unknown name (the message lists the valid ones) or bad values.
    """
    key = str(name).strip().lower()
    if key == "random":
        return _random_grid(area_m2, options)
    classes = {"office": OfficeGenerator, "school": SchoolGenerator, "house": HouseGenerator}
    if key not in classes and options.get("model") is not None:
        key = "office"
    if key not in classes:
        raise ConfigError(f"unknown generator {name!r}; valid: {', '.join(GENERATOR_NAMES)}")
    cls = classes[key]
    try:
        return cls(area_m2=DEFAULT_AREAS_M2[key] if area_m2 is None else area_m2, **options)
    except TypeError as e:
        raise ConfigError(f"bad option for the {key} generator: {e}") from None


def _random_grid(area_m2: float | None, options: dict[str, Any]) -> RandomGridGenerator:
    """The baseline from a grid size (``width_units``/``height_units``) or from an area."""
    unknown = set(options) - {"width_units", "height_units"}
    if unknown:
        raise ConfigError(f"bad option for the random generator: {', '.join(sorted(unknown))}")
    if options:
        if area_m2 is not None:
            raise ConfigError(
                "give the random generator either an area or width_units/height_units, not both"
            )
        return RandomGridGenerator(**options)
    return RandomGridGenerator.from_area(DEFAULT_AREAS_M2["random"] if area_m2 is None else area_m2)


def generate(name: str, area_m2: float | None = None, seed: int | None = None, **options: Any) -> Building:
    """Generate one building.

    Args:
        name: Generator name (see :func:`make_generator`).
        area_m2: Floor area wanted (m2); default per type.
        seed: Seed of the random generator; the same name, area, options and seed give the same
            building, byte for byte. ``None`` draws a fresh seed (recorded in the metadata).
        **options: Passed to :func:`make_generator`.

    Returns:
        The building; its metadata records ``generator``, ``params`` and ``seed``.

    Examples:
        >>> b = generate("office", area_m2=1200, seed=3)
        >>> b.metadata["generator"], b.metadata["seed"]
        ('office', 3)
    """
    return generate_from(make_generator(name, area_m2, **options), seed)


def generate_from(generator: Generator, seed: int | None = None) -> Building:
    """Draw one building from ``generator`` with a seed, and record the seed in its metadata.

    Args:
        generator: Any generator (see :class:`Generator`).
        seed: Seed of the random generator; ``None`` draws a fresh one.

    Raises:
        ConfigError: If the seed is not a non-negative integer.
    """
    if seed is None:
        seed = int(np.random.default_rng().integers(2**31))
    elif not isinstance(seed, (int, np.integer)) or isinstance(seed, bool) or seed < 0:
        raise ConfigError(f"seed must be a non-negative integer, not {seed!r}")
    b = generator(np.random.default_rng(int(seed)))
    return replace(b, metadata={**b.metadata, "seed": int(seed)})
