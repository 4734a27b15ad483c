"""Architectural conventions of a building type that its room statistics do not carry."""

from __future__ import annotations

from dataclasses import dataclass, field

__all__ = ["OFFICE_STYLE", "SCHOOL_STYLE", "TypeStyle"]


@dataclass(frozen=True)
class TypeStyle:
    """How a building type sizes, serves and names its rooms, whatever its layout.

    Sizes come from the building-type model; this keeps them within the type's usual ranges and
    says what the model does not: service cores, the annex beside the building, functions by
    role. Each layout has its own conventions besides
    (:class:`~realistic_indoor.generator.blocks.style.BlockStyle`,
    :class:`~realistic_indoor.generator.wings.style.WingStyle`).

    Attributes:
        name: Name of the convention (the building type).
        corridor_width_m: Range the model's corridor width is kept in (m).
        room_depth_m: Range the depth of a strip of ordinary rooms is kept in (m).
        shallow_depth_m: Range of the depth of a strip of small rooms (m).
        depth_scale: Depth of a strip of ordinary rooms over the side of a square medium room.
        corridor_scale: Corridor width over the width of a rectangle with the model's mean
            corridor area and axes ratio.
        exit_p: Probability that a corridor end on the facade has an exterior door.
        core_rooms: Small rooms per service core side (a core is a short corridor with small
            rooms on both sides).
        service_functions: Functions of small rooms in service cores (taken from the model's
            mix where it has them).
        storage_functions: Functions of closets and rooms entered through other rooms.
        end_functions: Functions of the small rooms that close dead-end corridors.
        entrance_functions: Functions of the entrance hall.
        grouped_functions: Functions that come only in groups, inside service cores (toilets,
            washrooms): other rooms rarely get them.
        annex: Function of a large hall added beside the building (``"gym"`` for schools), or
            empty.
        annex_area_m2: Range of the annex's area (m2); at most a quarter of the floor area.
        annex_from_m2: Floor areas (m2) over which the annex comes in: none below the first,
            always from the second, with a probability rising linearly in between (none of
            the shared real schools under 1,000 m2 has a room of a gym's size, 2 of the 5 of
            1,000-1,200 m2 have one).
        annex_functions: Functions of the small rooms along the annex's far side, in turn.
        required_functions: Functions every building of the type has (one room each at least).
        min_area_m2: Smallest footprint the layouts support (m2).
        max_area_m2: Largest footprint accepted (m2).
    """

    name: str
    corridor_width_m: tuple[float, float]
    room_depth_m: tuple[float, float]
    shallow_depth_m: tuple[float, float]
    depth_scale: float = 1.0
    corridor_scale: float = 1.0
    exit_p: float = 0.6
    core_rooms: tuple[int, int] = (2, 3)
    service_functions: tuple[str, ...] = ("toilet", "washroom", "bathroom", "storage", "stairs", "elevator")
    storage_functions: tuple[str, ...] = ("closet", "storage", "archive")
    end_functions: tuple[str, ...] = ("stairs", "storage", "elevator")
    entrance_functions: tuple[str, ...] = ("lobby", "entrance")
    grouped_functions: tuple[str, ...] = ("toilet", "washroom", "bathroom")
    annex: str = ""
    annex_area_m2: tuple[float, float] = (0.0, 0.0)
    annex_from_m2: tuple[float, float] = (0.0, 0.0)
    annex_functions: tuple[str, ...] = ("washroom", "washroom", "storage")
    required_functions: tuple[str, ...] = field(default_factory=tuple)
    min_area_m2: float = 300.0
    max_area_m2: float = 50_000.0


OFFICE_STYLE = TypeStyle(
    name="office",
    corridor_width_m=(1.6, 2.6),
    room_depth_m=(3.6, 7.0),
    shallow_depth_m=(2.4, 3.6),
    depth_scale=0.9,
    exit_p=0.6,
    core_rooms=(2, 3),
    min_area_m2=250.0,
)
"""Offices: double-loaded corridors of offices, service cores, entrance lobbies."""

SCHOOL_STYLE = TypeStyle(
    name="school",
    corridor_width_m=(2.2, 3.6),
    room_depth_m=(6.5, 9.0),
    shallow_depth_m=(3.2, 4.6),
    depth_scale=1.05,
    corridor_scale=1.2,
    exit_p=0.7,
    core_rooms=(2, 3),
    service_functions=("toilet", "washroom", "storage", "cleaning", "stairs", "closet"),
    storage_functions=("closet", "storage"),
    end_functions=("stairs", "storage", "cleaning"),
    entrance_functions=("entrance", "atrium"),
    annex="gym",
    annex_area_m2=(250.0, 450.0),
    annex_from_m2=(600.0, 1200.0),
    required_functions=("gym", "lab"),
    min_area_m2=300.0,
)
"""Schools: classrooms along long corridors, small service rooms, halls, a gym."""
