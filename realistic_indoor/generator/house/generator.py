"""The house generator: a programme drawn for the floor area, laid out, given doors and labels."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import lru_cache
from typing import TYPE_CHECKING, ClassVar

from realistic_indoor.errors import RealisticIndoorError
from realistic_indoor.generator.base import DEFAULT_AREAS_M2, check_area, finish
from realistic_indoor.generator.geometry import area_to_units
from realistic_indoor.generator.house.doors import add_doors
from realistic_indoor.generator.house.layout import ASPECT, NEAR_COST, choose_frame
from realistic_indoor.generator.house.programme import draw_programme
from realistic_indoor.generator.house.rooms import add_rooms
from realistic_indoor.generator.plan import B, M, Plan, S
from realistic_indoor.generator.typed import model_params
from realistic_indoor.models.building_model import BuildingTypeModel, default_model
from realistic_indoor.models.reference import reference_table

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.building.building import Building
    from realistic_indoor.generator.house.layout import Frame
    from realistic_indoor.generator.house.programme import Programme

__all__ = ["MAX_AREA_M2", "MIN_AREA_M2", "HouseGenerator"]

MIN_AREA_M2, MAX_AREA_M2 = 50.0, 1000.0
"""Floor areas a house may be asked for (m2)."""

OPTIONAL_KINDS = ("store", "study", "toilet", "dining room", "living room", "bathroom", "bedroom")
"""Kinds of room left out, in this order, where a house's rooms do not fit its floor area with
their least areas, down to the least count of the programme table."""


def _drop_one(prog: Programme) -> Programme | None:
    """The programme with its least needed room left out, the table's least counts kept (``None``: none left)."""
    rooms = prog.day + prog.night
    row = prog.row
    least = {
        "store": row.stores.low,
        "study": row.studies.low,
        "toilet": row.toilets.low,
        "dining room": row.dining_rooms.low,
        "living room": row.living_rooms.low,
        "bathroom": row.bathrooms.low,
        "bedroom": row.bedrooms.low - 1,
    }
    for kind in OPTIONAL_KINDS:
        pick = [r for r in rooms if r.kind == kind]
        if len(pick) > least[kind]:
            gone = min(pick, key=lambda r: r.area_m2)
            return replace(
                prog,
                day=tuple(r for r in prog.day if r is not gone),
                night=tuple(r for r in prog.night if r is not gone),
            )
    return None


def _frame(prog: Programme, target: float) -> tuple[Programme, Frame]:
    """The programme's frame, leaving out rooms (see :data:`OPTIONAL_KINDS`) until one fits.

    A frame near the wanted proportions (see :data:`~realistic_indoor.generator.house.layout.NEAR_COST`)
    is preferred to all the programme's rooms: an over-full house of one strip loses a store
    rather than get a second hallway. Where even the least programme does not fit so, any
    proportions are taken, and in the smallest houses rooms below their least areas.

    Raises:
        RealisticIndoorError: If the least programme does not fit at all (a layout bug).
    """
    while True:
        frame = choose_frame(prog, target, allowance=NEAR_COST)
        if frame is not None:
            return prog, frame
        smaller = _drop_one(prog)
        if smaller is None:
            break
        prog = smaller
    frame = choose_frame(prog, target) or choose_frame(prog, target, strict=False)
    if frame is None:
        raise RealisticIndoorError(
            f"house of {prog.area_m2:g} m2 without a layout (a bug: please report the seed)"
        )
    return prog, frame


@lru_cache(maxsize=1)
def _size_limits() -> tuple[float, float]:
    """Largest small and largest medium room of a house (m2): geometric means of Table 1's mean areas.

    The rule of :func:`realistic_indoor.validator.label_inference.size_thresholds`, so that a
    generated room has the label its area would be given.
    """
    t = reference_table("house")
    s, m, b = (t[lab]["area_mean"] for lab in (S, M, B))
    return math.sqrt(s * m), math.sqrt(m * b)


def _label_by_size(plan: Plan) -> None:
    """Give every room but the entrance and the hallway the size label of its area."""
    small, medium = (area_to_units(a) for a in _size_limits())
    for r in plan.rooms:
        if not r.is_circulation:
            area = r.area
            r.label = S if area < small else M if area < medium else B


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
        prog = draw_programme(rng, self.area_m2)
        prog, frame = _frame(prog, float(rng.uniform(*ASPECT)))
        plan = Plan()
        add_rooms(plan, frame, prog.day)
        add_doors(plan, rng, model, (frame.width, frame.depth))
        _label_by_size(plan)
        params = {"area_m2": self.area_m2, **model_params(model, "house")}
        return finish(plan, rng, "house", {"generator": "house", "params": params})
