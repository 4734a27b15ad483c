"""Where an environment's buildings come from: one small tagged type, :data:`BuildingSource`.

Four kinds, each a frozen dataclass:

- :class:`GeneratedBuildings`: a new building each episode from a generator named by building
  type (``"office"``, ``"school"``, ``"house"``, ``"random"``), with its area and options;
- :class:`CustomGenerator`: a new building each episode from any callable ``rng -> Building``;
- :class:`FixedBuilding`: the same building every episode;
- :class:`PlanFile`: the building of a plan file, read once when the environment is built.

:func:`as_source` turns the shorthand values ``EnvConfig(source=...)`` also takes into one, and
:func:`source_from_keywords` maps the older keywords (``building_type``, ``area_m2``,
``generator_params``, ``generator``, ``building``, ``plan_path``) onto a source.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace
from os import PathLike
from pathlib import Path
from typing import TYPE_CHECKING, Any, Union

from realistic_indoor.building.admit import admit_building
from realistic_indoor.building.building import Building
from realistic_indoor.errors import ConfigError
from realistic_indoor.generator.base import GENERATOR_NAMES

if TYPE_CHECKING:
    import numpy as np

__all__ = [
    "GENERATED_KEYWORDS",
    "SOURCE_KEYWORDS",
    "BuildingSource",
    "CustomGenerator",
    "FixedBuilding",
    "GeneratedBuildings",
    "PlanFile",
    "as_source",
    "episode_building",
    "source_from_keywords",
]

GENERATED_KEYWORDS = ("building_type", "area_m2", "generator_params")
"""Older ``EnvConfig`` keywords that set a :class:`GeneratedBuildings` source's fields."""

SOURCE_KEYWORDS = ("generator", "building", "plan_path")
"""Older ``EnvConfig`` keywords that each give a whole source (at most one at a time)."""


@dataclass(frozen=True)
class GeneratedBuildings:
    """A new building each episode, from the generator named by ``building_type``.

    Attributes:
        building_type: ``"office"``, ``"school"``, ``"house"`` or ``"random"`` (the
            World-Generator-like baseline).
        area_m2: Floor area asked of the generator (m2); ``None`` for its default.
        params: More keyword arguments for the generator (e.g. ``{"model": "paper"}``; for
            ``"random"``, ``width_units``/``height_units`` fix the grid and override the area).
    """

    building_type: str = "office"
    area_m2: float | None = None
    params: Mapping[str, Any] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if self.building_type not in GENERATOR_NAMES:
            raise ConfigError(
                f"EnvConfig.building_type: unknown building type {self.building_type!r}; "
                f"valid types: {', '.join(GENERATOR_NAMES)}"
            )
        area = self.area_m2
        if area is not None and (
            isinstance(area, bool)
            or not isinstance(area, (int, float))
            or not math.isfinite(area)
            or area <= 0
        ):
            raise ConfigError(f"EnvConfig.area_m2 must be a positive number of m2 or None, got {area!r}")
        if not isinstance(self.params, Mapping):
            raise ConfigError(f"EnvConfig.generator_params must be a mapping, got {self.params!r}")

    def generator(self) -> Callable[[np.random.Generator], Building]:
        """The named generator with the area and options.

        Raises:
            ConfigError: If the generator rejects its options.
        """
        from realistic_indoor.generator import make_generator

        params: dict[str, Any] = dict(self.params)
        grid_given = "width_units" in params or "height_units" in params
        if self.area_m2 is not None and not grid_given:
            params["area_m2"] = self.area_m2
        return make_generator(self.building_type, **params)


@dataclass(frozen=True)
class CustomGenerator:
    """A new building each episode from any callable ``rng -> Building``.

    Attributes:
        function: The generator (picklable, for vector environments that run in processes).
    """

    function: Callable[[np.random.Generator], Building]

    def __post_init__(self) -> None:
        if not callable(self.function):
            raise ConfigError(
                f"EnvConfig.generator must be a callable rng -> Building, got {self.function!r}"
            )

    def generator(self) -> Callable[[np.random.Generator], Building]:
        """The callable itself."""
        return self.function


@dataclass(frozen=True, repr=False)
class FixedBuilding:
    """The same building every episode (e.g. a real plan); also a picklable generator of it.

    Attributes:
        building: The building every episode runs in.
    """

    building: Building

    def __post_init__(self) -> None:
        if not isinstance(self.building, Building):
            raise ConfigError(f"EnvConfig.building must be a Building, got {type(self.building).__name__}")
        object.__setattr__(self, "building", admit_building(self.building, "EnvConfig.building"))

    def __call__(self, rng: np.random.Generator) -> Building:
        """Return the building; ``rng`` is not used."""
        return self.building

    def __repr__(self) -> str:
        return f"FixedBuilding({self.building.building_type.value}, {len(self.building.rooms)} rooms)"

    def generator(self) -> Callable[[np.random.Generator], Building]:
        """Itself: a generator that always returns the building."""
        return self


@dataclass(frozen=True)
class PlanFile:
    """The building of a plan file (any format :func:`realistic_indoor.io.load` reads).

    Attributes:
        path: The file; read when an environment is built, then the building of every episode.
    """

    path: str | Path

    def __post_init__(self) -> None:
        if not isinstance(self.path, (str, PathLike)):
            raise ConfigError(f"EnvConfig.plan_path must be a file path, got {self.path!r}")

    def generator(self) -> Callable[[np.random.Generator], Building]:
        """A :class:`FixedBuilding` of the file's building.

        Raises:
            PlanFormatError: If the file cannot be read.
        """
        from realistic_indoor.io import load

        return FixedBuilding(load(self.path))


BuildingSource = Union[GeneratedBuildings, CustomGenerator, FixedBuilding, PlanFile]  # noqa: UP007
"""Where an environment's buildings come from: one of the four kinds above."""

_KINDS = (GeneratedBuildings, CustomGenerator, FixedBuilding, PlanFile)


def episode_building(building: object, given: bool = False) -> Building:
    """``building`` as an episode's building: given in ``reset``'s options or drawn from a source.

    Args:
        building: The building.
        given: Whether the user gave it (``reset(options={"building": ...})``): such a building
            passes :func:`~realistic_indoor.building.admit_building`, as plans read from files
            do; drawn ones are the source's (generated, or checked when the source was made).

    Raises:
        ConfigError: If it is not a :class:`~realistic_indoor.building.Building`.
        PlanFormatError: If a given building is refused by the gate.
    """
    if not isinstance(building, Building):
        raise ConfigError(f"the building of an episode must be a Building, got {type(building).__name__}")
    if given:
        return admit_building(building, "reset(options['building'])")
    return building


def as_source(value: object) -> BuildingSource:
    """A source from ``EnvConfig(source=...)``'s value.

    Args:
        value: A source; or a shorthand: a building type name (``"office"``), a mapping of
            :class:`GeneratedBuildings` fields, a :class:`Building`, a plan file's path (a
            ``Path``, or a string that is not a building type) or a callable ``rng -> Building``.

    Raises:
        ConfigError: If ``value`` is none of these.
    """
    if isinstance(value, _KINDS):
        return value
    if isinstance(value, Building):
        return FixedBuilding(value)
    if isinstance(value, str):
        return GeneratedBuildings(value) if value in GENERATOR_NAMES else PlanFile(value)
    if isinstance(value, PathLike):
        return PlanFile(value)
    if isinstance(value, Mapping):
        unknown = sorted(set(value) - {"building_type", "area_m2", "params"})
        if unknown:
            raise ConfigError(
                f"EnvConfig.source: unknown key {unknown[0]!r}; keys: building_type, area_m2, params"
            )
        return GeneratedBuildings(**value)
    if callable(value):
        return CustomGenerator(value)
    raise ConfigError(
        f"EnvConfig.source must be a building type, a Building, a plan file's path or a callable "
        f"rng -> Building, got {type(value).__name__}"
    )


def source_from_keywords(source: BuildingSource, keywords: Mapping[str, Any]) -> BuildingSource:
    """Apply the older keywords to ``source`` (those not ``None``).

    ``generator``, ``building`` or ``plan_path`` (at most one) replaces the source.
    ``building_type`` makes it a :class:`GeneratedBuildings` of that type; ``area_m2`` and
    ``generator_params`` change a :class:`GeneratedBuildings` source's area and options.

    Raises:
        ConfigError: If two whole sources are given, or generator options are given for a
            source that does not generate (they would be ignored).
    """
    whole = [k for k in SOURCE_KEYWORDS if keywords.get(k) is not None]
    named = {k: keywords[k] for k in GENERATED_KEYWORDS if keywords.get(k) is not None}
    if len(whole) > 1:
        raise ConfigError(
            f"EnvConfig: give at most one building source, got {' and '.join(whole)}; "
            "building fixes one building, plan_path reads one, generator draws one per episode"
        )
    if whole:
        if named:
            raise ConfigError(
                f"EnvConfig: {', '.join(named)} set the named generator's buildings, "
                f"not those of {whole[0]}; remove {' and '.join(named)}"
            )
        kind = {"generator": CustomGenerator, "building": FixedBuilding, "plan_path": PlanFile}[whole[0]]
        return kind(keywords[whole[0]])
    if not named:
        return source
    if not isinstance(source, GeneratedBuildings):
        if "building_type" not in named:
            raise ConfigError(
                f"EnvConfig: {', '.join(named)} apply to buildings drawn by a named generator, "
                f"but the building source is {source!r}; give building_type too, or remove them"
            )
        source = GeneratedBuildings()
    fields = {"params" if k == "generator_params" else k: v for k, v in named.items()}
    return replace(source, **fields)
