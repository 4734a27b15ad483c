"""Like-for-like sets: generated buildings of the same floor area as given plans ("twins").

Comparing generated buildings with real ones of other sizes mixes size with structure; a twin
has its plan's floor area, so what differs is how the floor is organised.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from realistic_indoor.errors import ConfigError
from realistic_indoor.generator.base import GENERATOR_NAMES
from realistic_indoor.generator.house import MAX_AREA_M2, MIN_AREA_M2
from realistic_indoor.generator.make import generate_from, make_generator
from realistic_indoor.generator.random_grid import CELL_M, MAX_UNITS, MIN_UNITS
from realistic_indoor.generator.typed import OfficeGenerator, SchoolGenerator

if TYPE_CHECKING:
    from realistic_indoor.building.building import Building

__all__ = ["Twin", "area_limits", "generate_like"]


def area_limits(name: str) -> tuple[float, float]:
    """The smallest and largest floor area (m2) the generator called ``name`` makes.

    Raises:
        ConfigError: For an unknown generator name.
    """
    if name in ("office", "school"):
        style = (OfficeGenerator if name == "office" else SchoolGenerator).style
        return style.min_area_m2, style.max_area_m2
    if name == "house":
        return MIN_AREA_M2, MAX_AREA_M2
    if name == "random":
        return MIN_UNITS**2 * CELL_M**2, MAX_UNITS**2 * CELL_M**2
    raise ConfigError(f"unknown generator {name!r}; valid: {', '.join(GENERATOR_NAMES)}")


@dataclass(frozen=True)
class Twin:
    """One generated building made like a plan.

    Attributes:
        name: The plan's name with the twin's number when there are several per plan
            (``"Off-2"``, ``"Off-2_1"``): a file name without its extension.
        plan_area_m2: Floor area of the plan (m2).
        building: The generated building; its floor area is ``plan_area_m2`` within the
            generator's tolerance, or the nearest limit when ``clamped``.
        clamped: Whether the plan's area lay outside the generator's limits.
    """

    name: str
    plan_area_m2: float
    building: Building
    clamped: bool


def generate_like(
    plans: Iterable[tuple[str, Building]],
    building_type: str,
    count: int = 1,
    seed: int = 0,
    **options: Any,
) -> Iterator[Twin]:
    """Generate ``count`` buildings of ``building_type`` per plan, each of the plan's floor area.

    The ``k``-th twin of the ``i``-th plan is drawn with seed ``seed + i * count + k``, so the
    same plans in the same order give the same twins. Areas outside the generator's limits
    (:func:`area_limits`) are clamped to the nearest limit and the twin says so.

    Args:
        plans: ``(name, building)`` pairs, e.g. the file stem and the plan read from it.
        building_type: A generator name (``"office"``, ``"school"``, ``"house"``, ``"random"``).
        count: Twins per plan, >= 1.
        seed: Seed of the first twin, >= 0.
        **options: Passed to :func:`~realistic_indoor.generator.make_generator` (``model=``).

    Yields:
        One :class:`Twin` per plan and twin, plan by plan.

    Raises:
        ConfigError: For an unknown type, a count under 1 or a negative seed.
    """
    low, high = area_limits(building_type)
    if isinstance(count, bool) or not isinstance(count, int) or count < 1:
        raise ConfigError(f"count must be an integer >= 1, not {count!r}")
    if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
        raise ConfigError(f"seed must be a non-negative integer, not {seed!r}")
    for i, (name, plan) in enumerate(plans):
        area = plan.area
        target = min(max(area, low), high)
        generator = make_generator(building_type, target, **options)
        for k in range(count):
            building = generate_from(generator, seed + i * count + k)
            building.metadata["like"] = {"plan": name, "plan_area_m2": round(area, 3)}
            twin_name = name if count == 1 else f"{name}_{k}"
            yield Twin(twin_name, area, building, target != area)
