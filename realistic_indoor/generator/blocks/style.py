"""How a building type arranges its blocks: proportions, cores, crossings, courts and halls."""

from __future__ import annotations

from dataclasses import dataclass, field

__all__ = ["OFFICE_BLOCKS", "SCHOOL_BLOCKS", "BlockStyle"]


@dataclass(frozen=True)
class BlockStyle:
    """Conventions of the block layout that a building type's room statistics do not carry.

    Attributes:
        aspect: Range of the footprint's length over its depth, drawn log-uniformly (>= 1).
        facade_scale: Range of the depth of a strip of rooms on the facade over the type's
            strip depth (the model's, see ``rooms.dims.layout_dims``).
        core_scale: Range of the depth of a strip of rooms inside the block (back to back with
            another across the core) over the depth of a strip on the facade.
        section_m: Range of the distance between two corridors crossing the core (m).
        step_p: Probability that a facade strip steps back over part of its length.
        step_m: Range of the step's depth (m).
        notch_p: Probability that a facade strip is left out at one end of the block, the
            corridor running along the facade there (an L- or U-shaped footprint).
        court_p: Probability that a core section is a courtyard instead of rooms.
        deep_core_p: Probability that a core section (not a courtyard) is one strip as deep
            as the core, its rooms opening onto one corridor, instead of two strips back to
            back: open-plan and meeting rooms as deep as they are wide.
        core_hall_p: Share of the halls (after the lobby) set across a core, joining the two
            corridors beside it; the others open onto a facade strip.
        hall_area_scale: The halls' area over the model's mean hall area.
        through_hall_p: Probability that a hall across a core reaches both corridors beside
            it (else it takes one strip and opens onto one corridor).
        corridor_scale: Corridor width over the type's (see ``rooms.dims.layout_dims``).
        doors_per_room: Most further doors one room gets (see ``connect_rooms``).
        compositions: Relative frequency of each footprint: ``"I"`` one block, ``"L"``, ``"T"``
            and ``"U"`` a main bar with wings (see ``blocks.compose``).
        max_axes_ratio: Rooms are at least their strip's depth over this wide (real offices'
            medium and big rooms have axes ratios of 1.4-1.5 on average).
        suites: Make the model's connected pairs of medium and big rooms suites (one room
            entered only through the other, see ``rooms.suites.make_suites``) instead of two rooms
            with a corridor door each and a door between them: real plans' connected rooms are
            mostly reached through each other, so most of their rooms keep one door.
        max_bar_m: Longest bar of a composed footprint (m); larger buildings are one block.
        main_share: Range of the main block's share of the floor area in an L or T.
        ring_main_p: Probability that the main block of an L, T or U is a ring (two corridors
            around a core) rather than one bar; its wings stay bars.
        ring_share: Follow the model's share of buildings with a ring corridor
            (``LocalStructures.ring_share``): a block drawn without one is one double-loaded
            bar, or an E (a main bar with 3 or more wings) where one bar would be too long.
            Schools do (15% of the shared real schools have a loop); offices leave rings to
            the block's proportions, since their plans without a loop are still compact blocks.
        annex_room_m: Range of the depth of the rooms along the annex's far side, and the
            length along it each takes (m): a school gym's changing rooms and stores are group
            rooms of about 30 m2 in the real plans, not cubicles.
        annex_area_m2: Range of the annex's area (m2) in this layout, its service rooms
            included, in place of the type style's (``None``: the type style's); at most a
            quarter of the floor area, a cap that binds below about 2,000-3,400 m2. The gyms of
            the shared real schools have 486-868 m2 (median 579 m2; one of 2,167 m2), a quarter
            or more of the floor in schools under 2,200 m2.
        more_annexes: Large rooms beside the block besides the style's annex, for large
            buildings: ``(function, area range (m2), floor areas over which it comes in (m2))``
            each, drawn as :func:`~realistic_indoor.generator.rooms.annex.draw_annex` draws the
            annex (none below the first floor area, certain above the second, where it finds
            a place), largest first, without service rooms. Of the shared real schools of
            1,500 m2 and more, 12 of 26 have a canteen (median about 290 m2), and 7 of the 17
            of 2,700 m2 and more an auditorium of 450-830 m2 (function ``conference``, the
            real plans' label); the largest real school has 7,641 m2.
        more_annex_share: Largest share of the floor area one of ``more_annexes`` takes (so an
            auditorium of a school under 5,700 m2 is smaller than its range).
        corridor_cuts: How many corridor segments to cut, as a share of the number the model's
            corridor share asks for (real plans divide corridors at doors, width changes and
            fire doors: their segments are short, axes ratio about 4 in offices).
    """

    aspect: tuple[float, float]
    facade_scale: tuple[float, float] = (0.95, 1.1)
    core_scale: tuple[float, float] = (0.8, 1.1)
    section_m: tuple[float, float] = (20.0, 36.0)
    step_p: float = 0.5
    step_m: tuple[float, float] = (1.0, 2.5)
    notch_p: float = 0.2
    court_p: float = 0.0
    deep_core_p: float = 0.0
    core_hall_p: float = 0.5
    hall_area_scale: float = 1.0
    through_hall_p: float = 0.3
    corridor_scale: float = 1.0
    doors_per_room: int = 3
    corridor_cuts: float = 1.0
    max_axes_ratio: float = 1.6
    suites: bool = True
    max_bar_m: float = 90.0
    main_share: tuple[float, float] = (0.5, 0.7)
    ring_main_p: float = 0.0
    annex_room_m: tuple[tuple[float, float], float] = ((2.6, 3.4), 3.5)
    annex_area_m2: tuple[float, float] | None = None
    more_annexes: tuple[tuple[str, tuple[float, float], tuple[float, float]], ...] = ()
    more_annex_share: float = 0.15
    ring_share: bool = False
    compositions: dict[str, float] = field(default_factory=lambda: {"I": 1.0})


OFFICE_BLOCKS = BlockStyle(
    aspect=(1.0, 2.2),
    facade_scale=(1.05, 1.35),
    core_scale=(1.6, 2.4),
    section_m=(30.0, 55.0),
    step_p=0.6,
    step_m=(1.0, 4.0),
    notch_p=0.5,
    deep_core_p=0.7,
    core_hall_p=0.3,
    compositions={"I": 0.75, "L": 0.15, "T": 0.1},
    main_share=(0.65, 0.85),
    ring_main_p=0.7,
)
"""Offices: compact deep plans, ring corridors around cores of rooms and halls."""

SCHOOL_BLOCKS = BlockStyle(
    aspect=(1.1, 2.8),
    facade_scale=(0.95, 1.1),
    core_scale=(0.9, 1.1),
    section_m=(35.0, 60.0),
    step_p=0.5,
    step_m=(1.0, 3.0),
    notch_p=0.4,
    court_p=0.35,
    core_hall_p=0.3,
    annex_room_m=((3.4, 4.6), 7.0),
    annex_area_m2=(500.0, 850.0),
    more_annexes=(
        ("conference", (450.0, 850.0), (2500.0, 6000.0)),
        ("canteen", (200.0, 400.0), (1500.0, 6000.0)),
    ),
    ring_share=True,
    compositions={"I": 0.3, "L": 0.35, "T": 0.15, "U": 0.2},
)
"""Schools: classroom strips on both sides of corridors, courtyards in the larger ones."""
