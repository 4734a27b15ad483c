"""How a building type lays out its wings along a corridor skeleton."""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["OFFICE_WINGS", "SCHOOL_WINGS", "WingStyle"]


@dataclass(frozen=True)
class WingStyle:
    """Conventions of the wing layout that a building type's room statistics do not carry.

    The type's conventions for every layout are its
    :class:`~realistic_indoor.generator.rooms.style.TypeStyle`.

    Attributes:
        wing_length_m: Typical length of a wing between two junctions (m); sets how many
            wings the footprint is cut into.
        side_weights: How often a corridor has ordinary rooms on both sides (``"double"``), on
            one side only, its other side a facade (``"single"``), or small rooms on the other
            side (``"shallow"``).
        shapes: Relative frequency of each skeleton shape (see ``wings.skeleton.SHAPES``).
        hall_rooms_p: Probability that a large hall has a strip of rooms along one side.
        corridor_cuts: How many corridor segments to cut, as a share of the number the model's
            corridor share asks for (real plans divide corridors at doors and width changes that
            a generated corridor does not have, so fewer, longer segments match their sizes).
        open_end_p: Probability that a dead-end corridor runs on to the facade (with an exit)
            instead of ending at a small room.
        max_extent_m: Floor of the footprint's longest side (m): draws longer than 2.6 times
            the side of a square of the same area, or than this, are redrawn.
    """

    wing_length_m: tuple[float, float]
    side_weights: dict[str, float]
    shapes: dict[str, float]
    hall_rooms_p: float = 0.7
    corridor_cuts: float = 1.0
    open_end_p: float = 0.6
    max_extent_m: float = 45.0


OFFICE_WINGS = WingStyle(
    wing_length_m=(12.0, 22.0),
    side_weights={"double": 0.15, "single": 0.8, "shallow": 0.05},
    corridor_cuts=0.9,
    shapes={
        "bar": 1.0,
        "L": 1.2,
        "T": 1.0,
        "cross": 0.6,
        "U": 1.0,
        "H": 0.8,
        "E": 0.8,
        "comb": 0.8,
        "court": 0.6,
        "deep": 0.3,
        "grid": 1.0,
    },
    open_end_p=0.6,
)
"""Offices: mostly single-loaded corridors (the paper's offices have much circulation)."""

SCHOOL_WINGS = WingStyle(
    wing_length_m=(18.0, 30.0),
    side_weights={"double": 0.15, "single": 0.35, "shallow": 0.5},
    shapes={
        "bar": 1.0,
        "L": 1.2,
        "T": 1.0,
        "cross": 0.4,
        "U": 1.0,
        "H": 0.8,
        "E": 0.8,
        "comb": 0.6,
        "court": 1.0,
        "deep": 0.3,
        "grid": 1.0,
    },
    open_end_p=0.7,
)
"""Schools: long wings, small service rooms opposite the classrooms, courtyards."""
