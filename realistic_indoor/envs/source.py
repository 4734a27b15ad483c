"""Where an environment's buildings come from: a named generator, any generator, or a fixed building."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from collections.abc import Callable

    import numpy as np

    from realistic_indoor.building.building import Building
    from realistic_indoor.envs.config import EnvConfig

__all__ = ["FixedBuilding", "building_source"]


class FixedBuilding:
    """A generator that always returns the same building (picklable, unlike a lambda).

    Args:
        building: The building every episode runs in.
    """

    def __init__(self, building: Building) -> None:
        self.building = building

    def __call__(self, rng: np.random.Generator) -> Building:
        """Return the building; ``rng`` is not used."""
        return self.building

    def __repr__(self) -> str:
        return f"FixedBuilding({self.building.building_type.value}, {len(self.building.rooms)} rooms)"


def building_source(config: EnvConfig) -> Callable[[np.random.Generator], Building]:
    """The generator an environment draws each episode's building from.

    In order of precedence: ``config.building`` (one fixed building), ``config.plan_path`` (a
    plan file, read once here), ``config.generator`` (any callable ``rng -> Building``), else
    the generator named by ``config.building_type`` with ``config.area_m2`` and
    ``config.generator_params``.

    Raises:
        PlanFormatError: If the plan file cannot be read.
        ConfigError: If the generator rejects its parameters.
    """
    if config.building is not None:
        return FixedBuilding(config.building)
    if config.plan_path is not None:
        from realistic_indoor.io import load

        return FixedBuilding(load(config.plan_path))
    if config.generator is not None:
        return config.generator
    from realistic_indoor.generator import make_generator

    params: dict[str, Any] = dict(config.generator_params)
    grid_given = "width_units" in params or "height_units" in params
    if config.area_m2 is not None and not grid_given:
        params["area_m2"] = config.area_m2
    return make_generator(config.building_type, **params)
