"""Realistic generators of offices and schools (wing layouts driven by a building-type model)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, ClassVar

from realistic_indoor.generator.base import DEFAULT_AREAS_M2, check_area, finish
from realistic_indoor.generator.wings import OFFICE_STYLE, SCHOOL_STYLE, WingStyle, wing_plan
from realistic_indoor.models.building_model import BuildingTypeModel, default_model

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.building.building import Building

__all__ = ["OfficeGenerator", "SchoolGenerator", "model_params"]


def model_params(model: BuildingTypeModel, default: str) -> dict[str, str]:
    """What the metadata says about the model: nothing for the default one, else its name and source."""
    if model is default_model(default):
        return {}
    return {"model": model.name, "model_source": model.source}


@dataclass(frozen=True)
class _WingGenerator:
    """Shared body of the wing-layout generators (see :class:`OfficeGenerator`)."""

    area_m2: float = 2000.0
    model: BuildingTypeModel | None = None

    name: ClassVar[str] = "office"
    style: ClassVar[WingStyle] = OFFICE_STYLE

    def __post_init__(self) -> None:
        area = check_area(self.name, self.area_m2, self.style.min_area_m2, self.style.max_area_m2)
        object.__setattr__(self, "area_m2", area)
        if self.model is not None and not isinstance(self.model, BuildingTypeModel):
            raise TypeError(f"model must be a BuildingTypeModel, not {type(self.model).__name__}")

    @property
    def type_model(self) -> BuildingTypeModel:
        """The model in use: the one given, or the type's default (the paper's Table 1)."""
        return self.model if self.model is not None else default_model(self.name)

    def __call__(self, rng: np.random.Generator) -> Building:
        """A new building of about :attr:`area_m2` drawn with ``rng``."""
        model = self.type_model
        plan, facts = wing_plan(rng, self.area_m2, model, self.style)
        btype = model.building_type.value if self.model is not None else self.name
        params = {"area_m2": self.area_m2, **model_params(model, self.name)}
        return finish(plan, rng, btype, {"generator": self.name, "params": params, **facts})


@dataclass(frozen=True)
class OfficeGenerator(_WingGenerator):
    """Offices: corridors with rooms along them, halls at the entrance and junctions, service cores.

    The footprint is a set of wings on a corridor skeleton (bar, L, T, U, H, E, comb, courtyard
    or deep plan), sized to the requested area; each corridor has a strip of rooms on one or both
    sides, cut into offices, meeting rooms and service cores with sizes drawn from the model.
    Hallways are cut into segments as real plans divide them, halls sit at the entrance and at
    junctions, and doors follow the model's connection frequencies (almost every office opens
    onto a corridor; few rooms connect to each other, and never as a chain).

    Args:
        area_m2: Floor area wanted (m2); the building comes out within about 1% of it. From
            250 to 50,000 m2.
        model: The building-type model (default: the paper's offices). A model fitted to plans of
            another type (see :func:`realistic_indoor.models.fit_model`) gives buildings of that
            type laid out the same way.

    Examples:
        >>> import numpy as np
        >>> b = OfficeGenerator(area_m2=1500)(np.random.default_rng(1))
        >>> b.building_type.value, round(b.area / 100)
        ('office', 15)
    """

    area_m2: float = DEFAULT_AREAS_M2["office"]

    name: ClassVar[str] = "office"
    style: ClassVar[WingStyle] = OFFICE_STYLE


@dataclass(frozen=True)
class SchoolGenerator(_WingGenerator):
    """Schools: classrooms along long corridors, small service rooms opposite, large halls, labs, a gym.

    Same layout as :class:`OfficeGenerator` with a school's conventions: wider corridors, deep
    classroom strips facing shallow strips of small rooms (or the facade), an entrance hall or
    atrium, and a gym beside the wings, reached from a corridor end or a hall.

    Args:
        area_m2: Floor area wanted (m2), from 800 to 50,000 m2 (default 3,000).
        model: The building-type model (default: the paper's schools).
    """

    area_m2: float = DEFAULT_AREAS_M2["school"]

    name: ClassVar[str] = "school"
    style: ClassVar[WingStyle] = SCHOOL_STYLE
