"""The generator protocol, the registry of generators by name, and checks of their arguments."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, Protocol, runtime_checkable

from realistic_indoor.errors import ConfigError

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.building.building import Building
    from realistic_indoor.generator.plan import Plan
    from realistic_indoor.models.building_model import BuildingTypeModel

__all__ = ["DEFAULT_AREAS_M2", "GENERATOR_NAMES", "Generator", "check_area", "finish", "model_params"]

GENERATOR_NAMES = ("office", "school", "house", "random")
"""Names accepted by :func:`realistic_indoor.generator.generate` and ``make_generator``."""

DEFAULT_AREAS_M2 = {"office": 2000.0, "school": 3000.0, "house": 150.0, "random": 2000.0}
"""Floor area each generator makes when none is given (m2)."""


@runtime_checkable
class Generator(Protocol):
    """Anything that makes a building from a random generator (the environments take these)."""

    def __call__(self, rng: np.random.Generator) -> Building:
        """A new building drawn with ``rng`` (the same state gives the same building)."""
        ...


def check_area(kind: str, area_m2: object, low: float, high: float) -> float:
    """``area_m2`` as a float if it lies in ``[low, high]``.

    Raises:
        ConfigError: If it is not a finite number in range; the message names the range.
    """
    try:
        area = float(area_m2)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise ConfigError(f"{kind} area must be a number of square metres, not {area_m2!r}") from None
    if not math.isfinite(area) or area <= 0:
        raise ConfigError(f"{kind} area must be a positive number of square metres, not {area_m2!r}")
    if area < low:
        raise ConfigError(f"{kind} area {area:g} m2 is too small: the smallest is {low:g} m2")
    if area > high:
        raise ConfigError(f"{kind} area {area:g} m2 is too large: the largest is {high:g} m2")
    return area


def finish(plan: Plan, rng: np.random.Generator, building_type: str, metadata: dict[str, Any]) -> Building:
    """Turn the plan by a random multiple of 90 degrees and/or mirror it, then build it."""
    swap, flip_x, flip_y = (bool(b) for b in rng.random(3) < 0.5)
    plan.transform(swap, flip_x, flip_y)
    return plan.to_building(building_type, metadata)


def model_params(model: BuildingTypeModel, default: BuildingTypeModel) -> dict[str, str]:
    """What the metadata says about the model: nothing for the default one, else its name and source."""
    if model is default:
        return {}
    return {"model": model.name, "model_source": model.source}
