"""The house generator: a house laid out in the layout template's steps (see :mod:`~realistic_indoor.generator.house.steps`)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, ClassVar

from realistic_indoor.generator.base import DEFAULT_AREAS_M2, check_area, finish, model_params
from realistic_indoor.generator.house.steps import HouseLayout
from realistic_indoor.generator.template import lay_out
from realistic_indoor.models.building_model import BuildingTypeModel, default_model

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.building.building import Building

__all__ = ["MAX_AREA_M2", "MIN_AREA_M2", "HouseGenerator"]

MIN_AREA_M2, MAX_AREA_M2 = 50.0, 1000.0
"""Floor areas a house may be asked for (m2)."""


@dataclass(frozen=True)
class HouseGenerator:
    """Single-storey houses with a house's programme: bedrooms and bathrooms along hallways, living rooms by the entrance.

    The rooms come from the programme table for the floor area
    (:mod:`realistic_indoor.generator.house.programme`), laid out as a day zone beside strips
    of hallway with rooms on both sides (:mod:`realistic_indoor.generator.house.layout`).

    Args:
        area_m2: Floor area wanted (m2), from 50 to 1,000 (default 150).
        model: The building-type model whose door habits are used: the chance of an en-suite
            bathroom and of a garden door (default: the paper's houses).

    Examples:
        >>> import numpy as np
        >>> b = HouseGenerator(area_m2=120)(np.random.default_rng(2))
        >>> abs(b.area - 120) < 1  # within a row of 0.1 m grid units
        True
    """

    area_m2: float = DEFAULT_AREAS_M2["house"]
    model: BuildingTypeModel | None = None

    name: ClassVar[str] = "house"

    def __post_init__(self) -> None:
        object.__setattr__(self, "area_m2", check_area("house", self.area_m2, MIN_AREA_M2, MAX_AREA_M2))

    def __call__(self, rng: np.random.Generator) -> Building:
        """A new house of about :attr:`area_m2` drawn with ``rng``."""
        model = self.model if self.model is not None else default_model("house")
        plan, _ = lay_out(HouseLayout(model), rng, self.area_m2)
        params = {"area_m2": self.area_m2, **model_params(model, "house")}
        return finish(plan, rng, "house", {"generator": "house", "params": params})
