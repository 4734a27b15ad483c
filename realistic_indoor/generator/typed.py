"""Realistic generators of offices and schools (block or wing layouts driven by a building-type model)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, ClassVar

from realistic_indoor.errors import ConfigError
from realistic_indoor.generator.base import DEFAULT_AREAS_M2, check_area, finish, model_params
from realistic_indoor.generator.blocks import OFFICE_BLOCKS, SCHOOL_BLOCKS, BlockStyle, block_layout
from realistic_indoor.generator.rooms.style import OFFICE_STYLE, SCHOOL_STYLE, TypeStyle
from realistic_indoor.generator.template import lay_out
from realistic_indoor.generator.wings import OFFICE_WINGS, SCHOOL_WINGS, WingStyle, wing_layout
from realistic_indoor.models.building_model import BuildingTypeModel, default_model, real_model

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.building.building import Building

__all__ = ["LAYOUTS", "MODEL_NAMES", "OfficeGenerator", "SchoolGenerator"]

LAYOUTS = ("blocks", "wings")
"""Layouts of offices and schools: compact blocks of double-loaded and ring corridors (the
default), or wings along a corridor skeleton (the paper's Table-1 reproduction)."""

MODEL_NAMES = ("real", "paper")
"""Named models: fitted to the shared real plans (the default), or the paper's Table 1."""


@dataclass(frozen=True)
class _TypedGenerator:
    """Shared body of the office and school generators (see :class:`OfficeGenerator`)."""

    area_m2: float = 2000.0
    model: BuildingTypeModel | str | None = None
    layout: str | None = None

    name: ClassVar[str] = "office"
    style: ClassVar[TypeStyle] = OFFICE_STYLE
    blocks: ClassVar[BlockStyle] = OFFICE_BLOCKS
    wings: ClassVar[WingStyle] = OFFICE_WINGS

    def __post_init__(self) -> None:
        area = check_area(self.name, self.area_m2, self.style.min_area_m2, self.style.max_area_m2)
        object.__setattr__(self, "area_m2", area)
        if isinstance(self.model, str) and self.model not in MODEL_NAMES:
            raise ConfigError(
                f"unknown model {self.model!r}; valid: {', '.join(MODEL_NAMES)} or a BuildingTypeModel"
            )
        if self.model is not None and not isinstance(self.model, (BuildingTypeModel, str)):
            raise TypeError(f"model must be a BuildingTypeModel or a name, not {type(self.model).__name__}")
        if self.layout is not None and self.layout not in LAYOUTS:
            raise ConfigError(f"unknown layout {self.layout!r}; valid: {', '.join(LAYOUTS)}")

    @property
    def type_model(self) -> BuildingTypeModel:
        """The model in use: the one given, the paper's Table 1 (``"paper"``), else the real plans'."""
        if isinstance(self.model, BuildingTypeModel):
            return self.model
        return default_model(self.name) if self.model == "paper" else real_model(self.name)

    @property
    def layout_name(self) -> str:
        """The layout in use: the one given, else wings for the paper's model and blocks otherwise."""
        return self.layout or ("wings" if self.model == "paper" else "blocks")

    def __call__(self, rng: np.random.Generator) -> Building:
        """A new building of about :attr:`area_m2` drawn with ``rng``."""
        model = self.type_model.at_area(self.area_m2, rng)
        if self.layout_name == "wings":
            layout = wing_layout(model, self.style, self.wings)
        else:
            layout = block_layout(model, self.style, self.blocks)
        plan, painted = lay_out(layout, rng, self.area_m2)
        custom = isinstance(self.model, BuildingTypeModel)
        btype = model.building_type.value if custom else self.name
        params = {"area_m2": self.area_m2, **model_params(self.type_model, real_model(self.name))}
        if self.layout is not None:
            params["layout"] = self.layout
        return finish(plan, rng, btype, {"generator": self.name, "params": params, "shape": painted.shape})


@dataclass(frozen=True)
class OfficeGenerator(_TypedGenerator):
    """Offices: compact blocks of rooms on double-loaded and ring corridors, halls, service cores.

    The default layout (``"blocks"``) makes the compact deep plans real offices have: one block
    whose depth holds one corridor with rooms on both sides, or two or more corridors joined
    into a ring around cores of rooms and halls, corridors crossing the cores every 30-55 m,
    facade strips stepped back or left out at one end. The block's proportions are drawn, its
    length solved for the floor area. Strips are cut into offices, meeting rooms and service
    cores with sizes drawn from the model; offices go to rooms with windows, rooms inside the
    block get meeting rooms, storage and services; doors follow the model's connection
    frequencies (almost every office opens onto a corridor; few rooms connect to each other,
    and never as a chain). The ``"wings"`` layout lays thin wings along a corridor skeleton
    (bar, L, T, U, H, E, comb, courtyards) and, with the paper's model, reproduces the paper's
    Table 1.

    Args:
        area_m2: Floor area wanted (m2); the building comes out within about 1% of it. From
            250 to 50,000 m2.
        model: The building-type model: ``None`` or ``"real"`` for the one fitted to the shared
            real offices (:func:`~realistic_indoor.models.real_model`), ``"paper"`` for the
            paper's Table 1, or a :class:`~realistic_indoor.models.BuildingTypeModel` (for
            example fitted to plans of another type with :func:`~realistic_indoor.models.fit_model`).
        layout: ``"blocks"`` or ``"wings"`` (default: wings with ``model="paper"``, else blocks).

    Examples:
        >>> import numpy as np
        >>> b = OfficeGenerator(area_m2=1500)(np.random.default_rng(1))
        >>> b.building_type.value, round(b.area / 100)
        ('office', 15)
    """

    area_m2: float = DEFAULT_AREAS_M2["office"]

    name: ClassVar[str] = "office"
    style: ClassVar[TypeStyle] = OFFICE_STYLE


@dataclass(frozen=True)
class SchoolGenerator(_TypedGenerator):
    """Schools: classrooms on both sides of corridors, halls, labs, a gym; courtyards in larger ones.

    Same layouts as :class:`OfficeGenerator` with a school's conventions: wider corridors,
    deeper classroom strips, core sections left open as courtyards, an entrance hall or atrium,
    and a gym beside the block, reached from a corridor end or a hall. Small schools are one
    corridor with classrooms, toilets and stores on both sides; the gym comes in between 600
    and 1,200 m2 (none below, always above), as in the real school plans, which have no
    gym-sized room under about 1,000 m2. Large schools of the block layout may also get an
    auditorium (from 2,500 m2) and a canteen (from 1,500 m2) beside the block, as about half
    of the real ones of those sizes have (``BlockStyle.more_annexes``).

    Args:
        area_m2: Floor area wanted (m2), from 300 to 50,000 m2 (default 3,000).
        model: ``None`` or ``"real"`` (fitted to the shared real schools), ``"paper"`` or a
            :class:`~realistic_indoor.models.BuildingTypeModel`.
        layout: ``"blocks"`` or ``"wings"`` (default: wings with ``model="paper"``, else blocks).
    """

    area_m2: float = DEFAULT_AREAS_M2["school"]

    name: ClassVar[str] = "school"
    style: ClassVar[TypeStyle] = SCHOOL_STYLE
    blocks: ClassVar[BlockStyle] = SCHOOL_BLOCKS
    wings: ClassVar[WingStyle] = SCHOOL_WINGS
